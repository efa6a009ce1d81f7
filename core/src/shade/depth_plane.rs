//! Setup: the depth plane of a triangle, `z(i, j)` at pixel centres.

use super::{div_round, PlaneFit};
use crate::geom::SubPoint;

/// Fraction bits of the fine depth values the sweep steps.
pub const DEPTH_FRAC: u32 = 16;

// The fit is shared with the Gouraud plane, in its fixed point.
const _: () = assert!(DEPTH_FRAC == crate::shade::PLANE_FRAC);

/// Steepest depth gradient kept, in fine units per pixel: 2^24 depth steps
/// (256 times the whole depth range) per pixel, so `gx * di` stays below
/// `2^53` for any pixel in the coordinate range. A triangle steeper than
/// that is thinner than 1/256 px across its depth range; it gets its mean
/// depth, flat (its pixels are almost all edge pixels of tiny coverage).
const GRAD_LIMIT: i64 = 1 << (24 + DEPTH_FRAC);

/// The depth of a triangle at pixel centres, `z * 2^16`, an exact integer
/// function of the pixel address (the same bits stepped or evaluated, so
/// every band height gives the same depths), clamped to the range of the
/// triangle's own vertex depths when read (a pixel centre outside the
/// triangle never gets a depth nearer or farther than the triangle has).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct DepthPlane {
    /// Reference pixel column.
    pub i0: i32,
    /// Reference pixel row.
    pub j0: i32,
    /// `z * 2^16` at the centre of pixel `(i0, j0)`.
    pub at0: i64,
    /// Change per pixel to the right, `* 2^16`.
    pub gx: i64,
    /// Change per pixel down, `* 2^16`.
    pub gy: i64,
    /// Farthest vertex depth.
    pub lo: u16,
    /// Nearest vertex depth.
    pub hi: u16,
}

impl DepthPlane {
    /// One depth everywhere.
    pub const fn flat(z: u16) -> Self {
        Self {
            i0: 0,
            j0: 0,
            at0: (z as i64) << DEPTH_FRAC,
            gx: 0,
            gy: 0,
            lo: z,
            hi: z,
        }
    }

    /// The plane through three vertices and their depths, or `None` for a
    /// triangle of zero area. Vertices must be inside the coordinate range
    /// ([`SubPoint::check`]); every product then stays below `2^54`.
    pub fn triangle(v: [SubPoint; 3], z: [u16; 3]) -> Option<Self> {
        let fit = PlaneFit::new(v)?;
        let lo = z[0].min(z[1]).min(z[2]);
        let hi = z[0].max(z[1]).max(z[2]);
        let f = z.map(i64::from);
        let (at0, gx, gy) = fit.values(f);
        let (i0, j0) = (fit.i0, fit.j0);
        if gx.abs() > GRAD_LIMIT || gy.abs() > GRAD_LIMIT {
            let one = 1i64 << DEPTH_FRAC;
            let mean = div_round((f[0] + f[1] + f[2]) * one, 3);
            return Some(Self {
                i0,
                j0,
                at0: mean,
                gx: 0,
                gy: 0,
                lo,
                hi,
            });
        }
        Some(Self {
            i0,
            j0,
            at0,
            gx,
            gy,
            lo,
            hi,
        })
    }

    /// `z * 2^16` at the centre of pixel `(i, j)`, unclamped (setup use:
    /// two multiplies).
    pub fn at(&self, i: i32, j: i32) -> i64 {
        let di = i64::from(i) - i64::from(self.i0);
        let dj = i64::from(j) - i64::from(self.j0);
        self.at0 + self.gx * di + self.gy * dj
    }

    /// How much the depth changes across one pixel, `|dz/dx| + |dz/dy|`,
    /// rounded up (setup use).
    pub fn slope(&self) -> u16 {
        let fine = self.gx.unsigned_abs() + self.gy.unsigned_abs();
        let whole = (fine >> DEPTH_FRAC) + 1;
        whole.min(u64::from(u16::MAX)) as u16
    }

    /// A fine value rounded to a depth and clamped to the triangle's range
    /// (per pixel: an add, a shift, two compares).
    #[inline]
    pub fn depth(&self, fine: i64) -> u16 {
        let z = (fine + (1 << (DEPTH_FRAC - 1))) >> DEPTH_FRAC;
        if z < i64::from(self.lo) {
            self.lo
        } else if z > i64::from(self.hi) {
            self.hi
        } else {
            z as u16
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_hits_vertex_depths_at_pixel_centres() {
        let c = |x: i32, y: i32| SubPoint::new(x * 16 + 8, y * 16 + 8);
        let p = DepthPlane::triangle([c(0, 0), c(10, 0), c(0, 10)], [0, 40000, 20000]).unwrap();
        assert_eq!(p.depth(p.at(0, 0)), 0);
        assert_eq!(p.depth(p.at(10, 0)), 40000);
        assert_eq!(p.depth(p.at(0, 10)), 20000);
        assert_eq!(p.depth(p.at(5, 5)), 30000);
        // Outside the triangle the plane goes on, the depth is clamped.
        assert_eq!(p.depth(p.at(20, 0)), 40000);
        assert_eq!(p.depth(p.at(-5, 0)), 0);
    }

    #[test]
    fn stepping_equals_evaluating() {
        let v = [
            SubPoint::new(3, 5),
            SubPoint::new(900, 170),
            SubPoint::new(40, 601),
        ];
        let p = DepthPlane::triangle(v, [65535, 3, 31000]).unwrap();
        let mut z = p.at(-3, 7);
        for i in -3..60 {
            assert_eq!(z, p.at(i, 7));
            z += p.gx;
        }
    }

    #[test]
    fn sliver_is_flat_at_the_mean_depth() {
        // Twice the area is 1 sub-pixel²: 1/512 px² over 1875 px.
        let v = [
            SubPoint::new(0, 0),
            SubPoint::new(30000, 1),
            SubPoint::new(30001, 1),
        ];
        let p = DepthPlane::triangle(v, [0, 0, 65535]).unwrap();
        assert_eq!((p.gx, p.gy), (0, 0));
        assert_eq!(p.depth(p.at(3, 0)), 21845);
        assert!(DepthPlane::triangle([v[0], v[0], v[1]], [1, 2, 3]).is_none());
    }
}
