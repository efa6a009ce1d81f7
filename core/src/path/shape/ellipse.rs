//! [`Ellipse`]: an ellipse given by its centre, semi-axes and rotation.

use crate::geom::{FinePoint, PathSink};
use crate::path::arc::{arc_cubics, EllipseFrame};
use crate::path::segment::SegmentSink;
use crate::path::trig::{Q30, TURN};
use crate::path::vector::{Pt, Unit};
use crate::path::{Degrees, StrokeError, StrokeStyle, Tolerance};

use super::{angle, ellipse_contour, Shape};

/// An ellipse: centre, semi-axes `rx` (along the rotated x axis) and `ry`
/// in fine units, rotated clockwise on screen by `rotation`.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Degrees, Ellipse};
/// let e = Ellipse::new(FinePoint::new(0, 0), 4096, 2048).rotated(Degrees::new(30));
/// assert_eq!(e.rotation, Degrees::new(30));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Ellipse {
    /// The centre.
    pub centre: FinePoint,
    /// The semi-axis along the (rotated) x axis, fine units.
    pub rx: u32,
    /// The semi-axis along the (rotated) y axis, fine units.
    pub ry: u32,
    /// The rotation, clockwise on screen.
    pub rotation: Degrees,
}

impl Ellipse {
    /// An axis-aligned ellipse.
    pub const fn new(centre: FinePoint, rx: u32, ry: u32) -> Self {
        Self {
            centre,
            rx,
            ry,
            rotation: Degrees::ZERO,
        }
    }

    /// The same ellipse rotated by `rotation` about its centre.
    pub const fn rotated(mut self, rotation: Degrees) -> Self {
        self.rotation = rotation;
        self
    }

    fn axis(&self) -> Unit {
        Unit::from_angle(angle(self.rotation) as u32)
    }

    pub(crate) fn frame(&self) -> EllipseFrame {
        EllipseFrame::new(self.centre.into(), self.rx, self.ry, self.axis())
    }
}

impl Shape for Ellipse {
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        let f = self.frame();
        if f.is_flat() {
            return;
        }
        let start = f.point(0, Q30);
        sink.move_to(start.to_fine());
        arc_cubics(&f, 0, TURN, Some(start), sink);
        sink.close();
    }

    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        ellipse_contour(&self.frame(), false, tol, sink);
    }

    /// The exact offset of the outline, through the
    /// [`Stroker`](crate::path::Stroker) (its quadrilaterals follow the
    /// ellipse's normals). embedded-graphics strokes an ellipse as the ring
    /// between the ellipses of semi-axes `a +- o`, `b +- i`, which is exact
    /// at the ends of the axes only and thinner between (by 2.7 % of the
    /// area for `a = 2 b`, 7 % for `a = 3.3 b`); see [`Ellipse::ring`] for that
    /// model.
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        crate::path::stroke::stroke_described(self, style, tol, sink)
    }
}

impl Ellipse {
    /// embedded-graphics' model of an ellipse's stroke: the ring between
    /// the ellipses with semi-axes `rx + o, ry + o` and `rx - i, ry - i`
    /// (`o`, `i` the style's reach outside and inside; the inner one only
    /// if both stay positive), as two area-preserving polygons. Dashes are
    /// ignored.
    pub fn ring<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) {
        if self.rx == 0 || self.ry == 0 || style.width == 0 {
            return;
        }
        let (out_q1, in_q1) = style.reach_q1();
        let c: Pt = self.centre.into();
        let c_q8 = Pt::new(c.x << 8, c.y << 8);
        let (a, b) = (i64::from(self.rx) << 8, i64::from(self.ry) << 8);
        let rot = self.axis();
        let outer = EllipseFrame::with_q8(c_q8, a + (out_q1 << 7), b + (out_q1 << 7), rot);
        ellipse_contour(&outer, false, tol, sink);
        let (ia, ib) = (a - (in_q1 << 7), b - (in_q1 << 7));
        if ia > 0 && ib > 0 {
            let inner = EllipseFrame::with_q8(c_q8, ia, ib, rot);
            ellipse_contour(&inner, true, tol, sink);
        }
    }
}
