//! [`Arc`] and [`Sector`]: parts of a circle between two angles.

use crate::geom::{FinePoint, PathSink};
use crate::path::arc::{arc_cubics, arc_points, EllipseFrame};
use crate::path::segment::SegmentSink;
use crate::path::stroke::LineCap;
use crate::path::trig::{Q30, TURN};
use crate::path::vector::{Pt, UNIT_X};
use crate::path::{Degrees, StrokeError, StrokeStyle, Tolerance};

use super::{ellipse_contour, needs_stroker, polygon, Shape};

/// The start and the non-negative sweep (binary units, at most one turn)
/// of `start` over `sweep`, turned around when the sweep is negative so
/// that the arc always runs clockwise.
fn clockwise(start: Degrees, sweep: Degrees) -> (i64, i64) {
    let (t0, s) = (start.binary(), sweep.binary());
    let (t0, s) = if s < 0 { (t0 + s, -s) } else { (t0, s) };
    (t0.rem_euclid(TURN), s.min(TURN))
}

/// An arc of a circle: centre, radius (fine units), start angle and sweep
/// ([`Degrees`], clockwise on screen from +x; a negative sweep runs the
/// other way, more than a turn is a whole circle).
///
/// Its [`describe`](Shape::describe) is the open arc (always clockwise);
/// its fill closes it with the chord (SVG's rule; embedded-graphics does
/// not fill arcs); its stroke with butt caps and no dashes is the annular
/// sector between radii `r + o` and `r - i` (`o`, `i` the stroke's reach
/// outside and inside the circle), as embedded-graphics draws it.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Arc, Degrees};
/// let quarter = Arc::new(FinePoint::new(0, 0), 10240, Degrees::new(0), Degrees::new(90));
/// assert_eq!(quarter.sweep, Degrees::new(90));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Arc {
    /// The centre of the circle.
    pub centre: FinePoint,
    /// Its radius, fine units.
    pub radius: u32,
    /// Where the arc starts.
    pub start: Degrees,
    /// How far it runs (negative: counter-clockwise).
    pub sweep: Degrees,
}

impl Arc {
    /// An arc of the circle about `centre` of radius `radius`.
    pub const fn new(centre: FinePoint, radius: u32, start: Degrees, sweep: Degrees) -> Self {
        Self {
            centre,
            radius,
            start,
            sweep,
        }
    }

    fn frame(&self) -> EllipseFrame {
        EllipseFrame::circle(self.centre.into(), self.radius)
    }
}

impl Shape for Arc {
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        let (t0, s) = clockwise(self.start, self.sweep);
        if self.radius == 0 || s == 0 {
            return;
        }
        let f = self.frame();
        sink.move_to(f.point(t0, Q30).to_fine());
        arc_cubics(&f, t0, s, None, sink);
    }

    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        if needs_stroker(style) || style.cap != LineCap::Butt {
            let mut st = crate::path::Stroker::with_tolerance(style, tol, sink);
            self.describe(&mut st);
            return st.finish();
        }
        let (t0, s) = clockwise(self.start, self.sweep);
        if self.radius == 0 || s == 0 || style.width == 0 {
            return Ok(());
        }
        let (out_q1, in_q1) = style.reach_q1();
        let c: Pt = self.centre.into();
        let c_q8 = Pt::new(c.x << 8, c.y << 8);
        let r_q8 = i64::from(self.radius) << 8;
        let ro = r_q8 + (out_q1 << 7);
        let ri = (r_q8 - (in_q1 << 7)).max(0);
        let outer = EllipseFrame::with_q8(c_q8, ro, ro, UNIT_X);
        let inner = EllipseFrame::with_q8(c_q8, ri, ri, UNIT_X);
        if s >= TURN {
            ellipse_contour(&outer, false, tol, sink);
            ellipse_contour(&inner, true, tol, sink);
            return Ok(());
        }
        polygon(sink, |out| {
            arc_points(&outer, t0, s, tol, &mut *out);
            if ri > 0 {
                arc_points(&inner, t0 + s, -s, tol, &mut *out);
            } else {
                out(c);
            }
        });
        Ok(())
    }
}

/// A sector of a disc (a pie slice): centre, radius, start angle and
/// sweep as for [`Arc`]; more than a turn is the whole disc.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Degrees, Sector};
/// let pie = Sector::new(FinePoint::new(0, 0), 10240, Degrees::new(-45), Degrees::new(270));
/// assert_eq!(pie.radius, 10240);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Sector {
    /// The centre of the circle (the apex).
    pub centre: FinePoint,
    /// Its radius, fine units.
    pub radius: u32,
    /// Where the arc starts.
    pub start: Degrees,
    /// How far it runs (negative: counter-clockwise).
    pub sweep: Degrees,
}

impl Sector {
    /// A sector of the disc about `centre` of radius `radius`.
    pub const fn new(centre: FinePoint, radius: u32, start: Degrees, sweep: Degrees) -> Self {
        Self {
            centre,
            radius,
            start,
            sweep,
        }
    }

    fn frame(&self) -> EllipseFrame {
        EllipseFrame::circle(self.centre.into(), self.radius)
    }
}

impl Shape for Sector {
    /// Apex, the first radius, the arc, back to the apex (closed); the
    /// whole circle for a sweep of a turn or more.
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        let (t0, s) = clockwise(self.start, self.sweep);
        if self.radius == 0 || s == 0 {
            return;
        }
        let f = self.frame();
        let start = f.point(t0, Q30);
        if s >= TURN {
            sink.move_to(start.to_fine());
            arc_cubics(&f, t0, s, Some(start), sink);
        } else {
            sink.move_to(self.centre);
            sink.line_to(start.to_fine());
            arc_cubics(&f, t0, s, None, sink);
        }
        sink.close();
    }

    fn fill_with<S: SegmentSink + ?Sized>(&self, tol: Tolerance, sink: &mut S) {
        let (t0, s) = clockwise(self.start, self.sweep);
        if self.radius == 0 || s == 0 {
            return;
        }
        let f = self.frame();
        if s >= TURN {
            ellipse_contour(&f, false, tol, sink);
            return;
        }
        let c: Pt = self.centre.into();
        polygon(sink, |out| {
            out(c);
            arc_points(&f, t0, s, tol, &mut *out);
        });
    }
}
