//! cargo-fuzz target for the text path (issue #17): the input is a font
//! file's bytes after a 4-byte header (size in 1/64 px, x, y, options) and a
//! string; a file that parses is drawn and measured with the string. No
//! input may panic.
//!
//! Needs the `fuzz/` crate (cargo-fuzz, `libfuzzer-sys`) and this entry in
//! its Cargo.toml:
//!
//! ```toml
//! [[bin]]
//! name = "text"
//! path = "fuzz_targets/text.rs"
//! test = false
//! doc = false
//! bench = false
//! ```
//!
//! Run: `cargo +nightly fuzz run text` (seed corpus: the bundled font,
//! `core/fonts/SoftedgeSans-Subset.ttf`, behind a 4-byte header and any
//! text). The same checks run on stable as proptest mutations in
//! `tests/tests/text_fuzz.rs`.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::text::{
    Alignment, Baseline, Font, FontStyle, LineHeight, Sharpen, Text, TextSize, TextStyle,
};
use softedge::{Band, BandBuffer};

fuzz_target!(|data: &[u8]| {
    let [size, x, y, opts, rest @ ..] = data else {
        return;
    };
    // The string is the last up-to-32 bytes (lossy UTF-8), the font the rest.
    let split = rest.len().saturating_sub(32);
    let (font_bytes, text_bytes) = rest.split_at(split);
    let text = String::from_utf8_lossy(text_bytes);
    let Ok(font) = Font::new(font_bytes) else {
        return;
    };
    let mut acc = [0i32; BandBuffer::<1>::acc_len(48, 16)];
    let mut cover = [0i32; BandBuffer::<1>::cover_len(48, 16)];
    let Ok(mut buf) = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(48, 0, 16)) else {
        return;
    };
    buf.clear([0]);
    let mut canvas = Canvas::new(&mut buf, None);
    let style = FontStyle::<1>::new(&font, 1, [4095])
        .with_size(TextSize::from_64ths(u32::from(*size) * 16 + 1))
        .with_kerning(opts & 1 != 0)
        .with_sharpen(if opts & 2 != 0 {
            Sharpen::GRID
        } else {
            Sharpen::NONE
        });
    let layout = TextStyle::new(
        [Alignment::Left, Alignment::Center, Alignment::Right][usize::from(opts >> 2) % 3],
        [
            Baseline::Top,
            Baseline::Bottom,
            Baseline::Middle,
            Baseline::Alphabetic,
        ][usize::from(opts >> 4) % 4],
        LineHeight::Percent(u32::from(*opts)),
    );
    let t = Text::with_text_style(
        &text,
        FinePoint::new(i32::from(*x as i8) * 256, i32::from(*y as i8) * 256),
        style,
        layout,
    );
    let _ = t.measure();
    let _ = t.draw(&mut canvas);
});
