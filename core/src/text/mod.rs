//! Anti-aliased text: fonts rasterized ahead of time (issue #33), outline
//! fonts through a glyph cache or drawn directly (issue #17), and
//! embedded-graphics' text idiom.
//!
//! The embedded-graphics way first: `Text` with an [`AaTextStyle`] in
//! place of a `MonoTextStyle` ([`eg`]), its glyphs from a [`RasterFont`]
//! (a `static` in flash made by `softedge-sim font`, or the crate's
//! [`bundled::SANS_16`]) or a [`CachedFont`] (an outline font at a size
//! through a [`GlyphCache`] in RAM). Both give glyph masks: the exact-area
//! coverage of each glyph's outline at its drawn position, decoded into
//! the band's coverage scratch and composed like any shape, in linear
//! light. [`RasterText`] is the same at sub-pixel positions in fine
//! units.
//!
//! The outline path takes a TrueType / OpenType font file (`glyf` or CFF
//! outlines) in flash
//! — `include_bytes!`, or the bundled [`bundled::SOFTEDGE_SANS`] — and a
//! string with a style; gives the canvas each line as one shape of glyph
//! outlines, placed and scaled on the fine grid (1/1024 px), so that text
//! is filled like any path: exact-area anti-aliasing, in linear light
//! (γ-correct after the tone stage), at any size from 1 to 2048 px, at
//! sub-pixel positions (1/1024 px), with pair kerning. A character a font
//! lacks is left out and reported ([`DrawError::MissingGlyph`]).
//!
//! [`DrawError::MissingGlyph`]: crate::DrawError::MissingGlyph
//!
//! ```
//! use softedge::canvas::Canvas;
//! use softedge::geom::FinePoint;
//! use softedge::text::{Baseline, Font, FontStyle, Text};
//! use softedge::{Band, BandBuffer};
//!
//! static FONT_FILE: &[u8] = softedge::text::bundled::SOFTEDGE_SANS; // or include_bytes!("my.ttf")
//! let font = Font::new(FONT_FILE).unwrap();
//! let style = FontStyle::<1>::new(&font, 12, [4095]);
//! // The top of the line's box at (2.25, 1) px.
//! let text = Text::with_baseline("24.5 °C", FinePoint::new(2 * 1024 + 256, 1024), style, Baseline::Top);
//!
//! let mut acc = [0i32; BandBuffer::<1>::acc_len(64, 16)];
//! let mut cover = [0i32; BandBuffer::<1>::cover_len(64, 16)];
//! let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(64, 0, 16)).unwrap();
//! buf.clear([0]);
//! let mut canvas = Canvas::new(&mut buf, None);
//! let next = text.draw(&mut canvas).unwrap();
//! assert!(next.x > 40 * 1024); // the pen after "C"
//! assert_eq!(text.measure().next_position, next);
//! ```
//!
//! ## The pieces
//!
//! | file | what |
//! | --- | --- |
//! | [`font`] | [`Font`]: the file parsed in place (`ttf-parser`), glyphs (`.notdef` for what it lacks), metrics, kerning, [`FontError`] |
//! | [`scale`] | [`TextSize`] (1/64 px) and [`Scale`]: font units to fine units, `(u * k) >> 24` |
//! | [`outline`] | [`Glyph`]: one glyph's outline on the fine grid, a [`Shape`](crate::path::Shape); where `f32` appears |
//! | [`run`] | [`GlyphRun`]: one line laid out (advances, kerning) as one shape and canvas outline |
//! | [`layout`] | [`Alignment`], [`Baseline`], [`LineHeight`], [`TextStyle`]: embedded-graphics' conventions |
//! | [`text`] | [`Text`] (draw, measure) and [`FontStyle`] (font, size, colour, opacity) |
//! | [`sharpen`] | [`Sharpen`]: baseline, x-height and glyph origins on the pixel grid, for 1-bit displays |
//! | [`one_bit`] | [`ContrastBoost`]: steeper coverage before 1-bit dithering (gain 2^shift, shifts only) |
//! | [`bundled`] | the bundled font's bytes (16 648), and the font rasterized ahead at 12 and 16 px |
//! | [`code`] | the 5-bit coverage code of rasterized glyphs ([`GlyphMask`], [`MaskDecoder`], [`MaskEncoder`]): levels `v / 29`, runs |
//! | [`rasterize`] | [`rasterize_glyph`]: one glyph's outline to its mask (the canvas's exact edge walk), for fonts made ahead and the cache |
//! | [`raster`] | [`RasterFont`]: a font rasterized ahead of time, a `static` (character ranges, advances, kerning classes, masks per phase) |
//! | [`cache`] | [`GlyphCache`] (caller RAM) and [`CachedFont`]: outline glyphs rasterized once |
//! | [`source`] | [`GlyphSource`]: what both give (glyphs, advances, kerning, masks), [`LineMetrics`] |
//! | `masked` | lines of masks into a band: the drawn positions, the scratch, one compose |
//! | [`raster_text`] | [`RasterText`]: rasterized glyphs at a fine position |
//! | [`eg`] | [`AaTextStyle`] (embedded-graphics' `TextRenderer`, `CharacterStyle`) and [`DrawAaText`] |
//!
//! ## Floating point
//!
//! Only in the font parser's outline callback: `ttf-parser` hands outline
//! points as `f32` (integer font units for `glyf`), which
//! [`outline::to_u64ths`] turns into integers at once (one `f32` multiply by
//! 64 and one conversion per coordinate); everything after is integer
//! fixed point. The parser itself computes composite-glyph transforms and
//! CFF charstrings in `f32` and CFF DICT operands in `f64`. On a Cortex-M0
//! all of these are soft-float library calls, per outline point or per
//! font opened (no FPU needed); the per-pixel loops never see a float. See
//! [`outline`].
//!
//! ## Bounded memory and work
//!
//! No heap. A [`Font`] is the parser's table directory on the stack (908
//! bytes on thumbv6m); drawing a glyph parses its outline in place (at most 32 levels
//! of composite glyphs, CFF's 48-operand stack) and flattens it with the
//! fixed-size [`Flattener`](crate::path::Flattener); nothing else is
//! stored. Each line is described again in every band it touches; a band
//! it misses is rejected from the font's global box without reading a
//! glyph. A malformed file is a [`FontError`] when it is opened; a table
//! damaged further in reads as absent (no glyph, no kerning, part of an
//! outline): never a panic.

pub mod bundled;
pub mod cache;
pub mod code;
#[cfg(feature = "embedded-graphics")]
pub mod eg;
pub mod font;
pub mod layout;
pub(crate) mod masked;
pub mod one_bit;
pub mod outline;
pub mod raster;
pub mod raster_text;
pub mod rasterize;
pub mod run;
mod sans12;
mod sans16;
pub mod scale;
pub mod sharpen;
pub mod source;
#[allow(clippy::module_inception)]
pub mod text;

pub use cache::{CacheStats, CachedFont, GlyphCache, MEMO, MEMO_WAYS, PROBES, SLOT_WORDS};
pub use code::{GlyphMask, MaskDecoder, MaskEncoder, BOOSTED_COVER, LEVEL_COVER, LEVEL_MAX};
#[cfg(feature = "embedded-graphics")]
pub use eg::{AaTextStyle, DrawAaText};
pub use font::{Font, FontError, MAX_KERN_LOOKUPS};
pub use layout::{Alignment, Baseline, LineHeight, TextStyle};
pub use one_bit::{ContrastBoost, MAX_CONTRAST_SHIFT};
pub use outline::Glyph;
pub use raster::{CharRange, MaskOffsets, RasterFont, RasterGlyph, RasterMetrics};
pub use raster_text::RasterText;
pub use rasterize::{rasterize_glyph, MaskBox, RasterizeError};
pub use run::GlyphRun;
pub use scale::{Scale, TextSize};
pub use sharpen::Sharpen;
pub use source::{GlyphSource, LineMetrics, OutlineGlyph};
pub use text::{FontStyle, Text, TextMetrics};
pub use ttf_parser::GlyphId;
