//! The frame loop: bands drawn, toned and flushed to a display, so that
//! users do not write the band loop by hand.
//!
//! Takes any embedded-graphics `DrawTarget` (a write-only SPI display is
//! fine: nothing is read back), a display [`Profile`] (the tone stage: γ
//! table and pixel format, or dithering to 1 bit) and a drawing closure;
//! gives the display one `fill_contiguous` per band over the band's
//! rectangle, a DMA-friendly stream of rows.
//!
//! Per band the renderer hands the closure a [`Canvas`] over the band (the
//! closure is called once per band, so keep the scene in data it can read
//! again), then streams the band through the profile: each pixel's one
//! rounding to 12 bits, the profile's colour, and the accumulator reset to
//! the background for the next band in the same pass (no separate clear).
//! Rows that no shape touched are sent as the background's colour without
//! being resolved, when the profile has a uniform colour for it.
//!
//! [`Renderer::render_window`] redraws only a rectangle of the frame: bands
//! of that width, one window set-up per band on the target; the shapes
//! outside it cost their bounds test only.

mod errors;
#[cfg(feature = "display-interface")]
#[cfg_attr(docsrs, doc(cfg(feature = "display-interface")))]
pub mod pages;
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use crate::band::{BandBuffer, BandError, Bands};
use crate::canvas::{Canvas, ShapeCache, ShapeEntry, Skipped, WalkCache, WalkSlot};
use crate::color::IntoLinear;
use crate::path::Segment as PathSegment;
use crate::tone::profile::{Profile, ToneRow};

/// Why a frame was not rendered, or not completely.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub enum RenderError<T, E> {
    /// The band buffers do not fit the frame's bands.
    Band(BandError),
    /// The frame is larger than the display (`frame` vs `display`, px).
    Size {
        /// Frame width and height.
        frame: (u16, u16),
        /// Display width and height.
        display: (u32, u32),
    },
    /// The drawing closure failed in the band starting at row `band_y0`;
    /// the rest of the frame was drawn and sent.
    Draw {
        /// First row of the band where it first failed.
        band_y0: i32,
        /// What it returned.
        error: E,
    },
    /// The display reported an error (the frame stops there).
    Target(T),
}

/// What a rendered frame skipped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FrameReport {
    /// Shapes rejected (the most in any one band), and the first one's
    /// place in the drawing order and reason.
    pub skipped: Skipped,
    /// Bands drawn.
    pub bands: u32,
}

/// Renders frames band by band into any `DrawTarget`, over caller-provided
/// buffers sized for `band_rows` rows of the frame's width.
///
/// ```
/// use embedded_graphics_core::pixelcolor::Gray8;
/// # use embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, Pixel};
/// # struct Screen(Vec<u8>);
/// # impl OriginDimensions for Screen { fn size(&self) -> Size { Size::new(16, 12) } }
/// # impl DrawTarget for Screen {
/// #     type Color = Gray8;
/// #     type Error = core::convert::Infallible;
/// #     fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, px: I) -> Result<(), Self::Error> {
/// #         for Pixel(p, c) in px { if p.x >= 0 && p.x < 16 && p.y >= 0 && p.y < 12 { self.0[(p.y * 16 + p.x) as usize] = embedded_graphics_core::pixelcolor::GrayColor::luma(&c); } }
/// #         Ok(())
/// #     }
/// # }
/// use softedge::canvas::{Contour, WalkSlot};
/// use softedge::geom::FinePoint;
/// use softedge::render::Renderer;
/// use softedge::style::{Blend, FillRule, Opacity};
/// use softedge::tone::{format::Gray8Format, Curve};
/// use softedge::BandBuffer;
/// const W: u16 = 16;
/// const ROWS: u16 = 4;
/// let mut acc = [0i32; BandBuffer::<1>::acc_len(W, ROWS)];
/// let mut cover = [0i32; BandBuffer::<1>::cover_len(W, ROWS)];
/// let mut slots = [WalkSlot::<1>::EMPTY; 8];
/// let mut screen = Screen(vec![0; 16 * 12]);
/// let p = |x, y| FinePoint::from_px(x, y);
/// let tri = [p(0, 0), p(16, 0), p(0, 12)];
/// let mut renderer = Renderer::new(&mut acc, &mut cover, &mut slots, W, 12, ROWS).unwrap();
/// static GRAY: Gray8Format = Gray8Format::new(Curve::Srgb);
/// renderer
///     .render(&mut screen, &GRAY, [0], |c| {
///         c.fill(&Contour(&tri), [4095], FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
///     })
///     .unwrap();
/// assert_eq!(screen.0[0], 255);
/// assert_eq!(screen.0[16 * 12 - 1], 0);
/// ```
#[derive(Debug)]
pub struct Renderer<'a, const C: usize> {
    acc: &'a mut [i32],
    cover: &'a mut [i32],
    slots: &'a mut [WalkSlot<C>],
    /// The last frame's cache hits and misses.
    stats: (u32, u32),
    width: u16,
    height: u16,
    band_rows: u16,
    /// The accumulator is known to hold this background (it is reset to it
    /// as each band is sent).
    holds: Option<[u16; C]>,
    /// The shape cache's segments and entries, kept from frame to frame.
    shapes: Option<(&'a mut [PathSegment], &'a mut [ShapeEntry])>,
    /// The last frame's outlines found kept, and described into the cache.
    shape_stats: (u32, u32),
}

impl<'a, const C: usize> Renderer<'a, C> {
    /// A renderer for a `width x height` frame in bands of `band_rows`
    /// rows, over `acc` and `cover` (at least
    /// [`BandBuffer::acc_len`] and [`BandBuffer::cover_len`] for
    /// `width x band_rows`) and `slots` for the walk cache (any number,
    /// none too; see [`WalkCache`]).
    pub fn new(
        acc: &'a mut [i32],
        cover: &'a mut [i32],
        slots: &'a mut [WalkSlot<C>],
        width: u16,
        height: u16,
        band_rows: u16,
    ) -> Result<Self, BandError> {
        let rows = band_rows.max(1);
        if width == 0
            || height == 0
            || width > crate::band::MAX_WIDTH
            || height > crate::band::MAX_WIDTH
        {
            return Err(BandError::BadBand);
        }
        if acc.len() < BandBuffer::<C>::acc_len(width, rows) {
            return Err(BandError::AccTooSmall);
        }
        if cover.len() < BandBuffer::<C>::cover_len(width, rows) {
            return Err(BandError::CoverTooSmall);
        }
        Ok(Self {
            acc,
            cover,
            slots,
            stats: (0, 0),
            width,
            height,
            band_rows: rows,
            holds: None,
            shapes: None,
            shape_stats: (0, 0),
        })
    }

    /// With a cache of shape outlines over `segments` (16 bytes each) and
    /// `entries` (one a shape; [`ShapeEntry::SIZE`] bytes each), kept from
    /// frame to frame: the circles, ellipses, arcs, sectors, rectangles,
    /// rounded rectangles and lines of the scene, filled or stroked
    /// without dashes, are described once, in the first band that draws
    /// them, and filled from the cache in every later band and frame
    /// ([`ShapeCache`]). The same pixels as without; a shape whose outline
    /// does not fit is drawn directly. Start with entries of
    /// [`ShapeEntry::EMPTY`]; they may be shared by renderers made for each
    /// frame (the frames are counted in them).
    pub fn with_shape_cache(
        mut self,
        segments: &'a mut [PathSegment],
        entries: &'a mut [ShapeEntry],
    ) -> Self {
        self.shapes = Some((segments, entries));
        self
    }

    /// The shape cache's outlines found kept, and outlines described into
    /// it, in the last frame.
    pub fn shape_stats(&self) -> (u32, u32) {
        self.shape_stats
    }

    /// The walk cache's hits and misses in the last frame.
    pub fn cache_stats(&self) -> (u32, u32) {
        self.stats
    }

    /// Renders one frame: per band, the background, the closure's shapes,
    /// the profile, one `fill_contiguous`.
    ///
    /// The background is any colour the canvas converts (an
    /// embedded-graphics colour as sRGB, or linear `[u16; C]`).
    ///
    /// A shape the canvas rejects is skipped and reported
    /// ([`FrameReport::skipped`]: how many, the first one's place in the
    /// drawing order and why); the rest of the frame is drawn. The styled
    /// shapes' [`draw`](crate::draw::AaDrawable::draw) returns `Ok` for a
    /// rejected shape too, so `?` after it in the closure is safe. An
    /// error the closure returns itself (or passes on with `?` from text's
    /// `draw` or the canvas's own `fill`-like methods, which return the
    /// rejection as well as record it) is reported after the frame, which
    /// is drawn and sent whole (each band as far as the closure drew it).
    pub fn render<D, P, B, E, F>(
        &mut self,
        target: &mut D,
        mut profile: P,
        background: B,
        draw: F,
    ) -> Result<FrameReport, RenderError<D::Error, E>>
    where
        D: DrawTarget + OriginDimensions,
        B: IntoLinear<C>,
        P: Profile<C, Color = D::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, D::Color>) -> Result<(), E>,
    {
        let size = target.size();
        if u32::from(self.width) > size.width || u32::from(self.height) > size.height {
            return Err(RenderError::Size {
                frame: (self.width, self.height),
                display: (size.width, size.height),
            });
        }
        let bands = Bands::new(self.width, self.height, self.band_rows);
        self.frame(target, &mut profile, background.into_linear(), bands, draw)
    }

    /// Renders only the window `area` of the frame (clipped to it): what a
    /// small change costs. The target gets one `fill_contiguous` per band
    /// over the window's part of the band. With a dithering profile, the
    /// window is dithered on its own (Bayer matches the full frame; error
    /// diffusion restarts at the window's edge).
    pub fn render_window<D, P, B, E, F>(
        &mut self,
        target: &mut D,
        mut profile: P,
        background: B,
        area: Rectangle,
        draw: F,
    ) -> Result<FrameReport, RenderError<D::Error, E>>
    where
        D: DrawTarget + OriginDimensions,
        B: IntoLinear<C>,
        P: Profile<C, Color = D::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, D::Color>) -> Result<(), E>,
    {
        let frame = Rectangle::new(
            Point::zero(),
            Size::new(u32::from(self.width), u32::from(self.height)),
        );
        let area = area.intersection(&frame);
        let (w, h) = (area.size.width as u16, area.size.height as u16);
        if w == 0 || h == 0 {
            return Ok(FrameReport::default());
        }
        let bands = Bands::window(area.top_left.x, area.top_left.y, w, h, self.band_rows);
        self.frame(target, &mut profile, background.into_linear(), bands, draw)
    }

    fn frame<D, P, E, F>(
        &mut self,
        target: &mut D,
        profile: &mut P,
        background: [u16; C],
        bands: Bands,
        mut draw: F,
    ) -> Result<FrameReport, RenderError<D::Error, E>>
    where
        D: DrawTarget,
        P: Profile<C, Color = D::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, D::Color>) -> Result<(), E>,
    {
        let bg = background.map(|v| v.min(crate::LIN_MAX));
        WalkCache::new(&mut *self.slots).clear();
        self.stats = (0, 0);
        self.shape_stats = (0, 0);
        let shape_frame = self
            .shapes
            .as_ref()
            .map_or(0, |(_, entries)| ShapeCache::next_frame(entries));
        profile.start_frame();
        let mut report = FrameReport::default();
        let mut failed: Option<(i32, E)> = None;
        for band in bands {
            let mut buf = match self.holds {
                Some(h) if h == bg && band.width == self.width => {
                    BandBuffer::reuse(&mut *self.acc, &mut *self.cover, band, bg)
                }
                _ => BandBuffer::new(&mut *self.acc, &mut *self.cover, band).map(|mut b| {
                    b.clear(bg);
                    b
                }),
            }
            .map_err(RenderError::Band)?;
            // The band is cleared to `bg` when it is sent.
            self.holds = None;
            let mut canvas = Canvas::typed(&mut buf, Some(WalkCache::new(&mut *self.slots)))
                .with_frame(self.width, self.height);
            if let Some((segments, entries)) = self.shapes.as_mut() {
                canvas = canvas.with_shapes(ShapeCache::new(segments, entries, shape_frame));
            }
            let r = draw(&mut canvas);
            let skipped = canvas.skipped();
            let (hits, misses) = canvas.cache_stats();
            self.stats = (self.stats.0 + hits, self.stats.1 + misses);
            let (kept, described) = canvas.shape_stats();
            self.shape_stats = (self.shape_stats.0 + kept, self.shape_stats.1 + described);
            if skipped.count > report.skipped.count {
                report.skipped.count = skipped.count;
            }
            if report.skipped.first.is_none() {
                report.skipped.first = skipped.first;
            }
            if let (Err(e), None) = (r, &failed) {
                failed = Some((band.y0, e));
            }
            send(&mut buf, target, &mut *profile).map_err(RenderError::Target)?;
            self.holds = (band.width == self.width).then_some(bg);
            report.bands += 1;
        }
        match failed {
            Some((band_y0, error)) => Err(RenderError::Draw { band_y0, error }),
            None => Ok(report),
        }
    }
}

/// Sends a band through `profile` to `target` in one `fill_contiguous`,
/// resetting the accumulator to the background as it goes.
fn send<D, P, const C: usize>(
    buf: &mut BandBuffer<'_, C>,
    target: &mut D,
    profile: &mut P,
) -> Result<(), D::Error>
where
    D: DrawTarget,
    P: Profile<C, Color = D::Color>,
{
    let band = buf.band();
    let area = Rectangle::new(
        Point::new(band.x0, band.y0),
        Size::new(u32::from(band.width), u32::from(band.rows)),
    );
    let uniform = profile.uniform(buf.background());
    let parts = buf.flush_parts();
    let mut rows = Segments {
        acc: parts.acc,
        extents: parts.extents,
        bg: parts.background,
        profile,
        uniform,
        x0: band.x0,
        y: band.y0 - 1,
        width: band.width,
        rows_left: band.rows,
        // A row is to start.
        col: band.width,
        dirty: 0..0,
    };
    let pixels = BandPixels {
        seg: &mut [],
        left: 0,
        x: band.x0,
        uniform,
        rows: &mut rows,
    };
    target.fill_contiguous(&area, pixels)
}

/// A band's pixels in row order, through the profile; each pixel's
/// accumulator reset to the background as it is read.
///
/// A row is up to three segments: columns nothing was drawn on left and
/// right of its drawn extent, sent as the background's colour when the
/// profile has one for every position (their accumulator already holds the
/// background), and the drawn extent, resolved pixel by pixel. A pixel
/// segment is its own count (the slice of its accumulator not sent yet),
/// a uniform one a count down. Finding the next segment is the slow path,
/// out of line and on its own state ([`Segments`]): the per-pixel state
/// here never has its address taken, so the compiler keeps it in
/// registers (the Cortex-M0 has eight low ones).
struct BandPixels<'r, 'x, P: Profile<C>, const C: usize> {
    /// The current pixel segment's accumulator not sent yet (empty in a
    /// uniform segment).
    seg: &'x mut [i32],
    /// Pixels left in the current uniform segment (0 in a pixel segment).
    left: u32,
    /// Frame column of `seg`'s first pixel.
    x: i32,
    /// The colour of uniform pixels (a copy of `rows.uniform`, read here
    /// from a register rather than through `rows`).
    uniform: Option<P::Color>,
    /// The band's segments after the current one (a local of [`send`]'s,
    /// by reference: its address is taken by the slow path).
    rows: &'r mut Segments<'x, P, C>,
}

/// One segment of a band row: its accumulator (pixels to resolve) or a
/// count of uniform pixels, and the frame column it starts at.
struct Segment<'x> {
    acc: &'x mut [i32],
    uniform: u32,
    x: i32,
}

/// The band's rows cut into segments (see [`BandPixels`]).
struct Segments<'x, P: Profile<C>, const C: usize> {
    /// The band's accumulator after the current segment (rows are
    /// contiguous).
    acc: &'x mut [i32],
    /// Per row, the drawn extent (see [`BandBuffer::flush_parts`]).
    extents: crate::band::DrawnExtents<'x>,
    bg: [i32; C],
    profile: &'x mut P,
    uniform: Option<P::Color>,
    x0: i32,
    /// Current frame row, and rows still to start.
    y: i32,
    width: u16,
    rows_left: u16,
    /// Band column where the next segment starts.
    col: u16,
    /// Drawn columns of the current row.
    dirty: core::ops::Range<u16>,
}

impl<'x, P: Profile<C>, const C: usize> Segments<'x, P, C> {
    /// The next non-empty segment (moving to the next row when the row is
    /// done); `None` at the band's end.
    #[cold]
    #[inline(never)]
    fn next_segment(&mut self) -> Option<Segment<'x>> {
        loop {
            if self.col >= self.width {
                if self.rows_left == 0 {
                    return None;
                }
                self.rows_left -= 1;
                self.y += 1;
                self.col = 0;
                self.dirty = self.extents.take(self.y);
                if self.uniform.is_none() {
                    self.dirty = 0..self.width;
                }
                if !self.dirty.is_empty() {
                    let n = usize::from(self.width) * C;
                    if let Some(row) = self.acc.get(..n) {
                        self.profile.start_row(&ToneRow::new(self.y, self.x0, row));
                    }
                }
            }
            let (pixels, end) = if self.col < self.dirty.start {
                (false, self.dirty.start)
            } else if self.col < self.dirty.end {
                (true, self.dirty.end)
            } else {
                (false, self.width)
            };
            let n = end.saturating_sub(self.col);
            let acc = core::mem::take(&mut self.acc);
            let (seg, rest) = acc.split_at_mut((usize::from(n) * C).min(acc.len()));
            self.acc = rest;
            let x = self.x0 + i32::from(self.col);
            self.col = end;
            if n > 0 {
                return Some(match (pixels, self.uniform) {
                    // Those pixels' accumulator holds the background.
                    (false, Some(_)) => Segment {
                        acc: &mut [],
                        uniform: u32::from(n),
                        x,
                    },
                    _ => Segment {
                        acc: seg,
                        uniform: 0,
                        x,
                    },
                });
            }
        }
    }
}

impl<P: Profile<C>, const C: usize> Iterator for BandPixels<'_, '_, P, C> {
    type Item = P::Color;

    #[inline]
    fn next(&mut self) -> Option<P::Color> {
        loop {
            // A pixel of a pixel segment: its one rounding, its reset to
            // the background, its colour. (The length is tested before the
            // slice is taken, so a uniform pixel does not write it.)
            if self.seg.len() >= C {
                if let Some((px, rest)) =
                    core::mem::take(&mut self.seg).split_first_chunk_mut::<C>()
                {
                    self.seg = rest;
                    let x = self.x;
                    self.x += 1;
                    let mut lin = [0u16; C];
                    for ch in 0..C {
                        lin[ch] = crate::band::resolve(px[ch]);
                        px[ch] = self.rows.bg[ch];
                    }
                    return Some(self.rows.profile.color(x, self.rows.y, lin));
                }
            }
            if self.left > 0 {
                self.left -= 1;
                return self.uniform;
            }
            let next = self.rows.next_segment()?;
            (self.seg, self.left, self.x) = (next.acc, next.uniform, next.x);
        }
    }
}
