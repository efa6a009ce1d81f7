//! Post-filter: lightness-adaptive smoothing in CIELAB (seed 002).
//!
//! Takes resolved linear 12-bit pixels (gray `[u16; 1]` or RGB `[u16; 3]`,
//! sRGB primaries, D65 white), between band accumulation and tone; gives
//! linear 12-bit pixels of the same kind whose CIELAB lightness `L*` is
//! smoothed and whose `a*`, `b*` are kept, so colours do not shift.
//!
//! ## The method (seed 002, eqs. 3-1 to 3-3, table 4.1)
//!
//! Every pixel is taken to CIELAB (eq. 3-1). Only the lightness `f = L*` is
//! filtered, with the 4-neighbour Laplacian (eq. 3-2):
//!
//! ```text
//!             f(i, j-1)
//! f(i-1, j)  -4 f(i, j)  f(i+1, j)      ∇²f = sum of the four - 4 f
//!             f(i, j+1)                 g = f + k(f) ∇²f     (eq. 3-3)
//! ```
//!
//! `k` depends on the pixel's own `L*`, rounded to the nearest integer, by
//! table 4.1 ([`K_TWENTIETHS`]): 0 below 55 and from 97 on, at most 0.2 for
//! `L*` 82-89. With `k <= 0.2`, `g = (1 - 4k) f + k * (sum of neighbours)` is
//! a convex combination, so `g` stays in `[0, 100]`. The new `L*` sets a new
//! `Y`; `a*` and `b*` are kept, so `X` and `Z` follow `Y` as CIELAB requires
//! ([`Lab::lighten`]); the result goes back to linear RGB and is clamped to
//! the gamut (a saturated colour made lighter or darker may leave it).
//!
//! Outside the frame, a neighbour repeats the edge pixel.
//!
//! ## Which `L*`
//!
//! The CIE 1976 `L*`, with its linear segment below `Y/Yn = (6/29)³`, not the
//! seed's cube root alone: `116 (Y/Yn)^(1/3) - 16` is `-16` at black, while
//! the seed itself says `L*` runs from 0 to 100, and its infinite slope at
//! black would need an unbounded table to invert. The two agree exactly for
//! `L* >= 8`, so `k` (nonzero only from `L*` 55) and every pixel it touches
//! see the same value; only a neighbour darker than `L*` 8 enters the
//! Laplacian with the CIE value.
//!
//! ## Integer form
//!
//! `L* = 116 fy - 16` is linear in the cube-root value `fy`, so the filter
//! runs on `F = F_ONE * fy` ([`F_ONE`] = 65535, a resolution of 0.0018 `L*`):
//! `ΔF = round(k ∇²F)` and `F' = F + ΔF` is exactly eq. 3-3 scaled by
//! `F_ONE / 116`. Ranges: `F` in `[9039, 65535]`, so `|∇²F| < 2^18`; `k` is
//! held in Q15 (`<= 6554 < 2^13`, within `2^-16` of the printed value), so
//! `k ∇²F < 2^31` fits `i32`.
//!
//! When `ΔF = 0` (`k = 0`, or a flat neighbourhood) the input pixel is
//! copied, bit for bit (values above 4095, which the band buffer never
//! gives, are clamped to 4095); only pixels whose lightness changes go through the
//! conversion back.
//!
//! ## Per-pixel work
//!
//! For every pixel, once (its `F` is kept in a three-row scratch):
//! gray, one table look-up; RGB, the `Y` row of the matrix (3 multiplies)
//! and an interpolated look-up (1 multiply).
//! For every output pixel: 5 loads and 4 add/shift for the Laplacian, the
//! rounded `L*` (7 compares, [`LSTAR_STEPS`]), the `k` look-up and, when
//! `k != 0`, one multiply `k ∇²F`.
//! For a pixel whose lightness changes: gray, an interpolated inverse
//! look-up (1 multiply); RGB, the whole conversion: the `X` and `Z` rows
//! (6 multiplies) and their interpolated look-ups (2), three interpolated
//! inverse look-ups (3) and the inverse matrix (9 widening `i32 x i32 ->
//! i64` multiplies). The 18 matrix multiplies are a fact of colour
//! conversion; every nonlinear function is a table. The filter is the only
//! stage with per-pixel multiplies; it is optional.
//!
//! Measured on the host (x86-64, release, callgrind, a 128x128 image of
//! 4x4 blocks of light colours, 73 % of pixels changed): about 112
//! instructions per pixel for gray and 282 for RGB, the whole filter
//! included.
//!
//! Tables (flash): [`F_TABLE`] and [`F_INV_TABLE`], 8194 bytes each;
//! [`LSTAR_STEPS`] 200 bytes, [`K_TWENTIETHS`] 101, [`K_Q15`] 202, the two
//! matrices 72: about 16.6 KiB in all.
//!
//! ## Bands
//!
//! An output row needs the rows above and below. [`LightnessFilter::filter_band`]
//! takes a band of `rows` output rows *with one halo row above and below*
//! (`rows + 2` input rows, frame rows `y0 - 1 ..= y0 + rows`): render the
//! band one row taller at each end (a [`Band`](crate::Band) with
//! `y0 - 1` and `rows + 2`). Each output pixel depends only on its 3x3
//! neighbourhood of input pixels, so every band height gives the very same
//! frame as [`LightnessFilter::filter_frame`]. The cost: every band boundary
//! is rendered twice (two extra rows per band: `2 / rows` more raster work,
//! 200 % for bands of 1 row, 12.5 % for 16), plus an accumulation buffer two
//! rows taller, and a scratch of three rows of `u16`.
//!
//! ```
//! use softedge::postfilter::LightnessFilter;
//! // A 5x3 gray frame of L* 71 (k = 0.1) with one white pixel (L* 100, k = 0).
//! let mut frame = [[1700u16]; 15];
//! frame[7] = [4095];
//! let filter = LightnessFilter::new(5, 3).unwrap();
//! let mut out = [[0u16]; 15];
//! let mut scratch = [0u16; LightnessFilter::scratch_len(5)];
//! let stats = filter.filter_frame(&frame, &mut out, &mut scratch).unwrap();
//! assert_eq!(out[7], [4095]); // k = 0: unchanged
//! assert!(out[6][0] > 1700 && out[2][0] > 1700); // its neighbours get lighter
//! assert_eq!(out[0], [1700]); // flat neighbourhood: unchanged
//! assert_eq!(stats.changed, 4);
//! ```

mod errors;
mod lab;
mod tables;

pub use lab::Lab;
pub use tables::{
    F_BLACK, F_INV_TABLE, F_ONE, F_TABLE, K_FRAC, K_Q15, K_TWENTIETHS, LSTAR_STEPS, TABLE_LEN,
    T_FRAC, T_ONE,
};

use crate::band::MAX_WIDTH;
use crate::shade::LIN_MAX;

/// A pixel the filter can work on: gray `[u16; 1]` or RGB `[u16; 3]`,
/// linear 12-bit (values above 4095 are read as 4095).
///
/// ```
/// use softedge::postfilter::{LightnessPixel, F_ONE};
/// assert_eq!([4095u16].lightness_f(), F_ONE);
/// assert_eq!([4095u16; 3].lightness_f(), F_ONE);
/// assert_eq!([2048u16].lighten(0), ([2048], false));
/// assert_eq!([5000u16, 7, 4096].clipped(), [4095, 7, 4095]);
/// ```
pub trait LightnessPixel: Copy + sealed::Sealed {
    /// `F_ONE * f(Y/Yn)`: `L* = 116 F / F_ONE - 16`.
    fn lightness_f(self) -> i32;
    /// The pixel with `L*` changed by `116 delta_f / F_ONE` and `a*`, `b*`
    /// kept, clamped to `0..=4095`; `true` when clamping was needed.
    fn lighten(self, delta_f: i32) -> (Self, bool);
    /// The pixel with every channel clamped to `0..=4095` (how the filter
    /// copies a pixel it does not change; a no-op on resolved band values).
    fn clipped(self) -> Self;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for [u16; 1] {}
    impl Sealed for [u16; 3] {}
}

impl LightnessPixel for [u16; 1] {
    #[inline]
    fn clipped(self) -> Self {
        self.map(|v| v.min(LIN_MAX))
    }
    #[inline]
    fn lightness_f(self) -> i32 {
        lab::fy_of_gray(self[0])
    }
    #[inline]
    fn lighten(self, delta_f: i32) -> (Self, bool) {
        let f = self.lightness_f().saturating_add(delta_f);
        let (v, clamped) = Lab {
            fx: f,
            fy: f,
            fz: f,
        }
        .to_gray();
        ([v], clamped)
    }
}

impl LightnessPixel for [u16; 3] {
    #[inline]
    fn clipped(self) -> Self {
        self.map(|v| v.min(LIN_MAX))
    }
    #[inline]
    fn lightness_f(self) -> i32 {
        lab::fy_of_rgb(self)
    }
    #[inline]
    fn lighten(self, delta_f: i32) -> (Self, bool) {
        Lab::from_rgb(self).lighten(delta_f).to_rgb()
    }
}

/// Why the filter did not run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FilterError {
    /// Width or height is zero, or the width is over
    /// [`MAX_WIDTH`].
    BadSize,
    /// The input holds fewer pixels than the rows it must hold.
    InputTooShort,
    /// The scratch is shorter than [`LightnessFilter::scratch_len`].
    ScratchTooSmall,
    /// The output is shorter than a row (band) or the frame (frame).
    OutputTooSmall,
}

/// What one call of the filter did.
///
/// ```
/// use softedge::postfilter::FilterStats;
/// let s = FilterStats::default();
/// assert_eq!((s.changed, s.clamped), (0, 0));
/// ```
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FilterStats {
    /// Output pixels whose lightness changed (`ΔF != 0`); all others are
    /// copies of their input.
    pub changed: u32,
    /// Of those, pixels that left the RGB gamut and were clamped.
    pub clamped: u32,
}

/// The lightness filter of a `width x height` frame (seed 002).
///
/// ```
/// use softedge::postfilter::LightnessFilter;
/// let f = LightnessFilter::new(320, 240).unwrap();
/// assert_eq!((f.width(), f.height()), (320, 240));
/// assert!(LightnessFilter::new(0, 240).is_err());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LightnessFilter {
    width: u16,
    height: u16,
}

/// The three-row scratch of `F` values: slot `y mod 3` holds frame row `y`.
struct FRows<'s> {
    f: &'s mut [u16],
    width: usize,
    held: [i32; 3],
}

impl<'s> FRows<'s> {
    fn new(f: &'s mut [u16], width: usize) -> Self {
        Self {
            f,
            width,
            held: [i32::MIN; 3],
        }
    }

    /// Makes sure frame row `y` (whose pixels are `row`) is held.
    fn load<P: LightnessPixel>(&mut self, y: i32, row: &[P]) {
        let slot = y.rem_euclid(3) as usize;
        if self.held.get(slot) == Some(&y) {
            return;
        }
        let start = slot * self.width;
        if let Some(dst) = self.f.get_mut(start..start + self.width) {
            for (d, &p) in dst.iter_mut().zip(row) {
                // F is in F_BLACK..=F_ONE, within u16.
                *d = p.lightness_f() as u16;
            }
        }
        if let Some(h) = self.held.get_mut(slot) {
            *h = y;
        }
    }

    fn row(&self, y: i32) -> &[u16] {
        let start = y.rem_euclid(3) as usize * self.width;
        self.f.get(start..start + self.width).unwrap_or(&[])
    }
}

/// Filters one row: `input` is frame row `y`, `f_up`/`f_mid`/`f_down` the
/// `F` of rows `y - 1`, `y`, `y + 1` (edge rows repeated), all `width` long.
fn filter_row<P: LightnessPixel>(
    input: &[P],
    f_up: &[u16],
    f_mid: &[u16],
    f_down: &[u16],
    out: &mut [P],
    stats: &mut FilterStats,
) {
    let w = input
        .len()
        .min(f_up.len())
        .min(f_mid.len())
        .min(f_down.len())
        .min(out.len());
    for x in 0..w {
        // x < w <= every length: the indexing below is in range.
        let c = i32::from(f_mid[x]);
        let k = i32::from(
            tables::K_Q15
                .get(tables::lstar_round(c))
                .copied()
                .unwrap_or(0),
        );
        let p = input[x];
        if k == 0 {
            out[x] = p.clipped();
            continue;
        }
        let left = i32::from(f_mid[x.saturating_sub(1)]);
        let right = i32::from(f_mid[(x + 1).min(w - 1)]);
        let lap = i32::from(f_up[x]) + i32::from(f_down[x]) + left + right - (c << 2);
        let delta = (lap * k + (1 << (K_FRAC - 1))) >> K_FRAC;
        if delta == 0 {
            out[x] = p.clipped();
            continue;
        }
        let (q, clamped) = p.lighten(delta);
        out[x] = q;
        stats.changed += 1;
        stats.clamped += u32::from(clamped);
    }
}

impl LightnessFilter {
    /// A filter for a `width x height` frame: `width` in
    /// `1..=MAX_WIDTH`, `height >= 1`.
    ///
    /// ```
    /// use softedge::postfilter::{FilterError, LightnessFilter};
    /// assert!(LightnessFilter::new(2048, 1).is_ok());
    /// assert_eq!(LightnessFilter::new(2049, 1), Err(FilterError::BadSize));
    /// ```
    pub const fn new(width: u16, height: u16) -> Result<Self, FilterError> {
        if width == 0 || width > MAX_WIDTH || height == 0 {
            return Err(FilterError::BadSize);
        }
        Ok(Self { width, height })
    }

    /// Frame width in pixels.
    ///
    /// ```
    /// # use softedge::postfilter::LightnessFilter;
    /// assert_eq!(LightnessFilter::new(8, 4).unwrap().width(), 8);
    /// ```
    pub const fn width(&self) -> u16 {
        self.width
    }

    /// Frame height in pixels.
    ///
    /// ```
    /// # use softedge::postfilter::LightnessFilter;
    /// assert_eq!(LightnessFilter::new(8, 4).unwrap().height(), 4);
    /// ```
    pub const fn height(&self) -> u16 {
        self.height
    }

    /// `u16`s of scratch the filter needs: three rows of `F` values.
    ///
    /// ```
    /// # use softedge::postfilter::LightnessFilter;
    /// assert_eq!(LightnessFilter::scratch_len(320), 960);
    /// ```
    pub const fn scratch_len(width: u16) -> usize {
        3 * width as usize
    }

    /// Filters the whole frame: `frame` and `out` hold `width * height`
    /// pixels, row by row.
    ///
    /// ```
    /// use softedge::postfilter::LightnessFilter;
    /// let frame = [[3000u16, 2000, 1000]; 6];
    /// let mut out = [[0u16; 3]; 6];
    /// let mut scratch = [0u16; LightnessFilter::scratch_len(3)];
    /// let f = LightnessFilter::new(3, 2).unwrap();
    /// f.filter_frame(&frame, &mut out, &mut scratch).unwrap();
    /// assert_eq!(out, frame); // flat: unchanged
    /// ```
    pub fn filter_frame<P: LightnessPixel>(
        &self,
        frame: &[P],
        out: &mut [P],
        scratch: &mut [u16],
    ) -> Result<FilterStats, FilterError> {
        let w = usize::from(self.width);
        let h = usize::from(self.height);
        if frame.len() < w * h {
            return Err(FilterError::InputTooShort);
        }
        if out.len() < w * h {
            return Err(FilterError::OutputTooSmall);
        }
        let f = scratch
            .get_mut(..Self::scratch_len(self.width))
            .ok_or(FilterError::ScratchTooSmall)?;
        let mut rows = FRows::new(f, w);
        let mut stats = FilterStats::default();
        let row_of = |y: i32| {
            frame
                .get(y as usize * w..(y as usize + 1) * w)
                .unwrap_or(&[])
        };
        let last = i32::from(self.height) - 1;
        for (y, out_row) in (0..=last).zip(out.chunks_exact_mut(w)) {
            let (up, down) = ((y - 1).max(0), (y + 1).min(last));
            for yy in [up, y, down] {
                rows.load(yy, row_of(yy));
            }
            filter_row(
                row_of(y),
                rows.row(up),
                rows.row(y),
                rows.row(down),
                out_row,
                &mut stats,
            );
        }
        Ok(stats)
    }

    /// Filters one band: output frame rows `y0 .. y0 + rows` (those inside
    /// the frame), each written to `out_row` and handed to
    /// `emit(frame_row, out_row)`.
    ///
    /// `input` holds `rows + 2` rows of `width` pixels: frame rows
    /// `y0 - 1 ..= y0 + rows`, one halo row above and below the band. Input
    /// rows outside the frame are never read (the edge row is repeated
    /// instead), so they may hold anything. The output is bit for bit that
    /// of [`filter_frame`](Self::filter_frame) for every band height.
    ///
    /// ```
    /// use softedge::postfilter::LightnessFilter;
    /// use softedge::{BandBuffer, Bands, RenderStyle, SubPoint, Triangle};
    /// const W: u16 = 16;
    /// const H: u16 = 12;
    /// const ROWS: u16 = 4;
    /// // The accumulation buffer holds the band and its two halo rows.
    /// let mut acc = [0i32; BandBuffer::<1>::acc_len(W, ROWS + 2)];
    /// let mut cover = [0i32; BandBuffer::<1>::cover_len(W, ROWS + 2)];
    /// let mut lin = [[0u16; 1]; (W * (ROWS + 2)) as usize];
    /// let mut scratch = [0u16; LightnessFilter::scratch_len(W)];
    /// let mut out_row = [[0u16; 1]; W as usize];
    /// let tri = Triangle::flat(
    ///     [SubPoint::from_px(0, 0), SubPoint::from_px(16, 3), SubPoint::from_px(2, 12)],
    ///     [1000],
    /// );
    /// let filter = LightnessFilter::new(W, H).unwrap();
    /// let mut frame = vec![0u16; (W * H) as usize];
    /// for band in Bands::new(W, H, ROWS) {
    ///     let halo = softedge::Band { y0: band.y0 - 1, rows: band.rows + 2, ..band };
    ///     let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, halo).unwrap();
    ///     buf.clear([3000]);
    ///     tri.draw(&mut buf, &RenderStyle::default()).unwrap();
    ///     for (r, row) in lin.chunks_exact_mut(W as usize).enumerate() {
    ///         buf.resolve_row(halo.y0 + r as i32, row);
    ///     }
    ///     filter
    ///         .filter_band(band.y0, band.rows, &lin, &mut scratch, &mut out_row, |y, row| {
    ///             for (x, p) in row.iter().enumerate() {
    ///                 frame[y as usize * W as usize + x] = p[0];
    ///             }
    ///         })
    ///         .unwrap();
    /// }
    /// assert_eq!(frame[W as usize * H as usize - 1], 3000); // far from the edge
    /// ```
    pub fn filter_band<P: LightnessPixel>(
        &self,
        y0: i32,
        rows: u16,
        input: &[P],
        scratch: &mut [u16],
        out_row: &mut [P],
        mut emit: impl FnMut(i32, &[P]),
    ) -> Result<FilterStats, FilterError> {
        let w = usize::from(self.width);
        if input.len() < w * (usize::from(rows) + 2) {
            return Err(FilterError::InputTooShort);
        }
        let f = scratch
            .get_mut(..Self::scratch_len(self.width))
            .ok_or(FilterError::ScratchTooSmall)?;
        let out_row = out_row.get_mut(..w).ok_or(FilterError::OutputTooSmall)?;
        let mut f_rows = FRows::new(f, w);
        let mut stats = FilterStats::default();
        let last = i32::from(self.height) - 1;
        let first_in = i64::from(y0) - 1; // frame row of input row 0
        let row_of = |y: i32| {
            let r = (i64::from(y) - first_in) as usize; // y in y0 - 1 ..= y0 + rows
            input.get(r * w..(r + 1) * w).unwrap_or(&[])
        };
        let y_start = y0.max(0);
        let y_end = y0.saturating_add(i32::from(rows)).min(last + 1);
        for y in y_start..y_end {
            let (up, down) = ((y - 1).max(0), (y + 1).min(last));
            for yy in [up, y, down] {
                f_rows.load(yy, row_of(yy));
            }
            filter_row(
                row_of(y),
                f_rows.row(up),
                f_rows.row(y),
                f_rows.row(down),
                out_row,
                &mut stats,
            );
            emit(y, out_row);
        }
        Ok(stats)
    }
}
