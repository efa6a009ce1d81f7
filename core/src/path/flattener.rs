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
use super::segment::{Contour, SegmentSink};
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
        for k in 1..n {
            self.out.line_to(quad_at(&q, k, n));
        }
        self.out.line_to(q[2]);
    }

    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        let q = [self.out.last(), Pt::from(c1), Pt::from(c2), Pt::from(p)];
        let n = cubic_count(&q, self.tol);
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
    use super::*;

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
