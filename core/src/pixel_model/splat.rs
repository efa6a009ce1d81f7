//! One sample row's cover change, spread over the pixels whose footprints
//! hold that row: the inner step shared by the 19-point hexagonal pixel and
//! the circular filters.
//!
//! A pixel `p`'s footprint in one sample row is `L` consecutive fine
//! columns starting at `n p + o` (`n` fine columns per pixel), with weights
//! `w_0 .. w_{L-1}`. The row is given as its suffix sums
//! `cum[t] = w_t + ... + w_{L-1}` (`cum[0]` the row's total, `cum[L] = 0`),
//! the weight of the samples right of a cut `t` columns into the footprint.
//! When the aliased walk reports that samples from fine column `c` on are
//! covered (cover change of sign `s`), the pixels whose footprints lie
//! wholly right of `c` gain `s * cum[0]` (carried by the span sweep), and
//! each pixel whose footprint `c` cuts gains `s * cum[t]` for itself only;
//! written as the differences between neighbouring pixels' shares, that is
//! one cover change per pixel. Per call: one shift (`n` is a power of
//! two) and at most `1 + ceil(L / n)` table look-ups and cover adds.
//! Values stay within `±2 cum[0] <= ±2 COVER_ONE`: nothing overflows.

use super::ModelCover;
use core::ops::Range;

use crate::band::BandBuffer;

/// The footprint of every pixel in one sample row: fine columns
/// `n p + o .. n p + o + L` with `n = 2^shift`, weights given by their
/// suffix sums `cum` (length `L + 1`).
#[derive(Clone, Copy)]
pub(super) struct RowFootprint<'a> {
    /// `log2` of the fine columns per pixel.
    pub shift: u32,
    /// First fine column of pixel 0's footprint.
    pub o: i64,
    /// Suffix sums of the weights.
    pub cum: &'a [u16],
}

/// Spreads a cover change of sign `sign` at fine column `c` over the
/// pixels of row `j` (if `j` is in `rows`).
#[inline]
pub(super) fn splat_row<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    rows: &Range<i32>,
    j: i32,
    c: i64,
    sign: i32,
    fp: RowFootprint<'_>,
) {
    let RowFootprint { shift, o, cum } = fp;
    if !rows.contains(&j) || shift > 8 {
        return;
    }
    let n = 1i64 << shift;
    let len = cum.len() as i64 - 1;
    let total = i32::from(cum.first().copied().unwrap_or(0));
    // First pixel whose footprint starts at or right of c: ceil((c - o) / n)
    // (an arithmetic shift floors, also below zero).
    let p_full = (c - o + n - 1) >> shift;
    // Pixel p's share is v_p = cum[t], t = c - (n p + o) (0 once t >= L),
    // for the pixels left of p_full, and `total` from p_full on. Written as
    // the differences v_p - v_{p-1}, one cover change per pixel.
    let reach = (len + n - 1) >> shift;
    let mut prev = 0;
    for p in p_full - reach..p_full {
        let t = c - ((p << shift) + o);
        let v = if t < len {
            sign * i32::from(cum.get(t as usize).copied().unwrap_or(0))
        } else {
            0
        };
        if v != prev {
            band.add_model_cover(p as i32, j, v - prev);
            prev = v;
        }
    }
    if sign * total != prev {
        band.add_model_cover(p_full as i32, j, sign * total - prev);
    }
}

/// Suffix sums of a footprint row: `out[t] = w[t] + ... + w[L-1]`,
/// `out[L] = 0` (`L1 = L + 1`).
pub(super) const fn suffix_sums<const L: usize, const L1: usize>(w: [i32; L]) -> [u16; L1] {
    let mut out = [0u16; L1];
    let mut t = L;
    let mut acc = 0;
    while t > 0 {
        t -= 1;
        acc += w[t];
        if t < L1 {
            out[t] = acc as u16;
        }
    }
    out
}
