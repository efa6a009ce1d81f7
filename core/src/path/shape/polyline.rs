//! [`Polyline`] and [`Line`]: open paths of straight segments.

use crate::arith::imul_wide;
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

    /// The line's vertices where it puts them: moved by `translate`.
    fn placed(&self) -> impl Fn(P) -> FinePoint {
        let t = self.translate;
        move |p| {
            let p: FinePoint = p.into();
            FinePoint::new(p.x.saturating_add(t.x), p.y.saturating_add(t.y))
        }
    }
}

impl<P: Copy + Into<FinePoint>> Shape for Polyline<'_, P> {
    fn key(&self) -> Option<super::ShapeKey> {
        super::ShapeKey::described(super::DescribedKind::Polyline, self)
    }

    fn key_reads_points(&self) -> bool {
        true
    }

    fn describe<S: PathSink + ?Sized>(&self, sink: &mut S) {
        let placed = self.placed();
        let mut it = self.vertices.iter().map(|&p| placed(p));
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
        let placed = self.placed();
        let at = |k: usize| {
            self.vertices
                .get(k)
                .map_or(FinePoint::new(0, 0), |&p| placed(p))
        };
        if crate::path::stroke::windowed::polyline(self.vertices.len(), at, style, tol, sink) {
            return Ok(());
        }
        // Fitted to the work budget once, for the stroke and its union.
        let tol = fitted(self, style, tol, self.vertices.len());
        // An error (stopped past its work limit, which a polyline fitted
        // to the budget never reaches): no union for pieces not drawn.
        centred_stroke(self, style, tol, sink)?;
        // Where the stroke overlaps itself: the union, not the sum.
        let points = self.vertices.iter().map(|&p| placed(p).into());
        crate::path::stroke::union::polyline_union(points, style, tol, false, sink);
        Ok(())
    }
}

/// The tolerance for a stroke of `shape`, `commands` straight drawing
/// commands, within its work budget (`stroke::budget`): `tol` without a
/// pass over its points where so few are plainly within it.
fn fitted<T: Shape + ?Sized>(
    shape: &T,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    commands: usize,
) -> Tolerance {
    use crate::path::stroke::budget;
    if budget::plainly_within(style, tol, commands) {
        tol
    } else {
        budget::fitted(shape, style, tol)
    }
}

/// Strokes an open shape, centred whatever the style's alignment, within
/// `tol` (already fitted to the work budget: `stroke::budget`).
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
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

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
        let tol = fitted(self, style, tol, 1);
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
    /// Every shape's description runs it, in every band: the products are
    /// `i32 x i32` in full ([`imul_wide`]: four 32-bit multiplies; an
    /// `i128` product is several 64-bit library calls on the Cortex-M0),
    /// summed in `i128`, and the closing edge is taken last instead of
    /// wrapping an index (a division per vertex).
    fn area2(&self) -> i128 {
        let cross = |p: FinePoint, q: FinePoint| {
            i128::from(imul_wide(p.x, q.y)) - i128::from(imul_wide(q.x, p.y))
        };
        let mut vs = self.vertices.iter().map(|&v| self.vertex(v));
        let Some(first) = vs.next() else {
            return 0;
        };
        let (mut a, mut p) = (0i128, first);
        for q in vs {
            a += cross(p, q);
            p = q;
        }
        a + cross(p, first)
    }
}

impl<P: Copy + Into<FinePoint>> Shape for Polygon<'_, P> {
    fn key(&self) -> Option<super::ShapeKey> {
        super::ShapeKey::described(super::DescribedKind::Polygon, self)
    }

    fn key_reads_points(&self) -> bool {
        true
    }

    fn describe<S: PathSink + ?Sized>(&self, sink: &mut S) {
        if self.vertices.is_empty() {
            return;
        }
        // A box needs no orientation (every band finds the shape's).
        let forward = !sink.needs_clockwise() || self.area2() >= 0;
        let mut emit = |k: usize, first: bool| {
            let p = self.vertex(self.vertices[k]);
            if first {
                sink.move_to(p);
            } else {
                sink.line_to(p);
            }
        };
        let n = self.vertices.len();
        if forward {
            (0..n).for_each(|k| emit(k, k == 0));
        } else {
            (0..n).rev().for_each(|k| emit(k, k == n - 1));
        }
        sink.close();
    }

    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        let tol = fitted(self, style, tol, self.vertices.len() + 1);
        let mut s = Stroker::with_tolerance(style, tol, sink);
        self.describe(&mut s);
        // An error (stopped past its work limit): no union for pieces not
        // drawn.
        s.finish()?;
        // Where the stroke overlaps itself: the union, not the sum; the
        // points in the order the stroker had them (clockwise on screen).
        let points = self.vertices.iter().map(|&p| self.vertex(p).into());
        if self.area2() >= 0 {
            crate::path::stroke::union::polyline_union(points, style, tol, true, sink);
        } else {
            crate::path::stroke::union::polyline_union(points.rev(), style, tol, true, sink);
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::path::testing::{Lcg, Numbering};
    use crate::path::{LineCap, LineJoin};

    /// Random lines of 17 to 80 points (steps of a chart, some repeated
    /// points, some long jumps and sharp turns), random widths, joins and
    /// caps, and windows of 1 to 40 rows: the segments a windowed stroke
    /// sends that reach into the window are exactly those of the whole
    /// stroke that do (the rows of a band get the same coverage), and
    /// their numbers rise, the same for a segment whatever the window.
    #[test]
    fn a_windowed_stroke_sends_the_window_the_whole_strokes_segments() {
        let mut rng = Lcg(0x5c1a_71e0);
        let (mut culled, mut checked, mut renumbered) = (0, 0, 0);
        for case in 0..1500 {
            let n = 17 + rng.below(64) as usize;
            let mut pts: Vec<FinePoint> = Vec::new();
            let (mut x, mut y) = (rng.below(100 << 10) as i32, rng.below(240 << 10) as i32);
            for _ in 0..n {
                pts.push(FinePoint::new(x, y));
                match rng.below(8) {
                    0 => {} // a repeated point
                    1 => {
                        x = rng.below(240 << 10) as i32;
                        y = rng.below(240 << 10) as i32;
                    }
                    _ => {
                        x += rng.below(8 << 10) as i32 - (2 << 10);
                        y += rng.below(40 << 10) as i32 - (20 << 10);
                    }
                }
            }
            let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][rng.below(3) as usize];
            let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][rng.below(3) as usize];
            let style = StrokeStyle::new(256 + rng.below(8 << 10) as u32)
                .with_join(join)
                .with_cap(cap);
            let line = Polyline::new(&pts);
            let tol = Tolerance::DEFAULT;
            let mut whole = Numbering {
                window: None,
                next: 0,
                segs: Vec::new(),
            };
            line.stroke_with(&style, tol, &mut whole).unwrap();
            let meets = |(lo, hi): (i32, i32), a: &FinePoint, b: &FinePoint| {
                a.y.min(b.y) <= hi && a.y.max(b.y) >= lo
            };
            let mut numbers = std::collections::BTreeMap::new();
            for _ in 0..4 {
                let lo = rng.below(250 << 10) as i32 - (5 << 10);
                let w = (lo, lo + (1 + rng.below(40) as i32) * 1024 - 1);
                let mut got = Numbering {
                    window: Some(w),
                    next: 0,
                    segs: Vec::new(),
                };
                line.stroke_with(&style, tol, &mut got).unwrap();
                culled += usize::from(got.segs.len() < whole.segs.len());
                assert!(
                    got.segs.windows(2).all(|p| p[0].0 < p[1].0),
                    "case {case}: numbers do not rise"
                );
                let inside = |v: &[(u32, FinePoint, FinePoint)]| {
                    let mut s: Vec<_> = v
                        .iter()
                        .filter(|(_, a, b)| meets(w, a, b))
                        .map(|&(_, a, b)| (a.x, a.y, b.x, b.y))
                        .collect();
                    s.sort();
                    s
                };
                assert_eq!(
                    inside(&got.segs),
                    inside(&whole.segs),
                    "case {case}, window {w:?}"
                );
                // A segment keeps its number from window to window (but
                // for the line's first piece: see `stroke::windowed`).
                for &(k, a, b) in &got.segs {
                    if meets(w, &a, &b) {
                        let seen = numbers.insert((a.x, a.y, b.x, b.y), k);
                        checked += 1;
                        renumbered += usize::from(seen.is_some_and(|s| s != k));
                    }
                }
            }
        }
        assert!(culled > 3000, "{culled} windows culled");
        assert!(
            renumbered * 100 < checked,
            "{renumbered} of {checked} renumbered"
        );
    }

    /// The shoelace sum as written down, in `i128` throughout.
    fn shoelace(v: &[FinePoint]) -> i128 {
        let n = v.len();
        (0..n)
            .map(|k| {
                let (p, q) = (v[k], v[(k + 1) % n]);
                i128::from(p.x) * i128::from(q.y) - i128::from(q.x) * i128::from(p.y)
            })
            .sum()
    }

    /// The points a description sends, and whether the sink asks for
    /// clockwise contours.
    struct Points(Vec<FinePoint>, bool);

    impl PathSink for Points {
        fn needs_clockwise(&self) -> bool {
            self.1
        }
        fn move_to(&mut self, p: FinePoint) {
            self.0.push(p);
        }
        fn line_to(&mut self, p: FinePoint) {
            self.0.push(p);
        }
        fn quad_to(&mut self, _: FinePoint, p: FinePoint) {
            self.0.push(p);
        }
        fn cubic_to(&mut self, _: FinePoint, _: FinePoint, p: FinePoint) {
            self.0.push(p);
        }
        fn close(&mut self) {}
    }

    #[test]
    fn a_polygon_is_described_clockwise_unless_the_sink_needs_no_order() {
        let f = FinePoint::new;
        let ccw = [f(0, 0), f(0, 4096), f(4096, 4096), f(4096, 0)];
        let p = Polygon::new(&ccw[..]);
        assert!(p.area2() < 0);
        let mut cw = Points(Vec::new(), true);
        p.describe(&mut cw);
        assert!(shoelace(&cw.0) > 0);
        let mut any = Points(Vec::new(), false);
        p.describe(&mut any);
        assert_eq!(any.0, ccw);
        let mut sorted = cw.0.clone();
        sorted.sort_by_key(|q| (q.x, q.y));
        let mut given = any.0.clone();
        given.sort_by_key(|q| (q.x, q.y));
        assert_eq!(sorted, given, "the same points either way");
    }

    #[test]
    fn twice_the_area_is_the_shoelace_sum_at_any_coordinates() {
        let mut rng = Lcg(0x0a2e_a2a2_5eed_0001);
        for case in 0..400 {
            let n = case % 9;
            // Small, in-range and extreme coordinates (the translation
            // saturates at the `i32` limits).
            let span = [1u64 << 12, 1 << 22, 1 << 32][case % 3];
            let v: Vec<FinePoint> = (0..n)
                .map(|_| {
                    let c = |r: &mut Lcg| (r.below(span) as i64 - (span / 2) as i64) as i32;
                    FinePoint::new(c(&mut rng), c(&mut rng))
                })
                .collect();
            let t = if case % 5 == 0 {
                FinePoint::new(i32::MAX - 7, i32::MIN + 3)
            } else {
                FinePoint::new(0, 0)
            };
            let p = Polygon {
                translate: t,
                vertices: &v,
            };
            let moved: Vec<FinePoint> = v.iter().map(|&q| p.vertex(q)).collect();
            assert_eq!(p.area2(), shoelace(&moved), "case {case}");
        }
    }
}
