//! Circles without flattening: the exact area of a disc's edge pixels
//! from the circle itself, row by row.
//!
//! A circle's boundary is walked as the edges of [`mod@super`] are: per
//! pixel it cuts, the signed area of the pixel right of it (`+` where it
//! runs down the screen, its left half, `-` on its right half), and per
//! row its cover. Only the band's rows are visited; nothing of the circle
//! is described or kept between bands.
//!
//! In a row `[Y0, Y1)`, each half of the circle (`x = cx -+ w(y)`, `w(y) =
//! sqrt(r^2 - (y - cy)^2)`) is one or two pieces monotone in `x` and `y`
//! (split at the centre's height). A piece's points on the row's sides
//! and on the pixel columns' sides it crosses come from integer square
//! roots of `r^2 - v^2` (quarter fine units, 1/4096 px, rounded: within
//! 1/8192 px of the circle); between two such points the piece lies in
//! one pixel, where the area right of it is the area right of its chord,
//! exact in integers, plus or minus the circular segment between chord
//! and arc (the arc bulges away from the centre):
//!
//! ```text
//!   segment(L) = r^2 (asin q - q sqrt(1 - q^2)),  q = L / 2r
//!              = L^3 / (12 r) * k(q^2),  k(z) = 1 + 3z/10 + 9z^2/56 + ...
//! ```
//!
//! `L` (the chord, at most `sqrt 2` px and `sqrt 2 r` for a piece of a
//! quadrant, so `z <= 1/2`) from an integer square root, `1 / r` as a
//! multiplier found once per circle, `k` from a table of 33 values with
//! linear interpolation (within 4e-4 of the series' sum). Every pixel's
//! area is so within a few coverage units (1/65536 px) of the exact disc
//! area, at any radius and sub-pixel centre (the tests below check 1/4096
//! px against an f64 formula); every value is a function of the row
//! alone, so any band height gives the same bits. A ring is its outer
//! circle walked with `+` and its inner one with `-`.
//!
//! Ranges: centre within the fine coordinate range (`|c| <= 2^21` fine,
//! `2^23` quarter units), radius at most `2^23` quarter units (2048 px):
//! `4 (r^2 - v^2) < 2^48` (`u64`), square roots below `2^24` with
//! remainders in `u32`; the segment's products in `u64`.

use super::DeltaSink;
use crate::arith::{isqrt32, isqrt64};
use crate::COVER_BITS;

/// Quarter fine units per pixel (1/4096 px).
const Q_BITS: u32 = 12;
const Q: i32 = 1 << Q_BITS;

/// Largest radius walked here, quarter fine units (2048 px).
pub(crate) const MAX_RADIUS_Q: u32 = 1 << 23;

/// `(k(z) - 1) * 4096` at `z = i / 64`, `i = 0..=33`: `k(z) =
/// (asin q - q sqrt(1 - q^2)) / (2 q^3 / 3)`, `q = sqrt z`.
const K_TABLE: [i32; 34] = [
    0, 19, 39, 59, 79, 100, 121, 143, 165, 187, 210, 233, 257, 281, 306, 331, 356, 383, 410, 437,
    465, 494, 523, 553, 584, 616, 649, 682, 716, 752, 788, 825, 864, 903,
];

/// `sqrt(1 + (j / 64)^2) * 2^16`, `j = 0..=65`: a chord across a whole
/// pixel, `Q sqrt(1 + (m / Q)^2)` for its other side `m <= Q`.
const CHORD_TABLE: [u32; 66] = [
    65536, 65544, 65568, 65608, 65664, 65736, 65823, 65927, 66046, 66181, 66331, 66497, 66678,
    66874, 67086, 67312, 67553, 67809, 68079, 68363, 68661, 68974, 69300, 69640, 69992, 70359,
    70738, 71129, 71534, 71950, 72379, 72819, 73271, 73735, 74210, 74696, 75193, 75700, 76218,
    76745, 77283, 77831, 78388, 78954, 79530, 80115, 80708, 81310, 81920, 82538, 83165, 83799,
    84441, 85091, 85747, 86411, 87082, 87760, 88444, 89135, 89832, 90536, 91245, 91961, 92682,
    93409,
];

/// The length of a chord one of whose sides is a whole pixel (`Q`) and
/// the other `m <= Q`, quarter fine units (within 0.7 of a unit).
#[inline]
fn pixel_chord(m: u32) -> u32 {
    let (j, f) = ((m >> 6) as usize, m & 63);
    let a = CHORD_TABLE.get(j).copied().unwrap_or(0);
    let b = CHORD_TABLE.get(j + 1).copied().unwrap_or(a);
    (a + (((b - a) * f) >> 6) + 8) >> 4
}

/// Bits of `d` (`0` for `0`).
fn bit_len(d: u64) -> u32 {
    64 - d.leading_zeros()
}

/// A height and, at a cut, the point's `x` (quarter fine units).
type End = (i32, Option<i32>);

/// Heights `lo.0 < hi.0` of a part of a circle within one quadrant.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Span {
    lo: End,
    hi: End,
}

/// The parts of a circle an arc keeps: per quadrant (0: `x >= cx, y >=
/// cy`, then clockwise on screen: 1 lower left, 2 upper left, 3 upper
/// right) up to two spans.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Arcs {
    q: [[Option<Span>; 2]; 4],
}

/// Which half of the circle a piece is on: the left (the segment adds to
/// the area right of the chord), the right (it takes from it), or the
/// left and its mirror image on the right at once.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Half {
    Left,
    Right,
    Both,
}

/// A circle in quarter fine units, with what its walks share.
#[derive(Debug, Clone, Copy)]
pub(crate) struct CircleEdge {
    cx: i32,
    cy: i32,
    r: i32,
    /// The chord's square is taken as `w2 = min(L^2 >> t0, W2_MAX)` and
    /// `v = min(w2 l >> t1, V_MAX)` (`l` the chord), shifts that keep as
    /// many bits as the circle's largest chord allows (`L <= sqrt 2 r`,
    /// and `sqrt 2` px).
    t0: u32,
    t1: u32,
    /// `2^(t0 + t1 + sh_seg) / (6 r)` in `(2^14, 2^15]`: twice the
    /// segment's area is `v m_seg >> sh_seg` (`L^3 / (6 r)`, then `k`).
    m_seg: u32,
    sh_seg: u32,
    /// `2^(t0 + 14 + sh_z) / r^2` in `(2^14, 2^15]`: `z` in 1/65536 is
    /// `w2 m_z >> sh_z`; 0 from `r = 32` px on, where chords give `z <
    /// 2^-11` (`k - 1` below 2^-12, not counted).
    m_z: u32,
    sh_z: u32,
    /// The pixel grid is its own mirror image about the centre's column
    /// (`2 cx` a multiple of a pixel: the centre on a pixel's side or in
    /// its middle, as every embedded-graphics circle's is): a left half's
    /// piece gives its right twin's cells too, from the same square roots
    /// (see [`side`](Self::side)).
    mirror: bool,
}

/// Largest `w2` and `v` (see [`CircleEdge`]): `v m_seg < 2^32`.
const W2_MAX: u32 = (1 << 16) - 1;
const V_MAX: u32 = (1 << 17) - 1;

impl CircleEdge {
    /// Smallest radius walked here, quarter fine units (1/128 px).
    pub(crate) const MIN_RADIUS_Q: u32 = 32;

    /// The circle of centre `(cx, cy)` and radius `r`, quarter fine units;
    /// `None` when out of the ranges above.
    pub(crate) fn new(cx: i32, cy: i32, r: u32) -> Option<Self> {
        if !(Self::MIN_RADIUS_Q..=MAX_RADIUS_Q).contains(&r) {
            return None;
        }
        let lim = 1 << 23;
        if !(-lim..=lim).contains(&cx) || !(-lim..=lim).contains(&cy) {
            return None;
        }
        let r64 = u64::from(r);
        // The longest chord of a piece: a quarter circle's or a pixel's
        // diagonal (each end within a unit of the circle).
        let l_max = (r64 * 3 / 2 + 2).min(5793);
        let t0 = bit_len(l_max * l_max).saturating_sub(16);
        let w2_max = (l_max * l_max) >> t0;
        let t1 = bit_len(w2_max * l_max).saturating_sub(17);
        // d in [2^(b-1), 2^b): 2^(b + 14) / d in (2^14, 2^15].
        let d = 6 * r64;
        let sh_seg = (bit_len(d) + 14).checked_sub(t0 + t1)?;
        let m_seg = ((1u64 << (bit_len(d) + 14)) / d) as u32;
        let (m_z, sh_z) = if r >= 32 << Q_BITS {
            (0, 0)
        } else {
            let d = r64 * r64;
            let sh = bit_len(d).checked_sub(t0)?;
            (((1u64 << (bit_len(d) + 14)) / d) as u32, sh)
        };
        Some(Self {
            cx,
            cy,
            r: r as i32,
            t0,
            t1,
            m_seg,
            sh_seg,
            m_z,
            sh_z,
            mirror: cx & (Q / 2 - 1) == 0,
        })
    }

    /// The pixel rows the circle's boundary crosses.
    pub(crate) fn rows(&self) -> core::ops::Range<i32> {
        let top = self.cy - self.r;
        let bot = self.cy + self.r;
        (top >> Q_BITS)..(((bot - 1) >> Q_BITS) + 1)
    }

    /// `w(v) = sqrt(r^2 - v^2)` rounded to the nearest unit, `|v| <= r`.
    #[inline]
    fn half_width(&self, v: i32) -> i32 {
        let v = v.unsigned_abs().min(self.r as u32);
        let r = self.r as u32;
        // (r - v)(r + v) < 2^48 in halves: no 64-bit multiply on an M0.
        ((isqrt64(crate::arith::mul_wide(r - v, r + v) << 2) + 1) >> 1) as i32
    }

    /// Twice the area of the circular segment over a chord of
    /// `(dx, dy)`, quarter fine units squared.
    #[inline]
    fn segment2(&self, dx: i32, dy: i32) -> i32 {
        let (dx, dy) = (dx.unsigned_abs(), dy.unsigned_abs());
        // Chords of pieces within a pixel: below 2^13 each.
        let l2 = dx * dx + dy * dy;
        // Most pieces cross a whole pixel, across or down.
        let q = Q as u32;
        let l = match (dx == q, dy == q) {
            (true, _) if dy <= q => pixel_chord(dy),
            (_, true) if dx <= q => pixel_chord(dx),
            _ => isqrt32(l2),
        };
        let w2 = (l2 >> self.t0).min(W2_MAX);
        let v = ((w2 * l) >> self.t1).min(V_MAX);
        let s = (v * self.m_seg) >> self.sh_seg;
        if self.m_z == 0 {
            return s as i32;
        }
        let z = ((w2 * self.m_z) >> self.sh_z).min(32 << 10);
        let i = (z >> 10) as usize;
        let f = (z & 1023) as i32;
        let (a, b) = (
            K_TABLE.get(i).copied().unwrap_or(0),
            K_TABLE.get(i + 1).copied().unwrap_or(0),
        );
        let kk = a + (((b - a) * f) >> 10);
        // s < 2^24 here (a small circle's pixel), kk < 2^10.
        (s + (((s >> 2) * kk as u32) >> 10)) as i32
    }

    /// The boundary's changes in the frame rows `rows` into `out`, each
    /// times `sign` (`1`: a disc; `-1`: a hole).
    pub(crate) fn walk<S: DeltaSink>(&self, rows: core::ops::Range<i32>, sign: i32, out: &mut S) {
        let span = self.rows();
        let (lo, hi) = (rows.start.max(span.start), rows.end.min(span.end));
        if lo >= hi {
            return;
        }
        let out = &mut self.clipped(out);
        let (top, bot) = (self.cy - self.r, self.cy + self.r);
        let mut ya = (lo << Q_BITS).max(top);
        // The half width at `ya`, once needed.
        let mut known = None;
        for row in lo..hi {
            let yb = ((row + 1) << Q_BITS).min(bot);
            if out.cols.is_some()
                && ya < yb
                && self.beside(out, (ya, yb), false, -sign, row)
                && self.beside(out, (ya, yb), true, sign, row)
            {
                // Both halves beside the columns kept: no square root.
                ya = yb;
                known = None;
                continue;
            }
            let wa = known.unwrap_or_else(|| self.half_width(ya - self.cy));
            let wb = self.half_width(yb - self.cy);
            if ya < self.cy && self.cy < yb {
                self.piece(row, ya, self.cy, wa, self.r, true, sign, out);
                self.piece(row, self.cy, yb, self.r, wb, false, sign, out);
            } else if ya < yb {
                self.piece(row, ya, yb, wa, wb, yb <= self.cy, sign, out);
            }
            ya = yb;
            known = Some(wb);
        }
    }

    /// `out`, saying which columns it keeps only when the circle reaches
    /// past them (a window's band): a circle within them is walked
    /// without the test.
    fn clipped<'s, S: DeltaSink>(&self, out: &'s mut S) -> Columns<'s, S> {
        let cols = out.columns().filter(|&(x0, x1)| {
            (self.cx - self.r) >> Q_BITS < x0 || (self.cx + self.r) >> Q_BITS >= x1
        });
        Columns { out, cols }
    }

    /// The parts of the circle from the clockwise angle `a` over `s`
    /// (binary angles, a turn `2^32`, `0 < s < 2^32`), cut at the points
    /// `pa` and `pb` (quarter fine units: the points at either end, or
    /// within a unit or two of them): per quadrant up to two intervals of
    /// heights. Where a part ends at a cut, its end is the
    /// cut point itself (so that a line from it closes the contour
    /// exactly); elsewhere it ends where a quadrant does.
    pub(crate) fn arc_spans(&self, a: i64, s: i64, pa: (i32, i32), pb: (i32, i32)) -> Arcs {
        const T: i64 = 1 << 32;
        const QT: i64 = T / 4;
        let a = a.rem_euclid(T);
        let mut q = [[None; 2]; 4];
        for (k, spans) in q.iter_mut().enumerate() {
            let (k0, k1) = (k as i64 * QT, (k as i64 + 1) * QT);
            let mut n = 0;
            for shift in [-T, 0, T] {
                let (lo, hi) = ((a + shift).max(k0), (a + s + shift).min(k1));
                if lo >= hi {
                    continue;
                }
                let end = |t: i64| -> End {
                    if t == a + shift {
                        (pa.1, Some(pa.0))
                    } else if t == a + s + shift {
                        (pb.1, Some(pb.0))
                    } else {
                        // A quadrant's end: 0, 90, 180, 270 or 360 degrees.
                        let y = match (t / QT) & 3 {
                            1 => self.cy + self.r,
                            3 => self.cy - self.r,
                            _ => self.cy,
                        };
                        (y, None)
                    }
                };
                let (e0, e1) = (end(lo), end(hi));
                // Heights within the quadrant's (a cut point may lie a
                // unit outside the circle).
                let (y_lo, y_hi) = if k < 2 {
                    (self.cy, self.cy + self.r)
                } else {
                    (self.cy - self.r, self.cy)
                };
                let fit = |e: End| (e.0.max(y_lo).min(y_hi), e.1);
                let (e0, e1) = (fit(e0), fit(e1));
                let (lo, hi) = if e0.0 <= e1.0 { (e0, e1) } else { (e1, e0) };
                if lo.0 < hi.0 {
                    if let Some(slot) = spans.get_mut(n) {
                        *slot = Some(Span { lo, hi });
                        n += 1;
                    }
                }
            }
        }
        Arcs { q }
    }

    /// [`walk`](Self::walk) of the parts `spans` of the circle
    /// ([`arc_spans`](Self::arc_spans)).
    pub(crate) fn walk_spans<S: DeltaSink>(
        &self,
        rows: core::ops::Range<i32>,
        sign: i32,
        spans: &Arcs,
        out: &mut S,
    ) {
        let span = self.rows();
        let (lo, hi) = (rows.start.max(span.start), rows.end.min(span.end));
        let out = &mut self.clipped(out);
        let (top, bot) = (self.cy - self.r, self.cy + self.r);
        let pair = self.paired(out);
        // The parts there are, the left quadrants' first (1 lower, 2
        // upper), so that a right part (0 lower, 3 upper) whose twin took
        // it is skipped: `(2 k + i, part)`.
        let mut live: [(usize, Option<&Span>); 8] = [(0, None); 8];
        let mut n = 0;
        for k in [1, 2, 0, 3] {
            for (i, part) in spans.q.get(k).into_iter().flatten().enumerate() {
                if let (Some(part), Some(slot)) = (part, live.get_mut(n)) {
                    *slot = (2 * k + i, Some(part));
                    n += 1;
                }
            }
        }
        let live = live.get(..n).unwrap_or_default();
        // The half width at the row's top, when the row above found it.
        let mut carried = None;
        for row in lo..hi {
            let ya = (row << Q_BITS).max(top);
            let yb = ((row + 1) << Q_BITS).min(bot);
            let (mut wa, mut wb) = (carried.take(), None);
            // The part of `part` in this row, and whether both its ends
            // are the circle's own (not a cut point).
            let in_row = |part: &Span| -> Option<(i32, i32, bool)> {
                let (y0, y1) = (ya.max(part.lo.0), yb.min(part.hi.0));
                let cut = |y: i32, e: &End| y == e.0 && e.1.is_some();
                (y0 < y1).then(|| (y0, y1, !cut(y0, &part.lo) && !cut(y1, &part.hi)))
            };
            // Right parts given with their left twins (bit `2 k + i`).
            let mut given = 0u32;
            for &(id, part) in live {
                let k = id >> 1;
                let (upper, left) = (k >= 2, k == 1 || k == 2);
                let Some(part) = part else {
                    continue;
                };
                let Some((y0, y1, own)) = in_row(part) else {
                    continue;
                };
                if given >> id & 1 != 0 {
                    continue;
                }
                let mut half = if left { Half::Left } else { Half::Right };
                if left && own && pair {
                    // The right twin: the same heights in this row,
                    // its ends the circle's too.
                    for &(tid, t) in live {
                        if tid >> 1 == k ^ 1 && t.and_then(in_row) == Some((y0, y1, true)) {
                            given |= 1 << tid;
                            half = Half::Both;
                            break;
                        }
                    }
                }
                let sg = if left { sign } else { -sign };
                if out.cols.is_some() && self.beside(out, (y0, y1), left, sg, row) {
                    continue;
                }
                let x_at = |y: i32, cut: &End, w: &mut Option<i32>| -> i32 {
                    if let (true, Some(x)) = (y == cut.0, cut.1) {
                        return x;
                    }
                    let h = if y == self.cy {
                        self.r
                    } else if y == ya || y == yb {
                        *w.get_or_insert_with(|| self.half_width(y - self.cy))
                    } else {
                        self.half_width(y - self.cy)
                    };
                    if left {
                        self.cx - h
                    } else {
                        self.cx + h
                    }
                };
                let x0 = if y0 == ya {
                    x_at(y0, &part.lo, &mut wa)
                } else {
                    x_at(y0, &part.lo, &mut None)
                };
                let x1 = if y1 == yb {
                    x_at(y1, &part.hi, &mut wb)
                } else {
                    x_at(y1, &part.hi, &mut None)
                };
                self.side(row, (x0, x1), (y0, y1), upper, half, sg, out);
            }
            carried = wb;
        }
    }

    /// True when the piece of the left or right half between heights
    /// `ys` lies wholly beside the columns `out` keeps, told without its
    /// square roots (the half width there is at least `r - |v|`, and a cut
    /// point lies within a few units of the circle): then it is put as
    /// [`side`](Self::side) would put it, its cover at the first column
    /// (left) or nothing (right).
    #[inline(never)]
    fn beside<S: DeltaSink>(
        &self,
        out: &mut Columns<'_, S>,
        ys: (i32, i32),
        left: bool,
        sign: i32,
        row: i32,
    ) -> bool {
        let Some((x0, x1)) = out.cols else {
            return false;
        };
        let v = (ys.0 - self.cy).abs().max((ys.1 - self.cy).abs());
        // Below every half width there, less the cut points' slack.
        let inner = self.r - v - 8;
        if inner < 0 {
            return false;
        }
        if left {
            if (self.cx - inner) >> Q_BITS < x0 {
                out.put(x0, row, sign * ((ys.1 - ys.0) << (COVER_BITS - Q_BITS)));
                return true;
            }
        } else if (self.cx + inner) >> Q_BITS >= x1 {
            return true;
        }
        false
    }

    /// Both halves' pieces between heights `y0 < y1` of row `row`, half
    /// widths `w0`, `w1` there; `upper`: above the centre.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn piece<S: DeltaSink>(
        &self,
        row: i32,
        y0: i32,
        y1: i32,
        w0: i32,
        w1: i32,
        upper: bool,
        sign: i32,
        out: &mut S,
    ) {
        let (cx, ends) = (self.cx, (y0, y1));
        if self.paired(out) {
            self.side(row, (cx - w0, cx - w1), ends, upper, Half::Both, sign, out);
            return;
        }
        self.side(row, (cx - w0, cx - w1), ends, upper, Half::Left, sign, out);
        self.side(
            row,
            (cx + w0, cx + w1),
            ends,
            upper,
            Half::Right,
            -sign,
            out,
        );
    }

    /// One half's piece from `(xs.0, ys.0)` to `(xs.1, ys.1)` (`ys.0 <
    /// ys.1`), its pixels' areas right of it times `sign`; the segments
    /// added on the left half (the arc bulges left of its chord) and taken
    /// on the right.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    fn side<S: DeltaSink>(
        &self,
        row: i32,
        xs: (i32, i32),
        ys: (i32, i32),
        upper: bool,
        half: Half,
        sign: i32,
        out: &mut S,
    ) {
        let (a, b) = ((xs.0, ys.0), (xs.1, ys.1));
        if let Some((x0, x1)) = out.columns() {
            // Every cell's column lies within these.
            let (c0, c1) = (xs.0.min(xs.1) >> Q_BITS, xs.0.max(xs.1) >> Q_BITS);
            if c0 >= x1 {
                // Right of the sink: dropped cell by cell, so skipped.
                return;
            }
            let h = (b.1 - a.1) << (COVER_BITS - Q_BITS);
            if c1 < x0 && h != 0 {
                // Left of it: the cells' changes all land at `x0`, and
                // they sum to the piece's cover.
                out.put(x0, row, sign * h);
                return;
            }
        }
        let mut p = a;
        if b.0 > a.0 {
            let mut x = ((a.0 >> Q_BITS) + 1) << Q_BITS;
            while x < b.0 {
                let q = (x, self.y_at(x, upper).max(p.1).min(b.1));
                self.cell(row, p, q, half, sign, out);
                p = q;
                x += Q;
            }
        } else if b.0 < a.0 {
            let mut x = ((a.0 - 1) >> Q_BITS) << Q_BITS;
            while x > b.0 {
                let q = (x, self.y_at(x, upper).max(p.1).min(b.1));
                self.cell(row, p, q, half, sign, out);
                p = q;
                x -= Q;
            }
        }
        self.cell(row, p, b, half, sign, out);
    }

    /// True when a left half's pieces may give their right twins
    /// ([`Half::Both`]): the grid is symmetric about the centre and `out`
    /// keeps every column (a clipping sink's shortcuts differ per side).
    #[inline(always)]
    fn paired<S: DeltaSink>(&self, out: &S) -> bool {
        self.mirror && out.columns().is_none()
    }

    /// The circle's height at `x` on the upper or lower half.
    #[inline]
    fn y_at(&self, x: i32, upper: bool) -> i32 {
        let h = self.half_width(x - self.cx);
        if upper {
            self.cy - h
        } else {
            self.cy + h
        }
    }

    /// The piece from `p` to `q` (`p.1 <= q.1`), within one pixel column:
    /// its area right of it there and its cover, times `sign`.
    #[inline]
    fn cell<S: DeltaSink>(
        &self,
        row: i32,
        p: (i32, i32),
        q: (i32, i32),
        half: Half,
        sign: i32,
        out: &mut S,
    ) {
        let s2 = self.segment2(q.0 - p.0, q.1 - p.1);
        match half {
            Half::Left => Self::cell_area(row, p.0, q.0, q.1 - p.1, s2, sign, out),
            Half::Right => Self::cell_area(row, p.0, q.0, q.1 - p.1, -s2, sign, out),
            Half::Both => {
                Self::cell_area(row, p.0, q.0, q.1 - p.1, s2, sign, out);
                // The mirror image (x -> 2 cx - x), as its own walk on
                // the right half would put it: the same segment.
                let m = 2 * self.cx;
                Self::cell_area(row, m - p.0, m - q.0, q.1 - p.1, -s2, -sign, out);
            }
        }
    }

    /// The piece from `x0` to `x1` (`dh` down), within one pixel column:
    /// its area right of it there (twice the chord's, plus `s2`, twice the
    /// signed segment) and its cover, times `sign`.
    #[inline(always)]
    fn cell_area<S: DeltaSink>(
        row: i32,
        x0: i32,
        x1: i32,
        dh: i32,
        s2: i32,
        sign: i32,
        out: &mut S,
    ) {
        let c = x0.min(x1) >> Q_BITS;
        let right = (c + 1) << Q_BITS;
        // Twice the area right of the chord, then the segment, quarter
        // fine units squared (< 2^26).
        let a2 = dh * (2 * right - x0 - x1) + s2;
        // To coverage units (2^(2 Q_BITS + 1 - COVER_BITS) of them a unit).
        const SHIFT: u32 = 2 * Q_BITS + 1 - COVER_BITS;
        let a = (a2 + (1 << (SHIFT - 1))) >> SHIFT;
        let h = dh << (COVER_BITS - Q_BITS);
        if a != 0 || h != 0 {
            out.put2(c, c + 1, row, sign * a, sign * (h - a));
        }
    }
}

/// A sink with the columns it keeps, or `None` (see
/// [`CircleEdge::clipped`]).
struct Columns<'s, S> {
    out: &'s mut S,
    cols: Option<(i32, i32)>,
}

impl<S: DeltaSink> DeltaSink for Columns<'_, S> {
    #[inline(always)]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        self.out.put(x, y, d);
    }
    #[inline(always)]
    fn put2(&mut self, x0: i32, x1: i32, y: i32, d0: i32, d1: i32) {
        self.out.put2(x0, x1, y, d0, d1);
    }
    #[inline(always)]
    fn columns(&self) -> Option<(i32, i32)> {
        self.cols
    }
}

/// The exact area of a disc in a pixel, in `f64` (the tests' reference).
#[cfg(test)]
pub(crate) mod reference {
    extern crate std;

    /// The area of the unit-free disc of radius `r` about the origin in
    /// `x < u, y < v` (f64, closed form).
    fn quadrant(u: f64, v: f64, r: f64) -> f64 {
        // The integral of sqrt(r^2 - s^2) from -r to t: half the disc's
        // area left of t.
        let a = |t: f64| {
            let t = t.clamp(-r, r);
            (t * (r * r - t * t).max(0.0).sqrt() + r * r * (t / r).clamp(-1.0, 1.0).asin()) / 2.0
                + core::f64::consts::PI * r * r / 4.0
        };
        if v > 0.0 {
            return 2.0 * a(u) - quadrant(u, -v, r);
        }
        if v <= -r {
            return 0.0;
        }
        let w = (r * r - v * v).sqrt();
        let m = u.clamp(-w, w);
        v * (m + w) + a(m) - a(-w)
    }

    /// The exact area of the disc in pixel `(x, y)`, pixels.
    pub(crate) fn exact(cx: f64, cy: f64, r: f64, x: i32, y: i32) -> f64 {
        let (x0, y0) = (f64::from(x) - cx, f64::from(y) - cy);
        let (x1, y1) = (x0 + 1.0, y0 + 1.0);
        quadrant(x1, y1, r) - quadrant(x0, y1, r) - quadrant(x1, y0, r) + quadrant(x0, y0, r)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::reference::exact;
    use super::*;
    use crate::path::testing::Lcg;
    use crate::COVER_ONE;

    /// A window of `w x h` pixels at `(x0, y0)`, changes as the band's
    /// scratch takes them (left of it: its first column; right: dropped).
    struct Window {
        x0: i32,
        y0: i32,
        w: i32,
        h: i32,
        d: Vec<i64>,
    }

    impl Window {
        fn new(x0: i32, y0: i32, w: i32, h: i32) -> Self {
            Self {
                x0,
                y0,
                w,
                h,
                d: std::vec![0; (w * h) as usize],
            }
        }
        /// The coverage of every pixel, row by row.
        fn coverage(&self) -> Vec<i64> {
            let mut out = self.d.clone();
            for row in out.chunks_mut(self.w as usize) {
                let mut s = 0;
                for v in row {
                    s += *v;
                    *v = s;
                }
            }
            out
        }
    }

    impl DeltaSink for Window {
        fn put(&mut self, x: i32, y: i32, d: i32) {
            let (r, c) = (y - self.y0, (x - self.x0).max(0));
            if r >= 0 && r < self.h && c < self.w {
                self.d[(r * self.w + c) as usize] += i64::from(d);
            }
        }
    }

    /// A window that says which columns it keeps (as a band does), so
    /// the walk sums what lies left of it and skips what lies right.
    struct Clipping(Window);

    impl DeltaSink for Clipping {
        fn put(&mut self, x: i32, y: i32, d: i32) {
            self.0.put(x, y, d);
        }
        fn columns(&self) -> Option<(i32, i32)> {
            Some((self.0.x0, self.0.x0 + self.0.w))
        }
    }

    /// The point of the circle about `(cx, cy)` of radius `r_q` at the
    /// clockwise binary angle `t` (a turn `2^32`), rounded to quarter fine
    /// units (within a unit): an arc's cut.
    fn cut_point(cx: i32, cy: i32, r_q: i32, t: i64) -> (i32, i32) {
        let ang = t as f64 / 4_294_967_296.0 * std::f64::consts::TAU;
        (
            cx + (f64::from(r_q) * ang.cos()).round() as i32,
            cy + (f64::from(r_q) * ang.sin()).round() as i32,
        )
    }

    /// The circle walked into a window in bands of `band` rows; the same
    /// changes whether the window says what it keeps or not.
    fn walk(c: &CircleEdge, win: (i32, i32, i32, i32), band: i32) -> Vec<i64> {
        let mut w = Window::new(win.0, win.1, win.2, win.3);
        let mut clip = Clipping(Window::new(win.0, win.1, win.2, win.3));
        let mut y = win.1;
        while y < win.1 + win.3 {
            c.walk(y..y + band, 1, &mut w);
            c.walk(y..y + band, 1, &mut clip);
            y += band;
        }
        assert_eq!(w.d, clip.0.d, "{c:?} in {win:?}");
        w.coverage()
    }

    #[test]
    fn whole_pixel_chords_are_within_a_unit() {
        for m in 0..=4096u32 {
            let l = f64::from(m).hypot(4096.0);
            assert!((f64::from(pixel_chord(m)) - l).abs() < 0.7, "{m}");
        }
    }

    /// An arc's parts walked into windows that cut the circle anywhere
    /// (beside it too): the same changes whether the window says which
    /// columns it keeps or not, in any band height.
    #[test]
    fn arcs_walk_the_same_into_clipping_windows() {
        let mut rng = Lcg(0x000a_2c50_fc01);
        for case in 0..800 {
            let r_q = 4 * (512 + (rng.below(200 * 1024) >> rng.below(8)) as i32);
            let (cx, cy) = (
                4 * (rng.below(100 * 1024) as i32 - 50 * 1024),
                4 * (rng.below(100 * 1024) as i32 - 50 * 1024),
            );
            let c = CircleEdge::new(cx, cy, r_q as u32).unwrap();
            let a = rng.below(1 << 32) as i64;
            let sweep = 1 + rng.below((1 << 32) - 1) as i64;
            // The cut points on the circle, rounded (within a unit).
            let at = |t: i64| cut_point(cx, cy, r_q, t);
            let spans = c.arc_spans(a, sweep, at(a), at(a + sweep));
            let rows = c.rows();
            let (x_lo, x_hi) = ((cx - r_q) >> Q_BITS, (cx + r_q) >> Q_BITS);
            let x0 = x_lo - 3 + rng.below((x_hi - x_lo + 6) as u64) as i32;
            let w = 1 + rng.below(40) as i32;
            let h = rows.end - rows.start;
            for band in [16, 3] {
                let mut plain = Window::new(x0, rows.start, w, h);
                let mut clip = Clipping(Window::new(x0, rows.start, w, h));
                let mut y = rows.start;
                while y < rows.end {
                    c.walk_spans(y..y + band, 1, &spans, &mut plain);
                    c.walk_spans(y..y + band, 1, &spans, &mut clip);
                    y += band;
                }
                assert_eq!(
                    plain.d, clip.0.d,
                    "case {case}: {c:?} window at {x0} width {w}"
                );
            }
        }
    }

    /// Circles and arcs whose centre lies on a pixel's side or in its
    /// middle (every embedded-graphics circle's), their right halves given
    /// by their left halves' mirror images: the same changes, bit for bit,
    /// as each half walked on its own, in bands of 16 and 3 rows, and
    /// every pixel of a whole circle within 1/4096 px of the exact area.
    #[test]
    fn mirrored_halves_are_the_halves_walked() {
        let mut rng = Lcg(0x5111_e7a1_c0de);
        let mut paired = 0;
        for case in 0..500 {
            let r_q = 4 * (8 + (rng.below(100 * 1024) >> rng.below(9)) as i32);
            let (cx, cy) = (
                2048 * (rng.below(200) as i32 - 100),
                if case % 3 == 0 {
                    2048 * (rng.below(200) as i32 - 100)
                } else {
                    4 * (rng.below(100 * 1024) as i32 - 50 * 1024)
                },
            );
            let c = CircleEdge::new(cx, cy, r_q as u32).unwrap();
            assert!(c.mirror, "{c:?}");
            let mut plain = c;
            plain.mirror = false;
            let rows = c.rows();
            let (x_lo, x_hi) = ((cx - r_q) >> Q_BITS, (cx + r_q) >> Q_BITS);
            let win = (x_lo - 1, rows.start, x_hi - x_lo + 3, rows.end - rows.start);
            let arc = case % 2 == 1;
            let a = rng.below(1 << 32) as i64;
            let sweep = 1 + rng.below((1 << 32) - 1) as i64;
            let at = |t: i64| cut_point(cx, cy, r_q, t);
            let spans = if case % 4 == 1 && r_q >= 3 * Q {
                // An arc from a cut on a row's side in the upper left
                // quadrant over half a turn: in the row below the cut,
                // the left part starts at the cut, its twin (a whole
                // quadrant) at the circle.
                let y = ((cy - r_q / 2) >> Q_BITS) << Q_BITS;
                let dx = (f64::from(r_q).powi(2) - f64::from(y - cy).powi(2)).sqrt();
                let p = (cx - dx.round() as i32 - 1, y);
                let ang = f64::from(y - cy)
                    .atan2(f64::from(p.0 - cx))
                    .rem_euclid(std::f64::consts::TAU);
                let a = (ang / std::f64::consts::TAU * 4_294_967_296.0) as i64;
                c.arc_spans(a, 1 << 31, p, at(a + (1 << 31)))
            } else if case % 4 == 3 {
                // An arc about the vertical through the centre (a gauge),
                // its end the start's mirror image a unit off: the rows of
                // its cuts, at the same height, are not mirrors.
                let half = sweep / 2;
                let a = (3 << 30) - half;
                let pa = at(a);
                c.arc_spans(a, 2 * half, pa, (2 * cx - pa.0 + 1, pa.1))
            } else {
                c.arc_spans(a, sweep, at(a), at(a + sweep))
            };
            for band in [16, 3] {
                let mut both = Window::new(win.0, win.1, win.2, win.3);
                let mut each = Window::new(win.0, win.1, win.2, win.3);
                let mut y = rows.start;
                while y < rows.end {
                    if arc {
                        c.walk_spans(y..y + band, 1, &spans, &mut both);
                        plain.walk_spans(y..y + band, 1, &spans, &mut each);
                    } else {
                        c.walk(y..y + band, 1, &mut both);
                        plain.walk(y..y + band, 1, &mut each);
                    }
                    y += band;
                }
                assert_eq!(both.d, each.d, "case {case}: {c:?} bands of {band}");
                paired += 1;
                if !arc && band == 16 {
                    let (cxf, cyf, r) = (
                        f64::from(cx) / 4096.0,
                        f64::from(cy) / 4096.0,
                        f64::from(r_q) / 4096.0,
                    );
                    for (k, &v) in both.coverage().iter().enumerate() {
                        let (x, y) = (win.0 + k as i32 % win.2, win.1 + k as i32 / win.2);
                        let e = exact(cxf, cyf, r, x, y);
                        let d = (v as f64 / f64::from(COVER_ONE) - e).abs();
                        assert!(d < 1.0 / 4096.0, "case {case}: pixel ({x}, {y}) off by {d}");
                    }
                }
            }
        }
        assert_eq!(paired, 1000);
    }

    /// Every square and its neighbours: `floor(sqrt)` changes exactly
    /// there (the reference is the integer definition itself).
    /// Every pixel of windows over the circle's edge within 1/4096 px of
    /// the exact area, at random sub-pixel centres and radii from 1/128 px
    /// to 500 px (windows cut the circle: what lies left of a window
    /// counts in its first column, as in a band), and the same bits in
    /// bands of 16, 7, 3 and 1 rows.
    #[test]
    fn edge_pixels_are_exact_and_band_invariant() {
        let mut rng = Lcg(0xd15c_0a2e_a5ee_d001);
        let mut worst = 0.0f64;
        for case in 0..600 {
            let r_fine = if case < 50 {
                // Below half a pixel too, to the smallest walked (1/128 px).
                8 + rng.below(504) as i32
            } else if case < 100 {
                512 + rng.below(4096) as i32
            } else {
                512 + (rng.below(500 * 1024) >> rng.below(10)) as i32
            };
            let (cx_f, cy_f) = (
                rng.below(200 * 1024) as i32 - 100 * 1024,
                rng.below(200 * 1024) as i32 - 100 * 1024,
            );
            let c = CircleEdge::new(cx_f * 4, cy_f * 4, r_fine as u32 * 4).unwrap();
            let (cx, cy, r) = (
                f64::from(cx_f) / 1024.0,
                f64::from(cy_f) / 1024.0,
                f64::from(r_fine) / 1024.0,
            );
            // A window about a random point of the circle (or the whole
            // circle when small).
            let t = rng.below(6283) as f64 / 1000.0;
            let (px, py) = (cx + r * t.cos(), cy + r * t.sin());
            let (ww, wh) = (24, 24);
            let win = if r < 8.0 {
                (
                    (cx - r) as i32 - 2,
                    (cy - r) as i32 - 2,
                    2 * r as i32 + 5,
                    2 * r as i32 + 5,
                )
            } else {
                (px as i32 - ww / 2, py as i32 - wh / 2, ww, wh)
            };
            let got = walk(&c, win, 16);
            for band in [7, 3, 1] {
                assert_eq!(walk(&c, win, band), got, "case {case}: bands of {band}");
            }
            for (k, &v) in got.iter().enumerate() {
                let (x, y) = (win.0 + k as i32 % win.2, win.1 + k as i32 / win.2);
                let e = exact(cx, cy, r, x, y);
                let d = (v as f64 / f64::from(COVER_ONE) - e).abs();
                worst = worst.max(d);
                assert!(
                    d < 1.0 / 4096.0,
                    "case {case}: r {r} c ({cx}, {cy}) pixel ({x}, {y}): {} against {e}",
                    v as f64 / f64::from(COVER_ONE)
                );
            }
        }
        std::println!("worst {worst} px ({} units)", worst * f64::from(COVER_ONE));
    }
}
