//! A page writer for SSD1306 / SH1106-style 1-bit displays (feature
//! `display-interface`): the renderer's bands go to the panel as they are
//! made, with no frame buffer anywhere.
//!
//! Takes the bands of a 1-bit frame (`BinaryColor`, one `fill_contiguous`
//! per band, rows top to bottom, as [`Renderer`](super::Renderer) sends
//! them) and gives the panel's controller whole pages over
//! `display-interface`: the controller keeps 1 bit per pixel in pages of 8
//! rows, byte `x` of page `p` holding column `x` of rows `8p..8p + 8`, bit
//! `r` row `8p + r`. Over I2C or SPI it can be written, not read, so a
//! write must bring whole bytes: the writer packs the rows of each page
//! into its one page buffer (128 bytes) and sends the page when its last
//! row arrives. Bands of any height work (1 or 2 rows keep the band
//! buffers small; a band may end inside a page or span two): a 128x64
//! frame in 2-row bands needs about 2.7 KiB of RAM in all (band buffers,
//! Floyd–Steinberg's rows, this writer and the renderer; measured by
//! `host-sim/tests/page_writer.rs`), against the 1 KiB frame buffer plus
//! the band buffers of a buffered driver.
//!
//! The commands are the controllers' own (datasheets: SSD1306 rev 1.1,
//! SH1106 v2.3):
//!
//! - SSD1306: horizontal addressing (`0x20 0x00`, once), then per page
//!   the column range (`0x21 x0 x1`) and the page range (`0x22 p p`), and
//!   the page's bytes.
//! - SH1106 (132 columns of RAM, a 128-pixel panel at column 2; page
//!   addressing only): per page `0xB0 | p`, the column's low and high
//!   nibbles (`0x00 | c & 0xF`, `0x10 | c >> 4`), and the page's bytes.
//!
//! Initialise the panel with its driver crate first (power, charge pump,
//! contrast: `ssd1306`'s `init`, then `release` its interface to this
//! writer), or with your own command list.
//!
//! An area must be rows of whole pages: each page's rows in order, over
//! the same columns, until the page is complete; a partial redraw
//! ([`Renderer::render_window`](super::Renderer::render_window)) of any
//! columns works when its top and height are multiples of 8. Anything
//! else (single pixels, a page left unfinished) would need the rest of
//! the page's bits, which only the panel has: it is refused with
//! [`PageError::NotWholePages`].
//!
//! ```
//! use display_interface::{DataFormat, DisplayError, WriteOnlyDataCommand};
//! use embedded_graphics::pixelcolor::BinaryColor;
//! use embedded_graphics::prelude::*;
//! use embedded_graphics::primitives::Circle;
//! use softedge::prelude::*;
//! use softedge::render::pages::PageWriter;
//! # struct I2c(usize);
//! # impl WriteOnlyDataCommand for I2c {
//! #     fn send_commands(&mut self, _: DataFormat<'_>) -> Result<(), DisplayError> { Ok(()) }
//! #     fn send_data(&mut self, d: DataFormat<'_>) -> Result<(), DisplayError> {
//! #         if let DataFormat::U8(b) = d { self.0 += b.len() } Ok(())
//! #     }
//! # }
//! # let interface = I2c(0);
//! let mut oled = PageWriter::ssd1306_128x64(interface); // ssd1306's interface, after its init
//! let mut acc = [0; BandBuffer::<1>::acc_len(128, 2)]; // bands of 2 rows: 1 024 bytes
//! let mut cover = [0; BandBuffer::<1>::cover_len(128, 2)]; // 1 056 bytes
//! let (mut err_row, mut bits) = ([0i16; 128], [false; 128]);
//! let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 128, 64, 2)?;
//! let mut dither = DiffusionProfile::new(&mut err_row, &mut bits);
//! renderer.render(&mut oled, &mut dither, BinaryColor::Off, |canvas| {
//!     Circle::new(Point::new(40, 8), 48).into_styled(AaStyle::with_fill(BinaryColor::On)).draw(canvas)
//! })?;
//! assert_eq!(oled.release().0, 1024); // 8 pages of 128 bytes
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use core::fmt::{self, Display, Formatter};

use display_interface::{DataFormat, DisplayError, WriteOnlyDataCommand};
use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::BinaryColor;
use embedded_graphics_core::primitives::Rectangle;
use embedded_graphics_core::Pixel;

/// Rows in a page: the bits of a byte.
const PAGE_ROWS: u8 = 8;
/// The widest panel (bytes in a page buffer).
pub const MAX_WIDTH: u8 = 128;
/// The tallest panel: 8 pages.
pub const MAX_HEIGHT: u8 = 64;
/// Where an SH1106's 128 pixels start in its 132 columns of RAM.
const SH1106_COLUMN_OFFSET: u8 = 2;

/// The controller's command set.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum Controller {
    /// SSD1306 (and SSD1309, SSD1315): horizontal addressing, column and
    /// page ranges.
    Ssd1306,
    /// SH1106 (and SH1107 in landscape, SSD1305-style page addressing):
    /// page addressing, the panel at RAM column 2.
    Sh1106,
}

/// Why a page writer refused an area or failed.
#[derive(Debug, Clone)]
#[non_exhaustive]
pub enum PageError {
    /// The display interface (the I2C or SPI bus) failed.
    Interface(DisplayError),
    /// Not rows of whole pages (single pixels, rows out of order, a page
    /// left unfinished for another): see the [module docs](self).
    NotWholePages,
    /// The area reaches outside the panel, px.
    OutOfBounds {
        /// The area asked for.
        area: Rectangle,
    },
    /// A panel size the writer cannot address (1..=128 columns, 8..=64
    /// rows in whole pages), px.
    Size {
        /// Width and height asked for.
        width: u8,
        /// Height asked for.
        height: u8,
    },
}

impl Display for PageError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::Interface(e) => write!(f, "display interface: {e:?}"),
            Self::NotWholePages => f.write_str("not rows of whole display pages"),
            Self::OutOfBounds { area } => write!(
                f,
                "area {}x{} at ({}, {}) px reaches outside the panel",
                area.size.width, area.size.height, area.top_left.x, area.top_left.y
            ),
            Self::Size { width, height } => write!(
                f,
                "panel {width}x{height} px: width must be 1..={MAX_WIDTH}, height 8..={MAX_HEIGHT} in whole pages of 8"
            ),
        }
    }
}

impl core::error::Error for PageError {}

#[cfg(feature = "defmt")]
impl defmt::Format for PageError {
    fn format(&self, f: defmt::Formatter<'_>) {
        // `DisplayError` logs with another defmt version: named only.
        match self {
            Self::Interface(_) => defmt::write!(f, "Interface"),
            Self::NotWholePages => defmt::write!(f, "NotWholePages"),
            Self::OutOfBounds { area } => defmt::write!(
                f,
                "OutOfBounds({}x{} at {}, {})",
                area.size.width,
                area.size.height,
                area.top_left.x,
                area.top_left.y
            ),
            Self::Size { width, height } => defmt::write!(f, "Size({}x{})", width, height),
        }
    }
}

/// The page being filled: its index, columns and the next row expected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Filling {
    page: u8,
    x0: u8,
    width: u8,
    /// Row within the page expected next.
    next: u8,
}

/// An embedded-graphics `DrawTarget<Color = BinaryColor>` that writes an
/// SSD1306 / SH1106-style panel page by page through `display-interface`
/// (see the [module docs](self)): 128 bytes of page buffer and a few of
/// state, beside the interface.
#[derive(Debug)]
pub struct PageWriter<DI> {
    di: DI,
    controller: Controller,
    width: u8,
    height: u8,
    /// SSD1306's addressing mode has been set.
    mode_set: bool,
    filling: Option<Filling>,
    page: [u8; MAX_WIDTH as usize],
}

impl<DI> PageWriter<DI> {
    /// A 128x64 SSD1306 on `di`.
    pub const fn ssd1306_128x64(di: DI) -> Self {
        Self {
            di,
            controller: Controller::Ssd1306,
            width: MAX_WIDTH,
            height: MAX_HEIGHT,
            mode_set: false,
            filling: None,
            page: [0; MAX_WIDTH as usize],
        }
    }

    /// A `width x height` panel of `controller` on `di` (1..=128 columns,
    /// 8..=64 rows, a multiple of 8: 128x64, 128x32, 96x16, 64x48, ...).
    ///
    /// ```
    /// use softedge::render::pages::{Controller, PageError, PageWriter};
    /// assert!(PageWriter::new((), Controller::Sh1106, 128, 64).is_ok());
    /// assert!(matches!(
    ///     PageWriter::new((), Controller::Ssd1306, 128, 60),
    ///     Err(PageError::Size { width: 128, height: 60 })
    /// ));
    /// ```
    pub fn new(di: DI, controller: Controller, width: u8, height: u8) -> Result<Self, PageError> {
        let ok = (1..=MAX_WIDTH).contains(&width)
            && (PAGE_ROWS..=MAX_HEIGHT).contains(&height)
            && height % PAGE_ROWS == 0;
        if !ok {
            return Err(PageError::Size { width, height });
        }
        let mut w = Self::ssd1306_128x64(di);
        (w.controller, w.width, w.height) = (controller, width, height);
        Ok(w)
    }

    /// The interface back (for the driver's other commands: contrast,
    /// power, rotation).
    pub fn release(self) -> DI {
        self.di
    }

    /// The interface, lent.
    pub fn interface(&mut self) -> &mut DI {
        &mut self.di
    }
}

impl<DI: WriteOnlyDataCommand> PageWriter<DI> {
    /// Sends the filled page.
    fn send(&mut self, f: Filling) -> Result<(), PageError> {
        let bytes = self.page.get(..usize::from(f.width)).unwrap_or_default();
        match self.controller {
            Controller::Ssd1306 => {
                if !self.mode_set {
                    self.di
                        .send_commands(DataFormat::U8(&[0x20, 0x00]))
                        .map_err(PageError::Interface)?;
                    self.mode_set = true;
                }
                // `x0 + width <= 128` and `page < 8` (checked by the caller).
                let x1 = f.x0 + (f.width - 1);
                let cmds = [0x21, f.x0, x1, 0x22, f.page, f.page];
                self.di.send_commands(DataFormat::U8(&cmds))
            }
            Controller::Sh1106 => {
                let col = f.x0 + SH1106_COLUMN_OFFSET;
                let cmds = [0xB0 | f.page, col & 0x0F, 0x10 | (col >> 4)];
                self.di.send_commands(DataFormat::U8(&cmds))
            }
        }
        .and_then(|()| self.di.send_data(DataFormat::U8(bytes)))
        .map_err(PageError::Interface)
    }
}

impl<DI> OriginDimensions for PageWriter<DI> {
    fn size(&self) -> Size {
        Size::new(u32::from(self.width), u32::from(self.height))
    }
}

impl<DI: WriteOnlyDataCommand> DrawTarget for PageWriter<DI> {
    type Color = BinaryColor;
    type Error = PageError;

    /// Single pixels cannot be written without the rest of their page:
    /// refused (nothing sent), unless there are none.
    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), PageError>
    where
        I: IntoIterator<Item = Pixel<BinaryColor>>,
    {
        match pixels.into_iter().next() {
            Some(_) => Err(PageError::NotWholePages),
            None => Ok(()),
        }
    }

    /// Packs each row into the page buffer's bits and sends each page as
    /// its last row arrives (see the [module docs](self)). Colours missing
    /// at the end count as off.
    fn fill_contiguous<I>(&mut self, area: &Rectangle, colors: I) -> Result<(), PageError>
    where
        I: IntoIterator<Item = BinaryColor>,
    {
        let Size { width, height } = area.size;
        if width == 0 || height == 0 {
            return Ok(());
        }
        let out = PageError::OutOfBounds { area: *area };
        let (Ok(x0), Ok(y0)) = (u8::try_from(area.top_left.x), u8::try_from(area.top_left.y))
        else {
            return Err(out);
        };
        let (Ok(w), Ok(h)) = (u8::try_from(width), u8::try_from(height)) else {
            return Err(out);
        };
        if u16::from(x0) + u16::from(w) > u16::from(self.width)
            || u16::from(y0) + u16::from(h) > u16::from(self.height)
        {
            return Err(out);
        }
        let mut colors = colors.into_iter();
        for y in y0..y0 + h {
            let (page, row) = (y / PAGE_ROWS, y % PAGE_ROWS);
            let f = match self.filling.take() {
                Some(f) if (f.page, f.x0, f.width, f.next) == (page, x0, w, row) => f,
                None if row == 0 => Filling {
                    page,
                    x0,
                    width: w,
                    next: 0,
                },
                _ => return Err(PageError::NotWholePages),
            };
            let bytes = self.page.get_mut(..usize::from(w)).unwrap_or_default();
            if row == 0 {
                bytes.fill(0);
            }
            let bit = 1u8 << row;
            for byte in bytes.iter_mut() {
                if colors.next() == Some(BinaryColor::On) {
                    *byte |= bit;
                }
            }
            if row + 1 == PAGE_ROWS {
                self.send(f)?;
            } else {
                self.filling = Some(Filling { next: row + 1, ..f });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;
    use std::vec::Vec;

    use super::*;
    use embedded_graphics_core::geometry::Point;

    /// Records every command and data batch.
    #[derive(Default)]
    struct Log(Vec<(bool, Vec<u8>)>);

    impl WriteOnlyDataCommand for Log {
        fn send_commands(&mut self, cmd: DataFormat<'_>) -> Result<(), DisplayError> {
            match cmd {
                DataFormat::U8(b) => self.0.push((true, b.to_vec())),
                _ => return Err(DisplayError::DataFormatNotImplemented),
            }
            Ok(())
        }
        fn send_data(&mut self, buf: DataFormat<'_>) -> Result<(), DisplayError> {
            match buf {
                DataFormat::U8(b) => self.0.push((false, b.to_vec())),
                _ => return Err(DisplayError::DataFormatNotImplemented),
            }
            Ok(())
        }
    }

    fn rect(x: i32, y: i32, w: u32, h: u32) -> Rectangle {
        Rectangle::new(Point::new(x, y), Size::new(w, h))
    }

    /// Bands of 3 rows (ending inside pages, spanning two) give the bytes
    /// of whole pages, each sent once, with the SSD1306's commands.
    #[test]
    fn bands_of_any_height_make_whole_pages() {
        let mut w = PageWriter::new(Log::default(), Controller::Ssd1306, 16, 16).unwrap();
        // Pixel (x, y) on iff x == y (a diagonal).
        for y0 in (0..16).step_by(3) {
            let h = 3.min(16 - y0);
            let colors = (y0..y0 + h)
                .flat_map(|y| (0..16).map(move |x| BinaryColor::from(x == y)))
                .collect::<Vec<_>>();
            w.fill_contiguous(&rect(0, y0, 16, h as u32), colors)
                .unwrap();
        }
        let log = w.release().0;
        let expected_page = |p: u8| {
            (0..16u8)
                .map(|x| if x / 8 == p { 1 << (x % 8) } else { 0 })
                .collect::<Vec<u8>>()
        };
        assert_eq!(
            log,
            [
                (true, vec![0x20, 0x00]),
                (true, vec![0x21, 0, 15, 0x22, 0, 0]),
                (false, expected_page(0)),
                (true, vec![0x21, 0, 15, 0x22, 1, 1]),
                (false, expected_page(1)),
            ]
        );
    }

    /// A window of whole pages at column 5, on an SH1106 (page
    /// addressing, RAM column 7); anything not whole pages is refused.
    #[test]
    fn windows_of_whole_pages_and_refusals() {
        let mut w = PageWriter::new(Log::default(), Controller::Sh1106, 128, 64).unwrap();
        let on = core::iter::repeat(BinaryColor::On);
        w.fill_contiguous(&rect(5, 8, 20, 8), on.clone()).unwrap();
        assert!(matches!(
            w.fill_contiguous(&rect(0, 3, 4, 2), on.clone()),
            Err(PageError::NotWholePages)
        ));
        // A page started over other columns, then another page: refused.
        w.fill_contiguous(&rect(0, 16, 4, 4), on.clone()).unwrap();
        assert!(matches!(
            w.fill_contiguous(&rect(1, 20, 4, 4), on.clone()),
            Err(PageError::NotWholePages)
        ));
        assert!(matches!(
            w.fill_contiguous(&rect(120, 0, 9, 8), on.clone()),
            Err(PageError::OutOfBounds { .. })
        ));
        assert!(matches!(
            w.fill_contiguous(&rect(-1, 0, 9, 8), on.clone()),
            Err(PageError::OutOfBounds { .. })
        ));
        assert!(matches!(
            w.draw_iter([Pixel(Point::new(1, 1), BinaryColor::On)]),
            Err(PageError::NotWholePages)
        ));
        let log = w.release().0;
        assert_eq!(
            log,
            [(true, vec![0xB1, 0x07, 0x10]), (false, vec![0xFF; 20])]
        );
    }

    #[test]
    fn sizes_out_of_reach_are_refused() {
        for (w, h) in [(0, 64), (129, 64), (128, 0), (128, 72), (128, 12)] {
            assert!(
                matches!(
                    PageWriter::new((), Controller::Ssd1306, w, h),
                    Err(PageError::Size { .. })
                ),
                "{w}x{h}"
            );
        }
    }
}
