//! The bed-of-nails walk: aliased sampling on the fine grid, distributed to
//! the pixels' tent weights (see the module docs). Per sample row: table
//! look-ups and additions.

use super::ModelCover;
use core::ops::Range;

use super::walk_samples;
use super::MODEL_ONE as COVER_ONE;
use super::{tent_sum, tent_weight};
use crate::arith::{div_ceil, div_floor};
use crate::band::BandBuffer;
use crate::edge::CoverSink;
use crate::SubPoint;

/// `CUM[t] = sum of w_k for k in t..2n`: the weight of the samples right of
/// a cut `t` samples into a base (`t = 0`: all, `t = 2n`: none).
const fn cumulative<const L: usize>(n: usize) -> [i32; L] {
    let mut out = [0i32; L];
    let mut t = 2 * n;
    let mut acc = 0i32;
    loop {
        if t < L {
            out[t] = acc;
        }
        if t == 0 {
            break;
        }
        t -= 1;
        acc += tent_weight(n, t) as i32;
    }
    out
}

const CUM_2: [i32; 5] = cumulative::<5>(2);
const CUM_4: [i32; 9] = cumulative::<9>(4);

/// Walks edge `p0 -> p1` of a primitive for the `n x n` bed-of-nails model
/// (`n` = 2 or 4), writing coverage changes for pixel `rows` into the band.
pub(crate) fn walk_bed_of_nails<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    p0: SubPoint,
    p1: SubPoint,
    n: usize,
    rows: Range<i32>,
) {
    let scale = n as i32;
    let fine = |p: SubPoint| SubPoint::new(p.x.saturating_mul(scale), p.y.saturating_mul(scale));
    // Sample rows that lie in the bases of the pixel rows.
    let half = scale / 2;
    let fine_rows = rows.start.saturating_mul(scale) - half..rows.end.saturating_mul(scale) + half;
    let mut sink = Distribute { band, n, rows };
    walk_samples(fine(p0), fine(p1), fine_rows, &mut sink);
}

/// Turns the fine grid's cover changes into pixel coverage.
struct Distribute<'a, 'b, const C: usize> {
    band: &'a mut BandBuffer<'b, C>,
    n: usize,
    rows: Range<i32>,
}

impl<const C: usize> CoverSink for Distribute<'_, '_, C> {
    fn cover(&mut self, c: i32, r: i32, delta: i32) {
        let sign = delta.signum();
        let n = self.n as i64;
        let half = n / 2;
        let (c, r) = (i64::from(c), i64::from(r));
        // Coverage units per unit of sample weight: 4096 / (2 n^2)^2.
        let per_weight = div_floor(
            i64::from(COVER_ONE),
            i64::from(tent_sum(self.n)) * i64::from(tent_sum(self.n)),
        );
        let cum: &[i32] = if self.n == 2 { &CUM_2 } else { &CUM_4 };
        // Base of pixel p along an axis: fine indices [n p - n/2, n p + 3n/2).
        let j_hi = div_floor(r + half, n);
        for j in [j_hi - 1, j_hi] {
            let k = r - (n * j - half);
            if !(0..2 * n).contains(&k) || !self.rows.contains(&(j as i32)) {
                continue;
            }
            let unit = i64::from(sign) * i64::from(tent_weight(self.n, k as usize)) * per_weight;
            // Pixels whose base lies wholly right of c: full horizontal weight.
            let p_full = div_ceil(c + half, n);
            self.band.add_model_cover(
                p_full as i32,
                j as i32,
                (unit * i64::from(tent_sum(self.n))) as i32,
            );
            // The pixels whose base c cuts: their share, for that pixel only.
            for p in p_full - 2..p_full {
                let t = c - (n * p - half);
                if t > 0 && t < 2 * n {
                    let v = (unit * i64::from(cum.get(t as usize).copied().unwrap_or(0))) as i32;
                    self.band.add_model_cover(p as i32, j as i32, v);
                    self.band.add_model_cover(p as i32 + 1, j as i32, -v);
                }
            }
        }
    }
}
