//! What the example programs and their embedded-graphics twins share:
//! showing a display (a window with `--features window`, else a PNG in
//! the system's temporary directory), and mock displays that behave like
//! the drivers' (`mipidsi`'s SPI windows, an SSD1306 on I2C).
#![allow(dead_code)]

use std::error::Error;

use display_interface::{DataFormat, DisplayError, WriteOnlyDataCommand};
use embedded_graphics::pixelcolor::{BinaryColor, Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics_simulator::{OutputSettingsBuilder, SimulatorDisplay};

/// Shows `display`: a window (feature `window`, SDL2), or `NAME.png`.
pub fn show<C: PixelColor + Into<Rgb888>>(
    display: &SimulatorDisplay<C>,
    name: &str,
) -> Result<(), Box<dyn Error>> {
    let settings = OutputSettingsBuilder::new().scale(3).build();
    #[cfg(feature = "window")]
    embedded_graphics_simulator::Window::new(name, &settings).show_static(display);
    #[cfg(not(feature = "window"))]
    {
        let path = std::env::temp_dir().join(format!("{name}.png"));
        display.to_rgb_output_image(&settings).save_png(&path)?;
        println!("{name}: {}", path.display());
    }
    Ok(())
}

/// A 240x240 ST7789 as `mipidsi` drives it over SPI: every
/// `fill_contiguous` and `fill_solid` sets one window (CASET, RASET,
/// RAMWR: 11 bytes) and streams 2 bytes a pixel; every pixel of
/// `draw_iter` is a window of its own. It counts the bytes on the wire.
pub struct Spi240 {
    /// What the panel shows.
    pub frame: SimulatorDisplay<Rgb565>,
    /// Bytes sent over SPI.
    pub wire_bytes: usize,
}

/// Bytes of a window's set-up: CASET and RASET (a command and 4 bytes
/// each), RAMWR.
const WINDOW_BYTES: usize = 11;

impl Spi240 {
    pub fn new() -> Self {
        Self {
            frame: SimulatorDisplay::new(Size::new(240, 240)),
            wire_bytes: 0,
        }
    }
}

impl OriginDimensions for Spi240 {
    fn size(&self) -> Size {
        Size::new(240, 240)
    }
}

impl DrawTarget for Spi240 {
    type Color = Rgb565;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for p in pixels {
            if self.bounding_box().contains(p.0) {
                self.wire_bytes += WINDOW_BYTES + 2;
                self.frame.draw_iter([p])?;
            }
        }
        Ok(())
    }

    fn fill_contiguous<I: IntoIterator<Item = Rgb565>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), Self::Error> {
        let inside = area.intersection(&self.bounding_box());
        self.wire_bytes += WINDOW_BYTES + 2 * (inside.size.width * inside.size.height) as usize;
        let pixels = area
            .points()
            .zip(colors)
            .filter(|(p, _)| inside.contains(*p));
        self.frame.draw_iter(pixels.map(|(p, c)| Pixel(p, c)))
    }

    fn fill_solid(&mut self, area: &Rectangle, color: Rgb565) -> Result<(), Self::Error> {
        self.fill_contiguous(area, core::iter::repeat(color))
    }
}

/// A 128x64 SSD1306's controller on I2C: it decodes the commands
/// `ssd1306` and `softedge::render::pages` send (addressing mode, column
/// and page ranges, page addressing) into its 1 KiB of display RAM, and
/// counts the bytes on the wire (a control byte a transfer).
pub struct I2cOled {
    pub ram: [u8; 1024],
    pub wire_bytes: usize,
    horizontal: bool,
    cols: (u8, u8),
    pages: (u8, u8),
    col: u8,
    page: u8,
}

impl I2cOled {
    pub fn new() -> Self {
        Self {
            ram: [0; 1024],
            wire_bytes: 0,
            horizontal: false,
            cols: (0, 127),
            pages: (0, 7),
            col: 0,
            page: 0,
        }
    }

    /// What the panel shows.
    pub fn frame(&self) -> SimulatorDisplay<BinaryColor> {
        let mut d = SimulatorDisplay::new(Size::new(128, 64));
        for (k, byte) in self.ram.iter().enumerate() {
            for bit in 0..8 {
                let p = Point::new((k % 128) as i32, (k / 128 * 8 + bit) as i32);
                d.draw_iter([Pixel(p, BinaryColor::from(byte >> bit & 1 == 1))])
                    .unwrap();
            }
        }
        d
    }
}

impl WriteOnlyDataCommand for I2cOled {
    fn send_commands(&mut self, cmd: DataFormat<'_>) -> Result<(), DisplayError> {
        let DataFormat::U8(c) = cmd else {
            return Err(DisplayError::DataFormatNotImplemented);
        };
        self.wire_bytes += 1 + c.len();
        let mut c = c.iter().copied();
        while let Some(op) = c.next() {
            let mut arg = || c.next().ok_or(DisplayError::InvalidFormatError);
            match op {
                0x20 => self.horizontal = arg()? == 0,
                0x21 => {
                    self.cols = (arg()?, arg()?);
                    self.col = self.cols.0;
                }
                0x22 => {
                    self.pages = (arg()?, arg()?);
                    self.page = self.pages.0;
                }
                0xB0..=0xB7 => self.page = op & 7,
                0x00..=0x0F => self.col = self.col & 0xF0 | op,
                0x10..=0x1F => self.col = self.col & 0x0F | (op & 0x0F) << 4,
                _ => {}
            }
        }
        Ok(())
    }

    fn send_data(&mut self, buf: DataFormat<'_>) -> Result<(), DisplayError> {
        let DataFormat::U8(d) = buf else {
            return Err(DisplayError::DataFormatNotImplemented);
        };
        self.wire_bytes += 1 + d.len();
        for &b in d {
            self.ram[usize::from(self.page) * 128 + usize::from(self.col)] = b;
            if !self.horizontal {
                self.col = (self.col + 1) % 128;
            } else if self.col < self.cols.1 {
                self.col += 1;
            } else {
                self.col = self.cols.0;
                self.page = if self.page < self.pages.1 {
                    self.page + 1
                } else {
                    self.pages.0
                };
            }
        }
        Ok(())
    }
}

/// `ssd1306`'s buffered graphics mode: a 1 KiB frame buffer drawn into,
/// then `flush`ed to the panel whole.
pub struct BufferedOled {
    pub interface: I2cOled,
    buffer: [u8; 1024],
}

impl BufferedOled {
    pub fn new(interface: I2cOled) -> Self {
        Self {
            interface,
            buffer: [0; 1024],
        }
    }

    /// The frame buffer to the panel: horizontal addressing, the whole
    /// window, 1 024 bytes.
    pub fn flush(&mut self) -> Result<(), DisplayError> {
        let i = &mut self.interface;
        i.send_commands(DataFormat::U8(&[0x20, 0x00, 0x21, 0, 127, 0x22, 0, 7]))?;
        i.send_data(DataFormat::U8(&self.buffer))
    }
}

impl OriginDimensions for BufferedOled {
    fn size(&self) -> Size {
        Size::new(128, 64)
    }
}

impl DrawTarget for BufferedOled {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in pixels {
            if let (Ok(x @ 0..128), Ok(y @ 0..64)) = (usize::try_from(p.x), usize::try_from(p.y)) {
                let (byte, bit) = (&mut self.buffer[y / 8 * 128 + x], 1 << (y % 8));
                *byte = if c.is_on() { *byte | bit } else { *byte & !bit };
            }
        }
        Ok(())
    }
}
