//! Shapes: circles, ellipses, arcs, sectors, rectangles, rounded
//! rectangles, polylines and lines, each a value that describes itself.
//!
//! Takes a shape's geometry in fine units (1/1024 px) and [`Degrees`];
//! gives, through the [`Shape`] trait,
//!
//! - [`Shape::describe`]: its outline as a path (lines and cubic Béziers,
//!   see [`arc`](crate::path::arc) for the arcs) into any
//!   [`PathSink`]: to stroke it, dash it, or hand it on;
//! - [`Shape::fill`]: its interior as closed contours of segments, the
//!   round parts as **area-preserving polygons** (the polygon's area is
//!   the exact area before the grid rounding), clockwise on screen;
//! - [`Shape::stroke`]: its stroke. Without dashes, circles, rectangles,
//!   rounded rectangles, sectors and arcs (butt caps, or centred round
//!   and square caps where the ring has a hole) are stroked as the
//!   ring between an outer and an inner outline of the same family (two
//!   contours of opposite direction, or one for an arc, its caps in it):
//!   exact offsets
//!   for circles, rectangles, sectors and circular corners, and
//!   embedded-graphics' model for elliptic corners (semi-axes plus and
//!   minus the offset). Ellipses, dashed outlines and everything else go
//!   through the [`Stroker`]: the exact offset
//!   ([`Ellipse::ring`] is embedded-graphics' model of an ellipse's
//!   stroke).
//!
//! Degenerate shapes (radius or size zero, zero sweep) are empty: nothing
//! is emitted. Radii are limited to [`MAX_RADIUS`](crate::path::MAX_RADIUS).
//!
//! | shape | area of the fill |
//! | --- | --- |
//! | [`Circle`] | `pi r^2` |
//! | [`Ellipse`] | `pi a b` |
//! | [`Sector`] | `s r^2 / 2` (`s` in radians) |
//! | [`Arc`] stroked, butt caps | `s ((r + o)^2 - (r - i)^2) / 2` |
//! | [`Rectangle`] | `w h` |
//! | [`RoundedRectangle`] | `w h - (1 - pi/4) sum rx_k ry_k` |

mod circle;
mod ellipse;
mod key;
mod polyline;
mod rect;
pub(crate) mod sector;

pub use circle::Circle;
pub use ellipse::Ellipse;
pub use key::ShapeKey;
pub(crate) use key::{same_stream, write_stream, Kind as DescribedKind};
pub use polyline::{Line, Polygon, Polyline};
pub use rect::{CornerRadii, Rectangle, RoundedRectangle};
pub use sector::{Arc, Sector};

use crate::geom::PathSink;

use super::arc::{ellipse_points, EllipseFrame};
use super::segment::{ContourVertices, SegmentSink, Vertices};
use super::{Degrees, Flattener, StrokeError, StrokeStyle, Tolerance};

/// A shape that can describe its outline, fill itself and stroke itself.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Circle, SegmentSink, Shape, StrokeStyle};
///
/// #[derive(Default)]
/// struct Area2(i64);
/// impl SegmentSink for Area2 {
///     fn segment(&mut self, a: FinePoint, b: FinePoint) {
///         self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
///     }
/// }
/// let disc = Circle::new(FinePoint::new(20 * 1024, 20 * 1024), 10 * 1024);
/// let mut a = Area2::default();
/// disc.fill(&mut a);
/// let px2 = a.0 as f64 / 2.0 / (1024.0 * 1024.0);
/// assert!((px2 / (core::f64::consts::PI * 100.0) - 1.0).abs() < 1e-4);
///
/// let mut ring = Area2::default();
/// disc.stroke(&StrokeStyle::new(2048), &mut ring).unwrap(); // 2 px wide
/// let px2 = ring.0 as f64 / 2.0 / (1024.0 * 1024.0);
/// assert!((px2 / (core::f64::consts::PI * (121.0 - 81.0)) - 1.0).abs() < 1e-4);
/// ```
pub trait Shape {
    /// Describes the outline: clockwise on screen, closed contours closed
    /// with [`PathSink::close`], open ones (arcs, polylines, lines) not.
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P);

    /// Fills the shape within `tol` (plus the grid rounding).
    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        let mut f = Flattener::with_tolerance(sink, tol);
        self.describe(&mut f);
        f.finish();
    }

    /// Fills the shape with the default tolerance.
    fn fill<S: SegmentSink + ?Sized>(&self, sink: &mut S) {
        self.fill_with(Tolerance::DEFAULT, sink);
    }

    /// Strokes the shape's outline within `tol`; where it goes through
    /// the [`Stroker`](crate::path::Stroker) and would build more than
    /// [`MAX_STROKE_WORK`](crate::path::MAX_STROKE_WORK) units of work
    /// (strokes thousands of pixels wide, or of curves across the whole
    /// range), within the finest of `4 tol`, `16 tol`, ... (at most 12 px)
    /// that keeps it there (`path::stroke::budget`), the same in every
    /// band.
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        super::stroke::stroke_described(self, style, tol, sink)
    }

    /// Strokes the shape's outline with the default tolerance.
    fn stroke<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        self.stroke_with(style, Tolerance::DEFAULT, sink)
    }

    /// The shape's geometry as a [`ShapeKey`], by which a
    /// [`ShapeCache`](crate::canvas::ShapeCache) keeps its outline:
    /// `None` (the default) for a shape described again wherever it is
    /// drawn. A shape that gives a key must describe the same segments
    /// whenever its key is the same (polylines, polygons and SVG paths,
    /// whose keys are made from their descriptions, are compared by their
    /// descriptions too).
    fn key(&self) -> Option<ShapeKey> {
        None
    }

    /// True when [`key`](Self::key) is made by a pass over the shape's
    /// points (polylines, polygons, SVG paths): a canvas without a shape
    /// cache, which only needs the keys of circles and arcs, then does not
    /// ask for it. False (the default) for a key of a few numbers.
    fn key_reads_points(&self) -> bool {
        false
    }
}

/// True when the style needs the general stroker (a dash pattern that
/// changes something).
fn needs_stroker(style: &StrokeStyle<'_>) -> bool {
    style.dash.is_some_and(|d| !d.is_solid())
}

/// Sends points as one closed contour (curves in it may leave out what
/// misses the sink's window, see [`Vertices`]).
fn polygon<S: SegmentSink + ?Sized>(sink: &mut S, mut points: impl FnMut(&mut dyn Vertices)) {
    let mut c = ContourVertices::new(sink);
    points(&mut c);
    c.close();
}

/// The area-preserving polygon of a whole ellipse as a closed contour,
/// clockwise or (`reverse`) counter-clockwise.
fn ellipse_contour<S: SegmentSink + ?Sized>(
    frame: &EllipseFrame,
    reverse: bool,
    tol: Tolerance,
    sink: &mut S,
) {
    if frame.is_flat() {
        return;
    }
    polygon(sink, |out| ellipse_points(frame, 0, reverse, tol, out));
}

/// The binary angle of `d` degrees (for rotations).
fn angle(d: Degrees) -> i64 {
    d.binary()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::FinePoint;
    use crate::path::testing::Tally;

    const C: FinePoint = FinePoint::new(40 * 1024, 40 * 1024);

    fn fill<T: Shape>(s: &T) -> Tally {
        let mut t = Tally::default();
        s.fill(&mut t);
        t
    }

    fn stroke<T: Shape>(s: &T, w: u32) -> Tally {
        let mut t = Tally::default();
        s.stroke(&StrokeStyle::new(w), &mut t).unwrap_or(());
        t
    }

    #[test]
    fn shapes_of_no_size_are_empty() {
        let z = Degrees::ZERO;
        assert_eq!(fill(&Circle::new(C, 0)).count, 0);
        assert_eq!(stroke(&Circle::new(C, 0), 1024).count, 0);
        assert_eq!(fill(&Ellipse::new(C, 0, 5000)).count, 0);
        assert_eq!(stroke(&Ellipse::new(C, 5000, 0), 1024).count, 0);
        assert_eq!(fill(&Sector::new(C, 5000, Degrees::new(30), z)).count, 0);
        assert_eq!(
            stroke(&Arc::new(C, 5000, Degrees::new(30), z), 1024).count,
            0
        );
        assert_eq!(stroke(&Arc::new(C, 0, z, Degrees::new(90)), 1024).count, 0);
        assert_eq!(fill(&Rectangle::new(C, 0, 100)).count, 0);
        assert_eq!(stroke(&Rectangle::new(C, 100, 0), 1024).count, 0);
        let r = RoundedRectangle::new(Rectangle::new(C, 0, 0), CornerRadii::uniform(9));
        assert_eq!(fill(&r).count, 0);
        assert_eq!(fill(&Polyline::<FinePoint>::new(&[])).count, 0);
        assert_eq!(fill(&Line::new(C, FinePoint::new(0, 0))).count, 0);
        // A zero-width stroke of anything: nothing.
        assert_eq!(stroke(&Circle::new(C, 5000), 0).count, 0);
        assert_eq!(stroke(&Rectangle::new(C, 100, 100), 0).count, 0);
    }

    #[test]
    fn a_sector_of_a_turn_or_more_is_the_disc() {
        let disc = fill(&Circle::new(C, 10240));
        for sweep in [360, 400, -360, -1000] {
            let s = fill(&Sector::new(
                C,
                10240,
                Degrees::new(77),
                Degrees::new(sweep),
            ));
            assert_eq!(s.area2, disc.area2, "{sweep}");
        }
    }

    #[test]
    fn a_negative_sweep_is_the_same_sector_run_the_other_way() {
        let a = fill(&Sector::new(C, 10240, Degrees::new(10), Degrees::new(-70)));
        let b = fill(&Sector::new(C, 10240, Degrees::new(-60), Degrees::new(70)));
        assert_eq!(a.area2, b.area2);
        assert!(a.area2 > 0 && a.closed());
    }

    #[test]
    fn radii_larger_than_the_sides_are_clamped_and_zero_radii_are_square() {
        let r = Rectangle::new(C, 10 * 1024, 4 * 1024);
        let rr = RoundedRectangle::new(r, CornerRadii::uniform(100 * 1024));
        // Every radius scaled by 4/200: 2 px, a stadium.
        assert_eq!(rr.radii(), CornerRadii::uniform(2 * 1024));
        let t = fill(&rr);
        let want = 10.0 * 4.0 - (4.0 - core::f64::consts::PI) * 4.0;
        assert!((t.px2() - want).abs() < 1e-3, "{}", t.px2());
        let sq = RoundedRectangle::new(
            r,
            CornerRadii {
                top_left: (0, 5000),
                ..CornerRadii::ZERO
            },
        );
        assert_eq!(sq.radii(), CornerRadii::ZERO);
        assert_eq!(fill(&sq).area2, fill(&r).area2);
    }

    #[test]
    fn huge_radii_are_limited_and_stay_closed_in_range() {
        let t = fill(&Circle::new(FinePoint::new(i32::MAX, i32::MIN), u32::MAX));
        assert!(t.closed() && t.count <= 5 * 2048);
        let t = stroke(
            &Ellipse::new(C, u32::MAX, 1).rotated(Degrees::new(33)),
            u32::MAX,
        );
        assert!(t.closed());
    }
}
