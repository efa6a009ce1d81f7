//! embedded-graphics glue: flushing finished bands to any `DrawTarget`.
//!
//! Takes a resolved band (linear 12-bit per channel) and a conversion to the
//! display's colour type (normally the [`tone`](crate::tone) stage: γ table,
//! then the pixel format); gives the display one
//! [`DrawTarget::fill_contiguous`] call per band, over the band's rectangle,
//! row by row: a DMA-friendly stream that never reads the display back, so
//! write-only SPI displays work. Rows of the band below the frame are left
//! to the target's own clipping, as embedded-graphics requires of every
//! target.
//!
//! [`Renderer`] runs the whole band loop: for every band it clears the
//! buffer, calls your drawing closure (draw the scene's primitives into the
//! band: every band gets every primitive, each clipped to the band), then
//! flushes. The closure is called once per band, so keep the scene in data
//! it can read again.

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{Point, Size};
use embedded_graphics_core::primitives::Rectangle;

use crate::band::{BandBuffer, BandError, Bands};
use crate::raster::DrawError;

impl<const C: usize> BandBuffer<'_, C> {
    /// Sends the band to `target` with one `fill_contiguous` over its
    /// rectangle, converting each pixel's linear 12-bit values with
    /// `convert`.
    ///
    /// ```
    /// use embedded_graphics_core::pixelcolor::Gray8;
    /// # use embedded_graphics_core::{draw_target::DrawTarget, geometry::{OriginDimensions, Size}, Pixel};
    /// # struct Screen(Vec<u8>);
    /// # impl OriginDimensions for Screen { fn size(&self) -> Size { Size::new(4, 2) } }
    /// # impl DrawTarget for Screen {
    /// #     type Color = Gray8;
    /// #     type Error = core::convert::Infallible;
    /// #     fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(&mut self, px: I) -> Result<(), Self::Error> {
    /// #         for Pixel(p, c) in px { self.0[(p.y * 4 + p.x) as usize] = embedded_graphics_core::pixelcolor::GrayColor::luma(&c); }
    /// #         Ok(())
    /// #     }
    /// # }
    /// use softedge::{Band, BandBuffer};
    /// let mut screen = Screen(vec![0; 8]);
    /// let (mut acc, mut cover) = ([0i32; 8], [0i32; 16]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(4, 0, 2)).unwrap();
    /// buf.clear([4095]);
    /// buf.flush(&mut screen, |[v]| Gray8::new((v >> 4) as u8)).unwrap();
    /// assert_eq!(screen.0, [255; 8]);
    /// ```
    pub fn flush<D: DrawTarget>(
        &self,
        target: &mut D,
        mut convert: impl FnMut([u16; C]) -> D::Color,
    ) -> Result<(), D::Error> {
        let band = self.band();
        let area = Rectangle::new(
            Point::new(0, band.y0),
            Size::new(u32::from(band.width), u32::from(band.rows)),
        );
        let w = i32::from(band.width);
        let rows = i32::from(band.rows);
        let colors = (0..rows).flat_map(move |r| (0..w).map(move |x| (x, band.y0 + r)));
        target.fill_contiguous(
            &area,
            colors.map(|(x, y)| convert(self.lin12(x, y).unwrap_or([0; C]))),
        )
    }
}

/// Why a frame was not rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RenderError<E> {
    /// The band buffers do not fit the frame's bands.
    Band(BandError),
    /// A primitive was rejected (the frame stops at that band).
    Draw(DrawError),
    /// The display reported an error.
    Target(E),
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
/// use softedge::eg::Renderer;
/// use softedge::{BandBuffer, RenderStyle, SubPoint, Triangle};
/// const W: u16 = 16;
/// const ROWS: u16 = 4;
/// let mut acc = [0i32; BandBuffer::<1>::acc_len(W, ROWS)];
/// let mut cover = [0i32; BandBuffer::<1>::cover_len(W, ROWS)];
/// let mut screen = Screen(vec![0; 16 * 12]);
/// let tri = Triangle::flat([SubPoint::from_px(0, 0), SubPoint::from_px(16, 0), SubPoint::from_px(0, 12)], [4095]);
/// let mut renderer = Renderer::new(&mut acc, &mut cover, W, 12, ROWS);
/// renderer
///     .render(&mut screen, [0], |band| tri.draw(band, &RenderStyle::default()), |[v]| Gray8::new((v >> 4) as u8))
///     .unwrap();
/// assert_eq!(screen.0[0], 255);
/// assert_eq!(screen.0[16 * 12 - 1], 0);
/// ```
#[derive(Debug)]
pub struct Renderer<'a, const C: usize> {
    acc: &'a mut [i32],
    cover: &'a mut [i32],
    width: u16,
    height: u16,
    band_rows: u16,
}

impl<'a, const C: usize> Renderer<'a, C> {
    /// A renderer for a `width x height` frame in bands of `band_rows`.
    pub fn new(
        acc: &'a mut [i32],
        cover: &'a mut [i32],
        width: u16,
        height: u16,
        band_rows: u16,
    ) -> Self {
        Self {
            acc,
            cover,
            width,
            height,
            band_rows: band_rows.max(1),
        }
    }

    /// Renders one frame: per band, clear to `background`, `draw`, flush
    /// through `convert`.
    pub fn render<D: DrawTarget>(
        &mut self,
        target: &mut D,
        background: [u16; C],
        mut draw: impl FnMut(&mut BandBuffer<'_, C>) -> Result<(), DrawError>,
        mut convert: impl FnMut([u16; C]) -> D::Color,
    ) -> Result<(), RenderError<D::Error>> {
        for band in Bands::new(self.width, self.height, self.band_rows) {
            let mut buf = BandBuffer::new(self.acc, self.cover, band).map_err(RenderError::Band)?;
            buf.clear(background);
            draw(&mut buf).map_err(RenderError::Draw)?;
            buf.flush(target, &mut convert)
                .map_err(RenderError::Target)?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use embedded_graphics_core::geometry::{OriginDimensions, Size};
    use embedded_graphics_core::pixelcolor::{Gray8, GrayColor};
    use embedded_graphics_core::primitives::Rectangle;
    use embedded_graphics_core::Pixel;

    use super::*;
    use crate::{RenderStyle, SubPoint, Triangle};

    /// A write-only display: accepts whole rows through `fill_contiguous`
    /// only, and panics on any per-pixel write or write outside it.
    struct WriteOnly {
        size: Size,
        frame: Vec<u8>,
        calls: Vec<Rectangle>,
    }

    impl OriginDimensions for WriteOnly {
        fn size(&self) -> Size {
            self.size
        }
    }

    impl DrawTarget for WriteOnly {
        type Color = Gray8;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Gray8>>>(
            &mut self,
            _: I,
        ) -> Result<(), Self::Error> {
            panic!("per-pixel writes are not expected");
        }
        fn fill_contiguous<I: IntoIterator<Item = Gray8>>(
            &mut self,
            area: &Rectangle,
            colors: I,
        ) -> Result<(), Self::Error> {
            let w = self.size.width as i32;
            assert_eq!(area.top_left.x, 0);
            assert_eq!(area.size.width, self.size.width, "whole rows");
            self.calls.push(*area);
            let mut n = 0;
            for (k, c) in colors.into_iter().enumerate() {
                let (x, y) = (k as i32 % w, area.top_left.y + k as i32 / w);
                // The last band may run past the frame: clip, as targets must.
                if y < self.size.height as i32 {
                    self.frame[(y * w + x) as usize] = c.luma();
                }
                n += 1;
            }
            assert_eq!(n, area.size.width * area.size.height);
            Ok(())
        }
    }

    #[test]
    fn every_band_arrives_in_one_fill_contiguous() {
        const W: u16 = 20;
        const H: u16 = 13;
        const ROWS: u16 = 4;
        let mut acc = [0i32; BandBuffer::<1>::acc_len(W, ROWS)];
        let mut cover = [0i32; BandBuffer::<1>::cover_len(W, ROWS)];
        let mut screen = WriteOnly {
            size: Size::new(u32::from(W), u32::from(H)),
            frame: std::vec![0; usize::from(W) * usize::from(H)],
            calls: Vec::new(),
        };
        let tri = Triangle::flat(
            [
                SubPoint::from_px(-5, -5),
                SubPoint::from_px(30, 2),
                SubPoint::from_px(3, 20),
            ],
            [4095],
        );
        let mut r = Renderer::new(&mut acc, &mut cover, W, H, ROWS);
        r.render(
            &mut screen,
            [0],
            |b| tri.draw(b, &RenderStyle::default()),
            |[v]| Gray8::new((v >> 4) as u8),
        )
        .unwrap();
        let ys: Vec<i32> = screen.calls.iter().map(|a| a.top_left.y).collect();
        assert_eq!(ys, [0, 4, 8, 12]);
        assert_eq!(screen.calls[3].size.height, 1);
        assert_eq!(screen.frame[0], 255);
        assert_eq!(screen.frame[usize::from(W) * usize::from(H) - 1], 0);
    }

    #[test]
    fn short_buffers_are_an_error_not_a_panic() {
        let mut acc = [0i32; 10];
        let mut cover = [0i32; 10];
        let mut screen = WriteOnly {
            size: Size::new(20, 4),
            frame: std::vec![0; 80],
            calls: Vec::new(),
        };
        let mut r = Renderer::<1>::new(&mut acc, &mut cover, 20, 4, 4);
        let e = r.render(
            &mut screen,
            [0],
            |_| Ok(()),
            |[v]| Gray8::new((v >> 4) as u8),
        );
        assert_eq!(e, Err(RenderError::Band(BandError::AccTooSmall)));
    }
}
