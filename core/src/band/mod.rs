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
//! Beside its accumulator every pixel has a one-byte tag: the place of its
//! value in the band's palette of opaque flat colours, or `MIXED`
//! (`band::tags`). A tagged pixel's value is its entry's, whatever its
//! accumulator holds: an opaque flat span only fills tags, and the flush
//! tones a palette colour once per band, not once per pixel.
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
pub(crate) mod image;
// Used by text's glyph masks only.
#[cfg(feature = "text")]
mod mask;
mod pixels;
mod sweep;
pub(crate) mod tags;
mod zsweep;

pub(crate) use crate::units::resolve;
pub use depth::{DepthBuffer, ZPass, SAMPLES};
pub(crate) use depth::{SampleEdges, ALL_SAMPLES, FULL, FULL_BITS};
pub(crate) use sweep::{ComposeOp, Coverage, Paint};
pub(crate) use tags::{Palette, MIXED};

use crate::shade::LIN_MAX;
use crate::COVER_BITS;

/// Largest band width and frame height handled, in pixels.
pub const MAX_WIDTH: u16 = 2048;

/// Per row of the scratch, beside its `width` cover changes: their extent
/// (`lo`, `hi`, inclusive) and the extent of the row's drawn pixels
/// (`dirty_lo`, `dirty_hi`, half-open). The heads of all rows follow the
/// changes of all rows, so that the changes are one run of `width * rows`
/// words (the flush writes the band's colours there).
const ROW_HEAD: usize = 4;
/// Offsets in a row's head.
const LO: usize = 0;
const HI: usize = 1;
const DIRTY_LO: usize = 2;

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
///
/// Beside its accumulator, each pixel has a one-byte tag: the place of its
/// value in the band's palette when an opaque flat colour covers it whole
/// (see `band::tags`), which lets the flush tone it once per band.
#[derive(Debug)]
pub struct BandBuffer<'a, const C: usize> {
    acc: &'a mut [i32],
    /// The cover changes of the rows, `width` a row, one after another.
    deltas: &'a mut [i32],
    /// The rows' heads ([`ROW_HEAD`] each).
    heads: &'a mut [i32],
    /// The pixels' tags, [`tags::row_words`] words a row.
    tags: &'a mut [i32],
    band: Band,
    background: [u16; C],
    palette: Palette<C>,
}

/// The parts of a `cover` slice for a band of `w x rows`: changes, heads,
/// tags.
fn split_cover(
    cover: &mut [i32],
    w: usize,
    rows: usize,
) -> Option<(&mut [i32], &mut [i32], &mut [i32])> {
    let (deltas, rest) = cover.split_at_mut_checked(w * rows)?;
    let (heads, rest) = rest.split_at_mut_checked(ROW_HEAD * rows)?;
    let tags = rest.get_mut(..tags::row_words(w) * rows)?;
    Some((deltas, heads, tags))
}

impl<'a, const C: usize> BandBuffer<'a, C> {
    /// `i32`s needed for `acc`: one per channel per pixel.
    pub const fn acc_len(width: u16, rows: u16) -> usize {
        width as usize * rows as usize * C
    }

    /// `i32`s needed for the `cover` scratch: one per pixel (the changes
    /// of a shape's coverage along each row), four per row (the extent of
    /// the row's changes, so the sweep visits only the columns between a
    /// shape's edges, and of what the row holds besides the background,
    /// so the rest is sent without being resolved), and a byte per pixel
    /// (the pixel's tag: its colour's place in the band's palette when an
    /// opaque flat colour covers it whole), four to a word, each row
    /// starting a word.
    pub const fn cover_len(width: u16, rows: u16) -> usize {
        let (w, r) = (width as usize, rows as usize);
        w * r + ROW_HEAD * r + w.div_ceil(4) * r
    }

    /// A buffer for `band` over `acc` and `cover` (longer slices are fine).
    /// Call [`clear`](Self::clear) before drawing.
    pub fn new(acc: &'a mut [i32], cover: &'a mut [i32], band: Band) -> Result<Self, BandError> {
        let mut buf = Self::new_unreset(acc, cover, band)?;
        buf.deltas.fill(0);
        buf.tags.fill(0);
        for r in 0..usize::from(band.rows) {
            buf.reset_head(r);
        }
        Ok(buf)
    }

    // Inlined (as `reuse`): a buffer returned by value through a call and a
    // `Result` was copied whole (its palette, some 450 bytes) five times a
    // band, 7 k instructions a band on the Cortex-M0.
    #[inline(always)]
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
        let (w, rows) = (usize::from(band.width), usize::from(band.rows));
        let (deltas, heads, tags) = split_cover(cover, w, rows).ok_or(BandError::CoverTooSmall)?;
        Ok(Self {
            acc,
            deltas,
            heads,
            tags,
            band,
            background: [0; C],
            palette: Palette::new([0; C]),
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
        let fill = bg.map(|b| i32::from(b) << COVER_BITS);
        self.palette = Palette::new(fill);
        // Every pixel tagged the background, which is its value; a dense
        // band's (one channel) accumulator holds it too (see `band::tags`).
        if self.palette.dense {
            let n = Self::acc_len(self.band.width, self.band.rows);
            let mut acc = self.acc.get_mut(..n).unwrap_or_default();
            while let Some((px, rest)) = core::mem::take(&mut acc).split_first_chunk_mut::<C>() {
                *px = fill;
                acc = rest;
            }
        }
        self.tags.fill(0);
        for r in 0..usize::from(self.band.rows) {
            if let Some([_, _, dlo, dhi]) = self.head_mut(r) {
                (*dlo, *dhi) = (0, 0);
            }
        }
    }

    /// The value of band pixel `(r, c)`: its palette entry's when it is
    /// tagged with one, its code's when tagged `SOURCE`, else its
    /// accumulator (see `band::tags`).
    #[inline]
    fn value(&self, r: usize, c: usize) -> Option<[i32; C]> {
        let w = usize::from(self.band.width);
        let k = (r * w + c) * C;
        let px = self.acc.get(k..k + C)?.first_chunk::<C>()?;
        if self.palette.dense {
            return Some(*px);
        }
        let n = tags::row_words(w);
        let t = tags::get(self.tags.get(r * n..r * n + n)?, c);
        Some(tags::value(px, t, self.palette.entries()))
    }

    /// The linear 12-bit value of frame pixel `(x, y)`, or `None` outside
    /// the band. This is the one rounding of the pipeline: round to nearest,
    /// then clamp to `0..=4095`.
    pub fn lin12(&self, x: i32, y: i32) -> Option<[u16; C]> {
        let (r, c) = self.place(x, y)?;
        Some(self.value(r, c)?.map(resolve))
    }

    /// Writes the linear 12-bit values of frame row `y` into `out` (at most
    /// `width` pixels; a shorter `out` gets the row's first pixels).
    /// Returns the number of pixels written, 0 when `y` is not in the band.
    pub fn resolve_row(&self, y: i32, out: &mut [[u16; C]]) -> usize {
        let Some(r) = self.row_of(y) else {
            return 0;
        };
        let mut n = 0;
        for (c, o) in out
            .iter_mut()
            .take(usize::from(self.band.width))
            .enumerate()
        {
            if let Some(v) = self.value(r, c) {
                *o = v.map(resolve);
            }
            n += 1;
        }
        n
    }

    /// The raw accumulation of frame pixel `(x, y)`: per channel,
    /// `lin12 * 2^16` before rounding.
    #[cfg(any(test, feature = "internals"))]
    pub fn raw(&self, x: i32, y: i32) -> Option<[i32; C]> {
        let (r, c) = self.place(x, y)?;
        self.value(r, c)
    }

    /// Band row and column of frame pixel `(x, y)`.
    #[inline]
    fn place(&self, x: i32, y: i32) -> Option<(usize, usize)> {
        let c = usize::try_from(x.checked_sub(self.band.x0)?).ok()?;
        let r = self.row_of(y)?;
        (c < usize::from(self.band.width)).then_some((r, c))
    }

    /// Band row of frame row `y`.
    #[inline]
    fn row_of(&self, y: i32) -> Option<usize> {
        let r = usize::try_from(y.checked_sub(self.band.y0)?).ok()?;
        (r < usize::from(self.band.rows)).then_some(r)
    }

    /// Band row `r`'s head.
    #[inline]
    fn head_mut(&mut self, r: usize) -> Option<&mut [i32; ROW_HEAD]> {
        self.heads
            .get_mut(r * ROW_HEAD..r * ROW_HEAD + ROW_HEAD)?
            .first_chunk_mut::<ROW_HEAD>()
    }

    /// The tag of the opaque flat colour `f` (accumulator units): its
    /// palette entry, made if there is room. With no room left the band
    /// goes dense (see [`Palette`]): every tag `MIXED`, for good; `MIXED`
    /// is the tag then.
    pub(crate) fn flat_tag(&mut self, f: &[i32; C]) -> u8 {
        if self.palette.dense {
            return MIXED;
        }
        if let Some(t) = self.palette.intern(f) {
            return t;
        }
        self.go_dense();
        MIXED
    }

    /// True when the band keeps no tags (see `band::tags`).
    #[cfg(test)]
    pub(crate) fn is_dense(&self) -> bool {
        self.palette.dense
    }

    /// Makes the band dense: every pixel's value into its accumulator,
    /// then every tag `MIXED`, for good (see `band::tags`).
    pub(crate) fn go_dense(&mut self) {
        if self.palette.dense {
            return;
        }
        let w = usize::from(self.band.width);
        let n = tags::row_words(w);
        for r in 0..usize::from(self.band.rows) {
            if let (Some(acc), Some(words)) = (
                self.acc.get_mut(r * w * C..(r + 1) * w * C),
                self.tags.get(r * n..r * n + n),
            ) {
                tags::materialise(acc, words, self.palette.entries(), 0, w);
            }
        }
        self.tags.fill(tags::MIXED_WORD);
        self.palette.dense = true;
    }

    /// Makes pixel `(r, c)`'s accumulator its value and tags it `MIXED`
    /// (it is about to be changed there), unless the band is dense.
    #[inline]
    fn set_mixed(&mut self, r: usize, c: usize) {
        if self.palette.dense {
            return;
        }
        let w = usize::from(self.band.width);
        let n = tags::row_words(w);
        if let (Some(words), Some(acc)) = (
            self.tags.get_mut(r * n..r * n + n),
            self.acc.get_mut(r * w * C..(r + 1) * w * C),
        ) {
            if let Some(px) = acc
                .get_mut(c * C..c * C + C)
                .and_then(|p| p.first_chunk_mut::<C>())
            {
                tags::take(px, words, self.palette.entries(), c);
            }
        }
    }

    /// Adds values (acc units, one per channel) to frame pixel `(x, y)`;
    /// pixels outside the band are dropped.
    #[inline]
    pub(crate) fn add_cell(&mut self, x: i32, y: i32, values: &[i32; C]) {
        let Some((r, c)) = self.place(x, y) else {
            return;
        };
        self.set_mixed(r, c);
        let k = (r * usize::from(self.band.width) + c) * C;
        if let Some(px) = self.acc.get_mut(k..k + C) {
            for (a, &v) in px.iter_mut().zip(values) {
                *a = a.saturating_add(v);
            }
        }
        self.mark(r, c, c + 1);
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
        let (r, c) = (r as usize, c.max(0) as usize);
        if let Some(d) = self.deltas.get_mut(r * w as usize + c) {
            *d = d.wrapping_add(delta);
        }
        if let Some([lo, hi, _, _]) = self.head_mut(r) {
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
        let (r, c) = (r as usize, c as usize);
        let start = r * w as usize;
        if let Some(d) = self.deltas.get_mut(start + c) {
            *d = d.wrapping_add(area);
        }
        let right = if c + 1 < w as usize {
            if let Some(d) = self.deltas.get_mut(start + c + 1) {
                *d = d.wrapping_sub(area);
            }
            c + 1
        } else {
            c
        };
        if let Some([lo, hi, _, _]) = self.head_mut(r) {
            *lo = (*lo).min(c as i32);
            *hi = (*hi).max(right as i32);
        }
    }

    /// Empties row `r`'s head: no changes, nothing drawn.
    fn reset_head(&mut self, r: usize) {
        if let Some(h) = self.head_mut(r) {
            *h = [i32::MAX, i32::MIN, 0, 0];
        }
    }

    /// A buffer for the next band of a frame over the storage the previous
    /// band of the same width and rows used (the layout of the scratch
    /// depends on both), which its flush left clean (no changes, every
    /// pixel tagged the background `background`, the heads reset; the
    /// accumulator of a band that went dense, as a one-channel band starts,
    /// the background too): nothing is cleared here. For the renderer,
    /// which knows all that.
    #[inline(always)]
    pub(crate) fn reuse(
        acc: &'a mut [i32],
        cover: &'a mut [i32],
        band: Band,
        background: [u16; C],
    ) -> Result<Self, BandError> {
        let mut buf = Self::new_unreset(acc, cover, band)?;
        let bg = background.map(|v| v.min(LIN_MAX));
        buf.background = bg;
        buf.palette = Palette::new(bg.map(|b| i32::from(b) << COVER_BITS));
        Ok(buf)
    }

    /// Marks columns `lo..hi` (band-relative) of row `r` as drawn.
    #[inline]
    fn mark(&mut self, r: usize, lo: usize, hi: usize) {
        if let Some([_, _, dlo, dhi]) = self.head_mut(r) {
            mark_extent(dlo, dhi, lo, hi);
        }
    }

    /// The band taken apart for its flush.
    pub(crate) fn flush_parts(&mut self) -> FlushParts<'_, C> {
        let n = Self::acc_len(self.band.width, self.band.rows);
        FlushParts {
            acc: self.acc.get_mut(..n).unwrap_or_default(),
            out: &mut *self.deltas,
            heads: &mut *self.heads,
            tags: &mut *self.tags,
            palette: &self.palette,
            band: self.band,
        }
    }

    /// The frame rows `y_lo..y_hi` clipped to the band (for the sweeps).
    fn rows_in_band(&self, y_lo: i32, y_hi: i32) -> core::ops::Range<i32> {
        let end = self.band.y0 + i32::from(self.band.rows);
        y_lo.max(self.band.y0)..y_hi.min(end)
    }
}

/// Widens a drawn extent `dlo..dhi` (empty when `dlo >= dhi`) by `lo..hi`.
#[inline]
fn mark_extent(dlo: &mut i32, dhi: &mut i32, lo: usize, hi: usize) {
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

/// A band taken apart to be sent ([`BandBuffer::flush_parts`]): its
/// accumulator (the flush resets a dense band's to the background), the
/// run of its rows' changes (all zero: the flush writes the band's colours
/// there, then zeroes it again), the rows' heads (the drawn extents), the
/// tags and the palette.
pub(crate) struct FlushParts<'p, const C: usize> {
    pub acc: &'p mut [i32],
    pub out: &'p mut [i32],
    pub heads: &'p mut [i32],
    pub tags: &'p mut [i32],
    pub palette: &'p Palette<C>,
    pub band: Band,
}

impl<const C: usize> FlushParts<'_, C> {
    /// The drawn columns of band row `r` at or right of column `c0`,
    /// counted from `c0` (empty when none), forgotten (the head reset for
    /// the next band).
    pub(crate) fn take_drawn(&mut self, r: usize, c0: usize) -> core::ops::Range<usize> {
        let w = i32::from(self.band.width);
        let c0 = c0 as i32;
        match self
            .heads
            .get_mut(r * ROW_HEAD..r * ROW_HEAD + ROW_HEAD)
            .and_then(|h| h.first_chunk_mut::<ROW_HEAD>())
        {
            Some(h) => {
                // A row not drawn on holds `0..0`: clamped, empty.
                let (lo, hi) = (h[DIRTY_LO].clamp(c0, w), h[DIRTY_LO + 1].clamp(c0, w));
                *h = [i32::MAX, i32::MIN, 0, 0];
                (lo - c0) as usize..(hi - c0) as usize
            }
            None => 0..0,
        }
    }

    /// True when no row was drawn on.
    pub(crate) fn untouched(&self) -> bool {
        self.heads
            .chunks_exact(ROW_HEAD)
            .all(|h| h[DIRTY_LO] >= h[DIRTY_LO + 1])
    }

    /// The columns drawn on in any row of the band (empty when none was),
    /// the rows' heads kept.
    pub(crate) fn drawn_columns(&self) -> core::ops::Range<u16> {
        let w = i32::from(self.band.width);
        // A row not drawn on holds `0..0`: its end is no bound's.
        let (mut lo, mut hi) = (i32::MAX, 0);
        for h in self.heads.chunks_exact(ROW_HEAD) {
            let (a, b) = (h[DIRTY_LO], h[DIRTY_LO + 1]);
            if a < b {
                lo = lo.min(a);
            }
            hi = hi.max(b);
        }
        let (lo, hi) = (lo.clamp(0, w), hi.clamp(0, w));
        if lo < hi {
            lo as u16..hi as u16
        } else {
            0..0
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
    deltas: &'s mut [i32],
    heads: &'s mut [i32],
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
            deltas: &mut *self.deltas,
            heads: &mut *self.heads,
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
            deltas: &mut *self.deltas,
            heads: &mut *self.heads,
            ..*self
        }
    }

    /// Band row of frame row `y`, if the walk writes it.
    #[inline]
    fn row(&self, y: i32) -> Option<usize> {
        let k = y.wrapping_sub(self.y_first) as u32;
        (k < self.n).then(|| self.r_first + k as usize)
    }

    /// [`put_n`](crate::edge::DeltaSink::put_n)'s changes at a band's
    /// sides, one at a time from band column `c` (left of the band: at its
    /// first column; right of it: dropped). Out of line: rare.
    #[inline(never)]
    fn put_n_clipped<const K: usize>(&mut self, r: usize, c: i32, step: i32, d: [i32; K]) {
        let (mut lo, mut hi) = (i32::MAX, i32::MIN);
        let mut c = c;
        let start = r * self.w as usize;
        for v in d {
            let k = c.max(0);
            if k < self.w {
                if let Some(e) = self.deltas.get_mut(start + k as usize) {
                    *e = e.wrapping_add(v);
                }
                lo = lo.min(k);
                hi = hi.max(k);
            }
            c = c.saturating_add(step);
        }
        self.widen(r, lo, hi);
    }

    /// Widens band row `r`'s extent of changes to columns `lo..=hi`.
    #[inline]
    fn widen(&mut self, r: usize, lo: i32, hi: i32) {
        if let Some([l, h]) = self.heads.get_mut(r * ROW_HEAD + LO..r * ROW_HEAD + HI + 1) {
            *l = (*l).min(lo);
            *h = (*h).max(hi);
        }
    }
}

impl crate::edge::DeltaSink for BandDeltas<'_> {
    #[inline]
    fn columns(&self) -> Option<(i32, i32)> {
        Some((self.x0, self.x0.saturating_add(self.w)))
    }

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
        let r = self.r_first + (ya - self.y_first) as usize;
        let mut start = r * w + c;
        let mut head = r * ROW_HEAD;
        let mut left = yb - ya;
        while left > 0 {
            if let Some([l, h]) = self.heads.get_mut(head + LO..head + HI + 1) {
                *l = (*l).min(c as i32);
                *h = (*h).max(c as i32 + 1);
            }
            if let Some([e0, e1]) = self.deltas.get_mut(start..start + 2) {
                *e0 = e0.wrapping_add(d0);
                *e1 = e1.wrapping_add(d1);
            }
            start += w;
            head += ROW_HEAD;
            left -= 1;
        }
    }

    #[inline]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        let Some(r) = self.row(y) else {
            return;
        };
        let c = x.saturating_sub(self.x0).max(0);
        if c >= self.w {
            return;
        }
        if let Some(v) = self.deltas.get_mut(r * self.w as usize + c as usize) {
            *v = v.wrapping_add(d);
        }
        self.widen(r, c, c);
    }

    #[inline]
    fn put2(&mut self, x0: i32, x1: i32, y: i32, d0: i32, d1: i32) {
        let Some(r) = self.row(y) else {
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
        let start = r * self.w as usize;
        for (c, d) in [(c0, d0), (c1, d1)] {
            if c < self.w {
                if let Some(v) = self.deltas.get_mut(start + c as usize) {
                    *v = v.wrapping_add(d);
                }
            }
        }
        self.widen(r, lo, hi.min(self.w - 1));
    }

    #[inline(always)]
    fn put_n<const K: usize>(&mut self, x: i32, y: i32, step: i32, d: [i32; K]) {
        let Some(r) = self.row(y) else {
            return;
        };
        // The common case, a y-major edge's row inside the band: the `K`
        // adjacent changes with one bounds check.
        let c = x.saturating_sub(self.x0);
        if K > 0 && (step == 1 || step == -1) {
            let far = c.saturating_add(step * (K as i32 - 1));
            let (lo, hi) = (c.min(far), c.max(far));
            if lo >= 0 && hi < self.w {
                let at = r * self.w as usize + lo as usize;
                if let Some((cells, _)) = self
                    .deltas
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
                    self.widen(r, lo, hi);
                    return;
                }
            }
        }
        self.put_n_clipped(r, c, step, d);
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
        let (Some(r), true) = (self.row(y), c0 >= 0 && c0 <= self.w) else {
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
        let Some(cells) = self.deltas.get_mut(r * w..r * w + w) else {
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
            self.widen(r, lo, hi);
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

/// One row of the scratch, taken for a sweep ([`SweepRows`]): its cover
/// changes, their column extent `lo..=hi` (`0 <= lo <= hi < w`: events
/// were clamped into the band at insertion), the row's drawn extent to
/// widen, its accumulator and its tags.
pub(crate) struct SweepRow<'r, const C: usize> {
    pub(crate) deltas: &'r mut [i32],
    pub(crate) acc: &'r mut [i32],
    pub(crate) tags: &'r mut [i32],
    /// The band's palette entries (a tagged pixel's value), and whether
    /// the band is dense (no tags).
    pub(crate) palette: &'r [[i32; C]],
    pub(crate) dense: bool,
    pub(crate) lo: usize,
    pub(crate) hi: usize,
    drawn: (&'r mut i32, &'r mut i32),
}

impl<const C: usize> SweepRow<'_, C> {
    /// Widens the row's drawn extent by columns `lo..hi`.
    pub(crate) fn mark(&mut self, lo: usize, hi: usize) {
        mark_extent(self.drawn.0, self.drawn.1, lo, hi);
    }
}

/// The band rows a sweep visits, top to bottom, each with its frame row:
/// only those with cover changes, their extent of changes reset for the
/// next shape as they are taken (the sweep clears the changes as it reads
/// them). Each row's parts are split off the fronts of the band's slices
/// (the rows' starts by additions, not a multiply per row).
pub(crate) struct SweepRows<'b, const C: usize> {
    deltas: &'b mut [i32],
    heads: &'b mut [i32],
    acc: &'b mut [i32],
    tags: &'b mut [i32],
    palette: &'b [[i32; C]],
    dense: bool,
    y: i32,
    left: usize,
    w: usize,
}

impl<'b, const C: usize> Iterator for SweepRows<'b, C> {
    type Item = (i32, SweepRow<'b, C>);

    #[inline]
    fn next(&mut self) -> Option<(i32, SweepRow<'b, C>)> {
        let w = self.w;
        let n = tags::row_words(w);
        while self.left > 0 {
            self.left -= 1;
            let (deltas, d_rest) = core::mem::take(&mut self.deltas).split_at_mut_checked(w)?;
            let (head, h_rest) =
                core::mem::take(&mut self.heads).split_first_chunk_mut::<ROW_HEAD>()?;
            let (acc, a_rest) = core::mem::take(&mut self.acc).split_at_mut_checked(w * C)?;
            let (tags, t_rest) = core::mem::take(&mut self.tags).split_at_mut_checked(n)?;
            (self.deltas, self.heads, self.acc, self.tags) = (d_rest, h_rest, a_rest, t_rest);
            let y = self.y;
            self.y += 1;
            let [lo, hi, dlo, dhi] = head;
            let (l, h) = (
                core::mem::replace(lo, i32::MAX),
                core::mem::replace(hi, i32::MIN),
            );
            if l > h {
                continue;
            }
            return Some((
                y,
                SweepRow {
                    deltas,
                    acc,
                    tags,
                    palette: self.palette,
                    dense: self.dense,
                    lo: l.max(0) as usize,
                    hi: (h.max(0) as usize).min(w - 1),
                    drawn: (dlo, dhi),
                },
            ));
        }
        None
    }
}

impl<const C: usize> BandBuffer<'_, C> {
    /// The rows of frame rows `y_lo..y_hi` (clipped to the band) that a
    /// sweep composes ([`SweepRows`]).
    #[inline]
    pub(crate) fn sweep_rows(&mut self, y_lo: i32, y_hi: i32) -> SweepRows<'_, C> {
        let rows = self.rows_in_band(y_lo, y_hi);
        let w = usize::from(self.band.width);
        let first = usize::try_from(rows.start - self.band.y0).unwrap_or(0);
        let n = tags::row_words(w);
        SweepRows {
            deltas: self.deltas.get_mut(first * w..).unwrap_or_default(),
            heads: self.heads.get_mut(first * ROW_HEAD..).unwrap_or_default(),
            acc: self.acc.get_mut(first * w * C..).unwrap_or_default(),
            tags: self.tags.get_mut(first * n..).unwrap_or_default(),
            palette: self.palette.entries(),
            dense: self.palette.dense,
            y: rows.start,
            left: usize::try_from(rows.end - rows.start).unwrap_or(0),
            w,
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
        let mut cov = [0i32; 18];
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
        let mut cov = [0i32; 18];
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
        assert!(b.sweep_rows(10, 12).next().is_none());
    }

    #[test]
    fn windowed_band_addresses_frame_columns() {
        let mut acc = [0i32; 4];
        let mut cov = [0i32; 9];
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
