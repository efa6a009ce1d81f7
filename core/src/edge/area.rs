//! Setup: exact area under the canonical line, for the end columns of an
//! edge. Runs a few times per edge (one i64 division; no per-pixel use).

use super::canon::Canon;
use crate::arith::{div_floor, limit};

/// `floor(16 * ∫_{ulo}^{uhi} clamp(v̄(u) - vlo, 0, vhi - vlo) du)`, where
/// `v̄` is the edge's line clamped flat beyond its end points, all in
/// sub-pixels: the area in 1/4096 px (256 sub-pixels² = 4096 units).
pub(crate) fn clamped_area(e: &Canon, ulo: i64, uhi: i64, vlo: i64, vhi: i64) -> i32 {
    let h = vhi - vlo;
    if uhi <= ulo || h <= 0 {
        return 0;
    }
    let flat = |len: i64, v: i64| len.max(0) * limit(v - vlo, 0, h);
    // The two flat extensions beyond the end points, in sub-pixels².
    let mut whole = flat(uhi.min(e.u0) - ulo, e.v0) + flat(uhi - ulo.max(e.u1), e.v1);
    let (p, q) = (ulo.max(e.u0), uhi.min(e.u1));
    let mut part = 0i64;
    let den = 2 * e.du * e.dv;
    if p < q {
        if e.dv == 0 {
            whole += flat(q - p, e.v0);
        } else {
            // Relative to (p, vlo): v'(x) = (a + x) / du with x = (u - p) dv,
            // so every term below is bounded by the cell, not by the
            // coordinates: |x| <= 16 dv, |a + x| <= 16 du where it matters,
            // and each product stays under 2^42.
            let (du, dv) = (e.du, e.dv);
            let a = e.v0 * du + (p - e.u0) * dv - vlo * du;
            let x_end = (q - p) * dv;
            // Where the line meets vlo (x = -a) and vhi (x = h du - a),
            // clamped into the piece.
            let xa = limit(-a, 0, x_end);
            let xb = limit(h * du - a, 0, x_end);
            // ∫ v' over [xa, xb] and the full height right of xb.
            part = (xb - xa) * (2 * a + xa + xb) + (x_end - xb) * h * 2 * du;
        }
    }
    // In 1/4096 px: 16 per sub-pixel². `part` is over `den`.
    let scaled = 16 * whole
        + if den > 0 {
            div_floor(16 * part, den)
        } else {
            0
        };
    scaled.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::SubPoint;

    #[test]
    fn unit_square_under_a_45_degree_line() {
        // Line from (0,0) to (32,32) sub-pixels: in pixel (0,0) the area
        // below the line (low v = above on screen) is half the pixel.
        let e = Canon::new(SubPoint::new(0, 0), SubPoint::new(32, 32)).unwrap();
        assert_eq!(clamped_area(&e, 0, 16, 0, 16), 2048);
        // Pixel (1, 0): the line is below row 0 everywhere: full.
        assert_eq!(clamped_area(&e, 16, 32, 0, 16), 4096);
        // Pixel (0, 1): nothing.
        assert_eq!(clamped_area(&e, 0, 16, 16, 32), 0);
    }

    #[test]
    fn beyond_the_end_points_the_line_is_flat() {
        let e = Canon::new(SubPoint::new(0, 0), SubPoint::new(16, 8)).unwrap();
        // Column [16, 32] lies past the end: v = 8 flat, row [0, 16): 8/16.
        assert_eq!(clamped_area(&e, 16, 32, 0, 16), 2048);
    }
}
