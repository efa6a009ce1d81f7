//! Strokes: a path's outline widened into one fillable shape.
//!
//! Takes a path through [`PathSink`] (the [`Stroker`]) and a
//! [`StrokeStyle`] (width in fine units down to hairlines, joins: miter
//! with a miter limit, round, bevel; caps: butt, round, square; dashes;
//! alignment for closed outlines); gives a [`SegmentSink`] closed contours
//! whose **nonzero** fill is exactly the stroke, every piece clockwise, so
//! the winding number is never negative (see [`outline`] for the sum of
//! pieces and the tiling at inner corners).
//!
//! ## Method
//!
//! 1. Each contour is cut into *pieces*: a straight segment gives one
//!    rectangle; a curve is flattened as in [`bezier`](crate::path::bezier)
//!    (with extra segments for wide strokes, so that the offset curve is
//!    within the tolerance too: see `bezier::offset_count`) and each chord gives a
//!    quadrilateral between the curve's true normals at its two vertices.
//!    Where that quadrilateral would fold (the stroke is wider than the
//!    curve's radius, or a cusp), the chord's rectangle is used instead and
//!    joined to its neighbours by round joins: the stroke of a curve is the
//!    union of discs along it.
//! 2. With a dash pattern, the pieces are cut into dashes ([`dash`]).
//! 3. Runs of pieces get joins between them and caps at their ends
//!    ([`outline`]).
//! 4. A [`Polyline`](crate::path::Polyline)'s or a centred
//!    [`Polygon`](crate::path::Polygon)'s stroke (solid, up to
//!    [`union::MAX_UNION_POINTS`] points) then gets the intersections of
//!    its overlapping pieces subtracted and added back ([`union`]): the
//!    edge engine applies the nonzero rule to each pixel's *mean* winding
//!    number, so where the stroke overlaps itself (crossings, short
//!    segments, U-turns) the sum alone covers the pixels along the
//!    overlap's border too much; the union covers each within 1/256.
//!
//! ## Cases handled
//!
//! - Zero-length segments and coincident points are skipped; a contour
//!   with a drawing command but no length (`M x y Z`, `M x y L x y`) is a
//!   dot: a disc (round caps), an axis-aligned square (square caps),
//!   nothing (butt), as SVG specifies. A lone `move_to` draws nothing.
//! - 180-degree turns: a round join is a half disc, bevel and miter (the
//!   miter is infinitely long, always beyond the limit) end flat.
//! - Cusps of curves: round, from the round joins between chords.
//! - Closed contours join their last piece to their first; open ones get
//!   caps. Dashes restart on every contour; on a closed contour a dash
//!   through the start point is one dash.
//! - Very short dashes and gaps, zero-length dashes (dots), patterns of
//!   zeros (solid): see [`dash`].
//! - Coordinates far outside the range: the path is clipped to the square
//!   of half side `2^24` fine units (16384 px) before it is stroked (the
//!   parts beyond are replaced by their clamped images, which lie more
//!   than 8192 px outside the coordinate range: the stroke inside the
//!   range is unchanged for widths up to [`MAX_STROKE_WIDTH`]).
//!
//! ## Accuracy
//!
//! Offset edges connect points that are exact offsets of the path (to
//! the grid rounding), as chords of the offset curve within the
//! tolerance; joins and caps are area-preserving arcs ([`arc`](crate::path::arc)).
//! So the stroke outline is within `tol + 0.71` fine units of the exact
//! one for straight paths, and for curves wherever the stroke is
//! narrower than twice the radius of curvature. A shape's stroke that
//! would cost more than its work budget is built at a coarser `tol`
//! (`stroke/budget.rs`: only strokes thousands of pixels wide or curves across
//! the whole range come near it).
//!
//! ## Alignment
//!
//! [`StrokeAlignment::Centre`] puts half the width on each side;
//! `Inside` puts all of it on the right of the direction of travel (on
//! screen, y down), which is the inside of every closed shape in
//! [`path`](crate::path) (they run clockwise), `Outside` on the left.
//! Alignment applies to any contour; embedded-graphics applies it to
//! closed shapes (and arcs) only, and the conversions follow that.

pub(crate) mod budget;
pub mod dash;
pub mod outline;
pub mod union;
pub(crate) mod windowed;

use crate::geom::{FinePoint, PathSink};

use super::bezier::{
    cubic_at, cubic_count, cubic_tangent, offset_count, quad_at, quad_count, quad_tangent,
    turn_count,
};
use super::segment::{clip_to_square, SegmentSink};
use super::trig::atan2;
use super::vector::{Pt, Unit};
use super::Tolerance;

use dash::Dasher;
pub use dash::{Dash, MAX_DASH_INTERVALS, MAX_STROKE_WORK};
use outline::{JoinKind, Outline, Piece, Sides};

/// The widest stroke, `2^22` fine units (4096 px); wider ones are limited
/// to it.
pub const MAX_STROKE_WIDTH: u32 = 1 << 22;

/// Half side of the square the stroker clips its input to, fine units.
const STROKE_BOX: i64 = 1 << 24;

/// How two segments of a stroke meet at a vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LineJoin {
    /// The outer edges extended until they meet, unless the miter is
    /// longer than [`MiterLimit`] allows, then [`Bevel`](Self::Bevel) (SVG's
    /// `miter`; embedded-graphics' polylines behave so with a limit of 4).
    #[default]
    Miter,
    /// A circular arc about the vertex.
    Round,
    /// The outer corners joined by a straight edge.
    Bevel,
}

/// How an open contour (or a dash) ends.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LineCap {
    /// Flat, at the end point (embedded-graphics' lines and polylines).
    #[default]
    Butt,
    /// A half disc beyond the end point.
    Round,
    /// A half square beyond the end point.
    Square,
}

/// Where a stroke lies across its path.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Circle, SegmentSink, Shape, StrokeAlignment, StrokeStyle};
/// # #[derive(Default)] struct Area2(i64);
/// # impl SegmentSink for Area2 { fn segment(&mut self, a: FinePoint, b: FinePoint) {
/// #     self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y); } }
/// // A 1-px stroke inside a circle of radius 10 px: the ring from 9 to 10 px.
/// let mut a = Area2::default();
/// let inside = StrokeStyle::new(1024).with_alignment(StrokeAlignment::Inside);
/// Circle::new(FinePoint::new(0, 0), 10 * 1024).stroke(&inside, &mut a).unwrap();
/// let px2 = a.0 as f64 / 2.0 / (1024.0 * 1024.0);
/// assert!((px2 / (core::f64::consts::PI * 19.0) - 1.0).abs() < 1e-3);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StrokeAlignment {
    /// Half on each side.
    #[default]
    Centre,
    /// All on the right of the direction of travel: inside a clockwise
    /// outline.
    Inside,
    /// All on the left: outside a clockwise outline.
    Outside,
}

/// The limit on miter joins: the longest allowed ratio of the miter's
/// length (outer tip to inner corner) to the stroke width, `1/sin(a/2)`
/// for an angle `a` between the segments (SVG's `stroke-miterlimit`), in
/// Q16. Below the limit the join is beveled.
///
/// ```
/// use softedge::path::MiterLimit;
/// assert_eq!(MiterLimit::DEFAULT, MiterLimit::from_int(4));
/// // A right angle needs sqrt(2) = 1.414...: allowed by 1.5, not by 1.4.
/// assert!(MiterLimit::from_q16(3 << 15).allows_angle_degrees(90));
/// assert!(!MiterLimit::from_q16(14 << 16 / 10).allows_angle_degrees(90));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct MiterLimit(u32);

impl MiterLimit {
    /// 4, SVG's default (embedded-graphics' polylines bevel at the same
    /// ratio: a miter longer than twice the width).
    pub const DEFAULT: MiterLimit = MiterLimit(4 << 16);

    /// A limit of `ratio` (whole number).
    pub const fn from_int(ratio: u16) -> Self {
        MiterLimit((ratio as u32) << 16)
    }

    /// A limit in Q16 (`65536` = 1: every miter beveled).
    pub const fn from_q16(ratio: u32) -> Self {
        MiterLimit(ratio)
    }

    /// True when a miter is drawn where the unit normals before and after
    /// the vertex have the dot product `dot` (Q30): `L^2 (1 + dot) >= 2`.
    ///
    /// In 32x32-bit products (a `u128` product is several library calls on
    /// the Cortex-M0): `L^2 = h 2^32 + l`, and `L^2 (1 + dot) = h (1 + dot)
    /// 2^32 + l (1 + dot)` is at least `2^63` when `h (1 + dot) >= 2^31`;
    /// else the sum is taken in `u64`, saturating (a sum past `2^64` is
    /// past `2^63` too).
    pub(crate) fn allows(self, dot_q30: i64) -> bool {
        use crate::arith::mul_wide;
        let l2 = mul_wide(self.0, self.0); // Q32
                                           // The dot product of unit vectors is at most 2^30 and a little:
                                           // 1 + dot fits in u32 (capped beyond, where every limit allows).
        let one_plus = (dot_q30 + (1 << 30)).clamp(0, i64::from(u32::MAX)) as u32; // Q30
        let (h, l) = ((l2 >> 32) as u32, l2 as u32);
        let high = mul_wide(h, one_plus);
        if high >= 1 << 31 {
            return true;
        }
        (high << 32).saturating_add(mul_wide(l, one_plus)) >= 1 << 63
    }

    /// The limit in Q16.
    pub const fn to_q16(self) -> u32 {
        self.0
    }

    /// True when a miter is drawn between two segments meeting at
    /// `degrees` (the angle between them: 180 is straight on).
    pub fn allows_angle_degrees(self, degrees: i32) -> bool {
        // The turn is 180 - a; the normals' dot product is cos(turn).
        let turn = super::Degrees::new(180 - degrees).binary();
        let (c, _) = super::trig::cos_sin(turn as u32);
        self.allows(c)
    }
}

impl Default for MiterLimit {
    fn default() -> Self {
        Self::DEFAULT
    }
}

/// Why a stroke is incomplete.
///
/// ```
/// use softedge::path::StrokeError;
/// let e = StrokeError::TooManyDashes;
/// assert!(format!("{e}").contains("65536"));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum StrokeError {
    /// A contour stepped through more than [`MAX_DASH_INTERVALS`] dash
    /// pattern intervals; the rest of that contour was not stroked.
    TooManyDashes,
    /// The stroke's dashes would build more than [`MAX_STROKE_WORK`]
    /// segments (each dash charged its caps and body, whether or not it
    /// meets the band being drawn, so every band stops at the same dash),
    /// or a solid stroke built more than twice that and 16 a drawing
    /// command (`stroke::budget`: a shape's stroke is first fitted to the
    /// budget with a coarser tolerance, so this takes a description the
    /// fitting could not bring within it); the rest of the stroke was not
    /// stroked.
    TooComplex,
}

impl core::fmt::Display for StrokeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StrokeError::TooManyDashes => write!(
                f,
                "dash pattern too fine: more than {MAX_DASH_INTERVALS} intervals in one contour"
            ),
            StrokeError::TooComplex => write!(
                f,
                "stroke too complex: more than its budget of {MAX_STROKE_WORK} segments of dashes, or of twice that and 16 a drawing command"
            ),
        }
    }
}

/// How to stroke: width, joins, caps, dashes, alignment.
///
/// ```
/// use softedge::path::{Dash, LineCap, LineJoin, StrokeStyle};
/// let pattern = [4096, 2048];
/// let style = StrokeStyle::new(1536) // 1.5 px
///     .with_join(LineJoin::Round)
///     .with_cap(LineCap::Square)
///     .with_dash(Dash::new(&pattern, 0));
/// assert_eq!(style.width, 1536);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct StrokeStyle<'d> {
    /// Width in fine units (1/1024 px); 0 strokes nothing; at most
    /// [`MAX_STROKE_WIDTH`].
    pub width: u32,
    /// Joins at the path's vertices.
    pub join: LineJoin,
    /// The limit of miter joins.
    pub miter_limit: MiterLimit,
    /// Caps at the ends of open contours and dashes.
    pub cap: LineCap,
    /// Dash pattern, `None` for a solid stroke.
    pub dash: Option<Dash<'d>>,
    /// Which side of the path the stroke lies on.
    pub alignment: StrokeAlignment,
}

impl<'d> StrokeStyle<'d> {
    /// How far, at most, the stroke reaches from its path, in fine units:
    /// the whole width (one-sided alignment) times the longest a join or
    /// cap makes it (the miter limit, or the square cap's √2 < 1.5).
    pub fn reach(&self) -> i64 {
        let limit = match self.join {
            LineJoin::Miter => u64::from(self.miter_limit.to_q16()).max(3 << 15),
            _ => 3 << 15,
        };
        ((u64::from(self.width) * limit) >> 16) as i64 + 2
    }

    /// A solid stroke of `width` fine units, miter joins (limit 4), butt
    /// caps, centred: SVG's defaults.
    pub const fn new(width: u32) -> Self {
        Self {
            width,
            join: LineJoin::Miter,
            miter_limit: MiterLimit::DEFAULT,
            cap: LineCap::Butt,
            dash: None,
            alignment: StrokeAlignment::Centre,
        }
    }

    /// The same with another join.
    pub const fn with_join(mut self, join: LineJoin) -> Self {
        self.join = join;
        self
    }

    /// The same with another miter limit.
    pub const fn with_miter_limit(mut self, limit: MiterLimit) -> Self {
        self.miter_limit = limit;
        self
    }

    /// The same with another cap.
    pub const fn with_cap(mut self, cap: LineCap) -> Self {
        self.cap = cap;
        self
    }

    /// The same, dashed.
    pub const fn with_dash<'e>(self, dash: Dash<'e>) -> StrokeStyle<'e> {
        StrokeStyle {
            width: self.width,
            join: self.join,
            miter_limit: self.miter_limit,
            cap: self.cap,
            dash: Some(dash),
            alignment: self.alignment,
        }
    }

    /// The same with another alignment.
    pub const fn with_alignment(mut self, alignment: StrokeAlignment) -> Self {
        self.alignment = alignment;
        self
    }

    /// The reach on each side, in half fine units.
    pub(crate) fn sides(&self) -> Sides {
        let w = i64::from(self.width.min(MAX_STROKE_WIDTH));
        match self.alignment {
            StrokeAlignment::Centre => Sides { m: w, p: w },
            StrokeAlignment::Inside => Sides { m: 0, p: 2 * w },
            StrokeAlignment::Outside => Sides { m: 2 * w, p: 0 },
        }
    }

    /// The reach `(outside, inside)` of the stroke of a clockwise closed
    /// outline, in half fine units.
    pub(crate) fn reach_q1(&self) -> (i64, i64) {
        let s = self.sides();
        (s.m, s.p)
    }
}

/// Strokes a path: a [`PathSink`] whose output is the stroke's outline.
///
/// It counts its work as it goes (segments sent or left out, and the
/// set-ups of pieces and arcs) and stops a solid stroke past twice
/// [`MAX_STROKE_WORK`] and 16 units a drawing command
/// ([`StrokeError::TooComplex`] from [`finish`](Self::finish)); a shape's
/// [`stroke_with`](crate::path::Shape::stroke_with) first fits its
/// tolerance so that it stays within [`MAX_STROKE_WORK`].
///
/// ```
/// use softedge::geom::{FinePoint, PathSink};
/// use softedge::path::{LineCap, SegmentSink, StrokeStyle, Stroker};
///
/// #[derive(Default)]
/// struct Area2(i64);
/// impl SegmentSink for Area2 {
///     fn segment(&mut self, a: FinePoint, b: FinePoint) {
///         self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
///     }
/// }
/// let mut area = Area2::default();
/// let style = StrokeStyle::new(2048).with_cap(LineCap::Square); // 2 px
/// let mut s = Stroker::new(&style, &mut area);
/// s.move_to(FinePoint::new(0, 0));
/// s.line_to(FinePoint::new(10 * 1024, 0));
/// s.finish().unwrap();
/// // 10 px long plus 1 px of cap at each end, 2 px wide: 24 px^2.
/// assert_eq!(area.0, 2 * 24 * 1024 * 1024);
/// ```
pub struct Stroker<'s, 'd, S: SegmentSink + ?Sized> {
    outline: Outline<'s, S>,
    dasher: Option<Dasher<'d>>,
    sides: Sides,
    tol: Tolerance,
    start: Pt,
    current: Pt,
    /// A contour is open.
    open: bool,
    /// It has had a drawing command.
    drawn: bool,
    /// It has had a piece.
    pieced: bool,
    /// The width is zero: nothing is drawn.
    empty: bool,
    /// How far the stroke reaches from its path (caps, joins), fine units.
    reach: i64,
    /// The work a solid stroke may do ([`budget::limit`] of its drawing
    /// commands so far), and whether it went past it (the rest is not
    /// stroked).
    limit: u32,
    too_complex: bool,
    /// No dashes.
    solid: bool,
}

impl<'s, 'd, S: SegmentSink + ?Sized> Stroker<'s, 'd, S> {
    /// A stroker with the default tolerance.
    pub fn new(style: &StrokeStyle<'d>, sink: &'s mut S) -> Self {
        Self::with_tolerance(style, Tolerance::DEFAULT, sink)
    }

    /// A stroker whose curves, offsets and round parts stay within `tol`
    /// (plus the grid rounding).
    pub fn with_tolerance(style: &StrokeStyle<'d>, tol: Tolerance, sink: &'s mut S) -> Self {
        let sides = style.sides();
        let outline = Outline::new(sink, style.join, style.miter_limit, style.cap, sides, tol);
        // A dash is charged its two caps and a body (two offset edges and
        // the two segments of an inner corner); its caps, dots and joins
        // reach at most the style's reach beyond its path.
        let dash_cost = 2 * outline.cap_cost() + 4;
        let reach = style.reach();
        let dasher = style.dash.and_then(|d| Dasher::new(d, dash_cost, reach));
        Self {
            outline,
            solid: dasher.is_none(),
            dasher,
            sides,
            tol,
            start: Pt::default(),
            current: Pt::default(),
            open: false,
            drawn: false,
            pieced: false,
            empty: sides.width() == 0,
            reach,
            limit: budget::limit(0),
            too_complex: false,
        }
    }

    /// Ends the last contour (open: caps); reports a dash pattern that
    /// was cut short. Dropping the stroker ends the contour too, without
    /// the report.
    pub fn finish(mut self) -> Result<(), StrokeError> {
        self.end_contour(false);
        match self.dasher.as_ref().and_then(Dasher::error) {
            Some(e) => Err(e),
            None if self.too_complex => Err(StrokeError::TooComplex),
            None => Ok(()),
        }
    }

    fn end_contour(&mut self, closed: bool) {
        if !self.open {
            return;
        }
        self.open = false;
        if self.pieced {
            match self.dasher.as_mut() {
                Some(d) => d.end_contour(closed, &mut self.outline),
                None => self.outline.end_contour(closed),
            }
        } else if self.drawn && !self.too_complex {
            let show = self.dasher.as_mut().is_none_or(Dasher::starts_on);
            if show {
                self.outline.dot(self.start);
            }
        }
        self.pieced = false;
        self.drawn = false;
    }

    fn begin_drawing(&mut self) {
        self.limit = self.limit.saturating_add(budget::WORK_PER_COMMAND);
        if !self.open {
            // A drawing command without move_to: a contour from the last
            // point (after `close`, the closed contour's start).
            self.start = self.current;
            self.open = true;
        }
        self.drawn = true;
    }

    /// The next piece of the contour.
    fn feed(&mut self, mut p: Piece, join: JoinKind) {
        p.quiet = dash::misses(&p, self.outline.window(), self.reach);
        if !self.pieced {
            self.pieced = true;
            match self.dasher.as_mut() {
                Some(d) => d.begin_contour(&mut self.outline),
                None => self.outline.begin_run(true),
            }
        }
        match self.dasher.as_mut() {
            Some(d) => d.piece(p, join, &mut self.outline),
            None => self.outline.piece(p, join),
        }
    }

    /// True when a solid stroke has done more work than a description of
    /// its drawing commands so far may cost ([`budget::limit`]; dashes
    /// have their own budget): the rest is not stroked.
    #[inline(always)]
    fn stopped(&mut self) -> bool {
        if !self.too_complex && self.solid {
            self.too_complex = self.outline.work() > self.limit;
        }
        self.too_complex
    }

    /// A straight segment, clipped to the stroke box.
    fn straight(&mut self, a: Pt, b: Pt, join: JoinKind) {
        if self.stopped() {
            return;
        }
        let inside = |p: Pt| p.x.abs() <= STROKE_BOX && p.y.abs() <= STROKE_BOX;
        if inside(a) && inside(b) {
            if let Some(p) = Piece::straight(a, b, self.sides) {
                self.feed(p, join);
            }
            return;
        }
        let mut join = join;
        let sides = self.sides;
        clip_to_square(a, b, STROKE_BOX, |p, q| {
            if let Some(piece) = Piece::straight(p, q, sides) {
                self.feed(piece, join);
                join = JoinKind::Curve;
            }
        });
    }

    /// A flattened curve: `n` vertices from `at`, tangents from `tangent`.
    fn curve(&mut self, n: u32, at: impl Fn(u32) -> Pt, tangent: impl Fn(u32) -> Pt) {
        let mut prev = at(0);
        let mut prev_t = tangent(0).unit();
        let mut join = JoinKind::Path;
        for k in 1..=n {
            if self.stopped() {
                return;
            }
            let v = at(k);
            let t = tangent(k).unit();
            if v == prev {
                prev_t = t;
                continue;
            }
            let inside = |p: Pt| p.x.abs() <= STROKE_BOX && p.y.abs() <= STROKE_BOX;
            if !(inside(prev) && inside(v)) {
                self.straight(prev, v, join);
            } else if let Some(p) = self.curve_piece(prev, v, prev_t, t) {
                self.feed(p, join);
            }
            join = JoinKind::Curve;
            prev = v;
            prev_t = t;
        }
    }

    /// The piece of a chord `a -> b` of a curve whose unit tangents there
    /// are `ta`, `tb`: between the true normals if that is a valid piece,
    /// else the chord's rectangle.
    fn curve_piece(&self, a: Pt, b: Pt, ta: Option<Unit>, tb: Option<Unit>) -> Option<Piece> {
        let chord = b.sub(a).unit()?;
        if let (Some(ta), Some(tb)) = (ta, tb) {
            if ta.dot(chord) > 0 && tb.dot(chord) > 0 {
                let p = Piece::new(a, b, ta.right(), tb.right(), self.sides);
                if p.is_convex() {
                    return Some(p);
                }
            }
        }
        // `Piece::straight(a, b)`, its unit vector already known.
        let n = chord.right();
        Some(Piece::new(a, b, n, n, self.sides))
    }

    /// Half the widest reach, fine units (for the extra curve segments).
    fn half_width(&self) -> i64 {
        self.sides.m.max(self.sides.p) / 2
    }
}

/// Strokes `shape`'s description with `style` within `tol`, or within the
/// coarser tolerance that keeps the stroke within its work budget
/// ([`budget`]): what [`Shape::stroke_with`](crate::path::Shape::stroke_with)
/// does wherever it goes through the [`Stroker`].
pub(crate) fn stroke_described<T, S>(
    shape: &T,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    sink: &mut S,
) -> Result<(), StrokeError>
where
    T: crate::path::Shape + ?Sized,
    S: SegmentSink + ?Sized,
{
    let tol = budget::fitted(shape, style, tol);
    let mut s = Stroker::with_tolerance(style, tol, sink);
    shape.describe(&mut s);
    s.finish()
}

/// The total turning of a control polygon's legs, binary units: the sum
/// of the angles between consecutive non-zero legs.
fn legs_turning(legs: &[Pt]) -> u64 {
    let mut total = 0u64;
    let mut prev: Option<u32> = None;
    for l in legs.iter().filter(|l| !l.is_zero()) {
        let a = atan2(l.y, l.x);
        if let Some(p) = prev {
            total += u64::from((a.wrapping_sub(p) as i32).unsigned_abs());
        }
        prev = Some(a);
    }
    total
}

impl<S: SegmentSink + ?Sized> Drop for Stroker<'_, '_, S> {
    fn drop(&mut self) {
        self.end_contour(false);
    }
}

impl<S: SegmentSink + ?Sized> PathSink for Stroker<'_, '_, S> {
    fn move_to(&mut self, p: FinePoint) {
        self.end_contour(false);
        self.start = p.into();
        self.current = self.start;
        self.open = !self.empty;
        self.drawn = false;
    }

    fn line_to(&mut self, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        let p = Pt::from(p);
        self.straight(self.current, p, JoinKind::Path);
        self.current = p;
    }

    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        let q = [self.current, Pt::from(c), Pt::from(p)];
        let turn = legs_turning(&[q[1].sub(q[0]), q[2].sub(q[1])]);
        let n = offset_count(
            quad_count(&q, i64::from(self.tol.fine())),
            turn_count(turn, self.half_width(), i64::from(self.tol.fine())),
        );
        self.curve(n, |k| quad_at(&q, k, n), |k| quad_tangent(&q, k, n));
        self.current = q[2];
    }

    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        let q = [self.current, Pt::from(c1), Pt::from(c2), Pt::from(p)];
        let turn = legs_turning(&[q[1].sub(q[0]), q[2].sub(q[1]), q[3].sub(q[2])]);
        let n = offset_count(
            cubic_count(&q, i64::from(self.tol.fine())),
            turn_count(turn, self.half_width(), i64::from(self.tol.fine())),
        );
        self.curve(n, |k| cubic_at(&q, k, n), |k| cubic_tangent(&q, k, n));
        self.current = q[3];
    }

    fn close(&mut self) {
        // `close` with no contour open (`Z` after `Z`) does nothing.
        if self.empty || !self.open {
            return;
        }
        self.drawn = true;
        self.limit = self.limit.saturating_add(budget::WORK_PER_COMMAND);
        if self.current != self.start {
            self.straight(self.current, self.start, JoinKind::Path);
        }
        self.current = self.start;
        self.end_contour(true);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::testing::Tally;

    /// The miter test in 32-bit products against the formula in `u128`.
    #[test]
    fn the_miter_limit_test_is_the_formula_in_full() {
        extern crate std;
        let mut rng = crate::path::testing::Lcg(0x31e7_e411_0c0f_5eed);
        let formula = |l: u32, dot: i64| {
            let l2 = u128::from(l) * u128::from(l);
            let one_plus = (dot + (1 << 30)).max(0) as u128;
            l2 * one_plus >= 2u128 << 62
        };
        let limits = [0, 1, 1 << 16, 92_681, 92_682, 4 << 16, 10 << 16, u32::MAX];
        let dots = [
            -(1i64 << 30) - 3,
            -(1 << 30),
            0,
            1 << 29,
            (1 << 30) - 1,
            1 << 30,
            (1 << 30) + 2,
        ];
        let mut cases = std::vec::Vec::new();
        for &l in &limits {
            for &d in &dots {
                cases.push((l, d));
            }
        }
        for _ in 0..200_000 {
            let l = (rng.below(1 << 32) as u32) >> rng.below(32);
            let d = rng.below(1 << 31) as i64 - (1 << 30) + rng.below(3) as i64;
            cases.push((l, d));
            // At the threshold: the smallest dot the limit allows, and
            // one below it.
            let l2 = u128::from(l) * u128::from(l);
            if l2 > 0 {
                let t = ((1u128 << 63).div_ceil(l2)).min(1 << 40) as i64 - (1 << 30);
                cases.push((l, t));
                cases.push((l, t - 1));
            }
        }
        for (l, d) in cases {
            if d + (1 << 30) > i64::from(u32::MAX) {
                continue;
            }
            assert_eq!(MiterLimit(l).allows(d), formula(l, d), "{l} {d}");
        }
    }

    fn p(x: i32, y: i32) -> FinePoint {
        FinePoint::new(x * 1024, y * 1024)
    }

    fn run(style: &StrokeStyle<'_>, f: impl FnOnce(&mut Stroker<'_, '_, Tally>)) -> Tally {
        let mut t = Tally::default();
        {
            let mut s = Stroker::new(style, &mut t);
            f(&mut s);
            s.finish().unwrap_or(());
        }
        t
    }

    #[test]
    fn zero_length_segments_and_coincident_points_change_nothing() {
        let st = StrokeStyle::new(2048);
        let plain = run(&st, |s| {
            s.move_to(p(0, 0));
            s.line_to(p(10, 0));
            s.line_to(p(10, 10));
        });
        let doubled = run(&st, |s| {
            s.move_to(p(0, 0));
            s.line_to(p(0, 0));
            s.line_to(p(10, 0));
            s.line_to(p(10, 0));
            s.quad_to(p(10, 0), p(10, 0));
            s.line_to(p(10, 10));
        });
        assert_eq!(plain.area2, doubled.area2);
        assert!(plain.closed() && doubled.closed());
    }

    #[test]
    fn a_lone_move_and_nothing_open_draw_nothing() {
        let st = StrokeStyle::new(2048).with_cap(LineCap::Round);
        assert_eq!(run(&st, |s| s.move_to(p(3, 3))).count, 0);
        assert_eq!(run(&st, |s| s.close()).count, 0);
        let t = run(&StrokeStyle::new(0), |s| {
            s.move_to(p(0, 0));
            s.line_to(p(5, 5));
        });
        assert_eq!(t.count, 0);
    }

    #[test]
    fn a_u_turn_ends_flat_with_bevel_and_miter_and_round_with_round() {
        let uturn = |join| {
            run(&StrokeStyle::new(2048).with_join(join), |s| {
                s.move_to(p(0, 0));
                s.line_to(p(10, 0));
                s.line_to(p(0, 0));
            })
        };
        // The two bodies coincide: 10 x 2 px, covered twice (the union is
        // nonzero, the shoelace counts it twice).
        assert_eq!(uturn(LineJoin::Bevel).area2, 2 * 2 * 20 * 1024 * 1024);
        assert_eq!(uturn(LineJoin::Miter).area2, uturn(LineJoin::Bevel).area2);
        let round = uturn(LineJoin::Round);
        let extra = round.px2() - 40.0;
        assert!(
            (extra - core::f64::consts::PI / 2.0).abs() < 2e-3,
            "{extra}"
        );
        assert!(round.closed());
    }

    #[test]
    fn a_dot_is_a_disc_or_a_square_or_nothing() {
        let dot = |cap| {
            run(&StrokeStyle::new(2048).with_cap(cap), |s| {
                s.move_to(p(5, 5));
                s.close();
            })
        };
        assert!((dot(LineCap::Round).px2() - core::f64::consts::PI).abs() < 2e-3);
        assert_eq!(dot(LineCap::Square).area2, 2 * 4 * 1024 * 1024);
        assert_eq!(dot(LineCap::Butt).count, 0);
    }

    #[test]
    fn the_miter_limit_bevels_sharp_corners() {
        let corner = |limit| {
            run(&StrokeStyle::new(2048).with_miter_limit(limit), |s| {
                s.move_to(p(0, 0));
                s.line_to(p(10, 0));
                s.line_to(p(0, 3)); // a sharp turn back
            })
        };
        let sharp = corner(MiterLimit::from_int(100));
        let cut = corner(MiterLimit::from_int(1));
        assert!(sharp.area2 > cut.area2);
        assert!(sharp.closed() && cut.closed());
    }

    #[test]
    fn a_dashed_closed_contour_whose_last_gap_ends_at_the_start_keeps_its_first_dash() {
        // 40 px around, 4 on, 4 off from the start: the last gap, [36, 40),
        // ends exactly where the contour began, so the first dash (held
        // for a join that never comes) must get its start cap after all.
        // Offset 4 px: the mirror case, the contour starts in a gap and its
        // last dash, [36, 40), ends at the start with nothing held.
        let pattern = [4096];
        for offset in [0, 4096] {
            let st = StrokeStyle::new(1024).with_dash(Dash::new(&pattern, offset));
            let t = run(&st, |s| {
                s.move_to(p(0, 0));
                s.line_to(p(10, 0));
                s.line_to(p(10, 10));
                s.line_to(p(0, 10));
                s.close();
            });
            assert!(t.closed(), "offset {offset}");
            // Five dashes of 4 x 1 px, 4 px² each, those through a corner
            // too (the mitered outer square of 1/4 px² is the inner square
            // the legs share). Before the fix, offset 0 dropped the dash at
            // the start: 16 px² and an unclosed outline.
            assert_eq!(t.area2, 2 * 5 * 4 * 1024 * 1024, "offset {offset}");
        }
    }

    #[test]
    fn a_closed_contour_has_no_caps() {
        let sq = |cap| {
            run(&StrokeStyle::new(2048).with_cap(cap), |s| {
                s.move_to(p(0, 0));
                s.line_to(p(10, 0));
                s.line_to(p(10, 10));
                s.line_to(p(0, 10));
                s.close();
            })
        };
        assert_eq!(sq(LineCap::Butt).area2, sq(LineCap::Round).area2);
        // Miter corners: 12 x 12 minus 8 x 8.
        assert_eq!(sq(LineCap::Square).area2, 2 * (144 - 64) * 1024 * 1024);
    }
}
