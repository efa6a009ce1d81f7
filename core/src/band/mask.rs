//! Coverage given pixel by pixel (a glyph's mask, `text::code`) into the
//! band's cover scratch.
//!
//! Takes one row of coverage values (coverage units, `0..=`
//! [`COVER_ONE`](crate::COVER_ONE) a pixel) starting at a frame pixel, as
//! runs of one value (a glyph mask's code is runs: of empty and of whole
//! pixels, and single pixels); gives the scratch the changes of running
//! coverage that sum to them: the first pixel's value at its column, each
//! next value's difference from the one before, and the last value taken
//! back right of the row. The row's extent of changes covers the changes
//! written (no more), so the sweep visits only those columns. The
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

use super::{BandBuffer, ROW_HEAD};

impl<const C: usize> BandBuffer<'_, C> {
    /// Adds the coverage `covers` of frame pixels `x, x + 1, ...` of frame
    /// row `y` to the cover scratch, as changes (one pixel a run).
    #[cfg(test)]
    pub(crate) fn add_mask_row(&mut self, x: i32, y: i32, covers: &[i32]) {
        let mut k = 0usize;
        let n = covers.len().min(u32::MAX as usize) as u32;
        self.add_mask(x, y, n, 1, || {
            let v = covers.get(k).copied().unwrap_or(0);
            k += 1;
            (v, 1)
        });
    }

    /// The changes of frame row `y` for a mask row of `width` pixels from
    /// frame column `x`, when all of it and the column right of it lie
    /// inside the band: the `width + 1` change cells from the mask's first
    /// column on (empty changes, or what other shapes' edges put there:
    /// add to them). The row's extent of changes is widened to those
    /// columns. `None` for a row outside the band or a mask row not wholly
    /// inside its columns: write that one with [`add_mask`](Self::add_mask).
    #[inline]
    pub(crate) fn mask_row(&mut self, x: i32, y: i32, width: u32) -> Option<&mut [i32]> {
        let w = i32::from(self.band.width);
        let r = y.wrapping_sub(self.band.y0);
        let c = x.wrapping_sub(self.band.x0);
        if r < 0 || r >= i32::from(self.band.rows) || c < 0 || width >= (w - c) as u32 {
            return None;
        }
        let (r, c, n, w) = (r as usize, c as usize, width as usize, w as usize);
        let deltas = self.deltas.get_mut(r * w..r * w + w)?;
        let [lo, hi, _, _] = self
            .heads
            .get_mut(r * ROW_HEAD..r * ROW_HEAD + ROW_HEAD)?
            .first_chunk_mut::<ROW_HEAD>()?;
        *lo = (*lo).min(c as i32);
        *hi = (*hi).max((c + n) as i32);
        deltas.get_mut(c..c + n + 1)
    }

    /// Adds a mask of `height` rows of `width` pixels, its first at frame
    /// pixel `(x, y)`, given as runs of one value that go on across row
    /// ends: `next()` gives the next run (its coverage, and its length,
    /// at least one pixel), and is not called past the mask's last pixel
    /// in the band. Each run is one change where its value differs from
    /// the one before it in its row (so a run of empty or whole pixels
    /// costs one call); each row's last value is taken back after it.
    /// Rows above the band are passed over, rows below it not asked for.
    #[inline(never)] // one loop per glyph; profiles name it
    pub(crate) fn add_mask(
        &mut self,
        x: i32,
        y: i32,
        width: u32,
        height: u32,
        mut next: impl FnMut() -> (i32, u32),
    ) {
        let w = i32::from(self.band.width);
        let c0 = x.saturating_sub(self.band.x0);
        let r0 = y.saturating_sub(self.band.y0);
        let rows = i32::from(self.band.rows);
        // The run being written: its value and the pixels of it left.
        let (mut v, mut n) = (0i32, 0u32);
        for j in 0..height.min(i32::MAX as u32) as i32 {
            let r = r0.saturating_add(j);
            if r >= rows || width == 0 {
                return;
            }
            let mut left = width;
            if r < 0 {
                // Above the band: passed over.
                loop {
                    if n == 0 {
                        (v, n) = next();
                        n = n.max(1);
                    }
                    if n >= left {
                        n -= left;
                        break;
                    }
                    left -= n;
                    n = 0;
                }
                continue;
            }
            let (r, wu) = (r as usize, w as usize);
            let (Some(deltas), Some([lo, hi, _, _])) = (
                self.deltas.get_mut(r * wu..r * wu + wu),
                self.heads
                    .get_mut(r * ROW_HEAD..r * ROW_HEAD + ROW_HEAD)
                    .and_then(|h| h.first_chunk_mut::<ROW_HEAD>()),
            ) else {
                return;
            };
            // Band column of the next pixel: a change left of the band
            // goes to its first column (the pixels there are not shown:
            // the first one shown gets the sum of the changes up to it,
            // its own value), one right of it is dropped.
            let mut c = c0;
            let (mut first, mut last) = (i32::MAX, i32::MIN);
            let mut prev = 0i32;
            loop {
                if n == 0 {
                    (v, n) = next();
                    n = n.max(1);
                }
                if v != prev {
                    let k = c.max(0);
                    if let Some(d) = deltas.get_mut(k as usize) {
                        *d = d.wrapping_add(v.wrapping_sub(prev));
                        first = first.min(k);
                        last = k;
                    }
                    prev = v;
                }
                if n >= left {
                    n -= left;
                    c = c.saturating_add(left as i32);
                    break;
                }
                c = c.saturating_add(n as i32);
                left -= n;
                n = 0;
            }
            if prev != 0 {
                let k = c.max(0);
                if let Some(d) = deltas.get_mut(k as usize) {
                    *d = d.wrapping_sub(prev);
                    first = first.min(k);
                    last = k;
                }
            }
            if first <= last {
                *lo = (*lo).min(first);
                *hi = (*hi).max(last.min(w - 1));
            }
        }
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
        composed_with(band, |buf| {
            for (x, y, covers) in rows {
                buf.add_mask_row(*x, *y, covers);
            }
        })
    }

    /// What `write` puts in the scratch, composed (see `composed`).
    fn composed_with(band: Band, write: impl FnOnce(&mut BandBuffer<'_, 1>)) -> Vec<i32> {
        let (w, h) = (band.width, band.rows);
        let mut acc = std::vec![0i32; BandBuffer::<1>::acc_len(w, h)];
        let mut cover = std::vec![0i32; BandBuffer::<1>::cover_len(w, h)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([0]);
        write(&mut buf);
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
        // (The changes are the scratch's first `w * h` words.)
        let changes = usize::from(w) * usize::from(h);
        assert!(cover[..changes].iter().all(|&v| v == 0));
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
    fn a_mask_given_as_runs_across_rows_is_its_rows() {
        let mut rng = crate::path::testing::Lcg(0x0033_a5c5);
        for case in 0..400 {
            let band = Band {
                width: 1 + rng.below(10) as u16,
                y0: rng.below(4) as i32,
                rows: 1 + rng.below(4) as u16,
                x0: if case % 2 == 0 { 0 } else { 5 },
            };
            let (w, h) = (rng.below(7) as usize, 1 + rng.below(6) as usize);
            let px: Vec<i32> = (0..w * h)
                .map(|_| match rng.below(3) {
                    0 => 0,
                    1 => COVER_ONE,
                    _ => rng.below(COVER_ONE as u64 + 1) as i32,
                })
                .collect();
            let (x, y) = (band.x0 + rng.below(16) as i32 - 5, rng.below(9) as i32);
            let rows: Vec<(i32, i32, Vec<i32>)> = (0..h)
                .map(|j| (x, y + j as i32, px[j * w..(j + 1) * w].to_vec()))
                .collect();
            let want = composed(band, &rows);
            // The same pixels as runs of equal values, across row ends.
            let mut runs: Vec<(i32, u32)> = Vec::new();
            for &v in &px {
                match runs.last_mut() {
                    Some((u, n)) if *u == v && rng.below(3) != 0 => *n += 1,
                    _ => runs.push((v, 1)),
                }
            }
            let got = composed_with(band, |buf| {
                let mut it = runs.iter().copied();
                buf.add_mask(x, y, w as u32, h as u32, || it.next().unwrap_or((0, 1)));
            });
            assert_eq!(got, want, "case {case}: {band:?} at ({x}, {y}), {w} x {h}");
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
