//! Text against an independent reference: glyph outlines read by
//! `ttf-parser` in the test, flattened in `f64` within 1e-4 px and
//! clipped to every pixel exactly (`softedge_tests::glyph_ref`), compared
//! with what softedge's canvas draws (fixed-point scale, its flattener, its
//! edge engine).
//!
//! - every glyph of the bundled font at 8, 12, 24 and 48 px, at random
//!   sub-pixel origins: each pixel's coverage within 1/32 of the exact one
//!   (also with the coarse tolerance of 16 fine units, 1/64 px);
//! - strings: the summed intensity within 0.5 % of the exact area;
//! - sub-pixel positioning: a string moved in 1/16-px steps keeps its summed
//!   linear intensity within 0.5 % (seed 000's equal energy).

use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::path::Tolerance;
use softedge::text::{Font, GlyphRun, Scale, TextSize};
use softedge::{Band, BandBuffer};
use softedge_tests::glyph_ref::{string_outline, RefOutline};

/// A tiny deterministic generator (64-bit LCG, high bits).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> u32 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 33) as u32
    }
    /// A fine-unit fraction of a pixel, 0..1024.
    fn frac(&mut self) -> i32 {
        (self.next() % 1024) as i32
    }
}

/// Draws a run (white on black, one band) and gives each pixel's linear
/// value as a fraction of full white.
fn draw(run: &GlyphRun<'_, '_, '_>, w: u16, h: u16) -> Vec<f64> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(w, 0, h)).unwrap();
    buf.clear([0]);
    let mut canvas = Canvas::new(&mut buf, None);
    use softedge::style::{Blend, FillRule, Opacity};
    canvas
        .fill(run, [4095], FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
        .unwrap();
    let buf = canvas.buffer();
    let mut out = Vec::with_capacity(usize::from(w) * usize::from(h));
    for y in 0..i32::from(h) {
        for x in 0..i32::from(w) {
            out.push(f64::from(buf.lin12(x, y).unwrap()[0]) / 4095.0);
        }
    }
    out
}

fn face() -> ttf_parser::Face<'static> {
    ttf_parser::Face::parse(softedge::text::bundled::SOFTEDGE_SANS, 0).unwrap()
}

/// Every printable character of the subset, and `.notdef` (U+FFFF).
fn characters() -> Vec<char> {
    let mut v: Vec<char> = (0x21u8..0x7f).map(char::from).collect();
    v.extend("°±µ×÷·²³½–—‘’“”•…€£Ω←↑→↓≤≥≠≈∞✓\u{ffff}".chars());
    v
}

#[test]
fn every_glyph_is_within_a_32nd_of_exact_coverage_at_8_12_24_48_px() {
    glyphs_against_exact(&[8, 12, 24, 48], Tolerance::DEFAULT);
}

#[test]
fn a_coarse_tolerance_of_a_64th_px_stays_within_a_32nd_too() {
    glyphs_against_exact(&[8, 12, 24], Tolerance::new(16));
}

/// Every glyph at each size against the exact coverage: worst and mean
/// pixel error, asserted within 1/32.
fn glyphs_against_exact(sizes: &[u16], tol: Tolerance) {
    let font = Font::bundled().unwrap();
    let face = face();
    let mut rng = Lcg(0x5eed_0017);
    let mut report = Vec::new();
    for &size in sizes {
        let (w, h) = (size * 2 + 8, size * 2 + 8);
        let mut worst: (f64, char) = (0.0, ' ');
        let mut sum_err = 0.0;
        let mut pixels = 0usize;
        let chars = characters();
        // At 48 px every third character (the reference is slow in debug).
        let step = if size == 48 { 3 } else { 1 };
        for &c in chars.iter().step_by(step) {
            let (fx, fy) = (rng.frac(), rng.frac());
            let (ox, oy) = (4 * 1024 + fx, i32::from(size) * 1024 + 4 * 1024 + fy);
            let scale = Scale::new(TextSize::px(size), font.units_per_em());
            let mut buf = [0u8; 4];
            let s = c.encode_utf8(&mut buf);
            let run = GlyphRun::new(&font, s, FinePoint::new(ox, oy), scale).with_tolerance(tol);
            let ours = draw(&run, w, h);
            let g = face.glyph_index(c).unwrap_or(ttf_parser::GlyphId(0));
            let reference = RefOutline::glyph(
                &face,
                g,
                f64::from(size),
                f64::from(ox) / 1024.0,
                f64::from(oy) / 1024.0,
            );
            let exact = reference.coverage_image(i32::from(w), i32::from(h));
            for (a, b) in ours.iter().zip(&exact) {
                let e = (a - b).abs();
                if *b > 0.0 || *a > 0.0 {
                    sum_err += e;
                    pixels += 1;
                }
                if e > worst.0 {
                    worst = (e, c);
                }
            }
        }
        report.push(format!(
            "tolerance {} fine: {size} px: worst pixel error {:.5} ({:?}), mean {:.6} over {pixels} pixels",
            tol.fine(),
            worst.0,
            worst.1,
            sum_err / pixels.max(1) as f64,
        ));
        assert!(
            worst.0 <= 1.0 / 32.0,
            "{size} px: pixel error {} at {:?}",
            worst.0,
            worst.1
        );
    }
    println!("{}", report.join("\n"));
}

/// The exact area and softedge's summed intensity of a string at a size
/// and origin (kerning off in both: layout is compared separately).
fn string_sums(font: &Font<'_>, text: &str, size: u16, ox: i32, oy: i32) -> (f64, f64) {
    let face = face();
    let scale = Scale::new(TextSize::px(size), font.units_per_em());
    let run = GlyphRun::new(font, text, FinePoint::new(ox, oy), scale).with_kerning(false);
    let w = (run.advance() / 1024 + 16).min(2040) as u16;
    let h = size * 2 + 8;
    let ours: f64 = draw(&run, w, h).iter().sum();
    let (reference, _) = string_outline(
        &face,
        text,
        f64::from(size),
        f64::from(ox) / 1024.0,
        f64::from(oy) / 1024.0,
        &|_, _| 0,
    );
    (ours, reference.signed_area().abs())
}

#[test]
fn string_intensity_is_within_half_a_percent_of_the_exact_area() {
    let font = Font::bundled().unwrap();
    let mut rng = Lcg(0x000a_11ce);
    let text = "Hamburgefonstiv 0123456789 ±°µ";
    for size in [8u16, 12, 24, 48] {
        for _ in 0..3 {
            let (ox, oy) = (
                4 * 1024 + rng.frac(),
                i32::from(size) * 1024 + 4 * 1024 + rng.frac(),
            );
            let (ours, exact) = string_sums(&font, text, size, ox, oy);
            let rel = ours / exact - 1.0;
            println!(
                "{size} px at ({ox}, {oy}) fine: {ours:.3} vs {exact:.3} px^2, {:+.4} %",
                rel * 100.0
            );
            assert!(rel.abs() < 0.005, "{size} px: {:+.4} %", rel * 100.0);
        }
    }
}

#[test]
fn a_string_moved_in_16th_pixel_steps_keeps_its_energy() {
    let font = Font::bundled().unwrap();
    for size in [8u16, 12, 24] {
        let mut sums = Vec::new();
        for k in 0..16 {
            for l in [0, 5, 11] {
                let (ox, oy) = (
                    4 * 1024 + k * 64,
                    i32::from(size) * 1024 + 4 * 1024 + l * 64,
                );
                let (ours, _) = string_sums(&font, "Flicker 12.5 °C", size, ox, oy);
                sums.push(ours);
            }
        }
        let mean = sums.iter().sum::<f64>() / sums.len() as f64;
        let worst = sums
            .iter()
            .map(|s| (s / mean - 1.0).abs())
            .fold(0.0, f64::max);
        println!(
            "{size} px: worst deviation from the mean {:.4} %",
            worst * 100.0
        );
        assert!(worst < 0.005, "{size} px: {:.4} %", worst * 100.0);
    }
}
