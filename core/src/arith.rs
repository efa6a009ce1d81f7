//! Integer division without panic paths, and the few other integer and
//! memory primitives the Cortex-M0 needs written out (wide products, a
//! slice fill).
//!
//! Every divisor in the setup code is positive by construction (an edge's
//! extent, a triangle's doubled area, one pixel in sub-pixels), but the
//! compiler cannot see that, and a firmware build that forbids panics must
//! link. These helpers floor like `div_euclid` for positive divisors and
//! give 0 for a zero divisor (or the one overflowing quotient), which no
//! caller produces.

/// `(floor(n / d), n - d * floor(n / d))` for `d > 0`; `(0, 0)` if `d <= 0`.
///
/// One division for both (on the Cortex-M0 a library call), in 32 bits
/// when both operands fit: a 64-bit division costs several times more.
#[inline]
pub(crate) fn divmod_floor(n: i64, d: i64) -> (i64, i64) {
    if d <= 0 {
        return (0, 0);
    }
    let (q, r) = match (i32::try_from(n), i32::try_from(d)) {
        (Ok(n32), Ok(d32)) if n32 != i32::MIN => {
            let (q, r) = (n32 / d32, n32 % d32);
            (i64::from(q), i64::from(r))
        }
        _ => (n / d, n % d),
    };
    if r < 0 {
        (q - 1, r + d)
    } else {
        (q, r)
    }
}

/// `floor(n / d)` for `d > 0`; 0 if `d <= 0`.
#[inline]
pub(crate) fn div_floor(n: i64, d: i64) -> i64 {
    divmod_floor(n, d).0
}

/// `n - d * floor(n / d)` (in `0..d`) for `d > 0`; 0 if `d <= 0`.
#[inline]
pub(crate) fn rem_floor(n: i64, d: i64) -> i64 {
    divmod_floor(n, d).1
}

/// `(n / d, n % d)` for `d > 0` (`(0, 0)` for `d == 0`), in 32 bits when
/// both fit.
#[inline]
pub(crate) fn udivmod(n: u64, d: u64) -> (u64, u64) {
    if d == 0 {
        return (0, 0);
    }
    match (u32::try_from(n), u32::try_from(d)) {
        (Ok(n32), Ok(d32)) => (u64::from(n32 / d32), u64::from(n32 % d32)),
        _ => (n / d, n % d),
    }
}

/// `(n / d, n % d)` for `d > 0` (`(0, 0)` for `d == 0`), for quotients
/// that are mostly small: below 3 by comparisons and subtractions, else
/// divided (on the Cortex-M0 a library call of about a hundred
/// instructions whatever the quotient).
#[inline]
pub(crate) fn divmod_small(n: u32, d: u32) -> (u32, u32) {
    if n < d {
        return (0, n);
    }
    let r = n - d;
    if r < d {
        return (1, r);
    }
    let r = r - d;
    if r < d {
        return (2, r);
    }
    match (n.checked_div(d), n.checked_rem(d)) {
        (Some(q), Some(r)) => (q, r),
        _ => (0, 0),
    }
}

/// `floor((2^32 - 1) / d)` for `d > 0` (0 for `d == 0`): the inverse
/// [`div_by_inverse`] divides by, one division to set it up.
#[inline]
pub(crate) fn inverse(d: u32) -> u32 {
    u32::MAX.checked_div(d).unwrap_or(0)
}

/// `floor(n / d)` for `d > 0`, with `inv = inverse(d)`: a product and one
/// correction instead of a division (on the Cortex-M0 a library call of
/// about a hundred instructions, here some twenty). Exact for every
/// `n < 2^32`: `2^32 - d <= inv d < 2^32`, so `q' = floor(n inv / 2^32)`
/// lies in `(n / d - n / 2^32 - 1, n / d]`, that is, `q'` is `q` or
/// `q - 1`, and the remainder `n - q' d` (below `2 d`) tells which.
#[inline(always)]
pub(crate) fn div_by_inverse(n: u32, d: u32, inv: u32) -> u32 {
    let q = (mul_wide(n, inv) >> 32) as u32;
    // q d <= n: the product and the difference do not wrap.
    let r = n.wrapping_sub(q.wrapping_mul(d));
    if r >= d {
        q + 1
    } else {
        q
    }
}

/// `a * b` in full, `u32 x u32 -> u64`, from four 16-bit products: the
/// Cortex-M0's multiply keeps the low 32 bits only, and a 64-bit product is
/// a library call several times longer. (On a 64-bit host, the one
/// multiply it has: the same product.)
#[inline]
pub(crate) fn mul_wide(a: u32, b: u32) -> u64 {
    if cfg!(target_pointer_width = "64") {
        return u64::from(a) * u64::from(b);
    }
    mul_wide_halves(a, b)
}

/// [`mul_wide`] from 16-bit halves (what 32-bit targets run; tested on
/// every host).
#[inline]
fn mul_wide_halves(a: u32, b: u32) -> u64 {
    let (a0, a1) = (a & 0xffff, a >> 16);
    let (b0, b1) = (b & 0xffff, b >> 16);
    // Each partial product is below 2^32; the middle sum below 2^33.
    let mid = u64::from(a0 * b1) + u64::from(a1 * b0);
    (u64::from(a1 * b1) << 32) + (mid << 16) + u64::from(a0 * b0)
}

/// `a * b` for `|a b| < 2^31` (the caller states why): one 32-bit
/// multiply where `i64` would call the Cortex-M0's 64-bit multiply
/// routine.
#[inline]
pub(crate) fn mul_small(a: i64, b: i64) -> i64 {
    i64::from((a as i32).wrapping_mul(b as i32))
}

/// `a * b` for `|a b| < 2^63` (the caller states why), from the halves
/// of `a`: [`mul_wide`] of the low one and a 32-bit multiply of the high
/// one, which the bound keeps below `2^31`.
#[inline]
pub(crate) fn mul_i64_i32(a: i64, b: i32) -> i64 {
    let (ua, ub) = (a.unsigned_abs(), b.unsigned_abs());
    let p = mul_wide(ua as u32, ub) + (u64::from(((ua >> 32) as u32).wrapping_mul(ub)) << 32);
    if (a < 0) != (b < 0) {
        (p as i64).wrapping_neg()
    } else {
        p as i64
    }
}

/// `a * b` in full for signed `a`, `b` (see [`mul_wide`]).
#[inline]
pub(crate) fn imul_wide(a: i32, b: i32) -> i64 {
    let p = mul_wide(a.unsigned_abs(), b.unsigned_abs()) as i64;
    if (a < 0) != (b < 0) {
        -p
    } else {
        p
    }
}

/// `a * b` for any `i64`s (as `i64 * i64`, whose overflow it keeps): on a
/// 32-bit target one [`imul_wide`] when both fit in `i32`, as they do for
/// the stroker's unit normals and offsets in the coordinate range; else
/// (and on a 64-bit host) the plain product.
#[inline]
pub(crate) fn mul_i64(a: i64, b: i64) -> i64 {
    if cfg!(target_pointer_width = "64") {
        return a * b;
    }
    mul_i64_halves(a, b)
}

/// [`mul_i64`] as 32-bit targets take it (tested on every host; there
/// [`imul_wide`] is [`mul_wide_halves`]'s, tested on its own).
#[inline]
fn mul_i64_halves(a: i64, b: i64) -> i64 {
    match (i32::try_from(a), i32::try_from(b)) {
        (Ok(a), Ok(b)) => imul_wide(a, b),
        _ => a * b,
    }
}

/// `a * b` in full, `i64 x i64 -> i128`: on a 32-bit target one
/// [`imul_wide`] when both fit in `i32` (a 128-bit product is three or
/// four 64-bit library calls on the Cortex-M0); else the plain product.
#[inline]
pub(crate) fn mul_i128(a: i64, b: i64) -> i128 {
    if cfg!(target_pointer_width = "64") {
        return i128::from(a) * i128::from(b);
    }
    mul_i128_halves(a, b)
}

/// [`mul_i128`] as 32-bit targets take it (tested on every host, as
/// [`mul_i64_halves`]).
#[inline]
fn mul_i128_halves(a: i64, b: i64) -> i128 {
    match (i32::try_from(a), i32::try_from(b)) {
        (Ok(a), Ok(b)) => i128::from(imul_wide(a, b)),
        _ => i128::from(a) * i128::from(b),
    }
}

/// `ceil(n / d)` for `d > 0`; 0 if `d == 0`.
#[inline]
pub(crate) fn div_ceil(n: i64, d: i64) -> i64 {
    div_floor(n, d) + i64::from(rem_floor(n, d) != 0)
}

/// `v` limited to `[lo, hi]`; `lo` wins if the bounds cross (where
/// `clamp` would panic).
#[inline]
pub(crate) fn limit(v: i64, lo: i64, hi: i64) -> i64 {
    v.min(hi).max(lo)
}

/// `floor(sqrt(n))` for any `u64`: [`isqrt64`] below `2^50` (lengths in
/// the coordinate range); above, the root of the top 32 bits by
/// [`isqrt32`], then the low 32 bits two at a time as [`isqrt64`] takes
/// them, the remainder in `u64` (below `2 sqrt(n) + 1 < 2^33`). The
/// library's root divides (on the Cortex-M0 several library calls, about
/// five times as many instructions: a stroke's unit normals take such
/// roots, `path::vector::Pt::unit`).
#[inline]
pub(crate) fn isqrt_u64(n: u64) -> u64 {
    if n < 1 << 50 {
        return u64::from(isqrt64(n));
    }
    let (hi, lo) = ((n >> 32) as u32, n as u32);
    let mut root = u64::from(isqrt32(hi));
    let mut rem = u64::from(hi) - root * root;
    let mut k = 16u32;
    while k > 0 {
        k -= 1;
        rem = (rem << 2) | u64::from((lo >> (2 * k)) & 3);
        let t = (root << 2) | 1;
        root <<= 1;
        if rem >= t {
            rem -= t;
            root |= 1;
        }
    }
    root
}

/// `floor(sqrt(n))` for `n < 2^50`: the root of its top 32 bits (an even
/// shift) by [`isqrt32`], then the remaining bits two at a time, the
/// remainder in `u32` (below `2 sqrt(n) + 1 < 2^26`).
#[inline]
pub(crate) fn isqrt64(n: u64) -> u32 {
    let hi = (n >> 32) as u32;
    if hi == 0 {
        return isqrt32(n as u32);
    }
    // Pairs below the top 32 bits: hi >> 2k == 0, k <= 9.
    let mut k = 1u32;
    while k < 15 && (hi >> (2 * k)) != 0 {
        k += 1;
    }
    // In 32-bit words (a variable 64-bit shift is a call on an M0).
    let lo = n as u32;
    let top = (hi << (32 - 2 * k)) | (lo >> (2 * k));
    let mut root = isqrt32(top);
    let mut rem = top - root * root;
    while k > 0 {
        k -= 1;
        rem = (rem << 2) | ((lo >> (2 * k)) & 3);
        let t = (root << 2) | 1;
        root <<= 1;
        if rem >= t {
            rem -= t;
            root |= 1;
        }
    }
    root
}

/// `floor(sqrt(n))`: `n` shifted left by an even amount into `[2^30,
/// 2^32)`, its root estimated from [`ROOTS`] by linear interpolation
/// (within two units of the root of the shifted value), shifted back and
/// corrected to the floor by comparing squares (`u32` products: the root
/// is below `2^16`). The bit-by-bit root costs about four times as many
/// Cortex-M0 instructions.
#[inline]
pub(crate) fn isqrt32(n: u32) -> u32 {
    if n == 0 {
        return 0;
    }
    let (mut m, mut s) = (n, 0u32);
    if m < 1 << 16 {
        m <<= 16;
        s += 8;
    }
    if m < 1 << 24 {
        m <<= 8;
        s += 4;
    }
    if m < 1 << 28 {
        m <<= 4;
        s += 2;
    }
    if m < 1 << 30 {
        m <<= 2;
        s += 1;
    }
    // m in [2^30, 2^32): entries 32..128 of the table, 2^25 apart.
    let i = (m >> 25) as usize;
    let f = (m >> 13) & 0xfff;
    let a = ROOTS.get(i).copied().unwrap_or(0);
    let b = ROOTS.get(i + 1).copied().unwrap_or(a);
    // sqrt(m) in 1/256, then the root of n (s halvings).
    let est = (a + (((b - a) * f) >> 12)) >> 8;
    let mut r = (est >> s).min(u32::from(u16::MAX));
    while r * r > n {
        r -= 1;
    }
    while r < u32::from(u16::MAX) && (r + 1) * (r + 1) <= n {
        r += 1;
    }
    r
}

/// `sqrt(i * 2^25) * 256`, rounded down, `i = 0..=128` (entries below 32
/// are not used): [`isqrt32`]'s estimate, made at compile time.
static ROOTS: [u32; 129] = {
    let mut t = [0u32; 129];
    let mut i = 0;
    while i < 129 {
        // sqrt(i * 2^25 * 2^16) = sqrt(i * 2^41), by bits (u64, exact).
        let n = (i as u64) << 41;
        let (mut op, mut res, mut one) = (n, 0u64, 1u64 << 62);
        while one > op {
            one >>= 2;
        }
        while one != 0 {
            if op >= res + one {
                op -= res + one;
                res = (res >> 1) + one;
            } else {
                res >>= 1;
            }
            one >>= 2;
        }
        t[i] = res as u32;
        i += 1;
    }
    t
};

/// `v` into every element of `run`, eight stores a loop (a slice's
/// `fill` of a 16- or 32-bit value compares after every store on the
/// Cortex-M0: three instructions an element, here about one and a half).
#[inline(always)]
pub(crate) fn fill<O: Copy>(run: &mut [O], v: O) {
    let mut eights = run.chunks_exact_mut(8);
    for e in &mut eights {
        // Eight stores written out: `*e = [v; 8]` is a loop of eight
        // again where a firmware is built for size (`opt-level = "s"`).
        if let [a, b, c, d, e, f, g, h] = e {
            (*a, *b, *c, *d) = (v, v, v, v);
            (*e, *f, *g, *h) = (v, v, v, v);
        }
    }
    for o in eights.into_remainder() {
        *o = v;
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// Both paths of the wide products against `i128` arithmetic.
    /// `fill` stores `v` in every element and nothing else, for every
    /// length across a few chunks of eight and every start within one.
    #[test]
    fn fill_stores_every_element() {
        for len in 0..40 {
            for start in 0..8 {
                let mut buf = [7u16; 56];
                fill(&mut buf[start..start + len], 0x1234);
                for (k, &b) in buf.iter().enumerate() {
                    let want = if (start..start + len).contains(&k) {
                        0x1234
                    } else {
                        7
                    };
                    assert_eq!(b, want, "len {len}, start {start}, element {k}");
                }
            }
        }
    }

    #[test]
    fn products_are_those_of_i128_on_both_paths() {
        let edges = [
            0i64,
            1,
            2,
            0xffff,
            0x1_0000,
            (1 << 30) + 1,
            i64::from(i32::MAX),
            1 << 31,
            (1 << 31) + 1,
            1 << 40,
            i64::MAX,
        ];
        let mut rng = crate::path::testing::Lcg(0x3a17_0f1d_e0c4_11aa);
        let mut cases = std::vec::Vec::new();
        for &a in &edges {
            for &b in &edges {
                for (sa, sb) in [(1, 1), (-1, 1), (1, -1), (-1, -1)] {
                    cases.push((sa * a, sb * b));
                }
            }
        }
        cases.push((i64::MIN, 1));
        cases.push((i64::from(i32::MIN), i64::from(i32::MIN)));
        for _ in 0..100_000 {
            let a = (rng.below(u64::MAX) as i64) >> rng.below(63);
            let b = (rng.below(u64::MAX) as i64) >> rng.below(63);
            cases.push((a, b));
        }
        for (a, b) in cases {
            let full = i128::from(a) * i128::from(b);
            assert_eq!(mul_i128(a, b), full, "{a} * {b}");
            assert_eq!(mul_i128_halves(a, b), full, "{a} * {b}");
            if let Ok(p) = i64::try_from(full) {
                assert_eq!(mul_i64(a, b), p, "{a} * {b}");
                assert_eq!(mul_i64_halves(a, b), p, "{a} * {b}");
            }
            let (ua, ub) = (a as u32, b as u32);
            assert_eq!(mul_wide_halves(ua, ub), u64::from(ua) * u64::from(ub));
            assert_eq!(mul_wide(ua, ub), u64::from(ua) * u64::from(ub));
        }
    }

    #[test]
    fn divmod_agrees_with_euclid_on_both_paths() {
        for n in [
            -(1i64 << 40) - 7,
            -1_000_001,
            -7,
            -1,
            0,
            1,
            7,
            1_000_001,
            1 << 40,
            i64::from(i32::MIN),
            i64::from(i32::MAX),
        ] {
            for d in [1i64, 2, 3, 16, 1023, 1 << 20, (1 << 33) + 5] {
                assert_eq!(
                    divmod_floor(n, d),
                    (n.div_euclid(d), n.rem_euclid(d)),
                    "{n} / {d}"
                );
                let (un, ud) = (n.unsigned_abs(), d as u64);
                assert_eq!(udivmod(un, ud), (un / ud, un % ud));
            }
        }
        assert_eq!(udivmod(5, 0), (0, 0));
    }

    #[test]
    fn small_quotients_by_subtraction_agree_with_division() {
        for d in [
            1u32,
            2,
            3,
            7,
            1000,
            1 << 22,
            u32::MAX / 2,
            u32::MAX / 3,
            u32::MAX,
        ] {
            for k in [0u32, 1, 2, 3, 4, 1000] {
                for e in [0u32, 1, d / 2, d - 1] {
                    let Some(n) = d.checked_mul(k).and_then(|m| m.checked_add(e)) else {
                        continue;
                    };
                    assert_eq!(divmod_small(n, d), (n / d, n % d), "{n} / {d}");
                }
            }
        }
        assert_eq!(divmod_small(5, 0), (0, 0));
    }

    #[test]
    fn division_by_the_inverse_is_exact_for_every_u32_numerator() {
        // The divisors at the ends of the range and near powers of two,
        // each with the numerators where an error would show first (the
        // multiples of `d` and their neighbours, the top of the range),
        // then random pairs.
        let mut divisors = std::vec![1u32, 2, 3, 5, 7, 255, 256, 257, u32::MAX, u32::MAX - 1];
        for k in 1..32 {
            divisors.extend([(1u32 << k) - 1, 1 << k, (1 << k) + 1]);
        }
        for &d in &divisors {
            let inv = inverse(d);
            let mut ns = std::vec![0u32, 1, u32::MAX, u32::MAX - 1, d - 1, d, d.wrapping_add(1)];
            for q in [1u32, 2, 3, 1000, u32::MAX / d, u32::MAX / d - 1] {
                let m = q.wrapping_mul(d);
                if u64::from(q) * u64::from(d) <= u64::from(u32::MAX) {
                    ns.extend([m, m.wrapping_sub(1), m.saturating_add(1)]);
                }
            }
            for n in ns {
                assert_eq!(div_by_inverse(n, d, inv), n / d, "{n} / {d}");
            }
        }
        let mut x = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let n = x as u32;
            let d = (((x >> 32) as u32) >> (x % 31)).max(1);
            assert_eq!(div_by_inverse(n, d, inverse(d)), n / d, "{n} / {d}");
        }
        assert_eq!(inverse(0), 0);
    }

    #[test]
    fn narrow_products_are_the_full_products_within_their_bounds() {
        // A simple generator: the crate's test Lcg lives in `path`.
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = move || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        for _ in 0..20_000 {
            let r = next();
            // mul_small: |a b| < 2^31.
            let bits = (r % 31) as u32;
            let a = (next() % (1 << bits)) as i64 * if r & 1 == 0 { 1 } else { -1 };
            let b_lim = (1i64 << 31) / a.abs().max(1);
            let b = (next() % b_lim as u64) as i64 * if r & 2 == 0 { 1 } else { -1 };
            assert_eq!(i128::from(mul_small(a, b)), i128::from(a) * i128::from(b));
            // mul_i64_i32: |a b| < 2^63, b any i32.
            let b = next() as i32;
            let a_lim = (1u64 << 63) / u64::from(b.unsigned_abs().max(1));
            let a = (next() % a_lim) as i64 * if r & 4 == 0 { 1 } else { -1 };
            assert_eq!(
                i128::from(mul_i64_i32(a, b)),
                i128::from(a) * i128::from(b),
                "{a} * {b}"
            );
        }
        for (a, b) in [
            (0i64, i32::MIN),
            (-1, i32::MIN),
            (1 << 31, i32::MIN + 1),
            (i64::MAX, 1),
            (i64::MIN + 1, -1),
            ((1 << 32) - 1, i32::MAX),
        ] {
            assert_eq!(i128::from(mul_i64_i32(a, b)), i128::from(a) * i128::from(b));
        }
    }

    #[test]
    fn wide_products_are_exact() {
        for a in [0u32, 1, 3, 0xffff, 0x1_0000, 0x1234_5678, u32::MAX] {
            for b in [0u32, 1, 7, 0xffff, 0xfffe_0001, u32::MAX] {
                assert_eq!(mul_wide(a, b), u64::from(a) * u64::from(b));
            }
        }
        for a in [0i32, -1, 5, -77_777, i32::MAX, i32::MIN + 1] {
            for b in [0i32, 1, -3, 1 << 22, -(1 << 21)] {
                assert_eq!(imul_wide(a, b), i64::from(a) * i64::from(b));
            }
        }
    }

    #[test]
    fn floors_like_div_euclid_and_never_panics() {
        assert_eq!((div_floor(-7, 2), rem_floor(-7, 2)), (-4, 1));
        assert_eq!((div_floor(7, 2), rem_floor(7, 2)), (3, 1));
        assert_eq!(
            (div_ceil(7, 2), div_ceil(-7, 2), div_ceil(8, 2)),
            (4, -3, 4)
        );
        assert_eq!((div_floor(5, 0), rem_floor(5, 0)), (0, 0));
        assert_eq!(div_floor(i64::MIN, -1), 0);
        assert_eq!(limit(5, 7, 3), 7);
    }

    #[test]
    fn wide_square_roots_are_floors_on_both_paths() {
        let mut rng = crate::path::testing::Lcg(0x0c0d_5e1f_2a9b_77e1);
        let check = |n: u64| {
            let s = isqrt_u64(n);
            let (sq, next) = (
                u128::from(s) * u128::from(s),
                u128::from(s + 1) * u128::from(s + 1),
            );
            assert!(sq <= u128::from(n) && next > u128::from(n), "{n}: {s}");
        };
        for n in [
            0,
            1,
            2,
            3,
            4,
            (1 << 50) - 1,
            1 << 50,
            (1 << 50) + 1,
            u64::MAX,
        ] {
            check(n);
        }
        for _ in 0..100_000 {
            let n = rng.below(u64::MAX) >> rng.below(64);
            check(n);
            let r = n >> 32;
            check(r * r);
            check((r * r).saturating_sub(1));
        }
    }

    #[test]
    fn square_roots_are_floors() {
        let mut rng = crate::path::testing::Lcg(0x51_7a7e);
        for k in 0..20_000u64 {
            let n = if k < 2000 {
                k
            } else {
                rng.below(1 << 50) >> rng.below(50)
            };
            let s = u64::from(isqrt64(n));
            assert!(s * s <= n && (s + 1) * (s + 1) > n, "{n}: {s}");
            if n < 1 << 32 {
                assert_eq!(isqrt32(n as u32), s as u32);
            }
        }
        let top = (1u64 << 50) - 1;
        let s = u64::from(isqrt64(top));
        assert!(s * s <= top && (s + 1) * (s + 1) > top);
    }

    #[test]
    fn square_roots_are_floors_at_every_square() {
        for k in 0..=u32::from(u16::MAX) {
            let sq = k * k;
            assert_eq!(isqrt32(sq), k, "{sq}");
            if sq > 0 {
                assert_eq!(isqrt32(sq - 1), k - 1, "{}", sq - 1);
            }
            // The largest n with floor(sqrt(n)) = k: k^2 + 2k.
            assert_eq!(isqrt32(sq.saturating_add(2 * k)), k, "{}", sq + 2 * k);
        }
        assert_eq!(isqrt32(u32::MAX), 65535);
    }
}
