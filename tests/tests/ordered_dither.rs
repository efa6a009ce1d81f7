//! The ordered-dithering profiles (`tone::ordered`) against an independent
//! reference: the display curves' inverses written here in `f64` from their
//! definitions (sRGB, IEC 61966-2-1; `V = x^(1/γ)`), the 4x4 tile read
//! through the public per-pixel API, the tile mean computed exactly (a sum
//! of 16 integers).
//!
//! The invariants (issue 16, "no banding"):
//! - `tile_mean_equals_the_encoded_value`: over any 4x4 tile the mean
//!   output code equals `max * V(I / 4095)` within half a step of the fine
//!   table (1/16 of a 5-bit code, 1/8 of a 6-bit code, 1/32 of a 4-bit
//!   code), for every `I` in `0..=4095` and every curve;
//! - `representable_values_are_flat`: where `max * V` is within that half
//!   step of a whole code, every pixel gets that code (no noise on flat
//!   colours, black and white included, at any position);
//! - `tile_mean_is_monotonic` (and each pixel's code too);
//! - `the_pattern_tiles_the_plane` at negative and huge coordinates;
//! - `uniform_is_exact`: `uniform()` is `Some` only for colours that are
//!   the same at every position, and then that colour.
//!
//! Run it in release as well as in debug (`cargo test --release -p
//! softedge-tests --test ordered_dither`): an LLVM miscompile once broke a
//! Bayer row loop in release builds only (issue #18).

use embedded_graphics_core::pixelcolor::{GrayColor, Rgb565, RgbColor};
use softedge::tone::ordered::{Gray4Dither, Rgb565Dither};
use softedge::tone::profile::Profile;
use softedge::tone::Curve;

const CURVES: [Curve; 3] = [Curve::Srgb, Curve::GAMMA_2_2, Curve::GAMMA_2_4];

/// The curve's inverse, `V(x)` for linear light `x` in `[0, 1]`.
fn encode(curve: Curve, x: f64) -> f64 {
    match curve {
        Curve::Srgb => {
            if x <= 0.0031308 {
                12.92 * x
            } else {
                1.055 * x.powf(1.0 / 2.4) - 0.055
            }
        }
        Curve::Power(g) => {
            let (num, den) = g.ratio();
            x.powf(f64::from(den) / f64::from(num))
        }
    }
}

/// `max * V(lin / 4095)`: the code the tile should average to.
fn reference(curve: Curve, lin: u16, max: u32) -> f64 {
    f64::from(max) * encode(curve, f64::from(lin) / 4095.0)
}

/// Slack for the table builder's fixed-point `pow` (its error is ~1e-9 of
/// a code) against `f64`.
const EPS: f64 = 1e-6;

/// The 16 `[r, g, b]` codes of the tile at `(x0, y0)` for a grey `lin`
/// (red and blue share the 5-bit table; red from `lin`, blue from
/// `4095 - lin` so both ends of the table are read on every call).
fn rgb_tile(d: &Rgb565Dither, x0: i32, y0: i32, lin: u16) -> [[u8; 3]; 16] {
    let mut t = [[0; 3]; 16];
    for (k, c) in t.iter_mut().enumerate() {
        let (x, y) = (x0 + (k % 4) as i32, y0 + (k / 4) as i32);
        let col = Profile::color(&d, x, y, [lin, lin, 4095 - lin]);
        *c = [col.r(), col.g(), col.b()];
        // The profile's colour and the packed code agree.
        let code = d.code(x, y, [lin, lin, 4095 - lin]);
        assert_eq!(
            code,
            (u16::from(c[0]) << 11) | (u16::from(c[1]) << 5) | u16::from(c[2])
        );
    }
    t
}

fn gray_tile(d: &Gray4Dither, x0: i32, y0: i32, lin: u16) -> [u8; 16] {
    core::array::from_fn(|k| {
        let (x, y) = (x0 + (k % 4) as i32, y0 + (k / 4) as i32);
        Profile::color(&d, x, y, [lin]).luma()
    })
}

/// Sum over the tile of channel `ch`.
fn sum(t: &[[u8; 3]; 16], ch: usize) -> u32 {
    t.iter().map(|c| u32::from(c[ch])).sum()
}

#[test]
fn tile_mean_equals_the_encoded_value() {
    for curve in CURVES {
        let d = Rgb565Dither::new(curve);
        let g = Gray4Dither::new(curve);
        let (mut worst5, mut worst6, mut worst4) = (0f64, 0f64, 0f64);
        for lin in 0..=4095u16 {
            let t = rgb_tile(&d, 0, 0, lin);
            let e_r = f64::from(sum(&t, 0)) / 16.0 - reference(curve, lin, 31);
            let e_g = f64::from(sum(&t, 1)) / 16.0 - reference(curve, lin, 63);
            let e_b = f64::from(sum(&t, 2)) / 16.0 - reference(curve, 4095 - lin, 31);
            let e_4 = f64::from(
                gray_tile(&g, 0, 0, lin)
                    .iter()
                    .map(|&c| u32::from(c))
                    .sum::<u32>(),
            ) / 16.0
                - reference(curve, lin, 15);
            assert!(e_r.abs() <= 1.0 / 16.0 + EPS, "{curve:?} r {lin}: {e_r}");
            assert!(e_b.abs() <= 1.0 / 16.0 + EPS, "{curve:?} b {lin}: {e_b}");
            assert!(e_g.abs() <= 1.0 / 8.0 + EPS, "{curve:?} g {lin}: {e_g}");
            assert!(
                e_4.abs() <= 1.0 / 32.0 + EPS,
                "{curve:?} gray4 {lin}: {e_4}"
            );
            worst5 = worst5.max(e_r.abs()).max(e_b.abs());
            worst6 = worst6.max(e_g.abs());
            worst4 = worst4.max(e_4.abs());
        }
        // The figures quoted in the module docs (`--nocapture`).
        println!(
            "{curve:?}: worst |tile mean - max V| = {worst5:.6} (5-bit), {worst6:.6} (6-bit), \
             {worst4:.6} (4-bit) codes"
        );
    }
}

/// The worst error of the undithered γ formats, for comparison: rounding
/// to the nearest code is off by up to half a code.
#[test]
fn undithered_error_is_half_a_code_for_comparison() {
    use softedge::tone::format::Rgb565Format;
    for curve in CURVES {
        let f = Rgb565Format::new(curve);
        let mut worst = 0f64;
        for lin in 0..=4095u16 {
            let [r, _, _] = f.channels([lin; 3]);
            worst = worst.max((f64::from(r) - reference(curve, lin, 31)).abs());
        }
        println!("{curve:?}: undithered worst |code - 31 V| = {worst:.6}");
        assert!(worst <= 0.5 + EPS && worst > 0.45);
    }
}

/// The curve itself, `B(V)`: the light of code value `V`.
fn decode(curve: Curve, v: f64) -> f64 {
    match curve {
        Curve::Srgb => {
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        }
        Curve::Power(g) => {
            let (num, den) = g.ratio();
            v.powf(f64::from(num) / f64::from(den))
        }
    }
}

/// Dithering γ codes puts the tile's light on the chord between two
/// codes: its error in light, against rounding to the nearest code. Both
/// in units of full scale, 5-bit channel; the dithered error must be
/// smaller everywhere it matters (at most a quarter of the undithered one).
#[test]
fn tile_light_error_is_below_the_undithered_one() {
    use softedge::tone::format::Rgb565Format;
    for curve in CURVES {
        let d = Rgb565Dither::new(curve);
        let f = Rgb565Format::new(curve);
        let (mut dith, mut flat) = (0f64, 0f64);
        for lin in 0..=4095u16 {
            let target = f64::from(lin) / 4095.0;
            let t = rgb_tile(&d, 0, 0, lin);
            let light: f64 = t
                .iter()
                .map(|c| decode(curve, f64::from(c[0]) / 31.0))
                .sum::<f64>()
                / 16.0;
            dith = dith.max((light - target).abs());
            let [r, _, _] = f.channels([lin; 3]);
            flat = flat.max((decode(curve, f64::from(r) / 31.0) - target).abs());
        }
        println!(
            "{curve:?}: worst |tile light - I| = {dith:.6}, undithered {flat:.6} (full scale, 5-bit)"
        );
        assert!(dith <= flat / 4.0, "{curve:?}: {dith} vs {flat}");
    }
}

#[test]
fn representable_values_are_flat() {
    for curve in CURVES {
        let d = Rgb565Dither::new(curve);
        let g = Gray4Dither::new(curve);
        let mut flat = 0;
        for lin in 0..=4095u16 {
            let t = rgb_tile(&d, -5, 7, lin);
            // Channel, its max code, its half fine step, its input.
            for (ch, max, half, l) in [
                (0, 31, 1.0 / 16.0, lin),
                (1, 63, 1.0 / 8.0, lin),
                (2, 31, 1.0 / 16.0, 4095 - lin),
            ] {
                let v = reference(curve, l, max);
                let n = v.round();
                if (v - n).abs() < half - EPS {
                    flat += 1;
                    assert!(
                        t.iter().all(|c| f64::from(c[ch]) == n),
                        "{curve:?} ch {ch} lin {l}: {t:?} not all {n}"
                    );
                }
            }
            let v = reference(curve, lin, 15);
            let n = v.round();
            if (v - n).abs() < 1.0 / 32.0 - EPS {
                assert!(gray_tile(&g, 3, -9, lin).iter().all(|&c| f64::from(c) == n));
            }
        }
        assert!(flat > 100, "{curve:?}: only {flat} flat values seen");
        // Black and white, at any position, and above 4095 (clamped).
        for (x, y) in [(0, 0), (-1, -1), (i32::MAX, i32::MIN), (12345, -678)] {
            for lin in [4095, 4096, u16::MAX] {
                let white = Profile::color(&&d, x, y, [lin; 3]);
                assert_eq!(white, Rgb565::WHITE);
                assert_eq!(Profile::color(&&g, x, y, [lin]).luma(), 15);
            }
            assert_eq!(Profile::color(&&d, x, y, [0; 3]), Rgb565::BLACK);
            assert_eq!(Profile::color(&&g, x, y, [0]).luma(), 0);
        }
    }
}

#[test]
fn tile_mean_is_monotonic() {
    for curve in CURVES {
        let d = Rgb565Dither::new(curve);
        let g = Gray4Dither::new(curve);
        let mut prev = rgb_tile(&d, 0, 0, 0);
        let mut prev4 = gray_tile(&g, 0, 0, 0);
        for lin in 1..=4095u16 {
            let t = rgb_tile(&d, 0, 0, lin);
            assert!(sum(&t, 0) >= sum(&prev, 0), "{curve:?} r at {lin}");
            assert!(sum(&t, 1) >= sum(&prev, 1), "{curve:?} g at {lin}");
            // Blue reads 4095 - lin: non-increasing in lin.
            assert!(sum(&t, 2) <= sum(&prev, 2), "{curve:?} b at {lin}");
            // Each pixel too: dithering never turns a pixel darker as the
            // light rises.
            for (a, b) in t.iter().zip(&prev) {
                assert!(a[0] >= b[0] && a[1] >= b[1] && a[2] <= b[2]);
            }
            let t4 = gray_tile(&g, 0, 0, lin);
            assert!(t4.iter().zip(&prev4).all(|(a, b)| a >= b));
            prev = t;
            prev4 = t4;
        }
    }
}

#[test]
fn the_pattern_tiles_the_plane() {
    let d = Rgb565Dither::new(Curve::Srgb);
    for lin in (0..=4095u16).step_by(37) {
        let base = rgb_tile(&d, 0, 0, lin);
        for (x0, y0) in [
            (4, 0),
            (0, -4),
            (-400, 812),
            (i32::MIN, i32::MIN),
            (i32::MAX - 3, 2_147_483_644),
        ] {
            assert_eq!(rgb_tile(&d, x0, y0, lin), base, "lin {lin} at ({x0}, {y0})");
        }
    }
}

#[test]
fn uniform_is_exact() {
    for curve in CURVES {
        let d = Rgb565Dither::new(curve);
        let g = Gray4Dither::new(curve);
        let (mut some, mut none) = (0, 0);
        for lin in 0..=4095u16 {
            let px = [lin, lin, 4095 - lin];
            let t = rgb_tile(&d, 0, 0, lin);
            let same = t.iter().all(|c| *c == t[0]);
            match Profile::uniform(&&d, px) {
                Some(c) => {
                    some += 1;
                    assert!(same, "{curve:?} {lin}: uniform but {t:?}");
                    assert_eq!([c.r(), c.g(), c.b()], t[0]);
                }
                None => none += 1,
            }
            let t4 = gray_tile(&g, 0, 0, lin);
            if let Some(c) = Profile::uniform(&&g, [lin]) {
                assert!(t4.iter().all(|&v| v == c.luma()));
            }
        }
        // Black and white are uniform; most values are not.
        assert!(Profile::uniform(&&d, [0; 3]) == Some(Rgb565::BLACK));
        assert!(Profile::uniform(&&d, [4095; 3]) == Some(Rgb565::WHITE));
        assert!(
            some >= 2 && none > some,
            "{curve:?}: {some} uniform, {none} not"
        );
    }
}

/// Through the renderer, as `&Rgb565Format` is used: a `static` profile by
/// reference; a flat dark background comes out as the profile's pattern
/// at each pixel's frame position, band after band.
#[test]
fn the_renderer_takes_a_static_dither_profile() {
    use embedded_graphics::mock_display::MockDisplay;
    use softedge::prelude::*;
    static DITHER: Rgb565Dither = Rgb565Dither::new(Curve::Srgb);
    const W: u16 = 16;
    const H: u16 = 12;
    const ROWS: u16 = 5;
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut slots = [WalkSlot::<3>::EMPTY; 2];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, ROWS).unwrap();
    let mut display = MockDisplay::<Rgb565>::new();
    let bg = [60u16, 300, 4095];
    r.render(&mut display, &DITHER, bg, |_| Ok::<(), ()>(()))
        .unwrap();
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            let want = Profile::color(&&DITHER, x, y, bg);
            assert_eq!(
                display.get_pixel(embedded_graphics::prelude::Point::new(x, y)),
                Some(want)
            );
        }
    }
}
