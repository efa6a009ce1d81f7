//! The circular filters of seed 003's survey — cone, Gaussian, Hamming —
//! as equal-energy splat tables on the 1/16-px sample grid.
//!
//! **Why samples, not a table by edge distance.** The seed (and SPEC §6)
//! read the intensity as the volume of the filter on the polygon's side of
//! one edge, tabulated by signed distance. That volume is right for a
//! pixel crossed by one long edge only; at vertices, thin slivers and two
//! edges in one pixel the per-edge volumes do not add up to the volume
//! over the polygon (the filter is wider than the pixel), shared edges
//! would need both triangles' tables to agree to the bit, and the
//! formulas are not equal energy at these radii (below), so the sum over a
//! moving object would ripple. Point samples avoid all three: the volume
//! over the polygon is the weighted count of samples inside (any shape), the
//! aliased walk's top-left rule gives each sample on a shared edge to
//! exactly one primitive (seamless to the bit), and the weights can be made
//! equal energy exactly in integers.
//!
//! **The grid.** Samples lie at `(k + 1/2) / 16` px: one per sub-pixel of
//! the vertex grid (`SUB_ONE` = 16), so moving an object by whole
//! sub-pixels moves it by whole samples and its weighted sample count —
//! its summed intensity — is exactly constant: no flicker at all. Pixel
//! `p`'s footprint along an axis is the `S = 16 m` samples within `m / 2`
//! px of its centre (`m` = 2 or 3 pixels wide), sample `k` of it at
//! `u_k = (2k + 1 - S) / 32` px. A sample's *phase* `(k_x mod 16, k_y mod
//! 16)` says where inside a pixel it lies; a sample of phase `(a, b)` falls
//! on slot `(a + 16s, b + 16t)` of exactly one pixel for every `s, t < m`.
//! So the filter is equal energy exactly when, for each of the 256 phases,
//! the `m^2` slots of that phase add to the same total.
//!
//! **The table** is built at compile time from the filter's formula (the
//! `sqrt`, `exp` and `cos` are `const` series, tested against `std`): per
//! phase, the formula's values at the slots are scaled to add to
//! [`CIRCULAR_PHASE_TOTAL`] = 16 and rounded by largest remainder, so each
//! phase adds to 16 exactly and a pixel's 256 phases to 4096 =
//! [`MODEL_ONE`]. The per-phase scaling is the smallest
//! change that makes the formula equal energy; the rounding is within one
//! unit, `1/4096` of a pixel, per sample. Measured against the continuous
//! filter (tests): a pixel's coverage by a half-plane is within 0.47 %
//! (cone), 0.37 % (Gaussian), 0.22 % (Hamming) of full scale of the
//! filter's volume on that side.
//!
//! **Cost** per edge and pixel row: 16 add/compare steps of the aliased
//! walk, and per sample row and pixel row of the footprint ([`splat_row`])
//! two shifts and up to `1 + m` table look-ups and cover adds: about
//! `16 m (1 + m)` cover adds, 96 for `m` = 2, 192 for the Gaussian's 3 —
//! the price of exact equal energy and zero flicker, so these are quality
//! models. Measured with callgrind on the host (x86-64, a 240x240 frame of
//! 288 flat triangles sharing edges, about 12 000 edge pixel-rows; the
//! `bench` binary of `softedge-sim`): 9.7 M instructions with the box
//! model, 104.2 M cone, 102.8 M Hamming, 153.5 M Gaussian, i.e. about
//! 7 800 (cone, Hamming) and 12 000 (Gaussian) more per edge pixel-row
//! (bed-of-nails 8x8: 3 400; Hex19: 1 000). No float at
//! run time: the `f64` below only runs in `const` evaluation. Tables:
//! `u16` suffix sums, `48 x 49` per filter (4.7 KB each).

use core::ops::Range;

use super::splat::{splat_row, RowFootprint};
use super::walk_samples;
use crate::band::BandBuffer;
use crate::edge::CoverSink;
use crate::SubPoint;

/// Samples per pixel and axis: one per sub-pixel.
pub const CIRCULAR_SAMPLES: usize = 1 << CIRCULAR_SHIFT;
/// `log2(CIRCULAR_SAMPLES)`.
const CIRCULAR_SHIFT: u32 = crate::SUB_BITS;
/// Weight units every sample position distributes in all (its phase's
/// total): `COVER_ONE / CIRCULAR_SAMPLES^2`.
pub const CIRCULAR_PHASE_TOTAL: u32 =
    (super::MODEL_ONE as u32) / (CIRCULAR_SAMPLES * CIRCULAR_SAMPLES) as u32;
/// Widest footprint in samples (`m = 3`).
const MAX_SPAN: usize = 3 * CIRCULAR_SAMPLES;

/// Cone radius `R`, px: `F = H (1 - r/R)`, `H = 3 / (pi R^2)`.
pub const CONE_RADIUS: f64 = 1.0;
/// Gaussian `sigma`, px: `F = exp(-r^2 / (2 sigma^2))` for `r < 3 sigma`.
pub const GAUSS_SIGMA: f64 = 0.5;
/// Hamming window `W`, px: `F = (cos(pi x / W) cos(pi y / W))^e` on
/// `|x|, |y| <= W/2`.
pub const HAMMING_W: f64 = 2.0;
/// Hamming exponent `e`.
pub const HAMMING_E: u32 = 2;

/// One of the circular filters of seed 003's survey.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum CircularFilter {
    /// The cone `H (1 - r/R)`, `R` = [`CONE_RADIUS`] = 1 px (base 2 px
    /// across, like the bed-of-nails tent). Its sum over the pixels, at the
    /// sample positions, ripples by +11.6 / -6.2 % around its mean.
    Cone,
    /// The Gaussian `exp(-r^2 / (2 sigma^2))`, `sigma` = [`GAUSS_SIGMA`] =
    /// 1/2 px, cut at `r = 3 sigma` = 1.5 px. Its sum over the pixels
    /// ripples by +3.9 / -5.3 %.
    Gaussian,
    /// Hamming `(cos(pi x/W) cos(pi y/W))^e` with `W` = 2 px, `e` = 2:
    /// per axis `cos^2(pi u/2) + cos^2(pi (1-u)/2) = 1`, so this one is
    /// equal energy by its formula; the table only rounds it. (`e` = 1
    /// would ripple by +23 / -37 %, `e` = 3 by +39 / -31 %.)
    Hamming,
}

impl CircularFilter {
    /// Width of the footprint in pixels, `m`: 2 for the cone and Hamming
    /// (support within 1 px of the centre), 3 for the Gaussian.
    pub const fn width_px(self) -> usize {
        match self {
            Self::Cone | Self::Hamming => 2,
            Self::Gaussian => 3,
        }
    }

    /// The filter's formula at `(x, y)` px from the pixel centre, unscaled.
    /// `const`, for the tables; tests compare it with `std`'s functions.
    pub const fn formula(self, x: f64, y: f64) -> f64 {
        match self {
            Self::Cone => {
                let r = const_sqrt(x * x + y * y);
                if r < CONE_RADIUS {
                    1.0 - r / CONE_RADIUS
                } else {
                    0.0
                }
            }
            Self::Gaussian => {
                let r2 = x * x + y * y;
                let cut = 3.0 * GAUSS_SIGMA;
                if r2 < cut * cut {
                    const_exp_neg(r2 / (2.0 * GAUSS_SIGMA * GAUSS_SIGMA))
                } else {
                    0.0
                }
            }
            Self::Hamming => {
                let h = HAMMING_W / 2.0;
                if const_abs(x) > h || const_abs(y) > h {
                    return 0.0;
                }
                let pi = core::f64::consts::PI;
                let v = const_cos(pi * x / HAMMING_W) * const_cos(pi * y / HAMMING_W);
                let mut out = 1.0;
                let mut k = 0;
                while k < HAMMING_E {
                    out *= v;
                    k += 1;
                }
                out
            }
        }
    }

    /// The integer weight of footprint slot `(kx, ky)` (each in
    /// `0..16 * width_px()`), in units of `1/4096` of the pixel; 0 outside.
    ///
    /// ```
    /// use softedge::pixel_model::{CircularFilter, CIRCULAR_PHASE_TOTAL, CIRCULAR_SAMPLES as N};
    /// for f in [CircularFilter::Cone, CircularFilter::Gaussian, CircularFilter::Hamming] {
    ///     let (m, mut pixel) = (f.width_px(), 0);
    ///     // Every phase distributes the same total: equal energy.
    ///     for (a, b) in (0..N).flat_map(|a| (0..N).map(move |b| (a, b))) {
    ///         let phase: u32 = (0..m)
    ///             .flat_map(|s| (0..m).map(move |t| (s, t)))
    ///             .map(|(s, t)| f.weight(a + N * s, b + N * t))
    ///             .sum();
    ///         assert_eq!(phase, CIRCULAR_PHASE_TOTAL);
    ///         pixel += phase;
    ///     }
    ///     assert_eq!(pixel, 4096);
    /// }
    /// ```
    pub fn weight(self, kx: usize, ky: usize) -> u32 {
        let t = self.table();
        let (Some(here), Some(next)) = (
            t.get(ky).and_then(|row| row.get(kx)),
            t.get(ky).and_then(|row| row.get(kx + 1)),
        ) else {
            return 0;
        };
        u32::from(here.abs_diff(*next))
    }

    /// The suffix sums of the footprint rows (see [`splat_row`]).
    fn table(self) -> &'static [[u16; MAX_SPAN + 1]; MAX_SPAN] {
        match self {
            Self::Cone => &CONE_TABLE,
            Self::Gaussian => &GAUSS_TABLE,
            Self::Hamming => &HAMMING_TABLE,
        }
    }
}

const CONE_TABLE: [[u16; MAX_SPAN + 1]; MAX_SPAN] = build_table(CircularFilter::Cone);
const GAUSS_TABLE: [[u16; MAX_SPAN + 1]; MAX_SPAN] = build_table(CircularFilter::Gaussian);
const HAMMING_TABLE: [[u16; MAX_SPAN + 1]; MAX_SPAN] = build_table(CircularFilter::Hamming);

/// The equal-energy integer table of a filter, as row suffix sums: per
/// phase, the formula's values scaled to [`CIRCULAR_PHASE_TOTAL`] and
/// rounded by largest remainder (ties to the lower slot index).
const fn build_table(f: CircularFilter) -> [[u16; MAX_SPAN + 1]; MAX_SPAN] {
    let n = CIRCULAR_SAMPLES;
    let m = f.width_px();
    let span = n * m;
    let mut w = [[0u16; MAX_SPAN]; MAX_SPAN];
    let mut a = 0;
    while a < n {
        let mut b = 0;
        while b < n {
            // The m x m slots of phase (a, b).
            let mut raw = [0.0f64; 9];
            let mut sum = 0.0;
            let mut s = 0;
            while s < m * m {
                let (kx, ky) = (a + n * (s % m), b + n * (s / m));
                let ux = (2.0 * kx as f64 + 1.0 - span as f64) / (2.0 * n as f64);
                let uy = (2.0 * ky as f64 + 1.0 - span as f64) / (2.0 * n as f64);
                raw[s] = f.formula(ux, uy);
                sum += raw[s];
                s += 1;
            }
            let total = CIRCULAR_PHASE_TOTAL as f64;
            let mut floor = [0i32; 9];
            let mut frac = [0.0f64; 9];
            let mut given = 0;
            s = 0;
            while s < m * m {
                let v = if sum > 0.0 { raw[s] * total / sum } else { 0.0 };
                floor[s] = v as i32;
                frac[s] = v - floor[s] as f64;
                given += floor[s];
                s += 1;
            }
            // Hand out the remainder to the largest fractions.
            while given < CIRCULAR_PHASE_TOTAL as i32 {
                let mut best = 0;
                s = 1;
                while s < m * m {
                    if frac[s] > frac[best] {
                        best = s;
                    }
                    s += 1;
                }
                floor[best] += 1;
                frac[best] = -1.0;
                given += 1;
            }
            s = 0;
            while s < m * m {
                w[b + n * (s / m)][a + n * (s % m)] = floor[s] as u16;
                s += 1;
            }
            b += 1;
        }
        a += 1;
    }
    // Rows as suffix sums.
    let mut out = [[0u16; MAX_SPAN + 1]; MAX_SPAN];
    let mut ky = 0;
    while ky < span {
        let mut t = span;
        let mut acc = 0;
        while t > 0 {
            t -= 1;
            acc += w[ky][t];
            out[ky][t] = acc;
        }
        ky += 1;
    }
    out
}

/// `|x|` in `const`.
const fn const_abs(x: f64) -> f64 {
    if x < 0.0 {
        -x
    } else {
        x
    }
}

/// `sqrt(x)` for `x >= 0` by Newton's iteration (converged to the last bit
/// or two within 64 steps for the arguments used, `x <= 8`).
const fn const_sqrt(x: f64) -> f64 {
    if x <= 0.0 {
        return 0.0;
    }
    let mut g = if x > 1.0 { x } else { 1.0 };
    let mut k = 0;
    while k < 64 {
        g = 0.5 * (g + x / g);
        k += 1;
    }
    g
}

/// `exp(-z)` for `z >= 0`: the Taylor series of `exp(-z / 64)` (20 terms),
/// squared six times.
const fn const_exp_neg(z: f64) -> f64 {
    let x = -z / 64.0;
    let mut term = 1.0;
    let mut sum = 1.0;
    let mut k = 1;
    while k < 20 {
        term *= x / k as f64;
        sum += term;
        k += 1;
    }
    let mut s = 0;
    while s < 6 {
        sum *= sum;
        s += 1;
    }
    sum
}

/// `cos(x)` for `|x| <= pi/2`: its Taylor series to `x^40`.
const fn const_cos(x: f64) -> f64 {
    let x2 = x * x;
    let mut term = 1.0;
    let mut sum = 1.0;
    let mut k = 1;
    while k <= 20 {
        term *= -x2 / ((2 * k - 1) as f64 * (2 * k) as f64);
        sum += term;
        k += 1;
    }
    sum
}

/// Walks edge `p0 -> p1` of a primitive for a circular filter, writing
/// coverage changes for pixel `rows` into the band.
pub(crate) fn walk_circular<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    p0: SubPoint,
    p1: SubPoint,
    filter: CircularFilter,
    rows: Range<i32>,
) {
    let n = CIRCULAR_SAMPLES as i32;
    let span = n * filter.width_px() as i32;
    // Pixel p's footprint starts `half` samples left of its own samples.
    let half = (span - n) / 2;
    let fine = |p: SubPoint| SubPoint::new(p.x.saturating_mul(n), p.y.saturating_mul(n));
    let fine_rows = rows.start.saturating_mul(n).saturating_sub(half)
        ..rows.end.saturating_mul(n).saturating_add(half);
    let mut sink = Splat {
        band,
        table: filter.table(),
        m: filter.width_px() as i64,
        half: i64::from(half),
        rows,
    };
    walk_samples(fine(p0), fine(p1), fine_rows, &mut sink);
}

/// Spreads the fine grid's cover changes over the filter's footprints.
struct Splat<'a, 'b, const C: usize> {
    band: &'a mut BandBuffer<'b, C>,
    table: &'static [[u16; MAX_SPAN + 1]; MAX_SPAN],
    m: i64,
    half: i64,
    rows: Range<i32>,
}

impl<const C: usize> CoverSink for Splat<'_, '_, C> {
    fn cover(&mut self, c: i32, r: i32, delta: i32) {
        let n = CIRCULAR_SAMPLES as i64;
        let span = n * self.m;
        let (c, r) = (i64::from(c), i64::from(r));
        // Pixel row j's footprint: sample rows n j - half .. + span.
        let j_hi = (r + self.half) >> CIRCULAR_SHIFT;
        for j in j_hi - self.m + 1..=j_hi {
            let ky = r - (n * j - self.half);
            if !(0..span).contains(&ky) {
                continue;
            }
            let Some(row) = self.table.get(ky as usize) else {
                continue;
            };
            let cum = row.get(..=span as usize).unwrap_or(&[]);
            let fp = RowFootprint {
                shift: CIRCULAR_SHIFT,
                o: -self.half,
                cum,
            };
            splat_row(self.band, &self.rows, j as i32, c, delta.signum(), fp);
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    #[test]
    fn const_functions_match_std() {
        for k in 0..=800 {
            let x = f64::from(k) / 100.0;
            assert!((const_sqrt(x) - x.sqrt()).abs() < 1e-14, "sqrt {x}");
            assert!((const_exp_neg(x) - (-x).exp()).abs() < 1e-13, "exp {x}");
        }
        for k in -157..=157 {
            let x = f64::from(k) / 100.0;
            assert!((const_cos(x) - x.cos()).abs() < 1e-15, "cos {x}");
        }
    }
}
