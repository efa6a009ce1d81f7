//! [`GlyphSource`]: where rasterized glyphs come from — a
//! [`RasterFont`](super::RasterFont) in flash, or an outline font through
//! a [`GlyphCache`](super::GlyphCache) in RAM ([`CachedFont`](super::CachedFont)).
//!
//! Takes a character; gives its glyph, advance, kerning (fine units) and,
//! at a horizontal sub-pixel phase, its mask ([`GlyphMask`]): what the
//! text drawing of `text::masked` and the
//! embedded-graphics style [`AaTextStyle`](super::AaTextStyle) lay out and
//! draw.

use super::code::{CodeBytes, GlyphMask};

/// A font's vertical metrics at its size: fine units (1/1024 px), y up
/// for the ascender and descender; the rows its glyphs' masks can reach.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LineMetrics {
    /// Above the baseline (positive), fine units.
    pub ascender: i32,
    /// Below the baseline (negative), fine units.
    pub descender: i32,
    /// Between two baselines (ascender - descender + line gap), fine
    /// units.
    pub line_height: i32,
    /// The first pixel row any glyph's mask can reach, from the row below
    /// the baseline (negative: above it).
    pub ink_top: i32,
    /// One past the last row any glyph's mask can reach.
    pub ink_bottom: i32,
}

/// A source of rasterized glyphs (see [the module](self)).
pub trait GlyphSource {
    /// Where its masks' codes are (flash bytes, or a cache's cells).
    type Code: CodeBytes + ?Sized;

    /// Vertical metrics, fine units.
    fn line_metrics(&self) -> LineMetrics;

    /// Horizontal sub-pixel phases (1 = whole pixels).
    fn phases(&self) -> u8;

    /// The glyph of `c`, `None` when the font lacks it.
    fn glyph(&self, c: char) -> Option<u16>;

    /// The advance of glyph `g`, fine units.
    fn advance(&self, g: u16) -> i32;

    /// The kerning between glyphs `left` and `right`, fine units
    /// (negative: closer).
    fn kerning(&self, left: u16, right: u16) -> i32;

    /// Calls `f` with glyph `g`'s mask at `phase` (`0..phases()`); `None`
    /// when there is none (a cache without room for it).
    fn mask<R>(
        &self,
        g: u16,
        phase: u8,
        f: impl FnOnce(&GlyphMask<'_, Self::Code>) -> R,
    ) -> Option<R>;

    /// The outline of glyph `g`, for a glyph [`mask`](Self::mask) cannot
    /// give (drawn directly then): `None` for fonts without outlines.
    fn outline(&self, g: u16) -> Option<OutlineGlyph<'_>> {
        let _ = g;
        None
    }
}

/// What drawing a glyph's outline directly needs.
#[derive(Debug, Clone, Copy)]
pub struct OutlineGlyph<'f> {
    /// The font.
    pub font: &'f super::Font<'f>,
    /// The glyph.
    pub id: super::GlyphId,
    /// Font units to fine units.
    pub scale: super::Scale,
    /// How far flattened curves may stray.
    pub tolerance: crate::path::Tolerance,
}

impl<S: GlyphSource + ?Sized> GlyphSource for &S {
    type Code = S::Code;
    fn line_metrics(&self) -> LineMetrics {
        (**self).line_metrics()
    }
    fn phases(&self) -> u8 {
        (**self).phases()
    }
    #[inline]
    fn glyph(&self, c: char) -> Option<u16> {
        (**self).glyph(c)
    }
    #[inline]
    fn advance(&self, g: u16) -> i32 {
        (**self).advance(g)
    }
    #[inline]
    fn kerning(&self, left: u16, right: u16) -> i32 {
        (**self).kerning(left, right)
    }
    #[inline]
    fn mask<R>(
        &self,
        g: u16,
        phase: u8,
        f: impl FnOnce(&GlyphMask<'_, Self::Code>) -> R,
    ) -> Option<R> {
        (**self).mask(g, phase, f)
    }
    fn outline(&self, g: u16) -> Option<OutlineGlyph<'_>> {
        (**self).outline(g)
    }
}
