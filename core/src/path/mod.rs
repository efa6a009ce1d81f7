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
//! ```
//! use softedge::geom::{FinePoint, PathSink};
//! use softedge::path::svg::SvgPath;
//! use softedge::path::{Circle, Flattener, LineJoin, SegmentSink, Shape, StrokeStyle};
//!
//! /// Twice the signed area of everything received (the shoelace sum).
//! #[derive(Default)]
//! struct Area2(i64);
//! impl SegmentSink for Area2 {
//!     fn segment(&mut self, a: FinePoint, b: FinePoint) {
//!         self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
//!     }
//! }
//! let px2 = |a: &Area2| a.0 as f64 / 2.0 / (1024.0 * 1024.0);
//!
//! // A shape: a disc of radius 10 px about (20.5, 20.5) px.
//! let mut a = Area2::default();
//! Circle::new(FinePoint::new(20 * 1024 + 512, 20 * 1024 + 512), 10 * 1024).fill(&mut a);
//! assert!((px2(&a) - 314.159).abs() < 0.01);
//!
//! // A path, by hand or from SVG path data, flattened into closed contours.
//! let mut a = Area2::default();
//! let mut f = Flattener::new(&mut a);
//! f.move_to(FinePoint::new(0, 0));
//! f.line_to(FinePoint::new(10 * 1024, 0));
//! f.quad_to(FinePoint::new(10 * 1024, 10 * 1024), FinePoint::new(0, 10 * 1024));
//! f.finish();
//! assert!((px2(&a) - (50.0 + 100.0 / 3.0)).abs() < 0.05); // chords lose a little area
//!
//! // A stroke is one shape: 2 px wide, round joins. Two 10-px legs, less
//! // the 1-px square where they overlap at the corner, plus the round
//! // join (a quarter disc): the pieces tile, so the shoelace sum is the area.
//! let mut a = Area2::default();
//! let style = StrokeStyle::new(2048).with_join(LineJoin::Round);
//! SvgPath::new("M 0 0 h 10 v 10").unwrap().stroke(&style, &mut a).unwrap();
//! assert!((px2(&a) - (39.0 + core::f64::consts::PI / 4.0)).abs() < 0.01);
//! ```
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
//!   overlaps. A solid polyline's stroke (up to
//!   [`stroke::union::MAX_UNION_POINTS`] points) then gets its overlaps'
//!   intersections taken out and added back ([`stroke::union`]), so that
//!   its coverage is the union's within 1/256 a pixel; other strokes
//!   (closed polygons, dashes, curves, SVG paths, longer polylines) keep
//!   that over-coverage at their overlaps' edge pixels.
//!
//! ## Bounded work
//!
//! Every loop is bounded by the input: at most
//! [`MAX_CURVE_SEGMENTS`] (1024) segments per Bézier, [`MAX_ELLIPSE_SEGMENTS`]
//! (2048) per circle or ellipse, [`MAX_ARC_SEGMENTS`] (2048) per arc,
//! [`MAX_DASH_INTERVALS`] (65536) dash intervals per contour,
//! [`MAX_STROKE_WORK`] (16384) segments of dashes per stroke as charged
//! (whether a band builds them or steps over them); a solid stroke is
//! built at the finest tolerance (up to 4 096 times the one asked for,
//! 12 px) whose work, counted from its description, is within that budget,
//! and stops past twice it and 16 units a drawing command
//! ([`StrokeError::TooComplex`]; the units and the measured bound per
//! band are in `stroke/budget.rs`); a few dozen
//! steps per square root, angle or number. Radii are limited to
//! [`MAX_RADIUS`] (8192 px), stroke widths to [`MAX_STROKE_WIDTH`] (4096
//! px). Typical counts at the default tolerance: a circle of radius 1/2
//! px has 32 segments, 10 px 112, 100 px 352; a stroke emits about two
//! segments per flattened segment of its path plus its joins and caps.
//!
//! ## Per band
//!
//! A description is deterministic and cheap to repeat, so a band engine
//! may describe every shape again for every band, dropping what the band
//! does not need with a [`BandFilter`]; or keep its outline once in a
//! [`ShapeCache`](crate::canvas::ShapeCache) and walk the kept segments
//! per band.
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
mod buffer;
#[cfg(feature = "embedded-graphics")]
pub mod eg;
mod errors;
mod flattener;
pub mod segment;
pub(crate) mod shape;
pub mod stroke;
pub mod svg;
pub(crate) mod trig;
pub(crate) mod vector;

pub use angle::Degrees;
pub use arc::{MAX_ARC_SEGMENTS, MAX_ELLIPSE_SEGMENTS, MAX_RADIUS};
pub use bezier::MAX_CURVE_SEGMENTS;
pub(crate) use buffer::SegmentBuffer;
pub use buffer::{BandFilter, Segment};
pub use flattener::Flattener;
pub use segment::SegmentSink;
pub use shape::{
    Arc, Circle, CornerRadii, Ellipse, Line, Polygon, Polyline, Rectangle, RoundedRectangle,
    Sector, Shape, ShapeKey,
};
pub use stroke::{
    Dash, LineCap, LineJoin, MiterLimit, StrokeAlignment, StrokeError, StrokeStyle, Stroker,
    MAX_DASH_INTERVALS, MAX_STROKE_WIDTH, MAX_STROKE_WORK,
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

    /// A tolerance of `fine` units, at least 1 and not limited above: the
    /// stroker's own coarser tolerances for strokes past their budget
    /// (`stroke::budget`).
    pub(crate) const fn coarse(fine: u16) -> Self {
        if fine < Self::MIN.0 {
            Self::MIN
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

/// Sinks for the unit tests: what a description sent, summed; and the
/// random numbers they draw.
#[cfg(test)]
pub(crate) mod testing {
    extern crate std;
    use super::SegmentSink;
    use crate::geom::FinePoint;

    /// The 64-bit linear congruential generator the unit tests draw from
    /// (Knuth's MMIX constants): the same stream wherever it is seeded
    /// alike.
    pub struct Lcg(pub u64);

    impl Lcg {
        /// The next state.
        pub fn next_u64(&mut self) -> u64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            self.0
        }

        /// A number below `m` (`m > 0`) from the next state's top 31 bits.
        pub fn below(&mut self, m: u64) -> u64 {
            (self.next_u64() >> 33) % m
        }
    }

    /// Numbers segments as a band's walk cache would, within `window`
    /// (fine rows): each sent segment with its number; skipped ones count.
    pub struct Numbering {
        pub window: Option<(i32, i32)>,
        pub next: u32,
        pub segs: std::vec::Vec<(u32, FinePoint, FinePoint)>,
    }

    impl SegmentSink for Numbering {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            self.segs.push((self.next, a, b));
            self.next += 1;
        }
        fn window(&self) -> Option<(i32, i32)> {
            self.window
        }
        fn skipped(&mut self, n: u32) {
            self.next += n;
        }
    }

    /// Twice the signed area, the segment count and the balance of ends.
    #[derive(Debug, Default)]
    pub struct Tally {
        pub area2: i128,
        pub count: usize,
        pub balance: (i64, i64),
        pub out_of_range: bool,
    }

    impl Tally {
        /// The area in px^2.
        pub fn px2(&self) -> f64 {
            self.area2 as f64 / 2.0 / (1024.0 * 1024.0)
        }

        /// Closed contours (ends balance) all in range.
        pub fn closed(&self) -> bool {
            self.balance == (0, 0) && !self.out_of_range
        }
    }

    impl SegmentSink for Tally {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            self.area2 += i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y);
            self.count += 1;
            self.balance.0 += i64::from(b.x) - i64::from(a.x);
            self.balance.1 += i64::from(b.y) - i64::from(a.y);
            self.out_of_range |= !a.in_range() || !b.in_range() || a == b;
        }
    }
}
