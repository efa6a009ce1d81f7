//! The frame loop: bands drawn, toned and flushed to a display, so that
//! users do not write the band loop by hand.
//!
//! Takes any embedded-graphics `DrawTarget` (a write-only SPI display is
//! fine: nothing is read back), a display [`Profile`] (the tone stage: γ
//! table and pixel format, or dithering to 1 bit) and a drawing closure;
//! gives the display one `fill_contiguous` per band over the band's
//! drawn columns (those any of its rows was drawn on, out to multiples of
//! 4), a DMA-friendly stream of rows, and the background left and right
//! of them in one `fill_solid` a side (a band nothing was drawn on, one
//! `fill_solid` of the background's colour). Every column is streamed
//! when the profile's background colour depends on the place (a dither
//! of a mid gray), when a side would be narrower than 16 columns, and to
//! a display whose pixels are smaller than a byte (a 1-bit OLED's pages,
//! 2- and 4-bit panels pack whole rows into bytes). A display that sends
//! bands by DMA can lend its buffer instead ([`BandTarget`],
//! [`Renderer::render_lent`]): the band's colours are then made in that
//! buffer, with no stream of pixels.
//!
//! Per band the renderer hands the closure a [`Canvas`] over the band (the
//! closure is called once per band, so keep the scene in data it can read
//! again), then makes the band's colours in its scratch and streams them
//! from there: a pixel that an opaque flat colour covers whole gets that
//! colour toned once for the band (its tag, see `band::tags`), any other
//! its one rounding to 12 bits and the profile's colour; columns left and
//! right of what a row holds besides the background get the background's
//! colour, when the profile has one colour for it everywhere. Each pixel
//! sent is reset to the background for the next band (no separate clear).
//! Made in the scratch and streamed, or made in a lent buffer: one toning
//! (`tone_band`) for both.
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
use embedded_graphics_core::pixelcolor::raw::RawData;
use embedded_graphics_core::pixelcolor::PixelColor;
use embedded_graphics_core::primitives::Rectangle;

use crate::band::tags::{self, PALETTE};
use crate::band::{resolve, BandBuffer, BandError, Bands};
use crate::canvas::{Canvas, ShapeCache, ShapeEntry, Skipped, WalkCache, WalkSlot};
use crate::color::IntoLinear;
use crate::path::Segment as PathSegment;
pub use crate::tone::format::RawColor;
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
    /// The buffer a [`BandTarget`] lends holds fewer pixels than a band
    /// (the frame stops there).
    Buffer {
        /// Pixels of the band (its width times its rows).
        needed: usize,
        /// Pixels the buffer holds.
        got: usize,
    },
}

/// One pixel's raw bits as a display's buffer holds them: `u8`, `u16` or
/// `u32` (embedded-graphics' storage of its colours' raw data: `u16` for
/// `Rgb565`, `u8` for `Gray8` and `BinaryColor`).
pub trait RawPixel: Copy + sealed::Sealed {
    /// Bits it holds.
    const BITS: usize;
    /// The low [`BITS`](Self::BITS) of raw colour bits `raw`.
    fn from_raw(raw: u32) -> Self;
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for u8 {}
    impl Sealed for u16 {}
    impl Sealed for u32 {}
}

impl RawPixel for u8 {
    const BITS: usize = 8;
    #[inline(always)]
    fn from_raw(raw: u32) -> Self {
        raw as u8
    }
}

impl RawPixel for u16 {
    const BITS: usize = 16;
    #[inline(always)]
    fn from_raw(raw: u32) -> Self {
        raw as u16
    }
}

impl RawPixel for u32 {
    const BITS: usize = 32;
    #[inline(always)]
    fn from_raw(raw: u32) -> Self {
        raw
    }
}

/// A display that lends the renderer a buffer for each band's pixels and
/// sends it itself, as a DMA flush does ([`Renderer::render_lent`]): the
/// band's colours are made in that buffer, as raw bits, with no stream of
/// pixels through `fill_contiguous`. What LVGL's partial mode hands its
/// `flush_cb`.
///
/// ```
/// use embedded_graphics_core::geometry::{OriginDimensions, Size};
/// use embedded_graphics_core::pixelcolor::Rgb565;
/// use embedded_graphics_core::primitives::Rectangle;
/// use softedge::render::BandTarget;
/// /// A 240x240 panel whose DMA sends 16 rows at a time.
/// struct Panel {
///     band: [u16; 240 * 16],
/// }
/// impl OriginDimensions for Panel {
///     fn size(&self) -> Size {
///         Size::new(240, 240)
///     }
/// }
/// impl BandTarget for Panel {
///     type Color = Rgb565;
///     type Raw = u16;
///     type Error = core::convert::Infallible;
///     fn buffer(&mut self) -> &mut [u16] {
///         &mut self.band
///     }
///     fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error> {
///         // Set the window to `area`, start the DMA of its pixels, wait.
///         Ok(())
///     }
/// }
/// ```
///
/// A `Raw` narrower than the colour's raw bits does not compile where a
/// frame is rendered into the display:
///
/// ```compile_fail
/// # use embedded_graphics_core::geometry::{OriginDimensions, Size};
/// # use embedded_graphics_core::pixelcolor::Rgb565;
/// # use embedded_graphics_core::primitives::Rectangle;
/// # use softedge::render::{BandTarget, Renderer};
/// # use softedge::tone::{format::Rgb565Format, Curve};
/// # use softedge::BandBuffer;
/// struct Narrow([u8; 64]);
/// # impl OriginDimensions for Narrow { fn size(&self) -> Size { Size::new(8, 8) } }
/// impl BandTarget for Narrow {
///     type Color = Rgb565;
///     type Raw = u8; // Rgb565 needs 16 bits
///     type Error = core::convert::Infallible;
///     fn buffer(&mut self) -> &mut [u8] { &mut self.0 }
///     fn send(&mut self, _: &Rectangle) -> Result<(), Self::Error> { Ok(()) }
/// }
/// # let mut acc = [0i32; BandBuffer::<3>::acc_len(8, 8)];
/// # let mut cover = [0i32; BandBuffer::<3>::cover_len(8, 8)];
/// # static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
/// let mut r = Renderer::<3>::new(&mut acc, &mut cover, &mut [], 8, 8, 8).unwrap();
/// let _ = r.render_lent(&mut Narrow([0; 64]), &RGB565, [0; 3], |_| Ok::<(), ()>(()));
/// ```
pub trait BandTarget: OriginDimensions {
    /// The display's colour.
    type Color: PixelColor + RawColor;
    /// Its raw bits in the buffer: at least the colour's
    /// (`Self::Color::Raw::BITS_PER_PIXEL`, checked when the renderer is
    /// compiled for the target): `u16` for `Rgb565`.
    type Raw: RawPixel;
    /// What [`send`](Self::send) can fail with.
    type Error;
    /// The buffer the next band's pixels are made in: row after row, the
    /// band's width times its rows of them from the start (at least that
    /// many, or the frame stops with [`RenderError::Buffer`]). Asked for
    /// in every band after the band is drawn (its length, then the
    /// buffer to fill); the same buffer each time, or another as long.
    fn buffer(&mut self) -> &mut [Self::Raw];
    /// Sends the pixels the buffer starts with to `area` of the display
    /// (`area.size.width * area.size.height` of them, row after row).
    fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error>;
    /// Fills `area` with `color`: a band nothing was drawn on, where the
    /// background has one colour everywhere. By default the buffer is
    /// filled and sent; a display with a fill command of its own can
    /// use that.
    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), Self::Error> {
        let n = area.size.width as usize * area.size.height as usize;
        let raw = Self::Raw::from_raw(color.to_raw());
        let buf = self.buffer();
        let n = n.min(buf.len());
        if let Some(run) = buf.get_mut(..n) {
            crate::arith::fill(run, raw);
        }
        self.send(area)
    }
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
    /// The band storage is known to be clean (no cover changes, heads
    /// reset, every tag the background's) for bands of this width and
    /// height (its layout depends on both): the last band's flush left it
    /// so.
    clean: Option<(u16, u16)>,
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
            clean: None,
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
    /// the profile, one `fill_contiguous` over the columns drawn on (the
    /// background beside them in a `fill_solid` each side; see the
    /// module's documentation).
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
        D::Color: RawColor,
        B: IntoLinear<C>,
        P: Profile<C, Color = D::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, D::Color>) -> Result<(), E>,
    {
        self.fits(target.size())?;
        let bands = Bands::new(self.width, self.height, self.band_rows);
        self.frame(
            Streamed(target),
            &mut profile,
            background.into_linear(),
            bands,
            draw,
        )
    }

    /// Renders only the window `area` of the frame (clipped to it): what a
    /// small change costs. The target gets one `fill_contiguous` per band
    /// over the window's part of the band (its drawn columns, the
    /// background beside them in `fill_solid`s, as [`render`](Self::render)
    /// sends them). With a dithering profile, the window is dithered on
    /// its own (Bayer matches the full frame; error diffusion restarts at
    /// the window's edge).
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
        D::Color: RawColor,
        B: IntoLinear<C>,
        P: Profile<C, Color = D::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, D::Color>) -> Result<(), E>,
    {
        let Some(bands) = self.window_bands(area) else {
            return Ok(FrameReport::default());
        };
        self.frame(
            Streamed(target),
            &mut profile,
            background.into_linear(),
            bands,
            draw,
        )
    }

    /// [`render`](Self::render) into a display that lends a buffer for
    /// each band and sends it itself ([`BandTarget`], a DMA flush): the
    /// same pixels, made in the lent buffer instead of streamed through
    /// `fill_contiguous` (on the Cortex-M0 about ten instructions a pixel
    /// of every band drawn on fewer; `boards/README.md`). The buffer must
    /// hold a band: the frame's width times `band_rows` pixels.
    pub fn render_lent<T, P, B, E, F>(
        &mut self,
        target: &mut T,
        mut profile: P,
        background: B,
        draw: F,
    ) -> Result<FrameReport, RenderError<T::Error, E>>
    where
        T: BandTarget,
        B: IntoLinear<C>,
        P: Profile<C, Color = T::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, T::Color>) -> Result<(), E>,
    {
        self.fits(target.size())?;
        let bands = Bands::new(self.width, self.height, self.band_rows);
        self.frame(
            Lent(target),
            &mut profile,
            background.into_linear(),
            bands,
            draw,
        )
    }

    /// [`render_window`](Self::render_window) into a [`BandTarget`]: each
    /// band of the window made in the lent buffer (the window's width
    /// times the band's rows of it) and sent over the window's part of the
    /// band. A frame larger than the display is [`RenderError::Size`], as
    /// for [`render_lent`](Self::render_lent): no area sent lies outside
    /// the display.
    pub fn render_window_lent<T, P, B, E, F>(
        &mut self,
        target: &mut T,
        mut profile: P,
        background: B,
        area: Rectangle,
        draw: F,
    ) -> Result<FrameReport, RenderError<T::Error, E>>
    where
        T: BandTarget,
        B: IntoLinear<C>,
        P: Profile<C, Color = T::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, T::Color>) -> Result<(), E>,
    {
        self.fits(target.size())?;
        let Some(bands) = self.window_bands(area) else {
            return Ok(FrameReport::default());
        };
        self.frame(
            Lent(target),
            &mut profile,
            background.into_linear(),
            bands,
            draw,
        )
    }

    /// [`RenderError::Size`] if the frame is larger than a display of
    /// `size`.
    fn fits<T, E>(&self, size: Size) -> Result<(), RenderError<T, E>> {
        if u32::from(self.width) > size.width || u32::from(self.height) > size.height {
            return Err(RenderError::Size {
                frame: (self.width, self.height),
                display: (size.width, size.height),
            });
        }
        Ok(())
    }

    /// The bands of window `area` clipped to the frame; `None` if nothing
    /// is left of it.
    fn window_bands(&self, area: Rectangle) -> Option<Bands> {
        let frame = Rectangle::new(
            Point::zero(),
            Size::new(u32::from(self.width), u32::from(self.height)),
        );
        let area = area.intersection(&frame);
        let (w, h) = (area.size.width as u16, area.size.height as u16);
        if w == 0 || h == 0 {
            return None;
        }
        Some(Bands::window(
            area.top_left.x,
            area.top_left.y,
            w,
            h,
            self.band_rows,
        ))
    }

    fn frame<T, P, E, F>(
        &mut self,
        mut target: T,
        profile: &mut P,
        background: [u16; C],
        bands: Bands,
        mut draw: F,
    ) -> Result<FrameReport, RenderError<T::Error, E>>
    where
        T: Flush<C>,
        P: Profile<C, Color = T::Color>,
        F: FnMut(&mut Canvas<'_, '_, C, T::Color>) -> Result<(), E>,
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
            // Made in place (no `map_err`, no closure: each move of a band
            // buffer is a copy of its palette).
            let clean = self.clean == Some((band.width, band.rows));
            let made = if clean {
                BandBuffer::reuse(&mut *self.acc, &mut *self.cover, band, bg)
            } else {
                BandBuffer::new(&mut *self.acc, &mut *self.cover, band)
            };
            let mut buf = match made {
                Ok(buf) => buf,
                Err(e) => return Err(RenderError::Band(e)),
            };
            if !clean {
                buf.clear(bg);
            }
            // The band's flush leaves it clean for the next.
            self.clean = None;
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
            match target.flush(&mut buf, &mut *profile) {
                Ok(()) => {}
                Err(FlushError::Target(e)) => return Err(RenderError::Target(e)),
                Err(FlushError::Buffer { needed, got }) => {
                    return Err(RenderError::Buffer { needed, got })
                }
            }
            self.clean = Some((band.width, band.rows));
            report.bands += 1;
        }
        match failed {
            Some((band_y0, error)) => Err(RenderError::Draw { band_y0, error }),
            None => Ok(report),
        }
    }
}

/// Where a band goes: streamed to a `DrawTarget`, or made in the buffer a
/// [`BandTarget`] lends.
trait Flush<const C: usize> {
    type Color: RawColor;
    type Error;
    fn flush<P: Profile<C, Color = Self::Color>>(
        &mut self,
        buf: &mut BandBuffer<'_, C>,
        profile: &mut P,
    ) -> Result<(), FlushError<Self::Error>>;
}

/// A `DrawTarget`, sent each band's drawn columns in one `fill_contiguous`.
struct Streamed<'t, D>(&'t mut D);

impl<D: DrawTarget, const C: usize> Flush<C> for Streamed<'_, D>
where
    D::Color: RawColor,
{
    type Color = D::Color;
    type Error = D::Error;

    fn flush<P: Profile<C, Color = D::Color>>(
        &mut self,
        buf: &mut BandBuffer<'_, C>,
        profile: &mut P,
    ) -> Result<(), FlushError<D::Error>> {
        send(buf, &mut *self.0, profile).map_err(FlushError::Target)
    }
}

/// A [`BandTarget`], each band made in its buffer.
struct Lent<'t, T>(&'t mut T);

impl<T: BandTarget, const C: usize> Flush<C> for Lent<'_, T> {
    type Color = T::Color;
    type Error = T::Error;

    fn flush<P: Profile<C, Color = T::Color>>(
        &mut self,
        buf: &mut BandBuffer<'_, C>,
        profile: &mut P,
    ) -> Result<(), FlushError<T::Error>> {
        lend(buf, &mut *self.0, profile)
    }
}

/// Sends a band through `profile` to `target` in one `fill_contiguous`
/// over its drawn columns and one `fill_solid` of the background each
/// side of them (or one `fill_solid` when nothing was drawn on it), when
/// the background has one colour everywhere; else in one
/// `fill_contiguous`. The band is left clean for the next: changes
/// zero, heads reset, every tag the background's.
///
/// The band's colours are made ([`tone_band`]) into its scratch of
/// changes (`width * rows` words, all zero between shapes), then streamed
/// to the target from that slice, each pixel zeroed as it is taken.
fn send<D, P, const C: usize>(
    buf: &mut BandBuffer<'_, C>,
    target: &mut D,
    profile: &mut P,
) -> Result<(), D::Error>
where
    D: DrawTarget,
    D::Color: RawColor,
    P: Profile<C, Color = D::Color>,
{
    let band = buf.band();
    let area = band_area(band);
    let bg = buf.background();
    let mut parts = buf.flush_parts();
    let uniform = profile.uniform(bg);
    if let Some(color) = uniform {
        if parts.untouched() {
            return target.fill_solid(&area, color);
        }
    }
    let w = usize::from(band.width);
    // The columns sent pixel by pixel: those drawn on in some row, out to
    // whole tag words (`tone_band` makes whole words); the background
    // beside them goes in one `fill_solid` a side, when that side is at
    // least `SOLID_SIDE` columns wide (narrower, a window set-up on the
    // display costs more than it saves). A display whose pixels are
    // smaller than a byte (1-bit OLED pages, 2- and 4-bit panels) packs
    // whole rows into its bytes: it gets whole bands.
    const SOLID_SIDE: usize = 16;
    let packs = <<D::Color as PixelColor>::Raw as RawData>::BITS_PER_PIXEL < 8;
    let cols = match uniform {
        Some(_) if !packs => {
            let drawn = parts.drawn_columns();
            let a = usize::from(drawn.start) & !3;
            let b = usize::from(drawn.end).next_multiple_of(4).min(w);
            let a = if a < SOLID_SIDE { 0 } else { a };
            let b = if w - b < SOLID_SIDE { w } else { b };
            a..b
        }
        _ => 0..w,
    };
    let out = core::mem::take(&mut parts.out);
    let put = |code| code as i32;
    if cols.len() == w {
        tone_band::<_, _, _, C, false>(&mut parts, profile, uniform.is_some(), out, 0..w, put);
    } else {
        let cols = cols.clone();
        tone_band::<_, _, _, C, true>(&mut parts, profile, uniform.is_some(), out, cols, put);
    }
    let side = |x0: usize, x1: usize| {
        Rectangle::new(
            Point::new(band.x0 + x0 as i32, band.y0),
            Size::new((x1 - x0) as u32, u32::from(band.rows)),
        )
    };
    // The drawn columns first: streaming them leaves the scratch zero
    // whatever the target answers.
    let len = cols.len() * usize::from(band.rows);
    stream(
        out.get_mut(..len).unwrap_or_default(),
        &side(cols.start, cols.end),
        target,
    )?;
    if let Some(color) = uniform {
        if cols.start > 0 {
            target.fill_solid(&side(0, cols.start), color)?;
        }
        if cols.end < w {
            target.fill_solid(&side(cols.end, w), color)?;
        }
    }
    Ok(())
}

/// Streams `out` to `area` of `target` in one `fill_contiguous`, each
/// pixel zeroed as it is taken; what the target did not take is zeroed
/// after.
#[inline(always)]
fn stream<D>(out: &mut [i32], area: &Rectangle, target: &mut D) -> Result<(), D::Error>
where
    D: DrawTarget,
    D::Color: RawColor,
{
    let mut taken = 0usize;
    let sent = target.fill_contiguous(
        area,
        out.iter_mut().map(|v| {
            taken += 1;
            D::Color::from_raw(core::mem::take(v) as u32)
        }),
    );
    if let Some(rest) = out.get_mut(taken..) {
        rest.fill(0);
    }
    sent
}

/// Sends a band through `profile` into the buffer `target` lends, then
/// asks it to send that ([`BandTarget::send`]; or its `fill_solid` when
/// nothing was drawn on the band and the background has one colour
/// everywhere), leaving the band clean for the next. The band's colours
/// are made ([`tone_band`]) in the lent buffer itself: no stream of
/// pixels, and the band's scratch of changes is never written.
fn lend<T, P, const C: usize>(
    buf: &mut BandBuffer<'_, C>,
    target: &mut T,
    profile: &mut P,
) -> Result<(), FlushError<T::Error>>
where
    T: BandTarget,
    P: Profile<C, Color = T::Color>,
{
    let band = buf.band();
    let area = band_area(band);
    let len = usize::from(band.width) * usize::from(band.rows);
    let got = target.buffer().len();
    if got < len {
        return Err(FlushError::Buffer { needed: len, got });
    }
    let bg = buf.background();
    let mut parts = buf.flush_parts();
    let uniform = profile.uniform(bg);
    if let Some(color) = uniform {
        if parts.untouched() {
            return target.fill_solid(&area, color).map_err(FlushError::Target);
        }
    }
    let out = target.buffer().get_mut(..len).unwrap_or_default();
    const {
        assert!(
            T::Raw::BITS >= <<T::Color as PixelColor>::Raw as RawData>::BITS_PER_PIXEL,
            "BandTarget::Raw holds fewer bits than the display's colour"
        );
    }
    tone_band::<_, _, _, C, false>(
        &mut parts,
        profile,
        uniform.is_some(),
        out,
        0..usize::from(band.width),
        T::Raw::from_raw,
    );
    target.send(&area).map_err(FlushError::Target)
}

/// Why a band could not be sent.
enum FlushError<E> {
    /// The target's buffer is shorter than the band.
    Buffer { needed: usize, got: usize },
    /// The target's own error.
    Target(E),
}

/// The frame rectangle of `band`.
fn band_area(band: crate::band::Band) -> Rectangle {
    Rectangle::new(
        Point::new(band.x0, band.y0),
        Size::new(u32::from(band.width), u32::from(band.rows)),
    )
}

/// The colours of a band's pixels in columns `cols` as raw display bits
/// into `out` (row after row, `cols.len() * rows` of them; `put` stores a
/// raw colour), and the band reset for the next (every pixel made reset
/// to the background, heads reset, every tag the background's). `cols`
/// holds every drawn column when `uniform` and starts on a tag word (a
/// multiple of 4 columns); else it is the whole band. The profile's rows
/// ([`ToneRow`]) start at `cols.start`. `SHIFT` false: `cols` is the
/// whole band, known at compile time (the per-row offsets fold away).
///
/// A pixel tagged with a palette entry gets the entry's colour, toned
/// once for the band (see `band::tags`); the others are resolved (the one
/// rounding), toned and packed one by one; columns left and right of a
/// row's drawn extent get the background's (`uniform`: the profile has
/// one colour for it everywhere; else every column is made).
fn tone_band<O: Copy, P, F, const C: usize, const SHIFT: bool>(
    parts: &mut crate::band::FlushParts<'_, C>,
    profile: &mut P,
    uniform: bool,
    out: &mut [O],
    cols: core::ops::Range<usize>,
    put: F,
) where
    P: Profile<C>,
    P::Color: RawColor,
    F: Fn(u32) -> O + Copy,
{
    let band = parts.band;
    // The palette's colours, toned once; `known` marks the entries whose
    // colour does not depend on the position.
    let mut codes = [0u32; PALETTE];
    let mut known = 0u32;
    for (t, v) in parts.palette.entries().iter().enumerate() {
        if let (Some(c), Some(code)) = (profile.uniform(v.map(resolve)), codes.get_mut(t)) {
            *code = c.to_raw();
            known |= 1 << t;
        }
    }
    let (w, rows) = (usize::from(band.width), usize::from(band.rows));
    let n = tags::row_words(w);
    let bg_acc = parts.palette.entries().first().copied().unwrap_or([0; C]);
    let dense = parts.palette.dense;
    let keeps565 = profile.keeps_rgb565();
    let bg_code = put(codes[0]);
    let (c0, mw) = if SHIFT {
        (cols.start, cols.len())
    } else {
        (0, w)
    };
    let x0 = band.x0 + c0 as i32;
    for r in 0..rows {
        let y = band.y0 + r as i32;
        // The row from column `c0` on (`c0` a whole tag word's first);
        // its drawn columns counted from there.
        let mut drawn = parts.take_drawn(r, c0);
        let t0 = r * n + c0 / 4;
        let (Some(out), Some(words), Some(acc)) = (
            out.get_mut(r * mw..r * mw + mw),
            parts.tags.get_mut(t0..r * n + n),
            parts.acc.get_mut((r * w + c0) * C..(r + 1) * w * C),
        ) else {
            continue;
        };
        if !uniform {
            drawn = 0..w;
        }
        if !drawn.is_empty() {
            profile.start_row(&if dense {
                ToneRow::new(y, x0, acc)
            } else {
                ToneRow::tagged(y, x0, acc, words, parts.palette.entries())
            });
        }
        if let Some(left) = out.get_mut(..drawn.start) {
            crate::arith::fill(left, bg_code);
        }
        if let Some(right) = out.get_mut(drawn.end..) {
            crate::arith::fill(right, bg_code);
        }
        let tone = RowTone {
            codes: &codes,
            known,
            entries: parts.palette.entries(),
            bg: bg_acc,
            profile: &*profile,
            keeps: keeps565,
            x0,
            y,
        };
        // The next band's tags: the background's. Outside the drawn
        // extent they are already (nothing drawn there since the last
        // flush); a dense band's are all `MIXED`.
        let k = if dense {
            r * n..r * n + n
        } else {
            t0 + drawn.start / 4..t0 + drawn.end.div_ceil(4)
        };
        tone.row(out, words, acc, drawn, dense, put);
        if let Some(drawn_words) = parts.tags.get_mut(k) {
            drawn_words.fill(0);
        }
        debug_assert!(
            parts
                .tags
                .get(r * n..r * n + n)
                .into_iter()
                .flatten()
                .all(|&t| t == 0),
            "a tag outside row {y}'s drawn extent"
        );
    }
}

/// What toning a band row needs: the palette's colours (`known`: which of
/// them do not depend on the position), the background in accumulator
/// units (what every pixel sent is reset to), the profile, and the row's
/// place.
struct RowTone<'t, P, const C: usize> {
    codes: &'t [u32; PALETTE],
    known: u32,
    /// The palette's entries (a tagged pixel's value).
    entries: &'t [[i32; C]],
    bg: [i32; C],
    profile: &'t P,
    /// The profile sends a `SOURCE` pixel's Rgb565 code as it is
    /// ([`Profile::keeps_rgb565`]).
    keeps: bool,
    x0: i32,
    y: i32,
}

impl<P: Profile<C>, const C: usize> RowTone<'_, P, C>
where
    P::Color: RawColor,
{
    /// The raw colours of the row's pixels `drawn` into `out`, from their
    /// tag `words` and accumulator `acc`, a run of equal tag words at a
    /// time: a run of one known palette entry (the background between
    /// shapes, a disc's inside) is one fill, a run of `MIXED` words a loop
    /// of its own, other words pixel by pixel. `drawn` is taken out to
    /// whole words: the pixels of a word beside it are the background's,
    /// tagged so (untouched since the last flush), and get its colour as
    /// the fill beside `drawn` gives them. Nothing is reset: the next
    /// band's tags say the background (see `band::tags`). A dense band's
    /// row (every tag `MIXED`) is one run, its accumulator reset to the
    /// background.
    #[inline(never)]
    fn row<O: Copy>(
        &self,
        out: &mut [O],
        words: &[i32],
        acc: &mut [i32],
        drawn: core::ops::Range<usize>,
        dense: bool,
        put: impl Fn(u32) -> O + Copy,
    ) {
        if dense {
            self.mixed::<_, true>(out, acc, drawn.start, drawn.end, put);
            return;
        }
        let w = out.len();
        let end = drawn.end.min(w);
        let Some(words) = words.get(..end.div_ceil(4)) else {
            return;
        };
        let mut i = drawn.start >> 2;
        while let Some((&word, rest)) = words.get(i..).and_then(|r| r.split_first()) {
            let j = i + 1 + rest.iter().take_while(|&&v| v == word).count();
            let (a, b) = (i * 4, (j * 4).min(w));
            i = j;
            let t = word as u8;
            if word == tags::MIXED_WORD {
                self.mixed::<_, false>(out, acc, a, b, put);
            } else if word == tags::splat(t) && self.is_known(t) {
                crate::arith::fill(
                    out.get_mut(a..b).unwrap_or_default(),
                    put(self.codes[usize::from(t) & (PALETTE - 1)]),
                );
            } else if word == tags::SOURCE_WORD && self.keeps {
                // An image's Rgb565 codes, sent as they are.
                let (Some(out), Some(px)) = (out.get_mut(a..b), acc.get(a * C..b * C)) else {
                    continue;
                };
                for (o, p) in out.iter_mut().zip(px.chunks_exact(C)) {
                    *o = put(p.first().copied().unwrap_or(0) as u32);
                }
            } else {
                // Words of different tags (at an edge): pixel by pixel.
                let (Some(out), Some(px)) = (out.get_mut(a..b), acc.get(a * C..b * C)) else {
                    continue;
                };
                let (mut tags, mut px) = (word as u32, px);
                let mut x = self.x0.wrapping_add(a as i32);
                for o in out {
                    let Some((p, rest)) = px.split_first_chunk::<C>() else {
                        break;
                    };
                    *o = put(self.take(p, tags as u8, x));
                    // The run's words are all `word`: rotated, not shifted.
                    (tags, px, x) = (tags.rotate_right(8), rest, x.wrapping_add(1));
                }
            }
        }
    }

    /// The raw colours of pixels `c0..c1` from their accumulator (every
    /// one resolved and toned); with `RESET` (a dense band) each reset to
    /// the background. (`chunks_exact` divides the length by `C` once a
    /// run, a call on the Cortex-M0 for colours; its loop is the tighter.)
    #[inline(never)]
    fn mixed<O: Copy, const RESET: bool>(
        &self,
        out: &mut [O],
        acc: &mut [i32],
        c0: usize,
        c1: usize,
        put: impl Fn(u32) -> O,
    ) {
        let (Some(out), Some(acc)) = (out.get_mut(c0..c1), acc.get_mut(c0 * C..c1 * C)) else {
            return;
        };
        let mut x = self.x0.wrapping_add(c0 as i32);
        for (o, px) in out.iter_mut().zip(acc.chunks_exact_mut(C)) {
            if let Some(p) = px.first_chunk_mut::<C>() {
                *o = put(self.profile.color(x, self.y, resolve_px(p)).to_raw());
                if RESET {
                    *p = self.bg;
                }
            }
            x = x.wrapping_add(1);
        }
    }

    /// True when palette entry `t` has a colour for every position.
    #[inline(always)]
    fn is_known(&self, t: u8) -> bool {
        (t as usize) < PALETTE && self.known >> t & 1 != 0
    }

    /// The raw colour of the pixel at column `x` tagged `t`, its
    /// accumulator `px`: its entry's colour if known, else its value (its
    /// entry's, or `px` when `MIXED`) resolved (the one rounding) and
    /// toned at its place.
    #[inline(always)]
    fn take(&self, px: &[i32; C], t: u8, x: i32) -> u32 {
        if self.is_known(t) {
            return self.codes[usize::from(t) & (PALETTE - 1)];
        }
        let decoded;
        let v = match self.entries.get(usize::from(t)) {
            Some(v) => v,
            None if t == tags::SOURCE => {
                let code = px.first().copied().unwrap_or(0);
                if self.keeps {
                    return code as u32;
                }
                decoded = tags::decode(code);
                &decoded
            }
            None => px,
        };
        self.profile.color(x, self.y, resolve_px(v)).to_raw()
    }
}

/// A pixel's value resolved (the one rounding) for the flush: a
/// one-channel band's through `units::resolve_split` (its clamp out of
/// line: the Cortex-M0's gray screen 5 % fewer instructions), a
/// three-channel band's through [`resolve`] (inline: 0.6 to 1 % fewer
/// than the split form on its frames). The same values.
#[inline(always)]
fn resolve_px<const C: usize>(px: &[i32; C]) -> [u16; C] {
    if C == 1 {
        px.map(crate::units::resolve_split)
    } else {
        px.map(resolve)
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;
    use std::vec::Vec;

    use embedded_graphics_core::pixelcolor::{Gray8, Rgb565};
    use embedded_graphics_core::prelude::PointsIter;
    use embedded_graphics_core::Pixel;

    use super::*;
    use crate::canvas::{Contour, MeshColors};
    use crate::geom::FinePoint;
    use crate::path::testing::Lcg;
    use crate::raster::DrawError;
    use crate::style::{Blend, FillRule, Gradient, Offset, Opacity, Stop};
    use crate::tone::format::{Gray8Format, Rgb565Format, ToneFormat};
    use crate::tone::{Bayer8, Curve};

    /// A display that keeps what it is sent, in raw bits.
    struct Capture<Col> {
        w: u32,
        h: u32,
        px: Vec<u32>,
        col: core::marker::PhantomData<Col>,
    }

    impl<Col> Capture<Col> {
        fn new(w: u16, h: u16) -> Self {
            Self {
                w: u32::from(w),
                h: u32::from(h),
                px: vec![u32::MAX; usize::from(w) * usize::from(h)],
                col: core::marker::PhantomData,
            }
        }
    }

    impl<Col> OriginDimensions for Capture<Col> {
        fn size(&self) -> Size {
            Size::new(self.w, self.h)
        }
    }

    impl<Col: PixelColorRaw> DrawTarget for Capture<Col> {
        type Color = Col;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Col>>>(
            &mut self,
            px: I,
        ) -> Result<(), Self::Error> {
            for Pixel(p, c) in px {
                let k = p.y as usize * self.w as usize + p.x as usize;
                self.px[k] = c.to_raw();
            }
            Ok(())
        }
    }

    /// An embedded-graphics colour whose raw bits the capture keeps.
    trait PixelColorRaw: embedded_graphics_core::pixelcolor::PixelColor + RawColor {}
    impl<T: embedded_graphics_core::pixelcolor::PixelColor + RawColor> PixelColorRaw for T {}

    /// A random scene: flat shapes opaque and translucent, over and added,
    /// Gouraud meshes, gradients, pixels and spans through the canvas as a
    /// `DrawTarget`, in up to 60 colours (more than a band's palette).
    fn scene<const C: usize, Col>(
        seed: u64,
        w: u16,
        h: u16,
    ) -> impl FnMut(&mut Canvas<'_, '_, C, Col>) -> Result<(), DrawError>
    where
        Col: PixelColorRaw + crate::color::IntoLinear<C>,
    {
        move |c| {
            let mut rng = Lcg(seed);
            let colours = 1 + rng.below(60) as usize;
            let shapes = 1 + rng.below(40);
            let p = |rng: &mut Lcg| {
                FinePoint::new(
                    rng.below(u64::from(w) * 1024 + 2048) as i32 - 1024,
                    rng.below(u64::from(h) * 1024 + 2048) as i32 - 1024,
                )
            };
            let colour = |rng: &mut Lcg| -> [u16; C] {
                let k = rng.below(colours as u64) as u16;
                core::array::from_fn(|ch| (k * 67 + ch as u16 * 1001) % 4096)
            };
            for _ in 0..shapes {
                let kind = rng.below(6);
                let opacity = if rng.below(3) == 0 {
                    Opacity::from_ratio(rng.below(255) as u32 + 1, 256).unwrap_or(Opacity::OPAQUE)
                } else {
                    Opacity::OPAQUE
                };
                let blend = if rng.below(6) == 0 {
                    Blend::Add
                } else {
                    Blend::Over
                };
                match kind {
                    0 | 1 => {
                        let n = 3 + rng.below(4) as usize;
                        let pts: Vec<FinePoint> = (0..n).map(|_| p(&mut rng)).collect();
                        let rule = if rng.below(2) == 0 {
                            FillRule::NonZero
                        } else {
                            FillRule::EvenOdd
                        };
                        let col = colour(&mut rng);
                        let _ = c.fill(&Contour(&pts), col, rule, blend, opacity);
                    }
                    2 => {
                        // An axis-aligned box on whole pixels: whole spans.
                        let (x0, y0) = (
                            rng.below(u64::from(w)) as i32,
                            rng.below(u64::from(h)) as i32,
                        );
                        let (x1, y1) =
                            (x0 + 1 + rng.below(12) as i32, y0 + 1 + rng.below(12) as i32);
                        let f = |x, y| FinePoint::from_px(x, y);
                        let col = colour(&mut rng);
                        let _ = c.fill(
                            &Contour(&[f(x0, y0), f(x1, y0), f(x1, y1), f(x0, y1)]),
                            col,
                            FillRule::NonZero,
                            Blend::Over,
                            Opacity::OPAQUE,
                        );
                    }
                    3 => {
                        let pts = [p(&mut rng), p(&mut rng), p(&mut rng), p(&mut rng)];
                        let cols = [
                            colour(&mut rng),
                            colour(&mut rng),
                            colour(&mut rng),
                            colour(&mut rng),
                        ];
                        let _ = c.fill_mesh(
                            &pts,
                            &[[0, 1, 2], [0, 2, 3]],
                            MeshColors::PerPoint(&cols),
                            blend,
                            opacity,
                        );
                    }
                    4 => {
                        let stops = [
                            Stop::lin(Offset::ZERO, colour(&mut rng)),
                            Stop::lin(Offset::ONE, colour(&mut rng)),
                        ];
                        if let Ok(g) = Gradient::linear(p(&mut rng), p(&mut rng), &stops) {
                            let pts = [p(&mut rng), p(&mut rng), p(&mut rng)];
                            let _ = c.fill_gradient(
                                &Contour(&pts),
                                &g,
                                FillRule::NonZero,
                                blend,
                                opacity,
                            );
                        }
                    }
                    _ => {
                        // e-g pixels and a solid fill through the canvas.
                        let col = colour(&mut rng);
                        let x = rng.below(u64::from(w)) as i32;
                        let y = rng.below(u64::from(h)) as i32;
                        let x1 = x + 1 + rng.below(9) as i32;
                        c.buffer().store_span(x, x1, y, col);
                        c.buffer().store_pixel(x, y + 1, colour(&mut rng));
                    }
                }
            }
            Ok(())
        }
    }

    /// The tag is the value (`band::tags`): a scene (flat, translucent and
    /// added polygons, whole boxes, Gouraud meshes, gradients, e-g pixels,
    /// discs and rings centred on pixels and off them, images, text) drawn
    /// into a band that keeps tags (its accumulator untouched where a flat colour
    /// covers) gives every pixel the value it gets in a band made dense
    /// before the first shape, where the accumulator is every pixel's
    /// value and no tag is kept; also where the tagged band itself goes
    /// dense part way (more flat colours than palette entries).
    #[test]
    fn a_band_that_keeps_tags_holds_the_values_of_a_dense_one() {
        use crate::draw::{AaDrawable, AaStyle};
        use crate::image::{format, AaImage, RawImage};
        use crate::path::Degrees;
        use crate::text::bundled::SANS_16;
        use crate::text::{AaTextStyle, DrawAaText};
        use embedded_graphics::prelude::{AngleUnit, Point, Primitive, RgbColor};
        use embedded_graphics::primitives::{Arc, Circle};
        use embedded_graphics::text::Text;
        let texels: Vec<u8> = (0..12 * 9 * 4).map(|k| (k * 37 % 256) as u8).collect();
        let opaque = RawImage::<format::Rgb565>::new(&texels, 12, 9).unwrap();
        let clear = RawImage::<format::Rgba8888>::new(&texels, 6, 9).unwrap();
        let mut rng = Lcg(0x7a65_d0e5);
        let (mut went_dense, mut stayed) = (0, 0);
        for case in 0..400 {
            let (w, h) = (1 + rng.below(48) as u16, 1 + rng.below(40) as u16);
            let seed = rng.next_u64();
            let discs: Vec<(i32, i32, u32, u16)> = (0..rng.below(4))
                .map(|_| {
                    (
                        rng.below(u64::from(w)) as i32 - 4,
                        rng.below(u64::from(h)) as i32 - 4,
                        1 + rng.below(30) as u32,
                        rng.below(0x10000) as u16,
                    )
                })
                .collect();
            let draw = |dense: bool| -> (Vec<[u16; 3]>, bool) {
                let mut acc = vec![0x5a5a_5a5a; BandBuffer::<3>::acc_len(w, h)];
                let mut cover = vec![0; BandBuffer::<3>::cover_len(w, h)];
                let band = crate::band::Band::new(w, 0, h);
                let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).unwrap();
                buf.clear([300, 2000, 4000]);
                if dense {
                    buf.go_dense();
                }
                {
                    let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
                    for &(x, y, d, c) in &discs {
                        let col =
                            Rgb565::from(embedded_graphics_core::pixelcolor::raw::RawU16::new(c));
                        let _ = Circle::new(Point::new(x, y), d)
                            .into_styled(AaStyle::with_fill(col))
                            .draw(&mut canvas);
                        let _ =
                            Arc::new(Point::new(x + 1, y), d + 3, 30.0f32.deg(), 250.0f32.deg())
                                .into_styled(AaStyle::with_stroke(Rgb565::GREEN, 3))
                                .draw(&mut canvas);
                    }
                    if case % 3 == 0 {
                        // More flat colours than the palette has entries.
                        for k in 0..40u16 {
                            let (x, y) = (i32::from(k * 7 % w), i32::from(k % h));
                            canvas
                                .buffer()
                                .store_span(x, x + 3, y, [k * 100, 50, 4000 - k]);
                        }
                    }
                    let _ = scene::<3, Rgb565>(seed, w, h)(&mut canvas);
                    // Images: an opaque one at whole pixels (replaces what
                    // it covers unread), a translucent one turned.
                    let at = FinePoint::from_px(i32::from(w) / 3, i32::from(h) / 4);
                    let _ = canvas.draw_image(&AaImage::new(&opaque).position(at));
                    let _ = canvas
                        .draw_image(&AaImage::new(&clear).position(at).rotate(Degrees::new(33)));
                    let style = AaTextStyle::new(&SANS_16, Rgb565::WHITE);
                    let _ = Text::new("Ag%", Point::new(2, i32::from(h) / 2 + 4), style)
                        .draw(&mut canvas);
                }
                let px = (0..i32::from(h))
                    .flat_map(|y| (0..i32::from(w)).map(move |x| (x, y)))
                    .map(|(x, y)| buf.lin12(x, y).unwrap())
                    .collect();
                (px, buf.is_dense())
            };
            let (tagged, ended_dense) = draw(false);
            let (plain, _) = draw(true);
            assert!(tagged == plain, "case {case}: {w}x{h}");
            if ended_dense {
                went_dense += 1;
            } else {
                stayed += 1;
            }
        }
        assert!(went_dense > 20 && stayed > 100, "{went_dense} {stayed}");
    }

    /// The reference: the scene drawn into one band of the whole frame,
    /// each pixel read back as linear 12 bits (the accumulator alone) and
    /// toned by the profile's colour at its place.
    fn reference<const C: usize, Col, P>(
        seed: u64,
        w: u16,
        h: u16,
        bg: [u16; C],
        profile: &P,
    ) -> Vec<u32>
    where
        Col: PixelColorRaw + crate::color::IntoLinear<C>,
        P: Profile<C, Color = Col>,
    {
        reference_of(scene::<C, Col>(seed, w, h), w, h, bg, profile)
    }

    /// [`reference`] of any drawing.
    fn reference_of<const C: usize, Col, P>(
        mut draw: impl FnMut(&mut Canvas<'_, '_, C, Col>) -> Result<(), DrawError>,
        w: u16,
        h: u16,
        bg: [u16; C],
        profile: &P,
    ) -> Vec<u32>
    where
        Col: PixelColorRaw + crate::color::IntoLinear<C>,
        P: Profile<C, Color = Col>,
    {
        let mut acc = vec![0; BandBuffer::<C>::acc_len(w, h)];
        let mut cover = vec![0; BandBuffer::<C>::cover_len(w, h)];
        let mut buf =
            BandBuffer::<C>::new(&mut acc, &mut cover, crate::band::Band::new(w, 0, h)).unwrap();
        buf.clear(bg);
        let mut canvas: Canvas<'_, '_, C, Col> = Canvas::typed(&mut buf, None);
        let _ = draw(&mut canvas);
        let mut out = Vec::new();
        for y in 0..i32::from(h) {
            for x in 0..i32::from(w) {
                out.push(profile.color(x, y, buf.lin12(x, y).unwrap()).to_raw());
            }
        }
        out
    }

    fn check<const C: usize, Col, P>(profile: &P, bg: [u16; C])
    where
        Col: PixelColorRaw + crate::color::IntoLinear<C>,
        P: Profile<C, Color = Col> + Clone,
    {
        let mut rng = Lcg(0xf1a5_4ed5);
        for case in 0..300u64 {
            let (w, h) = (1 + rng.below(40) as u16, 1 + rng.below(30) as u16);
            let rows = 1 + rng.below(9) as u16;
            let seed = rng.next_u64();
            let want = reference::<C, Col, P>(seed, w, h, bg, profile);
            let mut acc = vec![0; BandBuffer::<C>::acc_len(w, rows)];
            let mut cover = vec![0; BandBuffer::<C>::cover_len(w, rows)];
            let mut slots = [crate::canvas::WalkSlot::<C>::EMPTY; 4];
            let mut r = Renderer::<C>::new(&mut acc, &mut cover, &mut slots, w, h, rows).unwrap();
            // Twice: the second frame starts from the storage the first
            // left clean.
            for frame in 0..2 {
                let mut shown = Capture::<Col>::new(w, h);
                r.render(&mut shown, profile.clone(), bg, scene::<C, Col>(seed, w, h))
                    .unwrap();
                if shown.px != want {
                    let i = (0..want.len()).find(|&i| shown.px[i] != want[i]).unwrap();
                    panic!(
                        "case {case} frame {frame}: {w}x{h} in bands of {rows}: pixel ({}, {}) {:#x} != {:#x}",
                        i % usize::from(w),
                        i / usize::from(w),
                        shown.px[i],
                        want[i]
                    );
                }
            }
        }
    }

    /// A display that lends a buffer for each band ([`BandTarget`]) and
    /// keeps what it is sent in raw bits; the buffer is scrambled after
    /// each band, so every pixel of the next must be made again.
    struct Lending<Col: PixelColor, R> {
        shown: Capture<Col>,
        buf: Vec<R>,
        scramble: R,
        /// The areas sent, and filled.
        sent: Vec<Rectangle>,
        filled: usize,
    }

    impl<Col: PixelColor, R: Copy> Lending<Col, R> {
        fn new(w: u16, h: u16, len: usize, scramble: R) -> Self {
            Self {
                shown: Capture::new(w, h),
                buf: vec![scramble; len],
                scramble,
                sent: Vec::new(),
                filled: 0,
            }
        }
    }

    impl<Col: PixelColor, R> OriginDimensions for Lending<Col, R> {
        fn size(&self) -> Size {
            self.shown.size()
        }
    }

    impl<Col: PixelColorRaw, R: RawPixel + Into<u32>> BandTarget for Lending<Col, R> {
        type Color = Col;
        type Raw = R;
        type Error = core::convert::Infallible;
        fn buffer(&mut self) -> &mut [R] {
            &mut self.buf
        }
        fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error> {
            self.sent.push(*area);
            let n = area.size.width as usize * area.size.height as usize;
            for (p, &v) in area.points().zip(&self.buf[..n]) {
                let k = p.y as usize * self.shown.w as usize + p.x as usize;
                self.shown.px[k] = v.into();
            }
            self.buf.fill(self.scramble);
            Ok(())
        }
        fn fill_solid(&mut self, area: &Rectangle, color: Col) -> Result<(), Self::Error> {
            self.filled += 1;
            self.shown.fill_solid(area, color)
        }
    }

    /// Frames and windows rendered into a display that lends its band
    /// buffer are those streamed to a `DrawTarget`, bit for bit (which
    /// `check` holds to the reference), one send or fill per band over
    /// the band's rectangle; a buffer shorter than a band is an error.
    fn check_lent<const C: usize, Col, P, R>(profile: &P, bg: [u16; C], scramble: R)
    where
        Col: PixelColorRaw + crate::color::IntoLinear<C>,
        P: Profile<C, Color = Col> + Clone,
        R: RawPixel + Into<u32>,
    {
        let mut rng = Lcg(0x1e17_ba4d);
        for case in 0..200u64 {
            let (w, h) = (1 + rng.below(40) as u16, 1 + rng.below(30) as u16);
            let rows = 1 + rng.below(9) as u16;
            let seed = rng.next_u64();
            let mut acc = vec![0; BandBuffer::<C>::acc_len(w, rows)];
            let mut cover = vec![0; BandBuffer::<C>::cover_len(w, rows)];
            let mut slots = [crate::canvas::WalkSlot::<C>::EMPTY; 4];
            let mut r = Renderer::<C>::new(&mut acc, &mut cover, &mut slots, w, h, rows).unwrap();
            let x0 = rng.below(u64::from(w)) as i32;
            let y0 = rng.below(u64::from(h)) as i32;
            let area = Rectangle::new(
                Point::new(x0, y0),
                Size::new(
                    1 + rng.below(u64::from(w)) as u32,
                    1 + rng.below(u64::from(h)) as u32,
                ),
            );
            for window in [None, Some(area)] {
                let mut streamed = Capture::<Col>::new(w, h);
                let len = usize::from(w) * usize::from(rows);
                let mut lent = Lending::<Col, R>::new(w, h, len + rng.below(3) as usize, scramble);
                let (a, b) = match window {
                    None => (
                        r.render(
                            &mut streamed,
                            profile.clone(),
                            bg,
                            scene::<C, Col>(seed, w, h),
                        ),
                        r.render_lent(&mut lent, profile.clone(), bg, scene::<C, Col>(seed, w, h)),
                    ),
                    Some(area) => (
                        r.render_window(
                            &mut streamed,
                            profile.clone(),
                            bg,
                            area,
                            scene::<C, Col>(seed, w, h),
                        ),
                        r.render_window_lent(
                            &mut lent,
                            profile.clone(),
                            bg,
                            area,
                            scene::<C, Col>(seed, w, h),
                        ),
                    ),
                };
                assert_eq!(a.unwrap(), b.unwrap(), "case {case}");
                assert!(
                    lent.shown.px == streamed.px,
                    "case {case} {window:?}: {w}x{h} in bands of {rows}"
                );
                let bands = match window {
                    None => crate::band::Bands::new(w, h, rows),
                    Some(a) => r.window_bands(a).unwrap(),
                };
                let bands: Vec<_> = bands.map(band_area).collect();
                assert_eq!(lent.sent.len() + lent.filled, bands.len(), "case {case}");
                assert!(lent.sent.iter().all(|s| bands.contains(s)), "case {case}");
            }
            // A buffer a pixel short of a band (the frame's first).
            let len = usize::from(w) * usize::from(rows.min(h));
            let mut short = Lending::<Col, R>::new(w, h, len - 1, scramble);
            let got = r.render_lent(&mut short, profile.clone(), bg, scene::<C, Col>(seed, w, h));
            assert_eq!(
                got.err(),
                Some(RenderError::Buffer {
                    needed: len,
                    got: len - 1
                }),
                "case {case}"
            );
        }
    }

    /// A frame larger than the lending display is an error, whole or in a
    /// window (nothing sent).
    #[test]
    fn a_lent_frame_larger_than_the_display_is_an_error() {
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        let mut acc = vec![0; BandBuffer::<3>::acc_len(8, 4)];
        let mut cover = vec![0; BandBuffer::<3>::cover_len(8, 4)];
        let mut r = Renderer::<3>::new(&mut acc, &mut cover, &mut [], 8, 8, 4).unwrap();
        let want = Some(RenderError::Size {
            frame: (8, 8),
            display: (7, 8),
        });
        let mut small = Lending::<Rgb565, u16>::new(7, 8, 64, 0);
        let whole = r.render_lent(&mut small, &RGB565, [0; 3], scene::<3, Rgb565>(1, 8, 8));
        assert_eq!(whole.err(), want);
        let area = Rectangle::new(Point::new(0, 0), Size::new(2, 2));
        let part = r.render_window_lent(
            &mut small,
            &RGB565,
            [0; 3],
            area,
            scene::<3, Rgb565>(1, 8, 8),
        );
        assert_eq!(part.err(), want);
        assert!(small.sent.is_empty() && small.filled == 0);
    }

    #[test]
    fn a_lent_band_buffer_gets_the_streamed_pixels() {
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        static GRAY8: Gray8Format = Gray8Format::new(Curve::Srgb);
        check_lent::<3, Rgb565, _, u16>(&&RGB565, [0; 3], 0xa5a5);
        check_lent::<3, Rgb565, _, u32>(&&RGB565, [2000, 30, 4095], 0x5a5a_5a5a);
        check_lent::<1, Gray8, _, u8>(&&GRAY8, [700], 0x5a);
        check_lent::<1, _, _, u8>(&Bayer8::new(), [1234], 1);
    }

    /// A display that takes only the first pixels of each band it is
    /// sent (a driver that stops early), and keeps them.
    struct Stingy<Col> {
        shown: Capture<Col>,
        calls: usize,
    }

    impl<Col> OriginDimensions for Stingy<Col> {
        fn size(&self) -> Size {
            self.shown.size()
        }
    }

    impl<Col: PixelColorRaw> DrawTarget for Stingy<Col> {
        type Color = Col;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Col>>>(
            &mut self,
            px: I,
        ) -> Result<(), Self::Error> {
            self.shown.draw_iter(px)
        }
        fn fill_contiguous<I: IntoIterator<Item = Col>>(
            &mut self,
            area: &Rectangle,
            colors: I,
        ) -> Result<(), Self::Error> {
            self.calls += 1;
            let n = area.size.width as usize * area.size.height as usize;
            let take = self.calls * 37 % (n + 1);
            let px = area
                .points()
                .zip(colors)
                .take(take)
                .map(|(p, c)| Pixel(p, c));
            self.shown.draw_iter(px)
        }
    }

    /// A display that stops taking a band's pixels early gets the right
    /// ones, and the band is left clean for the next band and frame.
    #[test]
    fn a_band_the_display_took_part_of_is_left_clean() {
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        let bg = [300, 2000, 40];
        let mut rng = Lcg(0x5717_6e79);
        for case in 0..100u64 {
            let (w, h) = (1 + rng.below(40) as u16, 1 + rng.below(30) as u16);
            let rows = 1 + rng.below(9) as u16;
            let seed = rng.next_u64();
            let want = reference::<3, Rgb565, _>(seed, w, h, bg, &&RGB565);
            let mut acc = vec![0; BandBuffer::<3>::acc_len(w, rows)];
            let mut cover = vec![0; BandBuffer::<3>::cover_len(w, rows)];
            let mut slots = [crate::canvas::WalkSlot::<3>::EMPTY; 4];
            let mut r = Renderer::<3>::new(&mut acc, &mut cover, &mut slots, w, h, rows).unwrap();
            let mut stingy = Stingy {
                shown: Capture::<Rgb565>::new(w, h),
                calls: 0,
            };
            r.render(&mut stingy, &RGB565, bg, scene::<3, Rgb565>(seed, w, h))
                .unwrap();
            for (k, (&got, &px)) in stingy.shown.px.iter().zip(&want).enumerate() {
                assert!(got == u32::MAX || got == px, "case {case}: pixel {k}");
            }
            let mut shown = Capture::<Rgb565>::new(w, h);
            r.render(&mut shown, &RGB565, bg, scene::<3, Rgb565>(seed, w, h))
                .unwrap();
            assert!(shown.px == want, "case {case}: {w}x{h} in bands of {rows}");
        }
    }

    /// A display that counts how often each pixel is written and what
    /// came pixel by pixel (`fill_contiguous`) and in one colour
    /// (`fill_solid`).
    struct Tally<Col> {
        shown: Capture<Col>,
        writes: Vec<u32>,
        contiguous: usize,
        solid: usize,
    }

    impl<Col> OriginDimensions for Tally<Col> {
        fn size(&self) -> Size {
            self.shown.size()
        }
    }

    impl<Col: PixelColorRaw> Tally<Col> {
        fn put(&mut self, area: &Rectangle, colors: impl IntoIterator<Item = Col>) -> usize {
            let mut n = 0;
            for (p, c) in area.points().zip(colors) {
                let k = p.y as usize * self.shown.w as usize + p.x as usize;
                self.writes[k] += 1;
                self.shown.px[k] = c.to_raw();
                n += 1;
            }
            n
        }
    }

    impl<Col: PixelColorRaw> DrawTarget for Tally<Col> {
        type Color = Col;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Col>>>(
            &mut self,
            _: I,
        ) -> Result<(), Self::Error> {
            panic!("the renderer sends bands, not pixels");
        }
        fn fill_contiguous<I: IntoIterator<Item = Col>>(
            &mut self,
            area: &Rectangle,
            colors: I,
        ) -> Result<(), Self::Error> {
            self.contiguous += self.put(area, colors);
            Ok(())
        }
        fn fill_solid(&mut self, area: &Rectangle, color: Col) -> Result<(), Self::Error> {
            self.solid += self.put(area, core::iter::repeat(color));
            Ok(())
        }
    }

    /// Every pixel of a frame is sent once; the background beside a
    /// band's drawn columns goes by `fill_solid`, so a small shape costs
    /// the display's stream of pixels only about its width.
    #[test]
    fn every_pixel_is_sent_once_and_the_background_beside_the_drawing_in_one_colour() {
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        static DITHER: crate::tone::ordered::Rgb565Dither =
            crate::tone::ordered::Rgb565Dither::new(Curve::Srgb);
        let bg = [300, 2000, 40];
        let mut rng = Lcg(0x0b5e_55ed_f111);
        let mut beside = 0;
        for case in 0..300u64 {
            let (w, h) = (1 + rng.below(120) as u16, 1 + rng.below(30) as u16);
            let size = (w, h, 1 + rng.below(9) as u16);
            let seed = rng.next_u64();
            let sent = match case % 4 {
                // Colours that depend on the column (period 5, not a tag
                // word's 4) over a background of one colour: the drawn
                // columns are toned at their place.
                0 => tally_frame(
                    &Striped(&RGB565),
                    [0; 3],
                    || small_shapes(seed, w, h),
                    size,
                    case,
                ),
                // Dithered colours over a background the dither leaves
                // one colour (black).
                1 => tally_frame(&&DITHER, [0; 3], || small_shapes(seed, w, h), size, case),
                2 => tally_frame(&&RGB565, bg, || small_shapes(seed, w, h), size, case),
                _ => tally_frame(&&RGB565, bg, || scene::<3, Rgb565>(seed, w, h), size, case),
            };
            beside += usize::from(sent);
        }
        // The background beside the drawing went in `fill_solid`s often.
        assert!(beside > 100, "{beside} of 300 frames");
        // A disc of radius 5 px in a 200-px-wide frame: its bands stream
        // its columns (out to whole tag words), not the frame's width.
        let (w, h, rows) = (200u16, 32u16, 16u16);
        let mut acc = vec![0; BandBuffer::<3>::acc_len(w, rows)];
        let mut cover = vec![0; BandBuffer::<3>::cover_len(w, rows)];
        let mut r = Renderer::<3>::new(&mut acc, &mut cover, &mut [], w, h, rows).unwrap();
        let mut tally = Tally {
            shown: Capture::<Rgb565>::new(w, h),
            writes: vec![0; usize::from(w) * usize::from(h)],
            contiguous: 0,
            solid: 0,
        };
        r.render(
            &mut tally,
            &RGB565,
            bg,
            |cv: &mut Canvas<'_, '_, 3, Rgb565>| {
                let disc = crate::path::Circle::new(FinePoint::new(101 << 10, 16 << 10), 5 << 10);
                let op = Opacity::OPAQUE;
                cv.fill_shape(&disc, [4000, 100, 100], FillRule::NonZero, Blend::Over, op)
            },
        )
        .unwrap();
        assert!(tally.writes.iter().all(|&k| k == 1));
        // Columns 96..107 drawn, 96..108 streamed, in both bands.
        assert_eq!(tally.contiguous, 12 * 32);
    }

    /// Rgb565, each colour but black changed by its column (`x mod 5`).
    #[derive(Clone, Copy)]
    struct Striped(&'static Rgb565Format);

    impl Profile<3> for Striped {
        type Color = Rgb565;
        fn color(&self, x: i32, _y: i32, lin: [u16; 3]) -> Rgb565 {
            let c = ToneFormat::color(self.0, lin);
            match c.to_raw() {
                0 => c,
                raw => Rgb565::from_raw(raw ^ x.rem_euclid(5) as u32),
            }
        }
        fn uniform(&self, lin: [u16; 3]) -> Option<Rgb565> {
            let c = ToneFormat::color(self.0, lin);
            (c.to_raw() == 0).then_some(c)
        }
    }

    /// A frame of `draw` through [`Tally`], twice with one renderer: each
    /// pixel sent once, the colour of [`reference_of`]; true when some
    /// band sent background beside its drawn columns.
    fn tally_frame<P, F>(
        profile: &P,
        bg: [u16; 3],
        draw: impl Fn() -> F,
        (w, h, rows): (u16, u16, u16),
        case: u64,
    ) -> bool
    where
        P: Profile<3, Color = Rgb565> + Copy,
        F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
    {
        let want = reference_of(draw(), w, h, bg, profile);
        let mut acc = vec![0; BandBuffer::<3>::acc_len(w, rows)];
        let mut cover = vec![0; BandBuffer::<3>::cover_len(w, rows)];
        let mut r = Renderer::<3>::new(&mut acc, &mut cover, &mut [], w, h, rows).unwrap();
        let n = usize::from(w) * usize::from(h);
        let mut beside = false;
        for _ in 0..2 {
            let mut tally = Tally {
                shown: Capture::<Rgb565>::new(w, h),
                writes: vec![0; n],
                contiguous: 0,
                solid: 0,
            };
            r.render(&mut tally, *profile, bg, draw()).unwrap();
            assert!(tally.writes.iter().all(|&k| k == 1), "case {case}");
            assert!(
                tally.shown.px == want,
                "case {case}: {w}x{h} in bands of {rows}"
            );
            assert_eq!(tally.contiguous + tally.solid, n, "case {case}");
            beside |= tally.contiguous > 0 && tally.solid > 0;
        }
        beside
    }

    /// A few small shapes (discs, triangles; opaque or not, over or
    /// added) in a `w x h` frame.
    fn small_shapes(
        seed: u64,
        w: u16,
        h: u16,
    ) -> impl FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError> {
        move |c| {
            let mut rng = Lcg(seed);
            for _ in 0..1 + rng.below(4) {
                let (x, y) = (
                    rng.below(u64::from(w) << 10) as i32,
                    rng.below(u64::from(h) << 10) as i32,
                );
                let size = 256 + rng.below(12 << 10) as i32;
                let col = [rng.below(4096) as u16, 900, rng.below(4096) as u16];
                let op = match rng.below(3) {
                    0 => Opacity::from_percent(40),
                    _ => Opacity::OPAQUE,
                };
                let blend = [Blend::Over, Blend::Add][rng.below(4) as usize / 3];
                let _ = if rng.below(2) == 0 {
                    let disc = crate::path::Circle::new(FinePoint::new(x, y), size as u32);
                    c.fill_shape(&disc, col, FillRule::NonZero, blend, op)
                } else {
                    let tri = [
                        FinePoint::new(x, y),
                        FinePoint::new(x + size, y + size / 3),
                        FinePoint::new(x - size / 2, y + size),
                    ];
                    c.fill(&Contour(&tri), col, FillRule::NonZero, blend, op)
                };
            }
            Ok(())
        }
    }

    /// Rings, discs and stroked arcs redrawn in windows and bands that
    /// their rings may miss (a band wholly inside a hole, or beside a
    /// ring, is numbered and skipped without its set-up) give the pixels
    /// of the frame drawn in one band, where nothing is skipped.
    #[test]
    fn circles_and_arcs_redrawn_in_windows_are_the_frame_bit_for_bit() {
        use crate::path::{Arc, Circle, Degrees, LineCap, StrokeStyle};
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        let (w, h) = (64u16, 64u16);
        let mut rng = Lcg(0x71_a9b0_5e11_0c1e);
        let mut skipped_somewhere = 0;
        for case in 0..120 {
            let c = FinePoint::new(
                rng.below(80 * 1024) as i32 - 8 * 1024,
                rng.below(80 * 1024) as i32 - 8 * 1024,
            );
            let r = 2048 + rng.below(40 * 1024) as u32;
            let width = 512 + rng.below(12 * 1024) as u32;
            let (a, sw) = (rng.below(360) as i32, rng.below(700) as i32 - 350);
            let cap = [LineCap::Butt, LineCap::Round][case % 2];
            let kind = case % 3;
            let draw = |cv: &mut Canvas<'_, '_, 3, Rgb565>| -> Result<(), DrawError> {
                let op = Opacity::from_percent(80);
                let col = [4000, 1000, 300];
                // A shape before and after, so that numbers matter.
                let tri = [
                    FinePoint::new(0, 0),
                    FinePoint::new(9000, 2000),
                    FinePoint::new(3000, 30000),
                ];
                let _ = cv.fill(&tri, [200, 3000, 900], FillRule::NonZero, Blend::Over, op);
                let style = StrokeStyle::new(width).with_cap(cap);
                let _ = match kind {
                    0 => cv.fill_shape(&Circle::new(c, r), col, FillRule::NonZero, Blend::Over, op),
                    1 => cv.stroke_shape(&Circle::new(c, r), &style, col, Blend::Over, op),
                    _ => {
                        let arc = Arc::new(c, r, Degrees::new(a), Degrees::new(sw));
                        cv.stroke_shape(&arc, &style, col, Blend::Over, op)
                    }
                };
                let _ = cv.fill(&tri, [900, 100, 4000], FillRule::NonZero, Blend::Add, op);
                Ok(())
            };
            let bg = [100, 200, 300];
            let mut acc = vec![0; BandBuffer::<3>::acc_len(w, h)];
            let mut cover = vec![0; BandBuffer::<3>::cover_len(w, h)];
            let mut whole = Capture::<Rgb565>::new(w, h);
            Renderer::<3>::new(&mut acc, &mut cover, &mut [], w, h, h)
                .unwrap()
                .render(&mut whole, &RGB565, bg, draw)
                .unwrap();
            for _ in 0..4 {
                let rows = 1 + rng.below(8) as u16;
                let (x0, y0) = (rng.below(60) as i32, rng.below(60) as i32);
                let (ww, wh) = (
                    1 + rng.below(64 - x0 as u64) as u32,
                    1 + rng.below(64 - y0 as u64) as u32,
                );
                let area = Rectangle::new(Point::new(x0, y0), Size::new(ww, wh));
                let mut acc = vec![0; BandBuffer::<3>::acc_len(w, rows)];
                let mut cover = vec![0; BandBuffer::<3>::cover_len(w, rows)];
                let mut slots = [crate::canvas::WalkSlot::<3>::EMPTY; 8];
                let mut part = Capture::<Rgb565>::new(w, h);
                Renderer::<3>::new(&mut acc, &mut cover, &mut slots, w, h, rows)
                    .unwrap()
                    .render_window(&mut part, &RGB565, bg, area, draw)
                    .unwrap();
                for p in area.points() {
                    let k = p.y as usize * usize::from(w) + p.x as usize;
                    assert_eq!(
                        part.px[k], whole.px[k],
                        "case {case}: {p:?}, {area:?} in bands of {rows}"
                    );
                }
                // Whether a band of this window misses the ring.
                let (o, i) = (
                    u64::from(r + width / 2) * 4,
                    u64::from(r.saturating_sub(width / 2)) * 4,
                );
                for band in crate::band::Bands::window(x0, y0, ww as u16, wh as u16, rows) {
                    let misses = crate::canvas::ring_misses(
                        c,
                        o,
                        i,
                        &band.row_range(),
                        &band.column_range(),
                    );
                    skipped_somewhere += usize::from(misses && kind == 2);
                }
            }
        }
        assert!(skipped_somewhere > 20, "{skipped_somewhere}");
    }

    /// The flush sends what the accumulator holds, bit for bit, whether a
    /// pixel went out by its tag or was resolved, in bands that keep tags
    /// and bands that went dense.
    #[test]
    fn the_flush_sends_the_bits_of_the_accumulator() {
        static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
        static GRAY8: Gray8Format = Gray8Format::new(Curve::Srgb);
        check::<3, Rgb565, _>(&&RGB565, [0; 3]);
        check::<3, Rgb565, _>(&&RGB565, [2000, 30, 4095]);
        check::<1, Gray8, _>(&&GRAY8, [700]);
        check::<1, _, _>(&Bayer8::new(), [0]);
        check::<1, _, _>(&Bayer8::new(), [1234]);
        let _ = <Rgb565Format as ToneFormat<3>>::color;
    }
}
