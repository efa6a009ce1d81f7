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
use crate::hsr::{DepthBuffer, DepthPlane, ZPass, FULL, FULL_BITS};
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
        zbuf: &mut DepthBuffer<'_>,
        pass: ZPass,
    ) {
        let w = usize::from(self.band.width);
        let bg = self.background.map(|b| i32::from(b) << COVER_BITS);
        let full = i32::from(FULL);
        for y in self.rows_in_band(y_lo, y_hi) {
            let r = (y - self.band.y0) as usize;
            let Some(mut row) = super::take_row(self.cover, r, w) else {
                continue;
            };
            let (lo, hi) = (row.lo, row.hi);
            let deltas = &mut *row.deltas;
            let (Some(row_acc), Some((zrow, krow))) = (
                self.acc.get_mut(r * w * C..(r + 1) * w * C),
                zbuf.row_mut(r),
            ) else {
                // Clear what the walk left, even without a depth row.
                deltas.iter_mut().for_each(|d| *d = 0);
                continue;
            };
            // Row setup: the only multiplies outside partly covered pixels.
            let mut v = plane.at(lo as i32, y);
            let mut zf = zplane.at(lo as i32, y);
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
                    let z = zplane.depth(zf);
                    if let (Some(px), Some(zd), Some(k)) = (
                        row_acc.get_mut(x * C..x * C + C),
                        zrow.get_mut(x),
                        krow.get_mut(x),
                    ) {
                        // What the pass does with this pixel: `None` skips
                        // it, `Some(true)` replaces it, `Some(false)`
                        // composites under it.
                        let action = match pass {
                            ZPass::Single => Some(s_px == full && z > *zd),
                            ZPass::Centres => {
                                // Aliased coverage: whole pixels only.
                                if s_px == full && z > *zd {
                                    *zd = z;
                                    *k = slope;
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
                                let s = s_px.min(full - i32::from(*k));
                                if s > 0 {
                                    for ch in 0..C {
                                        let add = (v[ch] * i64::from(s)) >> FULL_BITS;
                                        px[ch] = px[ch].saturating_add(add as i32);
                                    }
                                    *k += s as u16;
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
            }
            row.mark(lo, drawn_end);
        }
    }
}
