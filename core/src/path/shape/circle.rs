//! [`Circle`]: a disc given by its centre and radius.

use crate::geom::{FinePoint, PathSink};
use crate::path::arc::{arc_cubics, EllipseFrame};
use crate::path::segment::SegmentSink;
use crate::path::trig::{Q30, TURN};
use crate::path::vector::{Pt, UNIT_X};
use crate::path::{StrokeError, StrokeStyle, Tolerance};

use super::{ellipse_contour, needs_stroker, Shape};

/// A circle (a disc when filled): centre and radius in fine units.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::Circle;
/// // A circle of radius 2.5 px about the centre of pixel (10, 10).
/// let c = Circle::new(FinePoint::centre_of(10, 10), 2560);
/// assert_eq!(c.centre, FinePoint::new(10752, 10752));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Circle {
    /// The centre.
    pub centre: FinePoint,
    /// The radius, fine units (0 is empty).
    pub radius: u32,
}

impl Circle {
    /// A circle about `centre` of radius `radius` fine units.
    pub const fn new(centre: FinePoint, radius: u32) -> Self {
        Self { centre, radius }
    }

    /// A circle from `fixed` numbers in pixels (negative radii are empty).
    pub fn from_fixed(
        x: fixed::types::I22F10,
        y: fixed::types::I22F10,
        radius: fixed::types::I22F10,
    ) -> Self {
        Self::new(FinePoint::from_fixed(x, y), radius.to_bits().max(0) as u32)
    }

    pub(crate) fn frame(&self) -> EllipseFrame {
        EllipseFrame::circle(self.centre.into(), self.radius)
    }
}

impl Shape for Circle {
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        if self.radius == 0 {
            return;
        }
        let f = self.frame();
        let start = f.point(0, Q30);
        sink.move_to(start.to_fine());
        arc_cubics(&f, 0, TURN, Some(start), sink);
        sink.close();
    }

    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        ellipse_contour(&self.frame(), false, tol, sink);
    }

    /// Without dashes: the ring between the circles of radius `r + o` and
    /// `r - i` (`o`, `i` the stroke's reach outside and inside), the hole
    /// counter-clockwise; a disc when `i >= r`.
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        if needs_stroker(style) {
            return crate::path::stroke::stroke_described(self, style, tol, sink);
        }
        if self.radius == 0 || style.width == 0 {
            return Ok(());
        }
        let (out_q1, in_q1) = style.reach_q1();
        let c: Pt = self.centre.into();
        let c_q8 = Pt::new(c.x << 8, c.y << 8);
        let r_q8 = i64::from(self.radius) << 8;
        let outer = EllipseFrame::with_q8(c_q8, r_q8 + (out_q1 << 7), r_q8 + (out_q1 << 7), UNIT_X);
        ellipse_contour(&outer, false, tol, sink);
        let inner_r = r_q8 - (in_q1 << 7);
        if inner_r > 0 {
            let inner = EllipseFrame::with_q8(c_q8, inner_r, inner_r, UNIT_X);
            ellipse_contour(&inner, true, tol, sink);
        }
        Ok(())
    }
}
