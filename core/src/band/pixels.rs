//! Whole pixels stored into the band: what an embedded-graphics drawing
//! (text in a mono font, an image, an aliased primitive) puts on the
//! canvas, composed in painter's order as an opaque pixel.

use super::BandBuffer;
use crate::COVER_BITS;

impl<const C: usize> BandBuffer<'_, C> {
    /// Replaces frame pixel `(x, y)` by the linear colour `lin` (dropped
    /// outside the band).
    #[inline]
    pub(crate) fn store_pixel(&mut self, x: i32, y: i32, lin: [u16; C]) {
        let Some(k) = self.index(x, y) else {
            return;
        };
        if let Some(px) = self.acc.get_mut(k..k + C) {
            for (a, v) in px.iter_mut().zip(lin) {
                *a = i32::from(v.min(crate::LIN_MAX)) << COVER_BITS;
            }
        }
        let w = usize::from(self.band.width);
        let (r, c) = ((k / C) / w, (k / C) % w);
        self.mark(r, c, c + 1);
    }

    /// Replaces the frame pixels `x0..x1` of row `y` by `lin` (clipped to
    /// the band).
    pub(crate) fn store_span(&mut self, x0: i32, x1: i32, y: i32, lin: [u16; C]) {
        let cols = self.band.column_range();
        let (lo, hi) = (x0.max(cols.start), x1.min(cols.end));
        let Ok(r) = usize::try_from(y.wrapping_sub(self.band.y0)) else {
            return;
        };
        if lo >= hi || r >= usize::from(self.band.rows) {
            return;
        }
        let w = usize::from(self.band.width);
        let (c0, c1) = ((lo - cols.start) as usize, (hi - cols.start) as usize);
        let v = lin.map(|v| i32::from(v.min(crate::LIN_MAX)) << COVER_BITS);
        if let Some(row) = self.acc.get_mut((r * w + c0) * C..(r * w + c1) * C) {
            for px in row.chunks_mut(C) {
                if let Ok(px) = <&mut [i32; C]>::try_from(px) {
                    *px = v;
                }
            }
        }
        self.mark(r, c0, c1);
    }
}
