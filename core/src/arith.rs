//! Integer division without panic paths.
//!
//! Every divisor in the setup code is positive by construction (an edge's
//! extent, a triangle's doubled area, one pixel in sub-pixels), but the
//! compiler cannot see that, and a firmware build that forbids panics must
//! link. These helpers floor like `div_euclid` for positive divisors and
//! give 0 for a zero divisor (or the one overflowing quotient), which no
//! caller produces.

/// `floor(n / d)` for `d > 0`; 0 if `d == 0`.
#[inline]
pub(crate) fn div_floor(n: i64, d: i64) -> i64 {
    n.checked_div_euclid(d).unwrap_or(0)
}

/// `n - d * floor(n / d)` (in `0..d`) for `d > 0`; 0 if `d == 0`.
#[inline]
pub(crate) fn rem_floor(n: i64, d: i64) -> i64 {
    n.checked_rem_euclid(d).unwrap_or(0)
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

#[cfg(test)]
mod tests {
    use super::*;

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
}
