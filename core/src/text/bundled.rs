//! The bundled font: **Softedge Sans Subset**, DejaVu Sans 2.37 (Bitstream
//! Vera licence; DejaVu's changes public domain) cut to printable ASCII
//! (U+0020..U+007E) and 30 symbols of instrument displays
//! (`° ± µ × ÷ · ² ³ ½ – — ‘ ’ “ ” • … € £ Ω ← ↑ → ↓ ≤ ≥ ≠ ≈ ∞ ✓`), 128
//! glyphs with `.notdef`, unhinted `glyf` outlines, GPOS and legacy `kern`
//! pair kerning: 16 648 bytes.
//!
//! Takes nothing; gives the font file's bytes, for [`Font::new`]
//! (or [`Font::bundled`]). The file, its licence
//! (`fonts/LICENSE-DejaVu.txt`: keep it with any copy of the font you
//! distribute, firmware included) and the script that regenerates it
//! (`fonts/make_subset.py`, fontTools' subsetter: a dev-time tool) are in
//! the crate's `fonts/` folder. The linker drops the bytes from any
//! firmware that does not use them.
//!
//! The same font rasterized ahead of time at 12 and 16 px ([`SANS_12`],
//! [`SANS_16`]: every character of the subset but `.notdef`, whole-pixel
//! positions, made by `softedge-sim font`, 6 364 and 8 200 bytes of
//! flash): [`RasterFont`](super::RasterFont)s to draw with no parsing at
//! all, through [`AaTextStyle`](super::AaTextStyle) or
//! [`RasterText`](super::RasterText).
//!
//! [`Font::new`]: super::Font::new
//! [`Font::bundled`]: super::Font::bundled

/// The font file (TrueType, 2048 units per em).
///
/// ```
/// assert_eq!(&softedge::text::bundled::SOFTEDGE_SANS[..4], &[0, 1, 0, 0]);
/// ```
pub static SOFTEDGE_SANS: &[u8] = include_bytes!("../../fonts/SoftedgeSans-Subset.ttf");

pub use super::sans12::SANS_12;
pub use super::sans16::SANS_16;
