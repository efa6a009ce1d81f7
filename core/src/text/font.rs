//! [`Font`]: a TrueType / OpenType font file in flash, parsed in place.
//!
//! Takes the bytes of a font file (`include_bytes!`, any `&'static [u8]` or
//! borrowed slice; a collection's face by index) and gives what layout and
//! drawing need, all in **font units** (integers, `units_per_em` to the
//! em): the glyph of a character (its `.notdef`, glyph 0, when the font
//! lacks it), advance widths, pair kerning (the GPOS `kern` feature's pair
//! adjustments, else the legacy `kern` table), the vertical metrics and the
//! outline of a glyph (see [`outline`](super::outline)).
//!
//! The file is parsed by `ttf-parser` (no heap, no unsafe, bounded
//! recursion: 32 levels of composite glyphs, CFF subroutines 10 deep with
//! 48 operands). Nothing is copied: a [`Font`] is the parser's table
//! directory plus a few numbers read once: 896 bytes on thumbv6m.
//! Every failure is a [`FontError`]; every look-up of a damaged table gives
//! "absent" (no glyph, zero advance, no kerning), never a panic.
//!
//! ## Integer ranges
//!
//! Font units are `i16` / `u16` as the file stores them; `units_per_em`
//! is checked to lie in `16..=16384` (the OpenType range), kerning sums of
//! up to [`MAX_KERN_LOOKUPS`] lookups are `i32`.

use core::fmt;

use ttf_parser::gpos::{PairAdjustment, PositioningSubtable};
use ttf_parser::{Face, GlyphId, Tag};

/// The most GPOS lookups of the `kern` feature that are applied; a font
/// with more has the first ones applied (bounded work per glyph pair).
pub const MAX_KERN_LOOKUPS: usize = 8;

/// The smallest and largest `units_per_em` accepted (OpenType's range).
pub const UNITS_PER_EM: core::ops::RangeInclusive<u16> = 16..=16384;

/// Why a font file was refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum FontError {
    /// Not a TrueType / OpenType file (or collection): unknown magic.
    UnknownMagic,
    /// A collection without the face asked for.
    FaceIndex,
    /// A required table (`head`, `hhea`, `maxp`, `hmtx`, `cmap`'s
    /// structures) is missing or damaged.
    Malformed,
    /// `units_per_em` outside `16..=16384`.
    UnitsPerEm(u16),
    /// Neither `glyf` nor `CFF ` outlines (a bitmap-only or variable-only
    /// font).
    NoOutlines,
}

impl fmt::Display for FontError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::UnknownMagic => f.write_str("not a TrueType or OpenType font file"),
            Self::FaceIndex => f.write_str("the font collection has no face of that index"),
            Self::Malformed => f.write_str("a required font table is missing or damaged"),
            Self::UnitsPerEm(u) => write!(f, "units per em {u} is outside 16..=16384"),
            Self::NoOutlines => f.write_str("the font has no glyf or CFF outlines"),
        }
    }
}

impl core::error::Error for FontError {}

/// A parsed font face: glyph look-up, metrics, kerning and outlines, read
/// from the file's bytes in place.
///
/// ```
/// use softedge::text::Font;
/// let font = Font::bundled().unwrap();
/// assert_eq!(font.units_per_em(), 2048);
/// let a = font.glyph('A');
/// assert_ne!(a, font.glyph('V'));
/// // A character the subset lacks is its .notdef, glyph 0.
/// assert_eq!(font.glyph('\u{4e2d}'), softedge::text::GlyphId(0));
/// // DejaVu Sans kerns "AV" tighter.
/// assert!(font.kerning(a, font.glyph('V')) < 0);
/// assert_eq!(Font::new(b"not a font").err(), Some(softedge::text::FontError::UnknownMagic));
/// ```
#[derive(Clone)]
pub struct Font<'a> {
    face: Face<'a>,
    upem: u16,
    max_advance: u16,
    kern_lookups: heapless::Vec<u16, MAX_KERN_LOOKUPS>,
}

impl fmt::Debug for Font<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Font")
            .field("units_per_em", &self.upem)
            .field("glyphs", &self.face.number_of_glyphs())
            .field("kern_lookups", &self.kern_lookups.len())
            .finish()
    }
}

/// False for a font collection (`ttcf`) whose count of faces runs past the
/// file: refused before the parser reads the faces' offsets (an
/// out-of-file read it checks only with a `debug_assert`, so a debug build
/// would panic; found by the `text` fuzz target).
fn collection_fits(data: &[u8]) -> bool {
    match (data.get(0..4), data.get(8..12)) {
        (Some(b"ttcf"), Some(&[a, b, c, d])) => {
            let faces = u64::from(u32::from_be_bytes([a, b, c, d]));
            12 + 4 * faces <= data.len() as u64
        }
        (Some(b"ttcf"), _) => false,
        _ => true,
    }
}

/// False when a `cmap` subtable with a 32-bit count (formats 10, 12, 13
/// and 14) claims more entries than the table holds: refused before the
/// parser reads the subtable in `glyph_index` (its array read checks the
/// length only with a `debug_assert`, so a debug build would panic; found
/// by the `text` fuzz target: a format 13 subtable of 2^28 groups).
fn cmap_fits(face: &Face<'_>) -> bool {
    let Some(cmap) = face.raw_face().table(Tag::from_bytes(b"cmap")) else {
        return true;
    };
    let u16_at = |d: &[u8], i: usize| d.get(i..i + 2).map(|b| u16::from_be_bytes([b[0], b[1]]));
    let u32_at = |d: &[u8], i: usize| {
        d.get(i..i + 4)
            .map(|b| u64::from(u32::from_be_bytes([b[0], b[1], b[2], b[3]])))
    };
    let tables = u16_at(cmap, 2).unwrap_or(0);
    (0..usize::from(tables)).all(|k| {
        // An encoding record: platform, encoding, offset of the subtable.
        let Some(sub) = u32_at(cmap, 4 + 8 * k + 4)
            .and_then(|o| usize::try_from(o).ok())
            .and_then(|o| cmap.get(o..))
        else {
            return true;
        };
        // (where the count is, the header's size, an entry's size)
        let array = match u16_at(sub, 0) {
            Some(10) => Some((16, 20, 2)),
            Some(12 | 13) => Some((12, 16, 12)),
            Some(14) => Some((6, 10, 11)),
            _ => None,
        };
        match array.and_then(|(at, head, size)| Some((u32_at(sub, at)?, head, size))) {
            Some((count, head, size)) => head + count * size <= sub.len() as u64,
            None => true,
        }
    })
}

impl<'a> Font<'a> {
    /// Parses the first face of a font file.
    pub fn new(data: &'a [u8]) -> Result<Self, FontError> {
        Self::with_index(data, 0)
    }

    /// Parses face `index` of a font file or collection.
    pub fn with_index(data: &'a [u8], index: u32) -> Result<Self, FontError> {
        use ttf_parser::FaceParsingError as E;
        if !collection_fits(data) {
            return Err(FontError::Malformed);
        }
        let face = Face::parse(data, index).map_err(|e| match e {
            E::UnknownMagic => FontError::UnknownMagic,
            E::FaceIndexOutOfBounds => FontError::FaceIndex,
            _ => FontError::Malformed,
        })?;
        if !cmap_fits(&face) {
            return Err(FontError::Malformed);
        }
        let upem = face.units_per_em();
        if !UNITS_PER_EM.contains(&upem) {
            return Err(FontError::UnitsPerEm(upem));
        }
        let t = face.tables();
        if t.glyf.is_none() && t.cff.is_none() {
            return Err(FontError::NoOutlines);
        }
        let mut kern_lookups = heapless::Vec::new();
        if let Some(gpos) = t.gpos {
            let kern = Tag::from_bytes(b"kern");
            // Every `kern` feature (one per script / language system) names
            // its lookups; each lookup counts once.
            for feature in gpos.features.into_iter().filter(|f| f.tag == kern) {
                for index in feature.lookup_indices {
                    if !kern_lookups.contains(&index) && kern_lookups.push(index).is_err() {
                        break;
                    }
                }
            }
        }
        // hhea's advanceWidthMax (bytes 10..12), which ttf-parser does not
        // expose; an em when it is missing or zero.
        let max_advance = face
            .raw_face()
            .table(Tag::from_bytes(b"hhea"))
            .and_then(|t| t.get(10..12))
            .map(|b| u16::from_be_bytes([b[0], b[1]]))
            .filter(|&a| a > 0)
            .unwrap_or(upem);
        Ok(Self {
            face,
            upem,
            max_advance,
            kern_lookups,
        })
    }

    /// The bundled font: Softedge Sans Subset, DejaVu Sans 2.37 cut to
    /// printable ASCII and a few symbols (see [`bundled`](super::bundled)).
    /// It parses (tested); the `Result` is the same as for any file.
    pub fn bundled() -> Result<Font<'static>, FontError> {
        Font::new(super::bundled::SOFTEDGE_SANS)
    }

    /// The parser's face, for what this type does not expose.
    pub fn face(&self) -> &Face<'a> {
        &self.face
    }

    /// Font units per em (`16..=16384`).
    pub fn units_per_em(&self) -> u16 {
        self.upem
    }

    /// The glyph of `c`, or `.notdef` (glyph 0) when the font lacks it.
    pub fn glyph(&self, c: char) -> GlyphId {
        self.face.glyph_index(c).unwrap_or(GlyphId(0))
    }

    /// True when the font has a glyph for `c`.
    pub fn has_glyph(&self, c: char) -> bool {
        self.face.glyph_index(c).is_some()
    }

    /// The advance width of a glyph, font units (0 when unknown).
    pub fn advance(&self, g: GlyphId) -> u16 {
        self.face.glyph_hor_advance(g).unwrap_or(0)
    }

    /// The largest advance of any glyph (`hhea`'s `advanceWidthMax`, an
    /// em when the table lacks it), font units.
    pub fn max_advance(&self) -> u16 {
        self.max_advance
    }

    /// The ascender (positive, above the baseline), font units.
    pub fn ascender(&self) -> i16 {
        self.face.ascender()
    }

    /// The descender (negative, below the baseline), font units.
    pub fn descender(&self) -> i16 {
        self.face.descender()
    }

    /// The default distance between two baselines: ascender - descender +
    /// line gap, font units (at least 1).
    pub fn line_height(&self) -> i32 {
        let h = i32::from(self.face.ascender()) - i32::from(self.face.descender())
            + i32::from(self.face.line_gap());
        h.max(1)
    }

    /// The height of lowercase `x` (OS/2, else the outline of `x`, else
    /// half an em), font units.
    pub fn x_height(&self) -> i16 {
        if let Some(h) = self.face.x_height().filter(|&h| h > 0) {
            return h;
        }
        self.face
            .glyph_index('x')
            .and_then(|g| self.face.glyph_bounding_box(g))
            .map(|r| r.y_max)
            .filter(|&h| h > 0)
            .unwrap_or((self.upem / 2) as i16)
    }

    /// The box that holds every glyph (the `head` table's), font units, y
    /// up: `(x_min, y_min, x_max, y_max)`.
    pub fn global_bbox(&self) -> (i16, i16, i16, i16) {
        let r = self.face.global_bounding_box();
        (r.x_min, r.y_min, r.x_max, r.y_max)
    }

    /// The kerning between two adjacent glyphs, font units (negative:
    /// closer): the x-advance adjustments of the GPOS `kern` feature's pair
    /// lookups (at most [`MAX_KERN_LOOKUPS`], each its first matching
    /// subtable), or, for a font without them, the legacy `kern` table's
    /// first horizontal subtable that has the pair.
    pub fn kerning(&self, left: GlyphId, right: GlyphId) -> i32 {
        if !self.kern_lookups.is_empty() {
            return self.gpos_kerning(left, right);
        }
        let Some(kern) = self.face.tables().kern else {
            return 0;
        };
        for st in kern.subtables {
            if st.horizontal && !st.variable && !st.has_cross_stream {
                if let Some(v) = st.glyphs_kerning(left, right) {
                    return i32::from(v);
                }
            }
        }
        0
    }

    fn gpos_kerning(&self, left: GlyphId, right: GlyphId) -> i32 {
        let Some(gpos) = self.face.tables().gpos else {
            return 0;
        };
        let mut total = 0i32;
        for &index in &self.kern_lookups {
            let Some(lookup) = gpos.lookups.get(index) else {
                continue;
            };
            for sub in lookup.subtables.into_iter::<PositioningSubtable>() {
                let PositioningSubtable::Pair(pair) = sub else {
                    continue;
                };
                if let Some(dx) = pair_advance(&pair, left, right) {
                    total += i32::from(dx);
                    break;
                }
            }
        }
        total
    }
}

/// The first glyph's x-advance adjustment of a pair subtable, if the pair
/// is in it.
fn pair_advance(pair: &PairAdjustment<'_>, left: GlyphId, right: GlyphId) -> Option<i16> {
    match pair {
        PairAdjustment::Format1 { coverage, sets } => {
            let k = coverage.get(left)?;
            let (v, _) = sets.get(k)?.get(right)?;
            Some(v.x_advance)
        }
        PairAdjustment::Format2 {
            coverage,
            classes,
            matrix,
        } => {
            coverage.get(left)?;
            let (v, _) = matrix.get((classes.0.get(left), classes.1.get(right)))?;
            Some(v.x_advance)
        }
    }
}
