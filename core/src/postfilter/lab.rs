//! Linear RGB (12 bits, sRGB primaries, D65) to CIELAB and back, in fixed
//! point.
//!
//! A colour is held as its three cube-root values ([`Lab`]):
//! `fx = f(X/Xn)`, `fy = f(Y/Yn)`, `fz = f(Z/Zn)`, in units of
//! `1 / F_ONE`. CIELAB is a linear function of them (seed 002, eq. 3-1):
//! `L* = 116 fy - 16`, `a* = 500 (fx - fy)`, `b* = 200 (fy - fz)`. Changing
//! `L*` by `ΔL` while `a*` and `b*` stay is therefore adding the same
//! `ΔL / 116` to all three ([`Lab::lighten`]): `X` and `Z` change with `Y`
//! exactly as CIELAB requires.
//!
//! ## The matrices
//!
//! `RGB -> XYZ` is the matrix of IEC 61966-2-1 (sRGB, D65), whose row sums
//! are the D65 white `(Xn, Yn, Zn) = (0.9505, 1, 1.0890)`. Dividing each row
//! by its sum gives the *normalised* matrix that maps linear RGB straight to
//! `(X/Xn, Y/Yn, Z/Zn)`, with white `(1, 1, 1)` going to `(1, 1, 1)`. It is
//! held in Q18 ([`RGB_TO_T`]), each row rounded and then corrected to sum to
//! exactly `2^18`, so white and every gray are exact. Its inverse
//! ([`T_TO_RGB`]) is the exact rational inverse of that integer matrix,
//! rounded to Q20 (coefficients up to 3.08 in magnitude).
//!
//! ## Ranges
//!
//! Forward: `lin12 <= 4095` times non-negative Q18 coefficients summing to
//! `2^18`: below `2^30`, in `i32`. The tristimulus values are kept with 4
//! fraction bits (`0..=T_ONE = 65520`). Back: a tristimulus value
//! (`<= 65535`) times a Q20 coefficient (`< 2^22`) needs 38 bits: the nine
//! products are `i64` (one `SMULL` on Cortex-M3/M4, a library call on M0;
//! with `i32` the coefficients would have to be so coarse that the round
//! trip would miss by more than one level).

use super::tables::{f_of_t, lstar_round, t_of_f, F_BLACK, F_ONE, T_FRAC};
use crate::shade::LIN_MAX;

/// Fraction bits of [`RGB_TO_T`].
const FWD_FRAC: u32 = 18;
/// Fraction bits of [`T_TO_RGB`].
const INV_FRAC: u32 = 20;

/// IEC 61966-2-1 `RGB -> XYZ` (D65), in units of `10^-4`.
const SRGB_TO_XYZ: [[i128; 3]; 3] = [[4124, 3576, 1805], [2126, 7152, 722], [193, 1192, 9505]];

/// `round(n / d)` for `d > 0`, any sign of `n`.
const fn div_round(n: i128, d: i128) -> i128 {
    (2 * n + d).div_euclid(2 * d)
}

/// `RGB -> (X/Xn, Y/Yn, Z/Zn)` in Q18: each IEC row divided by its sum
/// (the white point), rounded, and the largest entry corrected so the row
/// sums to exactly `2^18`.
pub(crate) const RGB_TO_T: [[i32; 3]; 3] = {
    let mut m = [[0i32; 3]; 3];
    let mut r = 0;
    while r < 3 {
        let row = SRGB_TO_XYZ[r];
        let sum = row[0] + row[1] + row[2];
        let mut c = 0;
        let mut total = 0;
        let mut big = 0;
        while c < 3 {
            m[r][c] = div_round(row[c] << FWD_FRAC, sum) as i32;
            total += m[r][c];
            if row[c] > row[big] {
                big = c;
            }
            c += 1;
        }
        m[r][big] += (1 << FWD_FRAC) - total;
        r += 1;
    }
    m
};

/// The inverse of `RGB_TO_T` (as the real matrix `RGB_TO_T / 2^18`), in
/// Q20: `2^38 adj(RGB_TO_T) / det(RGB_TO_T)`, rounded.
pub(crate) const T_TO_RGB: [[i32; 3]; 3] = {
    let mut a = [[0i128; 3]; 3];
    let mut r = 0;
    while r < 3 {
        let mut c = 0;
        while c < 3 {
            a[r][c] = RGB_TO_T[r][c] as i128;
            c += 1;
        }
        r += 1;
    }
    // Cofactor expansion; entries < 2^18, so det < 6 * 2^54.
    let det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
        - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
        + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    let mut inv = [[0i32; 3]; 3];
    let mut i = 0;
    while i < 3 {
        let mut j = 0;
        while j < 3 {
            // inv[i][j] = cofactor(j, i) / det
            let (r0, r1) = if j == 0 {
                (1, 2)
            } else if j == 1 {
                (0, 2)
            } else {
                (0, 1)
            };
            let (c0, c1) = if i == 0 {
                (1, 2)
            } else if i == 1 {
                (0, 2)
            } else {
                (0, 1)
            };
            let minor = a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
            let cof = if (i + j) % 2 == 0 { minor } else { -minor };
            inv[i][j] = div_round(cof << (FWD_FRAC + INV_FRAC), det) as i32;
            j += 1;
        }
        i += 1;
    }
    inv
};

/// A colour in CIELAB, held as its three cube-root values in units of
/// `1 / F_ONE` ([`F_ONE`](super::F_ONE) = 65535): `fx = f(X/Xn)`,
/// `fy = f(Y/Yn)`, `fz = f(Z/Zn)` (seed 002, eq. 3-1, with the CIE linear
/// segment below `(6/29)³`). Then `L* = 116 fy / F_ONE - 16`,
/// `a* = 500 (fx - fy) / F_ONE`, `b* = 200 (fy - fz) / F_ONE`.
///
/// ```
/// use softedge::postfilter::{Lab, F_ONE};
/// let white = Lab::from_rgb([4095; 3]);
/// assert_eq!((white.fx, white.fy, white.fz), (F_ONE, F_ONE, F_ONE));
/// assert_eq!(white.l_star_rounded(), 100);
/// assert_eq!(white.to_rgb(), ([4095; 3], false));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Lab {
    /// `F_ONE * f(X / Xn)`.
    pub fx: i32,
    /// `F_ONE * f(Y / Yn)`; `L* = 116 fy / F_ONE - 16`.
    pub fy: i32,
    /// `F_ONE * f(Z / Zn)`.
    pub fz: i32,
}

/// `Y / Yn` of linear RGB in tristimulus units (`T_ONE` = white): one row
/// of the normalised matrix, three multiplies.
#[inline]
pub(crate) fn t_of_rgb(row: &[i32; 3], rgb: [u16; 3]) -> i32 {
    let mut s = 1 << (FWD_FRAC - T_FRAC - 1); // rounding
    for c in 0..3 {
        s += row[c] * i32::from(rgb[c].min(LIN_MAX));
    }
    s >> (FWD_FRAC - T_FRAC)
}

/// `F_ONE * f(Y/Yn)` of a linear RGB pixel (the `Y` row and one table
/// look-up only).
#[inline]
pub(crate) fn fy_of_rgb(rgb: [u16; 3]) -> i32 {
    f_of_t(t_of_rgb(&RGB_TO_T[1], rgb))
}

/// `F_ONE * f(Y/Yn)` of a gray pixel: `Y/Yn = lin12 / 4095`, an exact table
/// index.
#[inline]
pub(crate) fn fy_of_gray(lin12: u16) -> i32 {
    f_of_t(i32::from(lin12.min(LIN_MAX)) << T_FRAC)
}

/// A cube-root value clamped to `F_BLACK..=F_ONE` (the range of
/// `0 <= t <= 1`), and whether it had to be.
#[inline]
fn clamp_f(f: i32, clamped: &mut bool) -> i32 {
    if f < F_BLACK {
        *clamped = true;
        F_BLACK
    } else if f > F_ONE {
        *clamped = true;
        F_ONE
    } else {
        f
    }
}

impl Lab {
    /// The CIELAB colour of a linear 12-bit RGB pixel (sRGB primaries, D65;
    /// values above 4095 are clamped): the normalised matrix (9 multiplies),
    /// then the cube-root table with interpolation for each of `X`, `Y`, `Z`.
    ///
    /// ```
    /// use softedge::postfilter::Lab;
    /// let red = Lab::from_rgb([4095, 0, 0]);
    /// assert_eq!(red.l_star_rounded(), 53);
    /// assert!(red.fx > red.fy && red.fy > red.fz); // a* > 0, b* > 0
    /// ```
    pub fn from_rgb(rgb: [u16; 3]) -> Self {
        Self {
            fx: f_of_t(t_of_rgb(&RGB_TO_T[0], rgb)),
            fy: f_of_t(t_of_rgb(&RGB_TO_T[1], rgb)),
            fz: f_of_t(t_of_rgb(&RGB_TO_T[2], rgb)),
        }
    }

    /// The CIELAB colour of a gray pixel: `Y/Yn = lin12 / 4095` (clamped to
    /// 4095), `a* = b* = 0`.
    ///
    /// ```
    /// use softedge::postfilter::Lab;
    /// let g = Lab::from_gray(2048);
    /// assert_eq!(g, Lab::from_rgb([2048; 3]));
    /// assert_eq!(g.l_star_rounded(), 76);
    /// ```
    pub fn from_gray(lin12: u16) -> Self {
        let f = fy_of_gray(lin12);
        Self {
            fx: f,
            fy: f,
            fz: f,
        }
    }

    /// `L*` rounded to the nearest integer (halves up), `0..=100` for any
    /// colour made by [`from_rgb`](Self::from_rgb) or
    /// [`from_gray`](Self::from_gray): seven compares against a table of
    /// half-step thresholds.
    ///
    /// ```
    /// use softedge::postfilter::Lab;
    /// assert_eq!(Lab::from_gray(0).l_star_rounded(), 0);
    /// assert_eq!(Lab::from_gray(4095).l_star_rounded(), 100);
    /// ```
    pub fn l_star_rounded(self) -> u8 {
        lstar_round(self.fy) as u8
    }

    /// The colour with `L*` changed by `116 delta_f / F_ONE` and `a*`, `b*`
    /// unchanged: `delta_f` is added to all three cube-root values
    /// (saturating).
    ///
    /// ```
    /// use softedge::postfilter::{Lab, F_ONE};
    /// let c = Lab::from_rgb([3000, 2000, 1000]);
    /// let d = c.lighten(F_ONE / 116); // L* + 1
    /// assert_eq!(d.fx - d.fy, c.fx - c.fy); // a* kept
    /// assert_eq!(d.fy - d.fz, c.fy - c.fz); // b* kept
    /// ```
    pub fn lighten(self, delta_f: i32) -> Self {
        Self {
            fx: self.fx.saturating_add(delta_f),
            fy: self.fy.saturating_add(delta_f),
            fz: self.fz.saturating_add(delta_f),
        }
    }

    /// Back to linear 12-bit RGB: the inverse cube-root table (with
    /// interpolation) for each of `X`, `Y`, `Z`, then the inverse matrix
    /// (9 widening multiplies), rounded and clamped to `0..=4095`. The flag
    /// is `true` when the colour lies outside the RGB gamut: a channel more
    /// than one level outside `0..=4095` (the conversion itself is exact to
    /// one level, see the round-trip test), or a cube-root value outside
    /// `[f(0), f(1)]`.
    ///
    /// ```
    /// use softedge::postfilter::Lab;
    /// let rgb = [1234, 3210, 17];
    /// let (back, clamped) = Lab::from_rgb(rgb).to_rgb();
    /// assert!(!clamped);
    /// assert!(back.iter().zip(rgb).all(|(&b, v)| b.abs_diff(v) <= 1));
    /// ```
    pub fn to_rgb(self) -> ([u16; 3], bool) {
        let mut clamped = false;
        let t = [
            i64::from(t_of_f(clamp_f(self.fx, &mut clamped))),
            i64::from(t_of_f(clamp_f(self.fy, &mut clamped))),
            i64::from(t_of_f(clamp_f(self.fz, &mut clamped))),
        ];
        let mut out = [0u16; 3];
        let shift = INV_FRAC + T_FRAC;
        for (o, row) in out.iter_mut().zip(T_TO_RGB.iter()) {
            let mut s: i64 = 1 << (shift - 1);
            for c in 0..3 {
                s += i64::from(row[c]) * t[c];
            }
            let v = s >> shift;
            // The conversion is exact to one level (the round trip), so a
            // result one level outside the range is rounding, not gamut.
            if v < -1 || v > i64::from(LIN_MAX) + 1 {
                clamped = true;
            }
            *o = v.clamp(0, i64::from(LIN_MAX)) as u16;
        }
        (out, clamped)
    }

    /// Back to a linear 12-bit gray value: `Y` from `fy` alone (the inverse
    /// table), rounded; `fx` and `fz` are ignored. The flag is `true` when
    /// `fy` lay outside `[f(0), f(1)]`.
    ///
    /// ```
    /// use softedge::postfilter::Lab;
    /// for v in [0, 1, 100, 2048, 4095] {
    ///     assert_eq!(Lab::from_gray(v).to_gray(), (v, false));
    /// }
    /// ```
    pub fn to_gray(self) -> (u16, bool) {
        let mut clamped = false;
        let t = t_of_f(clamp_f(self.fy, &mut clamped));
        let v = (t + (1 << (T_FRAC - 1))) >> T_FRAC;
        (v.clamp(0, i32::from(LIN_MAX)) as u16, clamped)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normalised_rows_sum_to_one_and_white_is_exact() {
        for row in RGB_TO_T {
            assert_eq!(row.iter().sum::<i32>(), 1 << FWD_FRAC);
        }
        assert_eq!(Lab::from_rgb([4095; 3]), Lab::from_gray(4095));
    }

    #[test]
    fn inverse_matrix_times_matrix_is_identity_within_2_pow_minus_18() {
        for i in 0..3 {
            for j in 0..3 {
                let s: i64 = (0..3)
                    .map(|k| i64::from(T_TO_RGB[i][k]) * i64::from(RGB_TO_T[k][j]))
                    .sum();
                let want = if i == j {
                    1i64 << (FWD_FRAC + INV_FRAC)
                } else {
                    0
                };
                assert!((s - want).abs() < 1 << (INV_FRAC), "{i},{j}: {s}");
            }
        }
    }

    #[test]
    fn grays_round_trip_exactly_through_rgb() {
        for v in (0..=4095).step_by(7).chain([4095]) {
            assert_eq!(Lab::from_rgb([v; 3]).to_rgb(), ([v; 3], false));
        }
    }

    #[test]
    fn out_of_range_cube_roots_are_flagged() {
        let c = Lab::from_rgb([4095, 0, 0]).lighten(F_ONE / 10);
        assert!(c.to_rgb().1);
        assert!(Lab::from_gray(4095).lighten(1).to_gray().1);
        assert_eq!(Lab::from_gray(0).lighten(i32::MIN).to_gray(), (0, true));
    }
}
