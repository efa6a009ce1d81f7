//! The depth-tested sweeps: one primitive's pixels composited against the
//! band's depth buffer (the z-buffer of seed 004 with anti-aliased edges;
//! the method and its passes are described in [`hsr`](crate::hsr)).
//!
//! The walk has left the primitive's whole coverage in the cover scratch
//! (edge pixels as pairs of changes), so a running sum along the row gives
//! each pixel's coverage `S`; Gouraud intensity and depth step by one
//! addition per pixel. Compositing "under" what the pixel holds,
//! `s = min(S, full - K)`, `acc += (I - bg) * s`, `K += s`, costs one
//! multiply per channel where `s` is not a whole pixel (a shift where it is).

use super::BandBuffer;
use super::{DepthBuffer, SampleEdges, ZPass, ALL_SAMPLES, FULL, FULL_BITS};
use crate::shade::DepthPlane;
use crate::shade::{Plane, PLANE_FRAC};
use crate::COVER_BITS;

impl<const C: usize> BandBuffer<'_, C> {
    /// Composites the primitive whose edges were just walked (coverage only)
    /// over frame rows `y_lo..y_hi` against `zbuf` as `pass` says, and
    /// clears the scratch. `slope` is the primitive's depth change across
    /// one pixel (`|dz/dx| + |dz/dy|`, rounded up).
    #[inline(never)] // kept out of line so profiles can name it
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn sweep_depth(
        &mut self,
        y_lo: i32,
        y_hi: i32,
        plane: &Plane<C>,
        zplane: &DepthPlane,
        slope: u16,
        samples: Option<&SampleEdges>,
        zbuf: &mut DepthBuffer<'_>,
        pass: ZPass,
    ) {
        let w = usize::from(self.band.width);
        let bg = self.background.map(|b| i32::from(b) << COVER_BITS);
        let full = i32::from(FULL);
        let y_band = self.band.y0;
        for (y, mut row) in self.sweep_rows(y_lo, y_hi) {
            let dense = row.dense;
            let r = (y - y_band) as usize;
            let (lo, hi) = (row.lo, row.hi);
            let deltas = &mut *row.deltas;
            let Some((zrow, krow, mrow)) = zbuf.row_mut(r) else {
                // Clear what the walk left, even without a depth row.
                deltas.iter_mut().for_each(|d| *d = 0);
                continue;
            };
            let row_acc = &mut *row.acc;
            // Row setup: the only multiplies outside partly covered pixels.
            let mut v = plane.at(lo as i32, y);
            let mut zf = zplane.at(lo as i32, y);
            let mut e = samples.map(|s| s.at(lo as i32, y)).unwrap_or_default();
            let mut c: i32 = 0;
            let mut drawn_end = lo;
            for x in lo..w {
                if x <= hi {
                    c += deltas.get_mut(x).map_or(0, core::mem::take);
                } else if c == 0 {
                    break;
                }
                // The winding integral's size, in the depth buffer's 1/32768 px.
                let s_px = ((c.unsigned_abs() >> (COVER_BITS - FULL_BITS)) as i32).min(full);
                if s_px > 0 {
                    drawn_end = x + 1;
                    // What the composite may change is no palette colour;
                    // its value below it is its entry's (see `band::tags`).
                    let px = row_acc
                        .get_mut(x * C..x * C + C)
                        .and_then(|p| p.first_chunk_mut::<C>());
                    if let (false, Some(px)) = (dense, px) {
                        super::tags::take(px, row.tags, row.palette, x);
                    }
                    let z = zplane.depth(zf);
                    if let (Some(px), Some(zd), Some(k), Some(mk)) = (
                        row_acc.get_mut(x * C..x * C + C),
                        zrow.get_mut(x),
                        krow.get_mut(x),
                        mrow.get_mut(x),
                    ) {
                        // What the pass does with this pixel: `None` skips
                        // it, `Some(true)` replaces it, `Some(false)`
                        // composites under it.
                        let action = match pass {
                            ZPass::Single => Some(s_px == full && z > *zd),
                            ZPass::Centres => {
                                // The nearest fragment touching the pixel,
                                // less its slope across a pixel, is the
                                // threshold (issue #18: with the surface at
                                // the centre alone, a pixel whose centre no
                                // surface covers sent every fragment to the
                                // front pass, hidden ones too).
                                let t = z.saturating_sub(slope);
                                if t > *zd {
                                    *zd = t;
                                }
                                None
                            }
                            ZPass::Front => (z.saturating_add(slope) >= *zd).then_some(false),
                            ZPass::Back => (z.saturating_add(slope) < *zd).then_some(false),
                        };
                        match action {
                            Some(true) => {
                                for ch in 0..C {
                                    let lit = (v[ch] >> (PLANE_FRAC - COVER_BITS)) as i32;
                                    px[ch] = bg[ch].saturating_add(lit);
                                }
                                *k = FULL;
                                *zd = z;
                            }
                            Some(false) => {
                                // The fragment's samples (issue #18; see
                                // `share`), only where the pass draws it.
                                let (m, near) = match samples {
                                    _ if s_px == full => (ALL_SAMPLES, ALL_SAMPLES),
                                    Some(se) => se.masks(&e, x as i32, y),
                                    None => (0, 0),
                                };
                                let s = share(s_px, i32::from(*k), m, near, *mk, pass);
                                if s > 0 {
                                    for ch in 0..C {
                                        let add = (v[ch] * i64::from(s)) >> FULL_BITS;
                                        px[ch] = px[ch].saturating_add(add as i32);
                                    }
                                    *k += s as u16;
                                    *mk |= m;
                                    if pass == ZPass::Single && z > *zd {
                                        *zd = z;
                                    }
                                }
                            }
                            None => {}
                        }
                    }
                }
                for ch in 0..C {
                    v[ch] += i64::from(plane.gx[ch]);
                }
                zf += zplane.gx;
                if let Some(se) = samples {
                    se.step(&mut e);
                }
            }
            row.mark(lo, drawn_end);
        }
    }
}

/// How much of a fragment of coverage `s` (sample mask `m`, near-sample
/// mask `near`) to composite into a pixel that nearer fragments claim `k`
/// of (samples `claimed`), in coverage units.
///
/// The count alone (before issue #18) gave `min(s, 1 - k)`: right when the
/// fragment covers the room left (a silhouette over a farther surface),
/// wrong when it lies under what is claimed (a hidden fragment in a pixel
/// one surface holds). The visible part always lies between `lo = max(0,
/// s - k)` and `hi = min(s, 1 - k)`; the samples choose:
///
/// - every sample of the fragment claimed: it lies under them, `lo` (0 for
///   a fragment wholly under a nearer one). A sliver between the samples
///   (`m = 0`) is judged by the samples near it, and only behind the
///   threshold (in front of it, it may be a mesh neighbour's, whose near
///   samples the triangle next to it claims);
/// - every unclaimed sample in the fragment: it covers the room, `hi`;
/// - between: the share of its samples that are unclaimed, `s |m \ claimed|
///   / |m|`, within `lo..=hi`;
/// - a whole pixel, or a pixel whose samples are all claimed (the room is a
///   sliver no sample sees, which a farther surface may fill): `hi`.
fn share(s: i32, k: i32, m: u16, near: u16, claimed: u16, pass: ZPass) -> i32 {
    let full = i32::from(FULL);
    let (lo, hi) = ((s - k).max(0), s.min(full - k));
    if s >= full || claimed == ALL_SAMPLES {
        return hi;
    }
    let unclaimed = !claimed;
    if m == 0 {
        if pass != ZPass::Back {
            return hi;
        }
        return weighted(s, near & unclaimed, near).max(lo).min(hi);
    }
    let seen = m & unclaimed;
    if seen == 0 {
        lo
    } else if unclaimed & !m == 0 {
        hi
    } else {
        // max / min, not clamp: lo <= hi always holds, but clamp's check
        // of it would be a panic path (the no-panic firmware build).
        weighted(s, seen, m).max(lo).min(hi)
    }
}

/// `s * weight(part) / weight(whole)` (`part` within `whole`; 0 for an
/// empty `whole`): below `2^15 * 2^10 = 2^25`, in `u32`.
fn weighted(s: i32, part: u16, whole: u16) -> i32 {
    let num = s.unsigned_abs() * sample_weight(part);
    num.checked_div(sample_weight(whole)).unwrap_or(0) as i32
}

/// The area a mask's samples stand for: each sample the part of the pixel
/// nearer to it than to the others (columns and rows 2.5, 5.5, 5.5, 2.5
/// sixteenths wide, times two: 5, 11, 11, 5), so a whole pixel is
/// `32 * 32 = 1024`.
fn sample_weight(mask: u16) -> u32 {
    const SIDE: [u32; 4] = [5, 11, 11, 5];
    let mut w = 0;
    let mut bit = 0;
    for row in SIDE {
        for col in SIDE {
            if mask & (1 << bit) != 0 {
                w += row * col;
            }
            bit += 1;
        }
    }
    w
}
