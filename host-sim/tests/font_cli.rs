//! `softedge-sim font` (issue #33): the fonts it made for the crate
//! (`text::bundled::SANS_12`, `SANS_16`) are what it makes now, missing
//! characters are named, bad arguments are refused.

use std::process::Command;

use softedge::path::Tolerance;
use softedge_sim::font_gen::{generate, parse_chars, FontSpec};

/// The bundled font's symbols beside ASCII (its subset's list).
const SYMBOLS: &str = "°±µ×÷·²³½–—‘’“”•…€£Ω←↑→↓≤≥≠≈∞✓";

fn bundled_spec(px: u32) -> FontSpec {
    let mut chars = parse_chars("ascii").unwrap();
    chars.extend(SYMBOLS.chars());
    FontSpec {
        name: format!("SANS_{px}"),
        size_64ths: px * 64,
        chars,
        phases: 1,
        tolerance: Tolerance::MIN,
        kerning: true,
        source_name: "SoftedgeSans-Subset.ttf (the bundled font)".into(),
        crate_path: "crate".into(),
        snap_x_height: false,
    }
}

#[test]
fn the_crates_rasterized_fonts_are_what_the_generator_makes() {
    for (px, committed) in [
        (12, include_str!("../../core/src/text/sans12.rs")),
        (16, include_str!("../../core/src/text/sans16.rs")),
    ] {
        let (source, report) =
            generate(softedge::text::bundled::SOFTEDGE_SANS, &bundled_spec(px)).unwrap();
        assert!(report.missing.is_empty());
        assert_eq!(report.glyphs, 125);
        assert!(
            source == committed,
            "core/src/text/sans{px}.rs is out of date: run \
             softedge-sim font --size {px} --chars ascii --text \"{SYMBOLS}\" \
             --name SANS_{px} --crate-path crate -o core/src/text/sans{px}.rs"
        );
    }
}

#[test]
fn missing_characters_are_named_and_left_out() {
    let out = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args([
            "font",
            "--size",
            "10",
            "--chars",
            "0x30-0x39,Ä",
            "--text",
            "°C",
        ])
        .output()
        .unwrap();
    assert!(out.status.success());
    let src = String::from_utf8(out.stdout).unwrap();
    let report = String::from_utf8(out.stderr).unwrap();
    assert!(src.contains("pub static FONT_10: softedge::text::RasterFont<'static>"));
    assert!(report.contains("missing (1): 'Ä' U+00C4"), "{report}");
    assert!(report.contains("FONT_10: 12 glyphs at 10 px"), "{report}");
    // The characters kept, in two ranges ('0'..'9', then 'C' and '°'
    // apart).
    assert!(src.contains("CharRange { first: 0x0030, len: 10, glyph: 0 }"));
}

#[test]
fn a_font_with_none_of_the_characters_or_a_bad_list_is_refused() {
    let sim = env!("CARGO_BIN_EXE_softedge-sim");
    let none = Command::new(sim)
        .args(["font", "--size", "12", "--chars", "U+4E2D"])
        .output()
        .unwrap();
    assert_eq!(none.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&none.stderr).contains("none of the characters"));
    for bad in [
        vec!["font", "--size", "0", "--chars", "ascii"],
        vec!["font", "--chars", "ascii"],
        vec!["font", "--size", "12", "--chars", "U+D800"],
        vec!["font", "--size", "12", "--phases", "17"],
    ] {
        let out = Command::new(sim).args(&bad).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad:?}");
    }
    assert!(parse_chars("U+0041-U+0040").is_err());
    assert_eq!(parse_chars("a,b,U+0063").unwrap(), vec!['a', 'b', 'c']);
}

#[test]
fn the_report_counts_every_byte_of_the_font() {
    let spec = FontSpec {
        phases: 2,
        crate_path: "softedge".into(),
        ..bundled_spec(16)
    };
    let (source, r) = generate(softedge::text::bundled::SOFTEDGE_SANS, &spec).unwrap();
    assert_eq!(
        r.flash_bytes,
        std::mem::size_of::<softedge::text::RasterFont<'static>>()
            + r.mask_bytes
            + r.offset_bytes
            + r.glyph_bytes
            + r.char_bytes
            + r.kern_bytes
    );
    // Two offsets a glyph, in u16 below 64 KiB of masks.
    assert_eq!(r.offset_bytes, 2 * 2 * r.glyphs);
    assert!(source.contains("phases: 2,"));
    assert!(r.text(&spec).contains("2 phase(s)"));
}
