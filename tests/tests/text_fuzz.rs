//! Malformed fonts and strings never panic: the bundled font file mutated
//! (bytes flipped, words overwritten — in the table directory, in table
//! headers, anywhere — and truncated), each result either refused with a
//! `FontError` or drawn and measured with random strings (any `char`), at
//! random sizes (1/64 to 2048 px) and positions (far off screen too),
//! with kerning, grid fitting and every baseline and alignment.
//!
//! A cargo-fuzz target for the same path is `fuzz/fuzz_targets/text.rs`
//! (it needs the `fuzz/` crate's `[[bin]]` entry; see its header). Run
//! once with `PROPTEST_CASES=100000` (release): no panic.

use proptest::prelude::*;
use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::path::Shape;
use softedge::style::{Blend, FillRule, Opacity};
use softedge::text::{
    Alignment, Baseline, Font, FontStyle, Glyph, GlyphId, LineHeight, Scale, Sharpen, Text,
    TextSize, TextStyle,
};
use softedge::{Band, BandBuffer};

const FONT: &[u8] = softedge::text::bundled::SOFTEDGE_SANS;

/// One mutation of the file.
#[derive(Debug, Clone)]
enum Mutation {
    /// XOR a byte.
    Flip(usize, u8),
    /// Overwrite 4 bytes (offsets, lengths, counts).
    Word(usize, u32),
    /// Cut the file.
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let len = FONT.len();
    prop_oneof![
        // Half of the flips in the first 512 bytes: the directory and the
        // small tables' headers.
        (0..512usize, 1..=255u8).prop_map(|(i, b)| Mutation::Flip(i, b)),
        (0..len, 1..=255u8).prop_map(|(i, b)| Mutation::Flip(i, b)),
        (0..len.saturating_sub(4), any::<u32>()).prop_map(|(i, w)| Mutation::Word(i, w)),
        (0..len).prop_map(Mutation::Truncate),
    ]
}

fn apply(muts: &[Mutation]) -> Vec<u8> {
    let mut v = FONT.to_vec();
    for m in muts {
        match *m {
            Mutation::Flip(i, b) => {
                if let Some(x) = v.get_mut(i) {
                    *x ^= b;
                }
            }
            Mutation::Word(i, w) => {
                if i + 4 <= v.len() {
                    v[i..i + 4].copy_from_slice(&w.to_be_bytes());
                }
            }
            Mutation::Truncate(n) => v.truncate(n),
        }
    }
    v
}

/// Draws and measures everything a user could with this font.
fn exercise(font: &Font<'_>, text: &str, size64: u32, x: i32, y: i32, opts: u8) {
    let mut acc = [0i32; BandBuffer::<1>::acc_len(48, 24)];
    let mut cover = [0i32; BandBuffer::<1>::cover_len(48, 24)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(48, 0, 24)).unwrap();
    buf.clear([0]);
    let mut canvas = Canvas::new(&mut buf, None);
    let baseline = [
        Baseline::Top,
        Baseline::Bottom,
        Baseline::Middle,
        Baseline::Alphabetic,
    ][usize::from(opts & 3)];
    let alignment =
        [Alignment::Left, Alignment::Center, Alignment::Right][usize::from(opts >> 2) % 3];
    let sharpen = if opts & 0x10 != 0 {
        Sharpen::GRID
    } else {
        Sharpen::NONE
    };
    let style = FontStyle::<1>::new(font, 1, [4095])
        .with_size(TextSize::from_64ths(size64))
        .with_kerning(opts & 0x20 != 0)
        .with_sharpen(sharpen)
        .with_opacity(Opacity::from_u8(opts));
    let line_height = if opts & 0x40 != 0 {
        LineHeight::Percent(u32::from(opts) * 7)
    } else {
        LineHeight::Pixels(u32::from(opts))
    };
    let t = Text::with_text_style(
        text,
        FinePoint::new(x, y),
        style,
        TextStyle::new(alignment, baseline, line_height),
    );
    let _ = t.measure();
    let _ = t.draw(&mut canvas);
    // Single glyphs by id, any id, as shapes.
    let scale = Scale::new(TextSize::from_64ths(size64), font.units_per_em());
    for id in [0u16, 1, 3, 127, 128, 255, u16::MAX] {
        let g = Glyph::new(font, GlyphId(id), FinePoint::new(x, y), scale);
        let _ = canvas.fill_shape(&g, [4095], FillRule::EvenOdd, Blend::Add, Opacity::OPAQUE);
        let _ = font.kerning(GlyphId(id), GlyphId(id / 2));
        let _ = font.advance(GlyphId(id));
    }
    let _ = (
        font.ascender(),
        font.descender(),
        font.x_height(),
        font.line_height(),
    );
    let mut n = 0usize;
    let mut count = |_: FinePoint, _: FinePoint| n += 1;
    struct Count<'a>(&'a mut dyn FnMut(FinePoint, FinePoint));
    impl softedge::path::SegmentSink for Count<'_> {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            (self.0)(a, b);
        }
    }
    t.lines().for_each(|l| l.fill(&mut Count(&mut count)));
}

fn coordinate() -> impl Strategy<Value = i32> {
    prop_oneof![
        -4096..60 * 1024,
        Just(i32::MIN),
        Just(i32::MAX),
        -(1 << 22)..(1 << 22),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 384, ..ProptestConfig::default() })]

    #[test]
    fn mutated_fonts_never_panic(
        muts in prop::collection::vec(mutation(), 1..8),
        text in "\\PC{0,12}",
        size64 in prop_oneof![1u32..64 * 64, Just(2048 * 64), Just(u32::MAX)],
        x in coordinate(),
        y in coordinate(),
        opts in any::<u8>(),
    ) {
        let data = apply(&muts);
        if let Ok(font) = Font::new(&data) {
            exercise(&font, &text, size64, x, y, opts);
        }
    }

    #[test]
    fn any_string_at_any_size_and_place_never_panics(
        text in "(\\PC|\n|\r|\t){0,40}",
        size64 in prop_oneof![1u32..128 * 64, Just(2048 * 64)],
        x in coordinate(),
        y in coordinate(),
        opts in any::<u8>(),
    ) {
        let font = Font::new(FONT).unwrap();
        exercise(&font, &text, size64, x, y, opts);
    }
}

#[test]
fn random_bytes_are_refused_or_survive() {
    // Random files with a valid magic: the parser's every early exit.
    let mut s = 0x1234_5678u64;
    for _ in 0..2000 {
        let mut v = vec![0u8; 64 + (s as usize % 2000)];
        for b in v.iter_mut() {
            s = s.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            *b = (s >> 56) as u8;
        }
        v[..4].copy_from_slice(&[0, 1, 0, 0]);
        if let Ok(font) = Font::new(&v) {
            exercise(&font, "Ag?", 12 * 64, 5000, 15000, 0);
        }
    }
}

/// Found by the `text` fuzz target: a font collection (`ttcf`) claiming
/// 0xe2000000 faces in a 60-byte file (their offsets would take 14 GB). ttf-parser checks that read only
/// with a `debug_assert` (a panic in debug builds, such as this test's);
/// `Font::new` refuses the file first.
#[test]
fn a_collection_whose_faces_run_past_the_file_is_malformed() {
    let mut file = b"ttcf".to_vec();
    file.extend_from_slice(&[0x00, 0xe3, 0xe2, 0xe2, 0xe2, 0x00, 0x00, 0x00]);
    file.resize(60, 0xe2);
    assert_eq!(
        Font::new(&file).err(),
        Some(softedge::text::FontError::Malformed)
    );
    // A collection header cut short is malformed too; one that fits is
    // left to the parser (no faces here: not a font).
    assert_eq!(
        Font::new(b"ttcf\x00\x01").err(),
        Some(softedge::text::FontError::Malformed)
    );
    let mut one = b"ttcf\x00\x01\x00\x00\x00\x00\x00\x01".to_vec();
    one.extend_from_slice(&[0, 0, 0, 16]);
    assert!(Font::new(&one).is_err());
}

/// The bundled font with its first `cmap` subtable's header rewritten
/// as format `format`, whose 32-bit count (at `at` in the subtable) is
/// `count`.
fn with_cmap_subtable(format: u16, at: usize, count: u32) -> Vec<u8> {
    let mut v = FONT.to_vec();
    let be16 = |v: &[u8], i: usize| usize::from(u16::from_be_bytes([v[i], v[i + 1]]));
    let be32 =
        |v: &[u8], i: usize| u32::from_be_bytes([v[i], v[i + 1], v[i + 2], v[i + 3]]) as usize;
    // The table directory: 12 bytes, then 16 a table (tag, sum, offset, length).
    let cmap = (0..be16(&v, 4))
        .map(|k| 12 + 16 * k)
        .find(|&r| &v[r..r + 4] == b"cmap")
        .map(|r| be32(&v, r + 8))
        .expect("the bundled font has a cmap");
    let sub = cmap + be32(&v, cmap + 4 + 4);
    v[sub..sub + 2].copy_from_slice(&format.to_be_bytes());
    v[sub + at..sub + at + 4].copy_from_slice(&count.to_be_bytes());
    v
}

/// Found by the `text` fuzz target: a `cmap` subtable of format 13 that
/// claims 2^28 groups of 12 bytes. ttf-parser checks that array's read
/// only with a `debug_assert` (a panic in debug builds, such as this
/// test's) when a character is looked up; `Font::new` refuses the file
/// first. Formats 10, 12 and 14 have such 32-bit counts too; one that fits
/// its table is left to the parser.
#[test]
fn a_cmap_subtable_whose_entries_run_past_its_table_is_malformed() {
    for (format, at) in [(10u16, 16usize), (12, 12), (13, 12), (14, 6)] {
        let file = with_cmap_subtable(format, at, 1 << 28);
        assert_eq!(
            Font::new(&file).err(),
            Some(softedge::text::FontError::Malformed),
            "format {format}"
        );
        let file = with_cmap_subtable(format, at, 1);
        if let Ok(font) = Font::new(&file) {
            exercise(&font, "Ag?", 12 * 64, 5000, 15000, 0);
        }
    }
}
