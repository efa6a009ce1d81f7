//! Set-up: the exact area under the canonical line in one cell, for the end
//! columns of an edge. A few times per edge; divides in `u64`/`i64`.

use super::canon::Canon;
use crate::arith::{div_floor, divmod_floor, limit, udivmod};
use crate::geom::FINE_BITS;
use crate::COVER_BITS;

/// Fine units² per coverage unit: `N² / COVER_ONE`.
const FINE2_PER_AREA: i64 = 1 << (2 * FINE_BITS - COVER_BITS);

/// `floor(∫_{ulo}^{uhi} clamp(v̄(u) - vlo, 0, vhi - vlo) du)` in coverage
/// units, where `v̄` is the edge's line clamped flat beyond its end points
/// and every coordinate is in fine units (`uhi - ulo <= N`, `vhi - vlo <= N`).
///
/// The line part is the trapezoid `∫ (v - vlo)` with the triangle below
/// `vlo` added back and the one above `vhi` taken away; with `g = (v - vlo)
/// du` (an integer at grid points) the triangles are `g² / (2 du dv)`, and
/// where they exist `|g| < (uhi - ulo) dv <= 2^32`, so their squares fit
/// `u64`. The trapezoid's numerator stays below `2^45`.
pub(crate) fn clamped_area(e: &Canon, ulo: i64, uhi: i64, vlo: i64, vhi: i64) -> i32 {
    let h = vhi - vlo;
    if uhi <= ulo || h <= 0 {
        return 0;
    }
    let flat = |len: i64, v: i64| len.max(0) * limit(v - vlo, 0, h);
    // The two flat extensions beyond the end points, in fine units².
    let mut whole = flat(uhi.min(e.u0) - ulo, e.v0) + flat(uhi - ulo.max(e.u1), e.v1);
    let (p, q) = (ulo.max(e.u0), uhi.min(e.u1));
    // The line part as `whole + frac / (2 du dv)`, `frac` in (-2^47, 2^47).
    let mut frac = 0i64;
    if p < q {
        let (du, dv) = (e.du, e.dv);
        let gp = (e.v0 - vlo) * du + (p - e.u0) * dv;
        let gq = gp + (q - p) * dv;
        let hd = h * du;
        if dv == 0 {
            whole += flat(q - p, e.v0);
        } else if gq <= 0 {
            // Wholly at or below vlo: nothing.
        } else if gp >= hd {
            // Wholly at or above vhi: the full height.
            whole += h * (q - p);
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
    let area = div_floor(whole, FINE2_PER_AREA);
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
}
