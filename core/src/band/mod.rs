//! Band accumulation: `I_acc += I * S` over the primitives of one band of rows.
//!
//! Takes edge-pixel values and cover changes from the [`edge`](crate::edge)
//! walker and the Gouraud plane of each primitive; gives linear 12-bit
//! intensities per pixel at [`BandBuffer::lin12`] / [`BandBuffer::resolve_row`].
//! Implements seed 000, eqs. 2-3: each pixel accumulates
//! `I_acc(j) = I_acc(j-1) + I_j * S_j` over the polygons drawn into it, so
//! polygons sharing an edge add up to exactly full coverage.
//!
//! ## The frame in bands
//!
//! A frame of `width x height` pixels is drawn as bands of `rows` rows
//! ([`Bands`]); a band is a window `[y0, y0 + rows)` of frame rows. Every
//! primitive is drawn into every band it touches; the walk of an edge is
//! started directly at the band's first row from exact (quotient, remainder)
//! state, so a pixel gets the very same bits whatever the band height.
//! A band may lie partly or wholly outside the frame: its rows then simply
//! receive whatever primitives cover them (nothing is written outside the
//! caller's buffers).
//!
//! ## Units and why `i32`
//!
//! A pixel holds, per channel, `bg * 4096 + sum((I - bg) * S)` where `I` is
//! linear 12-bit intensity, `S` coverage in 1/4096 of a pixel
//! ([`COVER_ONE`](crate::COVER_ONE)) and `bg` the band's background. Drawing
//! each primitive relative to the background makes the background show
//! exactly through the uncovered fraction `1 - sum(S)` with no multiply at
//! resolve. A full pixel is `4095 * 4096 < 2^24`; `i32` keeps the signed
//! per-edge terms (an edge's contribution is an area on one side of it, the
//! other side's edge takes it back) and room for 127 overlapping
//! full-intensity primitives; beyond that, additions saturate instead of
//! wrapping and the pixel resolves to the channel's limit (documented
//! clipping). `u16` cannot hold the fraction bits that make the seam test
//! exact: rounding happens once, in [`BandBuffer::lin12`].
//!
//! The second buffer, `cover`, is scratch for one primitive at a time: the
//! edge walker writes the change of "cover" (coverage carried to the pixels
//! right of an edge) into it and the span sweep reads it back and clears it.

mod span;
mod zsweep;

use crate::shade::LIN_MAX;
use crate::COVER_BITS;

/// Largest band width and frame height handled, in pixels.
pub const MAX_WIDTH: u16 = 2048;

/// One band: the frame rows `[y0, y0 + rows)`, `width` pixels wide.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Band {
    /// Width of the frame in pixels.
    pub width: u16,
    /// First frame row of the band.
    pub y0: i32,
    /// Number of rows.
    pub rows: u16,
}

/// The bands of a frame, top to bottom; the last one may be shorter.
///
/// ```
/// use softedge::Bands;
/// let rows: Vec<_> = Bands::new(240, 20, 8).map(|b| (b.y0, b.rows)).collect();
/// assert_eq!(rows, [(0, 8), (8, 8), (16, 4)]);
/// ```
#[derive(Debug, Clone)]
pub struct Bands {
    width: u16,
    height: u16,
    rows: u16,
    next: u16,
}

impl Bands {
    /// Bands of `rows` rows (at least 1) covering `height` rows.
    pub fn new(width: u16, height: u16, rows: u16) -> Self {
        Self {
            width,
            height,
            rows: rows.max(1),
            next: 0,
        }
    }
}

impl Iterator for Bands {
    type Item = Band;
    fn next(&mut self) -> Option<Band> {
        if self.next >= self.height {
            return None;
        }
        let rows = self.rows.min(self.height - self.next);
        let band = Band {
            width: self.width,
            y0: i32::from(self.next),
            rows,
        };
        self.next += rows;
        Some(band)
    }
}

/// Why a band buffer could not be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum BandError {
    /// Width or rows is zero, the width is over [`MAX_WIDTH`], or `y0` is
    /// outside the coordinate range.
    BadBand,
    /// `acc` is shorter than [`BandBuffer::acc_len`].
    AccTooSmall,
    /// `cover` is shorter than [`BandBuffer::cover_len`].
    CoverTooSmall,
    /// A depth buffer's slices are shorter than
    /// [`DepthBuffer::len`](crate::hsr::DepthBuffer::len).
    DepthTooSmall,
}

/// The accumulation buffer of one band, over caller-provided storage.
///
/// `C` is the number of channels: 1 (gray) or 3 (RGB).
#[derive(Debug)]
pub struct BandBuffer<'a, const C: usize> {
    acc: &'a mut [i32],
    cover: &'a mut [i32],
    band: Band,
    background: [u16; C],
}

impl<'a, const C: usize> BandBuffer<'a, C> {
    /// `i32`s needed for `acc`: one per channel per pixel.
    pub const fn acc_len(width: u16, rows: u16) -> usize {
        width as usize * rows as usize * C
    }

    /// `i32`s needed for the `cover` scratch: one per pixel, and two per
    /// row for the extent of the row's cover changes (so the span sweep
    /// visits only the columns between a primitive's edges).
    pub const fn cover_len(width: u16, rows: u16) -> usize {
        (width as usize + 2) * rows as usize
    }

    /// A buffer for `band` over `acc` and `cover` (longer slices are fine).
    /// Call [`clear`](Self::clear) before drawing.
    pub fn new(acc: &'a mut [i32], cover: &'a mut [i32], band: Band) -> Result<Self, BandError> {
        let y_ok = band.y0.unsigned_abs() <= crate::geom::COORD_LIMIT_PX as u32;
        if band.width == 0 || band.rows == 0 || band.width > MAX_WIDTH || !y_ok || C == 0 {
            return Err(BandError::BadBand);
        }
        if acc.len() < Self::acc_len(band.width, band.rows) {
            return Err(BandError::AccTooSmall);
        }
        let cover_len = Self::cover_len(band.width, band.rows);
        if cover.len() < cover_len {
            return Err(BandError::CoverTooSmall);
        }
        let mut buf = Self {
            acc,
            cover,
            band,
            background: [0; C],
        };
        for r in 0..band.rows {
            buf.reset_row(usize::from(r));
        }
        Ok(buf)
    }

    /// The band this buffer holds.
    pub fn band(&self) -> Band {
        self.band
    }

    /// The background set by the last [`clear`](Self::clear).
    pub fn background(&self) -> [u16; C] {
        self.background
    }

    /// Fills the band with `background` (linear 12-bit; larger values are
    /// clamped to 4095). Primitives drawn afterwards replace it in
    /// proportion to their coverage.
    pub fn clear(&mut self, background: [u16; C]) {
        let bg = background.map(|v| v.min(LIN_MAX));
        self.background = bg;
        let n = Self::acc_len(self.band.width, self.band.rows);
        let Some(acc) = self.acc.get_mut(..n) else {
            return;
        };
        for px in acc.chunks_exact_mut(C) {
            for (a, b) in px.iter_mut().zip(bg) {
                *a = i32::from(b) << COVER_BITS;
            }
        }
    }

    /// The linear 12-bit value of frame pixel `(x, y)`, or `None` outside
    /// the band. This is the one rounding of the pipeline: round to nearest,
    /// then clamp to `0..=4095`.
    pub fn lin12(&self, x: i32, y: i32) -> Option<[u16; C]> {
        let k = self.index(x, y)?;
        let px = self.acc.get(k..k + C)?;
        let mut out = [0u16; C];
        for (o, &a) in out.iter_mut().zip(px) {
            *o = resolve(a);
        }
        Some(out)
    }

    /// Writes the linear 12-bit values of frame row `y` into `out` (at most
    /// `width` pixels; a shorter `out` gets the row's first pixels).
    /// Returns the number of pixels written, 0 when `y` is not in the band.
    pub fn resolve_row(&self, y: i32, out: &mut [[u16; C]]) -> usize {
        let Some(start) = self.index(0, y) else {
            return 0;
        };
        let w = usize::from(self.band.width);
        let Some(row) = self.acc.get(start..start + w * C) else {
            return 0;
        };
        let mut n = 0;
        for (o, px) in out.iter_mut().zip(row.chunks_exact(C)) {
            for (oc, &a) in o.iter_mut().zip(px) {
                *oc = resolve(a);
            }
            n += 1;
        }
        n
    }

    /// The raw accumulation of frame pixel `(x, y)`: per channel,
    /// `lin12 * 4096` before rounding (for tests and tools).
    pub fn raw(&self, x: i32, y: i32) -> Option<[i32; C]> {
        let k = self.index(x, y)?;
        let px = self.acc.get(k..k + C)?;
        let mut out = [0i32; C];
        out.copy_from_slice(px);
        Some(out)
    }

    /// Index of channel 0 of `(x, y)` in `acc`.
    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let w = i32::from(self.band.width);
        let r = y.checked_sub(self.band.y0)?;
        if x < 0 || x >= w || r < 0 || r >= i32::from(self.band.rows) {
            return None;
        }
        Some((r as usize * w as usize + x as usize) * C)
    }

    /// Adds an edge pixel's values (acc units, one per channel) to `(x, y)`;
    /// pixels outside the band are dropped.
    #[inline]
    pub(crate) fn add_cell(&mut self, x: i32, y: i32, values: &[i32; C]) {
        if let Some(k) = self.index(x, y) {
            if let Some(px) = self.acc.get_mut(k..k + C) {
                for (a, &v) in px.iter_mut().zip(values) {
                    *a = a.saturating_add(v);
                }
            }
        }
    }

    /// Records a change of cover `delta` (coverage units) starting at
    /// column `x` of row `y`. Columns left of the band go to column 0 (they
    /// cover everything to their right); columns right of it are dropped.
    #[inline]
    pub(crate) fn add_cover(&mut self, x: i32, y: i32, delta: i32) {
        let w = i32::from(self.band.width);
        let r = y - self.band.y0;
        if r < 0 || r >= i32::from(self.band.rows) || x >= w {
            return;
        }
        let x = x.max(0);
        let start = r as usize * (w as usize + 2);
        if let Some(row) = self.cover.get_mut(start..start + w as usize + 2) {
            row[x as usize] += delta;
            let (lo, hi) = (w as usize, w as usize + 1);
            row[lo] = row[lo].min(x);
            row[hi] = row[hi].max(x);
        }
    }

    /// Empties row `r` of the cover scratch's extent (the deltas are
    /// cleared by the sweep as it reads them).
    fn reset_row(&mut self, r: usize) {
        let w = usize::from(self.band.width);
        let start = r * (w + 2);
        if let Some(row) = self.cover.get_mut(start..start + w + 2) {
            row[..w].iter_mut().for_each(|c| *c = 0);
            row[w] = i32::MAX;
            row[w + 1] = i32::MIN;
        }
    }
}

impl<const C: usize> BandBuffer<'_, C> {
    /// The frame rows `y_lo..y_hi` clipped to the band (for the sweeps).
    fn rows_in_band(&self, y_lo: i32, y_hi: i32) -> core::ops::Range<i32> {
        y_lo.max(self.band.y0)..y_hi.min(self.band.y0 + i32::from(self.band.rows))
    }
}

/// Row `r` of the cover scratch for a sweep: its cover changes and their
/// column extent `lo..=hi`, the extent reset for the next primitive (the
/// sweep clears the changes as it reads them). `None` when the row has no
/// changes. Events were clamped into the band at insertion, so
/// `0 <= lo <= hi < w`.
fn take_row(cover: &mut [i32], r: usize, w: usize) -> Option<(&mut [i32], usize, usize)> {
    let start = r * (w + 2);
    let row = cover.get_mut(start..start + w + 2)?;
    let (deltas, ext) = row.split_at_mut(w);
    let (lo, hi) = (
        core::mem::replace(&mut ext[0], i32::MAX),
        core::mem::replace(&mut ext[1], i32::MIN),
    );
    if lo > hi {
        return None;
    }
    let (lo, hi) = (lo.max(0) as usize, (hi.max(0) as usize).min(w - 1));
    Some((deltas, lo, hi))
}

/// Rounds an accumulated value to linear 12 bits: the pipeline's one rounding.
#[inline]
fn resolve(acc: i32) -> u16 {
    let v = ((acc >> (COVER_BITS - 1)) + 1) >> 1;
    v.clamp(0, i32::from(LIN_MAX)) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_is_to_nearest_and_clamped() {
        assert_eq!(resolve(0), 0);
        assert_eq!(resolve(2047), 0);
        assert_eq!(resolve(2048), 1);
        assert_eq!(resolve(4095 * 4096), 4095);
        assert_eq!(resolve(i32::MAX), 4095);
        assert_eq!(resolve(-5000), 0);
    }

    #[test]
    fn short_buffers_and_bad_bands_are_errors() {
        let mut acc = [0i32; 8];
        let mut cov = [0i32; 12];
        let band = Band {
            width: 4,
            y0: 0,
            rows: 2,
        };
        assert!(BandBuffer::<1>::new(&mut acc, &mut cov, band).is_ok());
        assert_eq!(
            BandBuffer::<3>::new(&mut acc, &mut cov, band).err(),
            Some(BandError::AccTooSmall)
        );
        let zero = Band {
            width: 0,
            y0: 0,
            rows: 2,
        };
        assert_eq!(
            BandBuffer::<1>::new(&mut acc, &mut cov, zero).err(),
            Some(BandError::BadBand)
        );
        let far = Band {
            width: 4,
            y0: i32::MIN,
            rows: 2,
        };
        assert_eq!(
            BandBuffer::<1>::new(&mut acc, &mut cov, far).err(),
            Some(BandError::BadBand)
        );
    }

    #[test]
    fn out_of_band_reads_are_none() {
        let mut acc = [0i32; 8];
        let mut cov = [0i32; 12];
        let mut b = BandBuffer::<1>::new(
            &mut acc,
            &mut cov,
            Band {
                width: 4,
                y0: 10,
                rows: 2,
            },
        )
        .unwrap();
        b.clear([100]);
        assert_eq!(b.lin12(0, 10), Some([100]));
        assert_eq!(b.lin12(0, 9), None);
        assert_eq!(b.lin12(4, 10), None);
        assert_eq!(b.lin12(-1, 11), None);
        b.add_cell(-1, 10, &[5]);
        b.add_cover(99, 10, 5);
        b.add_cover(0, 12, 5);
        assert_eq!(b.raw(0, 10), Some([100 << 12]));
    }
}
