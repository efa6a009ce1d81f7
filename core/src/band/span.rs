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
        let gx = plane.gx.map(i64::from);
        for y in self.rows_in_band(y_lo, y_hi) {
            let r = (y - self.band.y0) as usize;
            let Some((deltas, lo, hi)) = super::take_row(self.cover, r, w) else {
                continue;
            };
            let Some(row_acc) = self.acc.get_mut(r * w * C..(r + 1) * w * C) else {
                continue;
            };
            let mut c: i64 = 0;
            let mut x = lo;
            loop {
                c += deltas
                    .get_mut(x)
                    .map_or(0, |d| i64::from(core::mem::take(d)));
                // The span runs to the next cover change, or to the band's
                // end if cover remains after the last one.
                let mut next = x + 1;
                while next <= hi && deltas.get(next) == Some(&0) {
                    next += 1;
                }
                let end = if next > hi && c != 0 { w } else { next };
                if c != 0 {
                    // Span setup: the only multiplies of the sweep.
                    let i0 = plane.at(x as i32, y);
                    let mut v = [0i64; C];
                    let mut dv = [0i64; C];
                    for ch in 0..C {
                        v[ch] = i0[ch] * c;
                        dv[ch] = gx[ch] * c;
                    }
                    let span = row_acc.get_mut(x * C..end * C).unwrap_or_default();
                    for px in span.chunks_exact_mut(C) {
                        for ch in 0..C {
                            px[ch] = px[ch].saturating_add((v[ch] >> PLANE_FRAC) as i32);
                            v[ch] += dv[ch];
                        }
                    }
                }
                if next > hi {
                    break;
                }
                x = next;
            }
        }
    }
}
