//! [`Polyline`] and [`Line`]: open paths of straight segments.

use crate::geom::{FinePoint, PathSink};
use crate::path::segment::SegmentSink;
use crate::path::{StrokeAlignment, StrokeError, StrokeStyle, Stroker, Tolerance};

use super::Shape;

/// An open path through `vertices`: any point type that converts to
/// [`FinePoint`] (embedded-graphics' `Point`s convert to their pixel
/// centres). Filled, it is the polygon (closed by its last edge). Its
/// stroke is always centred: an open path has no inside (embedded-graphics
/// ignores the alignment of open shapes too; the [`Stroker`] offers
/// one-sided strokes of any path).
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::Polyline;
/// let pts = [FinePoint::new(0, 0), FinePoint::new(4096, 0), FinePoint::new(4096, 4096)];
/// let p = Polyline::new(&pts);
/// assert_eq!(p.vertices.len(), 3);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Polyline<'a, P = FinePoint> {
    /// An offset added to every vertex (embedded-graphics' `translate`).
    pub translate: FinePoint,
    /// The vertices, in order.
    pub vertices: &'a [P],
}

impl<'a, P: Copy + Into<FinePoint>> Polyline<'a, P> {
    /// A polyline through `vertices`.
    pub const fn new(vertices: &'a [P]) -> Self {
        Self {
            translate: FinePoint::new(0, 0),
            vertices,
        }
    }
}

impl<P: Copy + Into<FinePoint>> Shape for Polyline<'_, P> {
    fn describe<S: PathSink + ?Sized>(&self, sink: &mut S) {
        let t = self.translate;
        let mut it = self.vertices.iter().map(|&p| {
            let p: FinePoint = p.into();
            FinePoint::new(p.x.saturating_add(t.x), p.y.saturating_add(t.y))
        });
        if let Some(first) = it.next() {
            sink.move_to(first);
            for p in it {
                sink.line_to(p);
            }
        }
    }

    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        centred_stroke(self, style, tol, sink)
    }
}

/// Strokes an open shape, centred whatever the style's alignment.
fn centred_stroke<T: Shape + ?Sized, S: SegmentSink + ?Sized>(
    shape: &T,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    sink: &mut S,
) -> Result<(), StrokeError> {
    let style = style.with_alignment(StrokeAlignment::Centre);
    let mut s = Stroker::with_tolerance(&style, tol, sink);
    shape.describe(&mut s);
    s.finish()
}

/// A straight line between two points (no interior: its fill is empty;
/// its stroke is centred, as for [`Polyline`]).
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::Line;
/// let l = Line::new(FinePoint::new(0, 0), FinePoint::new(4096, 1024));
/// assert_eq!(l.end, FinePoint::new(4096, 1024));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Line {
    /// Where the line starts.
    pub start: FinePoint,
    /// Where it ends.
    pub end: FinePoint,
}

impl Line {
    /// The line from `start` to `end`.
    pub const fn new(start: FinePoint, end: FinePoint) -> Self {
        Self { start, end }
    }
}

impl Shape for Line {
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        sink.move_to(self.start);
        sink.line_to(self.end);
    }

    /// Nothing: a line has no area.
    fn fill_with<S: SegmentSink + ?Sized>(&self, _tol: Tolerance, _sink: &mut S) {}

    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        centred_stroke(self, style, tol, sink)
    }
}

/// A closed polygon through `vertices` (embedded-graphics' `Triangle` is
/// one): filled by the fill rule, its stroke closed, with joins at every
/// vertex. Described clockwise on screen whatever the order of the
/// vertices (a counter-clockwise list is described backwards), so an
/// inside or outside stroke lies inside or outside.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Polygon, StrokeAlignment, StrokeStyle, Shape, SegmentSink};
/// # #[derive(Default)] struct Area2(i64);
/// # impl SegmentSink for Area2 { fn segment(&mut self, a: FinePoint, b: FinePoint) {
/// #     self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y); } }
/// let p = |x, y| FinePoint::from_px(x, y);
/// // Counter-clockwise on screen; the inside stroke stays inside anyway.
/// let square = [p(0, 0), p(0, 10), p(10, 10), p(10, 0)];
/// let mut a = Area2::default();
/// let inside = StrokeStyle::new(1024).with_alignment(StrokeAlignment::Inside);
/// Polygon::new(&square).stroke(&inside, &mut a).unwrap();
/// assert_eq!(a.0, 2 * (100 - 64) * 1024 * 1024);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Polygon<'a, P = FinePoint> {
    /// An offset added to every vertex.
    pub translate: FinePoint,
    /// The vertices, in order.
    pub vertices: &'a [P],
}

impl<'a, P: Copy + Into<FinePoint>> Polygon<'a, P> {
    /// The polygon through `vertices`.
    pub const fn new(vertices: &'a [P]) -> Self {
        Self {
            translate: FinePoint::new(0, 0),
            vertices,
        }
    }

    fn vertex(&self, p: P) -> FinePoint {
        let p: FinePoint = p.into();
        FinePoint::new(
            p.x.saturating_add(self.translate.x),
            p.y.saturating_add(self.translate.y),
        )
    }

    /// Twice the signed area (positive: clockwise on screen, y down).
    fn area2(&self) -> i128 {
        let n = self.vertices.len();
        let mut a = 0i128;
        for (k, &v) in self.vertices.iter().enumerate() {
            let (p, q) = (self.vertex(v), self.vertex(self.vertices[(k + 1) % n]));
            a += i128::from(p.x) * i128::from(q.y) - i128::from(q.x) * i128::from(p.y);
        }
        a
    }
}

impl<P: Copy + Into<FinePoint>> Shape for Polygon<'_, P> {
    fn describe<S: PathSink + ?Sized>(&self, sink: &mut S) {
        if self.vertices.is_empty() {
            return;
        }
        let mut emit = |k: usize, first: bool| {
            let p = self.vertex(self.vertices[k]);
            if first {
                sink.move_to(p);
            } else {
                sink.line_to(p);
            }
        };
        let n = self.vertices.len();
        if self.area2() >= 0 {
            (0..n).for_each(|k| emit(k, k == 0));
        } else {
            (0..n).rev().for_each(|k| emit(k, k == n - 1));
        }
        sink.close();
    }
}
