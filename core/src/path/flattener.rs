//! [`Flattener`]: a [`PathSink`] that turns a path description into the
//! closed contours of straight segments the edge engine fills.
//!
//! Takes `move_to` / `line_to` / `quad_to` / `cubic_to` / `close` calls in
//! fine units (any `i32` coordinates); gives a [`SegmentSink`] the
//! segments of closed contours: curves flattened by [`bezier`](super::bezier)
//! (within `tol + 0.71` fine units of the curve, at most
//! [`MAX_CURVE_SEGMENTS`](super::MAX_CURVE_SEGMENTS) per curve), every
//! contour closed (on `close`, on the next `move_to`, and the last one on
//! [`finish`](Flattener::finish) or when the flattener is dropped), every
//! point clamped into the coordinate range without changing any winding
//! number inside it (see [`segment`](super::segment)).
//!
//! Work is bounded by the input: one segment per `line_to`, at most 1024
//! per curve, at most five pieces per segment from the clamping.

use crate::geom::{FinePoint, PathSink};

use super::bezier::{cubic_at, cubic_count, quad_at, quad_count};
use super::segment::{in_square, Contour, SegmentSink};
use super::vector::Pt;
use super::Tolerance;

/// Flattens a path into closed contours of segments.
///
/// ```
/// use softedge::geom::{FinePoint, PathSink};
/// use softedge::path::{Flattener, SegmentSink};
///
/// struct Count(usize);
/// impl SegmentSink for Count {
///     fn segment(&mut self, _: FinePoint, _: FinePoint) {
///         self.0 += 1;
///     }
/// }
/// let mut count = Count(0);
/// let mut f = Flattener::new(&mut count);
/// f.move_to(FinePoint::new(0, 0));
/// f.quad_to(FinePoint::new(10240, 0), FinePoint::new(10240, 10240));
/// f.finish(); // closes the contour: the curve's chords plus one segment back
/// assert!(count.0 > 2);
/// ```
pub struct Flattener<'s, S: SegmentSink + ?Sized> {
    out: Contour<'s, S>,
    tol: i64,
}

impl<'s, S: SegmentSink + ?Sized> Flattener<'s, S> {
    /// A flattener with the default tolerance ([`Tolerance::DEFAULT`]).
    pub fn new(sink: &'s mut S) -> Self {
        Self::with_tolerance(sink, Tolerance::DEFAULT)
    }

    /// A flattener whose curves stay within `tol` (plus the grid rounding,
    /// 0.71 fine units) of the true curves.
    pub fn with_tolerance(sink: &'s mut S, tol: Tolerance) -> Self {
        Self {
            out: Contour::new(sink),
            tol: i64::from(tol.fine()),
        }
    }

    /// Closes the last contour. (Dropping the flattener does the same.)
    pub fn finish(mut self) {
        self.out.close();
    }
}

impl<S: SegmentSink + ?Sized> Flattener<'_, S> {
    /// True when a curve with control points `q` lies wholly above or
    /// below the sink's window: a Bézier lies in the hull of its control
    /// points, and each flattened point is a point of the curve rounded to
    /// the grid (within a fine unit), so none of its segments meets the
    /// window and the curve is jumped over, its segments counted.
    ///
    /// Only a curve whose control points lie in the range square is
    /// jumped: its segments are then sent unclamped, one number each,
    /// which is what the jump counts (a clamped one takes
    /// [`CLAMPED_NUMBERS`](super::segment::CLAMPED_NUMBERS)).
    fn misses_window(&self, q: &[Pt]) -> bool {
        let Some((lo, hi)) = self.out.sink.window() else {
            return false;
        };
        let (mut ylo, mut yhi) = (i64::MAX, i64::MIN);
        for p in q {
            if !in_square(*p) {
                return false;
            }
            ylo = ylo.min(p.y);
            yhi = yhi.max(p.y);
        }
        yhi + 1 < i64::from(lo) || ylo - 1 > i64::from(hi)
    }
}

impl<S: SegmentSink + ?Sized> Drop for Flattener<'_, S> {
    fn drop(&mut self) {
        self.out.close();
    }
}

impl<S: SegmentSink + ?Sized> PathSink for Flattener<'_, S> {
    fn move_to(&mut self, p: FinePoint) {
        self.out.move_to(p.into());
    }

    /// A segment to `p`. Without a `move_to` first, the contour starts at
    /// the last point (the origin before anything else).
    fn line_to(&mut self, p: FinePoint) {
        self.out.line_to(p.into());
    }

    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        let q = [self.out.last(), Pt::from(c), Pt::from(p)];
        let n = quad_count(&q, self.tol);
        if self.misses_window(&q) {
            self.out.jump(q[2], n);
            return;
        }
        for k in 1..n {
            self.out.line_to(quad_at(&q, k, n));
        }
        self.out.line_to(q[2]);
    }

    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        let q = [self.out.last(), Pt::from(c1), Pt::from(c2), Pt::from(p)];
        let n = cubic_count(&q, self.tol);
        if self.misses_window(&q) {
            self.out.jump(q[3], n);
            return;
        }
        for k in 1..n {
            self.out.line_to(cubic_at(&q, k, n));
        }
        self.out.line_to(q[3]);
    }

    fn close(&mut self) {
        self.out.close();
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::path::testing::{Lcg, Numbering};

    #[derive(Default)]
    struct Sum {
        n: usize,
        area2: i128,
        balance: (i64, i64),
    }
    impl SegmentSink for Sum {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            self.n += 1;
            self.area2 += i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y);
            self.balance.0 += i64::from(b.x - a.x);
            self.balance.1 += i64::from(b.y - a.y);
        }
    }

    /// `culled` (numbered through window `w`) has the same count as
    /// `whole` and the same numbered segments where they meet `w`.
    fn assert_same_numbers(whole: &Numbering, culled: &Numbering, w: (i32, i32), case: u32) {
        let meets = |n: &Numbering| -> std::vec::Vec<_> {
            n.segs
                .iter()
                .copied()
                .filter(|(_, a, b)| a.y.max(b.y) >= w.0 && a.y.min(b.y) <= w.1)
                .collect()
        };
        assert_eq!(whole.next, culled.next, "case {case}");
        assert_eq!(meets(whole), meets(culled), "case {case}");
    }

    #[test]
    fn curves_outside_the_window_leave_out_only_segments_outside_it() {
        let mut rng = Lcg(0x2f6b_3a9c_11d4_e807);
        let mut next = |m: i64| rng.below(m as u64) as i64;
        let mut jumped = 0;
        for case in 0..2000 {
            let mut pts = [FinePoint::default(); 10];
            for p in pts.iter_mut() {
                *p = FinePoint::new(next(200_000) as i32, next(200_000) as i32);
            }
            let y0 = next(200_000) as i32;
            let w = (y0, y0 + 1 + next(30_000) as i32);
            let run = |window| {
                let mut n = Numbering {
                    window,
                    next: 0,
                    segs: std::vec::Vec::new(),
                };
                let mut f =
                    Flattener::with_tolerance(&mut n, Tolerance::new(1 + (case % 7) as u16));
                f.move_to(pts[0]);
                f.quad_to(pts[1], pts[2]);
                f.cubic_to(pts[3], pts[4], pts[5]);
                f.line_to(pts[6]);
                f.cubic_to(pts[7], pts[8], pts[9]);
                f.quad_to(pts[2], pts[0]);
                f.finish();
                n
            };
            let (whole, culled) = (run(None), run(Some(w)));
            assert_same_numbers(&whole, &culled, w, case);
            jumped += whole.segs.len() - culled.segs.len();
        }
        assert!(jumped > 10_000, "{jumped}");
    }

    /// The same beyond the coordinate range, where segments are clamped
    /// to it (sent as up to five pieces): numbers do not depend on the
    /// window there either, for curves and for circles (the fuzzer found a
    /// circle of radius 2 100 px numbered 1 592 segments whole and 1 584
    /// in a window).
    #[test]
    fn clamped_segments_keep_their_numbers_in_any_window() {
        use crate::path::{Circle, Shape};
        let mut rng = Lcg(0x77aa_0913_5eed_c0de);
        let mut next = |m: i64| rng.below(m as u64) as i64;
        let limit = crate::geom::FINE_LIMIT;
        for case in 0..600 {
            let mut pts = [FinePoint::default(); 10];
            for p in pts.iter_mut() {
                *p = FinePoint::new(
                    (next(6 << 20) - (3 << 20)) as i32,
                    (next(6 << 20) - (3 << 20)) as i32,
                );
            }
            let y0 = (next(4 << 20) - (2 << 20)) as i32;
            let w = (y0, y0 + 1 + next(60_000) as i32);
            let circle = Circle::new(
                FinePoint::new(pts[0].x / 4, pts[0].y / 4),
                limit as u32 / 2 + next(1 << 21) as u32,
            );
            let run = |window| {
                let mut n = Numbering {
                    window,
                    next: 0,
                    segs: std::vec::Vec::new(),
                };
                if case % 2 == 0 {
                    let mut f = Flattener::new(&mut n);
                    f.move_to(pts[0]);
                    f.quad_to(pts[1], pts[2]);
                    f.cubic_to(pts[3], pts[4], pts[5]);
                    f.line_to(pts[6]);
                    f.cubic_to(pts[7], pts[8], pts[9]);
                    f.finish();
                } else {
                    circle.fill(&mut n);
                }
                n
            };
            let (whole, culled) = (run(None), run(Some(w)));
            assert_same_numbers(&whole, &culled, w, case);
        }
    }

    #[test]
    fn every_contour_is_closed_also_without_close() {
        let mut s = Sum::default();
        {
            let mut f = Flattener::new(&mut s);
            f.move_to(FinePoint::new(0, 0));
            f.line_to(FinePoint::new(100, 0));
            f.line_to(FinePoint::new(100, 100));
            f.move_to(FinePoint::new(500, 500)); // closes the first
            f.line_to(FinePoint::new(600, 500));
            f.line_to(FinePoint::new(600, 600));
            // dropped: closes the second
        }
        assert_eq!(s.n, 6);
        assert_eq!(s.balance, (0, 0));
        assert_eq!(s.area2, 2 * 10000 / 2 * 2);
    }

    #[test]
    fn line_to_after_close_starts_at_the_contour_start() {
        let mut s = Sum::default();
        let mut f = Flattener::new(&mut s);
        f.move_to(FinePoint::new(0, 0));
        f.line_to(FinePoint::new(100, 0));
        f.line_to(FinePoint::new(100, 100));
        f.close();
        f.line_to(FinePoint::new(-100, 0));
        f.line_to(FinePoint::new(-100, -100));
        f.finish();
        assert_eq!(s.balance, (0, 0));
        assert_eq!(s.n, 6);
    }

    #[test]
    fn degenerate_curves_give_nothing_or_a_line() {
        let mut s = Sum::default();
        let mut f = Flattener::new(&mut s);
        let p = FinePoint::new(7, 7);
        f.move_to(p);
        f.cubic_to(p, p, p);
        f.quad_to(p, p);
        f.close();
        f.finish();
        assert_eq!(s.n, 0);
    }

    #[test]
    fn huge_coordinates_are_clamped_and_bounded() {
        let mut s = Sum::default();
        let mut f = Flattener::new(&mut s);
        let (a, b) = (i32::MIN, i32::MAX);
        f.move_to(FinePoint::new(a, a));
        f.cubic_to(
            FinePoint::new(b, a),
            FinePoint::new(a, b),
            FinePoint::new(b, b),
        );
        f.finish();
        assert!(s.n <= 5 * 1025);
        assert_eq!(s.balance, (0, 0));
    }
}
