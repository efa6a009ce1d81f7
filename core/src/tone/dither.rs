//! Dithering linear 12-bit intensity to 1-bit pixels (BinaryColor).
//!
//! A 1-bit OLED pixel is either black or full white, and the eye averages
//! neighbouring pixels in *light*: the brightness of an area is the fraction
//! of its pixels that are on. So the fraction of on-pixels must equal the
//! linear intensity `I / 4095`, and both ditherers here work on the linear
//! `lin12` value, not on a γ-corrected code (dithering a γ code would make
//! a 50 % linear grey come out at `0.5^(1/2.2) = 73 %` of white, and the
//! anti-aliased edges would lose the equal-energy property of seed 000,
//! eq. 4: a moving object would pulse in brightness).
//!
//! - [`Bayer8`]: ordered dithering with the 8x8 Bayer matrix: 65 levels per
//!   8x8 tile, stateless, a flat area averages to its intensity within
//!   1/128. Per pixel: one masked table look-up and a compare.
//! - [`FloydSteinberg`]: error diffusion with the weights 7/16 (next pixel),
//!   3/16, 5/16, 1/16 (row below), serpentine. It needs one error row that
//!   lives as long as the frame: the band renderer must keep the same
//!   `FloydSteinberg` (and its error row) from one band to the next, or each
//!   band edge shows a seam. Per pixel: shifts, adds and a compare.
//!
//! Output goes to any `T: From<bool>` (`true` = on): `bool`, `u8`, or
//! embedded-graphics' `BinaryColor`.

use super::{lin12_index, LIN_MAX};

/// Side of the Bayer matrix.
const BAYER_SIDE: usize = 8;
/// Entries of the Bayer matrix.
const BAYER_LEN: usize = BAYER_SIDE * BAYER_SIDE;

/// The 2x2 Bayer matrix `D2 = [[0, 2], [3, 1]]` (row `y`, column `x`): the
/// definition the larger matrices grow from.
const D2: [[usize; 2]; 2] = [[0, 2], [3, 1]];

/// Ordered dithering with the 8x8 Bayer matrix.
///
/// The matrix is grown from `D2` by `M_2n(x, y) = 4 M_n(x mod n, y mod n) +
/// D2(x div n, y div n)`, so each level `0..64` appears once. Pixel `(x, y)`
/// is on iff `I / 4095 > (M(x, y) + 1/2) / 64`, i.e.
/// `128 I > (2 M + 1) 4095` — thresholds at the middle of each 64th, so
/// `I = 0` is all off, `I = 4095` all on.
///
/// ```
/// # use softedge::tone::Bayer8;
/// let bayer = Bayer8::new();
/// let mut out = [false; 8];
/// bayer.row(&[[2048]; 8], 0, 0, &mut out);
/// assert_eq!(out.iter().filter(|&&on| on).count(), 4);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Bayer8 {
    /// Smallest `lin12` that turns each cell on, row-major.
    thresholds: [u16; BAYER_LEN],
}

impl Default for Bayer8 {
    fn default() -> Self {
        Self::new()
    }
}

impl Bayer8 {
    /// The matrix and its thresholds.
    pub const fn new() -> Self {
        let mut thresholds = [0u16; BAYER_LEN];
        let mut k = 0;
        while k < BAYER_LEN {
            let (x, y) = (k % BAYER_SIDE, k / BAYER_SIDE);
            let level = Self::level(x, y) as u32;
            // Smallest I with 128 I > (2 level + 1) 4095.
            let t = (2 * level + 1) * LIN_MAX as u32 / 128 + 1;
            thresholds[k] = t as u16;
            k += 1;
        }
        Bayer8 { thresholds }
    }

    /// `M(x, y)` in `0..64`, for `x, y < 8` (crate-internal: the
    /// [`ordered`](super::ordered) profiles take their 4x4 matrix from it).
    pub(super) const fn level(x: usize, y: usize) -> usize {
        let mut m = 0;
        let mut bit = 0;
        // Bit 0 of (x, y) picks the coarsest D2 term (weight 16), bit 2 the finest.
        while bit < 3 {
            let d = D2[(y >> bit) & 1][(x >> bit) & 1];
            m += d << (2 * (2 - bit));
            bit += 1;
        }
        m
    }

    /// Whether frame pixel `(x, y)` of intensity `lin12` (clamped) is on.
    ///
    /// ```
    /// # use softedge::tone::Bayer8;
    /// let b = Bayer8::new();
    /// assert!(!b.is_on(0, 3, 5));
    /// assert!(b.is_on(4095, 3, 5));
    /// ```
    #[inline]
    pub fn is_on(&self, lin12: u16, x: i32, y: i32) -> bool {
        // Masks keep the index in 0..64 for every (x, y), negative too.
        let k = ((y & 7) as usize) * BAYER_SIDE + (x & 7) as usize;
        let t = self.thresholds[k & (BAYER_LEN - 1)];
        lin12_index(lin12) >= usize::from(t)
    }

    /// Dithers frame row `y`, pixels from `x0` on: `out[k]` for `row[k]`,
    /// the pixel at column `x0 + k` (wrapping past `i32::MAX`, where the
    /// matrix keeps tiling: only `x mod 8` matters). Returns the number of
    /// pixels written (the shorter slice). Every pixel is exactly
    /// [`is_on`](Self::is_on) of its column (tested on random rows, in
    /// release builds too).
    ///
    /// The loop first takes the row's eight thresholds, rotated so that
    /// entry `k & 7` belongs to pixel `k`, and then only indexes that
    /// array by the pixel count. (It used to zip the pixels with the column
    /// range `x0..`: that panicked in debug builds for `x0` within a row's
    /// length of `i32::MAX`, and rustc 1.95's x86-64 release build
    /// vectorized it into a loop that disagreed with `is_on` on about a
    /// quarter of a 128x64 frame's pixels — issue #18.)
    pub fn row<T: From<bool>>(&self, row: &[[u16; 1]], x0: i32, y: i32, out: &mut [T]) -> usize {
        let base = ((y & 7) as usize) * BAYER_SIDE;
        // Column phase of x0 (two's complement: x0 & 7 is x0 mod 8).
        let phase = (x0 & 7) as usize;
        let mut cells = [0u16; BAYER_SIDE];
        for (j, c) in cells.iter_mut().enumerate() {
            let k = base + ((phase + j) & (BAYER_SIDE - 1));
            *c = self.thresholds.get(k).copied().unwrap_or(u16::MAX);
        }
        let mut n = 0;
        for (o, &[i]) in out.iter_mut().zip(row) {
            let t = cells.get(n & (BAYER_SIDE - 1)).copied().unwrap_or(u16::MAX);
            *o = T::from(lin12_index(i) >= usize::from(t));
            n += 1;
        }
        n
    }
}

/// Floyd–Steinberg error diffusion in linear light, over a caller-owned
/// error row (`i16` per pixel of the frame width).
///
/// The row holds, for each column, the error carried into the next row to
/// be dithered; keep this value (and so the buffer) alive across the bands
/// of a frame, and make a new one (or [`reset`](Self::reset)) at the start
/// of each frame. Rows go alternately left-to-right and right-to-left
/// (serpentine). Errors pushed past the row's ends are kept in the end
/// column, so no light is lost; stored errors are clamped to `±4095`.
///
/// ```
/// # use softedge::tone::FloydSteinberg;
/// let mut err = [0i16; 16];
/// let mut fs = FloydSteinberg::new(&mut err);
/// let mut out = [false; 16];
/// let mut on = 0;
/// for _ in 0..16 {
///     fs.row(&[[1024]; 16], &mut out);
///     on += out.iter().filter(|&&b| b).count();
/// }
/// assert!((60..=68).contains(&on)); // a quarter of 256 pixels
/// ```
#[derive(Debug)]
pub struct FloydSteinberg<'a> {
    err: &'a mut [i16],
    reverse: bool,
}

impl<'a> FloydSteinberg<'a> {
    /// Starts a frame over `err` (cleared here); `err` should be as long as
    /// the widest row.
    pub fn new(err: &'a mut [i16]) -> Self {
        err.fill(0);
        FloydSteinberg {
            err,
            reverse: false,
        }
    }

    /// Starts a new frame: clears the error row.
    ///
    /// ```
    /// # use softedge::tone::FloydSteinberg;
    /// let mut err = [5i16; 4];
    /// let mut fs = FloydSteinberg::new(&mut err);
    /// fs.reset();
    /// ```
    pub fn reset(&mut self) {
        self.err.fill(0);
        self.reverse = false;
    }

    /// Dithers the next row of the frame into `out` (`true` = on). Handles
    /// as many pixels as the shortest of `row`, `out` and the error row, and
    /// returns that count.
    pub fn row<T: From<bool>>(&mut self, row: &[[u16; 1]], out: &mut [T]) -> usize {
        let n = row.len();
        self.row_of(n, |x| row.get(x).map_or(0, |v| v[0]), out)
    }

    /// Like [`row`](Self::row) for a row of `n` pixels given by `value`
    /// (the renderer reads them from the band without copying the row).
    pub fn row_of<T: From<bool>>(
        &mut self,
        n: usize,
        value: impl Fn(usize) -> u16,
        out: &mut [T],
    ) -> usize {
        let n = n.min(out.len()).min(self.err.len());
        let reverse = self.reverse;
        self.reverse = !reverse;
        let (out, err) = (&mut out[..n], &mut self.err[..n]);

        let mut carry: i32 = 0; // 7/16 of the previous pixel's error
        let mut pending: i32 = 0; // its 1/16 for the row below, at this column
        let mut behind: Option<usize> = None; // the previous pixel's column
        for p in 0..n {
            let x = if reverse { n - 1 - p } else { p };
            let (i, Some(e_in)) = (value(x), err.get(x).copied()) else {
                break;
            };
            let v = i32::from(i.min(LIN_MAX)) + i32::from(e_in) + carry;
            let on = 2 * v > i32::from(LIN_MAX);
            if let Some(o) = out.get_mut(x) {
                *o = T::from(on);
            }
            let e = if on { v - i32::from(LIN_MAX) } else { v };
            // Shares by shifts; the last takes the rounding so they sum to e.
            let e7 = ((e << 3) - e) >> 4;
            let e5 = ((e << 2) + e) >> 4;
            let e3 = ((e << 1) + e) >> 4;
            let e1 = e - e7 - e5 - e3;
            let mut below = pending + e5;
            match behind.and_then(|b| err.get_mut(b)) {
                Some(b) => *b = clamp_err(i32::from(*b) + e3),
                None => below += e3, // first pixel: keep the share in its column
            }
            if p + 1 == n {
                below += e7 + e1; // last pixel: nothing ahead
            }
            if let Some(slot) = err.get_mut(x) {
                *slot = clamp_err(below);
            }
            pending = e1;
            carry = e7;
            behind = Some(x);
        }
        n
    }
}

/// A stored error, clamped to `±4095`.
fn clamp_err(e: i32) -> i16 {
    e.clamp(-i32::from(LIN_MAX), i32::from(LIN_MAX)) as i16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bayer_levels_are_a_permutation_of_0_to_63() {
        let mut seen = [false; BAYER_LEN];
        for y in 0..BAYER_SIDE {
            for x in 0..BAYER_SIDE {
                seen[Bayer8::level(x, y)] = true;
            }
        }
        assert!(seen.iter().all(|&s| s));
        // The classic first row of the 8x8 matrix.
        let first: [usize; 8] = core::array::from_fn(|x| Bayer8::level(x, 0));
        assert_eq!(first, [0, 32, 8, 40, 2, 34, 10, 42]);
    }

    #[test]
    fn extreme_intensities_are_solid() {
        let b = Bayer8::new();
        for y in -8..8 {
            for x in -8..8 {
                assert!(!b.is_on(0, x, y));
                assert!(b.is_on(4095, x, y));
                assert!(b.is_on(u16::MAX, x, y));
            }
        }
    }

    #[cfg(feature = "embedded-graphics")]
    #[test]
    fn binary_color_comes_from_bool() {
        use embedded_graphics_core::pixelcolor::BinaryColor;
        let mut out = [BinaryColor::Off; 4];
        Bayer8::new().row(&[[4095], [0], [4095], [0]], 0, 0, &mut out);
        assert_eq!(
            out,
            [
                BinaryColor::On,
                BinaryColor::Off,
                BinaryColor::On,
                BinaryColor::Off
            ]
        );
    }

    #[test]
    fn floyd_steinberg_handles_mismatched_lengths() {
        let mut err = [0i16; 3];
        let mut fs = FloydSteinberg::new(&mut err);
        let mut out = [false; 5];
        assert_eq!(fs.row(&[[4095]; 5], &mut out), 3);
        assert_eq!(fs.row(&[], &mut out), 0);
        let mut none: [i16; 0] = [];
        let mut fs = FloydSteinberg::new(&mut none);
        assert_eq!(fs.row(&[[1]; 5], &mut out), 0);
    }
}
