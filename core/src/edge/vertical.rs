//! Vertical edges, walked without set-up: what [`EdgeWalk`] reports for a
//! vertical edge in the exact mode, computed row by row from the edge's
//! end points.
//!
//! A vertical edge `x = X` (fine units) cuts every row it spans at the
//! same place: in pixel column `b = floor(X / N)` the area left of the
//! line is `h fx` (fine units², `fx = X - b N`, `h` the edge's height in
//! the row), the area right of it `h (N - fx)`. As coverage that is a
//! change of `h - S` at `b` and `S` at `b + 1`, `S = floor(h fx / 16)` (a
//! whole row: `fx << H_BITS`, exact), signed by the edge's direction. The
//! general walk gets the same values by its set-up (a division for the
//! step, the end rows' exact areas, a resumable state kept from band to
//! band); here each row is a shift and a multiply, so a band needs no
//! stored state and no lookup for the edge. User interfaces are full of
//! such edges: rectangles, buttons, bars, the straight sides of rounded
//! rectangles, a grid's cells.
//!
//! [`EdgeWalk`]: super::EdgeWalk

use core::ops::Range;

use super::canon::{cell_of, H_BITS, N};
use super::DeltaSink;
use crate::geom::{FinePoint, FINE_BITS};
use crate::{COVER_BITS, COVER_ONE};

/// Shift from fine units² to coverage units: `2 FINE_BITS - COVER_BITS`.
const AREA_SHIFT: u32 = 2 * FINE_BITS - COVER_BITS;

/// The changes of the vertical edge `p0 -> p1` (`p0.x == p1.x`, fine
/// coordinates in range; none for a point) in frame rows `rows`, into
/// `out`: the same calls, with the same values, as the exact-mode
/// [`EdgeWalk`](super::EdgeWalk) of the edge makes (interior rows a
/// `put_n` of two changes each, as one `put_rows`; the first and last rows
/// a cover change and, where the line is not on a pixel boundary, the two
/// changes of the cell's area).
pub(crate) fn walk<S: DeltaSink>(p0: FinePoint, p1: FinePoint, rows: Range<i32>, out: &mut S) {
    let (y0, y1, w) = if p0.y < p1.y {
        (p0.y, p1.y, 1)
    } else {
        (p1.y, p0.y, -1)
    };
    let x = p0.x;
    let b = cell_of(x);
    // 0 <= fx < N.
    let fx = x - b * N;
    // The first and last rows the edge touches (y0 < y1).
    let (a0, a1) = (cell_of(y0), cell_of(y1 - 1));
    let lo = rows.start.max(a0);
    let hi = rows.end.min(a1 + 1);
    if lo >= hi {
        return;
    }
    let end = Ends { y0, y1, b, fx, w };
    if lo == a0 {
        end.row(out, a0);
    }
    if hi == a1 + 1 && a1 != a0 {
        end.row(out, a1);
    }
    // The whole rows between; the area left of the line in a whole row
    // is exact.
    let (r0, r1) = (lo.max(a0 + 1), hi.min(a1));
    if r0 < r1 {
        let s = fx << H_BITS;
        out.put_rows(b, r0..r1, w * (COVER_ONE - s), w * s);
    }
}

/// What the first and last rows of a vertical edge need.
struct Ends {
    y0: i32,
    y1: i32,
    b: i32,
    fx: i32,
    w: i32,
}

impl Ends {
    /// End row `a`, where the edge's height may be part of the row.
    #[inline(always)]
    fn row<S: DeltaSink>(&self, out: &mut S, a: i32) {
        let Self { y0, y1, b, fx, w } = *self;
        // The edge's height in the row: 0 < h <= N, or 0 for a point
        // (`p0 == p1`), which gives nothing (as `Canon::new` says of a
        // horizontal edge).
        let h = (a * N + N).min(y1) - (a * N).max(y0);
        if h <= 0 {
            return;
        }
        // h fx < 2^20: the area's floor in coverage units.
        let s = (h * fx) >> AREA_SHIFT;
        if s != 0 {
            out.put(b, a, -w * s);
            out.put(b + 1, a, w * s);
        }
        out.put(b, a, w * (h << H_BITS));
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::edge::{AreaMode, EdgeWalk};

    /// Every change, one by one.
    struct Record(Vec<(i32, i32, i32)>);

    impl DeltaSink for Record {
        fn put(&mut self, x: i32, y: i32, d: i32) {
            self.0.push((x, y, d));
        }
    }

    impl DeltaSink for &mut Record {
        fn put(&mut self, x: i32, y: i32, d: i32) {
            self.0.push((x, y, d));
        }
    }

    fn sorted(mut v: Vec<(i32, i32, i32)>) -> Vec<(i32, i32, i32)> {
        v.sort_unstable();
        v
    }

    /// The general walk's changes of the edge in `rows`.
    fn general(p0: FinePoint, p1: FinePoint, rows: Range<i32>) -> Vec<(i32, i32, i32)> {
        let mut rec = Record(Vec::new());
        let mut w = EdgeWalk::new(p0, p1, AreaMode::Exact, -4096..4096).unwrap();
        w.walk_into(rows, &mut rec);
        sorted(rec.0)
    }

    fn fast(p0: FinePoint, p1: FinePoint, rows: Range<i32>) -> Vec<(i32, i32, i32)> {
        let mut rec = Record(Vec::new());
        walk(p0, p1, rows, &mut rec);
        sorted(rec.0)
    }

    #[test]
    fn vertical_edges_give_the_general_walks_changes() {
        // A small LCG: many x (on and off pixel boundaries, negative),
        // both directions, short and long, whole and partial end rows,
        // every window of rows around them.
        let mut s: u64 = 0x5eed_0001;
        let mut next = |m: i64| -> i64 {
            s = s
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((s >> 33) as i64).rem_euclid(m)
        };
        let n = i64::from(N);
        let mut checked = 0;
        for case in 0..3000 {
            let x = match case % 4 {
                0 => (next(80) - 40) * n,
                _ => next(80 * n) - 40 * n,
            } as i32;
            let ya = match case % 3 {
                0 => (next(60) - 30) * n,
                _ => next(60 * n) - 30 * n,
            };
            let len = match case % 5 {
                0 => 1 + next(n),
                1 => 1 + next(4 * n),
                _ => 1 + next(40 * n),
            };
            let (ya, yb) = (ya as i32, (ya + len) as i32);
            let (p0, p1) = if case % 2 == 0 {
                (FinePoint::new(x, ya), FinePoint::new(x, yb))
            } else {
                (FinePoint::new(x, yb), FinePoint::new(x, ya))
            };
            let (r0, r1) = (cell_of(ya) - 2, cell_of(yb) + 3);
            for start in r0..r1 {
                for end in [start + 1, start + 3, r1] {
                    let rows = start..end;
                    assert_eq!(
                        fast(p0, p1, rows.clone()),
                        general(p0, p1, rows.clone()),
                        "edge {p0:?} -> {p1:?}, rows {rows:?}"
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 50_000);
    }

    #[test]
    fn a_point_gives_no_changes() {
        for (x, y) in [(0, 0), (1000, 1500), (-77, 512), (5, -1)] {
            let p = FinePoint::new(x, y);
            assert_eq!(fast(p, p, -4..4), Vec::new());
        }
    }

    #[test]
    fn long_vertical_edges_at_the_range_limits_agree() {
        // Long enough for the general walk's end rows to take its 64-bit
        // area path (du >= 2^21).
        let lim = (1 << 21) - 1;
        for (x, ya, yb) in [
            (-lim, -lim, lim),
            (lim, lim, -lim),
            (12_345, -lim, 777),
            (-1, 3 - lim, lim - 5),
        ] {
            let (p0, p1) = (FinePoint::new(x, ya), FinePoint::new(x, yb));
            let (lo, hi) = (cell_of(ya.min(yb)), cell_of(ya.max(yb)));
            for rows in [lo - 1..lo + 3, hi - 2..hi + 2, -3..3, lo..hi + 1] {
                assert_eq!(fast(p0, p1, rows.clone()), general(p0, p1, rows));
            }
        }
    }
}
