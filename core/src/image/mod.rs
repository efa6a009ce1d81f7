//! Images as a paint: icons, sprites and masks with alpha, under an affine
//! transform (translation to 1/1024 px, scale, rotation about a point),
//! filtered in linear light and composed like any shape, band by band,
//! without a framebuffer.
//!
//! Takes an image source ([`ImageSource`]: softedge's [`RawImage`] over
//! bytes in flash in one of the [`format`]s, embedded-graphics images
//! through their `GetPixel` ([`Pixels`], `ImageRaw`), or a sequential
//! source decoded row by row into a caller's row cache) and an
//! [`ImageTransform`]; gives the band each pixel's filtered texel as a
//! paint of the image's outline (the transformed rectangle, or any shape:
//! [`AaImage::clip`]), so the image's edges get the exact-area coverage of
//! every shape and an image sits seamlessly beside shapes.
//!
//! ## The filter, in linear light
//!
//! Texel `(i, j)` is the square `[i, i + 1) x [j, j + 1)` of the image,
//! its centre `(i + 1/2, j + 1/2)`; the pixel centre `(x + 1/2, y + 1/2)`
//! maps into the image by the inverse transform to `(u, v)`. Each texel
//! is decoded to linear light (the sRGB tables of
//! [`color::srgb`](crate::color::srgb)) and premultiplied by its alpha.
//!
//! - **Bilinear** (both scales at least 1/2: magnification, rotation,
//!   mild minification): the interpolation of the four texels around
//!   `(u - 1/2, v - 1/2)`, weights `(1 - fu)(1 - fv)`, `fu (1 - fv)`, ...,
//!   indices clamped to the edge texels. `fu`, `fv` are kept to 1/1024
//!   texel (rounded), the weights' products to `2^-20`.
//! - **Box** (a scale below 1/2): the average of the image (each texel
//!   constant over its square, extended beyond the edges by the edge
//!   texels) over the box of `W x H` texels centred at `(u, v)`,
//!   `W = max(1, 1/sx)`, `H = max(1, 1/sy)`: the pixel's footprint area
//!   (along an axis of scale at least 1 the box is one texel, which is
//!   the linear interpolation there). For `W = H = 1` this is the bilinear
//!   filter above.
//! - **Copy**: an unscaled, unrotated image whose texels fall on whole
//!   pixels is read texel for pixel (the bilinear filter's value there).
//!
//! The filtered, premultiplied `(P, a)` is composed with the pixel's
//! coverage `k` (the outline's exact area times the opacity):
//! `acc = acc (1 - k a) + k P` (`band/image.rs`).
//!
//! ## Integer ranges
//!
//! The inverse map is set up once per band in `i64`/`i128` (sines and
//! cosines in Q30, scales in Q16, positions in fine units): per pixel the
//! sample position is an exact `i64` sum in Q32 texels (an addition per
//! axis), so a pixel's value depends on the pixel alone, whatever the
//! band. Scales lie in `1/16 ..= 256`, images up to 4096 texels a side.

mod drawable;
mod error;
pub mod format;
mod qoi;
mod sample;
mod source;
mod transform;

pub use drawable::{AaImage, NoClip};
pub use error::{ImageError, ImageFault};
pub use qoi::QoiImage;
#[cfg(feature = "embedded-graphics")]
pub use source::Pixels;
pub use source::{ImageSource, RawImage};
pub use transform::{ImageTransform, Scale};

pub(crate) use sample::paint;

/// Largest width or height of an image, texels.
pub const MAX_SIDE: u16 = 4096;

/// What sources and formats implement (crate-internal, unnameable
/// outside: the traits are sealed).
pub(crate) mod sealed {
    /// One texel in linear light, premultiplied: `c` per channel
    /// `0..=4095` (times `a / 1024`), `a` in `0..=1024`. A gray texel has
    /// the same value in the three channels.
    #[derive(Debug, Clone, Copy, PartialEq, Eq)]
    pub struct Lin {
        /// Premultiplied linear channels.
        pub c: [u32; 3],
        /// Alpha, `0..=1024`.
        pub a: u32,
    }

    /// How a format reads and decodes a texel.
    pub trait Decode: Copy + core::fmt::Debug {
        /// Bits of the colour data per texel.
        const BITS: u32;
        /// Every texel is opaque.
        const OPAQUE: bool;
        /// Alpha only (drawn in a tint).
        const MASK: bool;
        /// The three channels are equal.
        const GRAY: bool;
        /// Reads an 8-bit alpha plane.
        const PLANE: bool = false;
        /// Every texel is opaque and its raw bits are an Rgb565 colour
        /// (`r << 11 | g << 5 | b`), decoded as such.
        const RGB565: bool = false;
        /// The raw bits of texel `x` of `row` (`None` past the row's end).
        fn raw(row: &[u8], x: usize) -> Option<u32>;
        /// The texel of raw bits `raw`, its plane alpha `plane` (an 8-bit
        /// code, 255 without a plane) and the image's colour key `key`.
        fn decode(raw: u32, plane: u8, key: u32) -> Lin;
    }

    /// Texels by their place in the image.
    pub trait Fetch {
        /// Every texel is opaque.
        const OPAQUE: bool;
        /// Alpha only.
        const MASK: bool;
        /// The three channels are equal.
        const GRAY: bool;
        /// Texel `(x, y)`, `0 <= x < width`, `0 <= y < height`; one it
        /// cannot read (data short, a row not held) is transparent.
        fn texel(&self, x: i32, y: i32) -> Lin;
        /// Texels `(x0, y)` and `(x1, y)` (both inside the image): what
        /// [`texel`](Self::texel) gives for each. A source in memory looks
        /// the row up once.
        #[inline(always)]
        fn pair(&self, x0: i32, x1: i32, y: i32) -> (Lin, Lin) {
            (self.texel(x0, y), self.texel(x1, y))
        }
        /// Texels `x..x + n` of row `y`, in order, to `f` (a run inside
        /// the image: `0 <= x`, `x + n <= width`, `0 <= y < height`): what
        /// [`texel`](Self::texel) gives for each. A source in memory reads
        /// the row's bytes once, not a row look-up per texel.
        #[inline(always)]
        fn row(&self, x: i32, y: i32, n: usize, mut f: impl FnMut(Lin)) {
            for k in 0..n {
                f(self.texel(x.wrapping_add(k as i32), y));
            }
        }
        /// Texels `x..x + n` of row `y` (a run inside the image, as for
        /// [`row`](Self::row)) as Rgb565 codes into the first word of
        /// each of the `C`-word pixels `px` (`n` of them), when the
        /// source's texels are opaque Rgb565 colours read in place: true
        /// when it stored them (else `px` is untouched). Each code decodes
        /// to what [`texel`](Self::texel) gives.
        #[inline(always)]
        fn store_rgb565<const C: usize>(
            &self,
            _x: i32,
            _y: i32,
            _n: usize,
            _px: &mut [i32],
        ) -> bool {
            false
        }
    }

    /// An image source.
    pub trait Source {
        /// Its texels for a band.
        type Fetch<'f>: Fetch;
        /// Width and height, texels.
        fn size(&self) -> (u16, u16);
        /// Calls `f` with texels holding at least rows `rows` (clipped
        /// to the image; a source in memory holds them all).
        fn with_rows<R>(
            &self,
            rows: core::ops::Range<i32>,
            f: impl FnOnce(&Self::Fetch<'_>) -> R,
        ) -> Result<R, super::ImageFault>;
    }
}
