//! Setup: exact area under the canonical line, for the end columns of an
//! edge. Runs a few times per edge (i128 arithmetic, no per-pixel use).

use super::canon::Canon;

/// `floor(16 * ∫_{ulo}^{uhi} clamp(v̄(u) - vlo, 0, vhi - vlo) du)`, where
/// `v̄` is the edge's line clamped flat beyond its end points, all in
/// sub-pixels: the area in 1/4096 px (256 sub-pixels² = 4096 units).
pub(crate) fn clamped_area(e: &Canon, ulo: i64, uhi: i64, vlo: i64, vhi: i64) -> i32 {
    let h = vhi - vlo;
    if uhi <= ulo || h <= 0 {
        return 0;
    }
    let (du, dv) = (i128::from(e.du), i128::from(e.dv));
    let flat = |len: i64, v: i64| i128::from(len.max(0)) * i128::from((v - vlo).clamp(0, h));
    // Everything is summed over the common denominator 2 * du * dv (or 1).
    let den: i128 = if e.dv == 0 { 1 } else { 2 * du * dv };
    let mut num: i128 = 0;
    num += den * flat(uhi.min(e.u0) - ulo, e.v0);
    num += den * flat(uhi - ulo.max(e.u1), e.v1);
    let (p, q) = (ulo.max(e.u0), uhi.min(e.u1));
    if p < q {
        if e.dv == 0 {
            num += flat(q - p, e.v0);
        } else {
            let (p, q) = (i128::from(p), i128::from(q));
            let (u0, v0) = (i128::from(e.u0), i128::from(e.v0));
            let (vlo, vhi) = (i128::from(vlo), i128::from(vhi));
            // u where the line meets vlo and vhi, as numerators over dv,
            // clamped into [p, q].
            let clamp = |n: i128| n.clamp(p * dv, q * dv);
            let ua = clamp(u0 * dv + (vlo - v0) * du);
            let ub = clamp(u0 * dv + (vhi - v0) * du);
            // Middle piece: ∫ (v(u) - vlo) du over [ua, ub].
            num += (ub - ua) * (2 * (v0 - vlo) * du + ua + ub - 2 * u0 * dv);
            // Right piece: full height.
            num += (q * dv - ub) * (vhi - vlo) * 2 * du;
        }
    }
    let scaled = (16 * num).div_euclid(den);
    scaled.clamp(i128::from(i32::MIN), i128::from(i32::MAX)) as i32
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
