//! Shading setup: the Gouraud plane of a primitive.
//!
//! Takes the vertices and per-vertex colours of a triangle (or one flat
//! colour), gives the plane `I(i, j)` of linear intensity at pixel centres in
//! 16.16 fixed point, relative to the band's background. This is the only
//! place colour gradients are divided, once per primitive; the edge walker
//! and the span sweep then step the plane with one addition per pixel
//! (`I += gx` along a row, `I += gy` down a column) — Gouraud's bilinear
//! interpolation along edges and spans (seed 001) in its plane form, which
//! for a triangle is the same function.
//!
//! ## Ranges
//!
//! Intensities are linear 12-bit (`0..=4095`, [`LIN_MAX`]); larger inputs
//! are clamped. The gradients are rounded once, to 1/65536 of a level per
//! pixel, so the plane at any pixel is an exact integer function of the pixel
//! address (the same bits whether reached by stepping or evaluated directly:
//! what makes bands of any height agree).
//!
//! A channel whose gradient is steeper than one full scale (4095) per pixel
//! belongs to a triangle thinner than a pixel across; that channel is shaded
//! flat with the mean of its three vertex values, which is exactly the
//! plane's average over the triangle, so the triangle's energy is kept.
//! Every other plane changes by at most 4095 per pixel and is evaluated only
//! at the centres of pixels the primitive touches (within `√2/2` px of it),
//! so `|I| < 2 * 4096` and every product downstream stays far inside `i64`.

mod depth_plane;

pub use depth_plane::{DepthPlane, DEPTH_FRAC};

use crate::geom::SubPoint;

pub use crate::units::LIN_MAX;

/// Fraction bits of the plane's fine intensities.
pub const PLANE_FRAC: u32 = 16;

/// Steepest gradient kept, in fine units per pixel: one full scale.
const GRAD_LIMIT: i64 = (LIN_MAX as i64) << PLANE_FRAC;

/// Gouraud plane of one primitive, per channel, relative to the background.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Plane<const C: usize> {
    /// Reference pixel.
    pub i0: i32,
    /// Reference pixel row.
    pub j0: i32,
    /// `(I - bg) * 2^16` at the centre of pixel `(i0, j0)`.
    pub at0: [i32; C],
    /// Change per pixel to the right, `* 2^16`.
    pub gx: [i32; C],
    /// Change per pixel down, `* 2^16`.
    pub gy: [i32; C],
}

/// `round(n / d)` for `d > 0`, halves away from minus infinity.
pub(crate) fn div_round(n: i64, d: i64) -> i64 {
    crate::arith::div_floor(2 * n + d, 2 * d)
}

/// The set-up shared by every plane through a triangle's vertices (Gouraud
/// intensity here, depth in [`hsr`](crate::hsr)): its reference pixel and
/// the fit of three vertex values, in 16.16 fixed point, rounded once.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneFit {
    /// Reference pixel: the one holding vertex 0.
    pub(crate) i0: i32,
    /// Reference pixel row.
    pub(crate) j0: i32,
    dx1: i64,
    dy1: i64,
    dx2: i64,
    dy2: i64,
    /// `|2 * area|` in sub-pixels², and the sign that made it positive.
    d: i64,
    sign: i64,
    /// Offset of the reference pixel's centre from vertex 0, grid units.
    cx: i64,
    cy: i64,
    /// Fraction bits of the vertices' grid.
    bits: u32,
}

impl PlaneFit {
    /// `None` for a triangle of zero area. Vertices within the coordinate
    /// range keep every product of [`values`](Self::values) below `2^54`
    /// for values below `2^16`.
    pub(crate) fn new(v: [SubPoint; 3]) -> Option<Self> {
        Self::on_grid(v.map(|p| (p.x, p.y)), crate::SUB_BITS)
    }

    /// The same for vertices on the fine grid (1/1024 px): products stay
    /// below `2^61`.
    pub(crate) fn new_fine(v: [crate::geom::FinePoint; 3]) -> Option<Self> {
        Self::on_grid(v.map(|p| (p.x, p.y)), crate::geom::FINE_BITS)
    }

    /// Vertices with `bits` fraction bits.
    fn on_grid(v: [(i32, i32); 3], bits: u32) -> Option<Self> {
        let (x0, y0) = (i64::from(v[0].0), i64::from(v[0].1));
        let (dx1, dy1) = (i64::from(v[1].0) - x0, i64::from(v[1].1) - y0);
        let (dx2, dy2) = (i64::from(v[2].0) - x0, i64::from(v[2].1) - y0);
        let d = dx1 * dy2 - dx2 * dy1;
        if d == 0 {
            return None;
        }
        let i0 = v[0].0 >> bits;
        let j0 = v[0].1 >> bits;
        let per_px = 1i64 << bits;
        let half = per_px / 2;
        Some(Self {
            i0,
            j0,
            dx1,
            dy1,
            dx2,
            dy2,
            d: d.abs(),
            sign: d.signum(),
            cx: i64::from(i0) * per_px + half - x0,
            cy: i64::from(j0) * per_px + half - y0,
            bits,
        })
    }

    /// For values `f` at the three vertices: the plane at the reference
    /// pixel's centre, and its change per pixel right and down, all times
    /// `2^16`, each rounded once.
    pub(crate) fn values(&self, f: [i64; 3]) -> (i64, i64, i64) {
        let (df1, df2) = (f[1] - f[0], f[2] - f[0]);
        let one = 1i64 << PLANE_FRAC;
        let per_px = 1i64 << self.bits;
        // df/dx = a / d and df/dy = b / d per grid unit.
        let a = self.sign * (df1 * self.dy2 - df2 * self.dy1);
        let b = self.sign * (df2 * self.dx1 - df1 * self.dx2);
        let gx = div_round(a * per_px * one, self.d);
        let gy = div_round(b * per_px * one, self.d);
        let at = f[0] * one + div_round((a * self.cx + b * self.cy) * one, self.d);
        (at, gx, gy)
    }
}

impl<const C: usize> Plane<C> {
    /// A flat colour.
    pub fn flat(color: [u16; C], background: [u16; C]) -> Self {
        let mut at0 = [0i32; C];
        for ((a, c), b) in at0.iter_mut().zip(color).zip(background) {
            *a = (i32::from(c.min(LIN_MAX)) - i32::from(b.min(LIN_MAX))) << PLANE_FRAC;
        }
        Self {
            i0: 0,
            j0: 0,
            at0,
            gx: [0; C],
            gy: [0; C],
        }
    }

    /// The plane through three vertices and their colours, or `None` when
    /// the triangle has zero area.
    pub fn triangle(v: [SubPoint; 3], colors: [[u16; C]; 3], background: [u16; C]) -> Option<Self> {
        Self::fit(PlaneFit::new(v)?, colors, background)
    }

    fn fit(fit: PlaneFit, colors: [[u16; C]; 3], background: [u16; C]) -> Option<Self> {
        let one = 1i64 << PLANE_FRAC;
        let mut plane = Self {
            i0: fit.i0,
            j0: fit.j0,
            at0: [0; C],
            gx: [0; C],
            gy: [0; C],
        };
        for ch in 0..C {
            let c = |k: usize| i64::from(colors[k][ch].min(LIN_MAX));
            let bg = i64::from(background[ch].min(LIN_MAX));
            let (at, gx, gy) = fit.values([c(0), c(1), c(2)]);
            if gx.abs() > GRAD_LIMIT || gy.abs() > GRAD_LIMIT {
                // Thinner than a pixel: flat, at the plane's mean.
                let mean = div_round((c(0) + c(1) + c(2)) * one, 3);
                plane.at0[ch] = (mean - bg * one) as i32;
                continue;
            }
            plane.gx[ch] = gx as i32;
            plane.gy[ch] = gy as i32;
            plane.at0[ch] = (at - bg * one) as i32;
        }
        Some(plane)
    }

    /// The plane through three fine vertices and their colours (absolute:
    /// over a zero background), or `None` when the triangle has zero area.
    pub fn triangle_fine(v: [crate::geom::FinePoint; 3], colors: [[u16; C]; 3]) -> Option<Self> {
        Self::fit(PlaneFit::new_fine(v)?, colors, [0; C])
    }

    /// The fine intensity at the centre of pixel `(i, j)` (setup use: two
    /// multiplies per channel).
    pub fn at(&self, i: i32, j: i32) -> [i64; C] {
        let di = i64::from(i) - i64::from(self.i0);
        let dj = i64::from(j) - i64::from(self.j0);
        let mut out = [0i64; C];
        for ch in 0..C {
            out[ch] =
                i64::from(self.at0[ch]) + i64::from(self.gx[ch]) * di + i64::from(self.gy[ch]) * dj;
        }
        out
    }

    /// The plane times `num / den` (relative to the background; setup use).
    pub fn scaled(&self, num: i64, den: i64) -> Self {
        if den <= 0 || num < 0 {
            return *self;
        }
        let f = |v: i32| {
            crate::arith::limit(
                div_round(i64::from(v) * num, den),
                i64::from(i32::MIN),
                i64::from(i32::MAX),
            ) as i32
        };
        Self {
            i0: self.i0,
            j0: self.j0,
            at0: self.at0.map(f),
            gx: self.gx.map(f),
            gy: self.gy.map(f),
        }
    }

    /// The plane moved up by `background` (per channel, linear 12-bit): a
    /// plane relative to a background made absolute.
    pub(crate) fn offset(&self, background: [u16; C]) -> Self {
        let mut out = *self;
        for (a, b) in out.at0.iter_mut().zip(background) {
            *a = a.saturating_add(i32::from(b.min(LIN_MAX)) << PLANE_FRAC);
        }
        out
    }

    /// True when the plane is constant (a flat colour).
    pub fn is_flat(&self) -> bool {
        self.gx.iter().chain(self.gy.iter()).all(|&g| g == 0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_triangle_has_zero_gradient_exactly() {
        let v = [
            SubPoint::new(3, 5),
            SubPoint::new(200, 17),
            SubPoint::new(40, 301),
        ];
        let p = Plane::triangle(v, [[1000], [1000], [1000]], [0]).unwrap();
        assert!(p.is_flat());
        assert_eq!(p.at(7, 9), [1000 << 16]);
    }

    #[test]
    fn plane_interpolates_vertex_colours() {
        // Vertices at pixel centres, so the plane must hit their colours.
        let c = |x: i32, y: i32| SubPoint::new(x * 16 + 8, y * 16 + 8);
        let v = [c(0, 0), c(10, 0), c(0, 10)];
        let p = Plane::triangle(v, [[0], [4000], [2000]], [0]).unwrap();
        assert_eq!(p.at(0, 0), [0]);
        assert_eq!(p.at(10, 0), [4000 << 16]);
        assert_eq!(p.at(0, 10), [2000 << 16]);
        assert_eq!(p.at(5, 5), [3000 << 16]);
    }

    #[test]
    fn degenerate_triangle_has_no_plane() {
        let v = [
            SubPoint::new(0, 0),
            SubPoint::new(16, 16),
            SubPoint::new(32, 32),
        ];
        assert!(Plane::triangle(v, [[0], [1], [2]], [0]).is_none());
    }

    #[test]
    fn sliver_channel_is_flat_at_the_vertex_mean() {
        // 1/16 px tall: dI/dy would be 16 full scales per pixel.
        let v = [
            SubPoint::new(0, 0),
            SubPoint::new(1000, 0),
            SubPoint::new(0, 1),
        ];
        let p = Plane::triangle(v, [[0, 0], [0, 300], [4095, 0]], [0, 0]).unwrap();
        assert_eq!((p.gx[0], p.gy[0]), (0, 0));
        assert_eq!(p.at(3, 0)[0], 1365 << 16);
        // The second channel varies along x only, gently: kept as a plane.
        assert_ne!(p.gx[1], 0);
        assert_eq!(p.gy[1], 0);
    }
}
