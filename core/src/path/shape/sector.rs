//! [`Arc`] and [`Sector`]: parts of a circle between two angles.

use crate::geom::{FinePoint, PathSink};
use crate::path::arc::{arc_cubics, arc_inner_vertices, arc_points, EllipseFrame};
use crate::path::segment::{SegmentSink, Vertices};
use crate::path::stroke::LineCap;
use crate::path::trig::{atan2, round_shift, HALF_TURN, Q30, QUARTER_TURN, TURN};
use crate::path::vector::{Pt, Unit, UNIT_X};
use crate::path::{Degrees, StrokeError, StrokeStyle, Tolerance};

use super::{ellipse_contour, needs_stroker, polygon, Shape};
use crate::path::stroke::LineJoin;

/// The start and the non-negative sweep (binary units, at most one turn)
/// of `start` over `sweep`, turned around when the sweep is negative so
/// that the arc always runs clockwise.
pub(crate) fn clockwise(start: Degrees, sweep: Degrees) -> (i64, i64) {
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
/// outside and inside the circle), as embedded-graphics draws it. A
/// centred stroke with round or square caps narrower than the diameter is
/// the same ring with its caps (half discs, or squares, of half the width
/// about the centre line's ends) in one contour, its curves computed only
/// where a band needs them; other capped strokes go through the
/// [`Stroker`](crate::path::Stroker).
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
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

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
        let (t0, s) = clockwise(self.start, self.sweep);
        let (out_q1, in_q1) = style.reach_q1();
        let r_q8 = i64::from(self.radius) << 8;
        // Round and square caps on the ring: a centred stroke that leaves
        // a hole (otherwise the general stroker).
        let capped = style.cap != LineCap::Butt;
        let ring_caps = out_q1 == in_q1 && r_q8 > in_q1 << 7;
        if needs_stroker(style) || (capped && !ring_caps) {
            return crate::path::stroke::stroke_described(self, style, tol, sink);
        }
        if self.radius == 0 || s == 0 || style.width == 0 {
            return Ok(());
        }
        let c: Pt = self.centre.into();
        let c_q8 = Pt::new(c.x << 8, c.y << 8);
        let ro = r_q8 + (out_q1 << 7);
        let ri = (r_q8 - (in_q1 << 7)).max(0);
        let outer = EllipseFrame::with_q8(c_q8, ro, ro, UNIT_X);
        let inner = EllipseFrame::with_q8(c_q8, ri, ri, UNIT_X);
        if s >= TURN {
            // Caps of a whole turn lie inside the ring: a disc of radius
            // h about a point at radius r stays between r - h and r + h.
            ellipse_contour(&outer, false, tol, sink);
            ellipse_contour(&inner, true, tol, sink);
            return Ok(());
        }
        // A cap: about the centre line's end at parameter `t`, radius
        // h = o = i, half a turn clockwise from the direction `a` (the
        // end's outward radius at the end, its inward one at the start),
        // from the ring's vertex `from` there.
        let mid = EllipseFrame::with_q8(c_q8, r_q8, r_q8, UNIT_X);
        let cap = |t: i64, a: i64, from: Pt, out: &mut dyn Vertices| {
            let h = out_q1 << 7;
            let end = mid.point_q8(t);
            match style.cap {
                LineCap::Round => {
                    let f = EllipseFrame::with_q8(end, h, h, UNIT_X);
                    arc_inner_vertices(&f, a, HALF_TURN, tol, from, out);
                }
                LineCap::Square => {
                    // The corners, h sqrt 2 from the end at 45 degrees
                    // either side of the tangent (h <= 2^29: 2 h^2 < 2^60).
                    // (Unsigned: a signed `isqrt` keeps a panic for
                    // negative arguments in the firmware.)
                    let d = (2 * h * h).unsigned_abs().isqrt() as i64;
                    let f = EllipseFrame::with_q8(end, d, d, UNIT_X);
                    out.vertex(f.point(a + TURN / 8, Q30));
                    out.vertex(f.point(a + 3 * TURN / 8, Q30));
                }
                LineCap::Butt => {}
            }
        };
        polygon(sink, |out| {
            arc_points(&outer, t0, s, tol, &mut *out);
            if ri > 0 {
                if capped {
                    cap(t0 + s, t0 + s, outer.point(t0 + s, Q30), &mut *out);
                }
                arc_points(&inner, t0 + s, -s, tol, &mut *out);
                if capped {
                    cap(t0, t0 + HALF_TURN, inner.point(t0, Q30), &mut *out);
                }
            } else {
                out.vertex(c);
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
    fn key(&self) -> Option<super::ShapeKey> {
        Some((*self).into())
    }

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
            out.vertex(c);
            arc_points(&f, t0, s, tol, &mut *out);
        });
    }

    /// Without dashes (for a sweep up to half a turn, or any sweep with no
    /// reach outside): the ring between the sector grown by the stroke's
    /// reach outside (its three corners shaped by the join) and the sector
    /// shrunk by the reach inside (exact offsets: the points at least that
    /// far inside), as embedded-graphics draws a sector's stroke. A whole
    /// circle is the circle's ring. Otherwise the [`Stroker`](crate::path::Stroker).
    fn stroke_with<S: SegmentSink + ?Sized>(
        &self,
        style: &StrokeStyle<'_>,
        tol: Tolerance,
        sink: &mut S,
    ) -> Result<(), StrokeError> {
        let (t0, s) = clockwise(self.start, self.sweep);
        let (out_q1, in_q1) = style.reach_q1();
        if s >= TURN && !needs_stroker(style) {
            return super::Circle::new(self.centre, self.radius).stroke_with(style, tol, sink);
        }
        if needs_stroker(style) || (s > HALF_TURN && out_q1 > 0) {
            return crate::path::stroke::stroke_described(self, style, tol, sink);
        }
        if self.radius == 0 || s == 0 || style.width == 0 {
            return Ok(());
        }
        let ring = SectorRing::new(self.centre.into(), self.radius, t0, s);
        let (o, i) = (out_q1 << 7, in_q1 << 7);
        let parts = ring.grown(o, style);
        polygon(sink, |out| emit_parts(&parts, false, tol, out));
        let hole = if i == 0 {
            Some(ring.grown(0, style))
        } else {
            ring.shrunk(i)
        };
        if let Some(parts) = hole {
            polygon(sink, |out| emit_parts(&parts, true, tol, out));
        }
        Ok(())
    }
}

/// A piece of an outline in 1/256 fine units: a point, or an arc about a
/// centre (radius, start angle, sweep in binary units, clockwise when
/// positive; both ends included).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part {
    None,
    Point(Pt),
    Arc(Pt, i64, i64, i64),
}

/// Sends the parts' points in order, or all reversed (for a hole).
fn emit_parts(parts: &[Part; 8], reverse: bool, tol: Tolerance, out: &mut dyn Vertices) {
    let grid = |p: Pt| Pt::new((p.x + 128) >> 8, (p.y + 128) >> 8);
    let mut one = |part: &Part| match *part {
        Part::None => {}
        Part::Point(p) => out.vertex(grid(p)),
        Part::Arc(c, r, t, sw) => {
            let f = EllipseFrame::with_q8(c, r, r, UNIT_X);
            if reverse {
                arc_points(&f, t + sw, -sw, tol, &mut *out);
            } else {
                arc_points(&f, t, sw, tol, &mut *out);
            }
        }
    };
    if reverse {
        parts.iter().rev().for_each(&mut one);
    } else {
        parts.iter().for_each(&mut one);
    }
}

/// A sector in 1/256 fine units, for its offset outlines.
struct SectorRing {
    c: Pt,
    r: i64,
    t0: i64,
    s: i64,
    /// Directions of the two radii.
    u1: Unit,
    u2: Unit,
    /// Inward normals of the two straight edges (apex to arc, arc to apex).
    n1: Unit,
    n2: Unit,
}

impl SectorRing {
    fn new(c: Pt, r: u32, t0: i64, s: i64) -> Self {
        let u1 = Unit::from_angle(t0 as u32);
        let u2 = Unit::from_angle((t0 + s) as u32);
        Self {
            c: Pt::new(c.x << 8, c.y << 8),
            r: i64::from(r.min(crate::path::MAX_RADIUS)) << 8,
            t0,
            s,
            u1,
            u2,
            n1: u1.right(),
            n2: Unit { x: u2.y, y: -u2.x },
        }
    }

    /// `p + len u` (Q8, `u` Q30).
    fn at(p: Pt, u: Unit, len: i64) -> Pt {
        Pt::new(
            p.x + round_shift(u.x * len, 30),
            p.y + round_shift(u.y * len, 30),
        )
    }

    /// `c + k (n1 + n2) / (1 + n1.n2)`: where the two edges' offset lines
    /// at `k` (inward positive) cross.
    fn corner(&self, k: i64) -> Option<Pt> {
        let den = Q30 + self.n1.dot(self.n2);
        if den < Q30 >> 14 {
            return None;
        }
        let f = |a: i64, b: i64| {
            crate::path::trig::div_round(i128::from(a + b) * i128::from(k), i128::from(den)) as i64
        };
        Some(Pt::new(
            self.c.x + f(self.n1.x, self.n2.x),
            self.c.y + f(self.n1.y, self.n2.y),
        ))
    }

    /// The sector grown by `o` (Q8) with the style's joins at its
    /// corners, clockwise from the apex (`o = 0`: the sector).
    fn grown(&self, o: i64, style: &StrokeStyle<'_>) -> [Part; 8] {
        let mut parts = [Part::None; 8];
        let (c, r) = (self.c, self.r);
        let neg = |u: Unit| Unit { x: -u.x, y: -u.y };
        let (m1, m2) = (neg(self.n1), neg(self.n2)); // outward normals
        let join =
            |from: Pt, to: Pt, centre: Pt, ua: Unit, ub: Unit, t: i64, sweep: i64| -> [Part; 2] {
                let dot = ua.dot(ub);
                match style.join {
                    LineJoin::Round if o > 0 => [Part::Arc(centre, o, t, sweep), Part::None],
                    LineJoin::Miter if o > 0 && style.miter_limit.allows(dot) => {
                        let den = 2 * i128::from(Q30 + dot);
                        let f = |a: i64, b: i64| {
                            crate::path::trig::div_round(i128::from(a + b) * i128::from(2 * o), den)
                                as i64
                        };
                        [
                            Part::Point(Pt::new(
                                centre.x + f(ua.x, ub.x),
                                centre.y + f(ua.y, ub.y),
                            )),
                            Part::None,
                        ]
                    }
                    _ => [Part::Point(from), Part::Point(to)],
                }
            };
        // The apex: a join between the second edge and the first (convex
        // up to half a turn; o is zero beyond).
        let apex = if self.s < HALF_TURN {
            join(
                Self::at(c, m2, o),
                Self::at(c, m1, o),
                c,
                m2,
                m1,
                self.t0 + self.s + QUARTER_TURN,
                HALF_TURN - self.s,
            )
        } else {
            [Part::Point(self.corner(-o).unwrap_or(c)), Part::None]
        };
        let e1 = Self::at(c, self.u1, r);
        let e2 = Self::at(c, self.u2, r);
        let corner1 = join(
            Self::at(e1, m1, o),
            Self::at(e1, self.u1, o),
            e1,
            m1,
            self.u1,
            self.t0 - QUARTER_TURN,
            QUARTER_TURN,
        );
        let corner2 = join(
            Self::at(e2, self.u2, o),
            Self::at(e2, m2, o),
            e2,
            self.u2,
            m2,
            self.t0 + self.s,
            QUARTER_TURN,
        );
        parts[0] = apex[0];
        parts[1] = apex[1];
        parts[2] = corner1[0];
        parts[3] = corner1[1];
        parts[4] = Part::Arc(c, r + o, self.t0, self.s);
        parts[5] = corner2[0];
        parts[6] = corner2[1];
        parts
    }

    /// The points at least `i > 0` (Q8) inside the sector, clockwise;
    /// `None` when there are none.
    fn shrunk(&self, i: i64) -> Option<[Part; 8]> {
        if i <= 0 {
            return None;
        }
        let rho = self.r - i;
        if rho <= i {
            return None;
        }
        // Where the offset edges meet the circle of radius rho: an angle
        // asin(i / rho) in from either end.
        let foot = ((i128::from(rho) * i128::from(rho) - i128::from(i) * i128::from(i)) as u128)
            .isqrt() as i64;
        let alpha = i64::from(atan2(i, foot));
        let sweep = self.s - 2 * alpha;
        if sweep <= 0 {
            return None;
        }
        let mut parts = [Part::None; 8];
        if self.s <= HALF_TURN {
            // Convex: the offset edges meet at one point, which must lie
            // inside the circle of radius rho.
            let apex = self.corner(i)?;
            let d = apex.sub(self.c);
            if d.dot(d) >= i128::from(rho) * i128::from(rho) {
                return None;
            }
            parts[0] = Part::Point(apex);
            parts[1] = Part::Arc(self.c, rho, self.t0 + alpha, sweep);
        } else {
            // Reflex: around the apex the boundary is the arc of radius i
            // about it, from the second edge's offset back to the first's.
            parts[0] = Part::Point(Self::at(self.c, self.n1, i));
            parts[1] = Part::Arc(self.c, rho, self.t0 + alpha, sweep);
            parts[2] = Part::Arc(
                self.c,
                i,
                self.t0 + self.s - QUARTER_TURN,
                -(self.s - HALF_TURN),
            );
        }
        Some(parts)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::testing::{Lcg, Tally};

    /// The area of an arc's stroke with caps, exactly: the annular sector
    /// between `r - h` and `r + h` over `s` radians and its two caps.
    fn exact_px2(r: f64, h: f64, s: f64, cap: LineCap) -> f64 {
        let ring = s / 2.0 * ((r + h) * (r + h) - (r - h) * (r - h));
        ring + match cap {
            LineCap::Round => core::f64::consts::PI * h * h,
            LineCap::Square => 4.0 * h * h,
            LineCap::Butt => 0.0,
        }
    }

    #[test]
    fn capped_arc_strokes_have_the_exact_area() {
        let mut rng = Lcg(0x7a3c_55e1_0b9d_2f41);
        let mut next = |m: u64| rng.below(m);
        for case in 0..400 {
            let r_px = 4.0 + next(200) as f64;
            let w_fine = 512 + next((r_px * 1.6 * 1024.0) as u64) as u32;
            let h = f64::from(w_fine) / 2048.0;
            // Sweeps whose caps do not meet (a gap of more than 2h plus
            // some room on the centre line).
            let max_deg = 360.0 - (2.0 * h / r_px + 0.05).to_degrees();
            if max_deg < 20.0 {
                continue;
            }
            let sweep = 5 + next(max_deg as u64 - 5) as i32;
            let start = next(720) as i32 - 360;
            let sweep = if case % 2 == 0 { sweep } else { -sweep };
            let c = FinePoint::new(next(300 * 1024) as i32, next(300 * 1024) as i32);
            let arc = Arc::new(
                c,
                (r_px * 1024.0) as u32,
                Degrees::new(start),
                Degrees::new(sweep),
            );
            for cap in [LineCap::Round, LineCap::Square] {
                let style = StrokeStyle::new(w_fine).with_cap(cap);
                let mut t = Tally::default();
                arc.stroke(&style, &mut t).unwrap();
                assert!(t.closed(), "case {case}");
                let s = f64::from(sweep.abs()).to_radians();
                let want = exact_px2(r_px, h, s, cap);
                let rel = (t.px2() / want - 1.0).abs();
                assert!(
                    rel < 5e-4,
                    "case {case} {cap:?}: {} vs {want} ({rel})",
                    t.px2()
                );
                // The general stroker (what drew capped arcs before) agrees.
                let mut g = Tally::default();
                let mut st = crate::path::Stroker::new(&style, &mut g);
                arc.describe(&mut st);
                st.finish().unwrap();
                assert!(
                    (g.px2() / want - 1.0).abs() < 2e-3,
                    "case {case}: stroker {}",
                    g.px2()
                );
            }
        }
    }
}
