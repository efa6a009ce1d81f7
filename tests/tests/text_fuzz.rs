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

fn be16(v: &[u8], i: usize) -> usize {
    usize::from(u16::from_be_bytes([v[i], v[i + 1]]))
}

fn be32(v: &[u8], i: usize) -> usize {
    u32::from_be_bytes([v[i], v[i + 1], v[i + 2], v[i + 3]]) as usize
}

/// Where table `tag`'s record is in a font's directory (12 bytes, then 16
/// a table: tag, checksum, offset, length); the last one, as the parser
/// reads it.
fn record(v: &[u8], tag: &[u8; 4]) -> usize {
    (0..be16(v, 4))
        .map(|k| 12 + 16 * k)
        .rfind(|&r| &v[r..r + 4] == tag)
        .unwrap_or_else(|| panic!("no {}", String::from_utf8_lossy(tag)))
}

/// Where table `tag` starts.
fn table_at(v: &[u8], tag: &[u8; 4]) -> usize {
    be32(v, record(v, tag) + 8)
}

/// Renames table `tag` to `to` (a table softedge does not need, such as
/// `gasp`, `name` or `post`, becomes a new one).
fn retag(v: &mut [u8], tag: &[u8; 4], to: &[u8; 4]) {
    let r = record(v, tag);
    v[r..r + 4].copy_from_slice(to);
}

/// Gives table `tag` the contents `bytes`, appended to the file.
fn put_table(v: &mut Vec<u8>, tag: &[u8; 4], bytes: &[u8]) {
    let r = record(v, tag);
    v.resize(v.len().next_multiple_of(4), 0);
    let at = v.len() as u32;
    v[r + 8..r + 12].copy_from_slice(&at.to_be_bytes());
    v[r + 12..r + 16].copy_from_slice(&(bytes.len() as u32).to_be_bytes());
    v.extend_from_slice(bytes);
}

/// The bundled font with its first `cmap` subtable's header rewritten
/// as format `format`, whose 32-bit count (at `at` in the subtable) is
/// `count`.
fn with_cmap_subtable(format: u16, at: usize, count: u32) -> Vec<u8> {
    let mut v = FONT.to_vec();
    let cmap = table_at(&v, b"cmap");
    let sub = cmap + be32(&v, cmap + 4 + 4);
    v[sub..sub + 2].copy_from_slice(&format.to_be_bytes());
    v[sub + at..sub + at + 4].copy_from_slice(&count.to_be_bytes());
    v
}

/// Found by the `text` fuzz target: a `cmap` subtable of format 13 that
/// claims 2^28 groups of 12 bytes, where the table holds a few. ttf-parser
/// checks that array's read only with a `debug_assert` that the read ends
/// below 4 GiB (2^28 groups end at 3 GiB; 2^32 - 1 groups, 48 GiB, trip
/// it: a panic in debug builds, such as this test's) when a character is
/// looked up; `Font::new` refuses the file first, for any count that runs
/// past the table. Formats 10, 12 and 14 have such 32-bit counts too; one
/// that fits its table is left to the parser.
#[test]
fn a_cmap_subtable_whose_entries_run_past_its_table_is_malformed() {
    for (format, at) in [(10u16, 16usize), (12, 12), (13, 12), (14, 6)] {
        for count in [u32::MAX, 1 << 28] {
            let file = with_cmap_subtable(format, at, count);
            let font = Font::new(&file);
            if let Ok(font) = &font {
                // Where the parser would trip.
                exercise(font, "Ag?", 12 * 64, 5000, 15000, 0);
            }
            assert_eq!(
                font.err(),
                Some(softedge::text::FontError::Malformed),
                "format {format}, {count} entries"
            );
        }
        let file = with_cmap_subtable(format, at, 1);
        if let Ok(font) = Font::new(&file) {
            exercise(&font, "Ag?", 12 * 64, 5000, 15000, 0);
        }
    }
}

// Each of the tests below damages the bundled font where ttf-parser would
// panic (in a debug build, such as the tests'), unless `Font` reads the
// place itself first; see `softedge::text::font`.

use softedge::text::FontError::Malformed;

/// A `cmap` subtable of 2^32 - 1 groups, as above, in a second `cmap` record
/// at the end of an unsorted directory: the parser keeps the last record
/// of a tag, while a binary search of the directory finds the first one,
/// whose subtables fit. Every record of the tag is checked.
#[test]
fn a_cmap_named_twice_is_checked_whichever_record_the_parser_keeps() {
    let file = with_cmap_subtable(13, 12, u32::MAX);
    let cmap = table_at(&file, b"cmap");
    let bad_cmap = file[cmap..cmap + be32(&file, record(&file, b"cmap") + 12)].to_vec();
    let mut file = FONT.to_vec();
    retag(&mut file, b"post", b"cmap");
    put_table(&mut file, b"cmap", &bad_cmap);
    let font = Font::new(&file);
    if let Ok(font) = &font {
        // Where the parser would trip: looking a character up.
        exercise(font, "Ag?", 12 * 64, 5000, 15000, 0);
    }
    assert_eq!(font.err(), Some(Malformed));
}

/// A table directory of 65 535 records (1 MiB of them, nearly all empty,
/// before the bundled font's own 13): the parser walks it with a `u16`
/// index that overflows after the last record.
#[test]
fn a_directory_of_65535_tables_is_malformed() {
    let own = be16(FONT, 4);
    let moved = (0xffff - own) * 16;
    let mut file = FONT[..12].to_vec();
    file[4..6].copy_from_slice(&0xffffu16.to_be_bytes());
    // Empty records (tag 0) first, to keep the directory sorted.
    file.resize(12 + moved, 0);
    for k in 0..own {
        let mut r = FONT[12 + 16 * k..][..16].to_vec();
        let at = (be32(&r, 8) + moved) as u32;
        r[8..12].copy_from_slice(&at.to_be_bytes());
        file.extend_from_slice(&r);
    }
    file.extend_from_slice(&FONT[12 + 16 * own..]);
    assert_eq!(Font::new(&file).err(), Some(Malformed));
    // One record fewer (the last empty one dropped) opens as the font.
    let mut fewer = file[..12].to_vec();
    fewer[4..6].copy_from_slice(&0xfffeu16.to_be_bytes());
    fewer.extend_from_slice(&file[12 + 16..12 + 16 * 0xffff]);
    fewer.extend(std::iter::repeat_n(0, 16));
    fewer.extend_from_slice(&file[12 + 16 * 0xffff..]);
    let font = Font::new(&fewer).unwrap();
    exercise(&font, "AV", 12 * 64, 5000, 15000, 0x20);
}

/// An `sbix` table (color bitmaps, which softedge does not draw) of 2^30
/// strikes: the parser reads their offsets when the face is opened.
#[test]
fn an_sbix_table_whose_strikes_run_past_it_is_malformed() {
    let mut file = FONT.to_vec();
    retag(&mut file, b"gasp", b"sbix");
    // Version 1, flags, count of strikes.
    put_table(&mut file, b"sbix", &[0, 1, 0, 0, 0x40, 0, 0, 0]);
    assert_eq!(Font::new(&file).err(), Some(Malformed));
    put_table(&mut file, b"sbix", &[0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0]);
    assert!(Font::new(&file).is_ok());
}

/// A version 1 `COLR` table (color layers) whose base glyph paint list
/// claims 2^30 records: the parser reads it when the face is opened (with
/// a `CPAL` palette table, which it parses first).
#[test]
fn a_colr_table_whose_paint_list_runs_past_it_is_malformed() {
    let mut file = FONT.to_vec();
    retag(&mut file, b"gasp", b"CPAL");
    // Version 0, entries per palette, 1 palette, no colors (at 14), the
    // palette's first color.
    put_table(
        &mut file,
        b"CPAL",
        &[0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 14, 0, 0],
    );
    retag(&mut file, b"post", b"COLR");
    let colr = |paints: u32| {
        // Version 1, no base glyphs or layers (v0 fields), base glyph
        // paint list at 34, no layer or clip list, no variations.
        let mut t = vec![0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0];
        t.extend_from_slice(&[0, 0, 0, 34]);
        t.extend_from_slice(&[0; 16]);
        t.extend_from_slice(&paints.to_be_bytes());
        t
    };
    put_table(&mut file, b"COLR", &colr(1 << 30));
    assert_eq!(Font::new(&file).err(), Some(Malformed));
    put_table(&mut file, b"COLR", &colr(0));
    assert!(Font::new(&file).is_ok());
}

/// A CFF INDEX: count, offset size, `count + 1` offsets (from 1), data.
fn cff_index(off_size: u8, offsets: &[u32], data: &[u8]) -> Vec<u8> {
    let mut v = ((offsets.len() - 1) as u16).to_be_bytes().to_vec();
    v.push(off_size);
    for o in offsets {
        v.extend_from_slice(&o.to_be_bytes()[4 - usize::from(off_size)..]);
    }
    v.extend_from_slice(data);
    v
}

/// A CFF DICT integer operand (5-byte form).
fn cff_int(n: u32) -> Vec<u8> {
    let mut v = vec![29];
    v.extend_from_slice(&n.to_be_bytes());
    v
}

/// The bundled font with `cff` for a `CFF ` table, next to its `glyf`
/// outlines or (`glyf` renamed away) instead of them.
fn with_cff(cff: &[u8], glyf: bool) -> Vec<u8> {
    let mut file = FONT.to_vec();
    retag(&mut file, b"gasp", b"CFF ");
    put_table(&mut file, b"CFF ", cff);
    if !glyf {
        retag(&mut file, b"glyf", b"glyx");
    }
    file
}

/// A CFF header: version 1.0, 4 bytes, 4-byte offsets.
const CFF_HEADER: [u8; 4] = [1, 0, 4, 4];

/// A CFF table whose Name INDEX has a last offset (4 bytes) 4 GB past the
/// table: the parser steps over it with an unchecked add, and its next
/// read (in a debug build) trips a `debug_assert`.
#[test]
fn a_cff_name_index_that_runs_past_its_table_is_malformed() {
    let mut cff = CFF_HEADER.to_vec();
    cff.extend(cff_index(4, &[1, u32::MAX], b""));
    assert_eq!(Font::new(&with_cff(&cff, true)).err(), Some(Malformed));
}

/// A CFF table whose CharStrings INDEX, which the Top DICT points to, has
/// a last offset 4 GB past the table: the parser reads the INDEX's data
/// with a length it checks only with a `debug_assert`.
#[test]
fn a_cff_char_strings_index_that_runs_past_its_table_is_malformed() {
    // Header, empty Name INDEX, a Top DICT INDEX of `21 CharStrings`, empty
    // String and Global Subrs INDEXes, the CharStrings INDEX at 21.
    let char_strings = |last: u32| {
        let mut cff = CFF_HEADER.to_vec();
        cff.extend([0, 0]);
        let mut top = cff_int(21);
        top.push(17);
        cff.extend(cff_index(1, &[1, 7], &top));
        cff.extend([0, 0, 0, 0]);
        assert_eq!(cff.len(), 21);
        cff.extend(cff_index(4, &[1, 2, last], &[14]));
        cff
    };
    assert_eq!(
        Font::new(&with_cff(&char_strings(u32::MAX), true)).err(),
        Some(Malformed)
    );
    assert!(Font::new(&with_cff(&char_strings(2), true)).is_ok());
}

/// A CID-keyed CFF font (no `glyf`) whose glyph 1 calls local subroutine 0
/// of font DICT 0, whose Private DICT's Subrs INDEX has a last offset 4 GB
/// past the table: the parser reads that INDEX when the glyph is drawn,
/// with a length it checks only with a `debug_assert`.
#[test]
fn a_cid_fonts_local_subrs_that_run_past_the_table_are_malformed() {
    let cid = |last: u32| {
        let mut cff = CFF_HEADER.to_vec();
        cff.extend([0, 0]);
        // ROS, charset at 56, FDArray at 62, FDSelect at 59, CharStrings
        // at 46.
        let mut top = vec![139, 139, 139, 12, 30];
        top.extend(cff_int(56));
        top.push(15);
        top.extend(cff_int(62));
        top.extend([12, 36]);
        top.extend(cff_int(59));
        top.extend([12, 37]);
        top.extend(cff_int(46));
        top.push(17);
        cff.extend(cff_index(1, &[1, 1 + top.len() as u32], &top));
        cff.extend([0, 0, 0, 0]);
        assert_eq!(cff.len(), 46);
        // Glyph 0: endchar; glyph 1: 0 callsubr endchar.
        cff.extend(cff_index(1, &[1, 2, 5], &[14, 139, 10, 14]));
        // Charset (format 0, glyph 1's name), FDSelect (format 0: both
        // glyphs in font DICT 0).
        cff.extend([0, 0, 1, 0, 0, 0]);
        // FDArray: one font DICT, its Private DICT (6 bytes at 78).
        let mut font_dict = cff_int(6);
        font_dict.extend(cff_int(78));
        font_dict.push(18);
        cff.extend(cff_index(1, &[1, 12], &font_dict));
        assert_eq!(cff.len(), 78);
        // The Private DICT: Subrs 6 bytes on, at 84.
        cff.extend(cff_int(6));
        cff.push(19);
        cff.extend(cff_index(4, &[1, 2, last], &[11]));
        cff
    };
    let bad = with_cff(&cid(u32::MAX), false);
    let font = Font::new(&bad);
    if let Ok(font) = &font {
        // Where the parser would trip: drawing glyph 1.
        exercise(font, "AV", 12 * 64, 5000, 15000, 0);
    }
    assert_eq!(font.err(), Some(Malformed));
    let sound = with_cff(&cid(2), false);
    let font = Font::new(&sound).unwrap();
    exercise(&font, "AV", 12 * 64, 5000, 15000, 0);
}

/// `OS/2`'s `usWinDescent` of 0x8000, where `hhea`'s and `OS/2`'s
/// typographic descenders are 0: the parser negates it as an `i16`.
#[test]
fn a_windows_descent_of_0x8000_is_the_least_descender() {
    let mut file = FONT.to_vec();
    let (hhea, os2) = (table_at(&file, b"hhea"), table_at(&file, b"OS/2"));
    file[hhea + 6..hhea + 8].fill(0);
    file[os2 + 70..os2 + 72].fill(0);
    file[os2 + 76..os2 + 78].copy_from_slice(&0x8000u16.to_be_bytes());
    let font = Font::new(&file).unwrap();
    assert_eq!(font.descender(), i16::MIN);
    assert!(font.line_height() > 32768);
    for opts in 0..4 {
        exercise(&font, "Ag\nAg", 12 * 64, 5000, 15000, opts);
    }
}

/// The bundled font with `gpos` for its GPOS table.
fn with_gpos(gpos: &[u8]) -> Vec<u8> {
    let mut file = FONT.to_vec();
    put_table(&mut file, b"GPOS", gpos);
    file
}

/// A GPOS table: no scripts, `lookups` (type, subtables), then one `kern`
/// feature naming the lookups `kern` (last, so that its list may run past
/// 64 KB).
fn gpos(kern: &[u16], lookups: &[(u16, Vec<Vec<u8>>)]) -> Vec<u8> {
    let mut list = (lookups.len() as u16).to_be_bytes().to_vec();
    let mut body = Vec::new();
    let heads = 2 + 2 * lookups.len();
    for (kind, subtables) in lookups {
        list.extend_from_slice(&((heads + body.len()) as u16).to_be_bytes());
        let mut lookup = [*kind, 0, subtables.len() as u16]
            .map(u16::to_be_bytes)
            .concat();
        let mut at = 6 + 2 * subtables.len();
        for s in subtables {
            lookup.extend_from_slice(&(at as u16).to_be_bytes());
            at += s.len();
        }
        lookup.extend(subtables.concat());
        body.extend(lookup);
    }
    list.extend(body);
    let features = (12 + list.len()) as u16;
    // Version 1.0, script list at 10 (empty), feature list, lookup list
    // at 12.
    let mut t = vec![0, 1, 0, 0, 0, 10];
    t.extend_from_slice(&features.to_be_bytes());
    t.extend_from_slice(&[0, 12, 0, 0]);
    t.extend(list);
    // One feature record, `kern` at 8; no parameters.
    t.extend_from_slice(&[0, 1, b'k', b'e', b'r', b'n', 0, 8, 0, 0]);
    t.extend_from_slice(&(kern.len() as u16).to_be_bytes());
    t.extend(kern.iter().flat_map(|i| i.to_be_bytes()));
    t
}

/// Big-endian `u16`s.
fn words(w: &[u16]) -> Vec<u8> {
    w.iter().flat_map(|w| w.to_be_bytes()).collect()
}

/// A pair adjustment subtable, format 1: `left` then `right` moves the
/// second glyph by `dx`.
fn pair_format1(left: u16, right: u16, dx: i16) -> Vec<u8> {
    // Format, coverage at 12, value formats (x-advance; none), one pair
    // set at 18; coverage: format 1, one glyph; the set: one record.
    words(&[1, 12, 4, 0, 1, 18, 1, 1, left, 1, right, dx as u16])
}

/// A pair adjustment subtable, format 2, of one class each: `left` then
/// any glyph moves the second glyph by `dx`.
fn pair_format2(left: u16, dx: i16) -> Vec<u8> {
    // Format, coverage at 18, value formats (x-advance; none), both class
    // definitions at 24, 1 x 1 classes, the record; coverage: format 1,
    // one glyph; classes: format 2, no ranges (all class 0).
    words(&[2, 18, 4, 0, 24, 24, 1, 1, dx as u16, 1, 1, left, 2, 0])
}

/// An extension subtable (format 1) of type `kind`, whose subtable
/// follows it.
fn extension(kind: u16, sub: &[u8]) -> Vec<u8> {
    let mut v = words(&[1, kind, 0, 8]);
    v.extend_from_slice(sub);
    v
}

/// A device table whose last size is below its first: the parser
/// subtracts them unchecked.
const BAD_DEVICE: [u16; 3] = [10, 5, 1];

/// A pair adjustment subtable of format 2 whose value records carry a
/// device table (x-advance device, flag 0x40): the parser reads the device
/// table with the record. Its x-advance is read here, not the device.
#[test]
fn gpos_device_tables_are_not_read() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    // Format 2, coverage at 20, value formats (x-advance and its device;
    // none), both class definitions at 26, 1 x 1 classes; the record
    // (-77, device at 30); coverage: format 1, glyph A; classes: format
    // 2, no ranges (all class 0); the device.
    let mut sub = words(&[
        2,
        20,
        0x44,
        0,
        26,
        26,
        1,
        1,
        -77i16 as u16,
        30,
        1,
        1,
        a.0,
        2,
        0,
    ]);
    sub.extend(words(&BAD_DEVICE));
    let file = with_gpos(&gpos(&[0], &[(2, vec![sub])]));
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -77);
    assert_eq!(font.kerning(v, a), 0);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}

/// The bundled font with a GPOS table whose `kern` feature names a lookup
/// of type `kind` with subtable `sub`, then a pair lookup: `A` then `V`
/// kerned by -42.
fn with_kern_lookups(kind: u16, sub: Vec<u8>) -> Vec<u8> {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    let lookups = [(kind, vec![sub]), (2, vec![pair_format1(a.0, v.0, -42)])];
    with_gpos(&gpos(&[0, 1], &lookups))
}

/// A single adjustment lookup (type 1) named by the `kern` feature, whose
/// value record has a device table: the parser parses every subtable of a
/// lookup it walks, and reads this one's device table at once. It holds
/// no pair kerning and is not read; the pair lookup after it is.
#[test]
fn a_single_adjustment_kern_lookup_is_skipped() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    // Format 1, coverage at 8, value format (x-advance device), the record
    // (device at 14); coverage: format 1, glyph A; the device.
    let mut single = words(&[1, 8, 0x40, 14, 1, 1, a.0]);
    single.extend(words(&BAD_DEVICE));
    let file = with_kern_lookups(1, single);
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -42);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}

/// A mark-to-base lookup (type 4) named by the `kern` feature, whose
/// anchor matrix is 65 535 x 65 535 offsets (8 GB): the parser parses it
/// as it walks the lookup, with a length it checks only with a
/// `debug_assert`. It holds no pair kerning and is not read.
#[test]
fn a_mark_to_base_kern_lookup_is_skipped() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    // Format 1, mark and base coverage at 12 (empty), 65 535 classes, mark
    // array at 16 (empty), base array at 18: 65 535 rows.
    let mark_to_base = words(&[1, 12, 12, 0xffff, 16, 18, 1, 0, 0, 0xffff]);
    let file = with_kern_lookups(4, mark_to_base);
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -42);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}

/// An extension lookup (type 9) whose subtable extends type 9 again, at
/// offset 0 (itself): the parser follows it until the stack overflows.
/// An extension of a pair subtable is read.
#[test]
fn an_extension_of_an_extension_kerns_nothing() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    let endless = words(&[1, 9, 0, 0]);
    let pair = extension(2, &pair_format1(a.0, v.0, -50));
    let file = with_gpos(&gpos(&[0, 1], &[(9, vec![endless]), (9, vec![pair])]));
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -50);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}

/// A pair lookup's subtables are read in turn until one has the pair,
/// as the parser reads them: one that does not cover the first glyph
/// (format 2 here) is passed over, not taken for a damaged one.
#[test]
fn a_pair_lookup_reads_on_past_a_subtable_without_the_pair() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    let subtables = vec![pair_format2(v.0, -10), pair_format1(a.0, v.0, -20)];
    let file = with_gpos(&gpos(&[0], &[(2, subtables)]));
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -20);
    assert_eq!(font.kerning(v, a), -10);
    assert_eq!(font.kerning(a, a), 0);
    // What ttf-parser itself reads from the same table.
    let gpos = font.face().tables().gpos.unwrap();
    let lookup = gpos.lookups.get(0).unwrap();
    let subtables: Vec<_> = lookup
        .subtables
        .into_iter::<ttf_parser::gpos::PositioningSubtable>()
        .collect();
    assert_eq!(subtables.len(), 2);
}

/// The bundled font's class-pair kerning subtable with 65 535 x 65 535
/// classes (8 GB of value records): the parser reads the matrix with a
/// length it checks only with a `debug_assert`. The subtable runs past
/// its table and kerns nothing.
#[test]
fn a_kerning_class_matrix_that_runs_past_its_table_kerns_nothing() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    assert!(font.kerning(a, v) < 0);
    let mut file = FONT.to_vec();
    let gpos = table_at(&file, b"GPOS");
    let lookup = gpos + be16(&file, gpos + 8) + be16(&file, gpos + be16(&file, gpos + 8) + 2);
    let sub = lookup + be16(&file, lookup + 6);
    assert_eq!(
        be16(&file, sub),
        2,
        "the bundled font's pair subtable is of format 2"
    );
    file[sub + 12..sub + 16].fill(0xff);
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), 0);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}

/// A `kern` feature that names 65 535 lookups (all lookup 0): walking the
/// parser's array of them to its end overflows the iterator's `u16`
/// index. They are read by index; lookup 0 counts once.
#[test]
fn a_kern_feature_of_65535_lookups_counts_each_once() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    let lookups = [(2, vec![pair_format1(a.0, v.0, -30)])];
    let file = with_gpos(&gpos(&[0; 0xffff], &lookups));
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), -30);
}

/// A legacy `kern` table in Apple's format (no GPOS) whose second subtable
/// claims 4 GB: the parser reads it with a length it checks only with a
/// `debug_assert`. The table kerns nothing.
#[test]
fn an_apple_kern_subtable_that_runs_past_its_table_kerns_nothing() {
    let font = Font::bundled().unwrap();
    let (a, v) = (font.glyph('A'), font.glyph('V'));
    let mut file = FONT.to_vec();
    retag(&mut file, b"GPOS", b"GPOX");
    let legacy = Font::new(&file).unwrap().kerning(a, v);
    assert!(legacy < 0, "the bundled font's legacy kern table kerns AV");
    // Version 1.0, 2 subtables: length 8 (header only), horizontal, format
    // 3; length 2^32 - 1, format 0.
    let mut kern = vec![0, 1, 0, 0, 0, 0, 0, 2];
    kern.extend_from_slice(&[0, 0, 0, 8, 0, 3, 0, 0]);
    kern.extend_from_slice(&[0xff, 0xff, 0xff, 0xff, 0, 0, 0, 0]);
    put_table(&mut file, b"kern", &kern);
    let font = Font::new(&file).unwrap();
    assert_eq!(font.kerning(a, v), 0);
    exercise(&font, "AVA", 12 * 64, 5000, 15000, 0x20);
}
