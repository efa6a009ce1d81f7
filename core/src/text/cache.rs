//! [`GlyphCache`]: rasterized glyphs of an outline font kept in the
//! caller's RAM, and [`CachedFont`], an outline font at a size drawn
//! through one.
//!
//! Takes an outline [`Font`], a size (a [`Scale`]), and three slices of
//! the caller's: bytes for the glyphs' codes, `u32` words for the glyphs'
//! slots ([`SLOT_WORDS`] a glyph kept) and `i32` cells the rasterizer
//! walks edges into. Gives the
//! glyphs as masks ([`GlyphSource`]): a glyph met for the first time is
//! rasterized ([`rasterize_glyph`]) and kept;
//! every later band and frame decodes it. So text in a font or size not
//! converted ahead costs its outline's parsing, flattening and edge walk
//! once per glyph, not once per band and frame.
//!
//! ## RAM
//!
//! - codes: what the glyphs need (the 5-bit code: about 48 bytes a glyph
//!   of DejaVu Sans at 16 px, 4.7 bits a pixel of its box, plus at most a
//!   byte); a label's distinct glyphs times that, times the phases used;
//! - slots: [`SLOT_WORDS`] words (24 bytes) each, one a glyph and phase
//!   kept (a power of two of them is used, at least [`PROBES`]; a glyph
//!   is kept in one of the `PROBES` slots from its home slot, so give
//!   twice as many slots as glyphs in use, or more);
//! - scratch: `4 (width + 3)` bytes a row of the widest glyph's box; a
//!   scratch of fewer rows than the glyph is tall is walked again per
//!   strip (two passes), a scratch of less than one row cannot rasterize
//!   it.
//!
//! - the [`GlyphCache`] itself: 1.4 KB (on 32-bit targets) of memos:
//!   [`MEMO`] characters' glyphs and advances and as many kerning pairs
//!   (in sets of [`MEMO_WAYS`]), so
//!   that laying a line out does not read the font's `cmap`, `hmtx` and
//!   GPOS tables again in every band (those reads cost more than drawing
//!   the glyphs), and the line metrics.
//!
//! `softedge-sim font` prints the code bytes and box widths of a font's
//! glyphs (what a cache of the same glyphs holds). A glyph the cache cannot keep (wider than the scratch, longer
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
/// Words of a slot: its key, its last use, where its code is and how
/// long, its box (two words).
pub const SLOT_WORDS: usize = 6;
/// Entries of each memo (characters, kerning pairs), in sets of
/// [`MEMO_WAYS`].
pub const MEMO: usize = 64;
/// Entries of a memo's set: a key is looked for in the four of its set.
pub const MEMO_WAYS: usize = 4;

/// Word offsets in a slot.
const KEY: usize = 0;
const USED: usize = 1;
const OFFSET: usize = 2;
const LEN: usize = 3;
const LEFT_TOP: usize = 4;
const WIDTH_HEIGHT: usize = 5;

/// The key of no glyph (and of no memo entry).
const EMPTY_KEY: u32 = u32::MAX;

/// What a cache holds glyphs of: a font's data, scale, tolerance, phases,
/// kerning.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct FaceKey {
    data: usize,
    len: usize,
    glyphs: u16,
    scale: Scale,
    tol: Tolerance,
    phases: u8,
    kerning: bool,
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
/// use softedge::text::{GlyphCache, SLOT_WORDS};
/// let mut codes = [0u8; 4096];
/// let mut slots = [0u32; 64 * SLOT_WORDS]; // 64 glyphs kept at most
/// let mut scratch = [0i32; 32 * 32];
/// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
/// assert_eq!(cache.stats().misses, 0);
/// ```
#[derive(Debug)]
pub struct GlyphCache<'s> {
    codes: &'s [Cell<u8>],
    slots: &'s [Cell<u32>],
    scratch: &'s [Cell<i32>],
    face: Cell<Option<FaceKey>>,
    metrics: Cell<Option<LineMetrics>>,
    /// Characters: `(char + 1, glyph or EMPTY_KEY when missing, advance)`,
    /// key 0 for none.
    chars: [Cell<(u32, u32, i32)>; MEMO],
    /// Kerning pairs: `(left << 16 | right, value)`.
    kerns: [Cell<(u32, i32)>; MEMO],
    /// The next way of a set to replace, per set of each memo (round
    /// robin).
    turn: Cell<u32>,
    /// The glyph and advance of the last character looked up.
    last: Cell<(u32, i32)>,
    /// The next byte of the ring to write.
    head: Cell<usize>,
    /// Counts uses (the slots' last-use stamps).
    clock: Cell<u32>,
    stats: Cell<CacheStats>,
}

impl<'s> GlyphCache<'s> {
    /// A cache over `codes` (the glyphs' codes), `slots` ([`SLOT_WORDS`]
    /// words a glyph kept; the largest power of two of slots that fits,
    /// at least [`PROBES`], is used) and `scratch` (the rasterizer's
    /// cells).
    pub fn new(codes: &'s mut [u8], slots: &'s mut [u32], scratch: &'s mut [i32]) -> Self {
        let cache = Self {
            codes: Cell::from_mut(codes).as_slice_of_cells(),
            slots: Cell::from_mut(slots).as_slice_of_cells(),
            scratch: Cell::from_mut(scratch).as_slice_of_cells(),
            face: Cell::new(None),
            metrics: Cell::new(None),
            chars: [const { Cell::new((0, 0, 0)) }; MEMO],
            kerns: [const { Cell::new((EMPTY_KEY, 0)) }; MEMO],
            last: Cell::new((EMPTY_KEY, 0)),
            turn: Cell::new(0),
            head: Cell::new(0),
            clock: Cell::new(0),
            stats: Cell::new(CacheStats::default()),
        };
        cache.clear();
        cache
    }

    /// The counts so far.
    pub fn stats(&self) -> CacheStats {
        self.stats.get()
    }

    /// The counts so far, set back to zero.
    pub fn take_stats(&self) -> CacheStats {
        self.stats.replace(CacheStats::default())
    }

    /// Forgets every glyph (and the memos).
    pub fn clear(&self) {
        for (i, w) in self.slots.iter().enumerate() {
            w.set(if i % SLOT_WORDS == KEY { EMPTY_KEY } else { 0 });
        }
        for c in &self.chars {
            c.set((0, 0, 0));
        }
        for k in &self.kerns {
            k.set((EMPTY_KEY, 0));
        }
        self.last.set((EMPTY_KEY, 0));
        self.metrics.set(None);
        self.head.set(0);
        self.face.set(None);
    }

    /// The slots: each [`SLOT_WORDS`] words.
    fn slot_list(&self) -> impl Iterator<Item = &[Cell<u32>]> + '_ {
        self.slots.chunks_exact(SLOT_WORDS)
    }

    /// Code bytes in use by the glyphs kept.
    pub fn used_bytes(&self) -> usize {
        self.slot_list()
            .filter(|s| word(s, KEY) != EMPTY_KEY)
            .map(|s| word(s, LEN) as usize)
            .sum()
    }

    /// Glyphs kept.
    pub fn glyphs(&self) -> usize {
        self.slot_list()
            .filter(|s| word(s, KEY) != EMPTY_KEY)
            .count()
    }

    /// The slots looked at for a key: [`PROBES`] from its home slot (its
    /// hash onto the largest power of two of slots that fits), wrapping
    /// round that table; none when there are fewer than `PROBES` slots.
    #[inline]
    fn window(&self, key: u32) -> impl Iterator<Item = &[Cell<u32>]> + '_ {
        let n = self.slots.len() / SLOT_WORDS;
        let bits = if n < PROBES {
            0
        } else {
            usize::BITS - 1 - n.leading_zeros()
        };
        let mask = (1usize << bits).wrapping_sub(1);
        // Fibonacci hashing: the key times 2^32 / φ, its top bits.
        let home = if bits == 0 {
            0
        } else {
            (key.wrapping_mul(0x9e37_79b9) >> (32 - bits)) as usize
        };
        (0..if bits == 0 { 0 } else { PROBES }).filter_map(move |k| {
            let at = ((home + k) & mask) * SLOT_WORDS;
            self.slots.get(at..at + SLOT_WORDS)
        })
    }

    fn count(&self, f: impl FnOnce(&mut CacheStats)) {
        let mut s = self.stats.get();
        f(&mut s);
        self.stats.set(s);
    }

    /// The slot of `key`, if kept (its use stamped).
    #[inline]
    fn find(&self, key: u32) -> Option<&[Cell<u32>]> {
        let clock = self.clock.get().wrapping_add(1);
        self.clock.set(clock);
        let s = self.window(key).find(|s| word(s, KEY) == key)?;
        set(s, USED, clock);
        Some(s)
    }

    /// Rasterizes glyph `id` at `phase_fine` into the ring and a slot of
    /// the key's window; the slot, or why not.
    fn insert(
        &self,
        key: u32,
        o: &OutlineGlyph<'_>,
        phase_fine: i32,
    ) -> Result<&[Cell<u32>], RasterizeError> {
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
        for s in self.slot_list() {
            let a = word(s, OFFSET) as usize;
            let b = a + word(s, LEN) as usize;
            if word(s, KEY) != EMPTY_KEY && a < end && start < b {
                set(s, KEY, EMPTY_KEY);
            }
        }
        // An empty slot of the key's window, or its least recently used.
        let clock = self.clock.get();
        let victim = self
            .window(key)
            .min_by_key(|s| {
                if word(s, KEY) == EMPTY_KEY {
                    (0, 0)
                } else {
                    (1, u32::MAX - clock.wrapping_sub(word(s, USED)))
                }
            })
            .ok_or(RasterizeError::NoRoom)?;
        set(victim, KEY, key);
        set(victim, USED, clock);
        set(victim, OFFSET, start as u32);
        set(victim, LEN, len as u32);
        set(victim, LEFT_TOP, pack(mask.left as u16, mask.top as u16));
        set(victim, WIDTH_HEIGHT, pack(mask.width, mask.height));
        Ok(victim)
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
    #[inline]
    fn bind(&self, face: &FaceKey) {
        if self.face.get().as_ref() != Some(face) {
            self.clear();
            self.face.set(Some(*face));
        }
    }
}

/// Word `i` of a slot.
#[inline]
fn word(s: &[Cell<u32>], i: usize) -> u32 {
    s.get(i).map_or(0, Cell::get)
}

/// Sets word `i` of a slot.
#[inline]
fn set(s: &[Cell<u32>], i: usize, v: u32) {
    if let Some(w) = s.get(i) {
        w.set(v);
    }
}

/// Two halves in a word, `a` low.
const fn pack(a: u16, b: u16) -> u32 {
    a as u32 | (b as u32) << 16
}

/// The set of a memo's key: its [`MEMO_WAYS`] entries (the set from the
/// top bits of the key's Fibonacci hash).
#[inline]
fn memo_set<T>(memo: &[T; MEMO], key: u32) -> &[T] {
    const SETS: usize = MEMO / MEMO_WAYS;
    let set = (key.wrapping_mul(0x9e37_79b9) >> (32 - SETS.trailing_zeros())) as usize;
    memo.get(set * MEMO_WAYS..set * MEMO_WAYS + MEMO_WAYS)
        .unwrap_or(&[])
}

impl GlyphCache<'_> {
    /// The way of a set to replace next (the sets take turns on one
    /// counter: close enough to round robin for a memo).
    #[inline]
    fn next_way(&self) -> usize {
        let t = self.turn.get().wrapping_add(1);
        self.turn.set(t);
        t as usize % MEMO_WAYS
    }
}

/// An outline font at a size, drawn through a [`GlyphCache`]: a
/// [`GlyphSource`] for the embedded-graphics style
/// [`AaTextStyle`](super::AaTextStyle) and for [`Text`](super::Text)
/// ([`FontStyle::with_cache`](super::FontStyle::with_cache)).
///
/// ```
/// use softedge::text::{CachedFont, Font, GlyphCache, GlyphSource, TextSize, SLOT_WORDS};
/// let font = Font::bundled().unwrap();
/// let (mut codes, mut slots, mut scratch) = ([0u8; 2048], [0u32; 32 * SLOT_WORDS], [0i32; 512]);
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
    face: FaceKey,
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
        let data = font.face().raw_face().data;
        Self {
            font,
            face: FaceKey {
                data: data.as_ptr() as usize,
                len: data.len(),
                glyphs: font.face().number_of_glyphs(),
                scale,
                tol: Tolerance::DEFAULT,
                phases: 4,
                kerning: true,
            },
            cache,
        }
    }

    /// With `n` horizontal phases (`1..=16`: 1 places glyphs on whole
    /// pixels, so a glyph is kept once for every position).
    pub fn with_phases(mut self, n: u8) -> Self {
        self.face.phases = n.clamp(1, 16);
        self
    }

    /// With a flattening tolerance.
    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.face.tol = tol;
        self
    }

    /// With or without kerning.
    pub fn with_kerning(mut self, on: bool) -> Self {
        self.face.kerning = on;
        self
    }

    /// The font.
    pub fn font(&self) -> &'f Font<'f> {
        self.font
    }

    /// The glyph and advance of `c`, from the font (`(EMPTY_KEY, 0)` when
    /// it lacks it).
    fn look_up(&self, c: char) -> (u32, i32) {
        match self.font.face().glyph_index(c) {
            Some(g) => {
                let a = self.face.scale.x_units(i32::from(self.font.advance(g)));
                (u32::from(g.0), a.clamp(-(1 << 30), 1 << 30) as i32)
            }
            None => (EMPTY_KEY, 0),
        }
    }
}

impl GlyphSource for CachedFont<'_, '_> {
    type Code = [Cell<u8>];

    fn line_metrics(&self) -> LineMetrics {
        let cache = self.cache;
        cache.bind(&self.face);
        if let Some(m) = cache.metrics.get() {
            return m;
        }
        let f = self.font;
        let s = &self.face.scale;
        let fine = |v: i64| v.clamp(-(1 << 30), 1 << 30) as i32;
        let (_, y_min, _, y_max) = f.global_bbox();
        let row = |v: i64| (v.div_euclid(i64::from(FINE_ONE))) as i32;
        let m = LineMetrics {
            ascender: fine(s.y_units(i32::from(f.ascender()))),
            descender: fine(s.y_units(i32::from(f.descender()))),
            line_height: fine(s.y_units(f.line_height())),
            // The font's box, a pixel more each way (as the rasterizer's).
            ink_top: row(-s.y_units(i32::from(y_max.max(y_min)))) - 1,
            ink_bottom: row(-s.y_units(i32::from(y_min.min(y_max)))) + 2,
        };
        cache.metrics.set(Some(m));
        m
    }

    fn phases(&self) -> u8 {
        self.face.phases
    }

    #[inline]
    fn glyph(&self, c: char) -> Option<u16> {
        let cache = self.cache;
        cache.bind(&self.face);
        let key = (c as u32).wrapping_add(1);
        let set = memo_set(&cache.chars, key);
        let (g, adv) = match set.iter().map(Cell::get).find(|m| m.0 == key) {
            Some((_, g, adv)) => (g, adv),
            None => {
                let (g, adv) = self.look_up(c);
                if let Some(m) = set.get(cache.next_way()) {
                    m.set((key, g, adv));
                }
                (g, adv)
            }
        };
        cache.last.set((g, adv));
        u16::try_from(g).ok()
    }

    #[inline]
    fn advance(&self, g: u16) -> i32 {
        let (last, adv) = self.cache.last.get();
        if last == u32::from(g) {
            return adv;
        }
        let a = self
            .face
            .scale
            .x_units(i32::from(self.font.advance(GlyphId(g))));
        a.clamp(-(1 << 30), 1 << 30) as i32
    }

    #[inline]
    fn kerning(&self, left: u16, right: u16) -> i32 {
        if !self.face.kerning {
            return 0;
        }
        let cache = self.cache;
        cache.bind(&self.face);
        let key = u32::from(left) << 16 | u32::from(right);
        let set = memo_set(&cache.kerns, key);
        if let Some((_, v)) = set.iter().map(Cell::get).find(|m| m.0 == key) {
            return v;
        }
        let k = self
            .face
            .scale
            .x_units(self.font.kerning(GlyphId(left), GlyphId(right)));
        let k = k.clamp(-(1 << 30), 1 << 30) as i32;
        if let Some(m) = set.get(cache.next_way()) {
            m.set((key, k));
        }
        k
    }

    fn mask<R>(
        &self,
        g: u16,
        phase: u8,
        f: impl FnOnce(&GlyphMask<'_, [Cell<u8>]>) -> R,
    ) -> Option<R> {
        let cache = self.cache;
        cache.bind(&self.face);
        let phase = phase.min(self.face.phases - 1);
        let key = u32::from(g) << 8 | u32::from(phase);
        let slot = match cache.find(key) {
            Some(s) => {
                cache.count(|s| s.hits += 1);
                s
            }
            None => {
                let o = self.outline(g)?;
                let phase_fine = i32::from(phase) * FINE_ONE / i32::from(self.face.phases);
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
        let a = word(slot, OFFSET) as usize;
        let code = cache.codes.get(a..a + word(slot, LEN) as usize)?;
        let (lt, wh) = (word(slot, LEFT_TOP), word(slot, WIDTH_HEIGHT));
        Some(f(&GlyphMask::new(
            lt as u16 as i16,
            (lt >> 16) as u16 as i16,
            wh as u16,
            (wh >> 16) as u16,
            code,
        )))
    }

    fn outline(&self, g: u16) -> Option<OutlineGlyph<'_>> {
        Some(OutlineGlyph {
            font: self.font,
            id: GlyphId(g),
            scale: self.face.scale,
            tolerance: self.face.tol,
        })
    }
}
