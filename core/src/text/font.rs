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
//! directory plus a few numbers read once: 908 bytes on thumbv6m.
//! Every failure is a [`FontError`]; every look-up of a damaged table gives
//! "absent" (no glyph, zero advance, no kerning), never a panic.
//!
//! ## Damaged files
//!
//! `ttf-parser` checks some lengths read from the file only with a
//! `debug_assert` (or, in a few places, not at all: an unchecked `+`, `-`
//! or negation, a recursion through one table), so a damaged file can panic
//! a debug build — CI's fuzz targets run one — or, for the recursion,
//! overflow the stack of any build. [`Font::with_index`] reads those
//! places itself first, with the checked big-endian reads of this module,
//! and refuses the file ([`FontError::Malformed`]) when the parser would
//! trip while opening it or looking a glyph up: a collection whose faces
//! run past the file, a table directory of 65 535 records, a `cmap`
//! subtable, `sbix` strike list, `COLR` paint list or CFF INDEX whose
//! entries run past its table. Pair kerning from GPOS is read here, not
//! by the parser (its subtables' device tables, anchor matrices and
//! extension lookups are where it trips); a legacy `kern` subtable that
//! runs past its table, and a descender that the parser would negate out
//! of range, are read as no kerning and as `i16::MIN`.
//!
//! ## Integer ranges
//!
//! Font units are `i16` / `u16` as the file stores them; `units_per_em`
//! is checked to lie in `16..=16384` (the OpenType range), kerning sums of
//! up to [`MAX_KERN_LOOKUPS`] lookups are `i32`.

use core::cmp::Ordering;
use core::fmt;

use ttf_parser::{Face, FaceParsingError, GlyphId, RawFace, Tag};

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
    /// structures) is missing or damaged, or a table is damaged where the
    /// parser would panic reading it (see [the module](self)).
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

impl From<FaceParsingError> for FontError {
    fn from(e: FaceParsingError) -> Self {
        match e {
            FaceParsingError::UnknownMagic => Self::UnknownMagic,
            FaceParsingError::FaceIndexOutOfBounds => Self::FaceIndex,
            _ => Self::Malformed,
        }
    }
}

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
    /// GPOS's lookup list, found once (empty without GPOS kerning).
    lookup_list: Be<'a>,
    /// The legacy `kern` table can be read (see [`kern_fits`]).
    legacy_kern: bool,
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

/// Bytes of a font file or table, read big-endian. Every read is checked:
/// one that runs past the end is `None`, never a panic, and no position
/// arithmetic can overflow.
#[derive(Clone, Copy)]
struct Be<'a>(&'a [u8]);

impl<'a> Be<'a> {
    fn bytes<const N: usize>(self, at: usize) -> Option<[u8; N]> {
        self.0.get(at..at.checked_add(N)?)?.try_into().ok()
    }

    fn u8(self, at: usize) -> Option<u8> {
        self.0.get(at).copied()
    }

    fn u16(self, at: usize) -> Option<u16> {
        self.bytes(at).map(u16::from_be_bytes)
    }

    fn i16(self, at: usize) -> Option<i16> {
        self.bytes(at).map(i16::from_be_bytes)
    }

    fn u32(self, at: usize) -> Option<u32> {
        self.bytes(at).map(u32::from_be_bytes)
    }

    fn i32(self, at: usize) -> Option<i32> {
        self.bytes(at).map(i32::from_be_bytes)
    }

    fn len(self) -> usize {
        self.0.len()
    }

    /// The bytes from `at` on.
    fn sub(self, at: usize) -> Option<Be<'a>> {
        self.0.get(at..).map(Be)
    }

    /// The bytes a 16-bit offset at `at` points to (offsets count from the
    /// start of `self`).
    fn at16(self, at: usize) -> Option<Be<'a>> {
        self.sub(usize::from(self.u16(at)?))
    }

    /// True when `count` entries of `size` bytes from `at` lie inside.
    fn holds(self, at: usize, count: u64, size: u64) -> bool {
        (at as u64).saturating_add(count.saturating_mul(size)) <= self.len() as u64
    }
}

/// A binary search over `n` sorted entries: `probe(i)` compares entry `i`
/// with the key (`None`: the entry cannot be read).
fn search(n: usize, mut probe: impl FnMut(usize) -> Option<Ordering>) -> Option<usize> {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        match probe(mid)? {
            Ordering::Less => lo = mid + 1,
            Ordering::Greater => hi = mid,
            Ordering::Equal => return Some(mid),
        }
    }
    None
}

/// False for a font collection (`ttcf`) whose count of faces runs past the
/// file: refused before the parser reads the faces' offsets (an
/// out-of-file read it checks only with a `debug_assert`, so a debug build
/// would panic; found by the `text` fuzz target).
fn collection_fits(data: &[u8]) -> bool {
    let file = Be(data);
    match file.bytes::<4>(0) {
        Some(magic) if &magic == b"ttcf" => file
            .u32(8)
            .is_some_and(|faces| file.holds(12, faces.into(), 4)),
        _ => true,
    }
}

/// The bytes of every table record tagged `tag`, in file order, the way
/// the parser collects them: `Face::parse` walks the whole directory and
/// keeps the last record of each tag (`None` when its range runs past the
/// file). Not `RawFace::table`: that binary-searches the directory, and in
/// an unsorted one, or one that names a tag twice, it can find another
/// record than the parser uses.
fn records<'a>(raw: &RawFace<'a>, tag: &[u8; 4]) -> impl Iterator<Item = Option<Be<'a>>> {
    let (data, list, tag) = (raw.data, raw.table_records, Tag::from_bytes(tag));
    (0..list.len())
        .filter_map(move |i| list.get(i))
        .filter(move |r| r.tag == tag)
        .filter_map(move |r| {
            let start = usize::try_from(r.offset).ok()?;
            let end = start.checked_add(usize::try_from(r.length).ok()?)?;
            Some(data.get(start..end).map(Be))
        })
}

/// The table `tag` as the parser reads it (see [`records`]).
fn table<'a>(raw: &RawFace<'a>, tag: &[u8; 4]) -> Option<Be<'a>> {
    records(raw, tag).last().flatten()
}

/// False when opening the face, or looking a character up, would panic in
/// the parser (see [the module](self)); every record of a tag is checked,
/// whichever one the parser keeps.
fn directory_fits(raw: &RawFace<'_>) -> bool {
    // The parser walks the directory with a `u16` index that overflows
    // past the 65 535th record.
    raw.table_records.len() < u16::MAX
        && records(raw, b"cmap").flatten().all(cmap_fits)
        && records(raw, b"sbix").flatten().all(sbix_fits)
        && records(raw, b"COLR").flatten().all(colr_fits)
        && records(raw, b"CFF ").flatten().all(cff_fits)
}

/// False when a `cmap` subtable with a 32-bit count (formats 10, 12, 13
/// and 14) claims more entries than the table holds: refused before the
/// parser reads the subtable in `glyph_index` (its array read checks the
/// length only with a `debug_assert`, so a debug build would panic; found
/// by the `text` fuzz target: a format 13 subtable of 2^28 groups).
fn cmap_fits(cmap: Be<'_>) -> bool {
    let tables = cmap.u16(2).unwrap_or(0);
    (0..usize::from(tables)).all(|k| {
        // An encoding record: platform, encoding, offset of the subtable.
        let Some(sub) = cmap
            .u32(4 + 8 * k + 4)
            .and_then(|o| usize::try_from(o).ok())
            .and_then(|o| cmap.sub(o))
        else {
            return true;
        };
        // (where the count is, the header's size, an entry's size)
        let array = match sub.u16(0) {
            Some(10) => Some((16, 20, 2)),
            Some(12 | 13) => Some((12, 16, 12)),
            Some(14) => Some((6, 10, 11)),
            _ => None,
        };
        match array.and_then(|(at, head, size)| Some((sub.u32(at)?, head, size))) {
            Some((count, head, size)) => sub.holds(head, count.into(), size),
            None => true,
        }
    })
}

/// False when an `sbix` table's count of strikes (32-bit) runs past the
/// table: the parser reads the strikes' offsets when the face is opened,
/// with a length it checks only with a `debug_assert`.
fn sbix_fits(sbix: Be<'_>) -> bool {
    match (sbix.u16(0), sbix.u32(4)) {
        (Some(1), Some(strikes)) => sbix.holds(8, strikes.into(), 4),
        _ => true,
    }
}

/// False when a version 1 `COLR` table's base glyph paint list, layer list
/// or clip list (32-bit counts of 6, 4 and 7 byte records) runs past the
/// table: the parser reads all three when the face is opened (if a `CPAL`
/// table parses), with lengths it checks only with a `debug_assert`.
fn colr_fits(colr: Be<'_>) -> bool {
    // (offset of the list's offset, where its count is, a record's size);
    // a null offset of the first list still points at the table's start.
    let list_fits = |(field, count_at, size): (usize, usize, u64)| {
        let Some(list) = colr
            .u32(field)
            .filter(|&o| o != 0 || field == 14)
            .and_then(|o| colr.sub(usize::try_from(o).ok()?))
        else {
            return true;
        };
        list.u32(count_at)
            .is_none_or(|n| list.holds(count_at + 4, n.into(), size))
    };
    colr.u16(0) != Some(1)
        || [(14, 0, 6), (18, 0, 4), (22, 1, 7)]
            .into_iter()
            .all(list_fits)
}

/// The parser could panic (in a debug build) reading the bytes checked.
struct Refuse;

/// A CFF INDEX as the parser reads it: a count, an offset size, `count +
/// 1` offsets (from 1) and the data they point into.
struct CffIndex<'a> {
    count: u16,
    off_size: usize,
    offsets: Be<'a>,
    data: Be<'a>,
    /// Where the next structure starts in the table.
    end: usize,
}

impl<'a> CffIndex<'a> {
    /// The INDEX at `at` of the `CFF ` table: `Ok(None)` where the parser
    /// stops reading the table without harm (no count, an offset size
    /// outside `1..=4`, the offsets cut short), [`Refuse`] where the data
    /// runs past the table: the parser reads it with a length it checks
    /// only with a `debug_assert` (or, for the Name INDEX, steps over it
    /// with an unchecked add, and its next read trips).
    fn read(cff: Be<'a>, at: usize) -> Result<Option<Self>, Refuse> {
        let Some(count) = cff.u16(at) else {
            return Ok(None);
        };
        let empty = |end| Self {
            count: 0,
            off_size: 1,
            offsets: Be(&[]),
            data: Be(&[]),
            end,
        };
        if count == 0 {
            return Ok(Some(empty(at + 2)));
        }
        let off_size = match cff.u8(at + 2) {
            Some(n @ 1..=4) => usize::from(n),
            _ => return Ok(None),
        };
        let start = at + 3;
        let Some(offsets) = (usize::from(count) + 1)
            .checked_mul(off_size)
            .and_then(|len| cff.0.get(start..start.checked_add(len)?))
        else {
            return Ok(None);
        };
        let data_at = start + offsets.len();
        let mut index = empty(data_at);
        index.count = count;
        index.off_size = off_size;
        index.offsets = Be(offsets);
        // The last offset, less one, is the data's length (an offset of 0:
        // no data).
        let Some(len) = index
            .offset(usize::from(count))
            .and_then(|n| n.checked_sub(1))
        else {
            return Ok(Some(index));
        };
        let data = usize::try_from(len)
            .ok()
            .and_then(|len| cff.0.get(data_at..data_at.checked_add(len)?))
            .ok_or(Refuse)?;
        index.data = Be(data);
        index.end = data_at + data.len();
        Ok(Some(index))
    }

    /// Offset `i`, as stored (from 1).
    fn offset(&self, i: usize) -> Option<u32> {
        let at = i.checked_mul(self.off_size)?;
        (0..self.off_size).try_fold(0u32, |v, k| {
            Some(v << 8 | u32::from(self.offsets.u8(at.checked_add(k)?)?))
        })
    }

    /// Element `i`'s bytes.
    fn get(&self, i: usize) -> Option<Be<'a>> {
        let start = usize::try_from(self.offset(i)?.checked_sub(1)?).ok()?;
        let end = usize::try_from(self.offset(i.checked_add(1)?)?.checked_sub(1)?).ok()?;
        self.data.0.get(start..end).map(Be)
    }
}

/// An entry of a CFF DICT: an operator (two-byte ones as `1200 +` the
/// second byte) and the operands before it: how many, and the first two
/// (`None`: a real number, or cut short).
struct DictEntry {
    op: u16,
    count: usize,
    args: [Option<i32>; 2],
}

impl DictEntry {
    /// Operand `i` as an offset or length: `Ok(None)` when negative (the
    /// parser ignores it), [`Refuse`] when not an integer (the parser
    /// would read a real number as one; no sound font stores an offset
    /// so, and this reader does not decode them).
    fn offset(&self, i: usize) -> Result<Option<usize>, Refuse> {
        let v = self.args.get(i).copied().flatten().ok_or(Refuse)?;
        Ok(usize::try_from(v).ok())
    }
}

/// A CFF DICT's entries, in order, parsed the way the parser steps
/// through them.
struct Dict<'a> {
    bytes: Be<'a>,
    at: usize,
}

impl<'a> Dict<'a> {
    fn new(bytes: Be<'a>) -> Self {
        Self { bytes, at: 0 }
    }

    /// One operand byte `b0` (and the bytes after it): its value, if an
    /// integer.
    fn operand(&mut self, b0: u8) -> Option<i32> {
        let at = self.at;
        let (len, v) = match b0 {
            28 => (2, self.bytes.i16(at).map(i32::from)),
            29 => (4, self.bytes.i32(at)),
            30 => {
                // A real number: nibbles up to the first 0xf.
                let mut len = 0;
                while let Some(b) = self.bytes.u8(at.saturating_add(len)) {
                    len += 1;
                    if b >> 4 == 0xf || b & 0xf == 0xf {
                        break;
                    }
                }
                (len, None)
            }
            32..=246 => (0, Some(i32::from(b0) - 139)),
            247..=250 => (
                1,
                self.bytes
                    .u8(at)
                    .map(|b1| (i32::from(b0) - 247) * 256 + i32::from(b1) + 108),
            ),
            _ => (
                1,
                self.bytes
                    .u8(at)
                    .map(|b1| -(i32::from(b0) - 251) * 256 - i32::from(b1) - 108),
            ),
        };
        self.at = at.saturating_add(len);
        v
    }
}

impl Iterator for Dict<'_> {
    type Item = DictEntry;

    fn next(&mut self) -> Option<DictEntry> {
        let mut entry = DictEntry {
            op: 0,
            count: 0,
            args: [None; 2],
        };
        loop {
            let b0 = self.bytes.u8(self.at)?;
            self.at = self.at.saturating_add(1);
            match b0 {
                // Operators (12: the first byte of a two-byte one).
                0..=27 | 31 | 255 => {
                    entry.op = u16::from(b0);
                    if b0 == 12 {
                        entry.op = 1200 + u16::from(self.bytes.u8(self.at)?);
                        self.at = self.at.saturating_add(1);
                    }
                    return Some(entry);
                }
                _ => {
                    let v = self.operand(b0);
                    if let Some(arg) = entry.args.get_mut(entry.count) {
                        *arg = v;
                    }
                    entry.count = entry.count.saturating_add(1);
                }
            }
        }
    }
}

/// False when a CFF INDEX the parser reads runs past the `CFF ` table
/// (see [`CffIndex::read`]): the Name, Top DICT, String and Global Subrs
/// INDEXes, the CharStrings INDEX, the Private DICT's local Subrs and,
/// for a CID font, the FDArray and the local Subrs of each of its first
/// 256 font DICTs (read when a glyph is drawn). A DICT offset stored as a
/// real number is refused too.
fn cff_fits(cff: Be<'_>) -> bool {
    check_cff(cff).is_ok()
}

fn check_cff(cff: Be<'_>) -> Result<(), Refuse> {
    // Header: major version 1 (the parser reads no other), header size.
    let (Some(1), Some(header)) = (cff.u8(0), cff.u8(2)) else {
        return Ok(());
    };
    // The Name, Top DICT, String and Global Subrs INDEXes follow in turn.
    let mut at = usize::from(header).max(4);
    let mut top = None;
    for k in 0..4 {
        let Some(index) = CffIndex::read(cff, at)? else {
            return Ok(());
        };
        if k == 1 {
            top = index.get(0);
        }
        at = index.end;
    }
    for entry in Dict::new(top.unwrap_or(Be(&[]))) {
        match (entry.op, entry.count) {
            // CharStrings; FDArray, whose font DICTs name Private DICTs.
            (17, 1) | (1236, 1) => {
                let Some(index) = entry.offset(0)?.filter(|&o| o <= cff.len()) else {
                    continue;
                };
                let Some(index) = CffIndex::read(cff, index)? else {
                    continue;
                };
                if entry.op == 1236 {
                    for i in 0..usize::from(index.count).min(256) {
                        let font_dict = Dict::new(index.get(i).unwrap_or(Be(&[])));
                        for private in font_dict.filter(|e| (e.op, e.count) == (18, 2)) {
                            check_private(cff, &private)?;
                        }
                    }
                }
            }
            (18, 2) => check_private(cff, &entry)?,
            _ => {}
        }
    }
    Ok(())
}

/// The local Subrs INDEX of the Private DICT that a `Private` entry
/// (length, offset) points to.
fn check_private(cff: Be<'_>, private: &DictEntry) -> Result<(), Refuse> {
    let (Some(len), Some(start)) = (private.offset(0)?, private.offset(1)?) else {
        return Ok(());
    };
    let Some(dict) = start.checked_add(len).and_then(|end| cff.0.get(start..end)) else {
        return Ok(());
    };
    for entry in Dict::new(Be(dict)).filter(|e| (e.op, e.count) == (19, 1)) {
        // Subrs: an offset from the Private DICT's start.
        if let Some(subrs) = entry.offset(0)?.and_then(|o| start.checked_add(o)) {
            if subrs <= cff.len() {
                CffIndex::read(cff, subrs)?;
            }
        }
    }
    Ok(())
}

/// False when the legacy `kern` table is in Apple's format and one of its
/// subtables claims more bytes than the table holds: the parser's
/// subtable iterator reads it with a length (32-bit) it checks only with
/// a `debug_assert`. OpenType's format has 16-bit lengths: nothing to
/// check.
fn kern_fits(kern: Be<'_>) -> bool {
    if kern.u16(0) == Some(0) {
        return true;
    }
    // Apple's header is 8 bytes; each subtable's header is 8 bytes too:
    // length (header included), coverage, format, tuple index.
    let mut at = 8;
    while at < kern.len() {
        let (Some(len), Some(format)) = (kern.u32(at), kern.u8(at + 5)) else {
            return true;
        };
        // The parser stops at an unknown format or a length under 8.
        let Some(data) = usize::try_from(len).ok().and_then(|l| l.checked_sub(8)) else {
            return true;
        };
        if format > 3 {
            return true;
        }
        match (at + 8).checked_add(data) {
            Some(end) if end <= kern.len() => at = end,
            _ => return false,
        }
    }
    true
}

/// The lookups of a GPOS table's `kern` features: every `kern` feature
/// (one per script / language system) names its lookups; each lookup
/// counts once, the first [`MAX_KERN_LOOKUPS`] in the order the features
/// name them. As the parser lists features, the list ends at a feature
/// cut short.
fn kern_feature_lookups(gpos: Be<'_>) -> heapless::Vec<u16, MAX_KERN_LOOKUPS> {
    let mut lookups = heapless::Vec::new();
    let Some(features) = gpos.at16(6) else {
        return lookups;
    };
    // A feature record: tag, offset; a feature: parameters' offset, count,
    // lookup indices.
    for k in 0..usize::from(features.u16(0).unwrap_or(0)) {
        let record = 2 + 6 * k;
        let (Some(tag), Some(feature)) = (features.bytes::<4>(record), features.at16(record + 4))
        else {
            break;
        };
        let Some(n) = feature.u16(2).filter(|&n| feature.holds(4, n.into(), 2)) else {
            break;
        };
        if &tag != b"kern" {
            continue;
        }
        for i in 0..usize::from(n) {
            let Some(index) = feature.u16(4 + 2 * i) else {
                break;
            };
            if !lookups.contains(&index) && lookups.push(index).is_err() {
                break;
            }
        }
    }
    lookups
}

/// The first pair adjustment for `(left, right)` in a GPOS lookup's
/// subtables: a pair lookup (type 2), or an extension (type 9) of one.
/// Other types hold no pair kerning. As in the parser, the subtables end
/// at one it cannot read; an extension of an extension is one (the parser
/// would follow it forever).
fn lookup_kerning(lookup: Be<'_>, left: GlyphId, right: GlyphId) -> Option<i16> {
    // Type, flags, count, subtable offsets (and a mark filtering set when
    // flag 0x10 is set: a lookup cut short before it is not read).
    let (kind, flags, count) = (lookup.u16(0)?, lookup.u16(2)?, lookup.u16(4)?);
    let filter_set = u64::from(flags & 0x10 != 0);
    if !matches!(kind, 2 | 9) || !lookup.holds(6, u64::from(count) + filter_set, 2) {
        return None;
    }
    for k in 0..usize::from(count) {
        let mut sub = lookup.at16(6 + 2 * k)?;
        if kind == 9 {
            // Format 1, the extended type, a 32-bit offset from here.
            if sub.u16(0)? != 1 {
                return None;
            }
            match sub.u16(2)? {
                2 => sub = sub.sub(usize::try_from(sub.u32(4)?).ok()?)?,
                9 => return None,
                _ => continue,
            }
        }
        if let Some(dx) = pair_kerning(sub, left, right)? {
            return Some(dx);
        }
    }
    None
}

/// A GPOS value format (the low byte: the parser ignores the high one).
#[derive(Clone, Copy)]
struct ValueFormat(u8);

impl ValueFormat {
    /// A value record's size: 2 bytes per field present.
    fn len(self) -> usize {
        2 * self.0.count_ones() as usize
    }

    /// The x-advance of the value record at `at` (0 when absent), after
    /// its x- and y-placement if present; device tables are not read.
    fn x_advance(self, t: Be<'_>, at: usize) -> Option<i16> {
        if self.0 & 0x04 == 0 {
            return Some(0);
        }
        t.i16(at.checked_add(2 * (self.0 & 0x03).count_ones() as usize)?)
    }
}

/// A coverage table: the covered glyphs' indices.
enum Coverage<'a> {
    /// Format 1: sorted glyphs.
    Glyphs(Be<'a>, u16),
    /// Format 2: sorted ranges (first, last, index of the first).
    Ranges(Be<'a>, u16),
}

impl<'a> Coverage<'a> {
    fn read(t: Be<'a>) -> Option<Self> {
        let (format, n) = (t.u16(0)?, t.u16(2)?);
        match format {
            1 if t.holds(4, n.into(), 2) => Some(Self::Glyphs(t, n)),
            2 if t.holds(4, n.into(), 6) => Some(Self::Ranges(t, n)),
            _ => None,
        }
    }

    fn index(&self, g: GlyphId) -> Option<u16> {
        match *self {
            Self::Glyphs(t, n) => {
                let i = search(n.into(), |i| Some(t.u16(4 + 2 * i)?.cmp(&g.0)))?;
                u16::try_from(i).ok()
            }
            Self::Ranges(t, n) => {
                let i = search(n.into(), |i| range_cmp(t, 4 + 6 * i, g))?;
                let first = t.u16(4 + 6 * i)?;
                t.u16(8 + 6 * i)?.checked_add(g.0.checked_sub(first)?)
            }
        }
    }
}

/// How a range record (first, last glyph) at `at` compares with glyph `g`.
fn range_cmp(t: Be<'_>, at: usize, g: GlyphId) -> Option<Ordering> {
    let (first, last) = (t.u16(at)?, t.u16(at + 2)?);
    Some(if g.0 < first {
        Ordering::Greater
    } else if g.0 <= last {
        Ordering::Equal
    } else {
        Ordering::Less
    })
}

/// A class definition table: a glyph's class, 0 when it names none.
enum ClassDef<'a> {
    /// Format 1: the classes of consecutive glyphs from a first one.
    Array(Be<'a>, u16, u16),
    /// Format 2: sorted ranges (first, last, class).
    Ranges(Be<'a>, u16),
}

impl<'a> ClassDef<'a> {
    fn read(t: Be<'a>) -> Option<Self> {
        match t.u16(0)? {
            1 => {
                let (first, n) = (t.u16(2)?, t.u16(4)?);
                t.holds(6, n.into(), 2).then_some(Self::Array(t, first, n))
            }
            2 => {
                let n = t.u16(2)?;
                t.holds(4, n.into(), 6).then_some(Self::Ranges(t, n))
            }
            _ => None,
        }
    }

    fn class(&self, g: GlyphId) -> u16 {
        match *self {
            Self::Array(t, first, n) => {
                g.0.checked_sub(first)
                    .filter(|&i| i < n)
                    .and_then(|i| t.u16(6 + 2 * usize::from(i)))
            }
            Self::Ranges(t, n) => {
                search(n.into(), |i| range_cmp(t, 4 + 6 * i, g)).and_then(|i| t.u16(8 + 6 * i))
            }
        }
        .unwrap_or(0)
    }
}

/// The first glyph's x-advance adjustment for `(left, right)` in a pair
/// adjustment subtable (format 1: pair sets; format 2: class pairs):
/// `Some(None)` when the pair is not in it, `None` when the parser could
/// not read it as one (coverage, class definitions, pair set offsets or
/// class matrix damaged or running past it).
fn pair_kerning(sub: Be<'_>, left: GlyphId, right: GlyphId) -> Option<Option<i16>> {
    let format = sub.u16(0)?;
    let coverage = Coverage::read(sub.at16(2)?)?;
    let (first, second) = (
        ValueFormat(sub.bytes::<2>(4)?[1]),
        ValueFormat(sub.bytes::<2>(6)?[1]),
    );
    match format {
        1 => {
            // Pair sets, one per covered glyph: a count, then records of
            // the second glyph and two value records, sorted.
            let sets = sub.u16(8)?;
            if !sub.holds(10, sets.into(), 2) {
                return None;
            }
            let set = coverage
                .index(left)
                .filter(|&k| k < sets)
                .and_then(|k| sub.u16(10 + 2 * usize::from(k)))
                .filter(|&o| o != 0)
                .and_then(|o| sub.sub(o.into()));
            let Some(set) = set else {
                return Some(None);
            };
            let size = 2 + first.len() + second.len();
            let n = set.u16(0).filter(|&n| set.holds(2, n.into(), size as u64));
            let found =
                n.and_then(|n| search(n.into(), |i| Some(set.u16(2 + size * i)?.cmp(&right.0))));
            Some(found.and_then(|i| first.x_advance(set, 2 + size * i + 2)))
        }
        2 => {
            // Class definitions of the first and second glyphs, then a
            // matrix of value record pairs, class 1 by class 2.
            let classes = (
                ClassDef::read(sub.at16(8)?)?,
                ClassDef::read(sub.at16(10)?)?,
            );
            let (rows, cols) = (sub.u16(12)?, sub.u16(14)?);
            let size = first.len() + second.len();
            if !sub.holds(16, u64::from(rows) * u64::from(cols), size as u64) {
                return None;
            }
            let (row, col) = (classes.0.class(left), classes.1.class(right));
            if coverage.index(left).is_none() || row >= rows || col >= cols {
                return Some(None);
            }
            // Inside the matrix (checked above): no overflow.
            let cell = usize::from(row) * usize::from(cols) + usize::from(col);
            Some(first.x_advance(sub, 16 + cell * size))
        }
        _ => None,
    }
}

impl<'a> Font<'a> {
    /// Parses the first face of a font file.
    pub fn new(data: &'a [u8]) -> Result<Self, FontError> {
        Self::with_index(data, 0)
    }

    /// Parses face `index` of a font file or collection.
    pub fn with_index(data: &'a [u8], index: u32) -> Result<Self, FontError> {
        if !collection_fits(data) {
            return Err(FontError::Malformed);
        }
        // The table directory alone first: what the parser would trip on.
        if !directory_fits(&RawFace::parse(data, index)?) {
            return Err(FontError::Malformed);
        }
        let face = Face::parse(data, index)?;
        let upem = face.units_per_em();
        if !UNITS_PER_EM.contains(&upem) {
            return Err(FontError::UnitsPerEm(upem));
        }
        let t = face.tables();
        if t.glyf.is_none() && t.cff.is_none() {
            return Err(FontError::NoOutlines);
        }
        let raw = face.raw_face();
        // The GPOS table read here is the one the parser accepted.
        let (kern_lookups, lookup_list) = match (t.gpos, table(raw, b"GPOS")) {
            (Some(_), Some(gpos)) => (kern_feature_lookups(gpos), gpos.at16(8).unwrap_or(Be(&[]))),
            _ => (heapless::Vec::new(), Be(&[])),
        };
        let legacy_kern = t.kern.is_some() && table(raw, b"kern").is_some_and(kern_fits);
        // hhea's advanceWidthMax (bytes 10..12), which ttf-parser does not
        // expose; an em when it is missing or zero.
        let max_advance = table(raw, b"hhea")
            .and_then(|t| t.u16(10))
            .filter(|&a| a > 0)
            .unwrap_or(upem);
        Ok(Self {
            face,
            upem,
            max_advance,
            kern_lookups,
            lookup_list,
            legacy_kern,
        })
    }

    /// The bundled font: Softedge Sans Subset, DejaVu Sans 2.37 cut to
    /// printable ASCII and a few symbols (see [`bundled`](super::bundled)).
    /// It parses (tested); the `Result` is the same as for any file.
    pub fn bundled() -> Result<Font<'static>, FontError> {
        Font::new(super::bundled::SOFTEDGE_SANS)
    }

    /// The parser's face, for what this type does not expose. Its own
    /// look-ups are not guarded as this type's are: on a damaged file some
    /// can panic in a debug build (GPOS subtables, `Face::descender`; see
    /// [the module](self)).
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

    /// The characters of `text` the font lacks (line breaks are not
    /// characters), in order: what [`Text::draw`](super::Text::draw)
    /// reports and leaves out.
    ///
    /// ```
    /// let font = softedge::text::Font::bundled().unwrap();
    /// let missing: String = font.missing("24 °C\nÄ 中").collect();
    /// assert_eq!(missing, "Ä中");
    /// ```
    pub fn missing<'t>(&'t self, text: &'t str) -> impl Iterator<Item = char> + 't {
        text.chars()
            .filter(move |&c| c != '\n' && c != '\r' && !self.has_glyph(c))
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
    ///
    /// The parser's: `OS/2`'s typographic descender when its flags say
    /// so, else `hhea`'s, else (when that is 0) `OS/2`'s typographic
    /// one, else (when that is 0 too) `OS/2`'s `usWinDescent` negated.
    /// The parser reads that last one as an `i16` and negates it, which
    /// overflows for `0x8000`; it is negated here with wrap-around, as a
    /// release build of the parser does: `i16::MIN`.
    pub fn descender(&self) -> i16 {
        let t = self.face.tables();
        match t.os2 {
            Some(os2)
                if !os2.use_typographic_metrics()
                    && t.hhea.descender == 0
                    && os2.typographic_descender() == 0 =>
            {
                // usWinDescent: bytes 76..78 of OS/2 (every version has
                // them; the parser refuses a shorter table).
                table(self.face.raw_face(), b"OS/2")
                    .and_then(|t| t.i16(76))
                    .map_or(0, i16::wrapping_neg)
            }
            _ => self.face.descender(),
        }
    }

    /// The default distance between two baselines: ascender - descender +
    /// line gap, font units (at least 1).
    pub fn line_height(&self) -> i32 {
        let h = i32::from(self.ascender()) - i32::from(self.descender())
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
    /// first horizontal subtable that has the pair (none when one of an
    /// Apple-format table's subtables runs past the table).
    pub fn kerning(&self, left: GlyphId, right: GlyphId) -> i32 {
        if !self.kern_lookups.is_empty() {
            return self.gpos_kerning(left, right);
        }
        let (Some(kern), true) = (self.face.tables().kern, self.legacy_kern) else {
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

    /// The `kern` lookups' sum, read from the GPOS table here (see
    /// [`lookup_kerning`]); a lookup the list lacks adds nothing.
    fn gpos_kerning(&self, left: GlyphId, right: GlyphId) -> i32 {
        let list = self.lookup_list;
        // The lookup list: a count, then each lookup's offset (0: none).
        let count = list.u16(0).unwrap_or(0);
        let mut total = 0i32;
        for &index in self.kern_lookups.iter().filter(|&&i| i < count) {
            let lookup = list
                .u16(2 + 2 * usize::from(index))
                .filter(|&o| o != 0)
                .and_then(|o| list.sub(o.into()));
            if let Some(dx) = lookup.and_then(|l| lookup_kerning(l, left, right)) {
                total += i32::from(dx);
            }
        }
        total
    }
}
