//! Flattening quadratic and cubic Bézier curves into straight segments,
//! with a proved error bound that includes the rounding to the fine grid.
//!
//! Takes a curve's control points (fine units, from `i32` coordinates) and
//! a tolerance `tol` in fine units; gives the number `n` of segments and
//! the `n + 1` vertices `B(k/n)`, each the exact curve point rounded to the
//! nearest grid point.
//!
//! ## The bound
//!
//! Cut the parameter range into `n` equal steps `h = 1/n` and join the
//! curve points by chords. On one step the chord is the linear
//! interpolant of `B`, and for a vector-valued `B` with continuous second
//! derivative the interpolation error is
//! `|B(t) - chord(t)| <= (t - t0)(t1 - t) / 2 * max |B''| <= h^2 / 8 * max |B''|`
//! (the error is an integral of `B''` against a non-negative kernel of
//! mass `(t - t0)(t1 - t) / 2`). So every point of the curve is within that
//! distance of the polygon and every point of the polygon within it of the
//! curve (the same parameter). With the second differences of the control
//! polygon, `D_i = P_i - 2 P_{i+1} + P_{i+2}` and `M = max |D_i|`:
//!
//! - quadratic: `B'' = 2 D_0`, so the distance is at most `M / (4 n^2)`;
//!   `n = ceil(sqrt(M / (4 tol)))`;
//! - cubic: `B''(t) = 6 ((1 - t) D_0 + t D_1)`, `|B''| <= 6 M`, distance at
//!   most `3 M / (4 n^2)`; `n = ceil(sqrt(3 M / (4 tol)))`
//!
//! (the classic bound, Wang's formula). Each vertex is the exact rational
//! `B(k/n)` rounded to the grid, at most `sqrt(2)/2` fine units away, and a
//! chord between rounded vertices is within that of the chord between the
//! exact ones (convex combination). **The emitted polygon is therefore
//! within `tol + 0.71` fine units of the curve** (Hausdorff distance), as
//! long as `n` is not capped.
//!
//! `n` is capped at [`MAX_CURVE_SEGMENTS`] = 1024. The bound holds
//! uncapped for `M <= 4/3 tol 1024^2` on cubics (at the default `tol` of 3
//! fine units: `M <= 4096` px, e.g. every cubic whose control points lie
//! in a 1448-px square) and `M <= 4 tol 1024^2` on quadratics; beyond, the
//! distance is at most `3 M / (4 * 1024^2)` (cubic), and the work stays
//! bounded. A curve whose control points coincide has `M = 0` and one
//! segment (which vanishes if its ends coincide).
//!
//! ## Integer ranges
//!
//! Control points are `i32`, so every difference `P_i - P_0` is below
//! `2^32`. A vertex is `P_0 + (sum_i c_i (P_i - P_0)) / n^3` with the
//! Bernstein numerators `c_i <= n^3 <= 2^30` summing to at most `n^3`: the
//! sum stays below `2^62` in `i64`. `M^2 < 2^68` is formed in `i128`.

use super::trig::{ceil_sqrt_u64, radians_q31};
use super::vector::{div_round_i64, Pt};

/// The most segments one curve is cut into.
pub const MAX_CURVE_SEGMENTS: u32 = 1024;

/// `ceil(sqrt(v))` for a `u128` square of a length: in 64 bits when it
/// fits (every curve of the coordinate range, and glyphs; a 128-bit root
/// is a long library loop on a Cortex-M0), the same value either way.
fn ceil_len(v: u128) -> u64 {
    if let Ok(v) = u64::try_from(v) {
        return ceil_sqrt_u64(v);
    }
    let r = v.isqrt();
    let r = if r * r < v { r + 1 } else { r };
    r.min(u128::from(u64::MAX)) as u64
}

/// `|d|^2` of a second difference: `i64` squares while the components
/// are below `2^31` (the sum below `2^63`), else `i128`.
fn norm2(d: Pt) -> u128 {
    match (i32::try_from(d.x), i32::try_from(d.y)) {
        (Ok(x), Ok(y)) => {
            let (x, y) = (i64::from(x), i64::from(y));
            (x * x + y * y) as u128
        }
        _ => d.dot(d).unsigned_abs(),
    }
}

/// `n = ceil(sqrt(num * M / (den * tol)))` limited to `1..=MAX`
/// (`num, den <= 4`; in 64 bits for `M < 2^61`, the same value).
fn count_from(m: u64, num: u64, den: u64, tol: i64) -> u32 {
    let tol = tol.max(1) as u64;
    let cap = u64::from(MAX_CURVE_SEGMENTS) * u64::from(MAX_CURVE_SEGMENTS);
    let q = if m < 1 << 61 {
        (m * num).div_ceil(den * tol).min(cap)
    } else {
        let q = (u128::from(m) * u128::from(num)).div_ceil(u128::from(den) * u128::from(tol));
        q.min(u128::from(cap)) as u64
    };
    (ceil_sqrt_u64(q) as u32).clamp(1, MAX_CURVE_SEGMENTS)
}

/// The largest `|P_i - P_0|` component for which a curve's vertex sums
/// fit `i32` with up to [`SMALL_N`] segments: Bernstein numerators add up
/// to at most `n^3 = 2^15` (cubic; `n^2` quadratic), so the sum of their
/// products stays below `2^15 2^15 = 2^30`.
const SMALL_D: i64 = 1 << 15;
/// Segment counts for the 32-bit vertex evaluation.
const SMALL_N: i64 = 32;

/// `n / d` rounded, halves away from zero, in 32 bits (`d > 0`): the
/// value of [`div_round_i64`]. `d` is taken as at least 1, which its
/// callers' `n^2`, `n^3` with `n >= 1` are: the optimizer could not always
/// see it, and kept a division-by-zero panic (the Cortex-M0 no-panic
/// build found it once the stroker's segment count changed).
#[inline]
fn div_round_i32(n: i32, d: i32) -> i32 {
    let d = d.max(1);
    if n >= 0 {
        (n + d / 2) / d
    } else {
        -((d / 2 - n) / d)
    }
}

/// True when every component of `ds` is below [`SMALL_D`].
fn small(ds: &[Pt]) -> bool {
    ds.iter()
        .all(|d| d.x.abs() < SMALL_D && d.y.abs() < SMALL_D)
}

/// Segments for a quadratic within `tol` fine units (before rounding).
pub(crate) fn quad_count(p: &[Pt; 3], tol: i64) -> u32 {
    let d = p[0].sub(p[1]).sub(p[1]).add(p[2]);
    count_from(ceil_len(norm2(d)), 1, 4, tol)
}

/// Segments for a cubic within `tol` fine units (before rounding).
pub(crate) fn cubic_count(p: &[Pt; 4], tol: i64) -> u32 {
    let d0 = p[0].sub(p[1]).sub(p[1]).add(p[2]);
    let d1 = p[1].sub(p[2]).sub(p[2]).add(p[3]);
    let m = ceil_len(norm2(d0).max(norm2(d1)));
    count_from(m, 3, 4, tol)
}

/// `B(k/n)` of a quadratic, rounded to the grid (`k <= n <= 1024`).
pub(crate) fn quad_at(p: &[Pt; 3], k: u32, n: u32) -> Pt {
    let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
    let j = n - k;
    let d1 = p[1].sub(p[0]);
    let d2 = p[2].sub(p[0]);
    let den = n * n;
    if n <= SMALL_N && small(&[d1, d2]) {
        // 2 j k + k^2 <= n^2 <= 2^10: the sums stay below 2^25.
        let (a, b, den) = ((2 * j * k) as i32, (k * k) as i32, den as i32);
        let x = a * d1.x as i32 + b * d2.x as i32;
        let y = a * d1.y as i32 + b * d2.y as i32;
        return Pt::new(
            p[0].x + i64::from(div_round_i32(x, den)),
            p[0].y + i64::from(div_round_i32(y, den)),
        );
    }
    let x = 2 * j * k * d1.x + k * k * d2.x;
    let y = 2 * j * k * d1.y + k * k * d2.y;
    Pt::new(
        p[0].x + div_round_i64(x, den),
        p[0].y + div_round_i64(y, den),
    )
}

/// `B(k/n)` of a cubic, rounded to the grid (`k <= n <= 1024`).
pub(crate) fn cubic_at(p: &[Pt; 4], k: u32, n: u32) -> Pt {
    let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
    let j = n - k;
    let (d1, d2, d3) = (p[1].sub(p[0]), p[2].sub(p[0]), p[3].sub(p[0]));
    let (c1, c2, c3) = (3 * j * j * k, 3 * j * k * k, k * k * k);
    let den = n * n * n;
    if n <= SMALL_N && small(&[d1, d2, d3]) {
        // c1 + c2 + c3 <= n^3 <= 2^15: the sums stay below 2^30.
        let (c1, c2, c3, den) = (c1 as i32, c2 as i32, c3 as i32, den as i32);
        let x = c1 * d1.x as i32 + c2 * d2.x as i32 + c3 * d3.x as i32;
        let y = c1 * d1.y as i32 + c2 * d2.y as i32 + c3 * d3.y as i32;
        return Pt::new(
            p[0].x + i64::from(div_round_i32(x, den)),
            p[0].y + i64::from(div_round_i32(y, den)),
        );
    }
    let x = c1 * d1.x + c2 * d2.x + c3 * d3.x;
    let y = c1 * d1.y + c2 * d2.y + c3 * d3.y;
    Pt::new(
        p[0].x + div_round_i64(x, den),
        p[0].y + div_round_i64(y, den),
    )
}

/// A vector along `B'(k/n)` of a quadratic (scaled by `n / 2`); at the
/// ends a degenerate derivative falls back to the chord `P2 - P0`. Zero
/// only where the curve has no direction.
pub(crate) fn quad_tangent(p: &[Pt; 3], k: u32, n: u32) -> Pt {
    let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
    let (e1, e2) = (p[1].sub(p[0]), p[2].sub(p[1]));
    let v = Pt::new((n - k) * e1.x + k * e2.x, (n - k) * e1.y + k * e2.y);
    if v.is_zero() && (k == 0 || k == n) {
        p[2].sub(p[0])
    } else {
        v
    }
}

/// A vector along `B'(k/n)` of a cubic (scaled by `n^2 / 3`); at the ends
/// a degenerate derivative falls back to the next control point that
/// differs. Zero only at an exact cusp.
pub(crate) fn cubic_tangent(p: &[Pt; 4], k: u32, n: u32) -> Pt {
    let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
    let j = n - k;
    let (e1, e2, e3) = (p[1].sub(p[0]), p[2].sub(p[1]), p[3].sub(p[2]));
    let (c1, c2, c3) = (j * j, 2 * j * k, k * k);
    let v = Pt::new(
        c1 * e1.x + c2 * e2.x + c3 * e3.x,
        c1 * e1.y + c2 * e2.y + c3 * e3.y,
    );
    if !v.is_zero() {
        return v;
    }
    if k == 0 {
        for q in [p[2], p[3]] {
            if q != p[0] {
                return q.sub(p[0]);
            }
        }
    } else if k == n {
        for q in [p[1], p[0]] {
            if q != p[3] {
                return p[3].sub(q);
            }
        }
    }
    v
}

/// The segments of a curve's stroke ([`offset_count`]'s second count):
/// `ceil(T sqrt(h / (8 tol)))` for a total turning `T` (binary units) of
/// the tangent and an offset of half-width `h`.
pub(crate) fn turn_count(turn: u64, h: i64, tol: i64) -> u32 {
    if turn == 0 || h <= 0 {
        return 0;
    }
    let t = radians_q31(turn.min(1 << 33) as i64 / 2).unsigned_abs() * 2; // rad in Q31
    let t2 = u128::from(t) * u128::from(t); // Q62
    let q = (t2 * h as u128).div_ceil(8 * tol.max(1) as u128) >> 62;
    let q = q.min(u128::from(MAX_CURVE_SEGMENTS) * u128::from(MAX_CURVE_SEGMENTS)) as u64;
    ceil_sqrt_u64(q + 1).min(u64::from(MAX_CURVE_SEGMENTS)) as u32
}

/// Segments so that a stroke's offset edges stay within `tol` of the
/// offset curve: `ceil(sqrt(n_c^2 + n_t^2))` of the curve's own count
/// `n_c` ([`cubic_count`], [`quad_count`]) and the turning count `n_t`
/// ([`turn_count`]). An offset edge joins the offset points at two
/// vertices, `B + h N` with `N` the unit normal; the chord of a sum is the
/// sum of the chords, so the offset curve strays from it by at most the
/// curve's own chord error plus `h` times the normal's, `h a^2 / 8` for a
/// step that turns by `a`. Both fall as `1 / n^2`: the curve's is within
/// `tol n_c^2 / n^2` and the normal's within `tol n_t^2 / n^2` (turning
/// spread over the steps, as `turn_count` takes it), so `n^2 >= n_c^2 +
/// n_t^2` keeps their sum within `tol`. (For a circular arc of radius
/// `r` this is the exact condition `(r + h) a^2 / 8 <= tol`; the sum
/// `n_c + n_t` used before asked for up to `sqrt 2` times as many.)
pub(crate) fn offset_count(curve: u32, turn: u32) -> u32 {
    let q = u64::from(curve) * u64::from(curve) + u64::from(turn) * u64::from(turn);
    (ceil_sqrt_u64(q) as u32).clamp(1, MAX_CURVE_SEGMENTS)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::path::testing::Lcg;

    fn pts<const N: usize>(c: [(i64, i64); N]) -> [Pt; N] {
        c.map(|(x, y)| Pt::new(x, y))
    }

    /// The evaluations and counts as first written, in 64 and 128 bits.
    fn quad_at_wide(p: &[Pt; 3], k: u32, n: u32) -> Pt {
        let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
        let (d1, d2) = (p[1].sub(p[0]), p[2].sub(p[0]));
        let j = n - k;
        let x = 2 * j * k * d1.x + k * k * d2.x;
        let y = 2 * j * k * d1.y + k * k * d2.y;
        Pt::new(
            p[0].x + div_round_i64(x, n * n),
            p[0].y + div_round_i64(y, n * n),
        )
    }

    fn cubic_at_wide(p: &[Pt; 4], k: u32, n: u32) -> Pt {
        let (k, n) = (i64::from(k.min(n)), i64::from(n.max(1)));
        let j = n - k;
        let (d1, d2, d3) = (p[1].sub(p[0]), p[2].sub(p[0]), p[3].sub(p[0]));
        let (c1, c2, c3) = (3 * j * j * k, 3 * j * k * k, k * k * k);
        let x = c1 * d1.x + c2 * d2.x + c3 * d3.x;
        let y = c1 * d1.y + c2 * d2.y + c3 * d3.y;
        let den = n * n * n;
        Pt::new(
            p[0].x + div_round_i64(x, den),
            p[0].y + div_round_i64(y, den),
        )
    }

    fn count_wide(m2: u128, num: u64, den: u64, tol: i64) -> u32 {
        let r = m2.isqrt();
        let m = if r * r < m2 { r + 1 } else { r };
        let q = (m * u128::from(num)).div_ceil(u128::from(den) * tol.max(1) as u128);
        let q = q.min(1 << 20) as u64;
        (ceil_sqrt_u64(q) as u32).clamp(1, MAX_CURVE_SEGMENTS)
    }

    #[test]
    fn the_short_forms_give_the_wide_forms_bits() {
        let mut rng = Lcg(0x9a3f_0c11_77d2_5e01);
        let mut next = |m: u64| (rng.next_u64() >> 20) % m;
        for case in 0..20_000 {
            // Spans around the 32-bit forms' limits, and the whole range.
            let span = [1 << 10, (1 << 15) - 1, 1 << 15, 1 << 16, 1 << 32][case % 5];
            let mut p = [Pt::default(); 4];
            for q in p.iter_mut() {
                let c = |v: u64| v as i64 - (span as i64) / 2 - 7;
                *q = Pt::new(c(next(span)), c(next(span)));
            }
            let n = 1 + next(40) as u32;
            let k = next(u64::from(n) + 1) as u32;
            let q3 = [p[0], p[1], p[2]];
            assert_eq!(quad_at(&q3, k, n), quad_at_wide(&q3, k, n), "{p:?} {k}/{n}");
            assert_eq!(cubic_at(&p, k, n), cubic_at_wide(&p, k, n), "{p:?} {k}/{n}");
            let tol = 1 + next(300) as i64;
            let d = p[0].sub(p[1]).sub(p[1]).add(p[2]);
            assert_eq!(
                quad_count(&q3, tol),
                count_wide(d.dot(d) as u128, 1, 4, tol)
            );
        }
    }

    #[test]
    fn coincident_control_points_give_one_segment() {
        assert_eq!(cubic_count(&pts([(5, 5); 4]), 3), 1);
        assert_eq!(quad_count(&pts([(5, 5), (9, 9), (13, 13)]), 3), 1);
    }

    #[test]
    fn endpoints_are_exact_and_counts_follow_the_formula() {
        let c = pts([(0, 0), (0, 10240), (10240, 10240), (10240, 0)]);
        let n = cubic_count(&c, 3);
        // M = |(0,-10240)*... |: D0 = P0 - 2P1 + P2 = (10240, -10240).
        let m = (10240f64 * 2f64.sqrt()).ceil();
        assert_eq!(n, (3.0 * m / 12.0).sqrt().ceil() as u32);
        assert_eq!(cubic_at(&c, 0, n), c[0]);
        assert_eq!(cubic_at(&c, n, n), c[3]);
        assert_eq!(cubic_at(&c, 1, 2), Pt::new(5120, 7680));
    }

    #[test]
    fn huge_curves_are_capped() {
        let m = i64::from(i32::MAX);
        let c = pts([(-m, -m), (m, -m), (-m, m), (m, m)]);
        assert_eq!(cubic_count(&c, 1), MAX_CURVE_SEGMENTS);
        let v = cubic_at(&c, 512, 1024);
        assert!(v.x.abs() <= m && v.y.abs() <= m);
    }

    #[test]
    fn tangents_fall_back_at_degenerate_ends() {
        let c = pts([(0, 0), (0, 0), (10, 0), (10, 10)]);
        assert_eq!(cubic_tangent(&c, 0, 4), Pt::new(10, 0));
        let c = pts([(0, 0), (5, 5), (10, 10), (10, 10)]);
        assert_eq!(cubic_tangent(&c, 4, 4), Pt::new(5, 5));
        let q = pts([(0, 0), (0, 0), (8, 0)]);
        assert_eq!(quad_tangent(&q, 0, 3), Pt::new(8, 0));
    }

    #[test]
    fn turning_adds_segments_for_wide_strokes() {
        assert_eq!(turn_count(0, 1000, 3), 0);
        // A quarter turn, h = 10 px: (pi/2) sqrt(10240 / 24) = 32.4.
        let n = turn_count(1 << 30, 10240, 3);
        assert!((33..=34).contains(&n), "{n}");
    }
}
