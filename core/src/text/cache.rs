//! [`GlyphCache`]: rasterized glyphs of an outline font kept in the
//! caller's RAM, and [`CachedFont`], an outline font at a size drawn
//! through one.
//!
//! Takes an outline [`Font`], a size (a [`Scale`]), and three slices of
//! the caller's: bytes for the glyphs' codes, [`CacheSlot`]s (one a glyph
//! kept) and `i32` cells the rasterizer walks edges into. Gives the
//! glyphs as masks ([`GlyphSource`]): a glyph met for the first time is
//! rasterized ([`rasterize_glyph`](super::rasterize_glyph)) and kept;
//! every later band and frame decodes it. So text in a font or size not
//! converted ahead costs its outline's parsing, flattening and edge walk
//! once per glyph, not once per band and frame.
//!
//! ## RAM
//!
//! - codes: what the glyphs need (the 5-bit code: about 48 bytes a glyph
//!   of DejaVu Sans at 16 px, 4.7 bits a pixel of its box, plus at most a
//!   byte); a label's distinct glyphs times that, times the phases used;
//! - slots: [`CacheSlot::SIZE`] bytes each, one a glyph and phase kept
//!   (a power of two of them is used, at least [`PROBES`]; a glyph is
//!   kept in one of the `PROBES` slots from its home slot, so give twice
//!   as many slots as glyphs in use, or more);
//! - scratch: `4 (width + 3)` bytes a row of the widest glyph's box; a
//!   scratch of fewer rows than the glyph is tall is walked again per
//!   strip (two passes), a scratch of less than one row cannot rasterize
//!   it.
//!
//! `softedge-sim font --cache` prints the figures for a font, size and
//! text. A glyph the cache cannot keep (wider than the scratch, longer
//! than the code bytes) is drawn from its outline directly, in the same
//! shape: it costs its walk in every band, but is drawn.
//!
//! ## Keeping and replacing
//!
//! A cache serves one font at one scale, tolerance and phase count at a
//! time (its *face*); given another, it forgets what it holds and starts
//! over (give each size its own cache). The codes are written round a
//! ring: a new glyph takes the bytes after the last one written, and the
//! glyphs whose bytes it takes are forgotten; a set whose four slots are
//! full forgets its least recently used glyph. All state is in `Cell`s:
//! the cache is shared (`&GlyphCache`) by every style that draws with it,
//! with nothing to borrow and nothing that can fail at run time.

use core::cell::Cell;

use super::code::GlyphMask;
use super::rasterize::{rasterize_glyph, MaskBox, RasterizeError};
use super::scale::{Scale, TextSize};
use super::source::{GlyphSource, LineMetrics, OutlineGlyph};
use super::{Font, GlyphId};
use crate::geom::FINE_ONE;
use crate::path::Tolerance;

/// Slots a glyph may be kept in: the ones from its home slot on.
pub const PROBES: usize = 8;

/// One glyph kept: which (glyph, phase), where its code is, its box, when
/// it was last used.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CacheSlot {
    key: u32,
    offset: u32,
    len: u32,
    mask: MaskBox,
    used: u32,
}

impl CacheSlot {
    /// An empty slot.
    pub const EMPTY: CacheSlot = CacheSlot {
        key: EMPTY_KEY,
        offset: 0,
        len: 0,
        mask: MaskBox {
            left: 0,
            top: 0,
            width: 0,
            height: 0,
        },
        used: 0,
    };

    /// Bytes of a slot.
    pub const SIZE: usize = core::mem::size_of::<CacheSlot>();
}

/// The key of no glyph.
const EMPTY_KEY: u32 = u32::MAX;

/// What a cache holds glyphs of: a font's data, scale, tolerance, phases.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct FaceKey {
    data: usize,
    len: usize,
    glyphs: u16,
    scale: Scale,
    tol: Tolerance,
    phases: u8,
}

/// Hits, misses and glyphs drawn from their outline, since the cache was
/// made or its counts were taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CacheStats {
    /// Glyphs found.
    pub hits: u32,
    /// Glyphs rasterized and kept.
    pub misses: u32,
    /// Glyphs that could not be kept (too wide for the scratch, too long
    /// for the code bytes): drawn from their outline.
    pub uncached: u32,
}

/// Rasterized glyphs over the caller's slices (see [the module](self)).
///
/// ```
/// use softedge::text::{CacheSlot, GlyphCache};
/// let mut codes = [0u8; 4096];
/// let mut slots = [CacheSlot::EMPTY; 64];
/// let mut scratch = [0i32; 32 * 32];
/// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
/// assert_eq!(cache.stats().misses, 0);
/// ```
#[derive(Debug)]
pub struct GlyphCache<'s> {
    codes: &'s [Cell<u8>],
    slots: &'s [Cell<CacheSlot>],
    scratch: &'s [Cell<i32>],
    face: Cell<Option<FaceKey>>,
    /// The next byte of the ring to write.
    head: Cell<usize>,
    /// Counts uses (the slots' `used` stamps).
    clock: Cell<u32>,
    stats: Cell<CacheStats>,
}

impl<'s> GlyphCache<'s> {
    /// A cache over `codes` (the glyphs' codes), `slots` (one a glyph
    /// kept; the largest power of two of them, at least [`PROBES`], is
    /// used) and `scratch` (the rasterizer's cells).
    pub fn new(codes: &'s mut [u8], slots: &'s mut [CacheSlot], scratch: &'s mut [i32]) -> Self {
        slots.fill(CacheSlot::EMPTY);
        Self {
            codes: Cell::from_mut(codes).as_slice_of_cells(),
            slots: Cell::from_mut(slots).as_slice_of_cells(),
            scratch: Cell::from_mut(scratch).as_slice_of_cells(),
            face: Cell::new(None),
            head: Cell::new(0),
            clock: Cell::new(0),
            stats: Cell::new(CacheStats::default()),
        }
    }

    /// The counts so far.
    pub fn stats(&self) -> CacheStats {
        self.stats.get()
    }

    /// The counts so far, set back to zero.
    pub fn take_stats(&self) -> CacheStats {
        self.stats.replace(CacheStats::default())
    }

    /// Forgets every glyph.
    pub fn clear(&self) {
        for s in self.slots {
            s.set(CacheSlot::EMPTY);
        }
        self.head.set(0);
        self.face.set(None);
    }

    /// Code bytes in use by the glyphs kept.
    pub fn used_bytes(&self) -> usize {
        self.slots
            .iter()
            .map(Cell::get)
            .filter(|s| s.key != EMPTY_KEY)
            .map(|s| s.len as usize)
            .sum()
    }

    /// Glyphs kept.
    pub fn glyphs(&self) -> usize {
        self.slots
            .iter()
            .filter(|s| s.get().key != EMPTY_KEY)
            .count()
    }

    /// The slots looked at for a key: [`PROBES`] from its home slot (its
    /// hash onto the largest power of two of slots that fits), wrapping
    /// round that table; empty when there are fewer than `PROBES` slots.
    #[inline]
    fn window(&self, key: u32) -> impl Iterator<Item = &Cell<CacheSlot>> + '_ {
        let n = self.slots.len();
        let bits = if n < PROBES {
            0
        } else {
            usize::BITS - 1 - n.leading_zeros()
        };
        let table = if bits == 0 { 0 } else { 1usize << bits };
        // Fibonacci hashing: the key times 2^32 / φ, its top bits.
        let home = if bits == 0 {
            0
        } else {
            (key.wrapping_mul(0x9e37_79b9) >> (32 - bits)) as usize
        };
        (0..if table == 0 { 0 } else { PROBES })
            .filter_map(move |k| self.slots.get((home + k) & (table.wrapping_sub(1))))
    }

    fn count(&self, f: impl FnOnce(&mut CacheStats)) {
        let mut s = self.stats.get();
        f(&mut s);
        self.stats.set(s);
    }

    /// The slot of `key`, if kept (its use stamped).
    #[inline]
    fn find(&self, key: u32) -> Option<CacheSlot> {
        let clock = self.clock.get().wrapping_add(1);
        self.clock.set(clock);
        for w in self.window(key) {
            let mut s = w.get();
            if s.key == key {
                s.used = clock;
                w.set(s);
                return Some(s);
            }
        }
        None
    }

    /// Rasterizes glyph `id` at `phase_fine` into the ring and a slot of
    /// the key's window; the slot, or why not.
    fn insert(
        &self,
        key: u32,
        o: &OutlineGlyph<'_>,
        phase_fine: i32,
    ) -> Result<CacheSlot, RasterizeError> {
        // Written from the ring's head; at the end of the codes, the
        // glyph is written again from the start (a rare second walk).
        let mut start = self.head.get();
        let mut result = self.write(o, phase_fine, start);
        if result == Err(RasterizeError::NoRoom) && start > 0 {
            start = 0;
            result = self.write(o, phase_fine, start);
        }
        let (mask, len) = result?;
        self.head.set(start + len);
        // The glyphs whose bytes were taken are forgotten.
        let end = start + len;
        for s in self.slots {
            let v = s.get();
            let (a, b) = (v.offset as usize, v.offset as usize + v.len as usize);
            if v.key != EMPTY_KEY && a < end && start < b {
                s.set(CacheSlot::EMPTY);
            }
        }
        // An empty slot of the key's window, or its least recently used.
        let victim = self
            .window(key)
            .min_by_key(|w| {
                let v = w.get();
                if v.key == EMPTY_KEY {
                    (0, 0)
                } else {
                    (1, u32::MAX - self.clock.get().wrapping_sub(v.used))
                }
            })
            .ok_or(RasterizeError::NoRoom)?;
        let slot = CacheSlot {
            key,
            offset: start as u32,
            len: len as u32,
            mask,
            used: self.clock.get(),
        };
        victim.set(slot);
        Ok(slot)
    }

    /// Writes the code from byte `start` on: its box and length.
    fn write(
        &self,
        o: &OutlineGlyph<'_>,
        phase_fine: i32,
        start: usize,
    ) -> Result<(MaskBox, usize), RasterizeError> {
        let room = self.codes.get(start..).unwrap_or(&[]);
        let mut at = 0usize;
        let mask = rasterize_glyph(
            o.font,
            o.id,
            o.scale,
            o.tolerance,
            phase_fine,
            self.scratch,
            |b| match room.get(at) {
                Some(c) => {
                    c.set(b);
                    at += 1;
                    true
                }
                None => false,
            },
        )?;
        Ok((mask, at))
    }

    /// Binds the cache to `face`, forgetting what it held for another.
    fn bind(&self, face: FaceKey) {
        if self.face.get() != Some(face) {
            self.clear();
            self.face.set(Some(face));
        }
    }
}

/// An outline font at a size, drawn through a [`GlyphCache`]: a
/// [`GlyphSource`] for the embedded-graphics style
/// [`AaTextStyle`](super::AaTextStyle) and for [`Text`](super::Text)
/// ([`FontStyle::with_cache`](super::FontStyle::with_cache)).
///
/// ```
/// use softedge::text::{CacheSlot, CachedFont, Font, GlyphCache, GlyphSource, TextSize};
/// let font = Font::bundled().unwrap();
/// let (mut codes, mut slots, mut scratch) = ([0u8; 2048], [CacheSlot::EMPTY; 32], [0i32; 512]);
/// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
/// let sans = CachedFont::new(&font, TextSize::px(16), &cache);
/// let a = sans.glyph('a').unwrap();
/// let width = sans.mask(a, 0, |m| m.width).unwrap(); // rasterized now
/// assert_eq!(sans.mask(a, 0, |m| m.width), Some(width)); // found
/// assert_eq!((cache.stats().misses, cache.stats().hits), (1, 1));
/// ```
#[derive(Debug, Clone, Copy)]
pub struct CachedFont<'f, 'c> {
    font: &'f Font<'f>,
    scale: Scale,
    tol: Tolerance,
    phases: u8,
    kerning: bool,
    cache: &'c GlyphCache<'c>,
}

impl<'f, 'c> CachedFont<'f, 'c> {
    /// `font` at `size`, through `cache`: four phases (glyphs placed to a
    /// quarter pixel), kerned, the default tolerance.
    pub fn new(font: &'f Font<'f>, size: TextSize, cache: &'c GlyphCache<'c>) -> Self {
        Self::with_scale(font, Scale::new(size, font.units_per_em()), cache)
    }

    /// With a scale of its own (a [`FontStyle`](super::FontStyle)'s, the
    /// x-height snapped).
    pub fn with_scale(font: &'f Font<'f>, scale: Scale, cache: &'c GlyphCache<'c>) -> Self {
        Self {
            font,
            scale,
            tol: Tolerance::DEFAULT,
            phases: 4,
            kerning: true,
            cache,
        }
    }

    /// With `n` horizontal phases (`1..=16`: 1 places glyphs on whole
    /// pixels, so a glyph is kept once for every position).
    pub fn with_phases(mut self, n: u8) -> Self {
        self.phases = n.clamp(1, 16);
        self
    }

    /// With a flattening tolerance.
    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.tol = tol;
        self
    }

    /// With or without kerning.
    pub fn with_kerning(mut self, on: bool) -> Self {
        self.kerning = on;
        self
    }

    /// The font.
    pub fn font(&self) -> &'f Font<'f> {
        self.font
    }

    fn face_key(&self) -> FaceKey {
        let data = self.font.face().raw_face().data;
        FaceKey {
            data: data.as_ptr() as usize,
            len: data.len(),
            glyphs: self.font.face().number_of_glyphs(),
            scale: self.scale,
            tol: self.tol,
            phases: self.phases,
        }
    }
}

impl GlyphSource for CachedFont<'_, '_> {
    type Code = [Cell<u8>];

    fn line_metrics(&self) -> LineMetrics {
        let f = self.font;
        let s = &self.scale;
        let fine = |v: i64| v.clamp(-(1 << 30), 1 << 30) as i32;
        let (_, y_min, _, y_max) = f.global_bbox();
        let row = |v: i64| (v.div_euclid(i64::from(FINE_ONE))) as i32;
        LineMetrics {
            ascender: fine(s.y_units(i32::from(f.ascender()))),
            descender: fine(s.y_units(i32::from(f.descender()))),
            line_height: fine(s.y_units(f.line_height())),
            // The font's box, a pixel more each way (as the rasterizer's).
            ink_top: row(-s.y_units(i32::from(y_max.max(y_min)))) - 1,
            ink_bottom: row(-s.y_units(i32::from(y_min.min(y_max)))) + 2,
        }
    }

    fn phases(&self) -> u8 {
        self.phases
    }

    #[inline]
    fn glyph(&self, c: char) -> Option<u16> {
        self.font.face().glyph_index(c).map(|g| g.0)
    }

    #[inline]
    fn advance(&self, g: u16) -> i32 {
        let a = self.scale.x_units(i32::from(self.font.advance(GlyphId(g))));
        a.clamp(-(1 << 30), 1 << 30) as i32
    }

    #[inline]
    fn kerning(&self, left: u16, right: u16) -> i32 {
        if !self.kerning {
            return 0;
        }
        let k = self
            .scale
            .x_units(self.font.kerning(GlyphId(left), GlyphId(right)));
        k.clamp(-(1 << 30), 1 << 30) as i32
    }

    fn mask<R>(
        &self,
        g: u16,
        phase: u8,
        f: impl FnOnce(&GlyphMask<'_, [Cell<u8>]>) -> R,
    ) -> Option<R> {
        let cache = self.cache;
        cache.bind(self.face_key());
        let phase = phase.min(self.phases - 1);
        let key = u32::from(g) << 8 | u32::from(phase);
        let slot = match cache.find(key) {
            Some(s) => {
                cache.count(|s| s.hits += 1);
                s
            }
            None => {
                let o = self.outline(g)?;
                let phase_fine = i32::from(phase) * FINE_ONE / i32::from(self.phases);
                match cache.insert(key, &o, phase_fine) {
                    Ok(s) => {
                        cache.count(|s| s.misses += 1);
                        s
                    }
                    Err(_) => {
                        cache.count(|s| s.uncached += 1);
                        return None;
                    }
                }
            }
        };
        let (a, b) = (slot.offset as usize, (slot.offset + slot.len) as usize);
        let code = cache.codes.get(a..b)?;
        let m = slot.mask;
        Some(f(&GlyphMask::new(m.left, m.top, m.width, m.height, code)))
    }

    fn outline(&self, g: u16) -> Option<OutlineGlyph<'_>> {
        Some(OutlineGlyph {
            font: self.font,
            id: GlyphId(g),
            scale: self.scale,
            tolerance: self.tol,
        })
    }
}
