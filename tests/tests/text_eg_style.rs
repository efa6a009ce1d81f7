//! embedded-graphics' text idiom with softedge's character style
//! (issue #33): code written for `MonoTextStyle` compiles and draws with
//! `AaTextStyle` with only the style changed, and lays its lines out as
//! embedded-graphics does (alignment, baseline, line height, the next
//! position, the bounding box), anti-aliased in a canvas.

use embedded_graphics::geometry::Dimensions;
use embedded_graphics::mono_font::ascii::FONT_10X20;
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::text::renderer::TextRenderer;
use embedded_graphics::text::{Alignment, Baseline, LineHeight, Text, TextStyleBuilder};
use softedge::prelude::*;
use softedge::text::bundled::SANS_16;
use softedge::text::{AaTextStyle, CachedFont, Font, GlyphCache, TextSize, SLOT_WORDS};
use softedge::{Band, BandBuffer};

/// One screen's text, written for embedded-graphics' `MonoTextStyle`: the
/// same tokens are compiled with each style (only `$style` differs). It
/// returns the four texts' next positions.
macro_rules! screen {
    ($style:expr, $canvas:expr) => {{
        let style = $style;
        let centred = TextStyleBuilder::new()
            .alignment(Alignment::Center)
            .baseline(Baseline::Middle)
            .line_height(LineHeight::Percent(120))
            .build();
        let readout = Text::with_alignment("72%", Point::new(60, 30), style, Alignment::Center)
            .draw($canvas)?;
        let mode = Text::with_text_style("MODE\nAUTO", Point::new(60, 60), style, centred)
            .draw($canvas)?;
        let volts =
            Text::with_baseline("1.5 V", Point::new(4, 100), style, Baseline::Top).draw($canvas)?;
        let ok = Text::new("OK", Point::new(100, 140), style).draw($canvas)?;
        [readout, mode, volts, ok]
    }};
}

const W: u16 = 128;
const H: u16 = 160;

/// Draws `f` into one band of the whole screen and gives the pixels'
/// linear values (green) and the positions `f` returned.
fn screen_of(
    f: impl FnOnce(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<[Point; 4], Box<dyn std::error::Error>>,
) -> (Vec<u16>, [Point; 4]) {
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, H)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, H)];
    let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(W, 0, H)).unwrap();
    buf.clear([0; 3]);
    let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
    let next = f(&mut canvas).unwrap();
    let b = canvas.buffer();
    let values = (0..i32::from(H))
        .flat_map(|y| (0..i32::from(W)).map(move |x| (x, y)))
        .map(|(x, y)| b.lin12(x, y).unwrap()[1])
        .collect();
    (values, next)
}

/// The box of the lit pixels in rows `rows`: `(x0, y0, x1, y1)` inclusive.
fn ink(lit: &[u16], rows: core::ops::Range<i32>) -> (i32, i32, i32, i32) {
    let mut b = (i32::MAX, i32::MAX, i32::MIN, i32::MIN);
    for y in rows {
        for x in 0..i32::from(W) {
            if lit[(y * i32::from(W) + x) as usize] > 0 {
                b = (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y));
            }
        }
    }
    b
}

#[test]
fn monotextstyle_code_compiles_and_draws_with_only_the_style_changed() {
    let (mono, mono_next) = screen_of(|canvas| {
        Ok(screen!(
            MonoTextStyle::new(&FONT_10X20, Rgb565::WHITE),
            canvas
        ))
    });
    // A font rasterized ahead of time (a static in flash).
    let (raster, raster_next) =
        screen_of(|canvas| Ok(screen!(AaTextStyle::new(&SANS_16, Rgb565::WHITE), canvas)));
    // An outline font through a glyph cache.
    let font = Font::bundled().unwrap();
    let (mut codes, mut slots, mut scratch) = ([0u8; 4096], [0u32; 64 * SLOT_WORDS], [0i32; 1024]);
    let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    let sans = CachedFont::new(&font, TextSize::px(16), &cache).with_phases(1);
    let (cached, cached_next) =
        screen_of(|canvas| Ok(screen!(AaTextStyle::new(sans, Rgb565::WHITE), canvas)));
    // The same glyphs at one phase: the raster font and the cache draw the
    // same pixels to a level (both from `rasterize_glyph`; the font was
    // made with the finer tolerance, 1 fine unit, the cache uses 3).
    assert_eq!(raster_next, cached_next);
    let worst = raster
        .iter()
        .zip(&cached)
        .map(|(&a, &b)| a.abs_diff(b))
        .max()
        .unwrap();
    assert!(worst <= 4095 / 29 + 2, "{worst}");
    // Both anti-aliased: pixels partly covered; the mono font's whole.
    assert!(raster.iter().any(|&v| v > 200 && v < 3800));
    assert!(mono.iter().all(|&v| v == 0 || v == 4095));

    for (name, lit, next) in [("mono", &mono, mono_next), ("raster", &raster, raster_next)] {
        // "72%" centred on x = 60, alphabetic baseline on row 30's bottom.
        let r = ink(lit, 10..32);
        let centre2 = r.0 + r.2;
        assert!((centre2 - 120).abs() <= 3, "{name}: readout {r:?}");
        // (Round glyphs overshoot the baseline a little: row 31 faintly.)
        assert!(
            (30..=31).contains(&r.3) || (name == "mono" && r.3 <= 34),
            "{name}: readout {r:?}"
        );
        // "MODE" / "AUTO" centred, the first line's middle on row 60, the
        // second one 120 % of a line lower.
        let m = ink(lit, 44..100);
        assert!((m.0 + m.2 - 120).abs() <= 3, "{name}: mode {m:?}");
        // "1.5 V" from column 4, its top at or below row 100.
        let v = ink(lit, 95..125);
        assert!(v.0 >= 4 && v.0 <= 6 && v.1 >= 100, "{name}: volts {v:?}");
        // "OK" on the baseline of row 140, from column 100.
        let k = ink(lit, 120..160);
        assert!(k.0 >= 100 && k.0 <= 102, "{name}: ok {k:?}");
        // embedded-graphics' next position: after the last line's last
        // character, on the position's row.
        assert_eq!(next[3].y, 140, "{name}");
        assert!(
            next[3].x > k.2 - 1 && next[3].x <= k.2 + 3,
            "{name}: {:?} vs {k:?}",
            next[3]
        );
    }
}

#[test]
fn layout_follows_embedded_graphics_rules() {
    let style = AaTextStyle::new(&SANS_16, Rgb565::WHITE);
    let p = Point::new(60, 30);
    // Right: the line's last pixel column on the position; Center: moved
    // left by half its width less one (embedded-graphics' arithmetic).
    let m = style.measure_string("72%", Point::zero(), Baseline::Alphabetic);
    let w = m.next_position.x;
    assert!(w > 20 && w < 40, "{w}");
    let right = Text::with_alignment("72%", p, style, Alignment::Right).bounding_box();
    assert_eq!(right.top_left.x, p.x - (w - 1));
    let centre = Text::with_alignment("72%", p, style, Alignment::Center).bounding_box();
    assert_eq!(centre.top_left.x, p.x - (w - 1) / 2);
    // Baselines: the box from the ascender to the descender line.
    let top = Text::with_baseline("Hg", p, style, Baseline::Top).bounding_box();
    assert_eq!(top.top_left.y, p.y);
    let bottom = Text::with_baseline("Hg", p, style, Baseline::Bottom).bounding_box();
    assert_eq!(bottom.bottom_right().unwrap().y, p.y);
    let alpha = Text::new("Hg", p, style).bounding_box();
    assert!(alpha.top_left.y < p.y - 10 && alpha.bottom_right().unwrap().y > p.y);
    // Line height: the font's (ascender - descender + gap, 1.164 em),
    // rounded; LineHeight applies to it as for a MonoFont.
    assert_eq!(style.line_height(), 19);
    let two = Text::with_text_style(
        "a\nb",
        p,
        style,
        TextStyleBuilder::new()
            .line_height(LineHeight::Pixels(25))
            .build(),
    );
    let b = two.bounding_box();
    assert_eq!(b.size.height, top.size.height + 25);
}

#[test]
fn a_missing_character_is_reported_and_the_rest_drawn() {
    let (lit, _) = screen_of(|canvas| {
        let style = AaTextStyle::new(&SANS_16, Rgb565::WHITE);
        let r = Text::new("AÄB", Point::new(10, 40), style).draw(canvas);
        assert_eq!(r, Err(DrawError::MissingGlyph('Ä')));
        Ok([Point::zero(); 4])
    });
    assert!(lit.iter().filter(|&&l| l > 0).count() > 30);
    assert_eq!(SANS_16.missing("AÄB").collect::<String>(), "Ä");
}
