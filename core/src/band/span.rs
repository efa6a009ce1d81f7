//! The span sweep: interior pixels of one primitive, from the cover scratch.
//!
//! Per row, a running cover `c` (the sum of the cover changes met so far,
//! exact integers) times the Gouraud intensity is added to every pixel.
//! `I * c` is set up with one multiply where `c` changes (once per span);
//! along the span it steps by the constant `g_x * c`: one addition per
//! pixel. Reading the scratch clears it for the next primitive.

use super::BandBuffer;
use crate::shade::{Plane, PLANE_FRAC};

impl<const C: usize> BandBuffer<'_, C> {
    /// Adds the spans of the primitive whose edges were just walked, over
    /// frame columns `x_lo..=x_hi` and rows `y_lo..y_hi` (clipped here to
    /// the band), and clears the scratch there.
    pub(crate) fn sweep(&mut self, x_lo: i32, x_hi: i32, y_lo: i32, y_hi: i32, plane: &Plane<C>) {
        let w = i32::from(self.band.width);
        let x_lo = x_lo.max(0);
        let x_hi = x_hi.min(w - 1);
        let y_lo = y_lo.max(self.band.y0);
        let y_hi = y_hi.min(self.band.y0 + i32::from(self.band.rows));
        if x_lo > x_hi {
            return;
        }
        let gx = plane.gx.map(i64::from);
        for y in y_lo..y_hi {
            let r = (y - self.band.y0) as usize;
            let row_start = r * w as usize;
            let mut c: i64 = 0;
            let mut v = [0i64; C];
            let mut dv = [0i64; C];
            // Per-row setup: the plane at the first pixel of the sweep.
            let mut i_here = plane.at(x_lo, y);
            for x in x_lo..=x_hi {
                let k = row_start + x as usize;
                let d = match self.cover.get_mut(k) {
                    Some(d) => core::mem::take(d),
                    None => 0,
                };
                if d != 0 {
                    // A new span: the only multiplies of the sweep.
                    c += i64::from(d);
                    for ch in 0..C {
                        v[ch] = i_here[ch] * c;
                        dv[ch] = gx[ch] * c;
                    }
                }
                if c != 0 {
                    if let Some(px) = self.acc.get_mut(k * C..k * C + C) {
                        for ch in 0..C {
                            px[ch] = px[ch].saturating_add((v[ch] >> PLANE_FRAC) as i32);
                        }
                    }
                    for ch in 0..C {
                        v[ch] += dv[ch];
                    }
                }
                for ch in 0..C {
                    i_here[ch] += gx[ch];
                }
            }
        }
    }
}
