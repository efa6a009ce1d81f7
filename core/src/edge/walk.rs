//! The anti-aliased walk: set-up of the step constants (may divide), then
//! the per-column stepping (add / compare only, the exact mode's spill
//! included), resumable from one band to the next.
//!
//! The walk reports changes of each row's running coverage
//! ([`DeltaSink`]): a cell of area `S` is `+S` at its pixel and `-S` right
//! of it, a row's cover one change. Along an x-major row the main cells of
//! consecutive columns merge, so such a row costs one change per column
//! (`S(a) - S(a - 1)`, which is the step's `q` or `q + 1`) plus a few at its
//! ends and at the crossing into the next row.

use core::ops::Range;

use super::area::clamped_area;
use super::canon::{cell_of, Canon, Lv, H_BITS, N};
use super::crossing::{Crossing, Direct, Tracker};
use super::{AreaMode, CoverSink, DeltaSink, Forward};
use crate::arith::udivmod;
use crate::{COVER_BITS, COVER_ONE};

/// A whole pixel of coverage.
const ONE: i32 = COVER_ONE;

/// The main term at one interior column: exact integers, so equal to a
/// direct evaluation there.
#[derive(Debug, Clone, Copy)]
struct Step {
    /// Major column.
    a: i32,
    /// Chosen minor cell: the one holding the line at the column centre.
    b: i32,
    /// Main term `S = v(u_c) - b` in coverage units (floor) and its
    /// remainder over `du`.
    s: i32,
    r: i32,
    /// `S` at which the walk leaves the cell: a whole pixel, or less in the
    /// first row of an x-major edge (measured from the vertex, not the row
    /// top).
    h: i32,
}

/// The crossing tracker of a walk (exact mode): set up when the walk
/// first needs it, so edges without interior crossings never divide for
/// it.
#[derive(Debug, Clone, Copy)]
enum Next {
    /// Not looked for yet.
    Unset,
    /// No crossing left that the walk needs (or the seed formula's mode).
    Done,
    /// The next crossing at or after the walk's column.
    At(Crossing),
    /// The same, for a [`Tracker::Narrow`] (`u32` remainders).
    AtN(Crossing<u32>),
    /// The next of the few interior crossings a walk needs (the last few
    /// of an edge, or a band's worth of one walked once), evaluated one
    /// at a time ([`Direct`]): the walk needs those before boundary `end`.
    Direct { x: Direct, end: i32 },
}

impl Next {
    /// The column of the next crossing (`i32::MAX` if none).
    #[inline]
    fn col(&self) -> i32 {
        match self {
            Next::At(c) => c.col,
            Next::AtN(c) => c.col,
            Next::Direct { x, .. } => x.col,
            Next::Done | Next::Unset => i32::MAX,
        }
    }

    /// The crossing in column `a`, if any: whether the line leaves the
    /// row there.
    #[inline]
    fn down_at(&self, a: i32, cross: &Option<Tracker>) -> Option<bool> {
        match (self, cross) {
            (Next::At(c), Some(Tracker::Wide(k))) if c.col == a => Some(!c.is_left(k)),
            (Next::AtN(c), Some(Tracker::Narrow(k))) if c.col == a => Some(!c.is_left(k)),
            (Next::Direct { x, .. }, _) if x.col == a => Some(x.down),
            _ => None,
        }
    }

    /// The spill of the crossing in column `a` (see
    /// [`down_at`](Self::down_at)), and on to the next crossing.
    #[inline(always)]
    fn take_spill(&mut self, cross: &Option<Tracker>) -> i32 {
        match (&mut *self, cross) {
            (Next::At(c), Some(Tracker::Wide(k))) => {
                let t = c.spill(k);
                c.advance(k);
                t
            }
            (Next::AtN(c), Some(Tracker::Narrow(k))) => {
                let t = c.spill(k);
                c.advance(k);
                t
            }
            (Next::Direct { x, .. }, _) => {
                let t = x.spill;
                self.pass_direct();
                t
            }
            _ => 0,
        }
    }

    /// Past a directly evaluated crossing: on to the next one, or done.
    #[inline]
    fn pass_direct(&mut self) {
        if let Next::Direct { x, end } = self {
            if x.m + 1 < *end {
                x.advance();
            } else {
                *self = Next::Done;
            }
        }
    }
}

/// Most interior crossings a walk evaluates one at a time ([`Direct`]:
/// three divisions and an inverse for the first, a product by the
/// inverse for each next) instead of setting up the stepping
/// ([`Tracker`]: eight divisions and the `u64` products of its constants,
/// then additions only): when the rest of the edge crosses at most this
/// many boundaries, or the walk is dropped after its band and the band has
/// at most this many rows left (an edge crosses at most one boundary a
/// row). On the Cortex-M0 a crossing costs about 75 instructions so and
/// 70 stepped, the tracker's set-up about 1 800: the tracker pays only for
/// long edges (and those whose spill's denominator passes `2^32`, where
/// each direct spill is a 64-bit division). 128 measures best on the
/// benchmark's triangles of all three sizes (16 did while a direct
/// crossing was a division; 64 and 4 096 within 0.1 %).
const DIRECT: i32 = 128;

/// Where a walk stopped, so that the next band's walk resumes there
/// instead of starting over with divisions.
#[derive(Debug, Clone, Copy)]
struct Resume {
    /// The first row of the band this state starts.
    row: i32,
    /// The next major column (x-major) or frame row (y-major) to walk.
    a: i32,
    /// Rows above `prev` have had their cover reported (x-major).
    prev: i32,
    /// The main term at `a - 1`, when that was an interior column.
    st: Option<Step>,
    /// The next crossing at or after `a` (exact mode).
    x: Next,
}

/// One edge of a shape, set up once and walked band by band.
///
/// Built from two fine points ([`FinePoint`](crate::geom::FinePoint));
/// horizontal edges are `None` (they cut off no area in the row-wise
/// model). [`walk`](Self::walk) reports, through a [`CoverSink`], every
/// pixel of the given rows the edge cuts (its signed area right of the
/// edge, inside the edge's own y-range) and, per row, the column from which
/// the edge's full height applies. Walking the bands of a frame top to
/// bottom resumes where the previous band stopped; any other order starts
/// over from a direct evaluation. Both give the same bits.
///
/// The signs: an edge that runs down the screen reports `+` the area right
/// of it, one that runs up `-`; so the sum over the edges of closed
/// contours is, in every pixel, the integral of the winding number.
// In this order (`repr(C)`): the set-up, read by every column, at the
// smallest offsets (the Cortex-M0's loads reach 124 bytes in one
// instruction), then the state a band resumes from.
#[derive(Debug, Clone, Copy)]
#[repr(C)]
pub struct EdgeWalk {
    /// Walked for one band and then dropped ([`once`](Self::once)): its
    /// crossing tracker needs only that band's crossings. (First: the
    /// set-up's 92 bytes then end where the 8-byte aligned state begins.)
    once: bool,
    /// The set-up: what the walk of every band reads.
    g: Geom,
    /// Where the last band's walk stopped (stepped in place by the next).
    resume: Option<Resume>,
    /// The crossing constants, once a walk has needed them.
    cross: Option<Tracker>,
}

/// The set-up of an [`EdgeWalk`], apart from its state (so that a walk
/// can step its state in place while reading these).
#[derive(Debug, Clone, Copy)]
struct Geom {
    e: Canon,
    exact: bool,
    /// First and last major columns, first and last minor rows.
    a0: i32,
    a1: i32,
    b0: i32,
    b1: i32,
    /// Main term step per column `ONE dv / du`, quotient and remainder.
    q: i32,
    rr: i32,
    /// The line at the centres of the first and last columns (extended
    /// beyond the end points), from which the end columns' cells and the
    /// first interior column's main term follow without dividing.
    lc0: Lv,
    lc1: Lv,
    /// x-major only: the visible major columns `va..=vb` (empty when
    /// `va > vb`), the frame column covers left of them go to, and the
    /// rows whose cover columns lie left of the frame: `b0..r_in` (not
    /// mirrored) or `r_out..=b1` (mirrored).
    va: i32,
    vb: i32,
    c_lo: i32,
    r_in: i32,
    r_out: i32,
}

impl EdgeWalk {
    /// Sets up the edge `p0 -> p1` for a sink keeping the frame columns
    /// `columns` (divides: once per edge and frame). `None` for a
    /// horizontal edge. Points must be within the fine coordinate range
    /// (`FinePoint::in_range`); the caller checks.
    pub fn new(
        p0: crate::geom::FinePoint,
        p1: crate::geom::FinePoint,
        mode: AreaMode,
        columns: Range<i32>,
    ) -> Option<Self> {
        let e = Canon::new(p0, p1)?;
        let mut walk = Self::unclipped(e, mode, columns.start);
        walk.clip(columns);
        Some(walk)
    }

    /// [`new`](Self::new) of canonical edge `e`, before
    /// [`clip`](Self::clip). Always inlined, so that the walk is built
    /// where the caller keeps it: a walk is a few hundred bytes, and on the
    /// Cortex-M0 a copy of it costs about as much as walking a short edge.
    #[inline(always)]
    pub(crate) fn unclipped(e: Canon, mode: AreaMode, c_lo: i32) -> Self {
        let (a0, a1) = e.columns();
        let (b0, b1) = e.rows();
        // ONE dv <= 2^38; in 32 bits for edges of dv < 2^16.
        let (q, rr) = udivmod((e.dv as u64) << COVER_BITS, e.du as u64);
        Self {
            g: Geom {
                e,
                exact: mode == AreaMode::Exact,
                a0,
                a1,
                b0,
                b1,
                q: q as i32,
                rr: rr as i32,
                lc0: e.line_near_end(a0 * N + N / 2, false),
                lc1: e.line_near_end(a1 * N + N / 2, true),
                va: 0,
                vb: -1,
                c_lo,
                r_in: b0,
                r_out: b1 + 1,
            },
            cross: None,
            resume: None,
            once: false,
        }
    }

    /// Marks the walk as one that is walked for one band only and then
    /// dropped (no cache keeps it). When the walk's tracker is set up with
    /// at most [`DIRECT`] rows of the band left (an edge crosses at most
    /// one boundary a row: a row boundary for an x-major edge, a column
    /// boundary for a y-major one, `dv <= du`), the crossings are evaluated
    /// one at a time as the walk reaches them ([`Direct`]), rather than by
    /// setting up the stepping for the rest of the edge: the walk will not
    /// need the rest. The same spills either way (both are the exact
    /// floor); on the Cortex-M0 the benchmark's frame of 2 000 medium
    /// triangles in 16-row bands cost 166.1 M instead of 170.8 M when this
    /// came in.
    #[inline(always)]
    pub(crate) fn once(&mut self) {
        self.once = true;
    }

    /// The set-up's last step: which columns of an x-major edge are
    /// visible in frame columns `columns` (those given to
    /// [`unclipped`](Self::unclipped) as `c_lo..`).
    #[inline(always)]
    pub(crate) fn clip(&mut self, columns: Range<i32>) {
        if !self.g.e.transposed {
            self.g.clip_columns(columns);
        }
    }

    /// The frame rows canonical edge `e` touches: [`rows`](Self::rows) of
    /// its walk, known before the set-up.
    #[inline]
    pub(crate) fn rows_of(e: &Canon) -> Range<i32> {
        let (a0, a1) = if e.transposed { e.columns() } else { e.rows() };
        a0..a1 + 1
    }

    /// The frame rows the edge touches.
    // The canvas asks `rows_of` before the set-up; this is for the
    // `internals` API.
    #[cfg_attr(not(feature = "internals"), allow(dead_code))]
    pub fn rows(&self) -> Range<i32> {
        Self::rows_of(&self.g.e)
    }

    /// Reports the edge's pixels in frame rows `rows` to `sink`.
    pub fn walk<K: CoverSink>(&mut self, rows: Range<i32>, sink: &mut K) {
        let r = rows.clone();
        self.walk_into(r, Forward { sink, rows });
    }

    /// Walks frame rows `rows` straight into a band's coverage scratch:
    /// what [`walk`](Self::walk) reports, without a call per report.
    pub(crate) fn walk_band<const C: usize>(
        &mut self,
        rows: Range<i32>,
        buf: &mut crate::band::BandBuffer<'_, C>,
    ) {
        let out = buf.deltas(rows.clone());
        self.walk_into(rows, out);
    }

    /// Writes the edge's changes of running coverage in frame rows `rows`
    /// into `out` (a band's scratch, clipped to the same rows).
    pub(crate) fn walk_into<S: DeltaSink>(&mut self, rows: Range<i32>, out: S) {
        if rows.start >= rows.end {
            return;
        }
        if self.g.e.transposed {
            if self.g.e.mirrored {
                self.y_major::<S, true>(rows, out);
            } else {
                self.y_major::<S, false>(rows, out);
            }
        } else if self.g.e.mirrored {
            self.x_major::<S, true>(rows, out);
        } else {
            self.x_major::<S, false>(rows, out);
        }
    }
}

impl Geom {
    // ---- set-up ------------------------------------------------------------

    /// x-major: which major columns are visible, and the rows whose covers
    /// fall left of the frame (set-up, a few divisions).
    fn clip_columns(&mut self, cols: Range<i32>) {
        let (c_lo, c_hi) = (cols.start, cols.end);
        // Visible canonical columns: frame x in [c_lo, c_hi).
        let (vis_lo, vis_hi) = if self.e.mirrored {
            (c_hi.saturating_neg(), (-1i32).saturating_sub(c_lo))
        } else {
            (c_lo, c_hi.saturating_sub(1))
        };
        self.va = self.a0.max(vis_lo);
        self.vb = self.a1.min(vis_hi);
        // The side where columns are left of the frame: low canonical
        // columns unmirrored, high ones mirrored.
        let (b0, b1) = (self.b0, self.b1);
        if self.va > self.vb {
            let wholly_left = if self.e.mirrored {
                self.a0 > vis_hi
            } else {
                self.a1 < vis_lo
            };
            // Wholly left: every row's cover at c_lo; wholly right: none.
            (self.r_in, self.r_out) = match (wholly_left, self.e.mirrored) {
                (true, false) => (b1 + 1, b1 + 1),
                (true, true) => (b0, b0),
                (false, _) => (b0, b1 + 1),
            };
            return;
        }
        if !self.e.mirrored && self.va > self.a0 {
            self.r_in = self.centre_cell(self.va);
        }
        if self.e.mirrored && self.vb < self.a1 {
            self.r_out = self.centre_cell(self.vb);
        }
    }

    /// The chosen minor cell of column `a`: the one holding the (clamped)
    /// line at the column centre.
    fn centre_cell(&self, a: i32) -> i32 {
        let e = &self.e;
        let b = if self.a0 < self.a1 && a == self.a0 {
            if a * N + N / 2 <= e.u0 {
                self.b0
            } else {
                self.lc0.cell()
            }
        } else if self.a0 < self.a1 && a == self.a1 {
            if a * N + N / 2 >= e.u1 {
                cell_of(e.v1)
            } else {
                self.lc1.cell()
            }
        } else {
            e.cell_at(a * N + N / 2)
        };
        if self.e.transposed {
            b
        } else {
            b.min(self.b1).max(self.b0)
        }
    }

    /// Height of row `b` inside an x-major edge, in coverage units.
    #[inline]
    fn row_cover(&self, b: i32) -> i32 {
        ((b * N + N).min(self.e.v1) - (b * N).max(self.e.v0)) << H_BITS
    }

    /// Height of major row `a` inside a y-major edge, in coverage units.
    #[inline]
    fn column_cover(&self, a: i32) -> i32 {
        ((a * N + N).min(self.e.u1) - (a * N).max(self.e.u0)) << H_BITS
    }

    /// Half a column's rise of the line, `ONE dv / (2 du)`: the step's
    /// quotient and remainder halved (`ONE dv` is even).
    #[inline]
    fn half(&self) -> (i32, i32) {
        (self.q >> 1, ((self.q & 1) * self.e.du + self.rr) >> 1)
    }

    /// Direct evaluation of the main term at interior column `a`: at the
    /// first one a step from the line at the first column's centre, else
    /// (divides) the line at the column centre from the nearer end point,
    /// then its fraction to coverage units, a quotient below `2^6`.
    fn init(&self, a: i32) -> Step {
        let e = &self.e;
        let lv = if a == self.a0 + 1 {
            self.lc0.plus((self.q, self.rr), e.du)
        } else {
            let (vi, vr) = e.v_at(a * N + N / 2);
            // H v = H vi + H vr / du; H vr < 2^28.
            let (fq, fr) = udivmod(((vr as u32) << H_BITS).into(), e.du as u64);
            Lv {
                vi: (vi << H_BITS) + fq as i32,
                vr: fr as i32,
            }
        };
        let b = lv.cell();
        let (v_ref, h) = if !e.transposed && b == self.b0 {
            (e.v0, ((b + 1) * N - e.v0) << H_BITS)
        } else {
            (b * N, ONE)
        };
        // S = H (v - v_ref).
        Step {
            a,
            b,
            s: lv.vi - (v_ref << H_BITS),
            r: lv.vr,
            h,
        }
    }

    /// The last minor boundary strictly inside the edge.
    #[inline]
    fn last_boundary(&self) -> i32 {
        cell_of(self.e.v1 - 1)
    }

    /// The crossing tracker at interior column `a`: the first crossing at
    /// or after it, if one comes before the edge's last column (set-up on
    /// first use: the constants, then the state, eight divisions in all;
    /// when at most [`DIRECT`] are left, evaluated one at a time instead,
    /// [`Direct`]; none when the rest of the edge crosses no boundary
    /// inside). Written to `x` in place (a tracker is a few dozen words).
    /// `few`: the walk needs at most [`DIRECT`] more crossings, however
    /// many the edge has left (it is dropped after this band).
    fn track(&self, cross: &mut Option<Tracker>, x: &mut Next, a: i32, few: bool) {
        if !self.exact {
            *x = Next::Done;
            return;
        }
        // The first boundary whose crossing is at u >= a N, and whether it
        // comes before the last column: m N < v(a1 N). Interior columns
        // lie between the first and the last, so a1 > a0 + 1.
        let first = if a == self.a0 + 1 {
            self.lc0.plus(self.half(), self.e.du).boundary_ceil()
        } else {
            self.e.boundary_at_or_after(a * N)
        };
        let m = first.max(self.b0 + 1);
        let end = self.lc1.minus(self.half(), self.e.du).boundary_ceil();
        // The boundaries the walk needs: m up to the last one inside the
        // edge and before the last column.
        let end = end.min(self.last_boundary() + 1);
        if m >= end {
            *x = Next::Done;
            return;
        }
        if end - m <= DIRECT || few {
            // A few crossings left: evaluated directly, no stepping
            // constants.
            *x = Next::Direct {
                x: Direct::at(&self.e, m),
                end,
            };
            return;
        }
        if cross.is_none() {
            *cross = Tracker::new(self.e.du, self.e.dv);
        }
        *x = match cross {
            Some(Tracker::Wide(k)) => Next::At(k.at(&self.e, m)),
            Some(Tracker::Narrow(k)) => Next::AtN(k.at(&self.e, m)),
            None => Next::Done,
        };
    }

    /// Moves the tracker past the crossings in columns up to `a` (an end
    /// column: its crossings are in its direct areas).
    fn skip_crossings(&self, cross: &Option<Tracker>, x: &mut Next, a: i32) {
        match (&mut *x, cross) {
            (Next::At(c), Some(Tracker::Wide(k))) => {
                while c.col <= a && c.m <= self.last_boundary() {
                    c.advance(k);
                }
            }
            (Next::AtN(c), Some(Tracker::Narrow(k))) => {
                while c.col <= a && c.m <= self.last_boundary() {
                    c.advance(k);
                }
            }
            (Next::Direct { .. }, _) => {
                while matches!(x, Next::Direct { x, .. } if x.col <= a) {
                    x.pass_direct();
                }
            }
            _ => {}
        }
    }

    // ---- stepping (per column: add / compare) ------------------------------

    /// One column along the major axis; a diagonal step when the main term
    /// reaches the cell height (seed 001: horizontal vs diagonal by the
    /// sign of the evaluation function).
    #[inline]
    fn step(&self, st: &mut Step) {
        st.r += self.rr;
        if st.r >= self.e.du {
            st.r -= self.e.du;
            st.s += 1;
        }
        st.s += self.q;
        st.a += 1;
        if st.s >= st.h {
            st.s -= st.h;
            st.h = ONE;
            st.b += 1;
        }
    }

    /// The main term at interior column `a`: a step from the state at
    /// `a - 1` when there is one, else a direct start.
    #[inline]
    fn main_term(&self, st: Option<Step>, a: i32) -> Step {
        match st {
            Some(mut s) if s.a + 1 == a => {
                self.step(&mut s);
                s
            }
            _ => self.init(a),
        }
    }

    /// The cells of an end column (or end row of a y-major edge), computed
    /// directly from the exact area (per edge, twice): `(b, area - full)`
    /// for each cell the column's line touches, to `f`.
    fn end_cells<F: FnMut(i32, i32)>(&self, a: i32, bc: i32, mut f: F) {
        let e = &self.e;
        let (ulo, uhi) = if e.transposed {
            ((a * N).max(e.u0), (a * N + N).min(e.u1))
        } else {
            (a * N, a * N + N)
        };
        // The line where the column's part of the edge starts and ends,
        // exactly: an end point, or a column boundary next to one.
        let at_u0 = Lv {
            vi: e.v0 << H_BITS,
            vr: 0,
        };
        let at_u1 = Lv {
            vi: e.v1 << H_BITS,
            vr: 0,
        };
        let (mut lo, mut hi, ends) = if self.a0 < self.a1 && a == self.a0 {
            // From u <= u0 (the start's cell) to (a0 + 1) N < u1.
            let q = self.lc0.plus(self.half(), e.du);
            (self.b0, q.cell(), (e.u0, at_u0, a * N + N, q))
        } else if self.a0 < self.a1 && a == self.a1 {
            // From u0 < a1 N to u >= u1 (the end's cell).
            let p = self.lc1.minus(self.half(), e.du);
            (p.cell(), cell_of(e.v1), (a * N, p, e.u1, at_u1))
        } else {
            (e.cell_at(ulo), e.cell_at(uhi), (e.u0, at_u0, e.u1, at_u1))
        };
        if !e.transposed {
            lo = lo.min(self.b1).max(self.b0);
            hi = hi.min(self.b1).max(self.b0);
        }
        for b in lo..=hi {
            let (vlo, vhi) = if e.transposed {
                (b * N, b * N + N)
            } else {
                ((b * N).max(e.v0), (b * N + N).min(e.v1))
            };
            let area = match trapezoid_area(e, ulo, uhi, vlo, vhi, ends) {
                Some(area) => area,
                None => clamped_area(
                    e,
                    i64::from(ulo),
                    i64::from(uhi),
                    i64::from(vlo),
                    i64::from(vhi),
                ),
            };
            let full = if b >= bc {
                0
            } else if e.transposed {
                self.column_cover(a)
            } else {
                self.row_cover(b)
            };
            if area != full {
                f(b, area - full);
            }
        }
    }

    /// The last minor cell an end column's cells reach.
    fn end_last_cell(&self, a: i32) -> i32 {
        let c = if self.a0 < self.a1 && a == self.a0 {
            self.lc0.plus(self.half(), self.e.du).cell()
        } else if a == self.a1 {
            // a1 N + N >= u1: the end's cell.
            cell_of(self.e.v1)
        } else {
            self.e.cell_at(a * N + N)
        };
        c.min(self.b1).max(self.b0)
    }

    /// The state at which band `y0`'s walk starts, evaluated directly
    /// (divides).
    fn x_start(&self, y0: i32) -> Resume {
        let col = if y0 <= self.b0 {
            self.a0
        } else {
            // The column holding the crossing of the band's top boundary.
            self.e.crossing(y0).0
        };
        let a = col.max(self.va);
        let prev = if a == self.a0 {
            self.b0
        } else {
            (y0 - 1)
                .max(self.b0)
                .max(if self.e.mirrored { self.b0 } else { self.r_in })
        };
        Resume {
            row: y0,
            a,
            prev,
            st: None,
            x: if self.exact { Next::Unset } else { Next::Done },
        }
    }
}

impl EdgeWalk {
    // ---- the two walks -----------------------------------------------------

    /// Edges at most 45° from horizontal: major columns are frame columns
    /// (mirrored: negated), a row holds a run of edge pixels; one cover
    /// change per row.
    ///
    /// In frame terms, a change at canonical column `a` is written at the
    /// frame column of the boundary before it: `pos(a) = a`, or `-a` when
    /// mirrored (the pixel right of `-1 - a`); with `w` the winding, a cell
    /// `(a, b)` of canonical area `S` is `+w S` at `pos(a)` and `-w S` at
    /// `pos(a + 1)`, a cover `h` from column `a` on is `+w h` at `pos(a)`.
    ///
    /// Out of line: a y-major walk's entry then sets up only its own few
    /// values, not this walk's large frame (on the Cortex-M0 about 6
    /// instructions a resumed walk less).
    #[inline(never)]
    fn x_major<S: DeltaSink, const MIRRORED: bool>(&mut self, rows: Range<i32>, mut out: S) {
        let g = &self.g;
        let (y0, y1) = (rows.start, rows.end);
        let (b0, b1) = (g.b0, g.b1);
        let lo = y0.max(b0);
        let hi = y1.min(b1 + 1);
        if lo >= hi {
            return;
        }
        let w = i32::from(g.e.dir);
        let pos = |a: i32| if MIRRORED { a.saturating_neg() } else { a };
        let step_x = if MIRRORED { -1 } else { 1 };
        // Rows whose covers lie left of the frame: straight to c_lo.
        let left = if MIRRORED {
            g.r_out..b1 + 1
        } else {
            b0..g.r_in
        };
        for row in lo.max(left.start)..hi.min(left.end) {
            out.put(g.c_lo, row, w * g.row_cover(row));
        }
        // Where the walk starts: where the last band stopped, or directly
        // at the column holding the crossing of this band's top boundary.
        // (Fields are copied one by one, the crossing state straight into
        // `x`: a tuple of them was built first and then copied again, two
        // library copies of 72 bytes per band on the Cortex-M0.)
        let (mut a, mut prev, mut st, mut x);
        match &self.resume {
            Some(r) if r.row == y0 => {
                (a, prev, st) = (r.a, r.prev, r.st);
                x = r.x;
            }
            _ => {
                let r = g.x_start(y0);
                (a, prev, st) = (r.a, r.prev, r.st);
                x = r.x;
            }
        }
        // Whether the state the next band starts from is stored yet: it is
        // written in place when the walk reaches it (a resume is a few
        // dozen words, and each copy of one costs on the Cortex-M0).
        let mut next = false;
        // What the last column walked left to add at `pos(a)` of its main
        // row (the `-S` of its main cell, and of a spill there): the row
        // and the canonical value.
        let mut pend: Option<(i32, i32)> = None;
        loop {
            if a > g.vb {
                if let Some((pb, pv)) = pend.take() {
                    out.put(pos(a), pb, w * pv);
                }
                if a > g.a1 && g.vb == g.a1 {
                    // Past the end: the last rows' covers right of it.
                    let col = pos(g.a1 + 1);
                    for row in prev.max(lo)..=b1.min(hi - 1) {
                        out.put(col, row, w * g.row_cover(row));
                    }
                }
                // Nothing more to walk from here, unless a column already
                // walked reaches into the next band.
                if !next {
                    next = true;
                    self.resume = Some(Resume {
                        row: y1,
                        a,
                        prev,
                        st: None,
                        x: Next::Done,
                    });
                }
                break;
            }
            let is_end = a == g.a0 || a == g.a1;
            if is_end {
                if let Some((pb, pv)) = pend.take() {
                    out.put(pos(a), pb, w * pv);
                }
                let bc = g.centre_cell(a);
                if !next && g.end_last_cell(a) >= y1 {
                    next = true;
                    self.resume = Some(Resume {
                        row: y1,
                        a,
                        prev,
                        st,
                        x,
                    });
                }
                let (pa, pa1) = (pos(a), pos(a + 1));
                g.end_cells(a, bc, |b, v| out.put2(pa, pa1, b, w * v, -w * v));
                // Crossings inside an end column are in its direct areas.
                g.skip_crossings(&self.cross, &mut x, a);
                for row in prev.max(lo)..bc.min(hi) {
                    out.put(pa, row, w * g.row_cover(row));
                }
                prev = prev.max(bc);
                st = None;
                if bc >= y1 {
                    break;
                }
                a += 1;
                continue;
            }
            // An interior column: first the plain ones, as a run.
            if let (Some(s), Some((pb, pv))) = (st, pend) {
                if s.a + 1 == a && pb == s.b {
                    let x_col = match &x {
                        Next::Unset => a,
                        x => x.col(),
                    };
                    let stop = x_col.min(g.a1).min(g.vb.saturating_add(1));
                    if stop > a {
                        let (mut ss, mut r) = (s.s, s.r);
                        // The first change also takes what the last column
                        // left (0 after a plain one).
                        let mut carry = pv + s.s;
                        let (q, rr, du, h) = (g.q, g.rr, g.e.du, s.h);
                        let done = out.run(pos(a), s.b, step_x, stop - a, || {
                            let mut d = q;
                            let mut r2 = r + rr;
                            if r2 >= du {
                                r2 -= du;
                                d += 1;
                            }
                            if ss + d >= h {
                                return None;
                            }
                            ss += d;
                            r = r2;
                            let v = d + carry;
                            carry = 0;
                            Some(w * v)
                        });
                        if done > 0 {
                            a += done;
                            st = Some(Step {
                                a: a - 1,
                                b: s.b,
                                s: ss,
                                r,
                                h,
                            });
                            pend = Some((s.b, -ss));
                            continue;
                        }
                    }
                }
            }
            let s = g.main_term(st, a);
            if let Next::Unset = x {
                // Dropped after this band: its crossings are those of
                // boundaries up to y1, one per row at most.
                let few = self.once && y1 - s.b <= DIRECT;
                g.track(&mut self.cross, &mut x, a, few);
            }
            let (here, down) = match x.down_at(a, &self.cross) {
                Some(down) => (true, down),
                None => (false, false),
            };
            let bc = s.b;
            if !next && bc + i32::from(down) >= y1 {
                // The first column reaching below this band: the next band
                // starts here.
                next = true;
                self.resume = Some(Resume {
                    row: y1,
                    a,
                    prev,
                    st,
                    x,
                });
            }
            let (pa, pa1) = (pos(a), pos(a + 1));
            // The column's changes in rows bc - 1 (`up`), bc (`mid`) and
            // bc + 1 (`dn`), at `pa` and `pa1`, added up first: the main
            // cell, what the last column left, the covers of the rows the
            // line has left (normally just bc - 1), the spill.
            let (mut up0, mut up1) = (0, 0);
            let (mut mid0, mut mid1) = (s.s, -s.s);
            let (mut dn0, mut dn1) = (0, 0);
            match pend {
                Some((pb, pv)) if pb == bc => mid0 += pv,
                Some((pb, pv)) if pb == bc - 1 => up0 += pv,
                Some((pb, pv)) => out.put(pa, pb, w * pv),
                None => {}
            }
            for row in prev..bc {
                if row == bc - 1 {
                    up0 += g.row_cover(row);
                } else if row >= lo && row < hi {
                    out.put(pa, row, w * g.row_cover(row));
                }
            }
            if here {
                // The spill: taken from the cell above the boundary, given
                // to the one below.
                let t = x.take_spill(&self.cross);
                if down {
                    // Boundary bc + 1.
                    mid0 -= t;
                    mid1 += t;
                    dn0 += t;
                    dn1 -= t;
                } else {
                    // Boundary bc.
                    up0 -= t;
                    up1 += t;
                    mid0 += t;
                    mid1 -= t;
                }
            }
            if up0 != 0 || up1 != 0 {
                out.put2(pa, pa1, bc - 1, w * up0, w * up1);
            }
            out.put(pa, bc, w * mid0);
            if dn0 != 0 || dn1 != 0 {
                out.put2(pa, pa1, bc + 1, w * dn0, w * dn1);
            }
            pend = Some((bc, mid1));
            prev = prev.max(bc);
            st = Some(s);
            if bc >= y1 {
                break;
            }
            a += 1;
        }
        if !next {
            self.resume = None;
        }
    }

    /// Edges steeper than 45°: major columns are frame rows, one or two
    /// edge pixels each, one cover change each.
    ///
    /// With `mpos(b) = b`, or `-b` when mirrored (the frame column of minor
    /// boundary `b`), a cell `(a, b)` of canonical area `S` is `-w S` at
    /// `mpos(b)` and `+w S` at `mpos(b + 1)` of row `a`, the row's cover
    /// `+w h` at `mpos(bc)`.
    fn y_major<S: DeltaSink, const MIRRORED: bool>(&mut self, rows: Range<i32>, mut out: S) {
        let g = &self.g;
        let lo = rows.start.max(g.a0);
        let hi = rows.end.min(g.a1 + 1);
        if lo >= hi {
            return;
        }
        let w = i32::from(g.e.dir);
        let mpos = |b: i32| if MIRRORED { b.saturating_neg() } else { b };
        let step_x = if MIRRORED { -1 } else { 1 };
        // The state is stepped where it is kept, the crossing and the main
        // term too (a start is written over a stale one): a copy in and
        // out would cost as much as a few rows.
        let r = match &mut self.resume {
            Some(r) if r.a == lo => r,
            slot => slot.insert(Resume {
                row: lo,
                a: lo,
                prev: 0,
                st: None,
                x: if g.exact { Next::Unset } else { Next::Done },
            }),
        };
        let (x, st) = (&mut r.x, &mut r.st);
        for a in lo..hi {
            if a == g.a0 || a == g.a1 {
                *st = None;
                let bc = g.centre_cell(a);
                g.end_cells(a, bc, |b, v| {
                    out.put(mpos(b), a, -w * v);
                    out.put(mpos(b + 1), a, w * v);
                });
                g.skip_crossings(&self.cross, x, a);
                out.put(mpos(bc), a, w * g.column_cover(a));
                continue;
            }
            let s = g.main_term(*st, a);
            *st = Some(s);
            if let Next::Unset = x {
                // Dropped after this band: at most one crossing a row
                // (`dv <= du`).
                let few = self.once && hi - a <= DIRECT;
                g.track(&mut self.cross, x, a, few);
            }
            let bc = s.b;
            match x.down_at(a, &self.cross) {
                Some(down) => {
                    let t = x.take_spill(&self.cross);
                    if !down {
                        // m = bc: (m - 1, -t), (m, S + t).
                        out.put_n(
                            mpos(bc - 1),
                            a,
                            step_x,
                            [w * t, w * (ONE - s.s - 2 * t), w * (s.s + t)],
                        );
                    } else {
                        // m = bc + 1: (bc, S - t), (bc + 1, t).
                        out.put_n(
                            mpos(bc),
                            a,
                            step_x,
                            [w * (ONE - s.s + t), w * (s.s - 2 * t), w * t],
                        );
                    }
                }
                None => out.put_n(mpos(bc), a, step_x, [w * (ONE - s.s), w * s.s]),
            }
        }
        // (`row` and `prev` are the x-major walk's; a y-major one keys on
        // `a` alone.)
        r.a = hi;
    }
}

/// [`clamped_area`] of cell `[ulo, uhi] x [vlo, vhi]` of an end column
/// when the line stays inside the cell's rows where it is inside the edge
/// (`ends`: the line's exact points `(p, Vp)`, `(q, Vq)` at the start and
/// end of that part, in coverage-height units): then the area is a
/// trapezoid and the flat extensions, over the one denominator `du`, and
/// its floor takes one short 32-bit division (a quotient below `2^11`)
/// instead of the general case's 64-bit ones. `None` when the line leaves
/// the rows (the general case).
///
/// With `I = Vp + Vq - 2 H vlo` split as `vi + vr / du`, the area in fine
/// units² is `(q - p) (vi + vr / du) / (2 H) + flat`, so in coverage units
/// (`/ 16`) `floor(((q - p) vi + 2 H flat + floor((q - p) vr / du)) / 32 H)`:
/// `(q - p) <= 2^10`, `vi <= 2^17`, `flat <= 2^20`, `vr < 2 du`.
fn trapezoid_area(
    e: &Canon,
    ulo: i32,
    uhi: i32,
    vlo: i32,
    vhi: i32,
    (p, vp, q, vq): (i32, Lv, i32, Lv),
) -> Option<i32> {
    let h = vhi - vlo;
    let (hlo, hhi) = (vlo << H_BITS, vhi << H_BITS);
    // Inside the rows at both ends (the line is monotone between them).
    let inside = vp.vi >= hlo && (vq.vi < hhi || (vq.vi == hhi && vq.vr == 0));
    if h <= 0 || q <= p || !inside || e.du >= 1 << 21 {
        return None;
    }
    let len = (q - p) as u32;
    let flat = (e.u0 - ulo).max(0) * (e.v0 - vlo).min(h).max(0)
        + (uhi - e.u1).max(0) * (e.v1 - vlo).min(h).max(0);
    let vi = (vp.vi + vq.vi - 2 * hlo) as u32;
    // (q - p) (vr_p + vr_q) < 2^10 2^22: a u32 (du < 2^21).
    let (fq, _) = udivmod(u64::from(len * (vp.vr + vq.vr) as u32), e.du as u64);
    let num = len * vi + ((flat as u32) << (H_BITS + 1)) + fq as u32;
    Some((num >> (H_BITS + 1 + 2 * crate::geom::FINE_BITS - COVER_BITS)) as i32)
}
