//! The image's affine transform and its set-up: the inverse map from a
//! pixel centre to the image (exact per pixel, `i64` in Q32 texels), the
//! outline of the transformed image, and the filter it takes.
//!
//! Forward: a point `t` of the image (texels) lands at
//! `position + R(angle) S (t - pivot)` on screen, `S = diag(sx, sy)`, `R`
//! the rotation clockwise on screen (y down: `R = [[c, -s], [s, c]]`).
//! Inverse, for the pixel centre `p`: `t = pivot + S^-1 R^T (p - position)`,
//! whose coefficients `c / sx`, `s / sx`, `-s / sy`, `c / sy` are rounded
//! to Q32 once (sines and cosines in Q30: within `4e-9`). The value at
//! pixel `(x, y)` is then `U(x, y) = u0 + x ux + y uy` exactly (integers):
//! stepping along a row adds `ux`, and any pixel gets the same bits from
//! any start.

use super::ImageFault;
use crate::geom::{FinePoint, FINE_BITS};
use crate::path::trig::{cos_sin, div_round};
use crate::path::Degrees;

/// A scale factor, 1/65536 units (`Scale::ONE` is 1:1).
///
/// ```
/// use softedge::image::Scale;
/// assert_eq!(Scale::from_ratio(1, 2).bits(), 32768);
/// assert_eq!(Scale::from_ratio(48, 24), Scale::from_int(2));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Scale(u32);

impl Scale {
    /// 1:1.
    pub const ONE: Scale = Scale(1 << 16);
    /// The smallest scale drawn: 1/16.
    pub const MIN: Scale = Scale(1 << 12);
    /// The largest scale drawn: 256.
    pub const MAX: Scale = Scale(1 << 24);

    /// A scale from its bits (1/65536).
    pub const fn from_bits(bits: u32) -> Self {
        Self(bits)
    }

    /// `n` times.
    pub const fn from_int(n: u32) -> Self {
        Self(n.saturating_mul(1 << 16))
    }

    /// `num / den`, rounded to 1/65536 (`den = 0` gives 0, refused when
    /// drawn).
    pub const fn from_ratio(num: u32, den: u32) -> Self {
        if den == 0 {
            return Self(0);
        }
        let v = ((num as u64) << 17).saturating_add(den as u64) / (2 * den as u64);
        Self(if v > u32::MAX as u64 {
            u32::MAX
        } else {
            v as u32
        })
    }

    /// The bits, 1/65536.
    pub const fn bits(self) -> u32 {
        self.0
    }

    fn check(self) -> Result<u32, ImageFault> {
        if self < Self::MIN || self > Self::MAX {
            return Err(ImageFault::Scale { scale: self.0 });
        }
        Ok(self.0)
    }
}

/// Where an image lands: its point `pivot` (1/1024 texel from the image's
/// top-left corner) at `position` (1/1024 px on screen), scaled by
/// `scale` about it and rotated by `angle` (clockwise on screen) about it.
/// The default is the image unscaled with its top-left corner at the
/// frame's origin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ImageTransform {
    /// Where the pivot lands, fine units.
    pub position: FinePoint,
    /// The point of the image that stays put, 1/1024 texel.
    pub pivot: FinePoint,
    /// Horizontal and vertical scale (the image's own axes).
    pub scale: (Scale, Scale),
    /// Clockwise on screen.
    pub angle: Degrees,
}

impl Default for ImageTransform {
    fn default() -> Self {
        Self {
            position: FinePoint::new(0, 0),
            pivot: FinePoint::new(0, 0),
            scale: (Scale::ONE, Scale::ONE),
            angle: Degrees::ZERO,
        }
    }
}

/// How a band samples the image.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Filter {
    /// Texel for pixel: texel `(x - dx, y - dy)`.
    Copy { dx: i32, dy: i32 },
    /// Bilinear.
    Bilinear,
    /// Box of `W x H` texels (Q32).
    Box { w: i64, h: i64 },
}

/// The set-up of an image's transform.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Mapping {
    /// `U(x, y) = u[0] + x u[1] + y u[2]`: the image's u of pixel
    /// `(x, y)`'s centre, Q32 texels.
    pub u: [i64; 3],
    /// The same for v.
    pub v: [i64; 3],
    /// The image's outline on screen: its corners `(0, 0), (w, 0), (w, h),
    /// (0, h)` transformed.
    pub corners: [FinePoint; 4],
    pub filter: Filter,
    pub width: i32,
    pub height: i32,
}

/// `v / 2^30` rounded to nearest (halves up).
fn round_q30(v: i64) -> i64 {
    (v >> 1).wrapping_add(1 << 28) >> 29
}

/// Q32 texels of one texel.
const ONE_Q32: i64 = 1 << 32;

impl Mapping {
    /// True when a band takes texel for pixel (unscaled, unrotated, at
    /// a whole-pixel offset: [`Filter::Copy`]).
    pub(crate) fn is_copy(&self) -> bool {
        matches!(self.filter, Filter::Copy { .. })
    }

    /// The mapping of an image of `(w, h)` texels under `t`.
    pub(crate) fn new(t: &ImageTransform, (w, h): (u16, u16)) -> Result<Self, ImageFault> {
        // Position in the coordinate range, pivot within 2^24 fine texels
        // (4 times the largest image): every product below fits in i64.
        const PIVOT_LIMIT: i32 = 1 << 24;
        if !t.position.in_range()
            || t.pivot.x.unsigned_abs() > PIVOT_LIMIT as u32
            || t.pivot.y.unsigned_abs() > PIVOT_LIMIT as u32
        {
            return Err(ImageFault::Range);
        }
        let sx = i64::from(t.scale.0.check()?);
        let sy = i64::from(t.scale.1.check()?);
        let binary = t.angle.binary().rem_euclid(1 << 32) as u32;
        // No rotation: no series (and exact).
        let (c, s) = if binary == 0 {
            (1i64 << 30, 0)
        } else {
            cos_sin(binary)
        };
        // Q30 * 2^18 / Q16 = Q32 (|c| <= 2^30: the numerator below 2^49);
        // a scale of exactly 1 divides by nothing.
        let inv = |n: i64, d: i64| {
            if d == 1 << 16 {
                n << 2
            } else {
                div_round(i128::from(n << 18), i128::from(d)) as i64
            }
        };
        let (ux, uy, vx, vy) = (inv(c, sx), inv(s, sx), inv(-s, sy), inv(c, sy));
        let (px, py) = (i64::from(t.position.x), i64::from(t.position.y));
        let half = 1i64 << (FINE_BITS - 1);
        let pivot = |p: i32| i64::from(p) << (32 - FINE_BITS);
        // Unrotated at scale 1 (a copy, or an icon placed between pixels),
        // the matrix is 2^30 times the identity: see `corner` below.
        let identity = binary == 0 && sx == 1 << 16 && sy == 1 << 16;
        // The pixel centre's offset from the position is 1024 x + 512 -
        // position (fine units); the x part gives x ux exactly. With the
        // identity (`ux = vy = 2^32`, `uy = vx = 0`) the products are
        // shifts, exactly.
        let k = |a: i64, b: i64| (a * (half - px) + b * (half - py)) >> FINE_BITS;
        let (ku, kv) = if identity {
            (
                (half - px) << (32 - FINE_BITS),
                (half - py) << (32 - FINE_BITS),
            )
        } else {
            (k(ux, uy), k(vx, vy))
        };
        let u = [pivot(t.pivot.x) + ku, ux, uy];
        let v = [pivot(t.pivot.y) + kv, vx, vy];
        // Forward: position + R S (t - pivot), fine units: the matrix in
        // Q30 (|c sx| >> 16 <= 2^38), times offsets below 2^24 fine units,
        // in i64; the Q30 truncation moves a corner by under 2^-6 fine
        // units.
        // (Not made for the identity, which does not use them.)
        let (fc_x, fs_x, fs_y, fc_y) = if identity {
            (0, 0, 0, 0)
        } else {
            (
                (c * sx) >> 16,
                (s * sx) >> 16,
                (s * sy) >> 16,
                (c * sy) >> 16,
            )
        };
        // With the identity each corner is the position plus its offset,
        // exactly what the products round to: without them (64-bit
        // products are library calls on a Cortex-M0, and every band sets
        // its image's mapping up again).
        let corner = |tu: i32, tv: i32| -> Result<FinePoint, ImageFault> {
            let du = i64::from(tu) * (1 << FINE_BITS) - i64::from(t.pivot.x);
            let dv = i64::from(tv) * (1 << FINE_BITS) - i64::from(t.pivot.y);
            // |du|, |dv| < 2^25: a product beyond i64 lies far beyond the
            // range anyway.
            let m =
                |a: i64, b: i64, c: i64, d: i64| a.checked_mul(b)?.checked_add(c.checked_mul(d)?);
            let (x, y) = if identity {
                (px + du, py + dv)
            } else {
                let (Some(x), Some(y)) = (m(fc_x, du, -fs_y, dv), m(fs_x, du, fc_y, dv)) else {
                    return Err(ImageFault::Range);
                };
                (px + round_q30(x), py + round_q30(y))
            };
            match (i32::try_from(x), i32::try_from(y)) {
                (Ok(x), Ok(y)) if FinePoint::new(x, y).in_range() => Ok(FinePoint::new(x, y)),
                _ => Err(ImageFault::Range),
            }
        };
        let (wi, hi) = (i32::from(w), i32::from(h));
        let corners = [
            corner(0, 0)?,
            corner(wi, 0)?,
            corner(wi, hi)?,
            corner(0, hi)?,
        ];
        let one = 1u32 << 16;
        let (sxb, syb) = (t.scale.0.bits(), t.scale.1.bits());
        let filter = if binary == 0
            && sxb == one
            && syb == one
            && (t.position.x - t.pivot.x) & ((1 << FINE_BITS) - 1) == 0
            && (t.position.y - t.pivot.y) & ((1 << FINE_BITS) - 1) == 0
        {
            Filter::Copy {
                dx: (t.position.x - t.pivot.x) >> FINE_BITS,
                dy: (t.position.y - t.pivot.y) >> FINE_BITS,
            }
        } else if sxb >= one / 2 && syb >= one / 2 {
            Filter::Bilinear
        } else {
            // max(1, 1 / s) in Q32: 2^48 / s for s below 1.
            let side = |s: u32| {
                if s >= one {
                    ONE_Q32
                } else {
                    div_round(1 << 48, i128::from(s)) as i64
                }
            };
            Filter::Box {
                w: side(sxb),
                h: side(syb),
            }
        };
        Ok(Self {
            u,
            v,
            corners,
            filter,
            width: wi,
            height: hi,
        })
    }

    /// `(U, V)` of frame pixel `(x, y)`'s centre, Q32 texels (wrapping:
    /// the samplers clamp what they read).
    #[inline(always)]
    pub(crate) fn at(&self, x: i32, y: i32) -> (i64, i64) {
        let at = |k: &[i64; 3]| {
            k[0].wrapping_add(k[1].wrapping_mul(i64::from(x)))
                .wrapping_add(k[2].wrapping_mul(i64::from(y)))
        };
        (at(&self.u), at(&self.v))
    }

    /// The image rows the pixels `x0..x1` of rows `y0..y1` can read (with
    /// the filter's reach), clipped to the image.
    pub(crate) fn rows_for(&self, x: (i32, i32), y: (i32, i32)) -> core::ops::Range<i32> {
        let reach = match self.filter {
            Filter::Box { h, .. } => h / 2 + ONE_Q32,
            _ => ONE_Q32,
        };
        let mut lo = i64::MAX;
        let mut hi = i64::MIN;
        // `p k`, saturated; an unrotated, unscaled mapping's `0` and
        // `2^32` without a 64-bit product (a library call on a Cortex-M0).
        let mul = |p: i32, k: i64| match k {
            0 => 0,
            ONE_Q32 => i64::from(p) << 32,
            _ => i64::from(p).saturating_mul(k),
        };
        for (px, py) in [(x.0, y.0), (x.1, y.0), (x.0, y.1), (x.1, y.1)] {
            let v = self.v[0]
                .saturating_add(mul(px, self.v[1]))
                .saturating_add(mul(py, self.v[2]));
            lo = lo.min(v);
            hi = hi.max(v);
        }
        // `min` and `max`, not `Ord::clamp` (its panic path stays in the
        // firmware).
        let h = i64::from(self.height);
        let top = (lo.saturating_sub(reach) >> 32).min(h).max(0) as i32;
        let bottom = ((hi.saturating_add(reach) >> 32) + 1).min(h).max(0) as i32;
        top..bottom
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Unrotated at scale 1, every corner is the position plus the
    /// corner's offset from the pivot, in exact integers, and a corner
    /// beyond the coordinate range is a range fault.
    #[test]
    fn unscaled_unrotated_corners_are_the_position_plus_the_offsets() {
        let mut rng = crate::path::testing::Lcg(0x0001_dec0);
        let lim = i64::from(crate::geom::FINE_LIMIT);
        for k in 0..20_000 {
            let near = |rng: &mut crate::path::testing::Lcg| -> i32 {
                let v = if k % 2 == 0 {
                    rng.below(2 * lim as u64 + 1) as i64 - lim
                } else {
                    // Near the ends of the range.
                    (lim - rng.below(70_000) as i64) * if rng.below(2) == 0 { 1 } else { -1 }
                };
                v as i32
            };
            let position = FinePoint::new(near(&mut rng), near(&mut rng));
            let pivot = FinePoint::new(
                rng.below(1 << 23) as i32 - (1 << 22),
                rng.below(1 << 23) as i32 - (1 << 22),
            );
            let (w, h) = (1 + rng.below(4096) as u16, 1 + rng.below(4096) as u16);
            let t = ImageTransform {
                position,
                pivot,
                ..ImageTransform::default()
            };
            let want: Option<[FinePoint; 4]> = (|| {
                let c = |tu: i64, tv: i64| {
                    let x = i64::from(position.x) + tu * 1024 - i64::from(pivot.x);
                    let y = i64::from(position.y) + tv * 1024 - i64::from(pivot.y);
                    (x.abs() <= lim && y.abs() <= lim).then(|| FinePoint::new(x as i32, y as i32))
                };
                let (w, h) = (i64::from(w), i64::from(h));
                Some([c(0, 0)?, c(w, 0)?, c(w, h)?, c(0, h)?])
            })();
            match (Mapping::new(&t, (w, h)), want) {
                (Ok(m), Some(c)) => {
                    assert_eq!(m.corners, c, "{t:?} {w}x{h}");
                    // Pixel (x, y)'s centre maps to texel
                    // ((1024 x + 512 - position + pivot) / 1024) in Q32,
                    // exactly (i128 here).
                    let q = |p: i32, pos: i32, piv: i32, k: &[i64; 3], x: i32, y: i32| {
                        let want = ((i128::from(p) * 1024 + 512 - i128::from(pos)
                            + i128::from(piv))
                            << 22) as i64;
                        let got = k[0]
                            .wrapping_add(k[1].wrapping_mul(i64::from(x)))
                            .wrapping_add(k[2].wrapping_mul(i64::from(y)));
                        assert_eq!(got, want, "{t:?} at ({x}, {y})");
                    };
                    let (x, y) = (near(&mut rng) >> 10, near(&mut rng) >> 10);
                    q(x, position.x, pivot.x, &m.u, x, y);
                    q(y, position.y, pivot.y, &m.v, x, y);
                }
                (Err(ImageFault::Range), None) => {}
                (got, want) => panic!("{t:?} {w}x{h}: {:?} vs {want:?}", got.map(|m| m.corners)),
            }
        }
    }

    #[test]
    fn identity_copies_and_maps_centres_to_centres() {
        let t = ImageTransform {
            position: FinePoint::from_px(10, 20),
            ..ImageTransform::default()
        };
        let m = Mapping::new(&t, (4, 3)).unwrap();
        assert_eq!(m.filter, Filter::Copy { dx: 10, dy: 20 });
        // Pixel (10, 20)'s centre is texel (0.5, 0.5).
        assert_eq!(m.u[0] + 10 * m.u[1] + 20 * m.u[2], ONE_Q32 / 2);
        assert_eq!(m.v[0] + 10 * m.v[1] + 20 * m.v[2], ONE_Q32 / 2);
        assert_eq!(m.corners[2], FinePoint::from_px(14, 23));
    }

    #[test]
    fn a_quarter_turn_maps_exactly() {
        let t = ImageTransform {
            position: FinePoint::from_px(50, 50),
            pivot: FinePoint::from_px(2, 1),
            scale: (Scale::from_int(2), Scale::from_int(2)),
            angle: Degrees::new(90),
        };
        let m = Mapping::new(&t, (4, 2)).unwrap();
        assert_eq!(m.filter, Filter::Bilinear);
        // Image +u points down on screen: corner (4, 0) is 4 px below
        // the pivot's landing point (texel (2, 1)): (50 + 2, 50 + 4).
        assert_eq!(m.corners[1], FinePoint::from_px(52, 54));
        assert_eq!(m.corners[0], FinePoint::from_px(52, 46));
    }

    #[test]
    fn bad_scales_and_ranges_are_refused() {
        let mut t = ImageTransform::default();
        t.scale.0 = Scale::from_ratio(1, 17);
        assert!(matches!(
            Mapping::new(&t, (8, 8)),
            Err(ImageFault::Scale { .. })
        ));
        t.scale.0 = Scale::from_bits(0);
        assert!(matches!(
            Mapping::new(&t, (8, 8)),
            Err(ImageFault::Scale { .. })
        ));
        let t = ImageTransform {
            position: FinePoint::from_px(2000, 0),
            scale: (Scale::from_int(200), Scale::ONE),
            ..ImageTransform::default()
        };
        assert_eq!(Mapping::new(&t, (8, 8)).err(), Some(ImageFault::Range));
        for (position, pivot) in [
            (FinePoint::new(i32::MIN, 0), FinePoint::new(0, 0)),
            (FinePoint::new(0, 0), FinePoint::new(i32::MAX, i32::MIN)),
            (FinePoint::new(0, 0), FinePoint::new(1 << 24, -(1 << 24))),
        ] {
            let t = ImageTransform {
                position,
                pivot,
                scale: (Scale::MAX, Scale::MIN),
                angle: Degrees::new(45),
            };
            assert_eq!(
                Mapping::new(&t, (4096, 4096)).err(),
                Some(ImageFault::Range)
            );
        }
        let t = ImageTransform {
            scale: (Scale::from_ratio(1, 8), Scale::ONE),
            ..ImageTransform::default()
        };
        let m = Mapping::new(&t, (64, 8)).unwrap();
        assert_eq!(
            m.filter,
            Filter::Box {
                w: 8 * ONE_Q32,
                h: ONE_Q32
            }
        );
    }
}
