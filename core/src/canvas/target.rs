//! The canvas as an embedded-graphics `DrawTarget`: embedded-graphics'
//! own text, images and primitives draw into a band, aliased, each pixel
//! an opaque colour composed in painter's order with the rest.

use core::convert::Infallible;

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::PixelColor;
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

use super::Canvas;
use crate::color::IntoLinear;

impl<const C: usize, Col> OriginDimensions for Canvas<'_, '_, C, Col> {
    /// The whole frame: embedded-graphics clips to it; the band keeps only
    /// its own rows.
    fn size(&self) -> Size {
        Size::new(u32::from(self.frame.0), u32::from(self.frame.1))
    }
}

impl<const C: usize, Col: PixelColor + IntoLinear<C>> DrawTarget for Canvas<'_, '_, C, Col> {
    type Color = Col;
    type Error = Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Infallible>
    where
        I: IntoIterator<Item = Pixel<Col>>,
    {
        for Pixel(p, c) in pixels {
            self.buf.store_pixel(p.x, p.y, c.into_linear());
        }
        Ok(())
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Col) -> Result<(), Infallible> {
        let lin = color.into_linear();
        let (x0, x1) = (
            area.top_left.x,
            area.top_left.x.saturating_add(area.size.width as i32),
        );
        let rows = self.buf.band().row_range();
        let (y0, y1) = (
            area.top_left.y.max(rows.start),
            area.top_left
                .y
                .saturating_add(area.size.height as i32)
                .min(rows.end),
        );
        for y in y0..y1 {
            self.buf.store_span(x0, x1, y, lin);
        }
        Ok(())
    }
}
