//! Whole pixels stored into the band: what an embedded-graphics drawing
//! (text in a mono font, an image, an aliased primitive) puts on the
//! canvas, composed in painter's order as an opaque pixel.
//!
//! A stored span is tagged with its colour's palette entry (see
//! `band::tags`).

use super::sweep::Flat;
use super::tags;
use super::BandBuffer;
use crate::COVER_BITS;

impl<const C: usize> BandBuffer<'_, C> {
    /// Replaces frame pixel `(x, y)` by the linear colour `lin` (dropped
    /// outside the band).
    #[inline]
    pub(crate) fn store_pixel(&mut self, x: i32, y: i32, lin: [u16; C]) {
        self.store_span(x, x.saturating_add(1), y, lin);
    }

    /// Replaces the frame pixels `x0..x1` of row `y` by `lin` (clipped to
    /// the band).
    pub(crate) fn store_span(&mut self, x0: i32, x1: i32, y: i32, lin: [u16; C]) {
        let cols = self.band.column_range();
        let (lo, hi) = (x0.max(cols.start), x1.min(cols.end));
        let Some(r) = self.row_of(y) else {
            return;
        };
        if lo >= hi {
            return;
        }
        let w = usize::from(self.band.width);
        let (c0, c1) = ((lo - cols.start) as usize, (hi - cols.start) as usize);
        let f = lin.map(|v| i32::from(v.min(crate::LIN_MAX)) << COVER_BITS);
        let n = tags::row_words(w);
        let tag = self.flat_tag(&f);
        let flat = Flat {
            f,
            tag,
            dense: self.palette.dense,
        };
        if let (Some(acc), Some(words)) = (
            self.acc.get_mut(r * w * C..(r + 1) * w * C),
            self.tags.get_mut(r * n..r * n + n),
        ) {
            flat.whole(acc, words, c0, c1);
        }
        self.mark(r, c0, c1);
    }
}
