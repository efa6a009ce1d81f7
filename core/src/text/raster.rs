//! [`RasterFont`]: a font rasterized ahead of time, a `static` in flash.
//!
//! Takes what `softedge-sim font` (or [`rasterize_glyph`] in a build
//! script) wrote: per glyph its exact-area coverage at each horizontal
//! sub-pixel phase, in the 5-bit code of [`code`](super::code), its
//! advance and its kerning classes; the character map as ranges; the
//! line metrics. Gives a [`GlyphSource`]: drawing a glyph is decoding its
//! mask into the band's coverage scratch and composing it, with no
//! parsing, no flattening and no edge walk.
//!
//! ```text
//! chars    [CharRange]   first character, count, first glyph (sorted)
//! glyphs   [RasterGlyph] advance (fine units >> advance_shift), kerning classes
//! offsets  [u16] or [u32] per glyph and phase: where its mask starts in `masks`
//! kerning  [i8]          left classes x right classes, fine units >> kern_shift
//! masks    [u8]          per mask: left (i8), top (i8), width, height, code
//! ```
//!
//! A glyph's mask at phase `p` of `P` is the coverage of its outline drawn
//! with its origin at `(p / P px, 0)`: its box starts `left` columns right
//! of the pixel the origin is in and `top` rows below the baseline (a
//! pixel boundary; `top < 0` above it). Drawn at a pen position `(x, y)`
//! (fine units), a glyph lands at its **drawn position**: `x` rounded to
//! the nearest `1/P` px and `y` to the nearest pixel boundary; the mask is
//! the exact area of the outline there, to its quantization (see
//! [`code`](super::code)).
//!
//! Everything is read through bounds-checked look-ups: a damaged table
//! draws less or nothing, never panics.
//!
//! [`rasterize_glyph`]: super::rasterize_glyph
//! [`GlyphSource`]: super::GlyphSource

use super::code::GlyphMask;
use super::source::{GlyphSource, LineMetrics};

/// Characters `first..first + len` of a [`RasterFont`], glyphs
/// `glyph..glyph + len`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CharRange {
    /// The first character (`char as u32`).
    pub first: u32,
    /// How many characters follow from it.
    pub len: u16,
    /// The glyph of `first`.
    pub glyph: u16,
}

/// A glyph of a [`RasterFont`]: advance and kerning classes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RasterGlyph {
    /// The advance, fine units shifted right by the font's
    /// `advance_shift`.
    pub advance: u16,
    /// Its row of the kerning matrix (0: no kerning as the left glyph).
    pub kern_left: u8,
    /// Its column of the kerning matrix (0: no kerning as the right
    /// glyph).
    pub kern_right: u8,
}

/// Where each glyph's mask at each phase starts in the mask bytes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MaskOffsets<'a> {
    /// Offsets below 2^16.
    Short(&'a [u16]),
    /// Any offsets.
    Long(&'a [u32]),
}

impl MaskOffsets<'_> {
    fn get(&self, i: usize) -> Option<usize> {
        match self {
            MaskOffsets::Short(o) => o.get(i).map(|&v| usize::from(v)),
            MaskOffsets::Long(o) => o.get(i).map(|&v| v as usize),
        }
    }

    fn bytes(&self) -> usize {
        match self {
            MaskOffsets::Short(o) => 2 * o.len(),
            MaskOffsets::Long(o) => 4 * o.len(),
        }
    }
}

/// The sizes and scales of a [`RasterFont`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RasterMetrics {
    /// The em it was rasterized at, 1/64 px.
    pub size_64ths: u32,
    /// Line metrics, fine units.
    pub line: LineMetrics,
    /// Horizontal sub-pixel phases per pixel (1..=16).
    pub phases: u8,
    /// Advances are stored in fine units `>> advance_shift`.
    pub advance_shift: u8,
    /// Kerning values are stored in fine units `>> kern_shift`.
    pub kern_shift: u8,
    /// Columns of the kerning matrix.
    pub kern_columns: u8,
}

/// A font rasterized ahead of time (see [the module](self)): a `static`
/// made by `softedge-sim font`.
///
/// ```
/// use softedge::text::{CharRange, GlyphSource, LineMetrics, MaskOffsets, RasterFont, RasterGlyph, RasterMetrics};
/// // One glyph, 'I': a bar of 2 x 3 whole pixels, 3 px advance, no kerning.
/// static I: RasterFont<'static> = RasterFont::new(
///     RasterMetrics {
///         size_64ths: 4 * 64,
///         line: LineMetrics { ascender: 3 * 1024, descender: -1024, line_height: 4 * 1024, ink_top: -3, ink_bottom: 0 },
///         phases: 1,
///         advance_shift: 0,
///         kern_shift: 0,
///         kern_columns: 1,
///     },
///     &[CharRange { first: 'I' as u32, len: 1, glyph: 0 }],
///     &[RasterGlyph { advance: 3 * 1024, kern_left: 0, kern_right: 0 }],
///     MaskOffsets::Short(&[0]),
///     &[0],
///     // left 0, top -3, 2 x 3; a run of 6 whole pixels (symbol 31, 6 - 2).
///     &[0, (-3i8) as u8, 2, 3, 31 | (6 - 2) << 5],
/// );
/// assert_eq!(I.glyph('I'), Some(0));
/// assert_eq!(I.glyph('J'), None);
/// assert_eq!(I.advance(0), 3 * 1024);
/// let mask = I.mask_at(0, 0).unwrap();
/// assert_eq!((mask.left, mask.top, mask.width, mask.height), (0, -3, 2, 3));
/// ```
#[derive(Debug, Clone, Copy)]
pub struct RasterFont<'a> {
    metrics: RasterMetrics,
    chars: &'a [CharRange],
    glyphs: &'a [RasterGlyph],
    offsets: MaskOffsets<'a>,
    kerning: &'a [i8],
    masks: &'a [u8],
}

/// Bytes of a mask's header: left, top, width, height.
pub(crate) const MASK_HEAD: usize = 4;

impl<'a> RasterFont<'a> {
    /// A font from its parts (what the generated source calls).
    pub const fn new(
        metrics: RasterMetrics,
        chars: &'a [CharRange],
        glyphs: &'a [RasterGlyph],
        offsets: MaskOffsets<'a>,
        kerning: &'a [i8],
        masks: &'a [u8],
    ) -> Self {
        Self {
            metrics,
            chars,
            glyphs,
            offsets,
            kerning,
            masks,
        }
    }

    /// Its sizes and scales.
    pub fn metrics(&self) -> &RasterMetrics {
        &self.metrics
    }

    /// The glyph of `c`, if the font has it.
    #[inline]
    pub fn glyph(&self, c: char) -> Option<u16> {
        let c = c as u32;
        // Most text is in the first range (ASCII): tried first.
        if let Some(r) = self.chars.first() {
            let i = c.wrapping_sub(r.first);
            if i < u32::from(r.len) {
                return Some(r.glyph.wrapping_add(i as u16));
            }
        }
        // The last range starting at or before `c`.
        let k = self.chars.partition_point(|r| r.first <= c);
        let r = self.chars.get(k.checked_sub(1)?)?;
        let i = c - r.first;
        (i < u32::from(r.len)).then(|| r.glyph.wrapping_add(i as u16))
    }

    /// The characters of `text` the font lacks (line breaks are not
    /// characters), in order.
    ///
    /// ```
    /// # use softedge::text::{CharRange, LineMetrics, MaskOffsets, RasterFont, RasterGlyph, RasterMetrics};
    /// # static DIGITS: RasterFont<'static> = RasterFont::new(
    /// #     RasterMetrics { size_64ths: 64, line: LineMetrics { ascender: 1024, descender: 0, line_height: 1024, ink_top: -1, ink_bottom: 0 }, phases: 1, advance_shift: 0, kern_shift: 0, kern_columns: 1 },
    /// #     &[CharRange { first: '0' as u32, len: 10, glyph: 0 }],
    /// #     &[], MaskOffsets::Short(&[]), &[], &[]);
    /// let missing: String = DIGITS.missing("12.5\n°C").collect();
    /// assert_eq!(missing, ".°C");
    /// ```
    pub fn missing<'t>(&'t self, text: &'t str) -> impl Iterator<Item = char> + 't {
        text.chars()
            .filter(move |&c| c != '\n' && c != '\r' && self.glyph(c).is_none())
    }

    /// The mask of glyph `g` at phase `phase`.
    pub fn mask_at(&self, g: u16, phase: u8) -> Option<GlyphMask<'a>> {
        let p = usize::from(phase.min(self.metrics.phases.saturating_sub(1)));
        let i = usize::from(g) * usize::from(self.metrics.phases.max(1)) + p;
        let at = self.offsets.get(i)?;
        let (head, code) = self.masks.get(at..)?.split_first_chunk::<MASK_HEAD>()?;
        let [left, top, width, height] = *head;
        Some(GlyphMask::new(
            i16::from(left as i8),
            i16::from(top as i8),
            u16::from(width),
            u16::from(height),
            code,
        ))
    }

    /// The bytes the font's tables and masks take in flash (the parts'
    /// lengths, without alignment padding).
    pub fn flash_bytes(&self) -> usize {
        core::mem::size_of::<Self>()
            + core::mem::size_of_val(self.chars)
            + core::mem::size_of_val(self.glyphs)
            + self.offsets.bytes()
            + self.kerning.len()
            + self.masks.len()
    }

    /// Glyphs in the font.
    pub fn glyph_count(&self) -> usize {
        self.glyphs.len()
    }
}

impl<'a> GlyphSource for RasterFont<'a> {
    type Code = [u8];

    fn line_metrics(&self) -> LineMetrics {
        self.metrics.line
    }

    fn phases(&self) -> u8 {
        self.metrics.phases.clamp(1, 16)
    }

    #[inline]
    fn glyph(&self, c: char) -> Option<u16> {
        RasterFont::glyph(self, c)
    }

    #[inline]
    fn advance(&self, g: u16) -> i32 {
        self.glyphs.get(usize::from(g)).map_or(0, |e| {
            i32::from(e.advance) << self.metrics.advance_shift.min(14)
        })
    }

    #[inline]
    fn kerning(&self, left: u16, right: u16) -> i32 {
        let (Some(l), Some(r)) = (
            self.glyphs.get(usize::from(left)),
            self.glyphs.get(usize::from(right)),
        ) else {
            return 0;
        };
        if l.kern_left == 0 || r.kern_right == 0 {
            return 0;
        }
        let at = usize::from(l.kern_left) * usize::from(self.metrics.kern_columns)
            + usize::from(r.kern_right);
        self.kerning
            .get(at)
            .map_or(0, |&k| i32::from(k) << self.metrics.kern_shift.min(20))
    }

    #[inline]
    fn mask<R>(&self, g: u16, phase: u8, f: impl FnOnce(&GlyphMask<'_, [u8]>) -> R) -> Option<R> {
        self.mask_at(g, phase).map(|m| f(&m))
    }
}
