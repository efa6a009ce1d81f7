//! The display byte stream: what a scene sends to its display.
//!
//! Takes resolved rows of linear 12-bit values (from
//! [`BandBuffer::resolve_row`](softedge::BandBuffer::resolve_row)), runs the
//! tone stage of the scene's display [`Format`] (`softedge::tone`: the γ 2.2
//! table of the format's bit depth; for `Binary`, Floyd–Steinberg error
//! diffusion in linear light with its error row carried across bands), and
//! gives the display's bytes to a [`ByteSink`], row by row: Gray8 and Gray4
//! one byte per pixel holding the code, Rgb565 two bytes big-endian, Rgb888
//! three bytes, Binary one byte, 0 or 1 — the same stream `softedge-sim crc`
//! hashes for a scene file.

use softedge::tone::format::{Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat};
use softedge::tone::{Curve, FloydSteinberg};

use crate::{Scene, MAX_SCENE_WIDTH};

/// The pixel formats of the reference displays.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// 8-bit gray codes.
    Gray8,
    /// 4-bit gray codes.
    Gray4,
    /// 16-bit RGB 5-6-5.
    Rgb565,
    /// 24-bit RGB.
    Rgb888,
    /// 1 bit per pixel, dithered.
    Binary,
}

// The tables live in flash (built by `const fn`).
static GRAY8: Gray8Format = Gray8Format::new(Curve::GAMMA_2_2);
static GRAY4: Gray4Format = Gray4Format::new(Curve::GAMMA_2_2);
static RGB565: Rgb565Format = Rgb565Format::new(Curve::GAMMA_2_2);
static RGB888: Rgb888Format = Rgb888Format::new(Curve::GAMMA_2_2);

/// Where display bytes go (a CRC, a display driver, a file).
pub trait ByteSink {
    /// Takes the next bytes of the stream.
    fn write(&mut self, bytes: &[u8]);
}

impl ByteSink for crate::Crc32 {
    fn write(&mut self, bytes: &[u8]) {
        self.update(bytes);
    }
}

/// The tone stage of one frame: encodes its rows, top to bottom.
#[derive(Debug)]
pub struct Encoder<'a> {
    format: Format,
    dither: FloydSteinberg<'a>,
}

impl<'a> Encoder<'a> {
    /// Starts a frame of `scene` (`err`: the dither's error row, as wide as
    /// the frame; cleared here).
    pub fn new(scene: &Scene, err: &'a mut [i16]) -> Self {
        Self {
            format: scene.format,
            dither: FloydSteinberg::new(err),
        }
    }

    /// Encodes the next frame row, whose resolved linear 12-bit pixels are
    /// `row`, into display bytes. Gray formats take the first channel, RGB
    /// formats the first three (0 where a scene has fewer).
    #[inline(never)] // its row buffers live only while a row is encoded
    pub fn row<const C: usize>(&mut self, _y: u16, row: &[[u16; C]], sink: &mut impl ByteSink) {
        let first = |px: &[u16; C]| px.first().copied().unwrap_or(0);
        let rgb = |px: &[u16; C]| -> [u16; 3] {
            core::array::from_fn(|k| px.get(k).copied().unwrap_or(0))
        };
        match self.format {
            Format::Gray8 => row
                .iter()
                .for_each(|px| sink.write(&[GRAY8.code([first(px)])])),
            Format::Gray4 => row
                .iter()
                .for_each(|px| sink.write(&[GRAY4.code([first(px)])])),
            Format::Rgb565 => row
                .iter()
                .for_each(|px| sink.write(&RGB565.code(rgb(px)).to_be_bytes())),
            Format::Rgb888 => row.iter().for_each(|px| sink.write(&RGB888.code(rgb(px)))),
            Format::Binary => {
                let mut gray = [[0u16; 1]; MAX_SCENE_WIDTH as usize];
                let mut on = [false; MAX_SCENE_WIDTH as usize];
                let n = row.len().min(gray.len());
                for (g, px) in gray.iter_mut().zip(row) {
                    *g = [first(px)];
                }
                let (Some(gray), Some(on)) = (gray.get(..n), on.get_mut(..n)) else {
                    return;
                };
                self.dither.row(gray, on);
                on.iter().for_each(|&b| sink.write(&[u8::from(b)]));
            }
        }
    }
}
