//! What a shape's outline is made from, exactly: the key by which a
//! [`ShapeCache`](crate::canvas::ShapeCache) keeps the outline from one
//! band and one frame to the next.

use super::{Arc, Circle, Ellipse, Line, Rectangle, RoundedRectangle, Sector};

/// A shape's geometry, whole: two shapes with equal keys describe the
/// same segments (at the same tolerance, with the same stroke). The
/// shapes whose geometry is a few numbers give one
/// ([`Shape::key`](super::Shape::key)); shapes that borrow their points
/// (polylines, polygons, SVG paths, glyphs) and shapes of other crates do
/// not, and are described again wherever they are drawn.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Circle, Shape};
/// let c = FinePoint::new(20 * 1024, 20 * 1024);
/// assert_eq!(Circle::new(c, 5 * 1024).key(), Circle::new(c, 5 * 1024).key());
/// assert_ne!(Circle::new(c, 5 * 1024).key(), Circle::new(c, 5 * 1024 + 1).key());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShapeKey(Known);

/// The shapes a key is made of, by value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Known {
    Circle(Circle),
    Ellipse(Ellipse),
    Arc(Arc),
    Sector(Sector),
    Rectangle(Rectangle),
    Rounded(RoundedRectangle),
    Line(Line),
}

macro_rules! keys {
    ($($t:ident => $v:ident),* $(,)?) => {$(
        impl From<$t> for ShapeKey {
            fn from(s: $t) -> Self {
                ShapeKey(Known::$v(s))
            }
        }
    )*};
}

keys! {
    Circle => Circle,
    Ellipse => Ellipse,
    Arc => Arc,
    Sector => Sector,
    Rectangle => Rectangle,
    RoundedRectangle => Rounded,
    Line => Line,
}

impl ShapeKey {
    /// The circle the key is made of, if it is one.
    pub(crate) fn circle(&self) -> Option<Circle> {
        match self.0 {
            Known::Circle(c) => Some(c),
            _ => None,
        }
    }

    /// The arc the key is made of, if it is one.
    pub(crate) fn arc(&self) -> Option<Arc> {
        match self.0 {
            Known::Arc(a) => Some(a),
            _ => None,
        }
    }
}
