//! The aliased walk: pixel-centre sampling with the top-left fill rule.
//!
//! Per frame row `j` whose centre `y_c = j + 1/2` lies in the edge's
//! half-open range `[y0, y1)` (top included, bottom excluded), the edge's
//! `x` at `y_c` is stepped with the Bresenham quotient and remainder (add /
//! compare per row), and full cover starts at the first pixel whose centre
//! is at or right of it: a centre exactly on a left edge is inside, on a
//! right edge outside. Shared edges therefore give every pixel to exactly
//! one of the two triangles.

use core::ops::Range;

use super::EdgeSink;
use crate::arith::{div_floor, rem_floor};
use crate::{SubPoint, COVER_ONE, SUB_ONE};

/// Reports the cover changes of the aliased edge `p0 -> p1` in `rows`.
pub fn walk_edge_aliased<const C: usize, K: EdgeSink<C>>(
    p0: SubPoint,
    p1: SubPoint,
    orientation: i32,
    rows: Range<i32>,
    sink: &mut K,
) {
    let (a, b, dir) = match p0.y.cmp(&p1.y) {
        core::cmp::Ordering::Less => (p0, p1, 1),
        core::cmp::Ordering::Greater => (p1, p0, -1),
        core::cmp::Ordering::Equal => return,
    };
    let w = orientation.signum() * dir;
    if w == 0 {
        return;
    }
    let sub = i64::from(SUB_ONE);
    let (x0, y0, x1, y1) = (
        i64::from(a.x),
        i64::from(a.y),
        i64::from(b.x),
        i64::from(b.y),
    );
    let (dx, dy) = (x1 - x0, y1 - y0);
    // Rows whose centre 16 j + 8 lies in [y0, y1).
    let first = div_floor(y0 - sub / 2 + sub - 1, sub);
    let last = div_floor(y1 - sub / 2 + sub - 1, sub) - 1;
    let first = first.max(i64::from(rows.start));
    let last = last.min(i64::from(rows.end) - 1);
    if first > last {
        return;
    }
    // Column = ceil((x(y_c) - 8) / 16) = -floor(m / d) with
    // m = -(x0 dy + (y_c - y0) dx - 8 dy), d = 16 dy.
    let d = sub * dy;
    let yc = first * sub + sub / 2;
    let m = -(x0 * dy + (yc - y0) * dx - sub / 2 * dy);
    let (mut fq, mut fr) = (div_floor(m, d), rem_floor(m, d));
    let step = -sub * dx;
    let (sq, sr) = (div_floor(step, d), rem_floor(step, d));
    for j in first..=last {
        sink.cover(-fq as i32, j as i32, w * COVER_ONE);
        fr += sr;
        fq += sq;
        if fr >= d {
            fr -= d;
            fq += 1;
        }
    }
}
