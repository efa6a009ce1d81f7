//! The primitives an [`AaStyle`](super::AaStyle) draws: embedded-graphics'
//! own, as the [`path`] shapes of the same geometry, and those shapes
//! themselves (given embedded-graphics' `Primitive`, so `into_styled`
//! works on them too).

use embedded_graphics::primitives as eg;
use embedded_graphics_core::geometry::{Dimensions, Point, Size};

use crate::canvas::paths::shape_bounds;
use crate::error::ShapeKind;
use crate::geom::{FinePoint, FINE_BITS};
use crate::path::{self, svg::SvgPath, LineCap, Shape, StrokeAlignment, StrokeStyle};

/// A primitive with an anti-aliased outline: the [`Shape`] it stands for.
pub trait AaShape {
    /// The shape (it may borrow the primitive's vertices).
    type Shape<'s>: Shape
    where
        Self: 's;

    /// Its kind, as errors name it.
    const KIND: ShapeKind;

    /// The shape of this primitive.
    fn shape(&self) -> Self::Shape<'_>;

    /// The shape and stroke a stroke of `stroke` is drawn as:
    /// [`shape`](Self::shape) and `stroke`, moved onto embedded-graphics'
    /// pixels for its primitives (see [`eg_stroke`]).
    fn stroked<'s>(&self, stroke: &StrokeStyle<'s>) -> (Self::Shape<'_>, StrokeStyle<'s>) {
        (self.shape(), *stroke)
    }
}

/// Where embedded-graphics' strokes lie, for its primitives stroked with
/// a whole number of pixels (`stroke.width` a multiple of 1024); any
/// other width is stroked on the continuous outline.
///
/// embedded-graphics draws whole pixels. A closed shape's stroke of width
/// `w` reaches `outside` pixels beyond the shape's outline and `inside`
/// pixels within it: `(0, w)` inside, `(w, 0)` outside, and, centred,
/// `(w / 2, (w + 1) / 2)`: an odd centred stroke puts its extra pixel
/// inside. Inside and outside are the continuous strokes already; a
/// centred one of odd width is the continuous stroke of the outline moved
/// half a pixel in (rectangles and rounded rectangles inset by 1/2 px on
/// every side, their radii 1/2 px less; circles, ellipses, arcs and
/// sectors 1/2 px less in radius).
///
/// A `Line` of embedded-graphics lights both end pixels whole, and an
/// even width puts its extra row (column) on the left of the direction
/// of travel (up for a line drawn left to right). With butt caps, the
/// default, the line is drawn that way: its ends moved half a pixel out
/// along its major axis, and, for an even width, the line moved half a
/// pixel along its minor axis to that side. Round and square caps are
/// drawn at the pixel centres (a 1-px square cap is the butt line).
///
/// So at integer geometry an axis-aligned edge lies on a pixel boundary,
/// and every pixel embedded-graphics lights whole there is fully covered
/// and every pixel it leaves dark is empty (`tests/tests/eg_strokes.rs`
/// over rectangles, rounded rectangles' straight parts and lines, widths
/// 1 to 5, all three alignments); curves and slanted edges are
/// anti-aliased where embedded-graphics steps.
pub mod eg_stroke {
    /// Half a pixel, fine units.
    pub(super) const HALF: i32 = crate::geom::FINE_ONE / 2;

    /// True when `stroke` is centred with an odd whole number of pixels:
    /// the outline moves half a pixel in.
    pub(super) fn inset(stroke: &super::StrokeStyle<'_>) -> bool {
        let one = crate::geom::FINE_ONE as u32;
        stroke.alignment == super::StrokeAlignment::Centre
            && stroke.width % one == 0
            && (stroke.width / one) % 2 == 1
    }
}

/// embedded-graphics primitives: their geometry in continuous coordinates
/// (see [`path::eg`]).
macro_rules! eg_shape {
    ($($eg:ty => $shape:ty, $kind:ident, $stroked:ident);* $(;)?) => {$(
        impl AaShape for $eg {
            type Shape<'s> = $shape;
            const KIND: ShapeKind = ShapeKind::$kind;
            fn shape(&self) -> $shape {
                (*self).into()
            }
            fn stroked<'s>(&self, stroke: &StrokeStyle<'s>) -> ($shape, StrokeStyle<'s>) {
                $stroked(self.shape(), stroke)
            }
        }
    )*};
}

/// Half a pixel less, fine units (saturating at 0).
fn less_half(v: u32) -> u32 {
    v.saturating_sub(eg_stroke::HALF as u32)
}

/// Radius 1/2 px less for an odd centred stroke ([`eg_stroke`]).
fn circle_stroke<'s>(
    mut c: path::Circle,
    stroke: &StrokeStyle<'s>,
) -> (path::Circle, StrokeStyle<'s>) {
    if eg_stroke::inset(stroke) {
        c.radius = less_half(c.radius);
    }
    (c, *stroke)
}

/// Semi-axes 1/2 px less for an odd centred stroke.
fn ellipse_stroke<'s>(
    mut e: path::Ellipse,
    stroke: &StrokeStyle<'s>,
) -> (path::Ellipse, StrokeStyle<'s>) {
    if eg_stroke::inset(stroke) {
        e.rx = less_half(e.rx);
        e.ry = less_half(e.ry);
    }
    (e, *stroke)
}

/// Radius 1/2 px less for an odd centred stroke.
fn arc_stroke<'s>(mut a: path::Arc, stroke: &StrokeStyle<'s>) -> (path::Arc, StrokeStyle<'s>) {
    if eg_stroke::inset(stroke) {
        a.radius = less_half(a.radius);
    }
    (a, *stroke)
}

/// Radius 1/2 px less for an odd centred stroke.
fn sector_stroke<'s>(
    mut a: path::Sector,
    stroke: &StrokeStyle<'s>,
) -> (path::Sector, StrokeStyle<'s>) {
    if eg_stroke::inset(stroke) {
        a.radius = less_half(a.radius);
    }
    (a, *stroke)
}

/// `r` moved by `d` fine units on every side (out for `d > 0`), or `None`
/// when that leaves no width or height.
fn offset_rect(r: path::Rectangle, d: i32) -> Option<path::Rectangle> {
    let grow = |v: u32| i64::from(v) + 2 * i64::from(d);
    let (w, h) = (grow(r.width), grow(r.height));
    if w <= 0 || h <= 0 || w > i64::from(u32::MAX) || h > i64::from(u32::MAX) {
        return None;
    }
    let at = FinePoint::new(
        r.top_left.x.saturating_sub(d),
        r.top_left.y.saturating_sub(d),
    );
    Some(path::Rectangle::new(at, w as u32, h as u32))
}

/// An odd centred stroke: the outline inset by 1/2 px; a rectangle 1 px
/// wide or high (no inset outline), embedded-graphics' whole stroke area
/// instead: the rectangle grown by `(w - 1) / 2` px, stroked inside
/// (the same pixels, with a width).
fn rect_stroke<'s>(
    r: path::Rectangle,
    stroke: &StrokeStyle<'s>,
) -> (path::Rectangle, StrokeStyle<'s>) {
    if !eg_stroke::inset(stroke) || r.width == 0 || r.height == 0 {
        return (r, *stroke);
    }
    if let Some(inset) = offset_rect(r, -eg_stroke::HALF) {
        return (inset, *stroke);
    }
    let out = (stroke.width - crate::geom::FINE_ONE as u32) / 2;
    match offset_rect(r, i32::try_from(out).unwrap_or(i32::MAX)) {
        Some(grown) => (grown, stroke.with_alignment(StrokeAlignment::Inside)),
        None => (r, *stroke),
    }
}

/// Inset by 1/2 px, every radius 1/2 px less, for an odd centred stroke
/// (a rounded rectangle at least 1 px wide and high).
fn rounded_stroke<'s>(
    mut r: path::RoundedRectangle,
    stroke: &StrokeStyle<'s>,
) -> (path::RoundedRectangle, StrokeStyle<'s>) {
    if eg_stroke::inset(stroke) {
        if let Some(inset) = offset_rect(r.rect, -eg_stroke::HALF) {
            let less = |(rx, ry): (u32, u32)| (less_half(rx), less_half(ry));
            r.rect = inset;
            let c = &mut r.corner_radii;
            c.top_left = less(c.top_left);
            c.top_right = less(c.top_right);
            c.bottom_right = less(c.bottom_right);
            c.bottom_left = less(c.bottom_left);
        }
    }
    (r, *stroke)
}

/// embedded-graphics' line ([`eg_stroke`]): centred whatever the
/// alignment (embedded-graphics ignores it for lines); with butt caps
/// the ends half a pixel out along the major axis, an even width half a
/// pixel to the left of the direction of travel along the minor axis.
fn line_stroke<'s>(l: path::Line, stroke: &StrokeStyle<'s>) -> (path::Line, StrokeStyle<'s>) {
    let centred = stroke.with_alignment(StrokeAlignment::Centre);
    let one = i64::from(crate::geom::FINE_ONE);
    if stroke.cap != LineCap::Butt || i64::from(stroke.width) % one != 0 {
        return (l, centred);
    }
    let (s, e) = (l.start, l.end);
    let (dx, dy) = (
        i64::from(e.x) - i64::from(s.x),
        i64::from(e.y) - i64::from(s.y),
    );
    let half = i64::from(eg_stroke::HALF);
    // A point is drawn as a line one pixel long, left to right.
    let (dx, dy) = if dx == 0 && dy == 0 { (1, 0) } else { (dx, dy) };
    let major = dx.abs().max(dy.abs());
    // Half a pixel along the major axis: (dx, dy) * half / major.
    let ext = (dx * half / major, dy * half / major);
    let even = (i64::from(stroke.width) / one) % 2 == 0;
    // Left of the direction, along the minor axis (y grows down): up for
    // an x-major line drawn rightwards, right for a y-major one drawn down.
    let side = match (even, dx.abs() >= dy.abs()) {
        (false, _) => (0, 0),
        (true, true) => (0, -half * dx.signum()),
        (true, false) => (half * dy.signum(), 0),
    };
    let at = |p: FinePoint, k: i64| {
        let c = |v: i32, d: i64, o: i64| {
            (i64::from(v) + k * d + o).clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
        };
        FinePoint::new(c(p.x, ext.0, side.0), c(p.y, ext.1, side.1))
    };
    (path::Line::new(at(s, -1), at(e, 1)), centred)
}

eg_shape! {
    eg::Circle => path::Circle, Circle, circle_stroke;
    eg::Ellipse => path::Ellipse, Ellipse, ellipse_stroke;
    eg::Arc => path::Arc, Arc, arc_stroke;
    eg::Sector => path::Sector, Sector, sector_stroke;
    eg::Rectangle => path::Rectangle, Rectangle, rect_stroke;
    eg::RoundedRectangle => path::RoundedRectangle, RoundedRectangle, rounded_stroke;
    eg::Line => path::Line, Line, line_stroke;
}

impl<'a> AaShape for eg::Polyline<'a> {
    type Shape<'s>
        = path::Polyline<'a, Point>
    where
        Self: 's;
    const KIND: ShapeKind = ShapeKind::Polyline;
    fn shape(&self) -> path::Polyline<'a, Point> {
        (*self).into()
    }
    /// Centred whatever the alignment (embedded-graphics ignores it for
    /// polylines).
    fn stroked<'s>(
        &self,
        stroke: &StrokeStyle<'s>,
    ) -> (path::Polyline<'a, Point>, StrokeStyle<'s>) {
        (self.shape(), stroke.with_alignment(StrokeAlignment::Centre))
    }
}

impl AaShape for eg::Triangle {
    type Shape<'s> = path::Polygon<'s, Point>;
    const KIND: ShapeKind = ShapeKind::Triangle;
    /// The triangle through the vertices' pixel centres.
    fn shape(&self) -> path::Polygon<'_, Point> {
        path::Polygon::new(&self.vertices)
    }
}

/// softedge's shapes stand for themselves.
macro_rules! own_shape {
    ($($t:ty => $kind:ident),* $(,)?) => {$(
        impl AaShape for $t {
            type Shape<'s> = Self where Self: 's;
            const KIND: ShapeKind = ShapeKind::$kind;
            fn shape(&self) -> Self {
                *self
            }
        }

        impl Dimensions for $t {
            /// The pixels the shape's outline description reaches (its
            /// control points', for curves).
            fn bounding_box(&self) -> eg::Rectangle {
                pixel_box(self)
            }
        }

        impl eg::Primitive for $t {}
    )*};
}

own_shape!(
    path::Circle => Circle,
    path::Ellipse => Ellipse,
    path::Arc => Arc,
    path::Sector => Sector,
    path::Rectangle => Rectangle,
    path::RoundedRectangle => RoundedRectangle,
    path::Line => Line,
    path::Polyline<'_, FinePoint> => Polyline,
    path::Polyline<'_, Point> => Polyline,
    path::Polygon<'_, FinePoint> => Polygon,
    path::Polygon<'_, Point> => Polygon,
    SvgPath<'_> => Path,
);

/// The whole pixels around a shape's description (empty at the origin for
/// an empty shape).
fn pixel_box<S: Shape + ?Sized>(shape: &S) -> eg::Rectangle {
    let Some(b) = shape_bounds(shape) else {
        return eg::Rectangle::zero();
    };
    let one = (1i64 << FINE_BITS) - 1;
    let (x0, y0) = (i64::from(b.x0) >> FINE_BITS, i64::from(b.y0) >> FINE_BITS);
    let (x1, y1) = (
        (i64::from(b.x1) + one) >> FINE_BITS,
        (i64::from(b.y1) + one) >> FINE_BITS,
    );
    eg::Rectangle::new(
        Point::new(x0 as i32, y0 as i32),
        Size::new((x1 - x0) as u32, (y1 - y0) as u32),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boxes_are_the_pixels_reached() {
        let c = path::Circle::new(FinePoint::centre_of(10, 10), 3 * 1024);
        assert_eq!(
            c.bounding_box(),
            eg::Rectangle::new(Point::new(7, 7), Size::new(7, 7))
        );
        let empty = path::Polyline::<FinePoint>::new(&[]);
        assert_eq!(empty.bounding_box(), eg::Rectangle::zero());
    }
}
