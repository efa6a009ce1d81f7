//! [`Rectangle`] and [`RoundedRectangle`], with per-corner radii clamped
//! as CSS and SVG do.

use crate::geom::{FinePoint, PathSink};
use crate::path::arc::{arc_cubics, arc_points, EllipseFrame};
use crate::path::segment::{SegmentSink, Vertices};
use crate::path::stroke::LineJoin;
use crate::path::trig::{round_shift, QUARTER_TURN};
use crate::path::vector::{Pt, UNIT_X};
use crate::path::{StrokeError, StrokeStyle, Tolerance};

use super::{needs_stroker, polygon, Shape};

/// An axis-aligned rectangle covering `[x, x + width) x [y, y + height)`
/// (fine units; embedded-graphics' convention, continuous here).
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::Rectangle;
/// let r = Rectangle::new(FinePoint::from_px(2, 3), 4096, 2048);
/// assert_eq!(r.bottom_right(), FinePoint::from_px(6, 5));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Rectangle {
    /// The top-left corner.
    pub top_left: FinePoint,
    /// Width, fine units (0 is empty).
    pub width: u32,
    /// Height, fine units (0 is empty).
    pub height: u32,
}

impl Rectangle {
    /// A rectangle from its top-left corner and size.
    pub const fn new(top_left: FinePoint, width: u32, height: u32) -> Self {
        Self {
            top_left,
            width,
            height,
        }
    }

    /// The corner opposite `top_left` (saturating in `i32`).
    pub fn bottom_right(&self) -> FinePoint {
        let (_, _, x1, y1) = self.bounds();
        Pt::new(x1, y1).to_fine()
    }

    /// `(x0, y0, x1, y1)` in fine units, `i64`.
    fn bounds(&self) -> (i64, i64, i64, i64) {
        let (x, y) = (i64::from(self.top_left.x), i64::from(self.top_left.y));
        (x, y, x + i64::from(self.width), y + i64::from(self.height))
    }

    fn is_empty(&self) -> bool {
        self.width == 0 || self.height == 0
    }
}

impl Shape for Rectangle {
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        RoundedRectangle::new(*self, CornerRadii::ZERO).describe(sink);
    }

    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        RoundedRectangle::new(*self, CornerRadii::ZERO).fill_with(tol, sink);
    }

    /// Without dashes: the outer rectangle (grown by the reach outside,
    /// its corners mitered, beveled or rounded by the join) minus the
    /// inner one (shrunk by the reach inside; none when that closes it).
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        RoundedRectangle::new(*self, CornerRadii::ZERO).stroke_with(style, tol, sink)
    }
}

/// The radii of the four corners, `(horizontal, vertical)` each, fine
/// units: a corner is a quarter of the ellipse with these semi-axes. A
/// corner with either radius zero is square.
///
/// ```
/// use softedge::path::CornerRadii;
/// let r = CornerRadii { top_left: (4096, 2048), ..CornerRadii::uniform(1024) };
/// // 4 + 1 px along the top of a 4-px-wide rectangle: all scaled by 4/5.
/// assert_eq!(r.clamped(4096, 8192).top_left, (3276, 1638));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CornerRadii {
    /// Top-left corner.
    pub top_left: (u32, u32),
    /// Top-right corner.
    pub top_right: (u32, u32),
    /// Bottom-right corner.
    pub bottom_right: (u32, u32),
    /// Bottom-left corner.
    pub bottom_left: (u32, u32),
}

impl CornerRadii {
    /// Square corners.
    pub const ZERO: CornerRadii = CornerRadii::uniform(0);

    /// The same circular radius at every corner.
    pub const fn uniform(r: u32) -> Self {
        Self {
            top_left: (r, r),
            top_right: (r, r),
            bottom_right: (r, r),
            bottom_left: (r, r),
        }
    }

    /// Clockwise from the top left.
    fn corners(&self) -> [(i64, i64); 4] {
        [
            self.top_left,
            self.top_right,
            self.bottom_right,
            self.bottom_left,
        ]
        .map(|(x, y)| {
            if x == 0 || y == 0 {
                (0, 0)
            } else {
                (i64::from(x), i64::from(y))
            }
        })
    }

    /// The radii scaled down, all by one factor, until the two radii along
    /// every side fit in it (CSS Backgrounds 3, "corner overlap"; SVG 2
    /// uses the same rule): `f = min(1, side / (r1 + r2))` over the four
    /// sides, each radius then rounded down.
    pub fn clamped(&self, width: u32, height: u32) -> CornerRadii {
        let c = self.corners();
        let (w, h) = (i64::from(width), i64::from(height));
        let [tl, tr, br, bl] = c;
        let sides = [
            (w, tl.0 + tr.0),
            (h, tr.1 + br.1),
            (w, br.0 + bl.0),
            (h, bl.1 + tl.1),
        ];
        // The smallest side / sum, compared exactly: (num, den).
        let mut f = (1i64, 1i64);
        for (side, sum) in sides {
            if sum > 0 && i128::from(side) * i128::from(f.1) < i128::from(f.0) * i128::from(sum) {
                f = (side, sum);
            }
        }
        if f == (1, 1) {
            // Every pair fits its side (zero radii too): the corners as
            // they are, without the divisions by one.
            let s = |(x, y): (i64, i64)| (x as u32, y as u32);
            return CornerRadii {
                top_left: s(tl),
                top_right: s(tr),
                bottom_right: s(br),
                bottom_left: s(bl),
            };
        }
        let scale = |v: i64| -> u32 {
            if f.1 == 0 {
                return 0;
            }
            (i128::from(v) * i128::from(f.0) / i128::from(f.1)) as u32
        };
        let s = |(x, y): (i64, i64)| (scale(x), scale(y));
        CornerRadii {
            top_left: s(tl),
            top_right: s(tr),
            bottom_right: s(br),
            bottom_left: s(bl),
        }
    }
}

/// A rectangle with rounded corners.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{CornerRadii, Rectangle, RoundedRectangle};
/// let r = Rectangle::new(FinePoint::new(0, 0), 50 * 1024, 60 * 1024);
/// let rr = RoundedRectangle::new(r, CornerRadii::uniform(40 * 1024));
/// // Clamped as CSS does: 40 + 40 > 50, so every radius is scaled by 50/80.
/// assert_eq!(rr.radii().top_left, (25 * 1024, 25 * 1024));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RoundedRectangle {
    /// The rectangle.
    pub rect: Rectangle,
    /// The corner radii as given (clamped when used).
    pub corner_radii: CornerRadii,
}

impl RoundedRectangle {
    /// A rounded rectangle.
    pub const fn new(rect: Rectangle, corner_radii: CornerRadii) -> Self {
        Self { rect, corner_radii }
    }

    /// The radii in use: clamped to the sides (see
    /// [`CornerRadii::clamped`]), then each limited to
    /// [`MAX_RADIUS`](crate::path::MAX_RADIUS).
    pub fn radii(&self) -> CornerRadii {
        let max = crate::path::MAX_RADIUS;
        let c = self.corner_radii.clamped(self.rect.width, self.rect.height);
        let lim = |(x, y): (u32, u32)| (x.min(max), y.min(max));
        CornerRadii {
            top_left: lim(c.top_left),
            top_right: lim(c.top_right),
            bottom_right: lim(c.bottom_right),
            bottom_left: lim(c.bottom_left),
        }
    }

    /// The outline in 1/256 fine units, corners clockwise from the top
    /// left.
    fn outline_q8(&self) -> Outline {
        let (x0, y0, x1, y1) = self.rect.bounds();
        let c = self.radii().corners();
        Outline {
            x0: x0 << 8,
            y0: y0 << 8,
            x1: x1 << 8,
            y1: y1 << 8,
            corners: c.map(|(rx, ry)| Corner::Round(rx << 8, ry << 8)),
        }
    }
}

/// How a corner of an [`Outline`] is cut.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Corner {
    /// A quarter ellipse of these semi-axes (Q8); `(0, 0)` is square.
    Round(i64, i64),
    /// A straight cut this far along both sides (Q8).
    Chamfer(i64),
}

/// A rectangle with cut corners, in 1/256 fine units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Outline {
    x0: i64,
    y0: i64,
    x1: i64,
    y1: i64,
    /// Top left, top right, bottom right, bottom left.
    corners: [Corner; 4],
}

impl Outline {
    /// Calls `out` with the area-preserving polygon, clockwise from the
    /// top-left corner, or counter-clockwise with `reverse`.
    fn points(&self, reverse: bool, tol: Tolerance, out: &mut dyn Vertices) {
        let order: [usize; 4] = if reverse { [0, 3, 2, 1] } else { [0, 1, 2, 3] };
        for k in order {
            self.corner(k, reverse, tol, out);
        }
    }

    /// Corner `k` (0 top left, clockwise): its centre and the direction
    /// signs of its two sides, and the angle where its arc starts.
    fn corner(&self, k: usize, reverse: bool, tol: Tolerance, out: &mut dyn Vertices) {
        let (cx, cy, sx, sy) = match k {
            0 => (self.x0, self.y0, 1, 1),
            1 => (self.x1, self.y0, -1, 1),
            2 => (self.x1, self.y1, -1, -1),
            _ => (self.x0, self.y1, 1, -1),
        };
        let grid = |x: i64, y: i64| Pt::new(round_shift(x, 8), round_shift(y, 8));
        // Clockwise, corner k's arc runs from angle (k + 2) quarters.
        let t0 = (k as i64 + 2) * QUARTER_TURN;
        let corner = self.corners.get(k).copied().unwrap_or(Corner::Round(0, 0));
        match corner {
            Corner::Round(rx, ry) if rx > 0 && ry > 0 => {
                // Limited as the frame limits them, before the centre is
                // placed (a stroke's outer corners grow past the limit).
                let max = i64::from(crate::path::MAX_RADIUS) << 8;
                let (rx, ry) = (rx.min(max), ry.min(max));
                let frame =
                    EllipseFrame::with_q8(Pt::new(cx + sx * rx, cy + sy * ry), rx, ry, UNIT_X);
                if reverse {
                    arc_points(&frame, t0 + QUARTER_TURN, -QUARTER_TURN, tol, &mut *out);
                } else {
                    arc_points(&frame, t0, QUARTER_TURN, tol, &mut *out);
                }
            }
            Corner::Chamfer(d) if d > 0 => {
                // Clockwise the corner's first point lies on the side
                // before it: for the top left, on the left side.
                let on_prev = match k {
                    0 => grid(cx, cy + sy * d),
                    1 => grid(cx + sx * d, cy),
                    2 => grid(cx, cy + sy * d),
                    _ => grid(cx + sx * d, cy),
                };
                let on_next = match k {
                    0 => grid(cx + sx * d, cy),
                    1 => grid(cx, cy + sy * d),
                    2 => grid(cx + sx * d, cy),
                    _ => grid(cx, cy + sy * d),
                };
                if reverse {
                    out.vertex(on_next);
                    out.vertex(on_prev);
                } else {
                    out.vertex(on_prev);
                    out.vertex(on_next);
                }
            }
            _ => out.vertex(grid(cx, cy)),
        }
    }

    /// The outline grown by `d` (Q8) on every side: round corners grow
    /// their radii by `d`; square ones become what `join` makes of them.
    fn grown(&self, d: i64, join: LineJoin, miter_ok: bool) -> Outline {
        let corners = self.corners.map(|c| match c {
            Corner::Round(rx, ry) if rx > 0 && ry > 0 => Corner::Round(rx + d, ry + d),
            _ => match join {
                LineJoin::Miter if miter_ok => Corner::Round(0, 0),
                LineJoin::Round => Corner::Round(d, d),
                _ => Corner::Chamfer(d),
            },
        });
        Outline {
            x0: self.x0 - d,
            y0: self.y0 - d,
            x1: self.x1 + d,
            y1: self.y1 + d,
            corners,
        }
    }

    /// The outline shrunk by `d` (Q8), radii shrunk by `d` (a corner whose
    /// radius runs out is square); `None` when nothing is left.
    fn shrunk(&self, d: i64) -> Option<Outline> {
        if self.x1 - self.x0 <= 2 * d || self.y1 - self.y0 <= 2 * d {
            return None;
        }
        let corners = self.corners.map(|c| match c {
            Corner::Round(rx, ry) if rx > d && ry > d => Corner::Round(rx - d, ry - d),
            _ => Corner::Round(0, 0),
        });
        Some(Outline {
            x0: self.x0 + d,
            y0: self.y0 + d,
            x1: self.x1 - d,
            y1: self.y1 - d,
            corners,
        })
    }
}

impl Shape for RoundedRectangle {
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

    /// From the end of the top-left corner, clockwise, closed.
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        if self.rect.is_empty() {
            return;
        }
        let (x0, y0, x1, y1) = self.rect.bounds();
        let c = self.radii().corners();
        let centres = [
            (x0 + c[0].0, y0 + c[0].1),
            (x1 - c[1].0, y0 + c[1].1),
            (x1 - c[2].0, y1 - c[2].1),
            (x0 + c[3].0, y1 - c[3].1),
        ];
        // Corner k's arc from angle (k + 2) quarters over one quarter:
        // start and end points exactly.
        let start = |k: usize| -> Pt {
            let ((cx, cy), (rx, ry)) = (centres[k], c[k]);
            match k {
                0 => Pt::new(cx - rx, cy),
                1 => Pt::new(cx, cy - ry),
                2 => Pt::new(cx + rx, cy),
                _ => Pt::new(cx, cy + ry),
            }
        };
        let arc_end = |k: usize| -> Pt {
            let ((cx, cy), (rx, ry)) = (centres[k], c[k]);
            match k {
                0 => Pt::new(cx, cy - ry),
                1 => Pt::new(cx + rx, cy),
                2 => Pt::new(cx, cy + ry),
                _ => Pt::new(cx - rx, cy),
            }
        };
        sink.move_to(arc_end(0).to_fine());
        for k in [1usize, 2, 3, 0] {
            let s = start(k);
            sink.line_to(s.to_fine());
            let (rx, ry) = c[k];
            if rx > 0 && ry > 0 {
                let (cx, cy) = centres[k];
                let frame = EllipseFrame::new(Pt::new(cx, cy), rx as u32, ry as u32, UNIT_X);
                let t0 = (k as i64 + 2) * QUARTER_TURN;
                arc_cubics(&frame, t0, QUARTER_TURN, Some(arc_end(k)), sink);
            }
        }
        sink.close();
    }

    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        if self.rect.is_empty() {
            return;
        }
        let o = self.outline_q8();
        polygon(sink, |out| o.points(false, tol, out));
    }

    /// Without dashes: the outer outline (grown by the reach outside:
    /// radii grown by it, square corners shaped by the join) minus the
    /// inner one (shrunk by the reach inside, radii shrunk by it).
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        if needs_stroker(style) {
            return crate::path::stroke::stroke_described(self, style, tol, sink);
        }
        if self.rect.is_empty() || style.width == 0 {
            return Ok(());
        }
        let (out_q1, in_q1) = style.reach_q1();
        let base = self.outline_q8();
        let miter_ok = style.miter_limit.allows_angle_degrees(90);
        let outer = base.grown(out_q1 << 7, style.join, miter_ok);
        polygon(sink, |out| outer.points(false, tol, out));
        if let Some(inner) = base.shrunk(in_q1 << 7) {
            polygon(sink, |out| inner.points(true, tol, out));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::testing::Lcg;

    /// CSS's corner-overlap rule as written down, in exact rationals: `f =
    /// min(1, side / (r1 + r2))` over the four sides (a corner with a zero
    /// radius counts as none), each radius `floor(r f)`.
    fn css(r: &CornerRadii, w: u32, h: u32) -> CornerRadii {
        let fix = |(x, y): (u32, u32)| if x == 0 || y == 0 { (0, 0) } else { (x, y) };
        let (tl, tr, br, bl) = (
            fix(r.top_left),
            fix(r.top_right),
            fix(r.bottom_right),
            fix(r.bottom_left),
        );
        let sides = [
            (w, tl.0 + tr.0),
            (h, tr.1 + br.1),
            (w, br.0 + bl.0),
            (h, bl.1 + tl.1),
        ];
        let (mut num, mut den) = (1u128, 1u128);
        for (side, sum) in sides {
            let (side, sum) = (u128::from(side), u128::from(sum));
            if sum > 0 && side * den < num * sum {
                (num, den) = (side, sum);
            }
        }
        let s = |(x, y): (u32, u32)| {
            (
                (u128::from(x) * num / den) as u32,
                (u128::from(y) * num / den) as u32,
            )
        };
        CornerRadii {
            top_left: s(tl),
            top_right: s(tr),
            bottom_right: s(br),
            bottom_left: s(bl),
        }
    }

    #[test]
    fn radii_are_clamped_by_the_css_rule() {
        let mut rng = Lcg(0xc0_44e4_5eed);
        let mut r = |m: u64| rng.below(m) as u32;
        for case in 0..20_000 {
            let big = if case % 2 == 0 { 1 << 12 } else { 1 << 30 };
            let radius = |r: &mut dyn FnMut(u64) -> u32| (r(big) >> r(20), r(big) >> r(20));
            let radii = CornerRadii {
                top_left: radius(&mut r),
                top_right: radius(&mut r),
                bottom_right: radius(&mut r),
                bottom_left: radius(&mut r),
            };
            let (w, h) = (r(big) >> r(12), r(big) >> r(12));
            assert_eq!(radii.clamped(w, h), css(&radii, w, h), "{radii:?} {w} {h}");
        }
    }
}
