//! Rasterized text (issue #33) against the independent reference: glyph
//! outlines read by `ttf-parser` in the test, flattened in `f64` and
//! clipped exactly to every pixel (`softedge_tests::glyph_ref`), compared
//! with what softedge draws from a [`RasterFont`] (made at run time by
//! `softedge_tests::raster_font` with `rasterize_glyph`, as
//! `softedge-sim font` makes one) and through a [`GlyphCache`].
//!
//! - every glyph of the bundled font at 8, 12, 16, 24 and 48 px, at 1, 2
//!   and 4 phases, at random pen positions: each pixel within 1/32 of the
//!   exact coverage of the outline at the glyph's **drawn position** (its
//!   pen's x rounded to the nearest phase, its baseline to the nearest
//!   pixel boundary);
//! - the same through a glyph cache (`FontStyle::with_cache`);
//! - strings: the summed intensity within 0.5 % of the exact area;
//! - composition in linear light, a text drawn in bands of any height,
//!   missing characters reported.

use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::style::Opacity;
use softedge::text::{
    CharRange, Font, FontStyle, GlyphCache, LineMetrics, MaskOffsets, RasterFont, RasterGlyph,
    RasterMetrics, RasterText, Text, SLOT_WORDS,
};
use softedge::{Band, BandBuffer, DrawError};
use softedge_tests::glyph_ref::{string_outline, RefOutline};
use softedge_tests::raster_font::Built;

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
    fn frac(&mut self) -> i32 {
        (self.next() % 1024) as i32
    }
}

fn face() -> ttf_parser::Face<'static> {
    ttf_parser::Face::parse(softedge::text::bundled::SOFTEDGE_SANS, 0).unwrap()
}

/// Every printable character of the bundled font but the space.
fn characters() -> Vec<char> {
    let mut v: Vec<char> = (0x21u8..0x7f).map(char::from).collect();
    v.extend("°±µ×÷·²³½–—‘’“”•…€£Ω←↑→↓≤≥≠≈∞✓".chars());
    v
}

/// The characters of the raster fonts made here: those and the space.
fn font_chars() -> Vec<char> {
    let mut v = characters();
    v.push(' ');
    v
}

/// Draws into a `w x h` band at `y0` with `draw` and gives each pixel's
/// linear value as a fraction of full white.
fn frame(
    w: u16,
    h: u16,
    bg: u16,
    draw: impl FnOnce(&mut Canvas<'_, '_, 1>) -> Result<FinePoint, DrawError>,
) -> Vec<f64> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(w, 0, h)).unwrap();
    buf.clear([bg]);
    let mut canvas = Canvas::new(&mut buf, None);
    draw(&mut canvas).unwrap();
    let buf = canvas.buffer();
    let mut out = Vec::with_capacity(usize::from(w) * usize::from(h));
    for y in 0..i32::from(h) {
        for x in 0..i32::from(w) {
            out.push(f64::from(buf.lin12(x, y).unwrap()[0]) / 4095.0);
        }
    }
    out
}

/// The drawn position of a pen at fine `(x, y)` with `phases` phases, px.
fn drawn_at(x: i32, y: i32, phases: i32) -> (f64, f64) {
    let q = (i64::from(x) * i64::from(phases) + 512) >> 10;
    let row = (i64::from(y) + 512) >> 10;
    (q as f64 / f64::from(phases), row as f64)
}

/// Worst and mean pixel error of every glyph drawn by `draw` (a glyph
/// string at a pen position) against the exact outline at its drawn
/// position; also the worst error against the outline at the pen itself.
fn glyph_errors(
    size: u16,
    phases: i32,
    step: usize,
    seed: u64,
    mut draw: impl FnMut(&str, FinePoint, u16, u16) -> Vec<f64>,
) -> (f64, char, f64, f64) {
    let face = face();
    let mut rng = Lcg(seed);
    let (w, h) = (size * 2 + 8, size * 2 + 8);
    let (mut worst, mut worst_c, mut sum, mut n, mut worst_pen) =
        (0.0f64, ' ', 0.0, 0usize, 0.0f64);
    for &c in characters().iter().step_by(step) {
        let (ox, oy) = (
            4 * 1024 + rng.frac(),
            i32::from(size) * 1024 + 4 * 1024 + rng.frac(),
        );
        let mut b = [0u8; 4];
        let ours = draw(c.encode_utf8(&mut b), FinePoint::new(ox, oy), w, h);
        let g = face.glyph_index(c).unwrap();
        let (dx, dy) = drawn_at(ox, oy, phases);
        let exact = RefOutline::glyph(&face, g, f64::from(size), dx, dy)
            .coverage_image(i32::from(w), i32::from(h));
        let at_pen = RefOutline::glyph(
            &face,
            g,
            f64::from(size),
            f64::from(ox) / 1024.0,
            f64::from(oy) / 1024.0,
        )
        .coverage_image(i32::from(w), i32::from(h));
        for ((a, e), p) in ours.iter().zip(&exact).zip(&at_pen) {
            let err = (a - e).abs();
            if *a > 0.0 || *e > 0.0 {
                sum += err;
                n += 1;
            }
            if err > worst {
                (worst, worst_c) = (err, c);
            }
            worst_pen = worst_pen.max((a - p).abs());
        }
    }
    (worst, worst_c, sum / n.max(1) as f64, worst_pen)
}

#[test]
fn every_prerasterized_glyph_is_within_a_32nd_of_exact_at_its_drawn_position() {
    let font = Font::bundled().unwrap();
    let mut report = Vec::new();
    for (size, phases) in [
        (8u16, 1u8),
        (8, 4),
        (12, 1),
        (12, 2),
        (16, 1),
        (16, 2),
        (16, 4),
        (24, 1),
        (24, 4),
        (48, 1),
    ] {
        let built = Built::new(&font, size, &font_chars(), phases);
        let rf = built.font();
        let step = if size == 48 { 3 } else { 1 };
        let (worst, c, mean, pen) =
            glyph_errors(size, i32::from(phases), step, 0x5eed_0033, |s, at, w, h| {
                frame(w, h, 0, |canvas| {
                    RasterText::new(s, at, &rf, [4095]).draw(canvas)
                })
            });
        report.push(format!(
            "{size} px, {phases} phase(s): worst {worst:.4} ({c:?}), mean {mean:.5}; at the pen itself (phase rounding) {pen:.3}; {} bytes",
            rf.flash_bytes()
        ));
        assert!(
            worst <= 1.0 / 32.0,
            "{size} px, {phases} phases: {worst} at {c:?}"
        );
    }
    println!("{}", report.join("\n"));
}

#[test]
fn every_cached_glyph_is_within_a_32nd_of_exact_at_its_drawn_position() {
    let font = Font::bundled().unwrap();
    let mut report = Vec::new();
    for size in [8u16, 12, 16, 24] {
        let (mut codes, mut slots, mut scratch) = (
            vec![0u8; 1 << 16],
            vec![0u32; 512 * SLOT_WORDS],
            vec![0i32; 1 << 14],
        );
        let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
        let style = FontStyle::<1>::new(&font, size, [4095]).with_cache(&cache);
        let (worst, c, mean, pen) = glyph_errors(size, 4, 1, 0x5eed_cace, |s, at, w, h| {
            frame(w, h, 0, |canvas| Text::new(s, at, style).draw(canvas))
        });
        report.push(format!(
            "{size} px, cached, 4 phases: worst {worst:.4} ({c:?}), mean {mean:.5}; at the pen itself {pen:.3}; cache {:?}",
            cache.stats()
        ));
        assert_eq!(cache.stats().uncached, 0);
        assert!(worst <= 1.0 / 32.0, "{size} px: {worst} at {c:?}");
    }
    println!("{}", report.join("\n"));
}

#[test]
fn a_strings_prerasterized_ink_is_within_half_a_percent_of_the_exact_area() {
    let font = Font::bundled().unwrap();
    let face = face();
    let text = "Hamburgefonstiv 0123456789 ±°µ";
    let mut rng = Lcg(0x000a_11ce);
    for (size, phases) in [(8u16, 1u8), (12, 1), (16, 1), (16, 4), (24, 2), (48, 1)] {
        let built = Built::new(&font, size, &font_chars(), phases);
        let rf = built.font();
        for _ in 0..3 {
            let at = FinePoint::new(
                4 * 1024 + rng.frac(),
                i32::from(size) * 1024 + 4 * 1024 + rng.frac(),
            );
            let t = RasterText::new(text, at, &rf, [4095]);
            let w = (t.width(text) / 1024 + 16).min(2040) as u16;
            let ours: f64 = frame(w, size * 2 + 8, 0, |c| t.draw(c)).iter().sum();
            let (reference, _) = string_outline(&face, text, f64::from(size), 0.0, 0.0, &|_, _| 0);
            let exact = reference.signed_area().abs();
            let rel = ours / exact - 1.0;
            println!(
                "{size} px, {phases} phase(s): {ours:.3} vs {exact:.3} px², {:+.4} %",
                rel * 100.0
            );
            assert!(rel.abs() < 0.005, "{size} px: {:+.4} %", rel * 100.0);
        }
    }
}

#[test]
fn text_is_composed_in_linear_light_with_its_opacity() {
    let font = Font::bundled().unwrap();
    let built = Built::new(&font, 16, &font_chars(), 2);
    let rf = built.font();
    let at = FinePoint::new(3 * 1024 + 300, 18 * 1024 + 100);
    let coverage = frame(80, 24, 0, |c| {
        RasterText::new("Wave 3.7", at, &rf, [4095]).draw(c)
    });
    let (bg, fg) = (1000.0, 3500.0);
    let alpha = Opacity::from_ratio(3, 5).unwrap();
    let drawn = frame(80, 24, 1000, |c| {
        RasterText::new("Wave 3.7", at, &rf, [3500])
            .with_opacity(alpha)
            .draw(c)
    });
    let a = f64::from(alpha.to_4096ths()) / 4096.0;
    for (k, (&cv, &d)) in coverage.iter().zip(&drawn).enumerate() {
        let want = bg + (fg - bg) * cv * a;
        assert!(
            (d * 4095.0 - want).abs() <= 1.5,
            "pixel {k}: {} vs {want}",
            d * 4095.0
        );
    }
}

#[test]
fn a_text_drawn_in_bands_of_any_height_is_the_text_drawn_whole() {
    let font = Font::bundled().unwrap();
    let built = Built::new(&font, 14, &font_chars(), 4);
    let rf = built.font();
    let (mut codes, mut slots, mut scratch) = (
        vec![0u8; 8192],
        vec![0u32; 128 * SLOT_WORDS],
        vec![0i32; 4096],
    );
    let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    let text = "Sphinx of\nblack quartz";
    let at = FinePoint::new(2 * 1024 + 77, 14 * 1024 + 900);
    let (w, h) = (120u16, 40u16);
    let whole_raster = frame(w, h, 0, |c| RasterText::new(text, at, &rf, [4095]).draw(c));
    let style = FontStyle::<1>::new(&font, 14, [4095]).with_cache(&cache);
    let whole_cached = frame(w, h, 0, |c| Text::new(text, at, style).draw(c));
    let rasterized = cache.stats().misses;
    for rows in 1..=16u16 {
        let (mut a, mut b) = (
            vec![0.0; usize::from(w) * usize::from(h)],
            vec![0.0; usize::from(w) * usize::from(h)],
        );
        let mut y0 = 0;
        while y0 < i32::from(h) {
            for (out, cached) in [(&mut a, false), (&mut b, true)] {
                let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, rows)];
                let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, rows)];
                let mut buf =
                    BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(w, y0, rows)).unwrap();
                buf.clear([0]);
                let mut canvas = Canvas::new(&mut buf, None);
                if cached {
                    Text::new(text, at, style).draw(&mut canvas).unwrap();
                } else {
                    RasterText::new(text, at, &rf, [4095])
                        .draw(&mut canvas)
                        .unwrap();
                }
                for y in y0..(y0 + i32::from(rows)).min(i32::from(h)) {
                    for x in 0..i32::from(w) {
                        out[(y * i32::from(w) + x) as usize] =
                            f64::from(canvas.buffer().lin12(x, y).unwrap()[0]) / 4095.0;
                    }
                }
            }
            y0 += i32::from(rows);
        }
        assert_eq!(a, whole_raster, "{rows}-row bands, raster font");
        assert_eq!(b, whole_cached, "{rows}-row bands, cached");
    }
    // Every glyph was rasterized once, in the first frame.
    assert_eq!(cache.stats().misses, rasterized);
    assert!(rasterized > 10 && rasterized < 24, "{rasterized}");
}

#[test]
fn missing_characters_are_reported_and_not_drawn() {
    let font = Font::bundled().unwrap();
    let built = Built::new(&font, 16, &font_chars(), 1);
    let rf = built.font();
    assert!(!font.has_glyph('中') && rf.glyph('中').is_none());
    let at = FinePoint::new(2 * 1024, 18 * 1024);
    // The raster font: the others drawn as if the missing one were not
    // there, the first missing one named.
    let mut err = None;
    let with = frame(80, 24, 0, |c| {
        err = RasterText::new("A中BÄ", at, &rf, [4095]).draw(c).err();
        Ok(at)
    });
    let without = frame(80, 24, 0, |c| {
        RasterText::new("AB", at, &rf, [4095]).draw(c)
    });
    assert_eq!(err, Some(DrawError::MissingGlyph('中')));
    assert_eq!(with, without);
    assert!(with.iter().sum::<f64>() > 20.0);
    // The outline font, drawn directly and through a cache.
    let (mut codes, mut slots, mut scratch) = (
        vec![0u8; 4096],
        vec![0u32; 64 * SLOT_WORDS],
        vec![0i32; 2048],
    );
    let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    for style in [
        FontStyle::<1>::new(&font, 16, [4095]),
        FontStyle::<1>::new(&font, 16, [4095]).with_cache(&cache),
    ] {
        let mut err = None;
        let with = frame(80, 24, 0, |c| {
            err = Text::new("A中B", at, style).draw(c).err();
            Ok(at)
        });
        let without = frame(80, 24, 0, |c| Text::new("AB", at, style).draw(c));
        assert_eq!(err, Some(DrawError::MissingGlyph('中')));
        assert_eq!(with, without);
    }
    assert_eq!(
        DrawError::MissingGlyph('中').to_string(),
        "the font has no glyph for '中' (U+4E2D)"
    );
}

#[test]
fn each_prerasterized_glyph_keeps_its_ink() {
    // The quantizer carries each pixel's rounding to the next, so a
    // glyph's summed coverage stays near its outline's area: within 1.5 %
    // (0.98 % at worst, the underscore at 12 px, whose bar's rows each
    // have one fraction the bound of 3/4 level keeps it from rounding the
    // other way; nearest rounding errs by 3.3 % for the en dash at 12 px,
    // measured).
    let font = Font::bundled().unwrap();
    let face = face();
    let mut report = Vec::new();
    for size in [12u16, 16, 24] {
        let built = Built::new(&font, size, &font_chars(), 1);
        let rf = built.font();
        let (mut worst, mut worst_c, mut worst_abs) = (0.0f64, ' ', 0.0f64);
        for c in characters() {
            let at = FinePoint::new(4 * 1024, i32::from(size) * 1024 + 4 * 1024);
            let mut b = [0u8; 4];
            let s = c.encode_utf8(&mut b);
            let ours: f64 = frame(size * 2 + 8, size * 2 + 8, 0, |cv| {
                RasterText::new(s, at, &rf, [4095]).draw(cv)
            })
            .iter()
            .sum();
            let g = face.glyph_index(c).unwrap();
            let exact = RefOutline::glyph(&face, g, f64::from(size), 4.0, f64::from(size) + 4.0)
                .signed_area()
                .abs();
            worst_abs = worst_abs.max((ours - exact).abs());
            let rel = (ours / exact - 1.0).abs();
            if exact > 2.0 && rel > worst {
                (worst, worst_c) = (rel, c);
            }
        }
        report.push(format!(
            "{size} px: worst glyph ink error {:.3} % ({worst_c:?}), {worst_abs:.4} px² at most",
            worst * 100.0
        ));
        assert!(worst < 0.015, "{size} px: {worst} at {worst_c:?}");
    }
    println!("{}", report.join("\n"));
}

#[test]
fn damaged_raster_fonts_draw_without_panics() {
    // Random tables and mask bytes (a corrupted flash image, a hand-made
    // font): drawing reads everything through checked look-ups.
    let mut rng = Lcg(0x0033_dead);
    for case in 0..400 {
        let mut bytes =
            |n: u32| -> Vec<u8> { (0..rng.next() % n).map(|_| rng.next() as u8).collect() };
        let masks = bytes(300);
        let kerning: Vec<i8> = bytes(40).into_iter().map(|b| b as i8).collect();
        let glyphs: Vec<RasterGlyph> = bytes(20)
            .chunks(4)
            .map(|c| RasterGlyph {
                advance: u16::from(c[0]) << 4,
                kern_left: *c.get(1).unwrap_or(&0),
                kern_right: *c.get(2).unwrap_or(&0),
            })
            .collect();
        let offsets: Vec<u16> = bytes(40).into_iter().map(|b| u16::from(b) * 3).collect();
        let mut chars: Vec<CharRange> = bytes(12)
            .chunks(3)
            .map(|c| CharRange {
                first: 0x20 + u32::from(c[0]),
                len: u16::from(*c.get(1).unwrap_or(&1)),
                glyph: u16::from(*c.get(2).unwrap_or(&0)),
            })
            .collect();
        chars.sort_by_key(|r| r.first);
        let r = bytes(250);
        let metrics = RasterMetrics {
            size_64ths: 1024,
            line: LineMetrics {
                ascender: i32::from(r.first().copied().unwrap_or(0)) * 100,
                descender: -(i32::from(r.get(1).copied().unwrap_or(0)) * 100),
                line_height: i32::from(r.get(2).copied().unwrap_or(0)) * 100 - 3000,
                ink_top: -i32::from(r.get(3).copied().unwrap_or(0)),
                ink_bottom: i32::from(r.get(4).copied().unwrap_or(0)),
            },
            phases: r.get(5).copied().unwrap_or(0),
            advance_shift: r.get(6).copied().unwrap_or(0),
            kern_shift: r.get(7).copied().unwrap_or(0),
            kern_columns: r.get(8).copied().unwrap_or(0),
        };
        let font = RasterFont::new(
            metrics,
            &chars,
            &glyphs,
            MaskOffsets::Short(&offsets),
            &kerning,
            &masks,
        );
        let text: String = (0..rng.next() % 12)
            .map(|_| char::from_u32(0x20 + rng.next() % 0x80).unwrap_or('?'))
            .collect();
        let at = FinePoint::new(
            (rng.next() % 80) as i32 * 1024 - 20 * 1024 + rng.frac(),
            (rng.next() % 40) as i32 * 512,
        );
        let _ = frame(48, 24, 0, |c| {
            let _ = RasterText::new(&text, at, &font, [4095])
                .with_opacity(Opacity::from_ratio(1, 2).unwrap())
                .draw(c);
            Ok(at)
        });
        assert!(font.flash_bytes() > 0, "case {case}");
    }
}

#[test]
fn a_cache_without_room_draws_glyphs_from_their_outlines() {
    // No code bytes, no scratch: every glyph is drawn from its outline
    // into the same shape (the mask's drawn position), and counted.
    let font = Font::bundled().unwrap();
    let text = "Ag 0.5";
    let at = FinePoint::new(2 * 1024 + 300, 16 * 1024 + 100);
    let (mut codes, mut slots, mut scratch) =
        (vec![0u8; 0], vec![0u32; 16 * SLOT_WORDS], vec![0i32; 0]);
    let none = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    let uncached = frame(60, 24, 0, |c| {
        Text::new(
            text,
            at,
            FontStyle::<1>::new(&font, 14, [4095]).with_cache(&none),
        )
        .draw(c)
    });
    // Five glyphs with ink; the space has none to keep (kept, 0 bytes).
    assert_eq!(none.stats().uncached, 5);
    assert_eq!(none.stats().misses, 1);
    let (mut codes, mut slots, mut scratch) = (
        vec![0u8; 4096],
        vec![0u32; 64 * SLOT_WORDS],
        vec![0i32; 2048],
    );
    let room = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    let cached = frame(60, 24, 0, |c| {
        Text::new(
            text,
            at,
            FontStyle::<1>::new(&font, 14, [4095]).with_cache(&room),
        )
        .draw(c)
    });
    // The same glyphs at the same places: within a quantization level.
    let worst = uncached
        .iter()
        .zip(&cached)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    assert!(worst <= 1.0 / 29.0, "{worst}");
    assert!(uncached.iter().sum::<f64>() > 10.0);
}
