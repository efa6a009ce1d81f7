//! The anti-aliased walk: set-up of the step constants (may divide), then
//! the per-column stepping (add / compare only, the exact mode's spill
//! included), resumable from one band to the next.

use core::ops::Range;

use super::area::clamped_area;
use super::canon::{Canon, N};
use super::crossing::{Crossing, Crossings};
use super::{AreaMode, CoverSink};
use crate::arith::{div_floor, divmod_floor, limit};
use crate::geom::FinePoint;
use crate::COVER_ONE;

/// A whole pixel of coverage.
const ONE: i32 = COVER_ONE;
/// Coverage units per fine unit of height across a whole column.
const H: i64 = COVER_ONE as i64 / N;

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
    x: Option<Crossing>,
}

/// One edge of a shape, set up once and walked band by band.
///
/// Built from two fine points ([`FinePoint`]); horizontal edges are `None`
/// (they cut off no area in the row-wise model). [`walk`](Self::walk)
/// reports, through a [`CoverSink`], every pixel of the given rows the edge
/// cuts (its signed area right of the edge, inside the edge's own y-range)
/// and, per row, the column from which the edge's full height applies.
/// Walking the bands of a frame top to bottom resumes where the previous
/// band stopped; any other order starts over from a direct evaluation. Both
/// give the same bits.
///
/// The signs: an edge that runs down the screen reports `+` the area right
/// of it, one that runs up `-`; so the sum over the edges of closed
/// contours is, in every pixel, the integral of the winding number.
#[derive(Debug, Clone, Copy)]
pub struct EdgeWalk {
    e: Canon,
    /// Sign of the cell areas: the winding times the side of the canonical
    /// area.
    sw: i32,
    /// Sign of the covers: the winding.
    w: i32,
    /// First and last major columns, first and last minor rows.
    a0: i32,
    a1: i32,
    b0: i32,
    b1: i32,
    /// Main term step per column `ONE dv / du`, quotient and remainder.
    du: i32,
    q: i32,
    rr: i32,
    cross: Option<Crossings>,
    /// x-major only: the visible major columns `va..=vb` (empty when
    /// `va > vb`), the frame column covers left of them go to, and the
    /// rows whose cover columns lie left of the frame: `b0..r_in` (not
    /// mirrored) or `r_out..=b1` (mirrored).
    va: i32,
    vb: i32,
    c_lo: i32,
    c_hi: i32,
    r_in: i32,
    r_out: i32,
    resume: Option<Resume>,
}

impl EdgeWalk {
    /// Sets up the edge `p0 -> p1` for a sink keeping the frame columns
    /// `columns` (divides: once per edge and frame). `None` for a
    /// horizontal edge. Points must be within the fine coordinate range
    /// (`FinePoint::in_range`); the caller checks.
    pub fn new(p0: FinePoint, p1: FinePoint, mode: AreaMode, columns: Range<i32>) -> Option<Self> {
        let e = Canon::new(p0, p1)?;
        let (a0, a1) = e.columns();
        let (b0, b1) = e.rows();
        let one = i64::from(ONE);
        let exact = mode == AreaMode::Exact;
        let (q, rr) = divmod_floor(one * e.dv, e.du);
        let mut walk = Self {
            e,
            sw: e.sign() * e.dir,
            w: e.dir,
            a0: a0 as i32,
            a1: a1 as i32,
            b0: b0 as i32,
            b1: b1 as i32,
            du: e.du as i32,
            q: q as i32,
            rr: rr as i32,
            cross: if exact {
                Crossings::new(e.u0, e.v0, e.du, e.dv)
            } else {
                None
            },
            va: 0,
            vb: -1,
            c_lo: columns.start,
            c_hi: columns.end,
            r_in: b0 as i32,
            r_out: b1 as i32 + 1,
            resume: None,
        };
        if !e.transposed {
            walk.clip_columns(columns);
        }
        Some(walk)
    }

    /// The frame rows the edge touches.
    pub fn rows(&self) -> Range<i32> {
        if self.e.transposed {
            self.a0..self.a1 + 1
        } else {
            self.b0..self.b1 + 1
        }
    }

    /// Reports the edge's pixels in frame rows `rows` to `sink`.
    pub fn walk<K: CoverSink>(&mut self, rows: Range<i32>, sink: &mut K) {
        if rows.start >= rows.end {
            return;
        }
        if self.e.transposed {
            self.y_major(rows, sink);
        } else {
            self.x_major(rows, sink);
        }
    }

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
        let b = self.e.cell_at(i64::from(a) * N + N / 2);
        if self.e.transposed {
            b as i32
        } else {
            limit(b, i64::from(self.b0), i64::from(self.b1)) as i32
        }
    }

    /// Height of row `b` inside an x-major edge, in coverage units.
    fn row_cover(&self, b: i32) -> i32 {
        let b = i64::from(b);
        (H * ((b * N + N).min(self.e.v1) - (b * N).max(self.e.v0))) as i32
    }

    /// Height of major row `a` inside a y-major edge, in coverage units.
    fn column_cover(&self, a: i32) -> i32 {
        let a = i64::from(a);
        (H * ((a * N + N).min(self.e.u1) - (a * N).max(self.e.u0))) as i32
    }

    /// Direct evaluation of the main term at interior column `a` (divides).
    fn init(&self, a: i32) -> Step {
        let e = &self.e;
        let vn = e.v0 * e.du + (i64::from(a) * N + N / 2 - e.u0) * e.dv;
        let b = div_floor(vn, N * e.du);
        let (v_ref, h) = if !e.transposed && b == i64::from(self.b0) {
            (e.v0, H * ((b + 1) * N - e.v0))
        } else {
            (b * N, i64::from(ONE))
        };
        let n = H * (vn - v_ref * e.du);
        let (s, r) = divmod_floor(n, e.du);
        Step {
            a,
            b: b as i32,
            s: s as i32,
            r: r as i32,
            h: h as i32,
        }
    }

    /// The first crossing at or after boundary `m` whose column is past
    /// `after` (set-up: divides).
    fn crossing_from(&self, m: i32, after: i32) -> Option<Crossing> {
        let k = self.cross.as_ref()?;
        let mut x = k.at(m);
        while x.col <= after && x.m <= self.last_boundary() {
            x.advance(k);
        }
        Some(x)
    }

    /// The last minor boundary strictly inside the edge.
    fn last_boundary(&self) -> i32 {
        div_floor(self.e.v1 - 1, N) as i32
    }

    // ---- stepping (per column: add / compare) ------------------------------

    /// One column along the major axis; a diagonal step when the main term
    /// reaches the cell height (seed 001: horizontal vs diagonal by the
    /// sign of the evaluation function).
    #[inline]
    fn step(&self, st: &mut Step) {
        st.r += self.rr;
        if st.r >= self.du {
            st.r -= self.du;
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

    // ---- reporting ---------------------------------------------------------

    /// Reports canonical cell `(a, b)`'s change of low-`v` area `cov` if
    /// its frame row is in `rows`.
    #[inline]
    fn emit<K: CoverSink>(&self, a: i32, b: i32, cov: i32, rows: &Range<i32>, sink: &mut K) {
        if cov == 0 {
            return;
        }
        let (x, y) = self.e.pixel(a, b);
        if rows.contains(&y) && x >= self.c_lo && x < self.c_hi {
            sink.cell(x, y, self.sw * cov);
        }
    }

    /// The spill of the crossing in column `a`: taken from the cell above
    /// the boundary, given to the one below.
    #[inline]
    fn spill<K: CoverSink>(&self, a: i32, x: &Crossing, rows: &Range<i32>, sink: &mut K) {
        if let Some(k) = &self.cross {
            let t = x.spill(k);
            self.emit(a, x.m - 1, -t, rows, sink);
            self.emit(a, x.m, t, rows, sink);
        }
    }

    /// Frame row `y`'s cover of height `h` from frame column `x` on.
    #[inline]
    fn cover<K: CoverSink>(&self, x: i32, y: i32, h: i32, rows: &Range<i32>, sink: &mut K) {
        if h != 0 && rows.contains(&y) {
            sink.cover(x, y, self.w * h);
        }
    }

    /// An end column (or end row of a y-major edge), computed directly from
    /// the exact area (per edge, twice).
    fn end_cells<K: CoverSink>(&self, a: i32, bc: i32, rows: &Range<i32>, sink: &mut K) {
        let e = &self.e;
        let a64 = i64::from(a);
        let (ulo, uhi) = if e.transposed {
            ((a64 * N).max(e.u0), (a64 * N + N).min(e.u1))
        } else {
            (a64 * N, a64 * N + N)
        };
        let (mut lo, mut hi) = (e.cell_at(ulo), e.cell_at(uhi));
        if !e.transposed {
            lo = limit(lo, i64::from(self.b0), i64::from(self.b1));
            hi = limit(hi, i64::from(self.b0), i64::from(self.b1));
        }
        for b in lo as i32..=hi as i32 {
            let b64 = i64::from(b);
            let (vlo, vhi) = if e.transposed {
                (b64 * N, b64 * N + N)
            } else {
                ((b64 * N).max(e.v0), (b64 * N + N).min(e.v1))
            };
            let area = clamped_area(e, ulo, uhi, vlo, vhi);
            let full = if b >= bc {
                0
            } else if e.transposed {
                self.column_cover(a)
            } else {
                self.row_cover(b)
            };
            self.emit(a, b, area - full, rows, sink);
        }
    }

    /// The last minor cell an end column's cells reach.
    fn end_last_cell(&self, a: i32) -> i32 {
        let c = self.e.cell_at(i64::from(a) * N + N);
        limit(c, i64::from(self.b0), i64::from(self.b1)) as i32
    }

    // ---- the two walks -----------------------------------------------------

    /// Edges at most 45° from horizontal: major columns are frame columns,
    /// a row holds a run of edge pixels; one cover change per row.
    fn x_major<K: CoverSink>(&mut self, rows: Range<i32>, sink: &mut K) {
        let (y0, y1) = (rows.start, rows.end);
        let (b0, b1) = (self.b0, self.b1);
        let lo = y0.max(b0);
        let hi = y1.min(b1 + 1);
        if lo >= hi {
            return;
        }
        // Rows whose covers lie left of the frame: straight to c_lo.
        let left = if self.e.mirrored {
            self.r_out..b1 + 1
        } else {
            b0..self.r_in
        };
        for row in lo.max(left.start)..hi.min(left.end) {
            self.cover(self.c_lo, row, self.row_cover(row), &rows, sink);
        }
        // Where the walk starts: where the last band stopped, or directly
        // at the column holding the crossing of this band's top boundary.
        let start = match self.resume.take() {
            Some(r) if r.row == y0 => r,
            _ => self.x_start(y0),
        };
        let (mut a, mut prev, mut st, mut x) = (start.a, start.prev, start.st, start.x);
        let mut next: Option<Resume> = None;
        loop {
            if a > self.vb {
                if a > self.a1 && self.vb == self.a1 {
                    // Past the end: the last rows' covers right of it.
                    for row in prev..=b1 {
                        let col = self.e.cover_column(self.a1 + 1);
                        self.cover(col, row, self.row_cover(row), &rows, sink);
                    }
                }
                // Nothing more to walk from here, unless a column already
                // walked reaches into the next band.
                next = next.or(Some(Resume {
                    row: y1,
                    a,
                    prev,
                    st: None,
                    x: None,
                }));
                break;
            }
            let is_end = a == self.a0 || a == self.a1;
            let (bc, last, stepped) = if is_end {
                (self.centre_cell(a), self.end_last_cell(a), None)
            } else {
                let s = self.main_term(st, a);
                let down = match (&x, &self.cross) {
                    (Some(x), Some(k)) => x.col == a && !x.is_left(k),
                    _ => false,
                };
                (s.b, s.b + i32::from(down), Some(s))
            };
            if next.is_none() && last >= y1 {
                // The first column reaching below this band: the next band
                // starts here.
                next = Some(Resume {
                    row: y1,
                    a,
                    prev,
                    st,
                    x,
                });
            }
            if let Some(s) = &stepped {
                self.emit(a, s.b, s.s, &rows, sink);
                if let Some(c) = x.as_mut().filter(|c| c.col == a) {
                    self.spill(a, c, &rows, sink);
                    if let Some(k) = &self.cross {
                        c.advance(k);
                    }
                }
            } else {
                self.end_cells(a, bc, &rows, sink);
                // Crossings inside an end column are in its direct areas.
                if let (Some(c), Some(k)) = (x.as_mut(), &self.cross) {
                    while c.col <= a && c.m <= self.last_boundary() {
                        c.advance(k);
                    }
                }
            }
            let col = self.e.cover_column(a);
            for row in prev..bc {
                self.cover(col, row, self.row_cover(row), &rows, sink);
            }
            prev = prev.max(bc);
            st = stepped;
            if bc >= y1 {
                break;
            }
            a += 1;
        }
        self.resume = next;
    }

    /// The state at which band `y0`'s walk starts, evaluated directly
    /// (divides).
    fn x_start(&self, y0: i32) -> Resume {
        let e = &self.e;
        let col = if y0 <= self.b0 {
            self.a0
        } else {
            // The column holding the crossing of the band's top boundary.
            let t = e.u0 * e.dv + (i64::from(y0) * N - e.v0) * e.du;
            div_floor(t, N * e.dv) as i32
        };
        let a = col.max(self.va);
        let prev = if a == self.a0 {
            self.b0
        } else {
            (y0 - 1)
                .max(self.b0)
                .max(if self.e.mirrored { self.b0 } else { self.r_in })
        };
        // The next crossing at or after column a.
        let x = if a > self.vb {
            None
        } else {
            let m = if a == self.a0 {
                self.b0 + 1
            } else {
                self.centre_cell(a)
            };
            self.crossing_from(m.max(self.b0 + 1), a - 1)
        };
        Resume {
            row: y0,
            a,
            prev,
            st: None,
            x,
        }
    }

    /// Edges steeper than 45°: major columns are frame rows, one or two
    /// edge pixels each, one cover change each.
    fn y_major<K: CoverSink>(&mut self, rows: Range<i32>, sink: &mut K) {
        let lo = rows.start.max(self.a0);
        let hi = rows.end.min(self.a1 + 1);
        if lo >= hi {
            return;
        }
        let (mut st, mut x) = match self.resume.take() {
            Some(r) if r.a == lo => (r.st, r.x),
            _ => {
                let m = if lo == self.a0 {
                    div_floor(self.e.v0, N) as i32 + 1
                } else {
                    self.centre_cell(lo)
                };
                (None, self.crossing_from(m, lo - 1))
            }
        };
        for a in lo..hi {
            let bc = if a == self.a0 || a == self.a1 {
                st = None;
                let bc = self.centre_cell(a);
                self.end_cells(a, bc, &rows, sink);
                if let (Some(c), Some(k)) = (x.as_mut(), &self.cross) {
                    while c.col <= a && c.m <= self.last_boundary() {
                        c.advance(k);
                    }
                }
                bc
            } else {
                let s = self.main_term(st, a);
                self.emit(a, s.b, s.s, &rows, sink);
                if let Some(c) = x.as_mut().filter(|c| c.col == a) {
                    self.spill(a, c, &rows, sink);
                    if let Some(k) = &self.cross {
                        c.advance(k);
                    }
                }
                st = Some(s);
                s.b
            };
            self.cover(
                self.e.cover_column(bc),
                a,
                self.column_cover(a),
                &rows,
                sink,
            );
        }
        self.resume = Some(Resume {
            row: hi,
            a: hi,
            prev: 0,
            st,
            x,
        });
    }
}
