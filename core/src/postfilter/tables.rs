//! The tables of the lightness filter, each computed by a `const fn` from its
//! formula (exact integer or rational arithmetic in `u128`/`i128`), so they
//! are `static`s in flash and bit-identical on every target.
//!
//! | table | entries | type | bytes | formula |
//! |---|---|---|---|---|
//! | [`F_TABLE`] | 4097 | `u16` | 8194 | `F = round(F_ONE * f(i / 4095))` |
//! | [`F_INV_TABLE`] | 4097 | `u16` | 8194 | `T = round(T_ONE * f⁻¹(16 i / F_ONE))` |
//! | [`LSTAR_STEPS`] | 100 | `u16` | 200 | least `F` with `L* >= n - 1/2` |
//! | [`K_TWENTIETHS`] | 101 | `u8` | 101 | table 4.1 of seed 002, `20 k` |
//! | [`K_Q15`] | 101 | `u16` | 202 | `round(2^15 k)` |
//!
//! `f` is the CIE 1976 function with its linear segment
//! (`δ = 6/29`): `f(t) = t^(1/3)` for `t > δ³`, else `t / (3 δ²) + 4/29`;
//! `f⁻¹(u) = u³` for `u > δ`, else `3 δ² (u - 4/29)`.

/// `f = 1` in the units of the cube-root values `F` (`fx`, `fy`, `fz`):
/// `L* = 116 F / F_ONE - 16`.
/// ```
/// use softedge::postfilter::{Lab, F_ONE};
/// assert_eq!(Lab::from_gray(4095).fy, F_ONE);
/// ```
pub const F_ONE: i32 = 65535;

/// Fraction bits of a tristimulus value `T` (`X/Xn`, `Y/Yn`, `Z/Zn`) below
/// the 12 bits of `lin12`.
/// ```
/// use softedge::postfilter::{T_FRAC, T_ONE};
/// assert_eq!(T_ONE, 4095 << T_FRAC);
/// ```
pub const T_FRAC: u32 = 4;

/// `X/Xn = 1` in tristimulus units: `4095 << 4 = 65520`, so a gray `lin12`
/// value `v` has `Y/Yn = 16 v` exactly.
/// ```
/// use softedge::postfilter::{F_INV_TABLE, T_ONE};
/// assert!(i32::from(F_INV_TABLE[4095]) <= T_ONE);
/// ```
pub const T_ONE: i32 = 4095 << T_FRAC;

/// Entries of [`F_TABLE`] and [`F_INV_TABLE`]: one per 12-bit index, plus
/// one so that linear interpolation may read `i + 1`.
/// ```
/// use softedge::postfilter::{F_TABLE, TABLE_LEN};
/// assert_eq!(F_TABLE.len(), TABLE_LEN);
/// ```
pub const TABLE_LEN: usize = 4097;

/// `F` of black: `round(F_ONE * 4/29)` (the foot of the linear segment).
/// ```
/// use softedge::postfilter::{Lab, F_BLACK};
/// assert_eq!(Lab::from_gray(0).fy, F_BLACK);
/// ```
pub const F_BLACK: i32 = ((2 * F_ONE as i64 * 4 + 29) / (2 * 29)) as i32;

/// `round(a / b)` for `a >= 0`, `b > 0`.
const fn div_round(a: u128, b: u128) -> u128 {
    (2 * a + b) / (2 * b)
}

/// `F_TABLE[i] = round(F_ONE * f(i / 4095))`, `i = 0..=4095`; the last entry
/// (`i = 4096`, read only with a zero interpolation weight) saturates at
/// `F_ONE`.
const fn f_entry(i: u128) -> u16 {
    let one = F_ONE as u128;
    if i >= 4095 {
        return F_ONE as u16;
    }
    // t <= δ³ = 216 / 24389 (t = i / 4095): the linear segment
    // f = t * 841 / 108 + 4 / 29 = (29 * 841 i + 4 * 108 * 4095) / (4095 * 108 * 29).
    if i * 24389 <= 216 * 4095 {
        let num = one * (i * 841 * 29 + 4 * 4095 * 108);
        return div_round(num, 4095 * 108 * 29) as u16;
    }
    // F = round(cbrt(x)), x = F_ONE³ i / 4095: the largest r with
    // (r - 1/2)³ <= x, i.e. (2r - 1)³ * 4095 <= 8 * F_ONE³ * i
    // (both sides below 2^64).
    let rhs = 8 * one * one * one * i;
    let (mut lo, mut hi) = (0u128, one + 1); // lo satisfies, hi does not
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        let s = 2 * mid - 1;
        if s * s * s * 4095 <= rhs {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo as u16
}

/// `F_INV_TABLE[i] = round(T_ONE * f⁻¹(u))` at `u = 16 i / F_ONE`, clamped
/// to `0` below black (`u < 4/29` is a negative tristimulus value, outside
/// every gamut) and to `u16::MAX`.
const fn f_inv_entry(i: u128) -> u16 {
    let one = F_ONE as u128;
    let t_one = T_ONE as u128;
    let fq = 16 * i;
    let t = if fq * 29 > 6 * one {
        // u > δ: t = u³; fq³ * T_ONE < 2^64.
        div_round(t_one * fq * fq * fq, one * one * one)
    } else if fq * 29 <= 4 * one {
        0
    } else {
        // t = 3 δ² (u - 4/29) = 108 / 841 * (29 fq - 4 F_ONE) / (29 F_ONE)
        div_round(t_one * 108 * (29 * fq - 4 * one), 841 * 29 * one)
    };
    if t > u16::MAX as u128 {
        u16::MAX
    } else {
        t as u16
    }
}

/// The cube-root table: `f(t)` for `t = i / 4095`, in units of
/// `1 / F_ONE` (so it is also the `Y -> L*` table: `L* = 116 F / F_ONE - 16`).
/// One table serves `X`, `Y` and `Z`.
///
/// ```
/// use softedge::postfilter::{F_ONE, F_TABLE};
/// // Y/Yn = 0.5 (2047.5 / 4095): L* = 116 * 0.5^(1/3) - 16 = 76.07
/// let l = 116.0 * f64::from(F_TABLE[2048]) / f64::from(F_ONE) - 16.0;
/// assert!((l - 76.08).abs() < 0.01);
/// ```
pub static F_TABLE: [u16; TABLE_LEN] = {
    let mut t = [0u16; TABLE_LEN];
    let mut i = 0;
    while i < TABLE_LEN {
        t[i] = f_entry(i as u128);
        i += 1;
    }
    t
};

/// The inverse table: `f⁻¹(u)` for `u = 16 i / F_ONE`, in tristimulus units
/// (`T_ONE` = the white point).
///
/// ```
/// use softedge::postfilter::{F_INV_TABLE, F_TABLE, T_FRAC};
/// // f⁻¹(f(t)) = t, to a fraction of a level
/// let f = F_TABLE[1000];
/// let t = F_INV_TABLE[usize::from(f >> 4)];
/// assert!(((t >> T_FRAC) as i32 - 1000).abs() <= 1);
/// ```
pub static F_INV_TABLE: [u16; TABLE_LEN] = {
    let mut t = [0u16; TABLE_LEN];
    let mut i = 0;
    while i < TABLE_LEN {
        t[i] = f_inv_entry(i as u128);
        i += 1;
    }
    t
};

/// `LSTAR_STEPS[n - 1]` is the least `F` whose `L* = 116 F / F_ONE - 16` is
/// at least `n - 1/2`: `ceil((2n + 31) F_ONE / 232)`, `n = 1..=100`. The
/// number of steps at or below `F` is `L*` rounded to the nearest integer
/// (halves up).
///
/// ```
/// use softedge::postfilter::LSTAR_STEPS;
/// assert!(LSTAR_STEPS.windows(2).all(|w| w[0] < w[1]));
/// ```
pub static LSTAR_STEPS: [u16; 100] = {
    let mut t = [0u16; 100];
    let mut n = 1;
    while n <= 100 {
        let num = (2 * n + 31) * F_ONE as u32;
        t[n as usize - 1] = num.div_ceil(232) as u16;
        n += 1;
    }
    t
};

/// Table 4.1 of seed 002 as printed: `(first L*, last L*, 20 k)`.
const TABLE_4_1: [(u8, u8, u8); 8] = [
    (0, 54, 0),   // k = 0
    (55, 62, 1),  // k = 0.05
    (63, 72, 2),  // k = 0.1
    (73, 81, 3),  // k = 0.15
    (82, 89, 4),  // k = 0.2
    (90, 93, 3),  // k = 0.15
    (94, 96, 2),  // k = 0.1
    (97, 100, 0), // k = 0
];

/// The filter weight of seed 002, table 4.1, in twentieths:
/// `k = K_TWENTIETHS[L*] / 20` for integer `L* = 0..=100`.
///
/// ```
/// use softedge::postfilter::K_TWENTIETHS;
/// assert_eq!(K_TWENTIETHS[54], 0);
/// assert_eq!(K_TWENTIETHS[85], 4); // k = 0.2
/// assert_eq!(K_TWENTIETHS[100], 0);
/// ```
pub static K_TWENTIETHS: [u8; 101] = {
    let mut t = [0u8; 101];
    let mut r = 0;
    while r < TABLE_4_1.len() {
        let (first, last, k20) = TABLE_4_1[r];
        let mut l = first as usize;
        while l <= last as usize {
            t[l] = k20;
            l += 1;
        }
        r += 1;
    }
    t
};

/// Fraction bits of [`K_Q15`].
/// ```
/// use softedge::postfilter::{K_FRAC, K_Q15};
/// assert_eq!(K_Q15[85], ((1u32 << K_FRAC) / 5) as u16 + 1); // 0.2 = 6553.6 / 2^15, rounded
/// ```
pub const K_FRAC: u32 = 15;

/// `k` in Q15 by integer `L*`: `round(2^15 * K_TWENTIETHS[L*] / 20)`. The
/// rounding moves `k` by at most `2^-16`, `L*` by at most `400 * 2^-16 <
/// 0.007` (the Laplacian of `L*` is at most 400 in magnitude).
///
/// ```
/// use softedge::postfilter::K_Q15;
/// assert_eq!(K_Q15[60], 1638); // 0.05 * 32768 = 1638.4
/// ```
pub static K_Q15: [u16; 101] = {
    let mut t = [0u16; 101];
    let mut l = 0;
    while l < 101 {
        t[l] = div_round(K_TWENTIETHS[l] as u128 * (1 << K_FRAC), 20) as u16;
        l += 1;
    }
    t
};

/// `L*` rounded to the nearest integer (halves up) for a cube-root value
/// `F`: a binary search over [`LSTAR_STEPS`] (7 compares).
#[inline]
pub(crate) fn lstar_round(f: i32) -> usize {
    LSTAR_STEPS.partition_point(|&s| i32::from(s) <= f)
}

/// `F = F_ONE * f(t)` for a tristimulus value `t` (`0..=T_ONE`, clamped):
/// table look-up at the 12 integer bits, linear interpolation over the 4
/// fraction bits (one small multiply: `|ΔF| <= 125` per step, times `< 16`).
#[inline]
pub(crate) fn f_of_t(t: i32) -> i32 {
    let t = t.clamp(0, T_ONE);
    let i = (t >> T_FRAC) as usize;
    let w = t & ((1 << T_FRAC) - 1);
    let a = i32::from(F_TABLE.get(i).copied().unwrap_or(F_ONE as u16));
    if w == 0 {
        return a;
    }
    let b = i32::from(F_TABLE.get(i + 1).copied().unwrap_or(F_ONE as u16));
    a + (((b - a) * w + (1 << (T_FRAC - 1))) >> T_FRAC)
}

/// `t = T_ONE * f⁻¹(F / F_ONE)` for `F` in `F_BLACK..=F_ONE` (callers
/// clamp): look-up at the top 12 bits of `F`, linear interpolation over the
/// low 4 (one small multiply: steps are at most 49 units).
#[inline]
pub(crate) fn t_of_f(f: i32) -> i32 {
    let f = f.clamp(0, F_ONE);
    let i = (f >> 4) as usize;
    let w = f & 15;
    let a = i32::from(F_INV_TABLE.get(i).copied().unwrap_or(0));
    if w == 0 {
        return a;
    }
    let b = i32::from(F_INV_TABLE.get(i + 1).copied().unwrap_or(0));
    a + (((b - a) * w + 8) >> 4)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn f_table_is_strictly_increasing_from_black_to_white() {
        assert_eq!(i32::from(F_TABLE[0]), F_BLACK);
        assert_eq!(i32::from(F_TABLE[4095]), F_ONE);
        for w in F_TABLE[..4096].windows(2) {
            assert!(w[1] > w[0]);
        }
    }

    #[test]
    fn f_inv_table_is_monotone_and_maps_white_to_white() {
        assert_eq!(t_of_f(F_ONE), T_ONE);
        assert_eq!(t_of_f(F_BLACK), 0);
        for w in F_INV_TABLE.windows(2) {
            assert!(w[1] >= w[0]);
        }
    }

    #[test]
    fn f_then_f_inverse_returns_every_gray_level() {
        for v in 0..=4095 {
            let t = v << T_FRAC;
            let back = (t_of_f(f_of_t(t)) + 8) >> T_FRAC;
            assert_eq!(back, v);
        }
    }

    #[test]
    fn lstar_round_counts_half_steps() {
        // L* = 116 F / F_ONE - 16, so F = (L* + 16) F_ONE / 116.
        let f_at = |l: f64| ((l + 16.0) * f64::from(F_ONE) / 116.0).round() as i32;
        for n in 0..=100 {
            assert_eq!(lstar_round(f_at(f64::from(n))), n as usize);
            assert_eq!(lstar_round(f_at(f64::from(n) + 0.49)), n as usize);
        }
        assert_eq!(lstar_round(F_BLACK), 0);
        assert_eq!(lstar_round(F_ONE), 100);
    }

    #[test]
    fn k_q15_is_k_within_2_pow_minus_16() {
        for l in 0..=100 {
            let k = f64::from(K_TWENTIETHS[l]) / 20.0;
            let q = f64::from(K_Q15[l]) / 32768.0;
            assert!((k - q).abs() <= 1.0 / 65536.0);
        }
    }
}
