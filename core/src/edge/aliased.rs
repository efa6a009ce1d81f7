//! The aliased walk: pixel-centre sampling with the top-left fill rule.
//!
//! Per frame row `j` whose centre `y_c = j + 1/2` lies in the edge's
//! half-open range `[y0, y1)` (top included, bottom excluded), the edge's
//! `x` at `y_c` is stepped with the Bresenham quotient and remainder (add /
//! compare per row), and full cover starts at the first pixel whose centre
//! is at or right of it: a centre exactly on a left edge is inside, on a
//! right edge outside. Shared edges therefore give every pixel to exactly
//! one of the two shapes.

use core::ops::Range;

use super::CoverSink;
use crate::arith::{div_floor, divmod_floor};
use crate::geom::{FinePoint, FINE_ONE};
use crate::COVER_ONE;

/// An edge set up for aliased walking, resumable from band to band.
#[derive(Debug, Clone, Copy)]
pub struct AliasedWalk {
    /// Winding: `+1` down the screen, `-1` up.
    w: i32,
    /// First and last sampled rows.
    first: i32,
    last: i32,
    x0: i64,
    y0: i64,
    dx: i64,
    /// `N dy`: the divisor of the column.
    d: i64,
    /// The column's step per row, quotient and remainder over `d`.
    sq: i64,
    sr: i64,
    /// The next row and its column state `-floor(m / d)`, `m mod d`.
    row: i32,
    fq: i64,
    fr: i64,
}

impl AliasedWalk {
    /// Sets up the edge `p0 -> p1` (fine units, or any grid scaled to
    /// 1/1024 of its cells); `None` when it samples no row centre.
    pub fn new(p0: FinePoint, p1: FinePoint) -> Option<Self> {
        let (a, b, w) = match p0.y.cmp(&p1.y) {
            core::cmp::Ordering::Less => (p0, p1, 1),
            core::cmp::Ordering::Greater => (p1, p0, -1),
            core::cmp::Ordering::Equal => return None,
        };
        let n = i64::from(FINE_ONE);
        let (x0, y0, x1, y1) = (
            i64::from(a.x),
            i64::from(a.y),
            i64::from(b.x),
            i64::from(b.y),
        );
        let (dx, dy) = (x1 - x0, y1 - y0);
        // Rows whose centre N j + N/2 lies in [y0, y1).
        let first = div_floor(y0 - n / 2 + n - 1, n);
        let last = div_floor(y1 - n / 2 + n - 1, n) - 1;
        if first > last {
            return None;
        }
        let d = n * dy;
        let step = -n * dx;
        let (sq, sr) = divmod_floor(step, d);
        let mut walk = Self {
            w,
            first: first as i32,
            last: last as i32,
            x0,
            y0,
            dx,
            d,
            sq,
            sr,
            row: i32::MIN,
            fq: 0,
            fr: 0,
        };
        walk.seek(walk.first);
        Some(walk)
    }

    /// The frame rows the edge samples.
    pub fn rows(&self) -> Range<i32> {
        self.first..self.last + 1
    }

    /// Column state at row `j`, directly (divides).
    fn seek(&mut self, j: i32) {
        let n = i64::from(FINE_ONE);
        // Column = ceil((x(y_c) - N/2) / N) = -floor(m / d) with
        // m = -(x0 dy + (y_c - y0) dx - N/2 dy), d = N dy.
        let yc = i64::from(j) * n + n / 2;
        let dy = self.d / n;
        let m = -(self.x0 * dy + (yc - self.y0) * self.dx - n / 2 * dy);
        self.row = j;
        (self.fq, self.fr) = divmod_floor(m, self.d);
    }

    /// Reports the cover changes of the rows in `rows` to `sink`.
    pub fn walk<K: CoverSink>(&mut self, rows: Range<i32>, sink: &mut K) {
        let lo = rows.start.max(self.first);
        let hi = rows.end.min(self.last + 1);
        if lo >= hi {
            return;
        }
        if self.row != lo {
            self.seek(lo);
        }
        for j in lo..hi {
            sink.cover(
                (-self.fq).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32,
                j,
                self.w * COVER_ONE,
            );
            self.fr += self.sr;
            self.fq += self.sq;
            if self.fr >= self.d {
                self.fr -= self.d;
                self.fq += 1;
            }
        }
        self.row = hi;
    }
}
