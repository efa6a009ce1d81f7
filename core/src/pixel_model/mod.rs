//! Pixel models: what "covered area" means for an edge pixel.
//!
//! Takes the edges of one primitive and the band; gives each pixel its
//! coverage under the model, as cover changes in the band's scratch that the
//! span sweep turns into `I * coverage`. The box model (exact area, and the
//! seed-001 single formula) lives in the `edge` module, where the
//! combined evaluator of seed 001 computes `I * S` by additions; the models
//! here weigh point samples instead.
//!
//! ## Bed-of-nails filters (seed 000, fig. 4)
//!
//! A pixel's filter sits on a base of 2x2 pixels centred on the pixel, and is
//! sampled by `n x n` sub-samples per pixel (`n = 2`: the 4x4 filter of the
//! seed; `n = 4`: the 8x8 one). Sample `k` of the `2n` along an axis lies at
//! `u = (2k + 1 - 2n) / (2n)` pixels from the centre and weighs the tent
//! `1 - |u|`, in integers `w_k = 2n - |2k + 1 - 2n|`: `1 3 3 1` and
//! `1 3 5 7 7 5 3 1`. The 2-D weight is the product.
//!
//! **Equal energy** (eq. 4): a point lies on one sample of each of the four
//! filters that overlap it, at offsets `u` and `1 - u` along each axis,
//! whose tent weights add to 1; so the four 2-D weights add to `(2n)^2` in
//! every position (`1 + 3 + 3 + 9 = 16` for 4x4: the seed's
//! `a + 2b + c = const`; 64 for 8x8: its `a + 2d + k = b + c + g + i = ...`).
//! A small object moving across the grid keeps its total weight exactly.
//!
//! Samples are taken with the aliased walk
//! (`AliasedWalk`) on a grid
//! `n` times finer than the pixels, whose pixel centres are exactly the
//! sample points; its top-left rule gives every sample on a shared edge to
//! exactly one primitive, so meshes stay seamless to the last bit. A sample
//! row's cover change at fine column `c` becomes, for the two pixel rows
//! whose base holds that sample row, a full cover change where the pixels'
//! bases lie wholly right of `c`, and partial weights (a table of the tent's
//! cumulative sums) for the one or two pixels whose base `c` cuts.
//!
//! ## The hexagonal pixel (seed 003)
//!
//! Seven points per pixel, the centre weighing twice a ring point (the cone
//! model's centre-to-ring ratio), shared with the neighbours exactly as the
//! seed lays them out, so they form a lattice in which every point carries
//! the same total weight: equal energy again, exactly. See `hex.rs`.
//!
//! Nineteen points (seed 003's 1 + 6 + 12) on the same lattice: the ring-2
//! points lie one lattice step beyond ring 1. The seed's cone weights
//! (centre `V1 = 0.123`, ring 1 `(V7 - V1)/6`, ring 2 `(1 - V7)/12` each)
//! are *not* equal energy here: the lattice has four classes of points
//! (mod 1 px), and the pixels holding a point of class `A0` (row A,
//! centres) or `A½` (row A, between centres) give it 0.292 of a pixel in
//! all, those holding a `B` point only 0.208. The weights used
//! ([`HEX19_POINTS`]) are the integers nearest the seed's (least squares,
//! per class) that give every class exactly 1024/4096: centre 468 (seed
//! 504), ring 1 224 on the row and 295 on the diagonals (seed 252), ring 2
//! 139 at `(±1, 0)` and `(0, ±1)`, 144 at `(±1/2, ±1)`, 217 at
//! `(±3/4, ±1/2)` (seed 173); no weight moves by more than 0.011 of a
//! pixel. The diagonal points gain because the `B` rows hold fewer of a
//! pixel's points. Of the seed's cone numbers, `h = 0.106` follows from
//! the cone model and `V7 = 0.492` nearly (0.500, the cone over the disc
//! holding the 7 sub-pixels), `V1 = 0.123` does not (0.074 over the
//! central sub-pixel); the tests compute all three.
//!
//! ## Circular filters (seed 003's survey)
//!
//! Cone `H (1 - r/R)`, Gaussian and Hamming `(cos(pi x/W) cos(pi y/W))^e`,
//! sampled at every sub-pixel (16x16 samples per pixel), each sample's
//! weight spread over the pixels within the filter's radius by a table
//! computed at compile time from the formula and made equal energy per
//! sample position in integers. Moving an object by whole sub-pixels then
//! leaves its summed intensity exactly unchanged. See `circular.rs` for
//! why samples rather than a table by edge distance, and the measured
//! deviation from the continuous filters.
//!
//! Per sample row and edge: one add/compare step of the walk and a few
//! table look-ups and adds. The coverage of an edge pixel then changes from
//! one pixel to the next, so the span sweep sets up `I * coverage` with one
//! multiply per edge pixel (the seed-001 evaluator needs coverage linear
//! along the walk, which a sampled model is not).

mod bed_of_nails;
mod circular;
mod hex;
mod splat;

pub(crate) use bed_of_nails::walk_bed_of_nails;
pub(crate) use circular::walk_circular;
pub use circular::{
    CircularFilter, CIRCULAR_PHASE_TOTAL, CIRCULAR_SAMPLES, CONE_RADIUS, GAUSS_SIGMA, HAMMING_E,
    HAMMING_W,
};
pub use hex::{hex7_offsets, HEX19_POINTS};
pub(crate) use hex::{walk_hex19, walk_hex7};

/// Tent weights of a bed-of-nails filter with `n` samples per pixel and axis
/// (`2n` over the 2-pixel base): `w_k = 2n - |2k + 1 - 2n|`.
pub const fn tent_weight(n: usize, k: usize) -> u32 {
    let two_n = 2 * n as i64;
    (two_n - (2 * k as i64 + 1 - two_n).abs()) as u32
}

/// Sum of the tent weights of one axis: `2 n^2`.
pub const fn tent_sum(n: usize) -> u32 {
    let mut s = 0;
    let mut k = 0;
    while k < 2 * n {
        s += tent_weight(n, k);
        k += 1;
    }
    s
}

/// The weight of sample `(kx, ky)` of a bed-of-nails filter, `n` samples per
/// pixel and axis: the product of the two tent weights (in units of
/// `1 / (4 n^4)` of the filter's volume).
///
/// ```
/// use softedge::pixel_model::{sample_weight, tent_sum};
/// // The 4x4 filter of seed 000: corners 1, edges 3, centre 9.
/// assert_eq!([0, 1].map(|k| sample_weight(2, k, 0)), [1, 3]);
/// assert_eq!(sample_weight(2, 1, 1), 9);
/// assert_eq!(tent_sum(2), 8);
/// assert_eq!(tent_sum(4), 32);
/// ```
pub const fn sample_weight(n: usize, kx: usize, ky: usize) -> u32 {
    tent_weight(n, kx) * tent_weight(n, ky)
}

/// The unit of the models' weights: 4096 per pixel. Their tables
/// ([`HEX19_POINTS`], the circular filters') are published in it; the
/// band's scratch counts 16 times finer ([`COVER_ONE`](crate::COVER_ONE)),
/// so a weight is scaled by a shift when it is recorded.
pub const MODEL_ONE: i32 = 1 << 12;

/// Records a model's cover change (in [`MODEL_ONE`] units) in the band.
trait ModelCover {
    fn add_model_cover(&mut self, x: i32, y: i32, delta: i32);
}

impl<const C: usize> ModelCover for crate::band::BandBuffer<'_, C> {
    #[inline]
    fn add_model_cover(&mut self, x: i32, y: i32, delta: i32) {
        const SHIFT: u32 = crate::COVER_BITS - 12;
        self.add_cover(x, y, delta << SHIFT);
    }
}

/// The aliased walk of an edge given on a sample grid: `p0`, `p1` in 1/16
/// of a sample (a [`SubPoint`](crate::SubPoint) scaled by the samples per
/// pixel), rows in samples. Sample centres on a shared edge go to exactly
/// one shape (the top-left rule), so sampled meshes stay seamless.
pub(super) fn walk_samples<K: crate::edge::CoverSink>(
    p0: crate::SubPoint,
    p1: crate::SubPoint,
    rows: core::ops::Range<i32>,
    sink: &mut K,
) {
    let fine = |p: crate::SubPoint| crate::geom::FinePoint::from(p);
    if let Some(mut w) = crate::edge::AliasedWalk::new(fine(p0), fine(p1)) {
        w.walk(rows, sink);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Eq. 4 of seed 000 in integers: wherever a point falls, the weights
    /// of the four filters that hold it add to the same total.
    #[test]
    fn bed_of_nails_is_equal_energy() {
        for n in [2usize, 4] {
            let total = (2 * n * 2 * n) as u32;
            // A point on sample (kx, ky) of one filter is on sample
            // (kx ± n, ky ± n) of its neighbours.
            for kx in 0..n {
                for ky in 0..n {
                    let sum = sample_weight(n, kx, ky)
                        + sample_weight(n, kx + n, ky)
                        + sample_weight(n, kx, ky + n)
                        + sample_weight(n, kx + n, ky + n);
                    assert_eq!(sum, total, "n = {n}, sample ({kx}, {ky})");
                }
            }
        }
    }

    #[test]
    fn the_seed_conditions_hold() {
        // 4x4: a + 2b + c = const with a, b, c the corner, edge and centre
        // weights of one quadrant.
        let (a, b, c) = (
            sample_weight(2, 0, 0),
            sample_weight(2, 0, 1),
            sample_weight(2, 1, 1),
        );
        assert_eq!(a + 2 * b + c, 16);
        assert_eq!(tent_sum(2) * tent_sum(2), 64);
        assert_eq!(tent_sum(4) * tent_sum(4), 1024);
    }
}
