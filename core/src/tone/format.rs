//! Pixel formats: rows of linear 12-bit intensity → display codes.
//!
//! Each format owns γ tables built *directly for its bit depth* (one
//! rounding of the formula, no 8-bit intermediate): Gray8 and Rgb888 use an
//! 8-bit [`GammaLut`], Gray4 a 4-bit one, Rgb565 a 5-bit one (red, blue) and
//! a 6-bit one (green). A format maps one pixel, `[u16; C]` (`C = 1` gray,
//! `C = 3` RGB, as the band buffer's `resolve_row` gives them), to its
//! numeric code; with the `embedded-graphics` feature also to the
//! `embedded_graphics_core::pixelcolor` colour type.
//!
//! 1-bit displays (BinaryColor) need dithering, which depends on the pixel's
//! position: see [`dither`](super::dither).
//!
//! Per pixel: one table look-up per channel (and shifts to pack Rgb565).

use super::gamma::{Curve, GammaLut};

/// A display pixel format fed with linear 12-bit pixels of `C` channels.
pub trait ToneFormat<const C: usize> {
    /// The numeric code of a pixel (`u8`, `[u8; 3]`, packed `u16`).
    type Code: Copy;

    /// The embedded-graphics colour of a pixel.
    #[cfg(feature = "embedded-graphics")]
    #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
    type Color: embedded_graphics_core::pixelcolor::PixelColor + RawColor;

    /// The code of one pixel (channels above 4095 are clamped).
    fn code(&self, px: [u16; C]) -> Self::Code;

    /// The colour of one pixel (channels above 4095 are clamped).
    #[cfg(feature = "embedded-graphics")]
    #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
    fn color(&self, px: [u16; C]) -> Self::Color;

    /// True when every Rgb565 colour decoded by the sRGB tables is coded
    /// back to itself (see [`Profile::keeps_rgb565`](super::Profile::keeps_rgb565)).
    fn keeps_rgb565(&self) -> bool {
        false
    }
}

/// A display colour as the renderer's flush keeps it: its raw bits in a
/// `u32` (a band's colours are made into the band's scratch, then
/// streamed to the display from there). Every embedded-graphics colour
/// type is one.
#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
pub trait RawColor: Copy {
    /// The colour's raw bits.
    fn to_raw(self) -> u32;
    /// The colour of raw bits `raw` (as [`to_raw`](Self::to_raw) gave).
    fn from_raw(raw: u32) -> Self;
}

#[cfg(feature = "embedded-graphics")]
impl<T> RawColor for T
where
    T: embedded_graphics_core::pixelcolor::PixelColor + From<T::Raw>,
    T::Raw: From<T>,
    <T::Raw as embedded_graphics_core::pixelcolor::raw::RawData>::Storage: Into<u32>,
{
    #[inline]
    fn to_raw(self) -> u32 {
        use embedded_graphics_core::pixelcolor::raw::RawData;
        T::Raw::from(self).into_inner().into()
    }

    #[inline]
    fn from_raw(raw: u32) -> Self {
        use embedded_graphics_core::pixelcolor::raw::RawData;
        T::from(T::Raw::from_u32(raw))
    }
}

/// Converts a row: `out[k] = format.code(row[k])` for as many pixels as the
/// shorter slice holds; returns that count.
///
/// ```
/// # use softedge::tone::{Curve, format::{code_row, Gray8Format}};
/// let f = Gray8Format::new(Curve::Srgb);
/// let mut out = [0u8; 3];
/// assert_eq!(code_row(&f, &[[0], [4095], [9999]], &mut out), 3);
/// assert_eq!(out, [0, 255, 255]);
/// ```
pub fn code_row<F: ToneFormat<C>, const C: usize>(
    format: &F,
    row: &[[u16; C]],
    out: &mut [F::Code],
) -> usize {
    let mut n = 0;
    for (o, &px) in out.iter_mut().zip(row) {
        *o = format.code(px);
        n += 1;
    }
    n
}

/// Converts a row to embedded-graphics colours, like [`code_row`].
///
/// ```
/// # use softedge::tone::{Curve, format::{color_row, Rgb565Format}};
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
/// let f = Rgb565Format::new(Curve::Srgb);
/// let mut out = [Rgb565::BLACK; 2];
/// color_row(&f, &[[4095, 0, 0], [4095; 3]], &mut out);
/// assert_eq!(out, [Rgb565::RED, Rgb565::WHITE]);
/// ```
#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
pub fn color_row<F: ToneFormat<C>, const C: usize>(
    format: &F,
    row: &[[u16; C]],
    out: &mut [F::Color],
) -> usize {
    let mut n = 0;
    for (o, &px) in out.iter_mut().zip(row) {
        *o = format.color(px);
        n += 1;
    }
    n
}

/// 8-bit gray: `code = round(255 V(I))`.
///
/// ```
/// # use softedge::tone::{Curve, format::{Gray8Format, ToneFormat}};
/// let f = Gray8Format::new(Curve::GAMMA_2_2);
/// assert_eq!(f.code([4095]), 255);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Gray8Format {
    lut: GammaLut,
}

impl Gray8Format {
    /// The format for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        Gray8Format {
            lut: GammaLut::with_bits(curve, 8),
        }
    }
}

impl ToneFormat<1> for Gray8Format {
    type Code = u8;
    #[cfg(feature = "embedded-graphics")]
    type Color = embedded_graphics_core::pixelcolor::Gray8;

    #[inline]
    fn code(&self, [i]: [u16; 1]) -> u8 {
        self.lut.code(i)
    }

    #[cfg(feature = "embedded-graphics")]
    fn color(&self, px: [u16; 1]) -> Self::Color {
        embedded_graphics_core::pixelcolor::Gray8::new(self.code(px))
    }
}

/// 4-bit gray: `code = round(15 V(I))`, from a table built for 4 bits.
///
/// ```
/// # use softedge::tone::{Curve, format::{Gray4Format, ToneFormat}};
/// let f = Gray4Format::new(Curve::GAMMA_2_4);
/// assert_eq!(f.code([0]), 0);
/// assert_eq!(f.code([4095]), 15);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Gray4Format {
    lut: GammaLut,
}

impl Gray4Format {
    /// The format for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        Gray4Format {
            lut: GammaLut::with_bits(curve, 4),
        }
    }
}

impl ToneFormat<1> for Gray4Format {
    type Code = u8;
    #[cfg(feature = "embedded-graphics")]
    type Color = embedded_graphics_core::pixelcolor::Gray4;

    #[inline]
    fn code(&self, [i]: [u16; 1]) -> u8 {
        self.lut.code(i)
    }

    #[cfg(feature = "embedded-graphics")]
    fn color(&self, px: [u16; 1]) -> Self::Color {
        embedded_graphics_core::pixelcolor::Gray4::new(self.code(px))
    }
}

/// 24-bit RGB: 8 bits per channel through one table.
///
/// ```
/// # use softedge::tone::{Curve, format::{Rgb888Format, ToneFormat}};
/// let f = Rgb888Format::new(Curve::Srgb);
/// assert_eq!(f.code([0, 4095, 10]), [0, 255, 8]);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rgb888Format {
    lut: GammaLut,
}

impl Rgb888Format {
    /// The format for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        Rgb888Format {
            lut: GammaLut::with_bits(curve, 8),
        }
    }
}

impl ToneFormat<3> for Rgb888Format {
    type Code = [u8; 3];
    #[cfg(feature = "embedded-graphics")]
    type Color = embedded_graphics_core::pixelcolor::Rgb888;

    #[inline]
    fn code(&self, px: [u16; 3]) -> [u8; 3] {
        px.map(|i| self.lut.code(i))
    }

    #[cfg(feature = "embedded-graphics")]
    fn color(&self, px: [u16; 3]) -> Self::Color {
        let [r, g, b] = self.code(px);
        embedded_graphics_core::pixelcolor::Rgb888::new(r, g, b)
    }
}

/// 16-bit RGB 5-6-5: red and blue from a 5-bit table, green from a 6-bit
/// one; the code is packed `r << 11 | g << 5 | b`.
///
/// ```
/// # use softedge::tone::{Curve, format::{Rgb565Format, ToneFormat}};
/// let f = Rgb565Format::new(Curve::Srgb);
/// assert_eq!(f.code([4095, 4095, 4095]), 0xFFFF);
/// assert_eq!(f.code([0, 4095, 0]), 0x07E0);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rgb565Format {
    lut5: GammaLut,
    lut6: GammaLut,
    /// Every 5-bit and 6-bit sRGB code decoded by the sRGB tables is
    /// coded back to itself (found once, by [`new`](Self::new)).
    keeps: bool,
}

impl Rgb565Format {
    /// The format for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        let lut5 = GammaLut::with_bits(curve, 5);
        let lut6 = GammaLut::with_bits(curve, 6);
        let keeps = round_trips(&lut5, &crate::color::srgb::SRGB5_TO_LIN12)
            && round_trips(&lut6, &crate::color::srgb::SRGB6_TO_LIN12);
        Rgb565Format { lut5, lut6, keeps }
    }

    /// The three channel codes `(r5, g6, b5)`.
    ///
    /// ```
    /// # use softedge::tone::{Curve, format::Rgb565Format};
    /// let f = Rgb565Format::new(Curve::GAMMA_2_2);
    /// assert_eq!(f.channels([4095, 4095, 0]), [31, 63, 0]);
    /// ```
    #[inline]
    pub fn channels(&self, [r, g, b]: [u16; 3]) -> [u8; 3] {
        [self.lut5.code(r), self.lut6.code(g), self.lut5.code(b)]
    }
}

/// True when `lut` codes each level of `decode` (code `k`'s linear
/// value) back to `k`.
const fn round_trips<const N: usize>(lut: &GammaLut, decode: &[u16; N]) -> bool {
    let codes = lut.codes();
    let mut k = 0;
    while k < N {
        let lin = decode[k] as usize;
        if lin >= codes.len() || codes[lin] as usize != k {
            return false;
        }
        k += 1;
    }
    true
}

impl ToneFormat<3> for Rgb565Format {
    type Code = u16;
    #[cfg(feature = "embedded-graphics")]
    type Color = embedded_graphics_core::pixelcolor::Rgb565;

    fn keeps_rgb565(&self) -> bool {
        self.keeps
    }

    #[inline]
    fn code(&self, px: [u16; 3]) -> u16 {
        let [r, g, b] = self.channels(px).map(u16::from);
        (r << 11) | (g << 5) | b
    }

    #[cfg(feature = "embedded-graphics")]
    fn color(&self, px: [u16; 3]) -> Self::Color {
        let [r, g, b] = self.channels(px);
        embedded_graphics_core::pixelcolor::Rgb565::new(r, g, b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_stop_at_the_shorter_slice() {
        let f = Gray4Format::new(Curve::Srgb);
        let mut out = [0u8; 2];
        assert_eq!(code_row(&f, &[[4095]; 5], &mut out), 2);
        assert_eq!(code_row(&f, &[], &mut out), 0);
    }

    #[cfg(feature = "embedded-graphics")]
    #[test]
    fn colors_match_codes() {
        use embedded_graphics_core::pixelcolor::{raw::RawData, IntoStorage};
        let f = Rgb565Format::new(Curve::GAMMA_2_4);
        for px in [[0, 0, 0], [100, 2000, 4095], [4095, 7, 300]] {
            assert_eq!(f.color(px).into_storage(), f.code(px));
        }
        let g = Gray4Format::new(Curve::GAMMA_2_4);
        let c = g.color([2000]);
        assert_eq!(
            embedded_graphics_core::pixelcolor::raw::RawU4::from(c).into_inner(),
            g.code([2000])
        );
    }
}
