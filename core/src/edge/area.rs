//! Set-up: the exact area under the canonical line in one cell, for the end
//! columns of an edge. A few times per edge; divides in `u64`/`i64`.

use super::canon::Canon;
use crate::arith::{div_floor, divmod_floor, imul_wide, mul_i64_i32, mul_small, mul_wide, udivmod};
use crate::geom::FINE_BITS;
use crate::COVER_BITS;

/// Fine units² per coverage unit: `N² / COVER_ONE`.
const FINE2_PER_AREA: i64 = 1 << (2 * FINE_BITS - COVER_BITS);

/// Largest `du dv` for which [`clamped_area`] forms the area's exact
/// numerator in one `i64` (every term below `2^61`, see there).
const ONE_DIVISION_LIMIT: u64 = 1 << 38;

/// `floor(∫_{ulo}^{uhi} clamp(v̄(u) - vlo, 0, vhi - vlo) du)` in coverage
/// units, where `v̄` is the edge's line clamped flat beyond its end points
/// and every coordinate is in fine units (`uhi - ulo <= N`, `vhi - vlo <= N`).
///
/// The line part is the trapezoid `∫ (v - vlo)` with the triangle below
/// `vlo` added back and the one above `vhi` taken away; with `g = (v - vlo)
/// du` (an integer at grid points) the triangles are `g² / (2 du dv)`, and
/// where they exist `|g| < (uhi - ulo) dv <= 2^32`, so their squares fit
/// `u64`. Over the common denominator `2 du dv` the whole area's numerator
/// is `T = 2 du dv flat + (q - p)(gp + gq) dv ± g²`, whose terms are below
/// `2^21 du dv`, `2^22 du dv` and `2^20 du dv`: for `du dv <= 2^38` it is
/// one `i64` and the area one division, `floor(T / (32 du dv))` (the two
/// floors, to fine units² and to coverage units, are one). Longer edges
/// divide the pieces separately.
pub(crate) fn clamped_area(e: &Canon, ulo: i64, uhi: i64, vlo: i64, vhi: i64) -> i32 {
    let h = vhi - vlo;
    if uhi <= ulo || h <= 0 {
        return 0;
    }
    let (u0, v0, u1, v1) = (
        i64::from(e.u0),
        i64::from(e.v0),
        i64::from(e.u1),
        i64::from(e.v1),
    );
    let (du, dv) = (i64::from(e.du), i64::from(e.dv));
    // The products below are in 32 bits, or 32 x 32 -> 64, where the
    // ranges allow (each stated; the Cortex-M0 has no 64-bit multiply):
    // coordinates are within `±2^22`, `du, dv <= 2^22`, and a cell is at
    // most `N = 2^10` wide and high. A flat part: at most `N` by `h`.
    let flat = |len: i64, v: i64| mul_small(len.max(0), (v - vlo).min(h).max(0));
    // The two flat extensions beyond the end points, in fine units²
    // (below `2^21`).
    let mut whole = flat(uhi.min(u0) - ulo, v0) + flat(uhi - ulo.max(u1), v1);
    let (p, q) = (ulo.max(u0), uhi.min(u1));
    let dudv = mul_wide(e.du as u32, e.dv as u32);
    let one_division = dudv <= ONE_DIVISION_LIMIT;
    // The line part as `whole + frac / (2 du dv)`, `frac` in (-2^47, 2^47).
    let mut frac = 0i64;
    if p < q {
        // `v0 - vlo` and `p - u0` within `±2^23`, `q - p <= N`, `h <= N`.
        let gp = imul_wide((v0 - vlo) as i32, e.du) + imul_wide((p - u0) as i32, e.dv);
        let gq = gp + imul_wide((q - p) as i32, e.dv);
        let hd = imul_wide(h as i32, e.du);
        if dv == 0 {
            whole += flat(q - p, v0);
        } else if gq <= 0 {
            // Wholly at or below vlo: nothing.
        } else if gp >= hd {
            // Wholly at or above vhi: the full height.
            whole += mul_small(h, q - p);
        } else if one_division {
            // `den <= 2^39`, `whole < 2^21`: below `2^60`. `gp + gq` is
            // below `2^35` in magnitude, times `q - p` below `2^45`, times
            // `dv` the term bound above. Squares: `|g| < (q - p) dv <=
            // 2^32` where they are taken (`gp < 0 < gq`, `gp < hd < gq`).
            let den = 2 * dudv as i64;
            let mut t = mul_i64_i32(den, whole as i32)
                + mul_i64_i32(mul_i64_i32(gp + gq, (q - p) as i32), e.dv);
            let square = |g: i64| mul_wide(g.unsigned_abs() as u32, g.unsigned_abs() as u32) as i64;
            if gp < 0 {
                t += square(gp);
            }
            if gq > hd {
                t -= square(gq - hd);
            }
            let (area, _) = udivmod(t.max(0) as u64, (den * FINE2_PER_AREA) as u64);
            return area as i32;
        } else {
            // Trapezoid (q - p)(gp + gq) / (2 du): whole part and remainder.
            let n = (q - p) * (gp + gq);
            let (nq, nr) = divmod_floor(n, 2 * du);
            whole += nq;
            frac += nr * dv;
            let den = (2 * du * dv) as u64;
            let tri = |g: i64| {
                let g2 = (g.unsigned_abs()) * (g.unsigned_abs());
                let (q, r) = udivmod(g2, den);
                (q as i64, r as i64)
            };
            if gp < 0 {
                let (tq, tr) = tri(gp);
                whole += tq;
                frac += tr;
            }
            if gq > hd {
                let (tq, tr) = tri(gq - hd);
                whole -= tq;
                frac -= tr;
            }
            whole += div_floor(frac, 2 * du * dv);
        }
    }
    let area = whole >> (2 * FINE_BITS - COVER_BITS);
    area.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::FinePoint;

    const N: i32 = crate::geom::FINE_ONE;
    const FULL: i32 = crate::COVER_ONE;

    #[test]
    fn unit_square_under_a_45_degree_line() {
        // Line from (0,0) to (2,2) px: in pixel (0,0) the area below the
        // line (low v = above on screen) is half the pixel.
        let e = Canon::new(FinePoint::new(0, 0), FinePoint::new(2 * N, 2 * N)).unwrap();
        let n = i64::from(N);
        assert_eq!(clamped_area(&e, 0, n, 0, n), FULL / 2);
        assert_eq!(clamped_area(&e, n, 2 * n, 0, n), FULL);
        assert_eq!(clamped_area(&e, 0, n, n, 2 * n), 0);
    }

    #[test]
    fn beyond_the_end_points_the_line_is_flat() {
        let e = Canon::new(FinePoint::new(0, 0), FinePoint::new(N, N / 2)).unwrap();
        let n = i64::from(N);
        // Column [1, 2) px lies past the end: v = 1/2 px flat, half the row.
        assert_eq!(clamped_area(&e, n, 2 * n, 0, n), FULL / 2);
        // Inside: the triangle under the line, 1/4 px.
        assert_eq!(clamped_area(&e, 0, n, 0, n), FULL / 4);
    }

    #[test]
    fn a_steep_line_clipped_by_both_row_limits() {
        // v = u / 2 + 100 across one column, clamped to [300, 500) fine.
        let e = Canon::new(FinePoint::new(0, 100), FinePoint::new(N, 100 + N / 2)).unwrap();
        let n = i64::from(N);
        let exact = |vlo: f64, vhi: f64| -> f64 {
            let steps = 1 << 16;
            let mut s = 0.0;
            for k in 0..steps {
                let u = (k as f64 + 0.5) / steps as f64 * n as f64;
                let v = 100.0 + u / 2.0;
                s += (v - vlo).clamp(0.0, vhi - vlo);
            }
            s * n as f64 / steps as f64 / 16.0
        };
        let got = clamped_area(&e, 0, n, 300, 500);
        assert!((f64::from(got) - exact(300.0, 500.0)).abs() <= 1.0, "{got}");
    }

    #[test]
    fn one_division_equals_the_pieces() {
        // The same cells through both paths: the single numerator and the
        // separately divided pieces give the same floor.
        let f = FinePoint::new;
        for (p0, p1) in [
            (f(3, 7), f(5_000, 1_234)),
            (f(-1_000, 10), f(-20, 777)),
            (f(0, 0), f(1_025, 1_023)),
            (f(100, 511), f(99_999, 511 + 99_000)),
        ] {
            let e = Canon::new(p0, p1).unwrap();
            let n = i64::from(N);
            for a in [e.u0 / N - 1, e.u0 / N, e.u1 / N, e.u1 / N + 1] {
                for b in [e.v0 / N - 1, e.v0 / N, e.v0 / N + 1, e.v1 / N, e.v1 / N + 1] {
                    let (ulo, uhi) = (i64::from(a) * n, i64::from(a) * n + n);
                    let (vlo, vhi) = (i64::from(b) * n, i64::from(b) * n + n);
                    let fast = clamped_area(&e, ulo, uhi, vlo, vhi);
                    let slow = pieces(&e, ulo, uhi, vlo, vhi);
                    assert_eq!(fast, slow, "{p0:?} {p1:?} cell ({a}, {b})");
                }
            }
        }
    }

    /// The area by the separately divided pieces (the long-edge path).
    fn pieces(e: &Canon, ulo: i64, uhi: i64, vlo: i64, vhi: i64) -> i32 {
        // Scale the edge up so it takes the long path, then compare at the
        // same scale: instead, recompute directly in i128.
        let (u0, v0, u1, v1) = (
            i128::from(e.u0),
            i128::from(e.v0),
            i128::from(e.u1),
            i128::from(e.v1),
        );
        let (du, dv) = (i128::from(e.du), i128::from(e.dv));
        let (ulo, uhi, vlo, vhi) = (
            i128::from(ulo),
            i128::from(uhi),
            i128::from(vlo),
            i128::from(vhi),
        );
        // Exact area times 2 du dv by exact integration over 1/(2 du dv)
        // steps is too slow; use the closed form in i128.
        let h = vhi - vlo;
        let flat = |len: i128, v: i128| len.max(0) * (v - vlo).clamp(0, h);
        let mut t = (flat(uhi.min(u0) - ulo, v0) + flat(uhi - ulo.max(u1), v1)) * 2 * du * dv;
        let (p, q) = (ulo.max(u0), uhi.min(u1));
        if p < q {
            let gp = (v0 - vlo) * du + (p - u0) * dv;
            let gq = gp + (q - p) * dv;
            let hd = h * du;
            if gq <= 0 {
            } else if gp >= hd {
                t += h * (q - p) * 2 * du * dv;
            } else {
                t += (q - p) * (gp + gq) * dv;
                if gp < 0 {
                    t += gp * gp;
                }
                if gq > hd {
                    t -= (gq - hd) * (gq - hd);
                }
            }
        }
        t.div_euclid(32 * du * dv) as i32
    }
}
