//! Points, vectors and unit normals of the path set-up.
//!
//! Takes fine-grid points ([`FinePoint`], 1/1024 px, `i32`); gives the
//! set-up's working types: [`Pt`], a point or vector in fine units held in
//! `i64` (so sums, offsets and out-of-range intermediate points never
//! overflow), and [`Unit`], a direction as a unit vector in Q30
//! (`|u| = 2^30` within one unit).
//!
//! ## Ranges
//!
//! Every `Pt` the path code makes has `|x|, |y| < 2^40` (inputs are `i32`,
//! shapes add radii below `2^24`, strokes offsets below `2^23`), so a
//! `cross` or `dot` of two differences stays below `2^82` and is taken in
//! `i128`. Unit vectors come from [`Pt::unit`], which first scales the
//! vector down below `2^31` per component: the direction keeps 30 bits.

use crate::geom::FinePoint;

use super::trig::{round_shift, Q30};
use crate::arith::{isqrt_u64, mul_i128, mul_i64, mul_wide};

/// A point or vector in fine units (1/1024 px), in `i64`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Pt {
    pub x: i64,
    pub y: i64,
}

impl Pt {
    pub const fn new(x: i64, y: i64) -> Self {
        Self { x, y }
    }

    pub fn add(self, o: Pt) -> Pt {
        Pt::new(self.x + o.x, self.y + o.y)
    }

    pub fn sub(self, o: Pt) -> Pt {
        Pt::new(self.x - o.x, self.y - o.y)
    }

    /// `self x o = x1 y2 - y1 x2`; positive when `o` turns clockwise on
    /// screen (y down) from `self`.
    pub fn cross(self, o: Pt) -> i128 {
        mul_i128(self.x, o.y) - mul_i128(self.y, o.x)
    }

    pub fn dot(self, o: Pt) -> i128 {
        mul_i128(self.x, o.x) + mul_i128(self.y, o.y)
    }

    pub fn is_zero(self) -> bool {
        self.x == 0 && self.y == 0
    }

    /// `floor(|self|)` for vectors below `2^31` per component (the stroker
    /// clips its input so that every piece is), else a lower bound.
    pub fn len(self) -> i64 {
        let (x, y) = (self.x.unsigned_abs(), self.y.unsigned_abs());
        if x < 1 << 31 && y < 1 << 31 {
            isqrt_u64(mul_wide(x as u32, x as u32) + mul_wide(y as u32, y as u32)) as i64
        } else {
            // Scale down by 2^k, root, scale back: off by at most 2^k.
            let mut k = 0;
            let (mut sx, mut sy) = (x, y);
            while sx >= 1 << 31 || sy >= 1 << 31 {
                sx >>= 1;
                sy >>= 1;
                k += 1;
            }
            ((sx * sx + sy * sy).isqrt() << k) as i64
        }
    }

    /// The direction of `self` as a unit vector, `None` for the zero vector.
    pub fn unit(self) -> Option<Unit> {
        if self.is_zero() {
            return None;
        }
        let (mut x, mut y) = (self.x, self.y);
        // Below 2^31 per component, then up to at least 2^29 so the
        // quotient keeps its bits.
        while x.unsigned_abs() >= 1 << 31 || y.unsigned_abs() >= 1 << 31 {
            x >>= 1;
            y >>= 1;
        }
        while x.unsigned_abs() < 1 << 29 && y.unsigned_abs() < 1 << 29 {
            x <<= 1;
            y <<= 1;
        }
        // |x|, |y| < 2^31: the squares as u32 x u32 products.
        let (ax, ay) = (x.unsigned_abs() as u32, y.unsigned_abs() as u32);
        let len = isqrt_u64(mul_wide(ax, ax) + mul_wide(ay, ay)) as i64;
        if len == 0 {
            return None;
        }
        // |x| << 30 < 2^61: no overflow.
        Some(Unit {
            x: div_round_i64(x << 30, len),
            y: div_round_i64(y << 30, len),
        })
    }

    /// The nearest point inside `i32` (coordinates saturate).
    pub fn to_fine(self) -> FinePoint {
        FinePoint::new(sat_i32(self.x), sat_i32(self.y))
    }

    /// `self + u * h / 2^s` with the product rounded (`u` Q30, so
    /// `s = 30` offsets by `h` fine units and `s = 31` by `h / 2`).
    pub fn offset(self, u: Unit, h: i64, s: u32) -> Pt {
        Pt::new(
            self.x + round_shift(mul_i64(u.x, h), s),
            self.y + round_shift(mul_i64(u.y, h), s),
        )
    }
}

impl From<FinePoint> for Pt {
    fn from(p: FinePoint) -> Self {
        Pt::new(i64::from(p.x), i64::from(p.y))
    }
}

/// `v` limited to the `i32` range.
pub(crate) fn sat_i32(v: i64) -> i32 {
    v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

/// `n / d` rounded, halves away from zero, `d > 0`; 0 for `d <= 0`.
pub(crate) fn div_round_i64(n: i64, d: i64) -> i64 {
    if d <= 0 {
        return 0;
    }
    if n >= 0 {
        (n + d / 2) / d
    } else {
        -((d / 2 - n) / d)
    }
}

/// A direction: a unit vector in Q30 (`x^2 + y^2 = 2^60` within rounding).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Unit {
    pub x: i64,
    pub y: i64,
}

impl Unit {
    /// The direction `(cos t, sin t)` of a binary angle.
    pub fn from_angle(t: u32) -> Unit {
        let (c, s) = super::trig::cos_sin(t);
        Unit { x: c, y: s }
    }

    /// This direction turned a quarter clockwise on screen (y down):
    /// the right-hand normal of a path running along `self`.
    pub fn right(self) -> Unit {
        Unit {
            x: -self.y,
            y: self.x,
        }
    }

    /// `self . o` in Q30.
    pub fn dot(self, o: Unit) -> i64 {
        (mul_i64(self.x, o.x) + mul_i64(self.y, o.y)) >> 30
    }

    /// `self x o` in Q30: `sin` of the clockwise turn from `self` to `o`.
    pub fn cross(self, o: Unit) -> i64 {
        (mul_i64(self.x, o.y) - mul_i64(self.y, o.x)) >> 30
    }
}

/// The unit `x` direction.
pub(crate) const UNIT_X: Unit = Unit { x: Q30, y: 0 };

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_vectors_have_length_one_in_q30() {
        for v in [
            Pt::new(3, 4),
            Pt::new(-1, 0),
            Pt::new(1 << 40, -(1 << 39)),
            Pt::new(7, -1_000_000_007),
        ] {
            let u = v.unit().unwrap_or_default();
            let l2 = (u.x as f64).hypot(u.y as f64);
            assert!((l2 - Q30 as f64).abs() < 2.0, "{v:?} {u:?}");
        }
        assert_eq!(Pt::new(0, 0).unit(), None);
        assert_eq!(Pt::new(5, 0).unit(), Some(UNIT_X));
    }

    #[test]
    fn right_normal_points_down_for_a_path_to_the_right() {
        assert_eq!(UNIT_X.right(), Unit { x: 0, y: Q30 });
        assert!(Pt::new(1, 0).cross(Pt::new(0, 1)) > 0);
    }

    #[test]
    fn lengths_are_floors() {
        assert_eq!(Pt::new(3, 4).len(), 5);
        assert_eq!(Pt::new(1, 1).len(), 1);
        assert_eq!(Pt::new(-(1 << 20), 0).len(), 1 << 20);
    }
}
