//! The tone stage of a scene file's display, and what the CLI writes of it.
//!
//! [`tone`] runs `softedge::tone` on the rendered rows, top to bottom, as
//! firmware does after each band: the γ table of the format's bit depth
//! (Gray8, Gray4, Rgb888, Rgb565; with `[render] dither = "ordered"` the
//! ordered-dithering profiles of `softedge::tone::ordered` for Rgb565 and
//! Gray4, at each pixel's frame position) or, for a 1-bit display, Floyd–Steinberg
//! error diffusion in linear light with one error row for the whole frame
//! (so the error crosses band boundaries as it must). The renderer's output
//! does not depend on the band height, so toning its rows in order is the
//! firmware's per-band tone stage.
//!
//! Outputs:
//! - [`DisplayCodes::bytes`]: the codes as a display would receive them,
//!   row by row (gray8/gray4: one byte holding the code; rgb565: two bytes
//!   big-endian; rgb888: three bytes; binary: one byte, 0 or 1), and its
//!   CRC-32 ([`DisplayCodes::crc32`]);
//! - [`DisplayCodes::to_image8`]: what the display shows, as 8-bit levels
//!   (gray4 `c * 17`; rgb565 channels widened by bit replication; binary
//!   0 / 255);
//! - [`pnm16`]: the linear values before the tone stage as 16-bit Netpbm.

use softedge::tone::format::{Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat};
use softedge::tone::ordered::{Gray4Dither, Rgb565Dither};
use softedge::tone::{Curve, FloydSteinberg};

use super::{DisplayFormat, Dither};
use crate::image::{Channels, Image8, LinImage};

/// A rendered frame, linear 12-bit, before the tone stage.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Linear {
    /// One channel.
    Gray(LinImage<1>),
    /// Three channels.
    Rgb(LinImage<3>),
}

impl Linear {
    /// Width and height.
    pub fn size(&self) -> (u32, u32) {
        match self {
            Self::Gray(i) => (i.width(), i.height()),
            Self::Rgb(i) => (i.width(), i.height()),
        }
    }

    /// Every channel value, row by row, channels interleaved.
    pub fn values(&self) -> Vec<u16> {
        match self {
            Self::Gray(i) => i.pixels().map(|[v]| v).collect(),
            Self::Rgb(i) => i.pixels().flatten().collect(),
        }
    }
}

/// A frame of display codes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DisplayCodes {
    /// The pixel format.
    pub format: DisplayFormat,
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Codes, row by row: one per pixel (gray8, gray4, binary 0/1, rgb565
    /// packed) or three (rgb888).
    pub codes: Vec<u16>,
}

/// Runs the display's tone stage over `lin`.
pub fn tone(lin: &Linear, format: DisplayFormat, curve: Curve, dither: Dither) -> DisplayCodes {
    let (width, height) = lin.size();
    // Frame position of the k-th pixel, for ordered dithering.
    let w = width.max(1) as usize;
    let at = |k: usize| ((k % w) as i32, (k / w) as i32);
    let codes = match (lin, format, dither) {
        (Linear::Gray(img), DisplayFormat::Binary, _) => {
            let mut err = vec![0i16; width as usize];
            let mut fs = FloydSteinberg::new(&mut err);
            let px: Vec<[u16; 1]> = img.pixels().collect();
            let mut out = vec![0u8; width as usize];
            let mut codes = Vec::with_capacity(px.len());
            for row in px.chunks(width.max(1) as usize) {
                fs.row(row, &mut out);
                codes.extend(out.iter().map(|&b| u16::from(b)));
            }
            codes
        }
        (Linear::Gray(img), DisplayFormat::Gray4, Dither::Ordered) => {
            let d = Gray4Dither::new(curve);
            img.pixels()
                .enumerate()
                .map(|(k, [i])| {
                    let (x, y) = at(k);
                    u16::from(d.lut().code(i, x, y))
                })
                .collect()
        }
        (Linear::Gray(img), DisplayFormat::Gray4, Dither::None) => {
            let f = Gray4Format::new(curve);
            img.pixels().map(|p| u16::from(f.code(p))).collect()
        }
        (Linear::Gray(img), _, _) => {
            let f = Gray8Format::new(curve);
            img.pixels().map(|p| u16::from(f.code(p))).collect()
        }
        (Linear::Rgb(img), DisplayFormat::Rgb565, Dither::Ordered) => {
            let d = Rgb565Dither::new(curve);
            img.pixels()
                .enumerate()
                .map(|(k, p)| {
                    let (x, y) = at(k);
                    d.code(x, y, p)
                })
                .collect()
        }
        (Linear::Rgb(img), DisplayFormat::Rgb565, Dither::None) => {
            let f = Rgb565Format::new(curve);
            img.pixels().map(|p| f.code(p)).collect()
        }
        (Linear::Rgb(img), _, _) => {
            let f = Rgb888Format::new(curve);
            img.pixels()
                .flat_map(|p| f.code(p).map(u16::from))
                .collect()
        }
    };
    DisplayCodes {
        format,
        width,
        height,
        codes,
    }
}

/// `v` of `bits` bits widened to 8 by repeating its high bits.
fn widen(v: u16, bits: u32) -> u8 {
    let v = u32::from(v) & ((1 << bits) - 1);
    ((v << (8 - bits)) | (v >> (2 * bits - 8))) as u8
}

impl DisplayCodes {
    /// The byte stream a display receives, row by row.
    pub fn bytes(&self) -> Vec<u8> {
        match self.format {
            DisplayFormat::Rgb565 => self.codes.iter().flat_map(|c| c.to_be_bytes()).collect(),
            _ => self.codes.iter().map(|&c| c as u8).collect(),
        }
    }

    /// CRC-32 (IEEE) of [`bytes`](Self::bytes).
    pub fn crc32(&self) -> u32 {
        crc32fast::hash(&self.bytes())
    }

    /// What the display shows, as 8-bit gray or RGB levels.
    pub fn to_image8(&self) -> Image8 {
        let (channels, data): (Channels, Vec<u8>) = match self.format {
            DisplayFormat::Gray8 => (Channels::Gray, self.bytes()),
            DisplayFormat::Gray4 => (
                Channels::Gray,
                // c * 17 spreads 0..=15 evenly over 0..=255.
                self.codes.iter().map(|&c| (c.min(15) * 17) as u8).collect(),
            ),
            DisplayFormat::Binary => (
                Channels::Gray,
                self.codes
                    .iter()
                    .map(|&c| if c != 0 { u8::MAX } else { 0 })
                    .collect(),
            ),
            DisplayFormat::Rgb888 => (Channels::Rgb, self.bytes()),
            DisplayFormat::Rgb565 => (
                Channels::Rgb,
                self.codes
                    .iter()
                    .flat_map(|&c| [widen(c >> 11, 5), widen(c >> 5, 6), widen(c, 5)])
                    .collect(),
            ),
        };
        let (w, h) = (self.width, self.height);
        Image8::from_raw(w, h, channels, data)
            .unwrap_or_else(|| Image8::new(w, h, channels, &[0, 0, 0]))
    }
}

/// The linear values as binary 16-bit Netpbm: `P5` (one channel) or `P6`
/// (three), maxval 4095, samples big-endian.
pub fn pnm16(lin: &Linear) -> Vec<u8> {
    let (w, h) = lin.size();
    let magic = match lin {
        Linear::Gray(_) => "P5",
        Linear::Rgb(_) => "P6",
    };
    let mut out = format!("{magic}\n{w} {h}\n{}\n", softedge::LIN_MAX).into_bytes();
    out.extend(lin.values().iter().flat_map(|v| v.to_be_bytes()));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widening_replicates_bits() {
        assert_eq!(widen(31, 5), 255);
        assert_eq!(widen(63, 6), 255);
        assert_eq!(widen(0, 5), 0);
        assert_eq!(widen(0b10000, 5), 0b1000_0100);
        assert_eq!(widen(0b100000, 6), 0b1000_0010);
    }

    #[test]
    fn rgb565_bytes_are_big_endian() {
        let d = DisplayCodes {
            format: DisplayFormat::Rgb565,
            width: 1,
            height: 1,
            codes: vec![0xF800],
        };
        assert_eq!(d.bytes(), [0xF8, 0x00]);
        assert_eq!(d.to_image8().data(), [255, 0, 0]);
    }

    #[test]
    fn crc_is_the_ieee_one() {
        // The CRC-32 check value: "123456789" -> cbf43926.
        let d = DisplayCodes {
            format: DisplayFormat::Gray8,
            width: 9,
            height: 1,
            codes: b"123456789".iter().map(|&b| u16::from(b)).collect(),
        };
        assert_eq!(d.crc32(), 0xCBF4_3926);
    }

    #[test]
    fn pnm_header_and_samples() {
        let mut img = LinImage::<1>::new(2, 1);
        img.set_row(0, &[[4095], [258]]);
        let p = pnm16(&Linear::Gray(img));
        assert_eq!(p, b"P5\n2 1\n4095\n\x0f\xff\x01\x02");
    }
}
