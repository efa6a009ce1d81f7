//! Coverage given pixel by pixel (a glyph's mask, `text::code`) into the
//! band's cover scratch.
//!
//! Takes one row of coverage values (coverage units, `0..=`
//! [`COVER_ONE`](crate::COVER_ONE) a pixel) starting at a frame pixel;
//! gives the scratch the changes of running coverage that sum to them: the
//! first pixel's value at its column, each next pixel's difference from
//! the one before, and the last pixel's value taken back right of it. The
//! sweep ([`compose`](super::BandBuffer::compose)) then sums them along
//! the row as it sums an outline's edges, so a mask is composed like any
//! shape (every paint, opacity and blend, in linear light), and masks and
//! walked edges written into the scratch before one compose are one shape.
//!
//! Only the scratch is written (never the accumulator). Clipping follows
//! [`add_cover`](super::BandBuffer::add_cover): a pixel left of the band is
//! not shown, so the row's first change inside the band is the value of
//! its first pixel there; pixels right of the band are dropped (and the
//! taking back with them: the sweep stops at the band's end). Splitting a
//! row into pieces written one after the other gives the same changes (the
//! taking back of one piece and the first value of the next add up to
//! their difference).

use super::{row_start, BandBuffer, ROW_HEAD};

impl<const C: usize> BandBuffer<'_, C> {
    /// Adds the coverage `covers` of frame pixels `x, x + 1, ...` of frame
    /// row `y` to the cover scratch, as changes (see [the module](self)).
    /// Rows outside the band are dropped. Per pixel a subtraction and an
    /// addition to the scratch (none where the value repeats).
    #[inline(never)] // one out-of-line loop per row; profiles name it
    pub(crate) fn add_mask_row(&mut self, x: i32, y: i32, covers: &[i32]) {
        let w = i32::from(self.band.width);
        let r = y.wrapping_sub(self.band.y0);
        if r < 0 || r >= i32::from(self.band.rows) {
            return;
        }
        // The band columns of the row's pixels, and the pixels in the band.
        let c = x.saturating_sub(self.band.x0);
        let n = covers.len().min(i32::MAX as usize) as i32;
        let (first, end) = (c.max(0), c.saturating_add(n).min(w));
        if first >= end {
            return;
        }
        let Some(shown) = covers.get((first - c) as usize..(end - c) as usize) else {
            return;
        };
        let w = w as usize;
        let start = row_start(r as usize, w);
        let Some([lo, hi, _, _, deltas @ ..]) = self.cover.get_mut(start..start + w + ROW_HEAD)
        else {
            return;
        };
        let (first, end) = (first as usize, end as usize);
        let mut prev = 0i32;
        if let Some(cells) = deltas.get_mut(first..end) {
            for (d, &v) in cells.iter_mut().zip(shown) {
                if v != prev {
                    *d = d.wrapping_add(v.wrapping_sub(prev));
                    prev = v;
                }
            }
        }
        // The last value taken back right of the last pixel (dropped at
        // the band's end, where the sweep stops anyway).
        let mut last = end - 1;
        if prev != 0 {
            if let Some(d) = deltas.get_mut(end) {
                *d = d.wrapping_sub(prev);
                last = end;
            }
        }
        *lo = (*lo).min(first as i32);
        *hi = (*hi).max(last as i32);
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::super::{Band, BandBuffer, ComposeOp, Coverage, Paint};
    use crate::style::{FillRule, Opacity};
    use crate::COVER_ONE;

    /// Writes mask rows into a band, composes white over black (one
    /// channel), and gives each pixel's accumulator over 4095: its
    /// coverage in coverage units.
    fn composed(band: Band, rows: &[(i32, i32, Vec<i32>)]) -> Vec<i32> {
        let (w, h) = (band.width, band.rows);
        let mut acc = std::vec![0i32; BandBuffer::<1>::acc_len(w, h)];
        let mut cover = std::vec![0i32; BandBuffer::<1>::cover_len(w, h)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([0]);
        for (x, y, covers) in rows {
            buf.add_mask_row(*x, *y, covers);
        }
        buf.compose(
            band.y0,
            band.y0 + i32::from(h),
            Coverage::Rule(FillRule::NonZero),
            &Paint::Flat([4095]),
            ComposeOp::Over(Opacity::OPAQUE),
        );
        let mut out = Vec::new();
        for y in band.row_range() {
            for x in band.column_range() {
                out.push(buf.raw(x, y).unwrap()[0] / 4095);
            }
        }
        // The sweep left the scratch empty for the next shape.
        assert!(cover.iter().enumerate().all(|(i, &v)| {
            let at = i % (usize::from(w) + 4);
            at < 4 || v == 0
        }));
        out
    }

    /// The reference: each pixel the sum of the rows' values over it,
    /// limited to one pixel (the nonzero rule on summed coverage).
    fn reference(band: Band, rows: &[(i32, i32, Vec<i32>)]) -> Vec<i32> {
        let mut out = Vec::new();
        for y in band.row_range() {
            for x in band.column_range() {
                let mut s: i64 = 0;
                for (rx, ry, covers) in rows {
                    if *ry == y && x >= *rx {
                        if let Some(&v) = covers.get((x - rx) as usize) {
                            s += i64::from(v);
                        }
                    }
                }
                out.push(s.min(i64::from(COVER_ONE)) as i32);
            }
        }
        out
    }

    #[test]
    fn mask_rows_compose_to_their_values_clipped_and_summed() {
        let mut rng = crate::path::testing::Lcg(0x0033_3a5c);
        for case in 0..600 {
            let x0 = if case % 2 == 0 { 0 } else { 7 };
            let band = Band {
                width: 1 + rng.below(12) as u16,
                y0: rng.below(4) as i32,
                rows: 1 + rng.below(3) as u16,
                x0,
            };
            let rows: Vec<(i32, i32, Vec<i32>)> = (0..1 + rng.below(4))
                .map(|_| {
                    let n = rng.below(9) as usize;
                    let covers = (0..n)
                        .map(|_| match rng.below(4) {
                            0 => 0,
                            1 => COVER_ONE,
                            _ => rng.below(COVER_ONE as u64 + 1) as i32,
                        })
                        .collect();
                    (x0 + rng.below(20) as i32 - 6, rng.below(8) as i32, covers)
                })
                .collect();
            assert_eq!(
                composed(band, &rows),
                reference(band, &rows),
                "case {case}: {band:?} {rows:?}"
            );
        }
    }

    #[test]
    fn a_row_split_in_pieces_gives_the_same_changes() {
        let band = Band::new(16, 0, 1);
        let whole = [3000, 65536, 65536, 100, 0, 0, 40000, 7];
        let one = composed(band, &[(2, 0, whole.to_vec())]);
        for cut in 0..=whole.len() {
            let (a, b) = whole.split_at(cut);
            let two = composed(band, &[(2, 0, a.to_vec()), (2 + cut as i32, 0, b.to_vec())]);
            assert_eq!(one, two, "cut at {cut}");
        }
    }
}
