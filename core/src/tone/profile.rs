//! Display profiles: the whole tone stage of one display, from a band's
//! linear 12-bit pixels to the colours its driver takes, as the renderer
//! streams them (row by row, left to right, bands top to bottom).
//!
//! A profile sees every pixel's position, so ordered dithering (Bayer)
//! runs through it, and it may keep state across rows and bands, so error
//! diffusion (Floyd–Steinberg, serpentine) does too: it dithers each row
//! when the row starts and hands its pixels out in order.
//!
//! Every γ format of [`format`](super::format) is a profile (with the
//! `embedded-graphics` feature, its colour type is the driver's).

use super::dither::FloydSteinberg;
#[cfg(feature = "embedded-graphics")]
use super::{dither::Bayer8, format::ToneFormat};

/// One row of a band as the tone stage reads it: frame row `y`, columns
/// `x0..x0 + len()`, linear 12-bit pixels.
#[derive(Debug, Clone, Copy)]
pub struct ToneRow<'r, const C: usize> {
    /// Frame row.
    pub y: i32,
    /// Frame column of the first pixel.
    pub x0: i32,
    acc: &'r [i32],
    /// The row's tag words and the band's palette entries, when the band
    /// keeps tags: a tagged pixel's value is its entry's (see
    /// `band::tags`).
    tags: Option<(&'r [i32], &'r [[i32; C]])>,
}

impl<'r, const C: usize> ToneRow<'r, C> {
    /// A row of values (`C` accumulator values a pixel).
    pub(crate) fn new(y: i32, x0: i32, acc: &'r [i32]) -> Self {
        Self {
            y,
            x0,
            acc,
            tags: None,
        }
    }

    /// A band's row: its accumulator, tag words and palette entries.
    pub(crate) fn tagged(
        y: i32,
        x0: i32,
        acc: &'r [i32],
        words: &'r [i32],
        entries: &'r [[i32; C]],
    ) -> Self {
        Self {
            y,
            x0,
            acc,
            tags: Some((words, entries)),
        }
    }

    /// Number of pixels.
    pub fn len(&self) -> usize {
        self.acc.len() / C.max(1)
    }

    /// True when the row has no pixels.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The linear 12-bit value of the row's `k`-th pixel (0 past the end).
    pub fn lin12(&self, k: usize) -> [u16; C] {
        let Some(px) = self
            .acc
            .get(k * C..k * C + C)
            .and_then(|p| p.first_chunk::<C>())
        else {
            return [0; C];
        };
        let v = match self.tags {
            Some((words, entries)) => {
                crate::band::tags::value(px, crate::band::tags::get(words, k), entries)
            }
            None => *px,
        };
        v.map(crate::units::resolve)
    }
}

/// The tone stage of a display.
pub trait Profile<const C: usize> {
    /// What the display's driver takes.
    type Color: Copy;

    /// A new frame starts.
    fn start_frame(&mut self) {}

    /// Row `row.y` is about to be asked for, pixel by pixel.
    fn start_row(&mut self, _row: &ToneRow<'_, C>) {}

    /// The colour of frame pixel `(x, y)` of value `lin` (asked in order
    /// within the row last started).
    fn color(&self, x: i32, y: i32, lin: [u16; C]) -> Self::Color;

    /// The colour every pixel of value `lin` gets wherever it is, if the
    /// profile does not depend on position (no dithering): the renderer
    /// then sends rows nothing was drawn on without resolving them.
    fn uniform(&self, lin: [u16; C]) -> Option<Self::Color>;

    /// True when every Rgb565 colour (`r << 11 | g << 5 | b`), decoded to
    /// linear light by the sRGB tables
    /// ([`SRGB5_TO_LIN12`](crate::color::SRGB5_TO_LIN12),
    /// [`SRGB6_TO_LIN12`](crate::color::SRGB6_TO_LIN12)), is toned back
    /// to itself wherever it is, its raw bits that same number: the
    /// renderer then sends the whole pixels of an unscaled Rgb565 image
    /// as they were read, without resolving them (the same bits). False
    /// unless a profile knows it ([`Rgb565Format`](super::format::Rgb565Format)
    /// with the sRGB curve does).
    fn keeps_rgb565(&self) -> bool {
        false
    }
}

/// A γ format is a profile by reference: its tables are usually a
/// `static` in flash.
///
/// ```
/// use softedge::tone::{format::Rgb565Format, Curve, Profile};
/// static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);
/// let profile = &RGB565;
/// assert_eq!(profile.uniform([4095; 3]), Some(embedded_graphics_core::pixelcolor::Rgb565::new(31, 63, 31)));
/// ```
#[cfg(feature = "embedded-graphics")]
impl<F: ToneFormat<C>, const C: usize> Profile<C> for &F {
    type Color = F::Color;

    #[inline]
    fn color(&self, _x: i32, _y: i32, lin: [u16; C]) -> Self::Color {
        ToneFormat::color(*self, lin)
    }

    fn uniform(&self, lin: [u16; C]) -> Option<Self::Color> {
        Some(ToneFormat::color(*self, lin))
    }

    fn keeps_rgb565(&self) -> bool {
        ToneFormat::keeps_rgb565(*self)
    }
}

/// A profile with state (error diffusion) is lent to the renderer.
impl<P: Profile<C> + ?Sized, const C: usize> Profile<C> for &mut P {
    type Color = P::Color;

    fn start_frame(&mut self) {
        (**self).start_frame();
    }

    fn start_row(&mut self, row: &ToneRow<'_, C>) {
        (**self).start_row(row);
    }

    #[inline]
    fn color(&self, x: i32, y: i32, lin: [u16; C]) -> Self::Color {
        (**self).color(x, y, lin)
    }

    fn uniform(&self, lin: [u16; C]) -> Option<Self::Color> {
        (**self).uniform(lin)
    }

    fn keeps_rgb565(&self) -> bool {
        (**self).keeps_rgb565()
    }
}

#[cfg(feature = "embedded-graphics")]
impl Profile<1> for Bayer8 {
    type Color = embedded_graphics_core::pixelcolor::BinaryColor;

    #[inline]
    fn color(&self, x: i32, y: i32, [lin]: [u16; 1]) -> Self::Color {
        self.is_on(lin, x, y).into()
    }

    fn uniform(&self, [lin]: [u16; 1]) -> Option<Self::Color> {
        // Only black and white are the same everywhere.
        match lin {
            0 => Some(embedded_graphics_core::pixelcolor::BinaryColor::Off),
            l if l >= super::LIN_MAX => Some(embedded_graphics_core::pixelcolor::BinaryColor::On),
            _ => None,
        }
    }
}

/// Floyd–Steinberg error diffusion as a profile: the error row (`i16` per
/// pixel of the frame width) and a row of results (one byte per pixel)
/// are the caller's; the error row is carried across the bands of a frame
/// and cleared when a frame starts.
#[derive(Debug)]
pub struct DiffusionProfile<'a> {
    fs: FloydSteinberg<'a>,
    bits: &'a mut [bool],
    x0: i32,
}

impl<'a> DiffusionProfile<'a> {
    /// A profile over the caller's error row and result row (both as long
    /// as the widest row drawn).
    pub fn new(err: &'a mut [i16], bits: &'a mut [bool]) -> Self {
        Self {
            fs: FloydSteinberg::new(err),
            bits,
            x0: 0,
        }
    }
}

#[cfg(feature = "embedded-graphics")]
impl Profile<1> for DiffusionProfile<'_> {
    type Color = embedded_graphics_core::pixelcolor::BinaryColor;

    fn start_frame(&mut self) {
        self.fs.reset();
    }

    fn start_row(&mut self, row: &ToneRow<'_, 1>) {
        self.x0 = row.x0;
        self.fs.row_of(row.len(), |k| row.lin12(k)[0], self.bits);
    }

    #[inline]
    fn color(&self, x: i32, _y: i32, _lin: [u16; 1]) -> Self::Color {
        let k = x.wrapping_sub(self.x0);
        let on = usize::try_from(k)
            .ok()
            .and_then(|k| self.bits.get(k))
            .copied();
        on.unwrap_or(false).into()
    }

    fn uniform(&self, _lin: [u16; 1]) -> Option<Self::Color> {
        None
    }
}
