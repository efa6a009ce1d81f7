//! A display for the renderer's tests: it keeps what it is sent, pixel by
//! pixel (`None` where nothing came), and the rectangles of the
//! `fill_contiguous` calls that sent it.

use embedded_graphics::pixelcolor::PixelColor;
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Pixel, PointsIter, Size};
use embedded_graphics::primitives::Rectangle;

/// A `w x h` display that keeps what it is sent.
pub struct Screen<C> {
    /// Width in pixels.
    pub w: u32,
    /// Height in pixels.
    pub h: u32,
    /// Each pixel's last colour, row-major.
    pub px: Vec<Option<C>>,
    /// The areas of the `fill_contiguous` calls, in order.
    pub windows: Vec<Rectangle>,
}

impl<C: PixelColor> Screen<C> {
    /// A display that was sent nothing.
    pub fn new(w: u32, h: u32) -> Self {
        Self {
            w,
            h,
            px: vec![None; (w * h) as usize],
            windows: vec![],
        }
    }

    /// What pixel `(x, y)` was last sent.
    pub fn at(&self, x: i32, y: i32) -> Option<C> {
        self.px[(y as u32 * self.w + x as u32) as usize]
    }
}

impl<C: PixelColor> OriginDimensions for Screen<C> {
    fn size(&self) -> Size {
        Size::new(self.w, self.h)
    }
}

impl<C: PixelColor> DrawTarget for Screen<C> {
    type Color = C;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<C>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if p.x >= 0 && p.y >= 0 && (p.x as u32) < self.w && (p.y as u32) < self.h {
                self.px[(p.y as u32 * self.w + p.x as u32) as usize] = Some(c);
            }
        }
        Ok(())
    }
    fn fill_contiguous<I: IntoIterator<Item = C>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        self.windows.push(*area);
        let pts = area.points();
        self.draw_iter(pts.zip(colors).map(|(p, c)| Pixel(p, c)))
    }
}
