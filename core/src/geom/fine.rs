//! The fine sub-pixel grid: 1/1024 px, the unit the edge walker steps in.
//!
//! Triangles and polygons take their vertices on the 1/16-px grid of
//! [`SubPoint`]; curves need a finer one. A disc of radius 1/2 px drawn as
//! an inscribed polygon on the 1/16-px grid misses its area by several per
//! cent wherever its vertices round, and even on a 1/256-px grid the
//! rounding of 20 vertices moves its area by up to 0.32 %; on the 1/1024-px
//! grid the worst case is 0.065 % (measured over random centres with the
//! area-preserving radius of the inscribed 20-gon). So path vertices, and
//! every edge the walker steps, live on this grid: a [`SubPoint`] is the
//! same point with 6 more fraction bits.
//!
//! ## Range
//!
//! The accepted coordinate range is the same as for [`SubPoint`]:
//! `|x|, |y| <= COORD_LIMIT_PX` pixels, here `<= 2^21` fine units, so an
//! edge spans at most `2^22` units per axis.

use fixed::types::I22F10;

use super::{SubPoint, COORD_LIMIT_PX, SUB_BITS};

/// Fractional bits of a fine coordinate.
pub const FINE_BITS: u32 = 10;
/// One pixel in fine units.
pub const FINE_ONE: i32 = 1 << FINE_BITS;
/// Largest accepted `|coordinate|`, in fine units.
pub const FINE_LIMIT: i32 = COORD_LIMIT_PX * FINE_ONE;

/// A point on the fine grid, in units of 1/1024 px. Pixel `(i, j)` is the
/// square `[i, i+1) x [j, j+1)`; y grows downwards.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::SubPoint;
/// // The centre of pixel (3, 4) is (3.5, 4.5) px.
/// assert_eq!(FinePoint::centre_of(3, 4), FinePoint::new(3 * 1024 + 512, 4 * 1024 + 512));
/// // A 1/16-px point is the same point with six more fraction bits.
/// assert_eq!(FinePoint::from(SubPoint::new(17, -3)), FinePoint::new(17 * 64, -3 * 64));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FinePoint {
    /// x in 1/1024 px.
    pub x: i32,
    /// y in 1/1024 px.
    pub y: i32,
}

impl FinePoint {
    /// A point from fine units (1/1024 px).
    pub const fn new(x_fine: i32, y_fine: i32) -> Self {
        Self {
            x: x_fine,
            y: y_fine,
        }
    }

    /// The top-left corner of pixel `(x, y)`; saturates far outside the
    /// accepted range (such points are rejected when drawn).
    pub const fn from_px(x: i32, y: i32) -> Self {
        Self {
            x: x.saturating_mul(FINE_ONE),
            y: y.saturating_mul(FINE_ONE),
        }
    }

    /// The centre of pixel `(x, y)`: where embedded-graphics puts a
    /// primitive's `Point`s.
    pub const fn centre_of(x: i32, y: i32) -> Self {
        Self {
            x: x.saturating_mul(FINE_ONE).saturating_add(FINE_ONE / 2),
            y: y.saturating_mul(FINE_ONE).saturating_add(FINE_ONE / 2),
        }
    }

    /// A point from `fixed` numbers with 10 fractional bits (exactly this
    /// unit).
    pub fn from_fixed(x: I22F10, y: I22F10) -> Self {
        Self {
            x: x.to_bits(),
            y: y.to_bits(),
        }
    }

    /// The coordinates as `fixed` numbers, in pixels.
    pub fn to_fixed(self) -> (I22F10, I22F10) {
        (I22F10::from_bits(self.x), I22F10::from_bits(self.y))
    }

    /// True inside the accepted range, `|x|, |y| <= FINE_LIMIT`.
    pub const fn in_range(self) -> bool {
        in_fine_range(self.x) && in_fine_range(self.y)
    }
}

/// `-FINE_LIMIT <= c <= FINE_LIMIT` for one coordinate, in one unsigned
/// compare (a coordinate below the range wraps to above it).
#[inline]
pub(crate) const fn in_fine_range(c: i32) -> bool {
    (c.wrapping_add(FINE_LIMIT) as u32) <= 2 * FINE_LIMIT as u32
}

impl From<SubPoint> for FinePoint {
    /// The same point: 1/16 px is 64/1024 px, exactly.
    fn from(p: SubPoint) -> Self {
        const SHIFT: u32 = FINE_BITS - SUB_BITS;
        Self {
            x: p.x.saturating_mul(1 << SHIFT),
            y: p.y.saturating_mul(1 << SHIFT),
        }
    }
}

#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl From<embedded_graphics_core::geometry::Point> for FinePoint {
    /// The centre of the pixel `p`, as embedded-graphics' primitives read
    /// their points.
    fn from(p: embedded_graphics_core::geometry::Point) -> Self {
        Self::centre_of(p.x, p.y)
    }
}

/// Receives a path as it is described: contours of straight segments and
/// quadratic and cubic Bézier curves, in fine units.
///
/// The calls of a font parser's outline callback, of SVG path data and of
/// the shapes map onto it one to one. Every contour starts with
/// [`move_to`](Self::move_to); [`close`](Self::close) joins its last point
/// to its first (a fill closes every contour anyway; a stroke does not).
pub trait PathSink {
    /// Starts a contour at `p`.
    fn move_to(&mut self, p: FinePoint);
    /// A straight segment from the current point to `p`.
    fn line_to(&mut self, p: FinePoint);
    /// A quadratic Bézier curve from the current point to `p`, control
    /// point `c`.
    fn quad_to(&mut self, c: FinePoint, p: FinePoint);
    /// A cubic Bézier curve from the current point to `p`, control points
    /// `c1` and `c2`.
    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint);
    /// Closes the current contour.
    fn close(&mut self);

    /// Whether the sink needs closed contours clockwise on screen, as
    /// [`Shape::describe`](crate::path::Shape::describe) promises (the
    /// default). A sink that only collects points (a bounding box) says
    /// no, and a shape whose orientation costs work to find (a polygon:
    /// its signed area) may then skip it.
    fn needs_clockwise(&self) -> bool {
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_limits_are_inclusive_and_match_the_sub_pixel_grid() {
        assert!(FinePoint::new(FINE_LIMIT, -FINE_LIMIT).in_range());
        assert!(!FinePoint::new(FINE_LIMIT + 1, 0).in_range());
        let edge = SubPoint::new(super::super::COORD_LIMIT_SUB, 0);
        assert!(FinePoint::from(edge).in_range());
        assert!(!FinePoint::from_px(i32::MAX, 0).in_range());
    }

    #[test]
    fn fixed_round_trip() {
        let p = FinePoint::new(-12345, 678);
        let (x, y) = p.to_fixed();
        assert_eq!(FinePoint::from_fixed(x, y), p);
        assert_eq!(
            I22F10::from_num(2.5).to_bits(),
            FinePoint::centre_of(2, 0).x
        );
    }
}
