//! [`Degrees`]: angles of arcs, sectors and rotated ellipses.
//!
//! Takes fixed-point degrees (`fixed::types::I16F16` bits: 1/65536 degree,
//! `|angle| < 32768` degrees) or embedded-graphics' `Angle`; gives the
//! binary angles the set-up computes with (`2^32` units per turn, `i64`
//! so that sweeps of several turns keep their sign and size).
//!
//! Angles run **clockwise on screen from the +x axis** (y grows downwards,
//! so the point at angle `a` on a circle of radius `r` is
//! `(r cos a, r sin a)`): 90 degrees points down. This is
//! embedded-graphics' convention (its `Arc` from 0 with a sweep of +90
//! degrees is the bottom-right quarter).
//!
//! Conversion to binary units is `bits * 2^32 / (360 * 2^16)` rounded:
//! within `2^-33` turn (`7.3e-10` rad, `0.0015` fine units on a radius of
//! 2048 px).

use fixed::types::I16F16;

/// An angle in fixed-point degrees, 1/65536 degree per unit, clockwise on
/// screen from the +x axis.
///
/// ```
/// use softedge::path::Degrees;
/// assert_eq!(Degrees::new(90).bits(), 90 << 16);
/// assert_eq!(Degrees::from_fixed(fixed::types::I16F16::from_num(22.5)), Degrees::from_bits(22 << 16 | 1 << 15));
/// assert_eq!(Degrees::new(100_000), Degrees::MAX); // saturates
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, PartialOrd, Ord)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Degrees(i32);

impl Degrees {
    /// The largest angle, just below 32768 degrees.
    pub const MAX: Degrees = Degrees(i32::MAX);
    /// The smallest angle, `-MAX` (saturation is symmetric).
    pub const MIN: Degrees = Degrees(-i32::MAX);
    /// Zero.
    pub const ZERO: Degrees = Degrees(0);
    /// One full turn.
    pub const TURN: Degrees = Degrees(360 << 16);

    /// `deg` whole degrees; saturates beyond `+-32767`.
    pub const fn new(deg: i32) -> Self {
        let bits = deg.saturating_mul(1 << 16);
        Degrees(if bits < -i32::MAX { -i32::MAX } else { bits })
    }

    /// An angle from its bits, 1/65536 degree each.
    pub const fn from_bits(bits: i32) -> Self {
        Degrees(bits)
    }

    /// An angle from fixed-point degrees.
    pub fn from_fixed(deg: I16F16) -> Self {
        Degrees(deg.to_bits())
    }

    /// The bits, 1/65536 degree each.
    pub const fn bits(self) -> i32 {
        self.0
    }

    /// The angle in fixed-point degrees.
    pub fn to_fixed(self) -> I16F16 {
        I16F16::from_bits(self.0)
    }

    /// The angle in binary units (`2^32` per turn), rounded.
    pub(crate) fn binary(self) -> i64 {
        // bits * 2^32 / (360 * 2^16) = bits * 2^16 / 360.
        let n = i64::from(self.0) << 16;
        super::vector::div_round_i64(n, 360)
    }

    /// The angle of `radians` given as the bits of an IEEE-754 single
    /// (what embedded-graphics stores), decoded with integer operations
    /// only; saturates beyond `+-32768` degrees, NaN gives zero.
    pub fn from_f32_radians_bits(bits: u32) -> Self {
        let negative = bits >> 31 == 1;
        let exp = ((bits >> 23) & 0xff) as i32;
        let frac = i128::from(bits & 0x7f_ffff);
        if exp == 0xff {
            // Infinity saturates; NaN has no angle.
            return match (frac == 0, negative) {
                (true, false) => Degrees::MAX,
                (true, true) => Degrees::MIN,
                _ => Degrees::ZERO,
            };
        }
        // value = m * 2^(e - 150) with the implicit leading one for normals.
        let (m, e) = if exp == 0 {
            (frac, -149)
        } else {
            (frac | 1 << 23, exp - 150)
        };
        // degree bits = value * 180 / pi * 2^16 = m * K * 2^(e - 64) with
        // K = 180 * 2^80 / pi, i.e. 180 * 2^141 / PI_Q61 (below 2^86).
        let k = ((180i128 << 100) / i128::from(super::trig::PI_Q61)) << 41;
        let prod = m * k; // below 2^24 * 2^86 = 2^110
        let shift = e - 64;
        let v = if shift >= 0 {
            if shift > 20 {
                i128::MAX
            } else {
                prod.saturating_mul(1 << shift)
            }
        } else if shift < -120 {
            0
        } else {
            let s = (-shift) as u32;
            (prod + (1i128 << (s - 1))) >> s
        };
        let v = v.min(i128::from(i32::MAX));
        let v = if negative { -v } else { v };
        Degrees(v as i32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_units_of_common_angles() {
        assert_eq!(Degrees::new(90).binary(), 1 << 30);
        assert_eq!(Degrees::new(-180).binary(), -(1 << 31));
        assert_eq!(Degrees::new(360).binary(), 1 << 32);
        assert_eq!(Degrees::new(30).binary(), ((1i64 << 32) + 6) / 12);
    }

    #[test]
    fn f32_radians_decode_to_degrees() {
        let cases = [
            0.0f32,
            1.0,
            -1.0,
            core::f32::consts::PI,
            0.5e-3,
            100.0,
            -2.5,
            1e-40,
        ];
        for r in cases {
            let d = Degrees::from_f32_radians_bits(r.to_bits());
            let want = f64::from(r).to_degrees() * 65536.0;
            assert!(
                (f64::from(d.bits()) - want).abs() <= 1.0,
                "{r}: {} vs {want}",
                d.bits()
            );
        }
        assert_eq!(
            Degrees::from_f32_radians_bits(f32::INFINITY.to_bits()),
            Degrees::MAX
        );
        assert_eq!(
            Degrees::from_f32_radians_bits(f32::NAN.to_bits()),
            Degrees::ZERO
        );
        assert_eq!(
            Degrees::from_f32_radians_bits(1e30f32.to_bits()),
            Degrees::MAX
        );
        assert_eq!(
            Degrees::from_f32_radians_bits((-1e30f32).to_bits()),
            Degrees::MIN
        );
    }
}
