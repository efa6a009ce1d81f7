//! Set-up kept from one band to the next, in caller-provided slots.
//!
//! A frame is drawn band by band and every band draws the same shapes in
//! the same order; what a shape's set-up computes (an edge's step
//! constants and where its walk stopped, a triangle's Gouraud plane) is the
//! same in every band. The cache keeps it, keyed by the shape's place in
//! the drawing order and the edge's place in the shape, so that the next
//! band resumes each walk instead of starting it over with divisions: the
//! per-band cost of a shape is then its walk, whatever the band height.
//!
//! Every entry also records what it was made from (an edge's end points, a
//! plane's vertices and colours) and is used only when that matches, so a
//! drawing closure that draws something else in a later band gets correct
//! pixels, only without the saving. A full cache is not an error either:
//! an edge without a slot is set up again in the next band.
//!
//! Slots are open-addressed by a hash of the key with a short probe;
//! entries of edges that have ended are free for reuse.

use core::ops::Range;

use crate::band::BandDeltas;
use crate::edge::{AliasedWalk, AreaMode, Canon, EdgeWalk};
use crate::geom::FinePoint;
use crate::shade::Plane;

/// How far a lookup probes from a key's home slot.
const PROBE: usize = 4;

/// One slot of a [`WalkCache`]; make arrays of them with
/// [`WalkSlot::EMPTY`]. A slot is [`WalkSlot::SIZE`] bytes (368 on
/// thumbv6m and x86-64): RAM beside the band buffers, so size the cache
/// for the edges alive across a band boundary, not for the frame's.
// In this order (`repr(C)`): what a lookup reads lies within the first
// 124 bytes, which the Cortex-M0's loads reach with one instruction.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct WalkSlot<const C: usize> {
    key: u64,
    made_of: [i32; 6],
    /// The last frame row the entry is needed for.
    last_row: i32,
    entry: Entry<C>,
}

// Slots are uniform on purpose: a slot holds any of them.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
enum Entry<const C: usize> {
    Empty,
    Walk(EdgeWalk),
    Aliased(AliasedWalk),
    Plane(Plane<C>),
}

impl<const C: usize> WalkSlot<C> {
    /// An unused slot.
    pub const EMPTY: Self = Self {
        key: u64::MAX,
        made_of: [0; 6],
        last_row: i32::MIN,
        entry: Entry::Empty,
    };

    /// Bytes a slot takes (for sizing a cache).
    pub const SIZE: usize = core::mem::size_of::<Self>();
}

impl<const C: usize> Default for WalkSlot<C> {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// The walk states and planes of a frame, over caller-provided slots: a
/// view made for each band over the same slots, cleared once per frame.
///
/// ```
/// use softedge::canvas::{WalkCache, WalkSlot};
/// let mut slots = [WalkSlot::<3>::EMPTY; 64];
/// let mut cache = WalkCache::new(&mut slots);
/// cache.clear(); // a new frame
/// assert_eq!(cache.capacity(), 64);
/// ```
#[derive(Debug)]
pub struct WalkCache<'a, const C: usize> {
    slots: &'a mut [WalkSlot<C>],
    /// Lookups that found their entry, and set-ups that found no slot.
    hits: u32,
    misses: u32,
}

/// What a key names: an edge of a shape, or a shape's plane.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Item {
    Edge(u32),
    Plane(u32),
}

fn key(serial: u32, item: Item) -> u64 {
    let (tag, k) = match item {
        Item::Edge(k) => (0u64, k),
        Item::Plane(k) => (1u64 << 31, k),
    };
    (u64::from(serial) << 32) | tag | u64::from(k & 0x7fff_ffff)
}

/// The key's home slot among `len`: a 32-bit multiplicative hash of its
/// two halves, mapped to `0..len` by a multiply and a shift (no division,
/// no 64-bit product: library calls on the Cortex-M0), from the hash's top
/// 16 bits for up to `2^16` slots; beyond, the hash modulo `len`.
fn home(key: u64, len: usize) -> usize {
    let h = ((key as u32) ^ ((key >> 32) as u32).rotate_left(13)).wrapping_mul(0x9e37_79b9);
    let h = h ^ (h >> 15);
    if len <= 1 << 16 {
        (((h >> 16) * len as u32) >> 16) as usize
    } else {
        h as usize % len
    }
}

/// The slots a key may be in: its home and the next few, wrapping.
fn probes(key: u64, len: usize) -> impl Iterator<Item = usize> {
    let h = home(key, len);
    (0..PROBE.min(len)).map(move |i| if h + i >= len { h + i - len } else { h + i })
}

/// `a == b`, word by word: the array comparison becomes a `memcmp` call
/// on the Cortex-M0, several times longer than these six words, and it
/// runs for every edge of every shape in every band it touches.
#[inline]
fn same(a: &[i32; 6], b: &[i32; 6]) -> bool {
    let d = (a[0] ^ b[0]) | (a[1] ^ b[1]) | (a[2] ^ b[2]);
    let e = (a[3] ^ b[3]) | (a[4] ^ b[4]) | (a[5] ^ b[5]);
    d | e == 0
}

fn edge_made_of(p0: FinePoint, p1: FinePoint, tag: i32) -> [i32; 6] {
    [p0.x, p0.y, p1.x, p1.y, tag, 0]
}

impl<'a, const C: usize> WalkCache<'a, C> {
    /// A view of `slots` (any number; none is a valid, empty cache),
    /// keeping what they hold: the same slots, viewed in every band of a
    /// frame, carry the frame's walks from band to band.
    pub fn new(slots: &'a mut [WalkSlot<C>]) -> Self {
        Self {
            slots,
            hits: 0,
            misses: 0,
        }
    }

    /// Number of slots.
    pub fn capacity(&self) -> usize {
        self.slots.len()
    }

    /// Forgets every entry (a new frame).
    pub fn clear(&mut self) {
        for s in self.slots.iter_mut() {
            s.key = u64::MAX;
            s.last_row = i32::MIN;
            s.entry = Entry::Empty;
        }
        self.hits = 0;
        self.misses = 0;
    }

    /// Lookups that resumed a stored entry, and entries that found no free
    /// slot, through this view.
    pub fn stats(&self) -> (u32, u32) {
        (self.hits, self.misses)
    }

    /// (A loop over the probes rather than `probes(..).find(..)`: it runs
    /// for every edge of every band, and the iterator's closures cost the
    /// Cortex-M0 some 60 instructions a lookup more.)
    fn find(&mut self, k: u64, made_of: &[i32; 6]) -> Option<usize> {
        let len = self.slots.len();
        let mut i = home(k, len);
        for _ in 0..PROBE.min(len) {
            let s = self.slots.get(i)?;
            if s.key == k && same(&s.made_of, made_of) {
                return Some(i);
            }
            i += 1;
            if i == len {
                i = 0;
            }
        }
        None
    }

    /// A slot for a new entry: empty, or holding an entry not needed from
    /// row `row` on.
    fn free(&mut self, k: u64, row: i32) -> Option<usize> {
        probes(k, self.slots.len()).find(|&i| self.slots.get(i).is_some_and(|s| s.last_row < row))
    }

    /// Stores an entry in a free slot, and says which; `None` (a miss)
    /// when none is free.
    fn place(
        &mut self,
        k: u64,
        made_of: [i32; 6],
        row: i32,
        last_row: i32,
        entry: Entry<C>,
    ) -> Option<usize> {
        let Some(i) = self.free(k, row) else {
            self.misses += 1;
            return None;
        };
        let s = self.slots.get_mut(i)?;
        *s = WalkSlot {
            key: k,
            made_of,
            last_row,
            entry,
        };
        Some(i)
    }

    /// The stored walk of edge `edge` of shape `serial`, if it was made
    /// from `p0 -> p1` (`tag` tells walk kinds apart): walked in place.
    pub(crate) fn walk(
        &mut self,
        serial: u32,
        edge: u32,
        p0: FinePoint,
        p1: FinePoint,
        tag: i32,
    ) -> Option<&mut EdgeWalk> {
        let i = self.find(key(serial, Item::Edge(edge)), &edge_made_of(p0, p1, tag))?;
        match self.slots.get_mut(i).map(|s| &mut s.entry) {
            Some(Entry::Walk(w)) => {
                self.hits += 1;
                Some(w)
            }
            _ => None,
        }
    }

    /// The entry of a free slot, claimed for new entry `k` made of
    /// `made_of` and needed from row `row` to `last_row`, for the caller to
    /// fill in place: an edge's walk already there (ended, or of an earlier
    /// frame) is set up again over itself, anything else replaced. `None`
    /// (a miss) when no slot is free.
    fn claim(
        &mut self,
        k: u64,
        made_of: [i32; 6],
        row: i32,
        last_row: i32,
    ) -> Option<&mut Entry<C>> {
        let Some(i) = self.free(k, row) else {
            self.misses += 1;
            return None;
        };
        let s = self.slots.get_mut(i)?;
        s.key = k;
        s.made_of = made_of;
        s.last_row = last_row;
        Some(&mut s.entry)
    }

    /// Like [`walk`](Self::walk), for an aliased walk.
    pub(crate) fn aliased(
        &mut self,
        serial: u32,
        edge: u32,
        p0: FinePoint,
        p1: FinePoint,
    ) -> Option<&mut AliasedWalk> {
        let i = self.find(key(serial, Item::Edge(edge)), &edge_made_of(p0, p1, -1))?;
        match self.slots.get_mut(i).map(|s| &mut s.entry) {
            Some(Entry::Aliased(w)) => {
                self.hits += 1;
                Some(w)
            }
            _ => None,
        }
    }

    /// Like [`place_walk`](Self::place_walk), for an aliased walk.
    #[allow(clippy::result_large_err)]
    pub(crate) fn place_aliased(
        &mut self,
        serial: u32,
        edge: u32,
        p0: FinePoint,
        p1: FinePoint,
        row: i32,
        walk: AliasedWalk,
    ) -> Result<&mut AliasedWalk, AliasedWalk> {
        let last = walk.rows().end - 1;
        let k = key(serial, Item::Edge(edge));
        let Some(i) = self.free(k, row) else {
            self.misses += 1;
            return Err(walk);
        };
        let Some(s) = self.slots.get_mut(i) else {
            return Err(walk);
        };
        s.key = k;
        s.made_of = edge_made_of(p0, p1, -1);
        s.last_row = last;
        s.entry = Entry::Aliased(walk);
        match &mut s.entry {
            Entry::Aliased(w) => Ok(w),
            _ => Err(walk),
        }
    }

    /// The stored plane `index` of shape `serial`, if made from
    /// `made_of`.
    pub(crate) fn plane(
        &mut self,
        serial: u32,
        index: u32,
        made_of: &[i32; 6],
    ) -> Option<Plane<C>> {
        let k = key(serial, Item::Plane(index));
        let i = self.find(k, made_of)?;
        match self.slots.get(i).map(|s| &s.entry) {
            Some(Entry::Plane(p)) => {
                self.hits += 1;
                Some(*p)
            }
            _ => None,
        }
    }

    /// Stores plane `index` of shape `serial`, needed down to `last_row`.
    pub(crate) fn put_plane(
        &mut self,
        serial: u32,
        index: u32,
        made_of: [i32; 6],
        row: i32,
        last_row: i32,
        plane: Plane<C>,
    ) {
        let k = key(serial, Item::Plane(index));
        let _ = self.place(k, made_of, row, last_row, Entry::Plane(plane));
    }
}

/// What the edge walks of one shape in one band share (one reference
/// instead of four arguments per edge: the Cortex-M0 passes four in
/// registers, the rest on the stack).
pub(crate) struct ShapeBand {
    /// The shape's place in the drawing order.
    pub serial: u32,
    pub mode: AreaMode,
    /// The band's columns, and the shape's rows in the band.
    pub cols: Range<i32>,
    pub rows: Range<i32>,
}

/// Walks edge `edge` of shape `shape.serial`, `p0 -> p1` in `shape.mode`,
/// over frame rows `shape.rows` into `out` (a band's scratch for those
/// rows, whose columns are `shape.cols`): resumed from `cache` when it
/// holds the edge's walk, else set up, and kept in a free slot if it goes
/// on below the rows.
///
/// A walk is a few hundred bytes, and on the Cortex-M0 a copy of one costs
/// about as much as walking a short edge: the walk is set up where it
/// stays (in its slot, over the ended walk there, or on the stack), never
/// moved.
pub(crate) fn walk_edge<const C: usize>(
    cache: Option<&mut WalkCache<'_, C>>,
    shape: &ShapeBand,
    edge: u32,
    (p0, p1): (FinePoint, FinePoint),
    out: &mut BandDeltas<'_>,
) {
    let ShapeBand {
        serial,
        mode,
        ref cols,
        ref rows,
    } = *shape;
    let rows = rows.clone();
    if p0.y == p1.y {
        // A horizontal edge cuts off no area in the row-wise model (no
        // walk: `Canon::new` gives none), so it has no entry to look for.
        return;
    }
    if mode == AreaMode::Exact && p0.x == p1.x {
        // A vertical edge needs no set-up and no state: walked row by
        // row, never kept.
        crate::edge::walk_vertical(p0, p1, rows, out);
        return;
    }
    let tag = mode as i32;
    let mut cache = cache;
    if let Some(w) = cache
        .as_deref_mut()
        .and_then(|c| c.walk(serial, edge, p0, p1, tag))
    {
        w.walk_into(rows, out.lend());
        return;
    }
    let Some(e) = Canon::new(p0, p1) else {
        return;
    };
    // Kept only if it goes on below this band.
    let last = EdgeWalk::rows_of(&e).end - 1;
    if let Some(c) = cache.filter(|_| last >= rows.end) {
        let k = key(serial, Item::Edge(edge));
        if let Some(entry) = c.claim(k, edge_made_of(p0, p1, tag), rows.start, last) {
            if let Entry::Walk(w) = entry {
                *w = EdgeWalk::unclipped(e, mode, cols.start);
            } else {
                *entry = Entry::Walk(EdgeWalk::unclipped(e, mode, cols.start));
            }
            if let Entry::Walk(w) = entry {
                w.clip(cols.clone());
                w.walk_into(rows, out.lend());
            }
            return;
        }
    }
    let mut w = EdgeWalk::unclipped(e, mode, cols.start);
    w.clip(cols.clone());
    // Not kept: set up again if a later band needs it.
    w.once();
    w.walk_into(rows, out.lend());
}
