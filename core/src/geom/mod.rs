//! Geometry in: sub-pixel fixed-point vertex positions.
//!
//! Takes pixel or sub-pixel coordinates from the caller, gives [`SubPoint`]s
//! in units of 1/16 px (4 fractional bits, `SUB_BITS`). Pixel `(i, j)` is the
//! square `[i, i+1) x [j, j+1)`; its centre is `(i + 1/2, j + 1/2)`; y grows
//! downwards.
//!
//! ## Range
//!
//! Every coordinate must lie in `[-COORD_LIMIT_PX, COORD_LIMIT_PX]` pixels,
//! i.e. `|x_sub|, |y_sub| <= 2048 * 16 = 2^15`. An edge then spans at most
//! `2^16` sub-pixel units per axis, so the per-edge products of the setup
//! (`dx * dy * 2^8`, the largest being the area numerators) stay below
//! `2^48` in `i64`, and the per-pixel state of the walk stays in `i32`
//! (positions, remainders) and `i64` (the `I * S` products). Primitives with
//! a vertex outside the range are rejected with [`CoordError`]; parts of a
//! primitive inside the range but outside the frame are clipped.

use fixed::types::I28F4;

mod errors;
mod fine;

pub(crate) use fine::in_fine_range;
pub use fine::{FinePoint, PathSink, FINE_BITS, FINE_LIMIT, FINE_ONE};

/// Fractional bits of a sub-pixel coordinate.
pub const SUB_BITS: u32 = 4;
/// One pixel in sub-pixel units.
pub const SUB_ONE: i32 = 1 << SUB_BITS;
/// Largest accepted `|coordinate|`, in pixels.
pub const COORD_LIMIT_PX: i32 = 2048;
/// Largest accepted `|coordinate|`, in sub-pixel units.
pub const COORD_LIMIT_SUB: i32 = COORD_LIMIT_PX * SUB_ONE;

/// A vertex position in sub-pixel units (1/16 px).
///
/// ```
/// use softedge::SubPoint;
/// let p = SubPoint::new(10 * 16 + 4, 3 * 16 + 8); // (10.25, 3.5) px
/// assert_eq!(p, SubPoint::from_fixed(fixed::types::I28F4::from_num(10.25), fixed::types::I28F4::from_num(3.5)));
/// assert_eq!(SubPoint::from_px(2, 1), SubPoint::new(32, 16));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct SubPoint {
    /// x in 1/16 px.
    pub x: i32,
    /// y in 1/16 px.
    pub y: i32,
}

/// A vertex outside `[-COORD_LIMIT_PX, COORD_LIMIT_PX]`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct CoordError {
    /// The offending vertex.
    pub point: SubPoint,
}

impl SubPoint {
    /// A point from sub-pixel units (1/16 px).
    pub const fn new(x_sub: i32, y_sub: i32) -> Self {
        Self { x: x_sub, y: y_sub }
    }

    /// A point at the top-left corner of pixel `(x, y)`.
    ///
    /// Coordinates beyond `i32::MAX / 16` saturate; they are outside the
    /// accepted range anyway and are rejected when drawn.
    pub const fn from_px(x: i32, y: i32) -> Self {
        Self {
            x: x.saturating_mul(SUB_ONE),
            y: y.saturating_mul(SUB_ONE),
        }
    }

    /// A point from `fixed` numbers with 4 fractional bits (exactly our unit).
    pub fn from_fixed(x: I28F4, y: I28F4) -> Self {
        Self {
            x: x.to_bits(),
            y: y.to_bits(),
        }
    }

    /// Checks the documented coordinate range.
    pub const fn check(self) -> Result<Self, CoordError> {
        if self.x >= -COORD_LIMIT_SUB
            && self.x <= COORD_LIMIT_SUB
            && self.y >= -COORD_LIMIT_SUB
            && self.y <= COORD_LIMIT_SUB
        {
            Ok(self)
        } else {
            Err(CoordError { point: self })
        }
    }
}

#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl From<embedded_graphics_core::geometry::Point> for SubPoint {
    /// The top-left corner of the pixel `p`.
    fn from(p: embedded_graphics_core::geometry::Point) -> Self {
        Self::from_px(p.x, p.y)
    }
}

/// Twice the signed area of a closed polygon, in sub-pixel units squared
/// (positive when the vertices run clockwise on screen, y down).
pub(crate) fn area2(vertices: &[SubPoint]) -> i64 {
    let n = vertices.len();
    let mut sum = 0i64;
    for k in 0..n {
        let a = vertices[k];
        let b = vertices[(k + 1) % n];
        sum += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
    }
    sum
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn range_limits_are_inclusive() {
        assert!(SubPoint::new(COORD_LIMIT_SUB, -COORD_LIMIT_SUB)
            .check()
            .is_ok());
        assert!(SubPoint::new(COORD_LIMIT_SUB + 1, 0).check().is_err());
        assert!(SubPoint::new(0, -COORD_LIMIT_SUB - 1).check().is_err());
        assert!(SubPoint::from_px(i32::MAX, 0).check().is_err());
    }

    #[test]
    fn clockwise_square_has_positive_area2() {
        let sq = [
            SubPoint::from_px(0, 0),
            SubPoint::from_px(10, 0),
            SubPoint::from_px(10, 10),
            SubPoint::from_px(0, 10),
        ];
        assert_eq!(area2(&sq), 2 * 160 * 160);
    }
}
