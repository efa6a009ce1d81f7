//! The band: the caller-provided accumulator of one band of rows, the
//! coverage scratch its shapes are walked into, and the sweeps that compose
//! each shape into it (add, over, depth).
//!
//! Takes the cells and cover changes of a shape's edges from the
//! the `edge` module walker, and the shape's paint (a flat colour or a
//! Gouraud plane) and blend; gives linear 12-bit intensities per pixel at
//! [`BandBuffer::lin12`] / [`BandBuffer::resolve_row`].
//!
//! ## The frame in bands
//!
//! A frame of `width x height` pixels is drawn as bands of `rows` rows
//! ([`Bands`]); a band is a window `[x0, x0 + width) x [y0, y0 + rows)` of
//! the frame. Every shape is drawn into every band it touches; an edge's
//! walk resumes where the band above left it, or starts directly at the
//! band's first row from exact (quotient, remainder) state, so a pixel gets
//! the very same bits whatever the band height. A band may lie partly or
//! wholly outside the frame: its rows then simply receive whatever shapes
//! cover them (nothing is written outside the caller's buffers).
//!
//! ## One shape at a time: scratch, then compose
//!
//! A shape (a triangle, a polygon, a mesh, a path, a stroke) is walked edge
//! by edge into the `cover` scratch: per pixel the change of the winding
//! integral, each edge pixel as a pair of changes (`+S` at the pixel, `-S`
//! right of it) and each row's cover as one change. A running sum along the
//! row gives every pixel its signed coverage, exact, with the shape's
//! shared edges cancelled; the fill rule turns it into a share `c` in
//! `0..=1` px, and the shape is composed once, as a whole:
//!
//! - **over** (painter's order): `acc = acc (1 - c α) + I c α`, in linear
//!   light; one multiply per channel where the shape covers part of a
//!   pixel, a store where it covers all of it opaquely;
//! - **add** (seed 000, eqs. 2-3): `acc += (I - bg) c α`, a multiply per
//!   channel on partly covered pixels and an addition elsewhere; for a flat
//!   colour the product `(I - bg) c` is exact, so shapes sharing an edge sum
//!   to the bits of the shape drawn whole;
//! - **depth** (seed 004's z-buffer, `zsweep.rs`).
//!
//! Interior runs of one coverage are composed with the span set up once
//! (the Gouraud plane's value at the run's first pixel, two multiplies)
//! and stepped by one addition per pixel.
//!
//! ## Units and ranges
//!
//! Coverage is in [`COVER_ONE`](crate::COVER_ONE) = 2^16 per pixel. A pixel
//! of the accumulator holds, per channel, `lin12 * 2^16` (a fully covered
//! pixel of intensity 4095 is below `2^28`), so the frame is rounded to 12
//! bits once, at resolve. Over keeps every pixel a convex combination of
//! its inputs; add saturates instead of wrapping (a pixel beyond 8 full
//! layers resolves to the channel's limit, documented clipping). The
//! scratch sums wrap (two's complement, exact modulo `2^32`): the final
//! sum of a pixel, a winding integral, is far inside `i32` for any shape
//! with fewer than 32 767 nested windings.

mod depth;
mod errors;
mod gradient;
// Used by text's glyph masks only.
#[cfg(feature = "text")]
mod mask;
mod pixels;
mod sweep;
mod zsweep;

pub(crate) use crate::units::resolve;
pub use depth::{DepthBuffer, ZPass, SAMPLES};
pub(crate) use depth::{SampleEdges, ALL_SAMPLES, FULL, FULL_BITS};
pub(crate) use sweep::{ComposeOp, Coverage, Paint};

use crate::shade::LIN_MAX;
use crate::COVER_BITS;

/// Largest band width and frame height handled, in pixels.
pub const MAX_WIDTH: u16 = 2048;

/// Per row of the scratch, before its `width` cover changes: their extent
/// (`lo`, `hi`, inclusive) and the extent of the row's drawn pixels
/// (`dirty_lo`, `dirty_hi`, half-open).
const ROW_HEAD: usize = 4;
/// Extra `i32`s per row of the scratch.
const ROW_EXTRA: usize = ROW_HEAD;
/// Offsets in a row's head.
const LO: usize = 0;
const HI: usize = 1;
const DIRTY_LO: usize = 2;

/// Start of row `r` of the scratch of a band `w` wide.
#[inline]
const fn row_start(r: usize, w: usize) -> usize {
    r * (w + ROW_EXTRA)
}

/// One band: the frame rows `[y0, y0 + rows)`, columns `[x0, x0 + width)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Band {
    /// Width of the band in pixels.
    pub width: u16,
    /// First frame row of the band.
    pub y0: i32,
    /// Number of rows.
    pub rows: u16,
    /// First frame column of the band (0 unless only part of the frame is
    /// redrawn).
    pub x0: i32,
}

impl Band {
    /// A band of whole frame rows: columns `0..width`.
    pub const fn new(width: u16, y0: i32, rows: u16) -> Self {
        Self {
            width,
            y0,
            rows,
            x0: 0,
        }
    }

    /// The frame rows it holds.
    pub fn row_range(&self) -> core::ops::Range<i32> {
        self.y0..self.y0.saturating_add(i32::from(self.rows))
    }

    /// The frame columns it holds.
    pub fn column_range(&self) -> core::ops::Range<i32> {
        self.x0..self.x0.saturating_add(i32::from(self.width))
    }
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
    x0: i32,
    width: u16,
    next: i32,
    end: i32,
    rows: u16,
}

impl Bands {
    /// Bands of `rows` rows (at least 1) covering `height` rows of a frame
    /// `width` pixels wide.
    pub fn new(width: u16, height: u16, rows: u16) -> Self {
        Self {
            x0: 0,
            width,
            next: 0,
            end: i32::from(height),
            rows: rows.max(1),
        }
    }

    /// Bands of `rows` rows covering the window `x0..x0 + width`,
    /// `y0..y0 + height` of a frame: what a partial redraw walks.
    pub fn window(x0: i32, y0: i32, width: u16, height: u16, rows: u16) -> Self {
        Self {
            x0,
            width,
            next: y0,
            end: y0.saturating_add(i32::from(height)),
            rows: rows.max(1),
        }
    }
}

impl Iterator for Bands {
    type Item = Band;
    fn next(&mut self) -> Option<Band> {
        if self.next >= self.end {
            return None;
        }
        let rows = i32::from(self.rows).min(self.end - self.next) as u16;
        let band = Band {
            width: self.width,
            y0: self.next,
            rows,
            x0: self.x0,
        };
        self.next += i32::from(rows);
        Some(band)
    }
}

/// Why a band buffer could not be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum BandError {
    /// Width or rows is zero, the width is over [`MAX_WIDTH`], or `y0` or
    /// `x0` is outside the coordinate range.
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

    /// `i32`s needed for the `cover` scratch: one per pixel, and four per
    /// row: the extent of the row's cover changes (so the sweep visits
    /// only the columns between a shape's edges) and the extent of what the
    /// row holds besides the background (so the rest is sent without being
    /// resolved).
    pub const fn cover_len(width: u16, rows: u16) -> usize {
        (width as usize + ROW_EXTRA) * rows as usize
    }

    /// A buffer for `band` over `acc` and `cover` (longer slices are fine).
    /// Call [`clear`](Self::clear) before drawing.
    pub fn new(acc: &'a mut [i32], cover: &'a mut [i32], band: Band) -> Result<Self, BandError> {
        let mut buf = Self::new_unreset(acc, cover, band)?;
        for r in 0..band.rows {
            buf.reset_row(usize::from(r));
        }
        Ok(buf)
    }

    fn new_unreset(
        acc: &'a mut [i32],
        cover: &'a mut [i32],
        band: Band,
    ) -> Result<Self, BandError> {
        let limit = crate::geom::COORD_LIMIT_PX as u32;
        let y_ok = band.y0.unsigned_abs() <= limit && band.x0.unsigned_abs() <= limit;
        if band.width == 0 || band.rows == 0 || band.width > MAX_WIDTH || !y_ok || C == 0 {
            return Err(BandError::BadBand);
        }
        if acc.len() < Self::acc_len(band.width, band.rows) {
            return Err(BandError::AccTooSmall);
        }
        if cover.len() < Self::cover_len(band.width, band.rows) {
            return Err(BandError::CoverTooSmall);
        }
        Ok(Self {
            acc,
            cover,
            band,
            background: [0; C],
        })
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
    /// clamped to 4095). Shapes drawn afterwards cover it in painter's
    /// order, or add to it (`Blend::Add`, relative to this background).
    pub fn clear(&mut self, background: [u16; C]) {
        let bg = background.map(|v| v.min(LIN_MAX));
        self.background = bg;
        let n = Self::acc_len(self.band.width, self.band.rows);
        let Some(acc) = self.acc.get_mut(..n) else {
            return;
        };
        let fill = bg.map(|b| i32::from(b) << COVER_BITS);
        for px in acc.chunks_mut(C) {
            if let Ok(px) = <&mut [i32; C]>::try_from(px) {
                *px = fill;
            }
        }
        let w = usize::from(self.band.width);
        for r in 0..usize::from(self.band.rows) {
            let at = row_start(r, w) + DIRTY_LO;
            if let Some([dlo, dhi]) = self.cover.get_mut(at..at + 2) {
                (*dlo, *dhi) = (0, 0);
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
        let Some(row) = self.acc_row(y) else {
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

    /// The accumulator of frame row `y` (`width * C` values, `lin12 *
    /// 2^16` each), or `None` when `y` is not in the band.
    pub(crate) fn acc_row(&self, y: i32) -> Option<&[i32]> {
        let r = usize::try_from(y.checked_sub(self.band.y0)?).ok()?;
        if r >= usize::from(self.band.rows) {
            return None;
        }
        let w = usize::from(self.band.width) * C;
        self.acc.get(r * w..r * w + w)
    }

    /// The raw accumulation of frame pixel `(x, y)`: per channel,
    /// `lin12 * 2^16` before rounding.
    #[cfg(any(test, feature = "internals"))]
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
        let c = x.checked_sub(self.band.x0)?;
        let r = y.checked_sub(self.band.y0)?;
        if c < 0 || c >= w || r < 0 || r >= i32::from(self.band.rows) {
            return None;
        }
        Some((r as usize * w as usize + c as usize) * C)
    }

    /// Adds values (acc units, one per channel) to frame pixel `(x, y)`;
    /// pixels outside the band are dropped.
    #[inline]
    pub(crate) fn add_cell(&mut self, x: i32, y: i32, values: &[i32; C]) {
        if let Some(k) = self.index(x, y) {
            if let Some(px) = self.acc.get_mut(k..k + C) {
                for (a, &v) in px.iter_mut().zip(values) {
                    *a = a.saturating_add(v);
                }
            }
            let w = usize::from(self.band.width);
            let (r, c) = ((k / C) / w, (k / C) % w);
            self.mark(r, c, c + 1);
        }
    }

    /// Records a change of cover `delta` (coverage units) starting at frame
    /// column `x` of frame row `y`. Columns left of the band go to its
    /// first column (they cover everything to their right); columns right
    /// of it are dropped.
    #[inline]
    pub(crate) fn add_cover(&mut self, x: i32, y: i32, delta: i32) {
        let w = i32::from(self.band.width);
        let r = y.wrapping_sub(self.band.y0);
        let c = x.saturating_sub(self.band.x0);
        if r < 0 || r >= i32::from(self.band.rows) || c >= w {
            return;
        }
        let c = c.max(0) as usize;
        let w = w as usize;
        let start = row_start(r as usize, w);
        if let Some([lo, hi, _, _, deltas @ ..]) = self.cover.get_mut(start..start + w + ROW_EXTRA)
        {
            if let Some(d) = deltas.get_mut(c) {
                *d = d.wrapping_add(delta);
            }
            *lo = (*lo).min(c as i32);
            *hi = (*hi).max(c as i32);
        }
    }

    /// Records an edge pixel's area as a pair of cover changes: `+area` at
    /// the pixel, `-area` right of it (dropped at the band's right end).
    #[cfg(test)]
    pub(crate) fn add_area(&mut self, x: i32, y: i32, area: i32) {
        let w = i32::from(self.band.width);
        let r = y.wrapping_sub(self.band.y0);
        let c = x.wrapping_sub(self.band.x0);
        if r < 0 || r >= i32::from(self.band.rows) || c < 0 || c >= w {
            return;
        }
        let (c, w) = (c as usize, w as usize);
        let start = row_start(r as usize, w);
        if let Some([lo, hi, _, _, deltas @ ..]) = self.cover.get_mut(start..start + w + ROW_EXTRA)
        {
            if let Some(d) = deltas.get_mut(c) {
                *d = d.wrapping_add(area);
            }
            let right = if let Some(d) = deltas.get_mut(c + 1) {
                *d = d.wrapping_sub(area);
                c + 1
            } else {
                c
            };
            *lo = (*lo).min(c as i32);
            *hi = (*hi).max(right as i32);
        }
    }

    /// Empties row `r` of the cover scratch and its extents.
    fn reset_row(&mut self, r: usize) {
        let w = usize::from(self.band.width);
        let start = row_start(r, w);
        if let Some([lo, hi, dlo, dhi, deltas @ ..]) =
            self.cover.get_mut(start..start + w + ROW_EXTRA)
        {
            deltas.iter_mut().for_each(|c| *c = 0);
            *lo = i32::MAX;
            *hi = i32::MIN;
            (*dlo, *dhi) = (0, 0);
        }
    }

    /// A buffer for the next band of a frame over the storage the previous
    /// band of the same width used, whose scratch every sweep left empty:
    /// only the extents are reset (not every pixel), and the accumulator is
    /// taken to hold `background` already (the previous band's flush reset
    /// it). For the renderer, which knows both.
    pub(crate) fn reuse(
        acc: &'a mut [i32],
        cover: &'a mut [i32],
        band: Band,
        background: [u16; C],
    ) -> Result<Self, BandError> {
        let mut buf = Self::new_unreset(acc, cover, band)?;
        buf.background = background.map(|v| v.min(LIN_MAX));
        let w = usize::from(band.width);
        for r in 0..usize::from(band.rows) {
            let start = row_start(r, w);
            if let Some([lo, hi, dlo, dhi]) = buf.cover.get_mut(start..start + ROW_HEAD) {
                *lo = i32::MAX;
                *hi = i32::MIN;
                (*dlo, *dhi) = (0, 0);
            }
        }
        Ok(buf)
    }

    /// Marks columns `lo..hi` (band-relative) of row `r` as drawn.
    #[inline]
    fn mark(&mut self, r: usize, lo: usize, hi: usize) {
        let w = usize::from(self.band.width);
        let at = row_start(r, w) + DIRTY_LO;
        if let Some([dlo, dhi]) = self.cover.get_mut(at..at + 2) {
            let (lo, hi) = (lo as i32, hi as i32);
            if *dlo >= *dhi {
                (*dlo, *dhi) = (lo, hi);
            } else {
                *dlo = (*dlo).min(lo);
                *dhi = (*dhi).max(hi);
            }
        }
    }

    /// The band split for its flush: the accumulator, the drawn extents of
    /// its rows, and the background in accumulator units.
    pub(crate) fn flush_parts(&mut self) -> FlushParts<'_, C> {
        let n = Self::acc_len(self.band.width, self.band.rows);
        let acc = match self.acc.get_mut(..n) {
            Some(a) => a,
            None => &mut [],
        };
        FlushParts {
            acc,
            extents: DrawnExtents {
                cover: &mut *self.cover,
                width: usize::from(self.band.width),
                y0: self.band.y0,
            },
            background: self.background.map(|b| i32::from(b) << COVER_BITS),
        }
    }

    /// The frame rows `y_lo..y_hi` clipped to the band (for the sweeps).
    fn rows_in_band(&self, y_lo: i32, y_hi: i32) -> core::ops::Range<i32> {
        let end = self.band.y0 + i32::from(self.band.rows);
        y_lo.max(self.band.y0)..y_hi.min(end)
    }
}

/// A band taken apart to be sent ([`BandBuffer::flush_parts`]).
pub(crate) struct FlushParts<'p, const C: usize> {
    pub acc: &'p mut [i32],
    pub extents: DrawnExtents<'p>,
    pub background: [i32; C],
}

/// The drawn extents of a band's rows, read once each as the row is sent.
pub(crate) struct DrawnExtents<'p> {
    cover: &'p mut [i32],
    width: usize,
    y0: i32,
}

impl DrawnExtents<'_> {
    /// The drawn columns of frame row `y`, forgotten.
    pub(crate) fn take(&mut self, y: i32) -> core::ops::Range<u16> {
        let w = self.width;
        let Ok(r) = usize::try_from(y.wrapping_sub(self.y0)) else {
            return 0..0;
        };
        let at = row_start(r, w) + DIRTY_LO;
        match self.cover.get_mut(at..at + 2) {
            Some([dlo, dhi]) => {
                let out = (*dlo).clamp(0, w as i32) as u16..(*dhi).clamp(0, w as i32) as u16;
                (*dlo, *dhi) = (0, 0);
                out
            }
            _ => 0..0,
        }
    }
}

/// The scratch as an edge walk writes it ([`EdgeWalk::walk_into`]):
/// changes of the running coverage of the frame rows `y_first..y_first +
/// n` (the walk's rows, clipped to the band); rows outside are dropped,
/// columns left of the band apply from its first, right of it are dropped.
///
/// [`EdgeWalk::walk_into`]: crate::edge::EdgeWalk
pub(crate) struct BandDeltas<'s> {
    cover: &'s mut [i32],
    w: i32,
    x0: i32,
    y_first: i32,
    n: u32,
    /// Band row of `y_first`.
    r_first: usize,
}

impl<const C: usize> BandBuffer<'_, C> {
    /// The scratch rows `rows` (clipped to the band) for an edge walk.
    pub(crate) fn deltas(&mut self, rows: core::ops::Range<i32>) -> BandDeltas<'_> {
        let r = self.rows_in_band(rows.start, rows.end);
        self.deltas_within(r)
    }

    /// [`deltas`](Self::deltas) of rows already within the band (a
    /// triangle's rows in it: not clipped again; rows outside would give
    /// a sink whose rows miss the scratch, which writes nothing).
    #[inline]
    pub(crate) fn deltas_within(&mut self, r: core::ops::Range<i32>) -> BandDeltas<'_> {
        BandDeltas {
            cover: &mut *self.cover,
            w: i32::from(self.band.width),
            x0: self.band.x0,
            y_first: r.start,
            n: (r.end - r.start).max(0) as u32,
            r_first: (r.start - self.band.y0).max(0) as usize,
        }
    }
}

impl BandDeltas<'_> {
    /// The same rows for one more walk: a copy of the few words a walk
    /// keeps in registers (a walk writing through a reference reloads
    /// them at every change).
    #[inline(always)]
    pub(crate) fn lend(&mut self) -> BandDeltas<'_> {
        BandDeltas {
            cover: &mut *self.cover,
            ..*self
        }
    }

    /// The start of frame row `y`'s scratch row, if the walk writes it.
    #[inline]
    fn row(&self, y: i32) -> Option<usize> {
        let k = y.wrapping_sub(self.y_first) as u32;
        (k < self.n).then(|| row_start(self.r_first + k as usize, self.w as usize))
    }

    /// [`put_n`](crate::edge::DeltaSink::put_n)'s changes at a band's
    /// sides, one at a time from band column `c` (left of the band: at its
    /// first column; right of it: dropped). Out of line: rare.
    #[inline(never)]
    fn put_n_clipped<const K: usize>(&mut self, start: usize, c: i32, step: i32, d: [i32; K]) {
        let (mut lo, mut hi) = (i32::MAX, i32::MIN);
        let mut c = c;
        for v in d {
            let k = c.max(0);
            if k < self.w {
                if let Some(e) = self.cover.get_mut(start + ROW_HEAD + k as usize) {
                    *e = e.wrapping_add(v);
                }
                lo = lo.min(k);
                hi = hi.max(k);
            }
            c = c.saturating_add(step);
        }
        self.widen(start, lo, hi);
    }

    /// Widens row `start`'s extent of changes to columns `lo..=hi`.
    #[inline]
    fn widen(&mut self, start: usize, lo: i32, hi: i32) {
        if let Some([l, h]) = self.cover.get_mut(start + LO..start + HI + 1) {
            *l = (*l).min(lo);
            *h = (*h).max(hi);
        }
    }
}

impl crate::edge::DeltaSink for BandDeltas<'_> {
    /// One bounds test for the run of rows, then two additions and the
    /// extent per row (the general `put_n` finds each row's start by a
    /// multiply and tests it).
    #[inline]
    fn put_rows(&mut self, x: i32, ys: core::ops::Range<i32>, d0: i32, d1: i32) {
        let ya = ys.start.max(self.y_first);
        let yb = ys.end.min(self.y_first.saturating_add(self.n as i32));
        if ya >= yb {
            return;
        }
        // A difference past `i32` wraps to one that fails the test.
        let c = x.wrapping_sub(self.x0);
        if c < 0 || c >= self.w - 1 {
            // Clipped at the band's sides: change by change (`put`, not
            // `put_n`, which a third caller would have the compiler keep
            // out of line for the walks too).
            for y in ya..yb {
                self.put(x, y, d0);
                self.put(x.saturating_add(1), y, d1);
            }
            return;
        }
        let (w, c) = (self.w as usize, c as usize);
        let stride = w + ROW_EXTRA;
        let mut start = row_start(self.r_first + (ya - self.y_first) as usize, w);
        let mut left = yb - ya;
        while left > 0 {
            if let Some(row) = self.cover.get_mut(start..start + ROW_HEAD + c + 2) {
                if let Some([l, h]) = row.get_mut(LO..HI + 1) {
                    *l = (*l).min(c as i32);
                    *h = (*h).max(c as i32 + 1);
                }
                if let Some([e0, e1]) = row.get_mut(ROW_HEAD + c..) {
                    *e0 = e0.wrapping_add(d0);
                    *e1 = e1.wrapping_add(d1);
                }
            }
            start += stride;
            left -= 1;
        }
    }

    #[inline]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        let Some(start) = self.row(y) else {
            return;
        };
        let c = x.saturating_sub(self.x0).max(0);
        if c >= self.w {
            return;
        }
        if let Some(v) = self.cover.get_mut(start + ROW_HEAD + c as usize) {
            *v = v.wrapping_add(d);
        }
        self.widen(start, c, c);
    }

    #[inline]
    fn put2(&mut self, x0: i32, x1: i32, y: i32, d0: i32, d1: i32) {
        let Some(start) = self.row(y) else {
            return;
        };
        let (c0, c1) = (
            x0.saturating_sub(self.x0).max(0),
            x1.saturating_sub(self.x0).max(0),
        );
        let (lo, hi) = (c0.min(c1), c0.max(c1));
        if lo >= self.w {
            return;
        }
        for (c, d) in [(c0, d0), (c1, d1)] {
            if c < self.w {
                if let Some(v) = self.cover.get_mut(start + ROW_HEAD + c as usize) {
                    *v = v.wrapping_add(d);
                }
            }
        }
        self.widen(start, lo, hi.min(self.w - 1));
    }

    #[inline(always)]
    fn put_n<const K: usize>(&mut self, x: i32, y: i32, step: i32, d: [i32; K]) {
        let Some(start) = self.row(y) else {
            return;
        };
        // The common case, a y-major edge's row inside the band: the `K`
        // adjacent changes with one bounds check.
        let c = x.saturating_sub(self.x0);
        if K > 0 && (step == 1 || step == -1) {
            let far = c.saturating_add(step * (K as i32 - 1));
            let (lo, hi) = (c.min(far), c.max(far));
            if lo >= 0 && hi < self.w {
                let at = start + ROW_HEAD + lo as usize;
                if let Some((cells, _)) = self
                    .cover
                    .get_mut(at..)
                    .and_then(|r| r.split_first_chunk_mut::<K>())
                {
                    for (k, v) in d.into_iter().enumerate() {
                        let e = if step == 1 {
                            &mut cells[k]
                        } else {
                            &mut cells[K - 1 - k]
                        };
                        *e = e.wrapping_add(v);
                    }
                    self.widen(start, lo, hi);
                    return;
                }
            }
        }
        self.put_n_clipped(start, c, step, d);
    }

    #[inline]
    fn run<F: FnMut() -> Option<i32>>(
        &mut self,
        x: i32,
        y: i32,
        step: i32,
        n: i32,
        mut f: F,
    ) -> i32 {
        let c0 = x.saturating_sub(self.x0);
        let (Some(start), true) = (self.row(y), c0 >= 0 && c0 <= self.w) else {
            // Outside (or, never for the walker's runs, not in the band's
            // columns): steps only, or one change at a time.
            let mut x = x;
            for k in 0..n {
                let Some(d) = f() else {
                    return k;
                };
                if self.row(y).is_some() {
                    self.put(x, y, d);
                }
                x = x.saturating_add(step);
            }
            return n.max(0);
        };
        // The row's changes: the run's columns are within the walk's,
        // `0..=w` here; a change at `w` (the `-S` of a cell in the band's
        // last column, mirrored) falls off the slice, dropped.
        let w = self.w as usize;
        let Some(cells) = self.cover.get_mut(start + ROW_HEAD..start + ROW_HEAD + w) else {
            return 0;
        };
        let mut c = c0 as usize;
        let mut k = 0;
        while k < n {
            let Some(d) = f() else {
                break;
            };
            if let Some(e) = cells.get_mut(c) {
                *e = e.wrapping_add(d);
            }
            c = c.wrapping_add(step as usize);
            k += 1;
        }
        if k > 0 {
            let last = c0 + step * (k - 1);
            let (lo, hi) = (c0.min(last), c0.max(last).min(self.w - 1));
            self.widen(start, lo, hi);
        }
        k
    }
}

/// The walker's reports go straight into the scratch.
impl<const C: usize> crate::edge::CoverSink for BandBuffer<'_, C> {
    #[inline]
    fn cover(&mut self, x: i32, y: i32, delta: i32) {
        self.add_cover(x, y, delta);
    }
}

/// Row `r` of the cover scratch for a sweep: its cover changes, their
/// column extent `lo..=hi` (reset for the next shape: the sweep clears the
/// changes as it reads them) and the row's drawn extent to widen. `None`
/// when the row has no changes. Events were clamped into the band at
/// insertion, so `0 <= lo <= hi < w`.
fn take_row(cover: &mut [i32], r: usize, w: usize) -> Option<SweepRow<'_>> {
    let start = row_start(r, w);
    let row = cover.get_mut(start..start + w + ROW_HEAD)?;
    let [lo, hi, dlo, dhi, deltas @ ..] = row else {
        return None;
    };
    let (l, h) = (
        core::mem::replace(lo, i32::MAX),
        core::mem::replace(hi, i32::MIN),
    );
    if l > h {
        return None;
    }
    Some(SweepRow {
        deltas,
        lo: l.max(0) as usize,
        hi: (h.max(0) as usize).min(w - 1),
        drawn: (dlo, dhi),
    })
}

/// One row of the scratch, taken for a sweep.
struct SweepRow<'r> {
    deltas: &'r mut [i32],
    lo: usize,
    hi: usize,
    drawn: (&'r mut i32, &'r mut i32),
}

impl SweepRow<'_> {
    /// Widens the row's drawn extent by columns `lo..hi`.
    fn mark(&mut self, lo: usize, hi: usize) {
        let (dlo, dhi) = (&mut *self.drawn.0, &mut *self.drawn.1);
        let (lo, hi) = (lo as i32, hi as i32);
        if lo >= hi {
            return;
        }
        if *dlo >= *dhi {
            (*dlo, *dhi) = (lo, hi);
        } else {
            *dlo = (*dlo).min(lo);
            *dhi = (*dhi).max(hi);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ONE: i32 = crate::COVER_ONE;

    #[test]
    fn rounding_is_to_nearest_and_clamped() {
        assert_eq!(resolve(0), 0);
        assert_eq!(resolve(ONE / 2 - 1), 0);
        assert_eq!(resolve(ONE / 2), 1);
        assert_eq!(resolve(4095 * ONE), 4095);
        assert_eq!(resolve(i32::MAX), 4095);
        assert_eq!(resolve(-5000), 0);
    }

    #[test]
    fn short_buffers_and_bad_bands_are_errors() {
        let mut acc = [0i32; 8];
        let mut cov = [0i32; 16];
        let band = Band::new(4, 0, 2);
        assert!(BandBuffer::<1>::new(&mut acc, &mut cov, band).is_ok());
        assert_eq!(
            BandBuffer::<3>::new(&mut acc, &mut cov, band).err(),
            Some(BandError::AccTooSmall)
        );
        assert_eq!(
            BandBuffer::<1>::new(&mut acc, &mut cov, Band::new(0, 0, 2)).err(),
            Some(BandError::BadBand)
        );
        assert_eq!(
            BandBuffer::<1>::new(&mut acc, &mut cov, Band::new(4, i32::MIN, 2)).err(),
            Some(BandError::BadBand)
        );
    }

    #[test]
    fn out_of_band_reads_and_writes_are_dropped() {
        let mut acc = [0i32; 8];
        let mut cov = [0i32; 16];
        let mut b = BandBuffer::<1>::new(&mut acc, &mut cov, Band::new(4, 10, 2)).unwrap();
        b.clear([100]);
        assert_eq!(b.lin12(0, 10), Some([100]));
        assert_eq!(b.lin12(0, 9), None);
        assert_eq!(b.lin12(4, 10), None);
        assert_eq!(b.lin12(-1, 11), None);
        b.add_cell(-1, 10, &[5]);
        b.add_cover(99, 10, 5);
        b.add_cover(0, 12, 5);
        assert_eq!(b.lin12(0, 10), Some([100]));
        assert!(take_row(b.cover, 0, 4).is_none());
    }

    #[test]
    fn windowed_band_addresses_frame_columns() {
        let mut acc = [0i32; 4];
        let mut cov = [0i32; 8];
        let band = Band {
            width: 4,
            y0: 3,
            rows: 1,
            x0: 100,
        };
        let mut b = BandBuffer::<1>::new(&mut acc, &mut cov, band).unwrap();
        b.clear([7]);
        assert_eq!(b.lin12(100, 3), Some([7]));
        assert_eq!(b.lin12(99, 3), None);
        assert_eq!(b.lin12(103, 3), Some([7]));
        assert_eq!(b.lin12(104, 3), None);
    }

    /// The scratch after `f` wrote a band's deltas for rows `rows`.
    fn scratch_after<F: FnOnce(&mut BandDeltas<'_>)>(
        band: Band,
        rows: core::ops::Range<i32>,
        f: F,
    ) -> [i32; 64] {
        let mut acc = [0i32; 48];
        let mut cov = [0i32; 64];
        let mut b = BandBuffer::<1>::new(&mut acc, &mut cov, band).unwrap();
        f(&mut b.deltas(rows));
        cov
    }

    #[test]
    fn put_rows_is_put_n_in_each_row() {
        use crate::edge::DeltaSink;
        // Bands of 6 columns and 4 rows, at frame column 0 and windowed
        // (x0 = 10); pairs inside, at each side and off both sides; row
        // runs inside, across both ends and outside; the walk's rows a
        // subset of the band's.
        for x0 in [0, 10] {
            let band = Band {
                width: 6,
                y0: 20,
                rows: 4,
                x0,
            };
            for walk in [18..26, 21..23, 20..21] {
                for x in x0 - 3..x0 + 9 {
                    for ya in 17..26 {
                        for yb in ya..27 {
                            let bulk = scratch_after(band, walk.clone(), |d| {
                                d.put_rows(x, ya..yb, 5, -7);
                            });
                            let each = scratch_after(band, walk.clone(), |d| {
                                for y in ya..yb {
                                    d.put_n(x, y, 1, [5, -7]);
                                }
                            });
                            assert_eq!(bulk, each, "x0 {x0}, walk {walk:?}, x {x}, {ya}..{yb}");
                        }
                    }
                }
            }
        }
    }
}
