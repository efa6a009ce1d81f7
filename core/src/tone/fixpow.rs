//! Fixed-point `log2`, `exp2` and powers for building tone tables.
//!
//! Used only while a table is built (in a `const fn`, so a table can be a
//! `static` in flash), never per pixel. Everything is integer arithmetic, so
//! every target builds the very same bits.
//!
//! ## Representation and ranges
//!
//! - A *value* is a `u128` in Q62 (`ONE = 2^62` is 1.0). Tables only need
//!   values in `[0, 2^16]` (a contrast `K <= 65535`), i.e. below `2^79`;
//!   [`exp2`] saturates only above `2^64`.
//! - A *logarithm* is an `i64` in Q32 (`2^32` is 1.0). The log of a Q62
//!   value lies in `[-62, 66)`, so `|log| < 2^39`; multiplying it by a
//!   `u16` exponent numerator stays below `2^55`.
//!
//! `log2` is the classic bit-by-bit method: normalise the argument to a
//! mantissa `y` in `[1, 2)`, then square it 32 times; each square that
//! reaches 2 yields a 1 bit of the fraction (and is halved). The mantissa is
//! a Q63 `u64`, its square a `u128`, so nothing overflows; truncation makes
//! the result a floor with an error below `2^-31`.
//!
//! `exp2` is the inverse product: `2^f = prod(2^(2^-k))` over the set bits
//! `k` of the fraction `f`, with the 32 factors `2^(2^-k)` derived once, at
//! compile time, by repeated integer square roots of 2 ([`ROOTS`]). Each
//! product of two Q62 values below `2^63` is below `2^126`.

/// Fraction bits of a value.
pub(crate) const VALUE_FRAC: u32 = 62;
/// 1.0 as a value.
pub(crate) const ONE: u128 = 1 << VALUE_FRAC;
/// Fraction bits of a logarithm.
pub(crate) const LOG_FRAC: u32 = 32;

/// `ROOTS[k] = 2^(2^-(k+1))` in Q62: `sqrt(2)`, `sqrt(sqrt(2))`, ...
const ROOTS: [u128; LOG_FRAC as usize] = {
    let mut roots = [0u128; LOG_FRAC as usize];
    let mut r = 2 * ONE;
    let mut k = 0;
    while k < roots.len() {
        // sqrt(r / 2^62) * 2^62 = sqrt(r * 2^62); r < 2^64, so r << 62 < 2^126.
        r = (r << VALUE_FRAC).isqrt();
        roots[k] = r;
        k += 1;
    }
    roots
};

/// `log2(x / 2^62)` in Q32 for a Q62 value `x > 0`; `i64::MIN` for `x = 0`.
pub(crate) const fn log2(x: u128) -> i64 {
    if x == 0 {
        return i64::MIN;
    }
    let top = 127 - x.leading_zeros(); // bit index of the leading 1
                                       // Mantissa in Q63: the leading 1 moved to bit 63 (low bits truncated).
    let mut m: u128 = if top >= 63 {
        x >> (top - 63)
    } else {
        x << (63 - top)
    };
    let mut frac: i64 = 0;
    let mut k = 0;
    while k < LOG_FRAC {
        m = (m * m) >> 63; // m < 2^64, so m * m < 2^128
        frac <<= 1;
        if m >= 1 << 64 {
            m >>= 1;
            frac |= 1;
        }
        k += 1;
    }
    ((top as i64 - VALUE_FRAC as i64) << LOG_FRAC) + frac
}

/// `2^(y / 2^32)` as a Q62 value; 0 below `2^-62`, saturating above `2^64`.
pub(crate) const fn exp2(y: i64) -> u128 {
    let int = y >> LOG_FRAC; // floor
    let frac = (y & ((1 << LOG_FRAC) - 1)) as u64;
    let mut r = ONE;
    let mut k = 0;
    while k < LOG_FRAC {
        if frac & (1 << (LOG_FRAC - 1 - k)) != 0 {
            r = (r * ROOTS[k as usize]) >> VALUE_FRAC; // both < 2^63
        }
        k += 1;
    }
    if int > 64 {
        u128::MAX >> 1
    } else if int >= 0 {
        // r < 2^63, so r << 64 < 2^127.
        r << int as u32
    } else if int > -(VALUE_FRAC as i64 + 2) {
        r >> (-int) as u32
    } else {
        0
    }
}

/// `x^(num / den)` for a Q62 value `x <= ONE` (larger `x` are clamped to
/// `ONE`); 0 for `x = 0` or `den = 0`.
pub(crate) const fn pow_frac(x: u128, num: u32, den: u32) -> u128 {
    if x == 0 || den == 0 {
        return 0;
    }
    let x = if x > ONE { ONE } else { x };
    let l = log2(x); // in [-62 * 2^32, 0]
    exp2((l * num as i64).div_euclid(den as i64))
}

/// `K^(n / d)` as a Q62 value, for `K >= 1` and `0 <= n <= d`, `d > 0`.
pub(crate) const fn contrast_pow(k: u16, n: i64, d: i64) -> u128 {
    let lk = log2((k as u128) << VALUE_FRAC); // < 16 * 2^32
    exp2((lk * n).div_euclid(d))
}

/// `round(x * max)` for a Q62 value `x`, clamped to `0..=max`.
pub(crate) const fn round_to(x: u128, max: u32) -> u32 {
    let x = if x > 2 * ONE { 2 * ONE } else { x };
    let c = (x * max as u128 + (ONE >> 1)) >> VALUE_FRAC;
    if c > max as u128 {
        max
    } else {
        c as u32
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn log2_of_powers_of_two_is_exact() {
        assert_eq!(log2(ONE), 0);
        assert_eq!(log2(2 * ONE), 1 << LOG_FRAC);
        assert_eq!(log2(ONE >> 5), -5 << LOG_FRAC);
    }

    #[test]
    fn exp2_inverts_log2_within_2_pow_minus_30() {
        for x in [3u128, 1000, 4095, 65_535] {
            let v = x << VALUE_FRAC;
            let back = exp2(log2(v));
            let err = back.abs_diff(v);
            assert!(err <= v >> 29, "x = {x}: {back} vs {v}");
        }
    }

    #[test]
    fn exp2_of_integers_is_exact() {
        assert_eq!(exp2(0), ONE);
        assert_eq!(exp2(1 << LOG_FRAC), 2 * ONE);
        assert_eq!(exp2(-3 << LOG_FRAC), ONE >> 3);
        assert_eq!(exp2(-100 << LOG_FRAC), 0);
    }

    #[test]
    fn roots_square_to_their_predecessor() {
        let mut prev = 2 * ONE;
        for r in ROOTS {
            let sq = (r * r) >> VALUE_FRAC;
            assert!(sq.abs_diff(prev) <= 4, "{sq} vs {prev}");
            prev = r;
        }
    }
}
