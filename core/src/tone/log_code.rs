//! Logarithmic intensity codes (seed 000, eqs. 11-13 and 15, fig. 7).
//!
//! The eye tells apart brightness steps of a fixed ratio `1 + δ` (Weber–
//! Fechner), so a display of contrast `K = B_max / B_min` has about
//! `m = ln K / ln(1 + δ)` distinguishable gradations `B_i = B_min (1 + δ)^i`
//! (eq. 11). The log code numbers them: `I_i = i / m` in `[0, 1]`, and
//! `B_i = B_min * K^(I_i)` (eq. 12), `I_i = log_K(B_i / B_min)` (eq. 13). An
//! 8-bit code then covers `K = 100` in steps of `K^(1/m) - 1` (1.82 % for
//! `m = 255`), where a linear code needs 11-12 bits (eq. 9).
//!
//! ## Normalisation
//!
//! Linear light in the rest of the crate runs from the display's black
//! (`B_min`, `lin12 = 0`) to its white (`B_max`, `lin12 = 4095`). A log code
//! `i` is the light `B_min * K^(i/m)`, i.e. the linear value
//! `x = (K^(i/m) - 1) / (K - 1)`: code 0 is black, code `m` is white.
//!
//! ## Two filters (fig. 7)
//!
//! Filtering (eqs. 2-3) must add *linear* light `sum(S_j * I_j)`.
//!
//! - (a) potentiate, then multiply-accumulate in linear light:
//!   [`PotentiationLut`] gives `lin12 = round(4095 x)`, the band buffer
//!   accumulates, the [`GammaLut`](super::GammaLut) (eq. 7) maps to the display.
//! - (b) stay in logs: a [`LogValue`] is `log_K` of the light over `B_min`
//!   in units of `1 / (8 m)` (3 bits finer than the code, so the few
//!   roundings of a filter stay under one display code). The product
//!   `I_j * S_j` is the *sum* of logs ([`LogValue::mul`], one adder); the sum
//!   of two lights is the Gaussian logarithm
//!   `log_K(a + b) = log_K a + log_K(1 + K^(log_K b - log_K a))`, one table
//!   ([`GaussLog`]); the display code is the table of eq. 15,
//!   `V = ((K^I - 1) / (K - 1))^(1/γ)` ([`LogOutputLut`]). With weights that
//!   sum to one (coverage plus background) the result is a light in
//!   `[B_min, B_max]`, so `I` in `[0, 1]`.
//!
//! ## Ranges
//!
//! `K` is `2..=65535`, `m` is `1..=255`; a fine log value of a code is at
//! most `8 * 255 = 2040`; the log of a weight of `1/4096` is
//! `-8 m log_K 4096 >= -24480`; all sums are saturating `i32`s. Every
//! look-up index is clamped to its table.

use super::fixpow::{self, ONE, VALUE_FRAC};
use super::gamma::{encode, Curve};
use super::{ToneError, LIN_MAX};

/// Extra fraction bits of a [`LogValue`] over the 8-bit code.
pub const FINE_BITS: u32 = 3;

/// Entries of the Gaussian-logarithm table.
const GAUSS_LEN: usize = 4096;

/// Entries of the output table: every fine value of an 8-bit code.
const OUT_LEN: usize = 256 << FINE_BITS;

/// Coverage of a whole pixel for [`LogScale::log_weight`]: `2^12`.
const COVER_ONE: u16 = 1 << 12;

/// A logarithmic intensity scale: contrast `K` and gradations `m` (eq. 12).
///
/// ```
/// # use softedge::tone::LogScale;
/// let scale = LogScale::new(100, 255).unwrap();
/// assert_eq!(scale.contrast(), 100);
/// // Code 255 is white, K = 100 times the black level (Q16 ratio):
/// assert_eq!(scale.brightness(255), 100 << 16);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LogScale {
    contrast: u16,
    m: u8,
}

impl LogScale {
    /// The scale with contrast `K >= 2` and `m >= 1` gradations (codes
    /// `0..=m`; larger codes are clamped to `m`, white).
    ///
    /// ```
    /// # use softedge::tone::{LogScale, ToneError};
    /// assert_eq!(LogScale::new(1, 255), Err(ToneError::Contrast));
    /// assert_eq!(LogScale::new(100, 0), Err(ToneError::Gradations));
    /// ```
    pub const fn new(contrast: u16, m: u8) -> Result<Self, ToneError> {
        if contrast < 2 {
            return Err(ToneError::Contrast);
        }
        if m == 0 {
            return Err(ToneError::Gradations);
        }
        Ok(LogScale { contrast, m })
    }

    /// The contrast `K = B_max / B_min`.
    ///
    /// ```
    /// # use softedge::tone::LogScale;
    /// assert_eq!(LogScale::new(30, 200).unwrap().contrast(), 30);
    /// ```
    pub const fn contrast(&self) -> u16 {
        self.contrast
    }

    /// The number of gradations `m`: the code of white.
    ///
    /// ```
    /// # use softedge::tone::LogScale;
    /// assert_eq!(LogScale::new(30, 200).unwrap().gradations(), 200);
    /// ```
    pub const fn gradations(&self) -> u8 {
        self.m
    }

    /// Fine log units per unit of `I = log_K(B / B_min)`: `8 m`.
    const fn fine_per_unit(&self) -> i64 {
        (self.m as i64) << FINE_BITS
    }

    /// `log2 K` in Q32.
    const fn log2_k(&self) -> i64 {
        fixpow::log2((self.contrast as u128) << VALUE_FRAC)
    }

    /// `B_i / B_min = K^(i/m)` (eq. 12) as a Q16 ratio, rounded; codes above
    /// `m` are clamped to `m`.
    ///
    /// ```
    /// # use softedge::tone::LogScale;
    /// let s = LogScale::new(100, 2).unwrap();
    /// assert_eq!(s.brightness(0), 1 << 16);
    /// assert_eq!(s.brightness(1), 10 << 16); // sqrt(100)
    /// ```
    pub const fn brightness(&self, code: u8) -> u32 {
        let i = if code > self.m { self.m } else { code };
        let v = fixpow::contrast_pow(self.contrast, i as i64, self.m as i64);
        // v <= K * 2^62 (+ rounding), K < 2^16: the Q16 ratio is below 2^32.
        let q16 = (v + (1 << (VALUE_FRAC - 17))) >> (VALUE_FRAC - 16);
        if q16 > u32::MAX as u128 {
            u32::MAX
        } else {
            q16 as u32
        }
    }

    /// The log of a coverage weight `S = cover / 4096` (clamped to 1):
    /// `round(8 m log_K S)`, [`LogValue::ZERO`] for `cover = 0`. A setup-time
    /// computation (per primitive or per pixel-model weight), not per pixel.
    ///
    /// ```
    /// # use softedge::tone::{LogScale, LogValue};
    /// let s = LogScale::new(100, 255).unwrap();
    /// assert_eq!(s.log_weight(4096).fine(), 0);
    /// // log_100(1/10) = -1/2 of the scale: -8 * 255 / 2.
    /// assert_eq!(s.log_weight(410).fine(), -1020);
    /// assert_eq!(s.log_weight(0), LogValue::ZERO);
    /// ```
    pub const fn log_weight(&self, cover: u16) -> LogValue {
        if cover == 0 {
            return LogValue::ZERO;
        }
        let c = if cover > COVER_ONE { COVER_ONE } else { cover };
        // log2(S) in Q32, S = c / 4096 <= 1: in [-12 * 2^32, 0].
        let l = fixpow::log2(((c as u128) << VALUE_FRAC) / COVER_ONE as u128);
        LogValue(div_round(l * self.fine_per_unit(), self.log2_k()) as i32)
    }

    /// Linear light `x = (K^t - 1) / (K - 1)` (Q62) of a fine log value `t`
    /// (in units of `1 / (8 m)`), `t` in `0..=8m`.
    const fn linear_of_fine(&self, t: i64) -> u128 {
        let v = fixpow::contrast_pow(self.contrast, t, self.fine_per_unit());
        v.saturating_sub(ONE) / (self.contrast as u128 - 1)
    }
}

/// `round(n / d)` for `d > 0`, halves upwards.
const fn div_round(n: i64, d: i64) -> i64 {
    (2 * n + d).div_euclid(2 * d)
}

/// A light as `log_K(B / B_min)` in units of `1 / (8 m)` of its
/// [`LogScale`] (fig. 7b); or [`ZERO`](Self::ZERO), no light at all (the
/// log of a zero weight).
///
/// ```
/// # use softedge::tone::LogValue;
/// let a = LogValue::from_code(200);
/// assert_eq!(a.fine(), 1600);
/// assert_eq!(a.mul(LogValue::ZERO), LogValue::ZERO);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LogValue(i32);

impl LogValue {
    /// No light: the log of zero.
    pub const ZERO: LogValue = LogValue(i32::MIN);

    /// The value of an 8-bit log code `i` (eq. 13): `i << 3`.
    pub const fn from_code(code: u8) -> Self {
        LogValue((code as i32) << FINE_BITS)
    }

    /// The value from fine units (`i32::MIN` is [`ZERO`](Self::ZERO)).
    ///
    /// ```
    /// # use softedge::tone::LogValue;
    /// assert_eq!(LogValue::from_fine(8), LogValue::from_code(1));
    /// ```
    pub const fn from_fine(fine: i32) -> Self {
        LogValue(fine)
    }

    /// The fine units `8 m log_K(B / B_min)`; `i32::MIN` for [`ZERO`](Self::ZERO).
    pub const fn fine(self) -> i32 {
        self.0
    }

    /// Whether this is [`ZERO`](Self::ZERO).
    ///
    /// ```
    /// # use softedge::tone::LogValue;
    /// assert!(LogValue::ZERO.is_zero());
    /// ```
    pub const fn is_zero(self) -> bool {
        self.0 == i32::MIN
    }

    /// The product of two lights: the sum of their logs (saturating; a
    /// product with [`ZERO`](Self::ZERO) is `ZERO`).
    ///
    /// ```
    /// # use softedge::tone::LogValue;
    /// let p = LogValue::from_code(10).mul(LogValue::from_fine(-24));
    /// assert_eq!(p, LogValue::from_code(7));
    /// ```
    pub const fn mul(self, other: LogValue) -> LogValue {
        if self.is_zero() || other.is_zero() {
            return LogValue::ZERO;
        }
        let s = self.0.saturating_add(other.0);
        LogValue(if s == i32::MIN { i32::MIN + 1 } else { s })
    }
}

/// Potentiation table (fig. 7a): log code `i` → linear 12-bit intensity
/// `round(4095 (K^(i/m) - 1) / (K - 1))`, code 0 black, code `m` white
/// (codes above `m` give white).
///
/// ```
/// # use softedge::tone::{LogScale, PotentiationLut};
/// let pot = PotentiationLut::new(LogScale::new(100, 255).unwrap());
/// assert_eq!(pot.lin12(0), 0);
/// assert_eq!(pot.lin12(255), 4095);
/// // Half-way in log is sqrt(100) = 10 times black: 4095 * 9/99 = 372.3.
/// assert_eq!(PotentiationLut::new(LogScale::new(100, 2).unwrap()).lin12(1), 372);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PotentiationLut {
    lin12: [u16; 256],
}

impl PotentiationLut {
    /// The table of `scale`.
    pub const fn new(scale: LogScale) -> Self {
        let mut lin12 = [LIN_MAX; 256];
        let mut i = 0;
        while i <= scale.m as usize {
            let x = scale.linear_of_fine((i as i64) << FINE_BITS);
            lin12[i] = fixpow::round_to(x, LIN_MAX as u32) as u16;
            i += 1;
        }
        PotentiationLut { lin12 }
    }

    /// The linear 12-bit intensity of log code `code`.
    #[inline]
    pub fn lin12(&self, code: u8) -> u16 {
        self.lin12[usize::from(code)]
    }
}

/// Gaussian-logarithm table (fig. 7b):
/// `G(d) = round(8 m log_K(1 + K^(-d / 8m)))` for a fine difference `d >= 0`,
/// so that `log(a + b) = max + G(max - min)`.
///
/// The table has 4096 entries and must fall to 0 inside them (then every
/// larger `d` is 0 too); [`new`](Self::new) refuses a scale whose step is too
/// fine for its contrast (e.g. `K = 2` with `m = 255`). `K = 100`, `m = 255`
/// reaches 0 at `d ≈ 3300`.
///
/// ```
/// # use softedge::tone::{GaussLog, LogScale, LogValue};
/// let s = LogScale::new(100, 255).unwrap();
/// let g = GaussLog::new(s).unwrap();
/// // Twice a light is log_K 2 = 0.1505 of the scale higher: 8 * 255 * 0.1505 = 307.
/// let a = LogValue::from_code(100);
/// assert_eq!(g.add(a, a).fine(), 800 + 307);
/// assert_eq!(g.add(a, LogValue::ZERO), a);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct GaussLog {
    table: [u16; GAUSS_LEN],
}

impl GaussLog {
    /// The table of `scale`, or [`ToneError::GaussTooLong`].
    pub const fn new(scale: LogScale) -> Result<Self, ToneError> {
        let mut table = [0u16; GAUSS_LEN];
        let lk = scale.log2_k();
        let per = scale.fine_per_unit();
        let mut d = 0;
        while d < GAUSS_LEN {
            // K^(-d/8m) in Q62, then log2(1 + that) in Q32 (in [0, 1]).
            let y = fixpow::exp2(-div_round(lk * d as i64, per));
            let l = fixpow::log2(ONE + y);
            // G <= 8m log_K 2 <= 2040: fits u16.
            table[d] = div_round(l * per, lk) as u16;
            d += 1;
        }
        if table[GAUSS_LEN - 1] != 0 {
            return Err(ToneError::GaussTooLong);
        }
        Ok(GaussLog { table })
    }

    /// `log(A + B)` of two lights given as logs.
    #[inline]
    pub fn add(&self, a: LogValue, b: LogValue) -> LogValue {
        let (hi, lo) = if a >= b { (a, b) } else { (b, a) };
        if lo.is_zero() {
            return hi;
        }
        // hi >= lo > i32::MIN, so the difference fits u32.
        let d = hi.0.abs_diff(lo.0) as usize;
        let g = self.table.get(d).copied().unwrap_or(0);
        LogValue(hi.0.saturating_add(i32::from(g)))
    }

    /// The fig. 7b filter: `log(sum(I_j * S_j))` of pairs `(log I_j, log S_j)`
    /// (adders and this table only); [`LogValue::ZERO`] for no terms.
    ///
    /// ```
    /// # use softedge::tone::{GaussLog, LogScale, LogValue};
    /// let s = LogScale::new(100, 255).unwrap();
    /// let g = GaussLog::new(s).unwrap();
    /// let half = s.log_weight(2048);
    /// let a = LogValue::from_code(180);
    /// // Half of a light plus half of the same light is that light (±1 fine unit).
    /// let f = g.filter([(a, half), (a, half)]);
    /// assert!((f.fine() - a.fine()).abs() <= 1);
    /// ```
    pub fn filter(&self, terms: impl IntoIterator<Item = (LogValue, LogValue)>) -> LogValue {
        terms
            .into_iter()
            .fold(LogValue::ZERO, |acc, (i, s)| self.add(acc, i.mul(s)))
    }
}

/// Output table for log values (eq. 15): fine log value `t` (units of
/// `1 / 8m`) → display code `round(max * V)`,
/// `V = curve⁻¹((K^(t/8m) - 1) / (K - 1))`; for a power curve exactly
/// `V = ((K^I - 1) / (K - 1))^(1/γ)`. Values below 0 (or
/// [`LogValue::ZERO`]) give code 0, above `8 m` give `max`.
///
/// ```
/// # use softedge::tone::{Curve, LogOutputLut, LogScale, LogValue};
/// let s = LogScale::new(100, 255).unwrap();
/// let out = LogOutputLut::new(s, Curve::GAMMA_2_4);
/// assert_eq!(out.code(LogValue::from_code(0)), 0);
/// assert_eq!(out.code(LogValue::from_code(255)), 255);
/// assert_eq!(out.code(LogValue::ZERO), 0);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LogOutputLut {
    codes: [u8; OUT_LEN],
    last: u16,
}

impl LogOutputLut {
    /// The 8-bit table of `scale` for a display with `curve`.
    pub const fn new(scale: LogScale, curve: Curve) -> Self {
        let last = (scale.m as usize) << FINE_BITS;
        let mut codes = [u8::MAX; OUT_LEN];
        let mut t = 0;
        while t <= last {
            let x = scale.linear_of_fine(t as i64);
            codes[t] = fixpow::round_to(encode(curve, x), u8::MAX as u32) as u8;
            t += 1;
        }
        LogOutputLut {
            codes,
            last: last as u16,
        }
    }

    /// The display code of a log value (clamped to `0..=8m`).
    #[inline]
    pub fn code(&self, v: LogValue) -> u8 {
        let t = v.0.clamp(0, i32::from(self.last)) as usize;
        self.codes[t & (OUT_LEN - 1)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_table_of_k100_m255_closes() {
        let g = GaussLog::new(LogScale::new(100, 255).unwrap()).unwrap();
        let first_zero = g.table.iter().position(|&v| v == 0).unwrap();
        assert!((3000..3700).contains(&first_zero), "{first_zero}");
    }

    #[test]
    fn too_fine_a_step_for_the_contrast_is_refused() {
        let s = LogScale::new(2, 255).unwrap();
        assert_eq!(GaussLog::new(s), Err(ToneError::GaussTooLong));
    }

    #[test]
    fn potentiation_is_monotone_with_exact_ends() {
        for (k, m) in [(100, 255), (10, 116), (1000, 255), (65_535, 255), (2, 1)] {
            let pot = PotentiationLut::new(LogScale::new(k, m).unwrap());
            assert_eq!(pot.lin12(0), 0);
            assert_eq!(pot.lin12(m), LIN_MAX);
            assert_eq!(pot.lin12(255), LIN_MAX);
            assert!(pot.lin12.windows(2).all(|w| w[0] <= w[1]));
        }
    }
}
