//! Findings of the `renderer` fuzz target's oracles (issue #36), each
//! reduced to a test.
//!
//! ## Text ink inside `Text::bounding_box()`
//!
//! embedded-graphics' `Dimensions` contract for a `Drawable` such as
//! `Text`: "The implementation must return a rectangle that contains all
//! drawn pixels" (`embedded-graphics-core` 0.4, `geometry/mod.rs`); a
//! `Text`'s box is the union of its lines' `measure_string` boxes. With
//! [`AaTextStyle`] the box was the line's advance (rounded to whole
//! pixels) by its ascender-to-descender rows, and glyphs ink outside it:
//! `J`'s hook and `T`'s bar left of the pen (negative left side bearing),
//! `_` below the descender line, the anti-aliased fringe of `k`'s last
//! column right of the rounded advance. Firmware that clears a text's
//! box before redrawing it, or renders only the window of a changed
//! text, left those pixels stale. The target's first failing input was
//! `"   TT"` right-aligned from the top at (21, -2). The oracle here is
//! that contract exactly: every pixel the text changes (drawn alone over
//! a background) lies inside `bounding_box()`. Fixed in
//! `AaTextStyle::measure_string`: the line's box grown to its glyphs'
//! masks where they are drawn (a glyph without a mask, a full cache's,
//! to its outline's box).

use embedded_graphics::geometry::Dimensions;
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use embedded_graphics::prelude::*;
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use softedge::prelude::*;
use softedge::text::bundled::SANS_16;
use softedge::text::{
    AaTextStyle, CachedFont, Font, GlyphCache, GlyphSource, TextSize, SLOT_WORDS,
};
use softedge::{Band, BandBuffer};

const W: u16 = 96;
const H: u16 = 64;

/// The pixels `text` inks (drawn alone into a band over black) outside
/// its `bounding_box()`.
fn ink_outside_box<S: GlyphSource + Clone>(text: Text<'_, AaTextStyle<S, Rgb565>>) -> Vec<Point> {
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, H)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, H)];
    let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(W, 0, H)).unwrap();
    buf.clear([0; 3]);
    let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
    let bb = text.bounding_box();
    let _ = text.draw(&mut canvas);
    let b = canvas.buffer();
    let (x1, y1) = (
        i64::from(bb.top_left.x) + i64::from(bb.size.width),
        i64::from(bb.top_left.y) + i64::from(bb.size.height),
    );
    let inside = |x: i32, y: i32| {
        x >= bb.top_left.x && y >= bb.top_left.y && i64::from(x) < x1 && i64::from(y) < y1
    };
    (0..i32::from(H))
        .flat_map(|y| (0..i32::from(W)).map(move |x| (x, y)))
        .filter(|&(x, y)| b.lin12(x, y).unwrap() != [0; 3] && !inside(x, y))
        .map(|(x, y)| Point::new(x, y))
        .collect()
}

/// Every character of the bundled subset.
fn subset() -> impl Iterator<Item = char> {
    (0x21u8..0x7f)
        .map(char::from)
        .chain("°±µ×÷·²³½–—‘’“”•…€£Ω←↑→↓≤≥≠≈∞✓".chars())
}

#[test]
fn the_fuzzers_inputs_ink_inside_the_bounding_box() {
    // The reduced inputs: one character at a whole-pixel position.
    let style = AaTextStyle::new(&SANS_16, Rgb565::WHITE);
    for s in ["J", "T", "_", "k", "/", "j", "-f"] {
        let out = ink_outside_box(Text::new(s, Point::new(30, 30), style));
        assert!(out.is_empty(), "{s:?} inks {out:?} outside its box");
    }
    // The target's first failing input: right-aligned from the top, `T`'s
    // bar one column past the rounded advance.
    let ts = TextStyleBuilder::new()
        .baseline(Baseline::Top)
        .alignment(Alignment::Right)
        .build();
    let out = ink_outside_box(Text::with_text_style(
        "   TT",
        Point::new(21, -2),
        style,
        ts,
    ));
    assert!(out.is_empty(), "\"   TT\" inks {out:?} outside its box");
}

#[test]
fn every_character_inks_inside_the_bounding_box_at_every_baseline_and_alignment() {
    let style = AaTextStyle::new(&SANS_16, Rgb565::WHITE);
    let baselines = [
        Baseline::Top,
        Baseline::Middle,
        Baseline::Alphabetic,
        Baseline::Bottom,
    ];
    let aligns = [Alignment::Left, Alignment::Center, Alignment::Right];
    for c in subset() {
        let s = c.to_string();
        for (k, (&b, &a)) in baselines.iter().zip(aligns.iter().cycle()).enumerate() {
            let ts = TextStyleBuilder::new().baseline(b).alignment(a).build();
            let at = Point::new(40 + k as i32, 30);
            let out = ink_outside_box(Text::with_text_style(&s, at, style, ts));
            assert!(
                out.is_empty(),
                "{s:?} ({b:?}, {a:?}) inks {out:?} outside its box"
            );
        }
    }
    // Lines: kerned pairs, the box's union over lines.
    for s in ["AV_j", "Tj/k\n_J", "W.\nf‘", "y\u{2014}J"] {
        let out = ink_outside_box(Text::new(s, Point::new(20, 16), style));
        assert!(out.is_empty(), "{s:?} inks {out:?} outside its box");
    }
}

#[test]
fn an_outline_font_through_a_cache_inks_inside_the_bounding_box_also_when_full() {
    let font = Font::bundled().unwrap();
    // Room for every glyph, and for none (each drawn from its outline).
    for (slots, code) in [(64, 4096), (1, 16)] {
        let mut codes = vec![0u8; code];
        let mut slot_words = vec![0u32; slots * SLOT_WORDS];
        let mut scratch = vec![0i32; 1024];
        let cache = GlyphCache::new(&mut codes, &mut slot_words, &mut scratch);
        let style = AaTextStyle::new(
            CachedFont::new(&font, TextSize::px(19), &cache),
            Rgb565::WHITE,
        );
        for s in ["J", "T_k", "j/f", "Wy\nQ"] {
            let out = ink_outside_box(Text::new(s, Point::new(31, 30), style));
            assert!(
                out.is_empty(),
                "{s:?} ({slots} slots) inks {out:?} outside its box"
            );
        }
    }
}
