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
//! [`Font::new`]: super::Font::new
//! [`Font::bundled`]: super::Font::bundled

/// The font file (TrueType, 2048 units per em).
///
/// ```
/// assert_eq!(&softedge::text::bundled::SOFTEDGE_SANS[..4], &[0, 1, 0, 0]);
/// ```
pub static SOFTEDGE_SANS: &[u8] = include_bytes!("../../fonts/SoftedgeSans-Subset.ttf");
