//! The depth buffer of one band: a depth and a coverage count per pixel.

use crate::band::{Band, BandError, MAX_WIDTH};

/// Depth and coverage of one band's pixels, over caller-provided storage.
///
/// - `depth`: 16 bits per pixel, larger is nearer (seed 004); cleared to 0,
///   the farthest depth. Sixteen bits give 65 536 depth steps: for a scene
///   4 units deep, 1/16384 unit, far below one pixel for the displays this
///   library serves (a 240 px view across 4 units is 60 px per unit), so
///   two surfaces are ordered wrongly only where they are closer in depth
///   than that; 32-bit depth would double the RAM for no visible change.
/// - `covered`: how much of the pixel surfaces already claim, in 1/32768 px
///   (`FULL`, 1/32768 px): what lets anti-aliased edges meet the z-buffer
///   (see [`hsr`](crate::hsr)).
///
/// For 240x240 and 16-row bands that is `2 * 2 * 240 * 16` = 15 360 bytes
/// next to the band's accumulator.
#[derive(Debug)]
pub struct DepthBuffer<'a> {
    depth: &'a mut [u16],
    covered: &'a mut [u16],
    band: Band,
}

impl<'a> DepthBuffer<'a> {
    /// `u16`s needed for each of `depth` and `covered`: one per pixel.
    pub const fn len(width: u16, rows: u16) -> usize {
        width as usize * rows as usize
    }

    /// A depth buffer for `band` (longer slices are fine). Cleared.
    pub fn new(
        depth: &'a mut [u16],
        covered: &'a mut [u16],
        band: Band,
    ) -> Result<Self, BandError> {
        let y_ok = band.y0.unsigned_abs() <= crate::geom::COORD_LIMIT_PX as u32;
        if band.width == 0 || band.rows == 0 || band.width > MAX_WIDTH || !y_ok {
            return Err(BandError::BadBand);
        }
        let n = Self::len(band.width, band.rows);
        if depth.len() < n || covered.len() < n {
            return Err(BandError::DepthTooSmall);
        }
        let mut buf = Self {
            depth,
            covered,
            band,
        };
        buf.clear();
        Ok(buf)
    }

    /// The band this buffer holds.
    pub fn band(&self) -> Band {
        self.band
    }

    /// Every pixel empty and at the farthest depth (0).
    pub fn clear(&mut self) {
        let n = Self::len(self.band.width, self.band.rows);
        if let Some(d) = self.depth.get_mut(..n) {
            d.iter_mut().for_each(|z| *z = 0);
        }
        if let Some(c) = self.covered.get_mut(..n) {
            c.iter_mut().for_each(|c| *c = 0);
        }
    }

    /// Ends the [`ZPass::Centres`](super::ZPass::Centres) pass: each
    /// pixel's nearest centre depth becomes its threshold (less the depth
    /// slope across a pixel of the surface there, which that pass kept in
    /// the coverage slot) and the coverage is emptied for the drawing
    /// passes.
    pub fn finish_centres(&mut self) {
        let n = Self::len(self.band.width, self.band.rows);
        if let (Some(d), Some(c)) = (self.depth.get_mut(..n), self.covered.get_mut(..n)) {
            for (z, k) in d.iter_mut().zip(c.iter_mut()) {
                *z = z.saturating_sub(*k);
                *k = 0;
            }
        }
    }

    /// The depth at frame pixel `(x, y)`, or `None` outside the band: the
    /// nearest depth drawn (single pass) or the threshold of the drawing
    /// passes (three passes).
    pub fn depth(&self, x: i32, y: i32) -> Option<u16> {
        self.depth.get(self.index(x, y)?).copied()
    }

    /// How much of frame pixel `(x, y)` is covered, in 1/4096 px, or `None`
    /// outside the band.
    pub fn covered(&self, x: i32, y: i32) -> Option<u16> {
        self.covered.get(self.index(x, y)?).copied()
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let r = y.checked_sub(self.band.y0)?;
        if x < 0 || x >= i32::from(self.band.width) || r < 0 || r >= i32::from(self.band.rows) {
            return None;
        }
        Some(r as usize * usize::from(self.band.width) + x as usize)
    }

    /// Row `r` of the band: (depths, coverage counts).
    pub(crate) fn row_mut(&mut self, r: usize) -> Option<(&mut [u16], &mut [u16])> {
        let w = usize::from(self.band.width);
        let d = self.depth.get_mut(r * w..(r + 1) * w)?;
        let c = self.covered.get_mut(r * w..(r + 1) * w)?;
        Some((d, c))
    }
}

/// Full coverage as stored in [`DepthBuffer`]: 1/32768 px (the band's
/// coverage, 1/65536 px, with its last bit dropped, so that a whole pixel
/// fits a `u16`).
pub(crate) const FULL: u16 = 1 << FULL_BITS;
/// `log2(FULL)`.
pub(crate) const FULL_BITS: u32 = 15;
