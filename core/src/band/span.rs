//! The span sweep: interior pixels of one primitive, from the cover scratch.
//!
//! Per row, a running cover `c` (the sum of the cover changes met so far,
//! exact integers) times the Gouraud intensity is added to every pixel.
//! `I * c` is set up with one multiply where `c` changes (once per span);
//! along the span it steps by the constant `g_x * c`: one addition per
//! pixel. The sweep visits a row from its first cover change to its last
//! (or to the band's right end while cover remains, for primitives running
//! off the right of the band), and clears what it reads for the next
//! primitive.

use super::BandBuffer;
use crate::shade::{Plane, PLANE_FRAC};

impl<const C: usize> BandBuffer<'_, C> {
    /// Adds the spans of the primitive whose edges were just walked over
    /// frame rows `y_lo..y_hi` (clipped here to the band), and clears the
    /// scratch there.
    #[inline(never)] // kept out of line so profiles can name it
    pub(crate) fn sweep(&mut self, y_lo: i32, y_hi: i32, plane: &Plane<C>) {
        let w = usize::from(self.band.width);
        let y_lo = y_lo.max(self.band.y0);
        let y_hi = y_hi.min(self.band.y0 + i32::from(self.band.rows));
        let gx = plane.gx.map(i64::from);
        for y in y_lo..y_hi {
            let r = (y - self.band.y0) as usize;
            let scratch = r * (w + 2);
            let Some(ext) = self.cover.get_mut(scratch + w..scratch + w + 2) else {
                continue;
            };
            let (lo, hi) = (
                core::mem::replace(&mut ext[0], i32::MAX),
                core::mem::replace(&mut ext[1], i32::MIN),
            );
            if lo > hi {
                continue;
            }
            let (lo, hi) = (lo.max(0) as usize, (hi.max(0) as usize).min(w - 1));
            let mut c: i64 = 0;
            let mut v = [0i64; C];
            let mut dv = [0i64; C];
            // Per-row setup: the plane at the first pixel of the sweep.
            let mut i_here = plane.at(lo as i32, y);
            let mut x = lo;
            while x < w && (x <= hi || c != 0) {
                let d = match self.cover.get_mut(scratch + x) {
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
                    let k = (r * w + x) * C;
                    if let Some(px) = self.acc.get_mut(k..k + C) {
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
                x += 1;
            }
        }
    }
}
