//! The primitives an [`AaStyle`](super::AaStyle) draws: embedded-graphics'
//! own, as the [`path`] shapes of the same geometry, and those shapes
//! themselves (given embedded-graphics' `Primitive`, so `into_styled`
//! works on them too).

use embedded_graphics::primitives as eg;
use embedded_graphics_core::geometry::{Dimensions, Point, Size};

use crate::canvas::paths::shape_bounds;
use crate::error::ShapeKind;
use crate::geom::{FinePoint, FINE_BITS};
use crate::path::{self, svg::SvgPath, Shape};

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
}

/// embedded-graphics primitives: their geometry in continuous coordinates
/// (see [`path::eg`]).
macro_rules! eg_shape {
    ($($eg:ty => $shape:ty, $kind:ident);* $(;)?) => {$(
        impl AaShape for $eg {
            type Shape<'s> = $shape;
            const KIND: ShapeKind = ShapeKind::$kind;
            fn shape(&self) -> $shape {
                (*self).into()
            }
        }
    )*};
}

eg_shape! {
    eg::Circle => path::Circle, Circle;
    eg::Ellipse => path::Ellipse, Ellipse;
    eg::Arc => path::Arc, Arc;
    eg::Sector => path::Sector, Sector;
    eg::Rectangle => path::Rectangle, Rectangle;
    eg::RoundedRectangle => path::RoundedRectangle, RoundedRectangle;
    eg::Line => path::Line, Line;
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
