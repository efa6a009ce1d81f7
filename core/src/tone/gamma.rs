//! The γ-correction table: linear 12-bit intensity → display code (eq. 7).
//!
//! A display shows `B = B_min + (B_max - B_min) * V^γ` for a code
//! `V = code / max` (seed 000, eqs. 6 and 14, the stray light `B_min` included;
//! contrast `K = B_max / B_min`). Antialiasing needs brightness linear in the
//! accumulated intensity `I` (eq. 8, `B = B_min + k * I`), so the table sends
//! `V = I^(1/γ)` (eq. 7). Solving eq. 14 = eq. 8 for `V` leaves `K` out:
//! the linear-code table is the same for every contrast; `K` decides how
//! many bits the linear code and the DAC need ([`bits`](super::bits)) and
//! shapes the logarithmic code ([`log_code`](super::log_code)).
//!
//! Tables are built by a `const fn` from the formula (fixed-point
//! `log2`/`exp2`, no floats), so `static LUT: GammaLut = GammaLut::new(..)`
//! puts one in flash, or it can be built at start-up into RAM.

use super::fixpow::{self, ONE, VALUE_FRAC};
use super::{lin12_index, LIN_LEN, LIN_MAX};

/// A display exponent `γ = num / den`, both non-zero.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Gamma {
    num: u16,
    den: u16,
}

impl Gamma {
    /// `γ = 2.2`, the usual PC / TFT panel.
    pub const G2_2: Gamma = Gamma { num: 11, den: 5 };
    /// `γ = 2.4`, the CRT exponent of seed 000 (and BT.1886).
    pub const G2_4: Gamma = Gamma { num: 12, den: 5 };

    /// `γ = num / den`, or `None` when either is zero.
    ///
    /// ```
    /// # use softedge::tone::Gamma;
    /// assert_eq!(Gamma::new(12, 5), Some(Gamma::G2_4));
    /// assert_eq!(Gamma::new(0, 5), None);
    /// ```
    pub const fn new(num: u16, den: u16) -> Option<Gamma> {
        if num == 0 || den == 0 {
            return None;
        }
        // Reduce, so equal exponents compare equal.
        let (mut a, mut b) = (num, den);
        while b != 0 {
            let t = a % b;
            a = b;
            b = t;
        }
        Some(Gamma {
            num: num / a,
            den: den / a,
        })
    }

    /// Numerator and denominator of `γ`, in lowest terms.
    ///
    /// ```
    /// # use softedge::tone::Gamma;
    /// assert_eq!(Gamma::G2_2.ratio(), (11, 5));
    /// ```
    pub const fn ratio(self) -> (u16, u16) {
        (self.num, self.den)
    }
}

/// The transfer curve of a display: how its code becomes light.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Curve {
    /// `B = V^γ` (eq. 6); the table sends `V = I^(1/γ)` (eq. 7).
    Power(Gamma),
    /// The sRGB curve (IEC 61966-2-1): `B = V / 12.92` for `V <= 0.04045`,
    /// else `((V + 0.055) / 1.055)^2.4`; the table sends its inverse,
    /// `V = 12.92 * I` for `I <= 0.0031308`, else `1.055 * I^(1/2.4) - 0.055`.
    Srgb,
}

impl Curve {
    /// `γ = 2.2`.
    pub const GAMMA_2_2: Curve = Curve::Power(Gamma::G2_2);
    /// `γ = 2.4` (seed 000).
    pub const GAMMA_2_4: Curve = Curve::Power(Gamma::G2_4);
}

/// sRGB constants as exact ratios (IEC 61966-2-1).
mod srgb {
    /// Linear-segment limit `0.0031308 = 31308 / 10^7`.
    pub const LIN_LIMIT: (u128, u128) = (31_308, 10_000_000);
    /// Slope `12.92 = 323 / 25`.
    pub const SLOPE: (u128, u128) = (323, 25);
    /// Scale `1.055 = 211 / 200`.
    pub const SCALE: (u128, u128) = (211, 200);
    /// Offset `0.055 = 11 / 200`.
    pub const OFFSET: (u128, u128) = (11, 200);
    /// Exponent `1 / 2.4 = 5 / 12`.
    pub const INV_GAMMA: (u32, u32) = (5, 12);
}

/// The code value `V` (Q62) that makes the display emit the linear light `x`
/// (Q62, in `[0, 1]`): the inverse of the curve.
pub(crate) const fn encode(curve: Curve, x: u128) -> u128 {
    let x = if x > ONE { ONE } else { x };
    match curve {
        Curve::Power(g) => {
            let (num, den) = g.ratio();
            // V = x^(1/γ) = x^(den / num)   (eq. 7)
            fixpow::pow_frac(x, den as u32, num as u32)
        }
        Curve::Srgb => {
            // x * 10^7 < 2^63 * 2^24: no overflow.
            if x * srgb::LIN_LIMIT.1 <= srgb::LIN_LIMIT.0 * ONE {
                x * srgb::SLOPE.0 / srgb::SLOPE.1
            } else {
                let p = fixpow::pow_frac(x, srgb::INV_GAMMA.0, srgb::INV_GAMMA.1);
                let v = p * srgb::SCALE.0 / srgb::SCALE.1;
                let off = ONE * srgb::OFFSET.0 / srgb::OFFSET.1;
                v.saturating_sub(off)
            }
        }
    }
}

/// γ-correction table: linear 12-bit intensity → display code of `bits`
/// bits (1..=8), `code = round(max * V(I / 4095))` with `V` the inverse of
/// the display [`Curve`] (eq. 7 for a power curve) and `max = 2^bits - 1`.
///
/// Endpoints are exact (`0 → 0`, `4095 → max`) and the table is monotone;
/// every entry is the correctly rounded formula value except where the
/// formula lies within `~1e-9` of a rounding midpoint.
/// Intensities above 4095 are clamped to 4095.
///
/// ```
/// # use softedge::tone::{Curve, GammaLut};
/// static LUT: GammaLut = GammaLut::new(Curve::GAMMA_2_4);
/// assert_eq!(LUT.code(0), 0);
/// assert_eq!(LUT.code(4095), 255);
/// // Half the light is code 255 * 0.5^(1/2.4) = 191.0 on a γ = 2.4 display.
/// assert_eq!(LUT.code(2048), 191);
/// assert_eq!(LUT.code(60_000), 255); // clamped
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GammaLut {
    codes: [u8; LIN_LEN],
    max: u8,
}

impl GammaLut {
    /// The 8-bit table for `curve`.
    pub const fn new(curve: Curve) -> Self {
        Self::with_bits(curve, 8)
    }

    /// The table for `curve` with codes of `bits` bits, built directly for
    /// that depth (one rounding). `bits` outside `1..=8` is clamped.
    ///
    /// ```
    /// # use softedge::tone::{Curve, GammaLut};
    /// let g4 = GammaLut::with_bits(Curve::Srgb, 4);
    /// assert_eq!(g4.max_code(), 15);
    /// assert_eq!(g4.code(4095), 15);
    /// ```
    pub const fn with_bits(curve: Curve, bits: u8) -> Self {
        let bits = if bits < 1 {
            1
        } else if bits > 8 {
            8
        } else {
            bits
        };
        let max = ((1u16 << bits) - 1) as u8;
        let mut codes = [0u8; LIN_LEN];
        let mut i = 1;
        while i < LIN_LEN {
            // x = i / 4095 in Q62; i < 2^12, so i << 62 < 2^74.
            let x = ((i as u128) << VALUE_FRAC) / LIN_MAX as u128;
            codes[i] = fixpow::round_to(encode(curve, x), max as u32) as u8;
            i += 1;
        }
        GammaLut { codes, max }
    }

    /// The display code for a linear 12-bit intensity (clamped to 4095).
    #[inline]
    pub fn code(&self, lin12: u16) -> u8 {
        self.codes[lin12_index(lin12)]
    }

    /// The largest code, `2^bits - 1`.
    ///
    /// ```
    /// # use softedge::tone::{Curve, GammaLut};
    /// assert_eq!(GammaLut::new(Curve::Srgb).max_code(), 255);
    /// ```
    pub const fn max_code(&self) -> u8 {
        self.max
    }

    /// The whole table, indexed by linear 12-bit intensity.
    ///
    /// ```
    /// # use softedge::tone::{Curve, GammaLut};
    /// let lut = GammaLut::new(Curve::GAMMA_2_2);
    /// assert!(lut.codes().windows(2).all(|w| w[0] <= w[1]));
    /// ```
    pub const fn codes(&self) -> &[u8; LIN_LEN] {
        &self.codes
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoints_are_exact_for_every_depth() {
        for curve in [Curve::GAMMA_2_2, Curve::GAMMA_2_4, Curve::Srgb] {
            for bits in 1..=8 {
                let lut = GammaLut::with_bits(curve, bits);
                assert_eq!(lut.code(0), 0);
                assert_eq!(lut.code(LIN_MAX), lut.max_code());
                assert_eq!(u32::from(lut.max_code()), (1 << bits) - 1);
            }
        }
    }

    #[test]
    fn srgb_linear_segment_is_exact() {
        // I = 10: x = 10/4095 < 0.0031308, V = 12.92 x, code = round(255 V) = 8.
        let lut = GammaLut::new(Curve::Srgb);
        assert_eq!(lut.code(10), 8);
    }

    #[test]
    fn gamma_is_reduced() {
        assert_eq!(Gamma::new(24, 10), Gamma::new(12, 5));
        assert_eq!(Gamma::G2_4.ratio(), (12, 5));
    }
}
