//! Colours in: sRGB colours (embedded-graphics colour types, 8-bit
//! triples, `#rrggbb` text) to the engine's linear 12-bit intensity.
//!
//! Takes colours as users write them, which are **sRGB-encoded** display
//! codes: embedded-graphics' `Rgb565`, `Rgb888`, `Gray8`, `Gray4`,
//! `BinaryColor` (feature `embedded-graphics`), 8-bit `(r, g, b)` and
//! `#rrggbb` hex text. Gives what every stage of the engine adds and
//! multiplies: **linear light**, `0..=4095` per channel (`lin12`), as
//! `[u16; C]` with `C = 3` (RGB) or `C = 1` (one-channel displays).
//!
//! Anti-aliasing and Gouraud shading are sums of light (seed 000, eqs. 2-3):
//! half a pixel of white on black is half the light, which an sRGB display
//! shows at about code 188 of 255, not 128. So a colour is decoded once, here, from the sRGB curve
//! (IEC 61966-2-1) by the tables of [`srgb`], and the tone stage encodes
//! the result again: an sRGB colour drawn flat comes back to its own code
//! (tested for every 8-bit code).
//!
//! On a one-channel display an RGB colour gives its **linear luminance**
//! `Y = 0.2126 R + 0.7152 G + 0.0722 B` of the linear channels (Rec. 709 /
//! sRGB primaries), in integers ([`srgb::luminance`]).
//!
//! ```
//! use softedge::color::{IntoLinear, LinGray, LinRgb};
//! const ORANGE: LinRgb = LinRgb::from_srgb8(255, 128, 0);
//! assert_eq!(ORANGE.lin12(), [4095, 884, 0]);
//! assert_eq!(LinRgb::from_hex("#ff8000"), Ok(ORANGE));
//! // The same colour on a gray display: its luminance.
//! assert_eq!(LinGray::from_hex("#ff8000").map(LinGray::lin12), Ok([1503]));
//! # #[cfg(feature = "embedded-graphics")] {
//! use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
//! let c: [u16; 3] = Rgb565::YELLOW.into_linear();
//! assert_eq!(c, [4095, 4095, 0]);
//! let y: [u16; 1] = Rgb565::YELLOW.into_linear();
//! assert_eq!(y, [3799]);
//! # }
//! ```
//!
//! ## Integer ranges
//!
//! Tables are `u16` entries `<= 4095` indexed by a code that cannot exceed
//! the table (masked or of the right width); the luminance sum is below
//! `2^28` in `u32`. Table building (compile time) uses the Q62 fixed point
//! of the tone tables; nothing here uses floating point.

#[cfg(feature = "embedded-graphics")]
mod eg;
mod errors;
mod hex;
pub mod srgb;

pub use hex::{parse_hex, ColorError};
pub use srgb::{
    luminance, SRGB2_TO_LIN12, SRGB4_TO_LIN12, SRGB5_TO_LIN12, SRGB6_TO_LIN12, SRGB8_TO_LIN12,
};

use crate::shade::LIN_MAX;

/// A colour in linear light, 12 bits per channel (`0..=4095`), `C`
/// channels: 3 for RGB, 1 for one-channel displays.
///
/// The engine's primitives take the bare `[u16; C]` ([`lin12`](Self::lin12),
/// or `.into()`); this type is how a colour gets there from what users
/// write.
///
/// ```
/// use softedge::color::{Lin, LinRgb};
/// let c = Lin::new([5000, 2048, 0]); // channels above 4095 are clamped
/// assert_eq!(c.lin12(), [4095, 2048, 0]);
/// let arr: [u16; 3] = LinRgb::from_srgb8(0, 0, 255).into();
/// assert_eq!(arr, [0, 0, 4095]);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Lin<const C: usize>([u16; C]);

/// A linear RGB colour: `Lin<3>`.
pub type LinRgb = Lin<3>;
/// A linear one-channel colour (gray, or the luminance of an RGB colour):
/// `Lin<1>`.
pub type LinGray = Lin<1>;

impl<const C: usize> Lin<C> {
    /// A colour from linear 12-bit values; values above 4095 are clamped.
    pub const fn new(lin12: [u16; C]) -> Self {
        let mut v = lin12;
        let mut k = 0;
        while k < C {
            if v[k] > LIN_MAX {
                v[k] = LIN_MAX;
            }
            k += 1;
        }
        Self(v)
    }

    /// The linear 12-bit values, each `<= 4095`.
    pub const fn lin12(self) -> [u16; C] {
        self.0
    }
}

impl<const C: usize> Default for Lin<C> {
    /// Black.
    fn default() -> Self {
        Self([0; C])
    }
}

impl<const C: usize> From<Lin<C>> for [u16; C] {
    fn from(c: Lin<C>) -> Self {
        c.0
    }
}

impl Lin<3> {
    /// An sRGB colour of 8-bit codes, decoded to linear light by
    /// [`SRGB8_TO_LIN12`].
    ///
    /// ```
    /// use softedge::color::LinRgb;
    /// // sRGB 128 is 21.6 % of the light: 884 / 4095.
    /// assert_eq!(LinRgb::from_srgb8(128, 128, 128).lin12(), [884; 3]);
    /// ```
    pub const fn from_srgb8(r: u8, g: u8, b: u8) -> Self {
        Self([
            SRGB8_TO_LIN12[r as usize],
            SRGB8_TO_LIN12[g as usize],
            SRGB8_TO_LIN12[b as usize],
        ])
    }

    /// An sRGB colour written `#rrggbb` (see [`parse_hex`]).
    ///
    /// ```
    /// use softedge::color::{ColorError, LinRgb};
    /// assert_eq!(LinRgb::from_hex("#808080"), Ok(LinRgb::from_srgb8(128, 128, 128)));
    /// assert_eq!(LinRgb::from_hex("#80808"), Err(ColorError::Length { len: 6 }));
    /// ```
    pub const fn from_hex(text: &str) -> Result<Self, ColorError> {
        match parse_hex(text) {
            Ok([r, g, b]) => Ok(Self::from_srgb8(r, g, b)),
            Err(e) => Err(e),
        }
    }

    /// The linear luminance ([`luminance`]): the colour on a one-channel
    /// display.
    ///
    /// ```
    /// use softedge::color::{Lin, LinRgb};
    /// assert_eq!(LinRgb::from_srgb8(0, 255, 0).luminance(), Lin::new([2929]));
    /// ```
    pub const fn luminance(self) -> Lin<1> {
        Lin([luminance(self.0)])
    }
}

impl Lin<1> {
    /// The linear luminance of an sRGB colour of 8-bit codes.
    ///
    /// ```
    /// use softedge::color::LinGray;
    /// assert_eq!(LinGray::from_srgb8(255, 0, 0).lin12(), [871]);
    /// assert_eq!(LinGray::from_srgb8(128, 128, 128).lin12(), [884]);
    /// ```
    pub const fn from_srgb8(r: u8, g: u8, b: u8) -> Self {
        Lin::<3>::from_srgb8(r, g, b).luminance()
    }

    /// The linear luminance of an sRGB colour written `#rrggbb`.
    ///
    /// ```
    /// use softedge::color::LinGray;
    /// assert_eq!(LinGray::from_hex("#ffffff").map(LinGray::lin12), Ok([4095]));
    /// ```
    pub const fn from_hex(text: &str) -> Result<Self, ColorError> {
        match Lin::<3>::from_hex(text) {
            Ok(c) => Ok(c.luminance()),
            Err(e) => Err(e),
        }
    }

    /// An 8-bit sRGB gray level, decoded by [`SRGB8_TO_LIN12`].
    ///
    /// ```
    /// use softedge::color::LinGray;
    /// assert_eq!(LinGray::from_srgb_gray8(128).lin12(), [884]);
    /// ```
    pub const fn from_srgb_gray8(v: u8) -> Self {
        Self([SRGB8_TO_LIN12[v as usize]])
    }

    /// The gray as an RGB colour, `[v, v, v]`.
    ///
    /// ```
    /// use softedge::color::{Lin, LinGray};
    /// assert_eq!(LinGray::new([700]).rgb(), Lin::new([700; 3]));
    /// ```
    pub const fn rgb(self) -> Lin<3> {
        let [v] = self.0;
        Lin([v; 3])
    }
}

/// A colour that becomes linear 12-bit light with `C` channels: 3 for RGB
/// targets, 1 for one-channel ones (an RGB colour gives its luminance, a
/// gray level its value on every channel).
///
/// Implemented for [`Lin`] (1 and 3 channels), for bare `[u16; C]` (taken
/// as linear already, unchanged), and, with the `embedded-graphics`
/// feature, for embedded-graphics' colour types, read as sRGB:
/// `Rgb555`, `Bgr555`, `Rgb565`, `Bgr565`, `Rgb666`, `Bgr666`, `Rgb888`,
/// `Bgr888`, `Gray2`, `Gray4`, `Gray8` and `BinaryColor` (`On` is 4095,
/// `Off` 0).
///
/// ```
/// use softedge::color::{IntoLinear, LinRgb};
/// fn channels<T: IntoLinear<3>>(c: T) -> [u16; 3] {
///     c.into_linear()
/// }
/// assert_eq!(channels([1, 2, 3]), [1, 2, 3]);
/// assert_eq!(channels(LinRgb::from_srgb8(255, 255, 255)), [4095; 3]);
/// ```
pub trait IntoLinear<const C: usize> {
    /// The linear 12-bit channels of the colour.
    fn into_linear(self) -> [u16; C];

    /// The colour's Rgb565 code (`r << 11 | g << 5 | b`), when it has 5,
    /// 6 and 5 bits of sRGB channels (embedded-graphics' `Rgb565`,
    /// `Bgr565`), whose channels decoded by the sRGB tables are
    /// [`into_linear`](Self::into_linear)'s three: an image of such
    /// colours is sent as it is read where the display keeps them
    /// (`Profile::keeps_rgb565`). `None` for any other colour, and from
    /// a one-channel conversion (its value is a luminance).
    #[inline]
    fn rgb565_code(&self) -> Option<u16> {
        None
    }
}

impl<const C: usize> IntoLinear<C> for [u16; C] {
    #[inline]
    fn into_linear(self) -> [u16; C] {
        self
    }
}

impl<const C: usize> IntoLinear<C> for Lin<C> {
    #[inline]
    fn into_linear(self) -> [u16; C] {
        self.0
    }
}

impl IntoLinear<1> for Lin<3> {
    #[inline]
    fn into_linear(self) -> [u16; 1] {
        [luminance(self.0)]
    }
}

impl IntoLinear<3> for Lin<1> {
    #[inline]
    fn into_linear(self) -> [u16; 3] {
        self.rgb().0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hex_and_bytes_agree() {
        assert_eq!(
            LinRgb::from_hex("#0a80ff"),
            Ok(LinRgb::from_srgb8(10, 128, 255))
        );
        assert_eq!(
            LinGray::from_hex("#0A80FF"),
            Ok(LinGray::from_srgb8(10, 128, 255))
        );
        assert_eq!(LinGray::from_hex("0a80ff"), Err(ColorError::MissingHash));
    }

    #[test]
    fn gray_stays_gray_on_both_channel_counts() {
        for v in [0u8, 1, 17, 128, 200, 255] {
            let rgb = LinRgb::from_srgb8(v, v, v);
            let gray = LinGray::from_srgb_gray8(v);
            assert_eq!(rgb.luminance(), gray);
            assert_eq!(LinGray::from_srgb8(v, v, v), gray);
            assert_eq!(gray.rgb(), rgb);
            let as1: [u16; 1] = rgb.into_linear();
            let as3: [u16; 3] = gray.into_linear();
            assert_eq!((as1, as3), (gray.lin12(), rgb.lin12()));
        }
    }

    #[test]
    fn new_clamps_every_channel() {
        assert_eq!(Lin::new([4096, 4095, u16::MAX]).lin12(), [4095; 3]);
        assert_eq!(Lin::new([0]).lin12(), [0]);
    }

    #[test]
    fn constructors_work_in_const_context() {
        const C: LinRgb = match LinRgb::from_hex("#ffffff") {
            Ok(c) => c,
            Err(_) => panic!("a valid colour"),
        };
        assert_eq!(C.lin12(), [4095; 3]);
    }
}
