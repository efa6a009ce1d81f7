//! Bit-depth planning (seed 000, eqs. 9-10, and `m = ln K / ln(1 + δ)`).
//!
//! For a display of contrast `K = B_max / B_min` and an eye that tells apart
//! relative brightness steps `δ` (Weber–Fechner, 0.02..0.05), with a display
//! exponent `γ`:
//!
//! - `N_I = (K - 1) / δ` linear intensity levels (eq. 9): a step of the
//!   linear code must stay under `δ B_min` at black;
//! - `N_U = (K - 1)^(1/γ) / δ * (γ - 1)^(1 - 1/γ)` DAC / display-code levels
//!   (eq. 10), after the γ table;
//! - `m = ln K / ln(1 + δ)` distinguishable gradations: the levels a
//!   logarithmic code needs (eq. 11 with `K = (1 + δ)^m`).
//!
//! `K = 100`, `δ = 0.05..0.02`, `γ = 2.4` give `N_I = 1980..4950` (11-12
//! bits), `N_U = 165..413` (8-9 bits), `m = 94.4..232.6` (7-8 bits).
//!
//! A planning tool for the host, not a per-pixel path: it uses `f64`, with
//! `ln` and `exp` written here from their series (core has no `f64::ln`), so
//! results are the same on every IEEE-754 target.

use super::ToneError;

/// Levels needed for a display, from [`levels`].
#[derive(Debug, Clone, Copy, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct BitDepth {
    /// `N_I = (K - 1) / δ`: levels of the linear intensity code (eq. 9).
    pub n_i: f64,
    /// `N_U = (K - 1)^(1/γ) / δ * (γ - 1)^(1 - 1/γ)`: levels of the display
    /// code / DAC (eq. 10).
    pub n_u: f64,
    /// `m = ln K / ln(1 + δ)`: distinguishable gradations, the levels of a
    /// logarithmic code.
    pub m: f64,
}

impl BitDepth {
    /// Bits of the linear intensity code: `ceil(log2 N_I)`.
    ///
    /// ```
    /// # use softedge::tone::levels;
    /// assert_eq!(levels(100.0, 0.02, 2.4).unwrap().bits_i(), 13); // 4950 levels
    /// assert_eq!(levels(100.0, 0.05, 2.4).unwrap().bits_i(), 11); // 1980 levels
    /// ```
    pub fn bits_i(&self) -> u32 {
        bits_for(self.n_i)
    }

    /// Bits of the display code: `ceil(log2 N_U)`.
    ///
    /// ```
    /// # use softedge::tone::levels;
    /// assert_eq!(levels(100.0, 0.05, 2.4).unwrap().bits_u(), 8); // 165 levels
    /// assert_eq!(levels(100.0, 0.02, 2.4).unwrap().bits_u(), 9); // 413 levels
    /// ```
    pub fn bits_u(&self) -> u32 {
        bits_for(self.n_u)
    }

    /// Bits of the logarithmic code: `ceil(log2 m)`.
    ///
    /// ```
    /// # use softedge::tone::levels;
    /// assert_eq!(levels(100.0, 0.02, 2.4).unwrap().bits_m(), 8); // 232.6
    /// ```
    pub fn bits_m(&self) -> u32 {
        bits_for(self.m)
    }
}

/// Smallest `b` with `2^b >= n` (0 for `n <= 1`; at most 64).
fn bits_for(n: f64) -> u32 {
    let mut b = 0;
    let mut p = 1.0;
    while p < n && b < 64 {
        p *= 2.0;
        b += 1;
    }
    b
}

/// The levels a display of contrast `K`, Weber fraction `δ` and exponent `γ`
/// needs (eqs. 9, 10 and `m`); [`ToneError::PlanInput`] unless `K > 1`,
/// `δ > 0`, `γ > 1` and all are finite.
///
/// ```
/// # use softedge::tone::levels;
/// let d = levels(100.0, 0.05, 2.4).unwrap();
/// assert_eq!(d.n_i.round(), 1980.0);
/// assert_eq!(d.n_u.round(), 165.0);
/// assert_eq!((d.m * 10.0).round(), 944.0);
/// assert!(levels(1.0, 0.05, 2.4).is_err());
/// ```
pub fn levels(contrast: f64, delta: f64, gamma: f64) -> Result<BitDepth, ToneError> {
    let ok = contrast.is_finite()
        && delta.is_finite()
        && gamma.is_finite()
        && contrast > 1.0
        && delta > 0.0
        && gamma > 1.0;
    if !ok {
        return Err(ToneError::PlanInput);
    }
    let k1 = contrast - 1.0;
    let n_i = k1 / delta;
    let n_u = pow(k1, 1.0 / gamma) / delta * pow(gamma - 1.0, 1.0 - 1.0 / gamma);
    let m = ln(contrast) / ln(1.0 + delta);
    Ok(BitDepth { n_i, n_u, m })
}

/// `ln 2 = 2 atanh(1/3)`.
fn ln2() -> f64 {
    2.0 * atanh_series(1.0 / 3.0)
}

/// `atanh(s) = s + s^3/3 + s^5/5 + ...` for `|s| <= 1/3` (terms fall by 9x;
/// 40 terms are far past `f64` precision).
fn atanh_series(s: f64) -> f64 {
    let s2 = s * s;
    let mut term = s;
    let mut sum = 0.0;
    let mut k = 1.0;
    for _ in 0..40 {
        sum += term / k;
        term *= s2;
        k += 2.0;
    }
    sum
}

/// Natural logarithm of a finite `x > 0`: `x = 2^e f`, `f` in `[1, 2)`,
/// `ln x = e ln 2 + 2 atanh((f - 1) / (f + 1))`. Non-positive `x` give
/// `-inf` (not reached from [`levels`]).
fn ln(x: f64) -> f64 {
    if x <= 0.0 || !x.is_finite() {
        return f64::NEG_INFINITY;
    }
    let mut f = x;
    let mut e = 0i32;
    while f >= 2.0 {
        f /= 2.0;
        e += 1;
    }
    while f < 1.0 {
        f *= 2.0;
        e -= 1;
    }
    f64::from(e) * ln2() + 2.0 * atanh_series((f - 1.0) / (f + 1.0))
}

/// `e^y` for finite `y`: `y = n ln 2 + r`, `|r| <= ln 2 / 2`, Taylor series
/// of `e^r` (30 terms), scaled by `2^n` by repeated doubling.
fn exp(y: f64) -> f64 {
    let l2 = ln2();
    // n = round(y / ln 2); `as` saturates, and the doubling below is capped.
    let q = y / l2;
    let n = if q >= 0.0 {
        (q + 0.5) as i64
    } else {
        -((0.5 - q) as i64)
    };
    let r = y - n as f64 * l2;
    let mut term = 1.0;
    let mut sum = 0.0;
    for k in 1..=30 {
        sum += term;
        term *= r / f64::from(k);
    }
    let mut scale = 1.0;
    let (step, count) = if n >= 0 { (2.0, n) } else { (0.5, -n) };
    for _ in 0..count.min(2100) {
        scale *= step;
    }
    sum * scale
}

/// `a^b` for `a > 0`.
fn pow(a: f64, b: f64) -> f64 {
    exp(b * ln(a))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ln_and_exp_agree_with_std_within_1e_12() {
        extern crate std;
        for x in [1e-6, 0.3, 1.0, 1.02, 2.0, 99.0, 4095.0, 1e9] {
            assert!((ln(x) - std::primitive::f64::ln(x)).abs() < 1e-12, "ln {x}");
        }
        for y in [-20.0, -1.0, -0.2, 0.0, 0.5, 3.3, 40.0] {
            let want = std::primitive::f64::exp(y);
            assert!(((exp(y) - want) / want).abs() < 1e-12, "exp {y}");
        }
    }

    #[test]
    fn bad_inputs_are_refused() {
        for (k, d, g) in [
            (1.0, 0.02, 2.4),
            (100.0, 0.0, 2.4),
            (100.0, 0.02, 1.0),
            (f64::NAN, 0.02, 2.4),
            (f64::INFINITY, 0.02, 2.4),
        ] {
            assert_eq!(levels(k, d, g), Err(ToneError::PlanInput));
        }
    }
}
