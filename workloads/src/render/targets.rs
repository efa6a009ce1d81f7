//! The two displays the renderers draw into, both plain RAM.
//!
//! - [`BandSink`]: what a DMA flush takes: one band of the frame, the colours
//!   of one `fill_contiguous` over the band's rectangle copied in order into
//!   a static buffer of raw pixels (`u16` Rgb565, `u8` Gray8), which a real
//!   driver would hand to the SPI DMA.
//! - [`Framebuffer`]: a whole 240x240 Rgb565 frame in RAM, as
//!   embedded-graphics users drive a TFT without bands; `fill_solid` (what
//!   the `Triangle` fill calls per scanline) and `clear` fill row slices, so
//!   embedded-graphics is measured with a good target, not a per-pixel one.

use core::convert::Infallible;
use core::marker::PhantomData;

use embedded_graphics::pixelcolor::{IntoStorage, Rgb565};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;

/// One band of a `width`-wide frame, rows `y0..y0 + rows`, as raw pixels
/// of colour `C` (`C::Storage`: `u16` for Rgb565, `u8` for Gray8).
pub struct BandSink<'a, C: IntoStorage> {
    px: &'a mut [C::Storage],
    width: u32,
    height: u32,
    y0: i32,
    rows: u32,
    color: PhantomData<C>,
}

impl<'a, C: IntoStorage> BandSink<'a, C> {
    /// A sink over `px` (at least `width * rows` pixels) for the band at
    /// frame row `y0` of a `width x height` display.
    pub fn new(px: &'a mut [C::Storage], width: u32, height: u32, y0: i32, rows: u32) -> Self {
        Self {
            px,
            width,
            height,
            y0,
            rows,
            color: PhantomData,
        }
    }

    /// The raw pixels of the band, row after row.
    pub fn pixels(&self) -> &[C::Storage] {
        &self.px[..]
    }
}

impl<C: IntoStorage> OriginDimensions for BandSink<'_, C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl<C> DrawTarget for BandSink<'_, C>
where
    C: PixelColor + IntoStorage,
{
    type Color = C;
    type Error = Infallible;

    /// Single pixels (unused by the flush): stored if inside the band.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        for Pixel(p, c) in pixels {
            let r = p.y - self.y0;
            if p.x >= 0 && (p.x as u32) < self.width && r >= 0 && (r as u32) < self.rows {
                let k = r as usize * self.width as usize + p.x as usize;
                if let Some(slot) = self.px.get_mut(k) {
                    *slot = c.into_storage();
                }
            }
        }
        Ok(())
    }

    /// The band's flush: the colours of the band's rectangle, in order,
    /// into the buffer (a DMA transfer's source). Any other rectangle goes
    /// pixel by pixel.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        let band = Rectangle::new(Point::new(0, self.y0), Size::new(self.width, self.rows));
        if *area != band {
            return self.draw_iter(area.points().zip(colors).map(|(p, c)| Pixel(p, c)));
        }
        for (slot, c) in self.px.iter_mut().zip(colors) {
            *slot = c.into_storage();
        }
        Ok(())
    }
}

/// What a DMA display takes from a band renderer: each `fill_contiguous`
/// sets the window (here: nothing to do) and streams the colours in
/// order into one band's buffer of raw pixels, which a real driver hands
/// to the SPI DMA; any band of a `width x height` display.
pub struct BandStream<'a, C: IntoStorage> {
    px: &'a mut [C::Storage],
    width: u32,
    height: u32,
    color: PhantomData<C>,
}

impl<'a, C: IntoStorage> BandStream<'a, C> {
    /// A stream into `px` (as many pixels as the largest band).
    pub fn new(px: &'a mut [C::Storage], width: u32, height: u32) -> Self {
        Self {
            px,
            width,
            height,
            color: PhantomData,
        }
    }

    /// The last band's raw pixels, row after row.
    pub fn pixels(&self) -> &[C::Storage] {
        &self.px[..]
    }
}

impl<C: IntoStorage> OriginDimensions for BandStream<'_, C> {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl<C> DrawTarget for BandStream<'_, C>
where
    C: PixelColor + IntoStorage,
{
    type Color = C;
    type Error = Infallible;

    /// Single pixels are not what a band renderer sends: dropped.
    fn draw_iter<I>(&mut self, _pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<C>>,
    {
        Ok(())
    }

    /// A window's colours, in order, into the buffer (the DMA's source):
    /// the area's and no more (e-g's `fill_solid` passes an endless
    /// `repeat`).
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = C>,
    {
        let n = area.size.width as usize * area.size.height as usize;
        let px = self.px.get_mut(..n.min(self.px.len())).unwrap_or_default();
        for (slot, c) in px.iter_mut().zip(colors) {
            *slot = c.into_storage();
        }
        Ok(())
    }
}

/// The same buffer lent for the band's pixels to be made in
/// (`Renderer::render_lent`): the DMA's source, sent by the driver
/// (here: nothing to do).
impl softedge::render::BandTarget for BandStream<'_, Rgb565> {
    type Color = Rgb565;
    type Raw = u16;
    type Error = Infallible;

    fn buffer(&mut self) -> &mut [u16] {
        self.px
    }

    fn send(&mut self, _area: &Rectangle) -> Result<(), Self::Error> {
        Ok(())
    }
}

/// Command bytes an ST7789 needs to open a window: CASET, RASET, RAMWR.
pub const WINDOW_COMMAND_BYTES: u32 = 3;
/// Parameter bytes of those commands: CASET and RASET 4 each (start and
/// end, 16 bits each), RAMWR none.
pub const WINDOW_PARAM_BYTES: u32 = 8;
/// Bytes of an Rgb565 pixel on the wire.
pub const RGB565_BYTES: u32 = 2;

/// What an SPI display (ST7789-like, Rgb565) would be sent, counted and
/// not stored: each `fill_contiguous` opens one window and streams its
/// pixels; each pixel of `draw_iter` is a window of its own.
pub struct SpiCounter {
    width: u32,
    height: u32,
    /// Windows opened (CASET + RASET + RAMWR each).
    pub windows: u32,
    /// Pixels sent.
    pub pixels: u32,
}

impl SpiCounter {
    /// A counter for a `width x height` display, at zero.
    pub const fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            windows: 0,
            pixels: 0,
        }
    }

    /// Bytes on the wire:
    /// `pixels * 2 + windows * (3 command + 8 parameter bytes)`.
    pub fn bytes(&self) -> u32 {
        self.pixels * RGB565_BYTES + self.windows * (WINDOW_COMMAND_BYTES + WINDOW_PARAM_BYTES)
    }
}

impl OriginDimensions for SpiCounter {
    fn size(&self) -> Size {
        Size::new(self.width, self.height)
    }
}

impl DrawTarget for SpiCounter {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Rgb565>>,
    {
        for _ in pixels {
            self.windows += 1;
            self.pixels += 1;
        }
        Ok(())
    }

    /// One window; the area's colours are taken, and counted (the
    /// renderer resets its band as they are taken; `fill_solid`'s
    /// iterator never ends, so no more than the area's are).
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Rgb565>,
    {
        self.windows += 1;
        let n = area.size.width as usize * area.size.height as usize;
        for _ in colors.into_iter().take(n) {
            self.pixels += 1;
        }
        Ok(())
    }
}

/// Width and height of [`Framebuffer`].
pub const FB_SIDE: usize = 240;
/// Pixels of [`Framebuffer`].
pub const FB_LEN: usize = FB_SIDE * FB_SIDE;

/// A 240x240 Rgb565 frame in RAM.
pub struct Framebuffer<'a> {
    px: &'a mut [u16; FB_LEN],
}

impl<'a> Framebuffer<'a> {
    /// A framebuffer over `px`.
    pub fn new(px: &'a mut [u16; FB_LEN]) -> Self {
        Self { px }
    }

    /// The raw Rgb565 pixels, row after row.
    pub fn pixels(&self) -> &[u16; FB_LEN] {
        self.px
    }
}

impl OriginDimensions for Framebuffer<'_> {
    fn size(&self) -> Size {
        Size::new(FB_SIDE as u32, FB_SIDE as u32)
    }
}

impl DrawTarget for Framebuffer<'_> {
    type Color = Rgb565;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<Rgb565>>,
    {
        for Pixel(p, c) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as usize) < FB_SIDE && (p.y as usize) < FB_SIDE {
                if let Some(slot) = self.px.get_mut(p.y as usize * FB_SIDE + p.x as usize) {
                    *slot = c.into_storage();
                }
            }
        }
        Ok(())
    }

    /// Clipped to the frame, then one slice fill per row.
    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Self::Error> {
        let area = area.intersection(&self.bounding_box());
        let Some(bottom_right) = area.bottom_right() else {
            return Ok(());
        };
        let raw = color.into_storage();
        let (x0, x1) = (area.top_left.x as usize, bottom_right.x as usize + 1);
        for y in area.top_left.y as usize..=bottom_right.y as usize {
            let row = y * FB_SIDE;
            if let Some(span) = self.px.get_mut(row + x0..row + x1) {
                span.fill(raw);
            }
        }
        Ok(())
    }

    fn clear(&mut self, color: Rgb565) -> Result<(), Self::Error> {
        self.px.fill(color.into_storage());
        Ok(())
    }
}
