//! A frame's triangles prepared once, drawn in every band from a
//! caller-provided list.
//!
//! Drawn one call at a time, a triangle is described again in every band
//! (the drawing closure runs once a band): the caller's vertices
//! converted, their range checked, the triangle's orientation found, only
//! to find in most bands that its rows miss the band. With small bands
//! that is the largest part of what a frame costs beyond its 16-row cost
//! (issue 14: 80 bands of 3 rows call the closure 80 times). A
//! [`TriangleList`] does that once per frame:
//! [`push`](TriangleList::push) checks the vertices, orients the triangle
//! and keeps its rows; each band's [`Canvas::fill_triangles`] tests the
//! entries' rows against the band (two compares each) and draws only those
//! that meet it. (A Gouraud triangle's plane is fitted once per frame by
//! the walk cache, as for a triangle drawn directly.)
//!
//! Entries also keep two running bounds so that a band need not test them
//! all: `until`, the last row any entry up to this one reaches (a prefix
//! maximum, so the entries that ended above a band are a prefix, found by
//! a binary search), and `from`, a lower bound of the first row of every
//! entry from this one on (a suffix minimum, kept by [`push`] with a
//! bounded walk back, so the entries that start below a band are a
//! suffix). A list recorded roughly top to bottom, as a user interface or
//! a mesh usually is, then costs a band the entries near it, not the
//! frame's; in any other order the bounds skip nothing and cost two
//! binary searches a band.
//!
//! [`push`]: TriangleList::push
//!
//! The `n`-th entry is drawn exactly as the `n`-th of as many
//! [`Canvas::fill_triangle`] calls would be, with the same place in the
//! drawing order (the walk cache's key): the same pixels, bit for bit.

use super::{flat_color, op_of, orient, triangle_box, Canvas};
use crate::band::{ComposeOp, Paint};
use crate::geom::{FinePoint, FINE_BITS};
use crate::raster::DrawError;
use crate::style::{Blend, Opacity};

/// One entry of a [`TriangleList`]; make arrays of them with
/// [`ListedTriangle::EMPTY`]. An entry is [`ListedTriangle::SIZE`] bytes
/// (60 for three channels, 48 for one, on thumbv6m and x86-64).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ListedTriangle<const C: usize> {
    /// The vertices in the order whose winding integral is the coverage
    /// (as given, or `v[0], v[2], v[1]` when `flip`): a band walks them
    /// in place.
    o: [FinePoint; 3],
    colors: [[u16; C]; 3],
    /// The first and last pixel rows, then columns, of the box around
    /// the vertices (the coordinate range, ±2048 px, fits 16 bits).
    rows: [i16; 2],
    cols: [i16; 2],
    /// The last row of any entry up to this one (a prefix maximum).
    until: i16,
    /// At most the first row of every entry from this one on (a suffix
    /// minimum, or lower), where the list's `from_valid` says it holds.
    from: i16,
    /// True when the coverage order is `v[0], v[2], v[1]` of the
    /// vertices `v` as given (the Gouraud plane is fitted from those).
    flip: bool,
    /// True for one colour, then `colors[0]` clamped to 12 bits.
    flat: bool,
    op: ComposeOp,
}

impl<const C: usize> ListedTriangle<C> {
    /// An unused entry.
    pub const EMPTY: Self = Self {
        o: [FinePoint::new(0, 0); 3],
        colors: [[0; C]; 3],
        rows: [0; 2],
        cols: [0; 2],
        until: 0,
        from: 0,
        flip: false,
        flat: false,
        op: ComposeOp::Over(Opacity::OPAQUE),
    };

    /// Bytes an entry takes (for sizing a list).
    pub const SIZE: usize = core::mem::size_of::<Self>();
}

impl<const C: usize> Default for ListedTriangle<C> {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// A frame's triangles, checked and oriented once, over a caller-provided
/// slice: record them before the frame, then draw the list in every band
/// with [`Canvas::fill_triangles`].
///
/// ```
/// use softedge::canvas::{ListedTriangle, TriangleList};
/// use softedge::geom::FinePoint;
/// use softedge::style::{Blend, Opacity};
/// let mut store = [ListedTriangle::<3>::EMPTY; 8];
/// let mut list = TriangleList::new(&mut store);
/// let v = [FinePoint::new(0, 0), FinePoint::new(8192, 0), FinePoint::new(0, 8192)];
/// list.push(v, [[4095, 0, 0]; 3], Blend::Over, Opacity::OPAQUE).unwrap();
/// assert_eq!(list.len(), 1);
/// ```
#[derive(Debug)]
pub struct TriangleList<'a, const C: usize> {
    store: &'a mut [ListedTriangle<C>],
    len: usize,
    /// Entries from this index on have `from` bounds that hold (a walk
    /// back that [`FROM_WALK`] cut short leaves the ones before it stale).
    from_valid: usize,
}

/// Most entries one [`TriangleList::push`] walks back to lower their
/// `from` bounds: a list pushed in falling rows would otherwise cost
/// quadratic time; past it, the entries not reached lose their bound
/// (their bands test every entry after the ended ones).
const FROM_WALK: usize = 16;

impl<'a, const C: usize> TriangleList<'a, C> {
    /// An empty list over `store`.
    pub fn new(store: &'a mut [ListedTriangle<C>]) -> Self {
        Self {
            store,
            len: 0,
            from_valid: 0,
        }
    }

    /// Appends a triangle: one colour per vertex (all equal for a flat
    /// one), a blend and an opacity, as [`Canvas::fill_triangle`] takes
    /// them.
    ///
    /// # Errors
    /// [`DrawError::FineCoord`] for the first vertex outside the
    /// coordinate range, [`DrawError::ListFull`] when the store has no
    /// room; the list is then unchanged.
    pub fn push(
        &mut self,
        v: [FinePoint; 3],
        colors: [[u16; C]; 3],
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        if let Some(&p) = v.iter().find(|p| !p.in_range()) {
            return Err(DrawError::FineCoord(p));
        }
        let n = self.len;
        let (done, rest) = self.store.split_at_mut(n.min(self.store.len()));
        let entry = rest.first_mut().ok_or(DrawError::ListFull)?;
        let b = triangle_box(&v);
        // In range, a pixel is within ±2049: 16 bits.
        let px = |c: i32| (c >> FINE_BITS) as i16;
        let rows = [px(b.y0), px(b.y1)];
        let flat = flat_color(&colors);
        let o = orient(v);
        *entry = ListedTriangle {
            o,
            colors: flat.map_or(colors, |c| [c; 3]),
            rows,
            cols: [px(b.x0), px(b.x1)],
            until: done.last().map_or(rows[1], |t| t.until.max(rows[1])),
            from: rows[0],
            flip: o != v,
            flat: flat.is_some(),
            op: op_of(blend, opacity),
        };
        // The earlier entries' `from` bounds must not exceed this first
        // row: they are non-decreasing, so those to lower are the last few.
        for (walked, t) in done.iter_mut().rev().enumerate() {
            if t.from <= rows[0] {
                break;
            }
            if walked == FROM_WALK {
                // Cut short: the entries up to this one keep a stale bound.
                self.from_valid = self.from_valid.max(n - walked);
                break;
            }
            t.from = rows[0];
        }
        self.len = n + 1;
        Ok(())
    }

    /// How many triangles the list holds.
    pub fn len(&self) -> usize {
        self.len
    }

    /// True when it holds none.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// How many it can hold.
    pub fn capacity(&self) -> usize {
        self.store.len()
    }

    /// Empties the list (for the next frame).
    pub fn clear(&mut self) {
        self.len = 0;
        self.from_valid = 0;
    }

    fn entries(&self) -> &[ListedTriangle<C>] {
        self.store.get(..self.len).unwrap_or_default()
    }

    /// The entries that may meet rows `y_lo..y_hi`, and the index of the
    /// first: those before it ended above `y_lo`, those after the slice
    /// start at or below `y_hi`.
    fn window(&self, y_lo: i32, y_hi: i32) -> (usize, &[ListedTriangle<C>]) {
        let all = self.entries();
        let start = all.partition_point(|t| i32::from(t.until) < y_lo);
        // Where the bounds hold, entries from `end` on start at or
        // below `y_hi`.
        let valid = self.from_valid.max(start).min(all.len());
        let end = valid
            + all
                .get(valid..)
                .unwrap_or_default()
                .partition_point(|t| i32::from(t.from) < y_hi);
        (start, all.get(start..end).unwrap_or_default())
    }
}

impl<const C: usize, Col> Canvas<'_, '_, C, Col> {
    /// Draws every triangle of `list`, in its order, as as many
    /// [`fill_triangle`](Self::fill_triangle) calls would (the same
    /// places in the drawing order, the same pixels); a triangle whose
    /// rows miss the band costs two compares, or nothing when it lies
    /// beyond the list's running bounds (see the module's doc).
    pub fn fill_triangles(&mut self, list: &TriangleList<'_, C>) {
        let base = self.serial;
        self.serial = base.wrapping_add(list.len() as u32);
        let reach = self.reach;
        let (y_lo, y_hi) = self.triangle_reach();
        let (start, entries) = list.window(y_lo, y_hi);
        let at = self.triangle_band();
        for (i, t) in (start..).zip(entries) {
            let rows = [i32::from(t.rows[0]), i32::from(t.rows[1])];
            if rows[1] < y_lo || rows[0] >= y_hi {
                continue;
            }
            if i32::from(t.cols[1]) < reach.x_lo || i32::from(t.cols[0]) >= reach.x_hi {
                continue;
            }
            let serial = base.wrapping_add(i as u32);
            if t.flat {
                let paint = Paint::Flat(t.colors[0]);
                self.fill_oriented_here(&at, serial, 0, &t.o, rows, &paint, t.op);
            } else {
                let [p, q, r] = t.o;
                let v = if t.flip { [p, r, q] } else { t.o };
                self.gouraud(serial, 0, &v, &t.o, rows, &t.colors, t.op);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::band::{BandBuffer, Bands};
    use crate::canvas::{WalkCache, WalkSlot};
    use crate::path::testing::Lcg;
    use crate::path::Circle;
    use crate::raster::{PixelModel, RenderStyle};
    use crate::style::FillRule;

    const W: u16 = 64;
    const H: u16 = 48;

    /// A triangle, its colours, blend and opacity.
    type Tri = ([FinePoint; 3], [[u16; 3]; 3], Blend, Opacity);

    /// A `W x H` frame in bands of `rows` with a walk cache of `slots`
    /// slots, each band drawn by `draw`; the resolved linear values and the
    /// cache's hits and misses summed over the bands.
    fn frame(
        rows: u16,
        slots: usize,
        style: RenderStyle,
        mut draw: impl FnMut(&mut Canvas<'_, '_, 3>),
    ) -> (Vec<[u16; 3]>, (u32, u32)) {
        let mut acc = std::vec![0i32; BandBuffer::<3>::acc_len(W, rows)];
        let mut cover = std::vec![0i32; BandBuffer::<3>::cover_len(W, rows)];
        let mut store = std::vec![WalkSlot::<3>::EMPTY; slots];
        WalkCache::new(&mut store).clear();
        let mut out = std::vec![[0u16; 3]; usize::from(W) * usize::from(H)];
        let mut stats = (0, 0);
        for band in Bands::new(W, H, rows) {
            let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).unwrap();
            buf.clear([300, 1200, 2400]);
            let cache = (slots > 0).then(|| WalkCache::new(&mut store));
            let mut canvas = Canvas::new(&mut buf, cache);
            canvas.set_style(style);
            draw(&mut canvas);
            let (h, m) = canvas.cache_stats();
            stats = (stats.0 + h, stats.1 + m);
            for y in band.row_range() {
                for x in 0..W {
                    out[y as usize * usize::from(W) + usize::from(x)] =
                        buf.lin12(i32::from(x), y).unwrap();
                }
            }
        }
        (out, stats)
    }

    /// Random triangles over and beyond the frame: flat and Gouraud, some
    /// without area, some added, most opaque.
    fn triangles(rng: &mut Lcg, n: usize) -> Vec<Tri> {
        let mut next = |m: u32| rng.below(u64::from(m)) as i32;
        (0..n)
            .map(|_| {
                let p = |next: &mut dyn FnMut(u32) -> i32| {
                    FinePoint::new(next(80 * 1024) - 8 * 1024, next(64 * 1024) - 8 * 1024)
                };
                let a = p(&mut next);
                let mut v = [a, p(&mut next), p(&mut next)];
                // Small ones, around the first vertex.
                if next(3) == 0 {
                    for q in &mut v[1..] {
                        *q = FinePoint::new(a.x + next(6000) - 3000, a.y + next(6000) - 3000);
                    }
                }
                match next(12) {
                    0 => v[2] = v[1],
                    1 => v[2] = FinePoint::new(2 * v[1].x - v[0].x, 2 * v[1].y - v[0].y),
                    _ => {}
                }
                let c = |next: &mut dyn FnMut(u32) -> i32| {
                    [next(4600) as u16, next(4096) as u16, next(4096) as u16]
                };
                let colors = if next(2) == 0 {
                    [c(&mut next); 3]
                } else {
                    [c(&mut next), c(&mut next), c(&mut next)]
                };
                let blend = if next(5) == 0 {
                    Blend::Add
                } else {
                    Blend::Over
                };
                let op = if next(3) == 0 {
                    Opacity::from_ratio(1 + next(7) as u32, 8).unwrap()
                } else {
                    Opacity::OPAQUE
                };
                (v, colors, blend, op)
            })
            .collect()
    }

    #[test]
    fn a_listed_frame_is_the_bits_of_its_triangles_drawn_one_by_one() {
        let mut rng = Lcg(0x7e1a_11f7_0b0e_5eed);
        let styles = [
            RenderStyle::default(),
            RenderStyle::ALIASED,
            RenderStyle {
                antialias: true,
                model: PixelModel::BoxSeed,
            },
            RenderStyle {
                antialias: true,
                model: PixelModel::Hex7,
            },
        ];
        let disc = Circle::new(FinePoint::new(30 * 1024, 20 * 1024), 9 * 1024);
        for case in 0..24 {
            let tris = triangles(&mut rng, 1 + case * 3);
            let mut store = std::vec![ListedTriangle::<3>::EMPTY; tris.len()];
            let mut list = TriangleList::new(&mut store);
            for &(v, c, b, o) in &tris {
                list.push(v, c, b, o).unwrap();
            }
            let list = &list;
            // Shapes before and after, so that the list's places in the
            // drawing order show in the cache's hits.
            let draw = |c: &mut Canvas<'_, '_, 3>, listed: bool| {
                let op = Opacity::OPAQUE;
                c.fill_shape(&disc, [900, 0, 4095], FillRule::NonZero, Blend::Over, op)
                    .unwrap();
                if listed {
                    c.fill_triangles(list);
                } else {
                    for &(v, col, b, o) in &tris {
                        c.fill_triangle(v, col, b, o).unwrap();
                    }
                }
                let half = Opacity::from_percent(50);
                c.fill_shape(&disc, [0, 4095, 0], FillRule::NonZero, Blend::Add, half)
                    .unwrap();
            };
            let direct = |c: &mut Canvas<'_, '_, 3>| draw(c, false);
            let listed = |c: &mut Canvas<'_, '_, 3>| draw(c, true);
            let style = styles[case % styles.len()];
            let (whole, _) = frame(H, 64, style, direct);
            assert!(whole.iter().any(|&v| v != [300, 1200, 2400]));
            for rows in [1, 3, 7, 16] {
                for slots in [0, 5, 256] {
                    let d = frame(rows, slots, style, direct);
                    let l = frame(rows, slots, style, listed);
                    assert_eq!(
                        d.0, whole,
                        "case {case}, direct, {rows} rows, {slots} slots"
                    );
                    assert_eq!(
                        l.0, whole,
                        "case {case}, listed, {rows} rows, {slots} slots"
                    );
                    assert_eq!(l.1, d.1, "case {case}: cache hits and misses, {rows} rows");
                }
            }
        }
    }

    #[test]
    fn the_window_holds_every_entry_that_meets_the_rows() {
        // Lists in rising, falling, shuffled and nearly sorted row order,
        // against a plain test of every entry; the falling ones cut the
        // bounds' walk back short.
        let mut rng = Lcg(0x3a1d_0e55_51de_b0a7);
        for case in 0..40 {
            let n = 1 + case * 7;
            let mut tops: Vec<i32> = (0..n).map(|_| rng.below(300) as i32 - 30).collect();
            match case % 4 {
                0 => tops.sort_unstable(),
                1 => tops.sort_unstable_by(|a, b| b.cmp(a)),
                2 => {}
                _ => {
                    tops.sort_unstable();
                    for t in &mut tops {
                        *t += rng.below(7) as i32 - 3;
                    }
                }
            }
            let mut store = std::vec![ListedTriangle::<3>::EMPTY; n];
            let mut list = TriangleList::new(&mut store);
            for &top in &tops {
                let h = rng.below(60) as i32;
                let (x, y) = (rng.below(200) as i32 * 1024, top * 1024 + 100);
                let v = [
                    FinePoint::new(x, y),
                    FinePoint::new(x + 5000, y + h * 1024),
                    FinePoint::new(x - 3000, y + (h / 2) * 1024),
                ];
                list.push(v, [[1000; 3]; 3], Blend::Over, Opacity::OPAQUE)
                    .unwrap();
            }
            let all = list.entries();
            for y_lo in -40..300 {
                for y_hi in [y_lo + 1, y_lo + 3, y_lo + 16] {
                    let (start, w) = list.window(y_lo, y_hi);
                    for (i, t) in all.iter().enumerate() {
                        let meets = i32::from(t.rows[1]) >= y_lo && i32::from(t.rows[0]) < y_hi;
                        if meets {
                            assert!(
                                i >= start && i < start + w.len(),
                                "case {case}: entry {i} meets {y_lo}..{y_hi}, window {start}+{}",
                                w.len()
                            );
                        }
                    }
                }
            }
            // A sorted list's window is its entries near the rows.
            if case % 4 == 0 && n > 100 {
                let (_, w) = list.window(100, 103);
                assert!(w.len() < n / 2, "case {case}: {} of {n}", w.len());
            }
        }
    }

    #[test]
    fn lists_in_any_row_order_give_the_bits_of_their_triangles_drawn_one_by_one() {
        let mut rng = Lcg(0x51de_0f0e_57a1_1ed5);
        for case in 0..6 {
            let mut tris = triangles(&mut rng, 40);
            let top = |t: &Tri| t.0.iter().map(|p| p.y).min().unwrap_or(0);
            match case % 3 {
                0 => tris.sort_by_key(top),
                1 => tris.sort_by_key(|t| core::cmp::Reverse(top(t))),
                _ => {}
            }
            let mut store = std::vec![ListedTriangle::<3>::EMPTY; tris.len()];
            let mut list = TriangleList::new(&mut store);
            for &(v, c, b, o) in &tris {
                list.push(v, c, b, o).unwrap();
            }
            let list = &list;
            let style = RenderStyle::default();
            let direct = |c: &mut Canvas<'_, '_, 3>| {
                for &(v, col, b, o) in &tris {
                    c.fill_triangle(v, col, b, o).unwrap();
                }
            };
            let (whole, _) = frame(H, 64, style, direct);
            for rows in [1, 3, 7] {
                let (l, _) = frame(rows, 64, style, |c| c.fill_triangles(list));
                assert_eq!(l, whole, "case {case}, {rows} rows");
            }
        }
    }

    #[test]
    fn entries_are_the_documented_size() {
        assert_eq!(ListedTriangle::<3>::SIZE, 60);
        assert_eq!(ListedTriangle::<1>::SIZE, 48);
    }

    #[test]
    fn a_full_list_and_a_vertex_out_of_range_are_refused_and_leave_the_list_as_it_was() {
        let mut store = [ListedTriangle::<3>::EMPTY; 2];
        let mut list = TriangleList::new(&mut store);
        let v = [
            FinePoint::new(0, 0),
            FinePoint::new(4096, 0),
            FinePoint::new(0, 4096),
        ];
        let far = FinePoint::new(crate::geom::FINE_LIMIT + 1, 0);
        let c = [[4095, 0, 0]; 3];
        assert_eq!(
            list.push([v[0], far, v[2]], c, Blend::Over, Opacity::OPAQUE),
            Err(DrawError::FineCoord(far))
        );
        assert!(list.is_empty());
        list.push(v, c, Blend::Over, Opacity::OPAQUE).unwrap();
        list.push(v, c, Blend::Over, Opacity::OPAQUE).unwrap();
        assert_eq!(
            list.push(v, c, Blend::Over, Opacity::OPAQUE),
            Err(DrawError::ListFull)
        );
        assert_eq!((list.len(), list.capacity()), (2, 2));
        list.clear();
        assert!(list.is_empty());
    }
}
