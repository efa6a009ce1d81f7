//! The anti-aliased walk: setup of the step constants (may divide), then the
//! per-column stepping (add / compare only, plus the exact-mode spill).

use core::ops::Range;

use super::area::clamped_area;
use super::canon::Canon;
use super::{AreaMode, EdgeSink, Plane};
use crate::arith::{div_ceil, div_floor, limit, rem_floor};
use crate::shade::PLANE_FRAC;
use crate::{COVER_BITS, COVER_ONE, SUB_BITS, SUB_ONE};

/// One pixel of `v` over a full column, in coverage units: `4096 / 16`.
const COVER_PER_SUB: i64 = (COVER_ONE / SUB_ONE) as i64;
const ONE: i64 = COVER_ONE as i64;
const SUB: i64 = SUB_ONE as i64;

/// Walks the edge `p0 -> p1` and reports its pixels in `rows` to `sink`.
///
/// `orientation` is `+1` when the polygon's inside lies right of its edges
/// running down the screen, `-1` otherwise (see
/// [`raster`](crate::raster)); horizontal edges report nothing.
///
/// ```
/// use softedge::edge::{walk_edge, AreaMode, EdgeSink, Plane};
/// use softedge::SubPoint;
///
/// struct Sum(i64);
/// impl EdgeSink<1> for Sum {
///     fn cell(&mut self, _x: i32, _y: i32, cov: i32, _v: &[i32; 1]) { self.0 += i64::from(cov); }
///     fn cover(&mut self, x: i32, _y: i32, d: i32) { self.0 += i64::from(d) * i64::from(10 - x); }
/// }
/// // A vertical edge at x = 4.5 px from y = 0 to y = 2: right of it, inside
/// // columns 0..10, lie 5.5 px per row: 11 px² in all.
/// let mut sum = Sum(0);
/// let e = (SubPoint::new(72, 0), SubPoint::new(72, 32));
/// walk_edge(e.0, e.1, 1, &Plane::flat([4095], [0]), AreaMode::Exact, 0..2, &mut sum);
/// assert_eq!(sum.0, 11 * 4096);
/// ```
#[inline(never)] // a frame's edges: kept out of line so profiles can name it
pub fn walk_edge<const C: usize, K: EdgeSink<C>>(
    p0: crate::SubPoint,
    p1: crate::SubPoint,
    orientation: i32,
    plane: &Plane<C>,
    mode: AreaMode,
    rows: Range<i32>,
    sink: &mut K,
) {
    // Rows the edge can touch; nothing to set up for an edge outside them.
    let (top, bottom) = (p0.y.min(p1.y) >> SUB_BITS, p0.y.max(p1.y) >> SUB_BITS);
    if bottom < rows.start || top >= rows.end {
        return;
    }
    let Some(e) = Canon::new(p0, p1) else {
        return;
    };
    let w = orientation.signum() * e.dir;
    if w == 0 || rows.start >= rows.end {
        return;
    }
    let mut walker = Walker::new(e, w, plane, mode, rows, sink);
    if e.transposed {
        walker.y_major();
    } else {
        walker.x_major();
    }
}

/// Per-edge constants and the sink.
struct Walker<'a, const C: usize, K> {
    e: Canon,
    /// Sign of the cell values: winding times the side of the canonical area.
    sw: i64,
    /// Winding of the cover.
    w: i64,
    plane: &'a Plane<C>,
    exact: bool,
    ylo: i64,
    yhi: i64,
    sink: &'a mut K,
    /// Main term step `4096 * dv / du` as quotient and remainder.
    q: i64,
    rr: i64,
    /// Half a column of `v`, `2048 * dv / du`, as quotient and remainder.
    kq: i64,
    kr: i64,
    /// `2^19 * du / dv`: turns `e^2` into the spill `e^2 / (2k)` (`>> 32`).
    inv: u64,
    gu: [i64; C],
    gv: [i64; C],
    gq: [i64; C],
    gvq: [i64; C],
    b0: i64,
    b1: i64,
}

/// The walker's state at one column: exact integers, so equal to what a
/// direct evaluation at that column gives.
struct Step<const C: usize> {
    a: i64,
    /// Chosen minor cell.
    b: i64,
    /// Main term `S` (floor, 1/4096 px) and its remainder over `du`.
    s: i64,
    r: i64,
    /// `S` at which the walk leaves the cell (4096, or less in an x-major
    /// edge's first row).
    h: i64,
    /// Plane at the chosen pixel, `P = I * S`, `A = I * q`, `B = g_u * S`,
    /// `G = g_v * S`.
    i: [i64; C],
    p: [i64; C],
    pa: [i64; C],
    pb: [i64; C],
    pg: [i64; C],
}

impl<'a, const C: usize, K: EdgeSink<C>> Walker<'a, C, K> {
    // ---- setup (per edge) ------------------------------------------------

    fn new(
        e: Canon,
        w: i32,
        plane: &'a Plane<C>,
        mode: AreaMode,
        rows: Range<i32>,
        sink: &'a mut K,
    ) -> Self {
        let du = e.du;
        let q = div_floor(ONE * e.dv, du);
        let rr = rem_floor(ONE * e.dv, du);
        let kq = div_floor(ONE / 2 * e.dv, du);
        let kr = rem_floor(ONE / 2 * e.dv, du);
        let inv = if e.dv > 0 {
            ((du as u64) << 19).checked_div(e.dv as u64).unwrap_or(0)
        } else {
            0
        };
        let mut gu = [0i64; C];
        let mut gv = [0i64; C];
        let mut gq = [0i64; C];
        let mut gvq = [0i64; C];
        for ch in 0..C {
            let (u, v) = e.gradients(plane.gx[ch], plane.gy[ch]);
            gu[ch] = i64::from(u);
            gv[ch] = i64::from(v);
            gq[ch] = gu[ch] * q;
            gvq[ch] = gv[ch] * q;
        }
        let (b0, b1) = e.rows();
        Self {
            e,
            sw: i64::from(e.sign() * w),
            w: i64::from(w),
            plane,
            exact: mode == AreaMode::Exact,
            ylo: i64::from(rows.start),
            yhi: i64::from(rows.end),
            sink,
            q,
            rr,
            kq,
            kr,
            inv,
            gu,
            gv,
            gq,
            gvq,
            b0,
            b1,
        }
    }

    /// Chosen minor cell of column `a`: the cell holding the (clamped) line
    /// at the column centre.
    fn centre_cell(&self, a: i64) -> i64 {
        let b = div_floor(self.e.v_num_clamped(a * SUB + SUB / 2), SUB * self.e.du);
        if self.e.transposed {
            b
        } else {
            limit(b, self.b0, self.b1)
        }
    }

    /// Height of row `b` inside an x-major edge, in coverage units.
    fn row_cover(&self, b: i64) -> i64 {
        COVER_PER_SUB * ((b * SUB + SUB).min(self.e.v1) - (b * SUB).max(self.e.v0))
    }

    /// Height of major column `a` inside a y-major edge, in coverage units.
    fn column_cover(&self, a: i64) -> i64 {
        COVER_PER_SUB * ((a * SUB + SUB).min(self.e.u1) - (a * SUB).max(self.e.u0))
    }

    /// Direct evaluation of the state at interior column `a` (divides).
    fn init(&self, a: i64) -> Step<C> {
        let e = &self.e;
        let vn = e.v0 * e.du + (a * SUB + SUB / 2 - e.u0) * e.dv;
        let b = div_floor(vn, SUB * e.du);
        let (v_ref, h) = if !e.transposed && b == self.b0 {
            (e.v0, COVER_PER_SUB * ((b + 1) * SUB - e.v0))
        } else {
            (b * SUB, ONE)
        };
        let n = COVER_PER_SUB * (vn - v_ref * e.du);
        let (s, r) = (div_floor(n, e.du), rem_floor(n, e.du));
        let i = self.plane_at(a, b);
        let mut st = Step {
            a,
            b,
            s,
            r,
            h,
            i,
            p: [0; C],
            pa: [0; C],
            pb: [0; C],
            pg: [0; C],
        };
        for ch in 0..C {
            st.p[ch] = i[ch] * s;
            st.pa[ch] = i[ch] * self.q;
            st.pb[ch] = self.gu[ch] * s;
            st.pg[ch] = self.gv[ch] * s;
        }
        st
    }

    fn plane_at(&self, a: i64, b: i64) -> [i64; C] {
        let (x, y) = self.e.pixel(a as i32, b as i32);
        self.plane.at(x, y)
    }

    // ---- stepping (per pixel: add / compare) -----------------------------

    /// One column along the major axis; a diagonal step when the main term
    /// reaches the cell height (seed 001: horizontal vs diagonal by the
    /// sign of the evaluation function).
    #[inline]
    fn step(&self, st: &mut Step<C>) {
        st.r += self.rr;
        let carry = st.r >= self.e.du;
        if carry {
            st.r -= self.e.du;
        }
        st.s += self.q + i64::from(carry);
        for ch in 0..C {
            st.pb[ch] += self.gq[ch] + if carry { self.gu[ch] } else { 0 };
            st.p[ch] += st.pa[ch] + if carry { st.i[ch] } else { 0 } + st.pb[ch];
            st.pa[ch] += self.gq[ch];
            st.pg[ch] += self.gvq[ch] + if carry { self.gv[ch] } else { 0 };
            st.i[ch] += self.gu[ch];
        }
        st.a += 1;
        if st.s >= st.h {
            if st.h != ONE {
                // Leaving the first row of an x-major edge, whose top is the
                // vertex, not a pixel boundary: restart exactly, once per edge.
                *st = self.init(st.a);
                return;
            }
            st.s -= ONE;
            st.b += 1;
            for ch in 0..C {
                st.p[ch] += st.pg[ch] - (st.i[ch] << COVER_BITS) - (self.gv[ch] << COVER_BITS);
                st.pb[ch] -= self.gu[ch] << COVER_BITS;
                st.pg[ch] -= self.gv[ch] << COVER_BITS;
                st.pa[ch] += self.gvq[ch];
                st.i[ch] += self.gv[ch];
            }
        }
    }

    /// Walks to interior column `a`: one step from the previous column's
    /// state, or a direct start when there is none (the walk's first
    /// interior column, or after an end column); reports its pixels and
    /// returns its chosen cell.
    fn interior_column(&mut self, st: &mut Option<Step<C>>, a: i64) -> i64 {
        let s = match st.take() {
            Some(mut s) => {
                self.step(&mut s);
                s
            }
            None => self.init(a),
        };
        self.interior(&s);
        let bc = s.b;
        *st = Some(s);
        bc
    }

    /// Reports the chosen pixel of a stepped column, and in exact mode moves
    /// the spill of a minor-axis crossing to its true pixel.
    fn interior(&mut self, st: &Step<C>) {
        self.emit(st.a, st.b, st.s, &st.p);
        if !self.exact || self.e.dv == 0 {
            return;
        }
        let du = self.e.du;
        // Up-crossing: the line enters from the cell above inside this column.
        if (st.s, st.r) < (self.kq, self.kr) {
            let e = self.kq - st.s - i64::from(self.kr < st.r);
            self.spill(st, st.b - 1, e);
        }
        // Down-crossing: it leaves into the cell below.
        let carry = st.r + self.kr >= du;
        let rem = st.r + self.kr - if carry { du } else { 0 };
        let s2 = st.s + self.kq + i64::from(carry);
        if s2 > st.h || (s2 == st.h && rem > 0) {
            self.spill(st, st.b, s2 - st.h);
        }
    }

    /// Moves the triangle `e^2 / (2k)` from cell `upper` to the cell below.
    fn spill(&mut self, st: &Step<C>, upper: i64, e: i64) {
        let e = e.max(0) as u64;
        let t = ((e * e * self.inv) >> 32) as i64;
        if t == 0 {
            return;
        }
        let mut up = [0i64; C];
        let mut down = [0i64; C];
        for ch in 0..C {
            let i_up = if upper == st.b {
                st.i[ch]
            } else {
                st.i[ch] - self.gv[ch]
            };
            up[ch] = -(i_up * t);
            down[ch] = (i_up + self.gv[ch]) * t;
        }
        self.emit(st.a, upper, -t, &up);
        self.emit(st.a, upper + 1, t, &down);
    }

    // ---- reporting ---------------------------------------------------------

    /// Reports canonical cell `(a, b)`: `cov` is the change of its low-`v`
    /// area, `prod` is `I * cov` per channel (fine units).
    fn emit(&mut self, a: i64, b: i64, cov: i64, prod: &[i64; C]) {
        if cov == 0 {
            return;
        }
        let (x, y) = self.e.pixel(a as i32, b as i32);
        if i64::from(y) < self.ylo || i64::from(y) >= self.yhi {
            return;
        }
        let mut v = [0i32; C];
        for ch in 0..C {
            v[ch] = (self.sw * (prod[ch] >> PLANE_FRAC)) as i32;
        }
        self.sink.cell(x, y, (self.sw * cov) as i32, &v);
    }

    /// Reports a cover change at frame column `x` directly (for the covers
    /// of skipped columns, which all apply from the sink's first column).
    fn cover_at(&mut self, y: i64, x: i64, h: i64) {
        if y < self.ylo || y >= self.yhi || h == 0 {
            return;
        }
        self.sink.cover(x as i32, y as i32, (self.w * h) as i32);
    }

    fn cover(&mut self, y: i64, beta: i64, h: i64) {
        if y < self.ylo || y >= self.yhi || h == 0 {
            return;
        }
        let x = self.e.cover_column(beta as i32);
        self.sink.cover(x, y as i32, (self.w * h) as i32);
    }

    /// An end column, computed directly from the exact area (per edge).
    fn end_cells(
        &mut self,
        a: i64,
        ulo: i64,
        uhi: i64,
        bc: i64,
        rows: (i64, i64),
        bg_of: impl Fn(&Self, i64) -> i64,
    ) {
        for b in rows.0..=rows.1 {
            let (vlo, vhi) = if self.e.transposed {
                (b * SUB, b * SUB + SUB)
            } else {
                ((b * SUB).max(self.e.v0), (b * SUB + SUB).min(self.e.v1))
            };
            let area = i64::from(clamped_area(&self.e, ulo, uhi, vlo, vhi));
            let d = area - if b < bc { bg_of(self, b) } else { 0 };
            if d != 0 {
                let i = self.plane_at(a, b);
                self.emit(a, b, d, &i.map(|v| v * d));
            }
        }
    }

    // ---- the two walks -------------------------------------------------------

    /// Edges at most 45° from horizontal: columns are `x`, each band row may
    /// hold a run of edge pixels; one cover change per row.
    fn x_major(&mut self) {
        let (a0, a1) = self.e.columns();
        let (b0, b1) = (self.b0, self.b1);
        if b1 < self.ylo || b0 >= self.yhi {
            return;
        }
        // First column whose centre lies at or below v_top (divides: setup).
        let reach = |v_top: i64| {
            let e = &self.e;
            div_ceil((v_top - e.v0) * e.du + (e.u0 - SUB / 2) * e.dv, SUB * e.dv)
        };
        let a_start = if b0 >= self.ylo - 1 {
            a0
        } else {
            limit(reach((self.ylo - 1) * SUB), a0, a1)
        };
        let a_stop = if b1 <= self.yhi {
            a1
        } else {
            limit(reach((self.yhi + 1) * SUB) - 1, a0, a1)
        };
        let mut prev = if a_start == a0 {
            b0
        } else {
            self.centre_cell(a_start)
        };
        // Rows whose cover starts at or after column a_stop + 1 (exclusive
        // end of the rows this walk reports covers for).
        let rows_end = if a_stop == a1 {
            b1 + 1
        } else {
            self.centre_cell(a_stop)
        };
        // Only the columns the sink keeps need walking. Left of them, cover
        // changes apply from its first column; right of them, they are
        // dropped. Which side is which depends on the mirror.
        let cols = self.sink.columns();
        let (c_lo, c_hi) = (i64::from(cols.start), i64::from(cols.end));
        let (vis_lo, vis_hi) = if self.e.mirrored {
            (-c_hi, -1 - c_lo)
        } else {
            (c_lo, c_hi - 1)
        };
        let w_start = a_start.max(vis_lo);
        let w_stop = a_stop.min(vis_hi);
        if w_start > a_start {
            let reached = if w_start > a_stop {
                rows_end
            } else {
                self.centre_cell(w_start)
            };
            if !self.e.mirrored {
                for row in prev..reached {
                    self.cover_at(row, c_lo, self.row_cover(row));
                }
            }
            prev = prev.max(reached);
        }
        let mut st: Option<Step<C>> = None;
        for a in w_start..=w_stop {
            let bc = if a == a0 || a == a1 {
                st = None;
                let bc = self.centre_cell(a);
                let row =
                    |u: i64| limit(div_floor(self.e.v_num_clamped(u), SUB * self.e.du), b0, b1);
                let rows = (row(a * SUB), row(a * SUB + SUB));
                self.end_cells(a, a * SUB, a * SUB + SUB, bc, rows, |s, b| s.row_cover(b));
                bc
            } else {
                self.interior_column(&mut st, a)
            };
            for row in prev..bc {
                self.cover(row, a, self.row_cover(row));
            }
            prev = prev.max(bc);
        }
        if w_stop < a_stop {
            if self.e.mirrored {
                for row in prev..rows_end {
                    self.cover_at(row, c_lo, self.row_cover(row));
                }
            }
        } else if a_stop == a1 {
            for row in prev..=b1 {
                self.cover(row, a1 + 1, self.row_cover(row));
            }
        }
    }

    /// Edges steeper than 45°: columns of the walk are frame rows, one or
    /// two edge pixels each, one cover change each.
    fn y_major(&mut self) {
        let (a0, a1) = self.e.columns();
        let lo = a0.max(self.ylo);
        let hi = a1.min(self.yhi - 1);
        let mut st: Option<Step<C>> = None;
        for a in lo..=hi {
            let bc = if a == a0 || a == a1 {
                st = None;
                let (ulo, uhi) = ((a * SUB).max(self.e.u0), (a * SUB + SUB).min(self.e.u1));
                let bc = self.centre_cell(a);
                let cell = |u: i64| div_floor(self.e.v_num_clamped(u), SUB * self.e.du);
                let rows = (cell(ulo), cell(uhi));
                self.end_cells(a, ulo, uhi, bc, rows, |s, _| s.column_cover(a));
                bc
            } else {
                self.interior_column(&mut st, a)
            };
            self.cover(a, bc, self.column_cover(a));
        }
    }
}

// SUB_BITS documents the unit of `SUB`; keep the two tied together.
const _: () = assert!(SUB == 1 << SUB_BITS);
