//! [`PageWriter`]: an embedded-graphics `DrawTarget` over the `ssd1306`
//! driver's basic mode that writes whole display pages, so that no frame
//! buffer is needed anywhere.
//!
//! The SSD1306 keeps 1 bit per pixel in pages of 8 rows: byte `x` of page
//! `p` holds column `x` of rows `8p..8p + 8`, bit `r` row `8p + r`. It can
//! be written, not read (over I2C), so a write must bring whole bytes:
//! whole pages. The renderer with bands of 8 rows sends one band per page,
//! 128 x 8 `BinaryColor`s in row order through `fill_contiguous`; this
//! target packs them into the page's 128 bytes and sends those with the
//! driver's `set_draw_area` + `draw`. It is not a band loop: the renderer
//! drives it, one call per band.
//!
//! It takes any area of whole pages (top row and height multiples of 8),
//! of any width and column; a taller area is sent page by page. Anything else, single
//! pixels included, would need the rest of each page's bits, which only
//! the panel has: it is refused with [`PageError::NotWholePages`].

use display_interface::DisplayError;
use embedded_graphics::draw_target::DrawTarget;
use embedded_graphics::geometry::{OriginDimensions, Size};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Pixel;
use ssd1306::mode::BasicMode;
use ssd1306::prelude::{DisplaySize128x64, WriteOnlyDataCommand};
use ssd1306::Ssd1306;

/// Display width, px (one byte per column in a page).
const WIDTH: u32 = 128;
/// Display height, px.
const HEIGHT: u32 = 64;
/// Rows in a page: the bits of a byte.
const PAGE_ROWS: u32 = 8;

/// Why a write was refused or failed.
#[derive(Debug, Clone)]
pub enum PageError {
    /// The display interface (the I2C bus) failed.
    Interface(DisplayError),
    /// The area is not whole pages inside the display, or single pixels
    /// were drawn (see the module docs).
    NotWholePages,
}

impl core::fmt::Display for PageError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::Interface(e) => write!(f, "display interface: {e:?}"),
            Self::NotWholePages => f.write_str("not whole SSD1306 pages"),
        }
    }
}

/// A 128x64 SSD1306 in basic mode (initialised, horizontal addressing),
/// written a page at a time.
pub struct PageWriter<DI> {
    display: Ssd1306<DI, DisplaySize128x64, BasicMode>,
}

impl<DI: WriteOnlyDataCommand> PageWriter<DI> {
    /// Wraps an initialised display (`display.init()` first: it sets the
    /// horizontal addressing `set_draw_area` relies on).
    pub fn new(display: Ssd1306<DI, DisplaySize128x64, BasicMode>) -> Self {
        Self { display }
    }
}

impl<DI> OriginDimensions for PageWriter<DI> {
    fn size(&self) -> Size {
        Size::new(WIDTH, HEIGHT)
    }
}

impl<DI: WriteOnlyDataCommand> DrawTarget for PageWriter<DI> {
    type Color = BinaryColor;
    type Error = PageError;

    /// Single pixels cannot be written without the rest of their page.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), PageError>
    where
        I: IntoIterator<Item = Pixel<BinaryColor>>,
    {
        match pixels.into_iter().next() {
            Some(_) => Err(PageError::NotWholePages),
            None => Ok(()),
        }
    }

    /// Packs each page's rows into its bytes and sends them.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), PageError>
    where
        I: IntoIterator<Item = BinaryColor>,
    {
        let (Ok(x0), Ok(y0)) = (
            u32::try_from(area.top_left.x),
            u32::try_from(area.top_left.y),
        ) else {
            return Err(PageError::NotWholePages);
        };
        let Size { width, height } = area.size;
        let (x1, y1) = (x0.saturating_add(width), y0.saturating_add(height));
        let whole_pages = y0 % PAGE_ROWS == 0 && height % PAGE_ROWS == 0;
        if x1 > WIDTH || y1 > HEIGHT || !whole_pages {
            return Err(PageError::NotWholePages);
        }
        let mut colors = colors.into_iter();
        let mut page = [0u8; WIDTH as usize];
        let bytes = page.get_mut(..width as usize).unwrap_or_default();
        let mut top = y0;
        while top < y1 {
            bytes.fill(0);
            for r in 0..PAGE_ROWS {
                for byte in bytes.iter_mut() {
                    if colors.next() == Some(BinaryColor::On) {
                        *byte |= 1 << r;
                    }
                }
            }
            // Columns and rows are below 128 and 64 here: they fit u8, and
            // the driver's page numbers (row / 8) stay in range.
            self.display
                .set_draw_area((x0 as u8, top as u8), (x1 as u8, (top + PAGE_ROWS) as u8))
                .and_then(|()| self.display.draw(bytes))
                .map_err(PageError::Interface)?;
            top += PAGE_ROWS;
        }
        Ok(())
    }
}
