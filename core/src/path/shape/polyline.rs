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
