//! Every ditherer's row function against its per-pixel definition, on
//! random rows (issue #18: `Bayer8::row` disagreed with `Bayer8::is_on` in
//! x86-64 release builds). CI runs this file in release as well as in
//! debug, so the optimized loops are the ones checked.
//!
//! The references are written here from the definitions in the docs:
//! Bayer's `128 I > (2 M(x, y) + 1) 4095` with `M` grown from `D2`, and
//! Floyd–Steinberg's serpentine 7/16, 3/16, 5/16, 1/16 diffusion with its
//! documented edge rules, one pixel at a time in plain `i32`.

use softedge::tone::{Bayer8, FloydSteinberg};

/// Small deterministic generator (xorshift64*), so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// An intensity: mostly in range, sometimes above 4095 (clamped by
    /// every ditherer), often at the levels' edges.
    fn lin12(&mut self) -> u16 {
        match self.below(8) {
            0 => u16::MAX - self.below(100) as u16,
            1 => 4096 + self.below(1000) as u16,
            2 => {
                // Next to a Bayer threshold: (2 l + 1) * 4095 / 128 + {0, 1}.
                let l = self.below(64) as u32;
                ((2 * l + 1) * 4095 / 128 + self.below(2) as u32) as u16
            }
            _ => self.below(4096) as u16,
        }
    }

    /// A start column, anywhere in `i32` (near both ends, too).
    fn x0(&mut self) -> i32 {
        match self.below(4) {
            0 => i32::MAX - self.below(300) as i32,
            1 => i32::MIN + self.below(300) as i32,
            _ => self.below(4096) as i32 - 2048,
        }
    }
}

/// `M(x, y)` of the 8x8 Bayer matrix, by its recursive definition
/// `M_2n(x, y) = 4 M_n(x mod n, y mod n) + D2(x div n, y div n)`.
fn bayer_level(x: u32, y: u32, n: u32) -> u32 {
    const D2: [[u32; 2]; 2] = [[0, 2], [3, 1]];
    if n == 1 {
        return 0;
    }
    let h = n / 2;
    4 * bayer_level(x % h, y % h, h) + D2[(y / h) as usize][(x / h) as usize]
}

fn bayer_reference(lin12: u16, x: i32, y: i32) -> bool {
    let i = u32::from(lin12.min(4095));
    let m = bayer_level(x.rem_euclid(8) as u32, y.rem_euclid(8) as u32, 8);
    128 * i > (2 * m + 1) * 4095
}

#[test]
fn bayer_row_equals_is_on_on_random_rows() {
    let bayer = Bayer8::new();
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let mut out = vec![false; 600];
    for case in 0..3000 {
        let len = rng.below(600) as usize;
        let row: Vec<[u16; 1]> = (0..len).map(|_| [rng.lin12()]).collect();
        let x0 = rng.x0();
        let y = rng.x0();
        let out_len = if rng.below(4) == 0 {
            rng.below(600) as usize
        } else {
            len
        };
        out.iter_mut().for_each(|o| *o = false);
        let n = bayer.row(&row, x0, y, &mut out[..out_len]);
        assert_eq!(n, len.min(out_len), "case {case}: count");
        for (k, (&[i], &o)) in row.iter().zip(&out[..n]).enumerate() {
            // Column x0 + k, wrapping past i32::MAX as the matrix tiles.
            let x = x0.wrapping_add(k as i32);
            assert_eq!(
                o,
                bayer.is_on(i, x, y),
                "case {case}: pixel {k} (x {x}, y {y}, lin12 {i})"
            );
            assert_eq!(
                o,
                bayer_reference(i, x, y),
                "case {case}: pixel {k} against the definition"
            );
        }
    }
}

#[test]
fn bayer_row_near_i32_max_does_not_overflow() {
    let bayer = Bayer8::new();
    let row = [[2048u16]; 64];
    let mut out = [false; 64];
    assert_eq!(bayer.row(&row, i32::MAX - 3, 0, &mut out), 64);
    // The pattern keeps tiling: columns i32::MAX + 1.. are i32::MIN.. (mod 8
    // the same cells).
    for (k, &o) in out.iter().enumerate() {
        let x = (i32::MAX - 3).wrapping_add(k as i32);
        assert_eq!(o, bayer.is_on(2048, x, 0), "pixel {k}");
    }
    assert_eq!(bayer.row(&row, i32::MAX, i32::MAX, &mut out), 64);
}

/// Floyd–Steinberg one pixel at a time, from its documentation: the
/// pixel's value is its intensity (clamped to 4095) plus the error carried
/// down into its column plus 7/16 of the previous pixel's error; it is on
/// above 4095 / 2; its error goes 7/16 ahead, 3/16 below behind, 5/16 below,
/// 1/16 below ahead; shares that would leave the row stay in the pixel's
/// own column; stored errors are clamped to ±4095.
struct FsReference {
    err: Vec<i32>,
    reverse: bool,
}

impl FsReference {
    fn row(&mut self, row: &[[u16; 1]], out_len: usize) -> Vec<bool> {
        let n = row.len().min(out_len).min(self.err.len());
        let reverse = self.reverse;
        self.reverse = !reverse;
        let mut out = vec![false; n];
        let mut ahead_share = 0; // the previous pixel's 7/16
        let mut diagonal_share = 0; // the previous pixel's 1/16, for this column
        for p in 0..n {
            let x = if reverse { n - 1 - p } else { p };
            let v = i32::from(row[x][0].min(4095)) + self.err[x] + ahead_share;
            out[x] = 2 * v > 4095;
            let e = if out[x] { v - 4095 } else { v };
            let (e7, e5, e3) = ((7 * e) >> 4, (5 * e) >> 4, (3 * e) >> 4);
            let e1 = e - e7 - e5 - e3;
            let mut below = diagonal_share + e5;
            if p == 0 {
                below += e3;
            } else {
                let behind = if reverse { x + 1 } else { x - 1 };
                self.err[behind] = (self.err[behind] + e3).clamp(-4095, 4095);
            }
            if p + 1 == n {
                below += e7 + e1;
            }
            self.err[x] = below.clamp(-4095, 4095);
            ahead_share = e7;
            diagonal_share = e1;
        }
        out
    }
}

#[test]
fn floyd_steinberg_row_equals_its_per_pixel_definition() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for case in 0..200 {
        let width = 1 + rng.below(300) as usize;
        let mut err = vec![0i16; width];
        let mut fs = FloydSteinberg::new(&mut err);
        let mut reference = FsReference {
            err: vec![0; width],
            reverse: false,
        };
        for r in 0..1 + rng.below(40) {
            let len = if rng.below(5) == 0 {
                rng.below(width as u64 + 20) as usize
            } else {
                width
            };
            let out_len = if rng.below(5) == 0 {
                rng.below(width as u64 + 20) as usize
            } else {
                len
            };
            let row: Vec<[u16; 1]> = (0..len).map(|_| [rng.lin12()]).collect();
            let mut out = vec![false; out_len];
            let n = fs.row(&row, &mut out);
            let want = reference.row(&row, out_len);
            assert_eq!(n, want.len(), "case {case}, row {r}: count");
            assert_eq!(&out[..n], &want[..], "case {case}, row {r}");
        }
    }
}

/// The shape of the failure in issue #18: a 128x64 frame (an SSD1306),
/// rows from column 0 into `bool`s. The old loop (`zip(x0..)`), built by
/// rustc 1.95 for x86-64 in release, got 1 932 of these 8 192 pixels wrong
/// (the same loop with a run-time `x0` did not); debug builds agreed.
#[test]
fn bayer_frame_128x64_rows_equal_is_on() {
    let bayer = Bayer8::new();
    let mut rng = Rng(77);
    let mut wrong = 0;
    for y in 0..64 {
        let row: Vec<[u16; 1]> = (0..128).map(|_| [rng.below(4096) as u16]).collect();
        let mut out = [false; 128];
        bayer.row(&row, 0, y, &mut out);
        for x in 0..128 {
            let want = bayer.is_on(row[x][0], x as i32, y);
            assert_eq!(want, bayer_reference(row[x][0], x as i32, y));
            if out[x] != want {
                wrong += 1;
            }
        }
    }
    assert_eq!(wrong, 0, "of 8192 pixels");
}
