//! [`IntoLinear`] for embedded-graphics' colour types, read as sRGB.
//!
//! RGB types decode each channel by the table of its width (5, 6 or 8
//! bits); gray types by the table of theirs (2, 4 or 8 bits); `BinaryColor`
//! is black or white. On one channel an RGB colour gives its luminance and
//! a gray its level; on three a gray gives `[v, v, v]`.

use embedded_graphics_core::pixelcolor::{
    Bgr555, Bgr565, Bgr666, Bgr888, BinaryColor, Gray2, Gray4, Gray8, GrayColor, Rgb555, Rgb565,
    Rgb666, Rgb888, RgbColor,
};

use super::srgb::{
    luminance, SRGB2_TO_LIN12, SRGB4_TO_LIN12, SRGB5_TO_LIN12, SRGB6_TO_LIN12, SRGB8_TO_LIN12,
};
use super::IntoLinear;
use crate::shade::LIN_MAX;

/// One channel code of `max = 2^bits - 1` through the table of its width.
/// e-g's channel maxima are 31, 63 and 255; codes are masked to the table,
/// so no index is out of range.
#[inline]
fn channel(code: u8, max: u8) -> u16 {
    match max {
        31 => SRGB5_TO_LIN12[usize::from(code & 31)],
        63 => SRGB6_TO_LIN12[usize::from(code & 63)],
        255 => SRGB8_TO_LIN12[usize::from(code)],
        // No embedded-graphics RGB type has another width; decode by the
        // formula all the same.
        _ => super::srgb::srgb_to_lin12(u32::from(code), u32::from(max)),
    }
}

/// The linear channels of any embedded-graphics RGB colour.
#[inline]
fn rgb<T: RgbColor>(c: T) -> [u16; 3] {
    [
        channel(c.r(), T::MAX_R),
        channel(c.g(), T::MAX_G),
        channel(c.b(), T::MAX_B),
    ]
}

/// The Rgb565 code of a colour of 5, 6 and 5 bits.
#[inline]
fn rgb565<T: RgbColor>(c: &T) -> Option<u16> {
    ((T::MAX_R, T::MAX_G, T::MAX_B) == (31, 63, 31))
        .then(|| u16::from(c.r() & 31) << 11 | u16::from(c.g() & 63) << 5 | u16::from(c.b() & 31))
}

macro_rules! rgb_into_linear {
    ($($t:ty),*) => {$(
        #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
        impl IntoLinear<3> for $t {
            /// The sRGB channels decoded to linear 12-bit.
            #[inline]
            fn into_linear(self) -> [u16; 3] {
                rgb(self)
            }

            #[inline]
            fn rgb565_code(&self) -> Option<u16> {
                rgb565(self)
            }
        }

        #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
        impl IntoLinear<1> for $t {
            /// The linear luminance of the sRGB colour.
            #[inline]
            fn into_linear(self) -> [u16; 1] {
                [luminance(rgb(self))]
            }
        }
    )*};
}

rgb_into_linear!(Rgb555, Bgr555, Rgb565, Bgr565, Rgb666, Bgr666, Rgb888, Bgr888);

macro_rules! gray_into_linear {
    ($($t:ty => $table:ident, $mask:expr);*) => {$(
        #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
        impl IntoLinear<1> for $t {
            /// The sRGB gray level decoded to linear 12-bit.
            #[inline]
            fn into_linear(self) -> [u16; 1] {
                [$table[usize::from(self.luma() & $mask)]]
            }
        }

        #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
        impl IntoLinear<3> for $t {
            /// The gray level on every channel.
            #[inline]
            fn into_linear(self) -> [u16; 3] {
                let [v] = IntoLinear::<1>::into_linear(self);
                [v; 3]
            }
        }
    )*};
}

gray_into_linear!(Gray2 => SRGB2_TO_LIN12, 3; Gray4 => SRGB4_TO_LIN12, 15; Gray8 => SRGB8_TO_LIN12, 255);

#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl IntoLinear<1> for BinaryColor {
    /// `On` is white (4095), `Off` black (0).
    #[inline]
    fn into_linear(self) -> [u16; 1] {
        [if self.is_on() { LIN_MAX } else { 0 }]
    }
}

#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl IntoLinear<3> for BinaryColor {
    /// `On` is white, `Off` black, on every channel.
    #[inline]
    fn into_linear(self) -> [u16; 3] {
        let [v] = IntoLinear::<1>::into_linear(self);
        [v; 3]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::LinRgb;

    fn lin3<T: IntoLinear<3>>(c: T) -> [u16; 3] {
        c.into_linear()
    }
    fn lin1<T: IntoLinear<1>>(c: T) -> [u16; 1] {
        c.into_linear()
    }

    #[test]
    fn rgb888_is_the_8_bit_table() {
        assert_eq!(lin3(Rgb888::new(128, 128, 128)), [884; 3]);
        assert_eq!(
            lin3(Bgr888::new(255, 128, 0)),
            LinRgb::from_srgb8(255, 128, 0).lin12()
        );
        assert_eq!(
            lin1(Rgb888::new(255, 128, 0)),
            LinRgb::from_srgb8(255, 128, 0).luminance().lin12()
        );
    }

    #[test]
    fn rgb565_channels_use_their_widths() {
        let c = Rgb565::new(16, 32, 31);
        assert_eq!(lin3(c), [SRGB5_TO_LIN12[16], SRGB6_TO_LIN12[32], LIN_MAX]);
        assert_eq!(lin3(Bgr565::new(16, 32, 31)), lin3(c));
        assert_eq!(lin3(Rgb666::new(63, 0, 63)), [LIN_MAX, 0, LIN_MAX]);
        assert_eq!(lin3(Rgb555::WHITE), [LIN_MAX; 3]);
        assert_eq!(lin1(Rgb565::WHITE), [LIN_MAX]);
        assert_eq!(lin1(Rgb565::BLACK), [0]);
    }

    #[test]
    fn grays_and_binary() {
        assert_eq!(lin1(Gray8::new(128)), [884]);
        assert_eq!(lin3(Gray8::new(128)), [884; 3]);
        assert_eq!(lin1(Gray4::new(15)), [LIN_MAX]);
        assert_eq!(lin1(Gray4::new(8)), [SRGB4_TO_LIN12[8]]);
        assert_eq!(lin1(Gray2::new(1)), [SRGB2_TO_LIN12[1]]);
        assert_eq!(lin1(BinaryColor::On), [LIN_MAX]);
        assert_eq!(lin3(BinaryColor::Off), [0; 3]);
    }
}
