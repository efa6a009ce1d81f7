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
//! - [`Shape::stroke`]: its stroke. Without dashes, circles, ellipses,
//!   rectangles, rounded rectangles and butt-capped arcs are stroked as
//!   the ring between an outer and an inner outline of the same family
//!   (two contours of opposite direction, or one for an arc): exact
//!   offsets for circles, rectangles and circular corners, and
//!   embedded-graphics' model for ellipses and elliptic corners (semi-axes
//!   plus and minus the offset). Everything else goes through the
//!   [`Stroker`].
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
mod polyline;
mod rect;
mod sector;

pub use circle::Circle;
pub use ellipse::Ellipse;
pub use polyline::{Line, Polyline};
pub use rect::{CornerRadii, Rectangle, RoundedRectangle};
pub use sector::{Arc, Sector};

use crate::geom::PathSink;

use super::arc::{ellipse_points, EllipseFrame};
use super::segment::{Contour, SegmentSink};
use super::{Degrees, Flattener, StrokeError, StrokeStyle, Stroker, Tolerance};

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

    /// Strokes the shape's outline within `tol`.
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        let mut s = Stroker::with_tolerance(style, tol, sink);
        self.describe(&mut s);
        s.finish()
    }

    /// Strokes the shape's outline with the default tolerance.
    fn stroke<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        self.stroke_with(style, Tolerance::DEFAULT, sink)
    }
}

/// True when the style needs the general stroker (a dash pattern that
/// changes something).
fn needs_stroker(style: &StrokeStyle<'_>) -> bool {
    style.dash.is_some_and(|d| !d.is_solid())
}

/// Sends points as one closed contour.
fn polygon<S: SegmentSink + ?Sized>(
    sink: &mut S,
    mut points: impl FnMut(&mut dyn FnMut(super::vector::Pt)),
) {
    let mut c = Contour::new(sink);
    let mut first = true;
    points(&mut |p| {
        if first {
            c.move_to(p);
            first = false;
        } else {
            c.line_to(p);
        }
    });
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
