//! Integer trigonometry and roots for the path set-up: `sin`/`cos` of a
//! binary angle, `atan2`, `sin(x)/x`, and integer square roots.
//!
//! Takes binary angles (`2^32` units per turn, so angles wrap for free in a
//! `u32`) and integer vectors; gives Q30 sines and cosines (`1.0 = 2^30`),
//! binary angles, and floors of square roots. Only `i64` multiplies and
//! shifts (and `u128` in the once-per-shape roots); no float. One small
//! table, a coarse quarter-wave sine built at compile time, serves bounds
//! that need not be exact ([`sin_coarse_q15`]); vertices use the series.
//!
//! ## Method
//!
//! - `sin`/`cos`: the angle is folded into the first octant `[0, pi/4]`
//!   (exactly: the octant and the mirror are read off the top three bits),
//!   converted to radians in Q31, and both series are summed in Horner form
//!   in Q31: `sin x = x (1 - x^2/(2*3) (1 - x^2/(4*5) (1 - ...)))` up to
//!   `x^11`, `cos x = 1 - x^2/(1*2) (1 - x^2/(3*4) (...))` up to `x^12`.
//!   For `x <= pi/4` the first dropped terms are below `7.1e-12` and
//!   `3.9e-13`; each of the six Horner steps truncates by at most one Q31
//!   unit (`4.7e-10`), so both results are within `3.3e-9` of the true
//!   value before the final rounding to Q30 (half a unit, `4.7e-10`). On a
//!   radius of `2^23` fine units (8192 px) that is `0.03` fine units. The
//!   folding makes `sin(-a) = -sin(a)`, `cos(-a) = cos(a)` and the octant
//!   symmetries hold bit for bit, so shapes come out mirror-symmetric.
//! - `atan2`: the vector is folded into the first octant (swap and signs),
//!   the ratio `z = min/max` taken in Q31, reduced to `|w| <= tan(pi/8)`
//!   by `atan z = pi/4 + atan((z-1)/(z+1))` above `tan(pi/8)`, and the
//!   series `w - w^3/3 + ...` summed to `w^23` (dropped terms below
//!   `2e-10`). The error is below `1e-9` rad, a few binary units.
//! - `pi` comes from Machin's formula `pi = 16 atan(1/5) - 4 atan(1/239)`
//!   summed in Q61 by a `const fn`.
//! - Square roots: the digit-by-digit method, one result bit per step
//!   (32 steps for `u64`, 64 for `u128`): exact floors, bounded loops.

use crate::arith::mul_wide;

/// Binary angle units per turn: `2^32`.
pub(crate) const TURN: i64 = 1 << 32;
/// A quarter turn in binary units.
pub(crate) const QUARTER_TURN: i64 = TURN / 4;
/// Half a turn in binary units.
pub(crate) const HALF_TURN: i64 = TURN / 2;

/// `1.0` in Q30, the format of every sine, cosine and unit vector here.
pub(crate) const Q30: i64 = 1 << 30;
/// `1.0` in Q31, the internal format of the series.
const Q31: i64 = 1 << 31;

/// `atan(1/x) * 2^61` by its series `sum (-1)^k / ((2k+1) x^(2k+1))`.
const fn atan_inv_q61(x: i64) -> i64 {
    let mut power = (1i64 << 61) / x;
    let mut sum = 0i64;
    let mut k = 0i64;
    // The power shrinks by x^2 >= 25 per step: at most 14 steps.
    while power != 0 {
        let term = power / (2 * k + 1);
        sum += if k % 2 == 0 { term } else { -term };
        power /= x * x;
        k += 1;
    }
    sum
}

/// `pi * 2^61` (below `2^63`: `pi < 4`), from Machin's formula.
pub(crate) const PI_Q61: i64 = 16 * atan_inv_q61(5) - 4 * atan_inv_q61(239);

/// Steps of [`SINE_Q15`] per quarter turn.
const SINE_STEPS: usize = 64;

/// `sin(k pi / 128)` for `k = 0..=64` (a quarter turn in 64 steps) in
/// Q15, rounded: the coarse sine of [`sin_coarse_q15`]. Built at compile
/// time from the Taylor series `x - x^3/3! + ...` to `x^29` in Q61
/// (`x <= pi/2`: the first dropped term is below `1e-20`; `x^2` and every
/// term times it stay below `2^124`).
const SINE_Q15: [i32; SINE_STEPS + 1] = {
    let mut t = [0i32; SINE_STEPS + 1];
    let mut k = 0;
    while k <= SINE_STEPS {
        // x = k pi / 128 in Q61.
        let x = (PI_Q61 as i128 * k as i128) >> 7;
        let x2 = (x * x) >> 61;
        let (mut term, mut sum, mut n) = (x, x, 1i128);
        while n < 15 {
            term = -((term * x2) >> 61) / ((2 * n) * (2 * n + 1));
            sum += term;
            n += 1;
        }
        // Q61 -> Q15, rounded.
        t[k] = ((sum + (1 << 45)) >> 46) as i32;
        k += 1;
    }
    t
};

/// `sin(a)` in Q15 for the binary angle `a`, coarse and cheap: the quarter
/// wave [`SINE_Q15`] read by linear interpolation in 32-bit integers (a
/// few additions, one short multiply). Within [`SIN_COARSE_ERR_Q15`] of
/// the true value: the table's rounding (half a Q15 unit, `1.6e-5`), the
/// interpolation (`h^2 / 8 = 7.6e-5` for a step `h = pi/128`), the
/// position truncated to 10 bits of a step (`h / 2^10 = 2.4e-5`) and the
/// product's floor (one unit, `3.1e-5`): `1.5e-4`, 5 units. For bounds
/// where the exact [`cos_sin`] would cost too much (which pieces of a
/// curve a band needs), never for a vertex.
pub(crate) fn sin_coarse_q15(a: u32) -> i32 {
    let quadrant = a >> 30;
    let f = a & ((1 << 30) - 1);
    // sin over the quadrants: S(f), S(q - f), -S(f), -S(q - f).
    let f = if quadrant & 1 == 1 { (1 << 30) - f } else { f };
    let i = (f >> 24) as usize;
    let frac = ((f >> 14) & 1023) as i32;
    let lo = SINE_Q15.get(i).copied().unwrap_or(1 << 15);
    let hi = SINE_Q15.get(i + 1).copied().unwrap_or(lo);
    // (hi - lo) < 2^10, frac < 2^10: the product fits easily.
    let v = lo + (((hi - lo) * frac) >> 10);
    if quadrant >= 2 {
        -v
    } else {
        v
    }
}

/// The error bound of [`sin_coarse_q15`], Q15 units.
pub(crate) const SIN_COARSE_ERR_Q15: i32 = 5;

/// `(x >> s)` rounded to nearest, halves away from zero (so negation
/// commutes with it: mirror images round to mirror images). `s` in
/// `1..=62`; `|x| < 2^62` in every caller.
#[inline]
pub(crate) fn round_shift(x: i64, s: u32) -> i64 {
    let half = 1i64 << (s - 1);
    if x >= 0 {
        (x + half) >> s
    } else {
        -((half - x) >> s)
    }
}

/// `n / d` rounded to nearest, halves away from zero; 0 if `d == 0`.
///
/// In 64 bits when both fit below `2^62` (every stroke join's corner in
/// the coordinate range: the Cortex-M0 divides 64 bits in a library call,
/// 128 bits in several), else in 128; the same quotient either way.
#[inline]
pub(crate) fn div_round(n: i128, d: i128) -> i128 {
    const SMALL: i128 = 1 << 62;
    if d == 0 {
        return 0;
    }
    if -SMALL < n && n < SMALL && -SMALL < d && d < SMALL {
        let (n, d) = (n as i64, d as i64);
        let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
        // |n| + d / 2 < 2^63: no overflow.
        let q = if n >= 0 {
            (n + d / 2) / d
        } else {
            -((d / 2 - n) / d)
        };
        return i128::from(q);
    }
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    if n >= 0 {
        (n + d / 2) / d
    } else {
        -((d / 2 - n) / d)
    }
}

/// Binary angle of the first octant (`0..=2^29`) to radians in Q31
/// (`<= pi/4 * 2^31 < 2^31`).
#[inline]
fn octant_radians_q31(f: i64) -> i64 {
    // f / 2^29 of pi/4 = f * pi / 2^31; in Q31: f * PI_Q61 / 2^61,
    // rounded. With PI_Q61 = h 2^32 + l: (f h 2^32 + f l + 2^60) >> 61 is
    // (f h + ((f l + 2^60) >> 32)) >> 29 exactly (floors nest), all in
    // 32x32->64 products: f <= 2^29, so f l + 2^60 < 2^62 and the sum
    // stays below 2^61.
    let f = f.clamp(0, 1 << 29) as u32;
    let (h, l) = ((PI_Q61 >> 32) as u32, PI_Q61 as u32);
    let low = (mul_wide(f, l) + (1 << 60)) >> 32;
    ((mul_wide(f, h) + low) >> 29) as i64
}

/// `floor(v / D)` for `v < 2^31` by a multiply and a shift
/// (Granlund–Montgomery): with `l = ceil(log2 D)`, `s = 31 + l` and
/// `M = ceil(2^s / D)`, `M D - 2^s < D <= 2^l = 2^(s - 31)`, which makes
/// `floor(v M / 2^s)` the quotient for every `v < 2^31`; `M < 2^32`.
struct DivBy<const D: u32>;

impl<const D: u32> DivBy<D> {
    const S: u32 = 31 + (32 - (D - 1).leading_zeros());
    const M: u32 = (1u64 << Self::S).div_ceil(D as u64) as u32;

    #[inline(always)]
    fn of(v: u32) -> u32 {
        (mul_wide(v, Self::M) >> Self::S) as u32
    }
}

/// One Horner step of the series: `1 - x2 acc / D` in Q31. Every value
/// is in `0..=2^31` (`x2 <= (pi/4)^2 < 2^31`, `acc` a partial sum within
/// `(0, 1]`), so the product is 32x32->64 and `x2 acc / 2^31 < 2^31`: the
/// same floors as in 64 bits.
#[inline(always)]
fn horner_q31<const D: u32>(x2: u32, acc: u32) -> u32 {
    (1 << 31) - DivBy::<D>::of((mul_wide(x2, acc) >> 31) as u32)
}

/// `sin(x)/x` in Q31 from `x^2` in Q31 (`x <= pi/4`), Horner form to
/// `x^10/11!`: denominators `(2k)(2k+1)` for `k = 5, 4, 3, 2, 1`.
#[inline]
fn sinc_series_q31(x2: u32) -> u32 {
    let acc = horner_q31::<110>(x2, 1 << 31);
    let acc = horner_q31::<72>(x2, acc);
    let acc = horner_q31::<42>(x2, acc);
    let acc = horner_q31::<20>(x2, acc);
    horner_q31::<6>(x2, acc)
}

/// `cos(x)` in Q31 from `x^2` in Q31 (`x <= pi/4`), Horner form to
/// `x^12/12!`: denominators `(2k-1)(2k)` for `k = 6, ..., 1`.
#[inline]
fn cos_series_q31(x2: u32) -> u32 {
    let acc = horner_q31::<132>(x2, 1 << 31);
    let acc = horner_q31::<90>(x2, acc);
    let acc = horner_q31::<56>(x2, acc);
    let acc = horner_q31::<30>(x2, acc);
    let acc = horner_q31::<12>(x2, acc);
    horner_q31::<2>(x2, acc)
}

/// `x^2` in Q31 for `x` in Q31, `0 <= x <= pi/4`.
#[inline]
fn square_q31(x: i64) -> u32 {
    (mul_wide(x as u32, x as u32) >> 31) as u32
}

/// `(cos a, sin a)` in Q30 for the binary angle `a` (`2^32` per turn).
///
/// Exact at multiples of 45 degrees' axes (`cos 0 = 2^30`, `sin 90 = 2^30`)
/// and within `3.8e-9` of the true values elsewhere (see the module doc).
pub(crate) fn cos_sin(a: u32) -> (i64, i64) {
    let octant = a >> 29;
    let f = i64::from(a & ((1 << 29) - 1));
    let f = if octant & 1 == 1 { (1 << 29) - f } else { f };
    let x = octant_radians_q31(f);
    let x2 = square_q31(x);
    let s = round_shift((mul_wide(x as u32, sinc_series_q31(x2)) >> 31) as i64, 1);
    let c = round_shift(i64::from(cos_series_q31(x2)), 1);
    match octant {
        0 => (c, s),
        1 => (s, c),
        2 => (-s, c),
        3 => (-c, s),
        4 => (-c, -s),
        5 => (-s, -c),
        6 => (s, -c),
        _ => (c, -s),
    }
}

/// `sin(x)/x` in Q31 for `x = a` binary units, `0 < a <= 2^29` (at most
/// an eighth of a turn); `a` beyond is limited to `2^29`.
///
/// Used for the area-preserving radii of polygons on circles: relative
/// precision stays at `1e-9` however small the angle (no cancellation).
pub(crate) fn sinc_q31(a: i64) -> i64 {
    let a = a.clamp(0, 1 << 29);
    let x = octant_radians_q31(a);
    i64::from(sinc_series_q31(square_q31(x)))
}

/// Radians in Q31 of `a` binary units, `|a| <= 2^32` (one turn).
pub(crate) fn radians_q31(a: i64) -> i64 {
    let a = a.clamp(-TURN, TURN);
    // a / 2^32 turns = a * 2 pi / 2^32 = a * pi / 2^31 rad.
    let v = (a as i128 * PI_Q61 as i128) >> 61;
    v as i64
}

/// `tan(pi/8) = sqrt(2) - 1` in Q31, from `isqrt(2 * 2^62)`.
fn tan_pi_8_q31() -> i64 {
    (2u64 << 62).isqrt() as i64 - Q31
}

/// `atan(w)` in Q31 for `|w| <= tan(pi/8)` in Q31, series to `w^23`.
fn atan_small_q31(w: i64) -> i64 {
    let w2 = (w * w) >> 31;
    let mut acc = 0i64;
    // atan w = w (1 - w^2 (1/3 - w^2 (1/5 - ... (1/21 - w^2/23)))).
    let mut k = 11i64;
    while k >= 1 {
        acc = Q31 / (2 * k + 1) - ((w2 * acc) >> 31);
        k -= 1;
    }
    let acc = Q31 - ((w2 * acc) >> 31);
    (w * acc) >> 31
}

/// The binary angle of the vector `(x, y)`: `(cos t, sin t)` points along
/// it. `(0, 0)` gives 0. Any `i64` components (they are scaled down to 31
/// bits first, which keeps the direction to `2^-31`).
pub(crate) fn atan2(y: i64, x: i64) -> u32 {
    if x == 0 && y == 0 {
        return 0;
    }
    let mut ax = x.unsigned_abs();
    let mut ay = y.unsigned_abs();
    while ax >= 1 << 31 || ay >= 1 << 31 {
        ax >>= 1;
        ay >>= 1;
    }
    // Fold into the first octant: the angle is atan(min/max), mirrored
    // about 45 degrees when |y| > |x|.
    let swapped = ay > ax;
    let (min, max) = if swapped { (ax, ay) } else { (ay, ax) };
    // z = min / max in Q31, in [0, 1]; max > 0 here.
    let z = (min << 31).checked_div(max).unwrap_or(0) as i64;
    let t8 = tan_pi_8_q31();
    let a_q31 = if z > t8 {
        let w = ((z - Q31) << 31) / (z + Q31);
        // pi/4 in Q31 = PI_Q61 >> 32.
        (PI_Q61 >> 32) + atan_small_q31(w)
    } else {
        atan_small_q31(z)
    };
    // Radians Q31 to binary units: a * 2^32 / (2 pi) = a_q31 / pi.
    let mut t = ((a_q31 as i128) << 61) / PI_Q61 as i128;
    let t_max = i128::from(1u32 << 29);
    if t > t_max {
        t = t_max;
    }
    let mut t = t as i64; // [0, 2^29]: first octant
    if swapped {
        t = QUARTER_TURN - t;
    }
    if x < 0 {
        t = HALF_TURN - t;
    }
    if y < 0 {
        t = -t;
    }
    t.rem_euclid(TURN) as u32
}

/// `ceil(sqrt(v))` (in 32 bits below `2^32`: the same value, without the
/// 64-bit loop and multiply of a Cortex-M0).
pub(crate) fn ceil_sqrt_u64(v: u64) -> u64 {
    if let Ok(w) = u32::try_from(v) {
        let r = w.isqrt();
        // r < 2^16: r^2 fits.
        return u64::from(if r * r < w { r + 1 } else { r });
    }
    let r = v.isqrt();
    if r * r < v {
        r + 1
    } else {
        r
    }
}

#[cfg(test)]
mod tests {

    extern crate std;

    /// The quotient rounded half away from zero, from the floor and the
    /// remainder of Euclid's division (exact, in `i128`), not from the
    /// code under test.
    fn reference(n: i128, d: i128) -> i128 {
        if d == 0 {
            return 0;
        }
        let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
        let (q, r) = (n.div_euclid(d), n.rem_euclid(d));
        // n / d = q + r / d, 0 <= r < d; a half goes up when q + r/d >= 0.
        let up = 2 * r > d || (2 * r == d && q >= 0);
        q + i128::from(up)
    }

    #[test]
    fn division_rounds_halves_away_from_zero_on_both_paths() {
        use super::div_round;
        use crate::path::testing::Lcg;
        let edges = [
            0i128,
            1,
            2,
            3,
            7,
            (1 << 31) - 1,
            1 << 31,
            (1 << 61) + 12345,
            (1 << 62) - 1,
            1 << 62,
            (1 << 62) + 1,
            1 << 80,
            (1 << 100) + 3,
        ];
        let mut cases = std::vec::Vec::new();
        for &a in &edges {
            for &b in &edges {
                for (sa, sb) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                    cases.push((sa * a, sb * b));
                }
            }
        }
        let mut rng = Lcg(0xd1f0_4071_0a11_5eed);
        for _ in 0..100_000 {
            let n = (rng.below(1 << 63) as i128 - (1 << 62)) >> rng.below(60);
            let d = (rng.below(1 << 63) as i128 - (1 << 62)) >> rng.below(62);
            cases.push((n, d));
            // Exact halves.
            cases.push((d * (n >> 20) + d / 2, d));
        }
        for (n, d) in cases {
            assert_eq!(div_round(n, d), reference(n, d), "{n} / {d}");
        }
    }

    #[test]
    fn the_coarse_sine_is_within_its_bound() {
        extern crate std;
        let mut worst = 0f64;
        let mut a = 0u64;
        while a < 1 << 32 {
            let want = (a as f64 / (1u64 << 32) as f64 * 2.0 * core::f64::consts::PI).sin();
            let got = f64::from(sin_coarse_q15(a as u32)) / 32768.0;
            worst = worst.max((got - want).abs());
            a += 4099;
        }
        for a in [
            0u32,
            1 << 30,
            1 << 31,
            3 << 30,
            u32::MAX,
            (1 << 30) - 1,
            1 << 24,
        ] {
            let want = (f64::from(a) / (1u64 << 32) as f64 * 2.0 * core::f64::consts::PI).sin();
            let got = f64::from(sin_coarse_q15(a)) / 32768.0;
            worst = worst.max((got - want).abs());
        }
        assert!(
            worst * 32768.0 <= f64::from(SIN_COARSE_ERR_Q15),
            "{}",
            worst * 32768.0
        );
        // The table is the rounded sine.
        for (k, &v) in SINE_Q15.iter().enumerate() {
            let want = (k as f64 * core::f64::consts::PI / 128.0).sin() * 32768.0;
            assert!((f64::from(v) - want).abs() <= 0.5 + 1e-9, "{k}");
        }
    }

    /// The series in plain 64- and 128-bit arithmetic, as first written:
    /// the 32-bit forms must give the same bits.
    fn reference_cos_sin_sinc(a: u32) -> (i64, i64, i64) {
        let octant = a >> 29;
        let f = i64::from(a & ((1 << 29) - 1));
        let f = if octant & 1 == 1 { (1 << 29) - f } else { f };
        let x = ((f as i128 * PI_Q61 as i128 + (1i128 << 60)) >> 61) as i64;
        let x2 = (x * x) >> 31;
        let series = |k0: i64, odd: bool| {
            let mut acc = Q31;
            let mut k = k0;
            while k >= 1 {
                let d = if odd {
                    (2 * k) * (2 * k + 1)
                } else {
                    (2 * k - 1) * (2 * k)
                };
                acc = Q31 - ((x2 * acc) >> 31) / d;
                k -= 1;
            }
            acc
        };
        let sinc = series(5, true);
        let s = round_shift((x * sinc) >> 31, 1);
        let c = round_shift(series(6, false), 1);
        let (c, s) = match octant {
            0 => (c, s),
            1 => (s, c),
            2 => (-s, c),
            3 => (-c, s),
            4 => (-c, -s),
            5 => (-s, -c),
            6 => (s, -c),
            _ => (c, -s),
        };
        (c, s, sinc)
    }

    #[test]
    fn division_by_multiplication_is_exact_below_2_pow_31() {
        fn check<const D: u32>() {
            let mut seed = u64::from(D);
            let mut v_of = |k: u32| match k {
                0 => 0,
                1 => (1 << 31) - 1,
                2..=200 => (k - 2) * D + (k % 2) * (D - 1),
                _ => {
                    seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1);
                    (seed >> 33) as u32
                }
            };
            for k in 0..20_000 {
                let v = v_of(k).min((1 << 31) - 1);
                assert_eq!(DivBy::<D>::of(v), v / D, "{v} / {D}");
                // Just below and at every multiple near the top.
                let top = ((1u32 << 31) - 1) / D * D;
                assert_eq!(DivBy::<D>::of(top), top / D);
                assert_eq!(DivBy::<D>::of(top - 1), (top - 1) / D);
            }
        }
        check::<2>();
        check::<6>();
        check::<12>();
        check::<20>();
        check::<30>();
        check::<42>();
        check::<56>();
        check::<72>();
        check::<90>();
        check::<110>();
        check::<132>();
    }

    #[test]
    fn thirty_two_bit_series_give_the_64_bit_bits() {
        let check = |a: u32| {
            let (c, s, _) = reference_cos_sin_sinc(a);
            assert_eq!(cos_sin(a), (c, s), "angle {a}");
            let f = a & ((1 << 29) - 1);
            if f != 0 {
                let (_, _, sinc) = reference_cos_sin_sinc(f);
                assert_eq!(sinc_q31(i64::from(f)), sinc, "sinc at {f}");
            }
        };
        for a in [0, 1, 2, (1 << 29) - 1, 1 << 29, (1 << 29) + 1, u32::MAX] {
            check(a);
        }
        let mut rng = crate::path::testing::Lcg(0x9e37_79b9_7f4a_7c15);
        for _ in 0..200_000 {
            check((rng.next_u64() >> 32) as u32);
        }
        assert_eq!(sinc_q31(1 << 29), reference_cos_sin_sinc(1 << 29).2);
    }
    use super::*;

    #[test]
    fn pi_from_machin_is_exact_to_the_last_bits() {
        // pi * 2^61 = 7244019458077122842.9...
        assert!((PI_Q61 - 7_244_019_458_077_122_843).abs() <= 64);
    }

    #[test]
    fn cos_sin_on_the_axes_is_exact_and_symmetric() {
        assert_eq!(cos_sin(0), (Q30, 0));
        assert_eq!(cos_sin(1 << 30), (0, Q30));
        assert_eq!(cos_sin(1 << 31), (-Q30, 0));
        assert_eq!(cos_sin(3 << 30), (0, -Q30));
        for a in [1u32, 12345, 1 << 27, 0x1234_5678, 0x9abc_def0, u32::MAX] {
            let (c, s) = cos_sin(a);
            let (c2, s2) = cos_sin(a.wrapping_neg());
            assert_eq!((c, -s), (c2, s2));
        }
    }

    #[test]
    fn cos_sin_within_4e_9_of_f64() {
        let mut worst = 0f64;
        for i in 0..5000u32 {
            let a = i.wrapping_mul(858_993_459).wrapping_add(i * 7919);
            let (c, s) = cos_sin(a);
            let t = f64::from(a) / 4_294_967_296.0 * 2.0 * core::f64::consts::PI;
            worst = worst
                .max((c as f64 / Q30 as f64 - t.cos()).abs())
                .max((s as f64 / Q30 as f64 - t.sin()).abs());
        }
        assert!(worst < 4e-9, "{worst}");
    }

    /// The integer `atan2` of a vector in the first quadrant (the turns
    /// of round joins) is at most `ATAN2_SLACK` binary units above the
    /// exact angle (`f64`, exact to far below a unit here), whatever the
    /// vector's length up to 2^31.
    #[test]
    fn atan2_is_within_its_slack_of_the_exact_angle() {
        extern crate std;
        let slack = crate::path::stroke::outline::ATAN2_SLACK;
        let mut rng = crate::path::testing::Lcg(0x0a7a_2e5a);
        let mut worst = 0f64;
        for k in 0..200_000u64 {
            let x = 1 + rng.below(1 << (1 + k % 31)) as i64;
            // Small turns (most joins of a curve), and any.
            let y = if k % 2 == 0 {
                (x >> rng.below(24)) * rng.below(3) as i64 / 2
            } else {
                rng.below(1 << 31) as i64
            };
            let exact = (y as f64).atan2(x as f64) / core::f64::consts::TAU * 4_294_967_296.0;
            let got = f64::from(atan2(y, x));
            worst = worst.max(got - exact);
            assert!(got <= exact + slack as f64, "({x}, {y}): {got} vs {exact}");
        }
        std::println!("atan2 at most {worst:.2} units above the exact angle");
    }

    #[test]
    fn atan2_inverts_cos_sin() {
        for i in 0..3000u32 {
            let a = i.wrapping_mul(2_654_435_761);
            let (c, s) = cos_sin(a);
            let b = atan2(s, c);
            let d = (b.wrapping_sub(a) as i32).abs();
            assert!(d <= 4, "a={a} b={b}");
        }
        assert_eq!(atan2(0, 0), 0);
        assert_eq!(atan2(0, -5), 1 << 31);
        assert_eq!(atan2(i64::MIN, i64::MIN), atan2(-1, -1));
    }

    #[test]
    fn square_roots_are_floors() {
        for v in [
            0u64,
            1,
            2,
            3,
            4,
            15,
            16,
            17,
            u64::MAX,
            1 << 62,
            (1 << 62) - 1,
        ] {
            let r = v.isqrt();
            assert!(u128::from(r) * u128::from(r) <= u128::from(v));
            assert!(u128::from(r + 1) * u128::from(r + 1) > u128::from(v));
        }
        assert_eq!(u128::MAX.isqrt(), u128::from(u64::MAX));
        assert_eq!(ceil_sqrt_u64(17), 5);
        assert_eq!(ceil_sqrt_u64(16), 4);
        // The ceiling about the 32-bit form's edge and squares around it.
        for v in [
            0u64,
            1,
            2,
            (1 << 32) - 1,
            1 << 32,
            (1 << 32) + 1,
            65535 * 65535,
            65535 * 65535 + 1,
            u64::from(u32::MAX) - 5,
            u64::MAX,
        ] {
            let c = u128::from(ceil_sqrt_u64(v));
            assert!(c * c >= u128::from(v), "{v}");
            assert!(c == 0 || (c - 1) * (c - 1) < u128::from(v), "{v}");
        }
    }

    #[test]
    fn sinc_is_one_at_zero_and_matches_f64() {
        assert_eq!(sinc_q31(0), Q31);
        for a in [1i64, 1000, 1 << 20, 1 << 27, 1 << 29] {
            let x = a as f64 / 4_294_967_296.0 * 2.0 * core::f64::consts::PI;
            let want = x.sin() / x;
            assert!((sinc_q31(a) as f64 / Q31 as f64 - want).abs() < 3e-9);
        }
    }
}
