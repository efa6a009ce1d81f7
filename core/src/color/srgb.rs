//! The sRGB decoding tables: display code → linear 12-bit intensity, and
//! the Rec. 709 luminance of a linear RGB triple.
//!
//! A code `c` of an `n`-bit channel stands for `V = c / (2^n - 1)`; the sRGB
//! curve (IEC 61966-2-1) gives its linear light
//!
//! ```text
//! L(V) = V / 12.92                     for V <= 0.04045
//! L(V) = ((V + 0.055) / 1.055)^2.4     otherwise
//! ```
//!
//! and the table holds `lin12 = round(4095 * L(V))`, halves up. The linear
//! segment is computed in exact rationals (`4095 * 25 c / (323 max)`); the
//! power segment in the Q62 fixed point of [`tone`](crate::tone)'s table
//! builder (`log2`, then `exp2` of `12/5` of it), whose error, below
//! `1e-8` relative, moves no entry: the tests compare every entry with the
//! `f64` formula. `0 → 0` and `max → 4095` exactly; every table is
//! monotone.
//!
//! Built by `const fn`s at compile time, so they live in flash; per pixel a
//! conversion is one look-up per channel.

use crate::shade::LIN_MAX;
use crate::tone::fixpow::{self, VALUE_FRAC};

/// sRGB constants as exact ratios (IEC 61966-2-1).
mod iec {
    /// End of the linear segment on the code side, `0.04045 = 4045 / 10^5`.
    pub const CODE_LIMIT: (u64, u64) = (4_045, 100_000);
    /// Slope of the linear segment, `12.92 = 323 / 25`.
    pub const SLOPE: (u64, u64) = (323, 25);
    /// Offset `0.055 = 11 / 200`.
    pub const OFFSET: (u64, u64) = (11, 200);
    /// Scale `1.055 = 211 / 200` (same denominator as the offset).
    pub const SCALE: (u64, u64) = (211, 200);
    /// Exponent `2.4 = 12 / 5`.
    pub const GAMMA: (u32, u32) = (12, 5);
}

/// `round(4095 * L(code / max))`, halves up, for `code <= max`, `max >= 1`
/// (a larger `code` is clamped to `max`; `max = 0` gives 0).
///
/// ```
/// use softedge::color::srgb::srgb_to_lin12;
/// assert_eq!(srgb_to_lin12(0, 255), 0);
/// assert_eq!(srgb_to_lin12(128, 255), 884); // 4095 * 0.21586 = 883.95
/// assert_eq!(srgb_to_lin12(255, 255), 4095);
/// ```
pub const fn srgb_to_lin12(code: u32, max: u32) -> u16 {
    if max == 0 {
        return 0;
    }
    let c = if code > max { max } else { code } as u64;
    let m = max as u64;
    let lin_max = LIN_MAX as u64;
    // V <= 0.04045  <=>  c * 10^5 <= 4045 * max   (c, max < 2^32: no overflow)
    if c * iec::CODE_LIMIT.1 <= iec::CODE_LIMIT.0 * m {
        // 4095 * V / 12.92 = 4095 * 25 c / (323 max), rounded half up:
        // floor((2 * 4095 * 25 c + 323 max) / (2 * 323 max)).
        let num = 2 * lin_max * iec::SLOPE.1 * c + iec::SLOPE.0 * m;
        let den = 2 * iec::SLOPE.0 * m;
        return (num / den) as u16;
    }
    // y = (V + 0.055) / 1.055 = (200 c + 11 max) / (211 max), in Q62;
    // the numerator is below 2^41, shifted below 2^103.
    let num = (iec::OFFSET.1 * c + iec::OFFSET.0 * m) as u128;
    let den = (iec::SCALE.0 * m) as u128;
    let y = (num << VALUE_FRAC) / den;
    let l = fixpow::pow_frac(y, iec::GAMMA.0, iec::GAMMA.1);
    fixpow::round_to(l, LIN_MAX as u32) as u16
}

/// The table of an `N`-entry channel (`N = 2^bits`): entry `c` is
/// [`srgb_to_lin12`]`(c, N - 1)`.
const fn table<const N: usize>() -> [u16; N] {
    let mut t = [0u16; N];
    let mut c = 0;
    while c < N {
        t[c] = srgb_to_lin12(c as u32, (N - 1) as u32);
        c += 1;
    }
    t
}

/// 8-bit sRGB code (Rgb888, Gray8, `#rrggbb`) → linear 12-bit:
/// `round(4095 * L(c / 255))`, halves up.
///
/// ```
/// use softedge::color::SRGB8_TO_LIN12;
/// assert_eq!([SRGB8_TO_LIN12[0], SRGB8_TO_LIN12[128], SRGB8_TO_LIN12[255]], [0, 884, 4095]);
/// ```
pub const SRGB8_TO_LIN12: [u16; 256] = table::<256>();
/// 6-bit sRGB code (Rgb565's green, Rgb666) → linear 12-bit:
/// `round(4095 * L(c / 63))`, halves up.
///
/// ```
/// use softedge::color::SRGB6_TO_LIN12;
/// assert_eq!([SRGB6_TO_LIN12[32], SRGB6_TO_LIN12[63]], [907, 4095]);
/// ```
pub const SRGB6_TO_LIN12: [u16; 64] = table::<64>();
/// 5-bit sRGB code (Rgb565's red and blue, Rgb555) → linear 12-bit:
/// `round(4095 * L(c / 31))`, halves up.
///
/// ```
/// use softedge::color::SRGB5_TO_LIN12;
/// assert_eq!([SRGB5_TO_LIN12[16], SRGB5_TO_LIN12[31]], [939, 4095]);
/// ```
pub const SRGB5_TO_LIN12: [u16; 32] = table::<32>();
/// 4-bit sRGB code (Gray4) → linear 12-bit: `round(4095 * L(c / 15))`,
/// halves up.
///
/// ```
/// use softedge::color::SRGB4_TO_LIN12;
/// assert_eq!([SRGB4_TO_LIN12[8], SRGB4_TO_LIN12[15]], [1008, 4095]);
/// ```
pub const SRGB4_TO_LIN12: [u16; 16] = table::<16>();
/// 2-bit sRGB code (Gray2) → linear 12-bit: `round(4095 * L(c / 3))`,
/// halves up.
///
/// ```
/// use softedge::color::SRGB2_TO_LIN12;
/// assert_eq!(SRGB2_TO_LIN12, [0, 372, 1646, 4095]);
/// ```
pub const SRGB2_TO_LIN12: [u16; 4] = table::<4>();

/// Fraction bits of the luminance weights.
///
/// ```
/// use softedge::color::srgb::{LUMA_BITS, LUMA_WEIGHTS};
/// assert_eq!(LUMA_WEIGHTS.iter().sum::<u32>(), 1 << LUMA_BITS);
/// ```
pub const LUMA_BITS: u32 = 16;

/// One Rec. 709 weight (`w / 10^4`) in units of `2^-16`, rounded to nearest.
const fn luma_weight(w_1e4: u32) -> u32 {
    (w_1e4 * (1 << LUMA_BITS) + 5_000) / 10_000
}

/// The Rec. 709 (and sRGB) luminance weights 0.2126, 0.7152, 0.0722 of R, G
/// and B in units of `2^-16`, each rounded to nearest: 13933, 46871, 4732.
/// They add up to exactly `2^16` (checked at compile time), so a gray
/// `[v, v, v]` has luminance `v`; each is within `5.4e-6` of the exact weight.
pub const LUMA_WEIGHTS: [u32; 3] = [luma_weight(2_126), luma_weight(7_152), luma_weight(722)];

const _: () = assert!(LUMA_WEIGHTS[0] + LUMA_WEIGHTS[1] + LUMA_WEIGHTS[2] == 1 << LUMA_BITS);

/// `v` clamped to 4095, widened.
const fn clamp12(v: u16) -> u32 {
    (if v > LIN_MAX { LIN_MAX } else { v }) as u32
}

/// The linear luminance of a linear 12-bit RGB triple:
/// `Y = (13933 R + 46871 G + 4732 B + 2^15) >> 16`, i.e. `Y` rounded to
/// nearest (halves up) with the weights of [`LUMA_WEIGHTS`]. Channels above
/// 4095 are clamped first, so `Y <= 4095`; the sum stays below `2^28`.
///
/// ```
/// use softedge::color::srgb::luminance;
/// assert_eq!(luminance([4095, 0, 0]), 871); // 0.2126 * 4095 = 870.6
/// assert_eq!(luminance([0, 4095, 0]), 2929);
/// assert_eq!(luminance([0, 0, 4095]), 296);
/// assert_eq!(luminance([1234; 3]), 1234);
/// ```
pub const fn luminance([r, g, b]: [u16; 3]) -> u16 {
    let sum =
        LUMA_WEIGHTS[0] * clamp12(r) + LUMA_WEIGHTS[1] * clamp12(g) + LUMA_WEIGHTS[2] * clamp12(b);
    ((sum + (1 << (LUMA_BITS - 1))) >> LUMA_BITS) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoints_are_exact() {
        assert_eq!(SRGB8_TO_LIN12[0], 0);
        assert_eq!(SRGB8_TO_LIN12[255], LIN_MAX);
        assert_eq!(SRGB6_TO_LIN12[63], LIN_MAX);
        assert_eq!(SRGB5_TO_LIN12[31], LIN_MAX);
        assert_eq!(SRGB4_TO_LIN12[15], LIN_MAX);
        assert_eq!(SRGB2_TO_LIN12[3], LIN_MAX);
    }

    #[test]
    fn tables_are_strictly_increasing() {
        for t in [
            &SRGB8_TO_LIN12[..],
            &SRGB6_TO_LIN12[..],
            &SRGB5_TO_LIN12[..],
            &SRGB4_TO_LIN12[..],
            &SRGB2_TO_LIN12[..],
        ] {
            assert!(t.windows(2).all(|w| w[0] < w[1]));
        }
    }

    #[test]
    fn linear_segment_is_exact() {
        // c = 10: V = 10/255 = 0.0392 <= 0.04045; 4095 * 250 / 3294.6 = 12.43.
        assert_eq!(SRGB8_TO_LIN12[10], 12);
        // c = 1: 4095 / 3294.6 = 1.243.
        assert_eq!(SRGB8_TO_LIN12[1], 1);
        // c = 11 is past the segment: ((11/255 + 0.055) / 1.055)^2.4 * 4095 = 13.70.
        assert_eq!(SRGB8_TO_LIN12[11], 14);
    }

    #[test]
    fn the_code_past_max_is_clamped() {
        assert_eq!(srgb_to_lin12(300, 255), LIN_MAX);
        assert_eq!(srgb_to_lin12(5, 0), 0);
    }

    #[test]
    fn luminance_weights_are_rec_709() {
        assert_eq!(LUMA_WEIGHTS, [13_933, 46_871, 4_732]);
        assert_eq!(luminance([4095; 3]), 4095);
        assert_eq!(luminance([u16::MAX; 3]), 4095);
        assert_eq!(luminance([0; 3]), 0);
    }
}
