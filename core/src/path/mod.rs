//! Paths, shapes and strokes: everything before the edge engine (issue #16).
//!
//! Takes descriptions of geometry — paths of lines and quadratic and cubic
//! Béziers (through [`PathSink`](crate::geom::PathSink)), SVG path data,
//! circles, ellipses, arcs, sectors, rectangles, rounded rectangles,
//! polylines, and strokes of any of them — and gives the edge engine what
//! it fills: directed straight segments of closed contours on the fine grid
//! ([`FinePoint`](crate::geom::FinePoint), 1/1024 px), through a
//! [`SegmentSink`]. All set-up: integer only, bounded loops, no panic.
//!
//! ## What a [`SegmentSink`] receives
//!
//! - **Closed contours** of non-zero-length segments, every endpoint inside
//!   the coordinate range (`|x|, |y| <= FINE_LIMIT`), points beyond it
//!   clamped without changing any winding number inside the range
//!   ([`segment`]). Segments come in no particular order.
//! - **Orientation**: a filled region is bounded clockwise on screen (y
//!   down), i.e. its shoelace sum `sum x_i y_(i+1) - x_(i+1) y_i` is
//!   positive and the winding number inside is `+1`; holes (the inside of
//!   a ring) run counter-clockwise. Every shape here fills with winding
//!   numbers in `{0, 1}`, so the nonzero and the even-odd rule agree on
//!   it. Paths ([`Flattener`], SVG data) keep the direction they are
//!   described in; the fill rule is the engine's choice.
//! - **Strokes** ([`Stroker`]) are one shape: closed contours made of the
//!   pieces of the stroke (segment bodies, joins, caps), each piece
//!   clockwise, summed so that the edges two pieces share cancel. The
//!   winding number is the number of pieces covering a point, never
//!   negative; where pieces would overlap at a join, the stroker trims
//!   them so that they tile (winding exactly 1), and where it cannot (a
//!   segment shorter than its join needs, a stroke wider than a curve's
//!   radius, a path that crosses itself) the overlap counts 2 and the
//!   **nonzero** rule gives the exact stroke outline. An engine that
//!   applies nonzero to each pixel's accumulated area (rather than to the
//!   winding at each point) over-covers only the edge pixels of such
//!   overlaps.
//!
//! ## Accuracy
//!
//! Curves are cut into chords within a tolerance `tol` ([`Tolerance`],
//! 3 fine units by default) of the true curve, and every vertex is the
//! true point rounded to the grid: emitted geometry is within
//! `tol + sqrt(2)/2 < 4` fine units (1/256 px) of the exact shape.
//! Circles, ellipses, arcs, sectors and rounded corners are polygons whose
//! vertices are placed so that the polygon's area equals the exact area
//! (before rounding): an inscribed polygon would lose area. See
//! [`bezier`] and [`arc`] for the bounds and the
//! segment counts.
//!
//! ## Units
//!
//! Coordinates and lengths are fine units (`i32`/`u32`, 1/1024 px, the
//! bits of `fixed::types::I22F10`); angles are [`Degrees`] (fixed-point
//! degrees, 1/65536 degree, clockwise on screen from the +x axis, as
//! embedded-graphics measures them).

mod angle;
pub mod arc;
pub mod bezier;
#[cfg(feature = "embedded-graphics")]
pub mod eg;
mod flattener;
pub mod segment;
mod shape;
pub mod stroke;
pub mod svg;
mod trig;
mod vector;

pub use angle::Degrees;
pub use arc::{MAX_ARC_SEGMENTS, MAX_ELLIPSE_SEGMENTS, MAX_RADIUS};
pub use bezier::MAX_CURVE_SEGMENTS;
pub use flattener::Flattener;
pub use segment::SegmentSink;
pub use shape::{
    Arc, Circle, CornerRadii, Ellipse, Line, Polyline, Rectangle, RoundedRectangle, Sector, Shape,
};
pub use stroke::{
    Dash, LineCap, LineJoin, MiterLimit, StrokeAlignment, StrokeError, StrokeStyle, Stroker,
    MAX_DASH_INTERVALS, MAX_STROKE_WIDTH,
};

/// How far flattened curves may stray from the true curves, in fine units
/// (1/1024 px), before the vertices are rounded to the grid (which adds at
/// most `sqrt(2)/2` fine units).
///
/// ```
/// use softedge::path::Tolerance;
/// assert_eq!(Tolerance::DEFAULT.fine(), 3);
/// assert_eq!(Tolerance::new(0).fine(), 1); // limited to 1..=256
/// assert_eq!(Tolerance::new(1000).fine(), 256);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Tolerance(u16);

impl Tolerance {
    /// 3 fine units: with the rounding, every emitted point is within
    /// `3.71 < 4` fine units (1/256 px) of the exact curve, so a pixel's
    /// coverage is within `4 * 4/1024 = 1/64` of the exact coverage (a
    /// convex boundary inside one pixel is at most 4 px long).
    pub const DEFAULT: Tolerance = Tolerance(3);
    /// The finest tolerance.
    pub const MIN: Tolerance = Tolerance(1);
    /// The coarsest tolerance, 1/4 px.
    pub const MAX: Tolerance = Tolerance(256);

    /// A tolerance of `fine` units, limited to `1..=256`.
    pub const fn new(fine: u16) -> Self {
        if fine < Self::MIN.0 {
            Self::MIN
        } else if fine > Self::MAX.0 {
            Self::MAX
        } else {
            Tolerance(fine)
        }
    }

    /// The tolerance in fine units.
    pub const fn fine(self) -> u16 {
        self.0
    }
}

impl Default for Tolerance {
    fn default() -> Self {
        Self::DEFAULT
    }
}
