//! Image sources: softedge's [`RawImage`] (bytes in flash, read in place
//! row by row), embedded-graphics images through their pixel access
//! ([`Pixels`], and `ImageRaw` directly).

use core::marker::PhantomData;
use core::ops::Range;

use super::format::TexelFormat;
use super::sealed::{Decode, Fetch, Lin, Source};
use super::{ImageFault, MAX_SIDE};

/// Something an [`AaImage`](super::AaImage) can paint with: softedge's
/// [`RawImage`], embedded-graphics' `ImageRaw` (and any
/// `GetPixel + OriginDimensions` image through [`Pixels`], such as
/// `tinybmp`'s `Bmp`), and row-cached sequential sources. Sealed; the
/// open door for other images is embedded-graphics' `GetPixel`.
pub trait ImageSource: Source {}

impl<T: Source + ?Sized> ImageSource for T {}

/// The checked size of an image.
fn check_size(width: u16, height: u16) -> Result<(), ImageFault> {
    if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
        return Err(ImageFault::Size {
            width: u32::from(width),
            height: u32::from(height),
        });
    }
    Ok(())
}

/// An image in memory (usually a `&'static [u8]` in flash): rows of
/// `ceil(width * bits / 8)` bytes, top to bottom, texels in one of the
/// [`format`](super::format)s; read in place, only the rows a band needs.
///
/// ```
/// use softedge::image::{format, RawImage};
/// // A 2x2 Rgb565 image (little endian): red, green / blue, white.
/// static DATA: [u8; 8] = [0x00, 0xf8, 0xe0, 0x07, 0x1f, 0x00, 0xff, 0xff];
/// let img = RawImage::<format::Rgb565>::new(&DATA, 2, 2).unwrap();
/// assert_eq!(img.size(), (2, 2));
/// // A 1-bpp mask, 12 texels a row: two bytes a row.
/// let mask = RawImage::<format::Alpha1>::new(&[0xff, 0xf0, 0x80, 0x10], 12, 2).unwrap();
/// assert_eq!(mask.stride(), 2);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct RawImage<'a, F> {
    data: &'a [u8],
    alpha: &'a [u8],
    width: u16,
    height: u16,
    stride: usize,
    key: u32,
    format: PhantomData<F>,
}

impl<'a, F: TexelFormat> RawImage<'a, F> {
    /// The image of `width x height` texels in `data`; an error if the
    /// size is empty or above [`MAX_SIDE`], or `data` is too short.
    pub fn new(data: &'a [u8], width: u16, height: u16) -> Result<Self, ImageFault> {
        check_size(width, height)?;
        let stride = (usize::from(width) * F::BITS as usize).div_ceil(8);
        let needed = stride * usize::from(height);
        if data.len() < needed {
            return Err(ImageFault::Truncated {
                needed: needed as u32,
                have: u32::try_from(data.len()).unwrap_or(u32::MAX),
            });
        }
        Ok(Self {
            data,
            alpha: &[],
            width,
            height,
            stride,
            key: u32::MAX,
            format: PhantomData,
        })
    }

    /// The same image with a separate alpha plane (one byte a texel, rows
    /// of `width` bytes; read by the [`PlaneAlpha`](super::format::PlaneAlpha)
    /// formats); an error if it is too short.
    pub fn with_alpha_plane(mut self, alpha: &'a [u8]) -> Result<Self, ImageFault> {
        let needed = usize::from(self.width) * usize::from(self.height);
        if alpha.len() < needed {
            return Err(ImageFault::Truncated {
                needed: needed as u32,
                have: u32::try_from(alpha.len()).unwrap_or(u32::MAX),
            });
        }
        self.alpha = alpha;
        Ok(self)
    }

    /// The same image with a colour key: the raw texel value (an Rgb565
    /// word, an Rgb888 `0xrrggbb`) that the [`Keyed`](super::format::Keyed)
    /// formats draw transparent.
    pub const fn with_color_key(mut self, key: u32) -> Self {
        self.key = key;
        self
    }

    /// Width and height, texels.
    pub const fn size(&self) -> (u16, u16) {
        (self.width, self.height)
    }

    /// Bytes per row.
    pub const fn stride(&self) -> usize {
        self.stride
    }
}

/// A [`RawImage`]'s texels.
#[derive(Debug)]
pub struct RawTexels<'a, F> {
    image: RawImage<'a, F>,
}

impl<F: Decode> RawTexels<'_, F> {
    /// The bytes of row `y` onwards (empty past the data's end).
    #[inline(always)]
    fn row_bytes(&self, y: usize) -> &[u8] {
        let i = &self.image;
        i.data.get(y * i.stride..).unwrap_or_default()
    }

    /// Texel `x` of row `y`, whose bytes onwards are `row`.
    #[inline(always)]
    fn decode_at(&self, row: &[u8], x: usize, y: usize) -> Lin {
        let i = &self.image;
        let Some(raw) = F::raw(row, x) else {
            return Lin { c: [0; 3], a: 0 };
        };
        let plane = if F::PLANE {
            match i.alpha.get(y * usize::from(i.width) + x) {
                Some(&a) => a,
                None => 0,
            }
        } else {
            u8::MAX
        };
        F::decode(raw, plane, i.key)
    }
}

impl<F: Decode> Fetch for RawTexels<'_, F> {
    const OPAQUE: bool = F::OPAQUE;
    const MASK: bool = F::MASK;
    const GRAY: bool = F::GRAY;
    #[inline(always)]
    fn texel(&self, x: i32, y: i32) -> Lin {
        let (x, y) = (x as usize, y as usize);
        self.decode_at(self.row_bytes(y), x, y)
    }

    /// Both texels from one look-up of the row.
    #[inline(always)]
    fn pair(&self, x0: i32, x1: i32, y: i32) -> (Lin, Lin) {
        let y = y as usize;
        let row = self.row_bytes(y);
        (
            self.decode_at(row, x0 as usize, y),
            self.decode_at(row, x1 as usize, y),
        )
    }

    /// Whole-byte texels without a plane: the run's bytes sliced once,
    /// a texel from each `BITS / 8` of them.
    #[inline(always)]
    fn row(&self, x: i32, y: i32, n: usize, mut f: impl FnMut(Lin)) {
        let i = &self.image;
        let b = (F::BITS / 8) as usize;
        if !F::PLANE && F::BITS % 8 == 0 && b > 0 && x >= 0 && y >= 0 {
            let start = (y as usize)
                .saturating_mul(i.stride)
                .saturating_add((x as usize).saturating_mul(b));
            let end = start.saturating_add(n.saturating_mul(b));
            if let Some(bytes) = i.data.get(start..end) {
                for t in bytes.chunks_exact(b) {
                    f(match F::raw(t, 0) {
                        Some(raw) => F::decode(raw, u8::MAX, i.key),
                        None => Lin { c: [0; 3], a: 0 },
                    });
                }
                return;
            }
        }
        for k in 0..n {
            f(self.texel(x.wrapping_add(k as i32), y));
        }
    }

    /// An Rgb565 format's raw bits, the run's bytes sliced once.
    #[inline(always)]
    fn store_rgb565<const C: usize>(&self, x: i32, y: i32, n: usize, px: &mut [i32]) -> bool {
        if !F::RGB565 || F::PLANE || F::BITS != 16 || C == 0 || x < 0 || y < 0 {
            return false;
        }
        // Inside the image (the caller's run), so below the data's length:
        // no product overflows (`saturating_mul` is a 64-bit product, a
        // library call, on a Cortex-M0); `get` checks the range anyway.
        let i = &self.image;
        let start = (y as usize)
            .wrapping_mul(i.stride)
            .wrapping_add((x as usize).wrapping_mul(2));
        let Some(bytes) = i.data.get(start..start.wrapping_add(n.wrapping_mul(2))) else {
            return false;
        };
        for (p, t) in px.chunks_exact_mut(C).zip(bytes.chunks_exact(2)) {
            if let Some(first) = p.first_mut() {
                *first = F::raw(t, 0).unwrap_or(0) as i32;
            }
        }
        true
    }
}

impl<'a, F: TexelFormat> Source for RawImage<'a, F> {
    type Fetch<'f> = RawTexels<'a, F>;
    fn size(&self) -> (u16, u16) {
        (self.width, self.height)
    }
    fn with_rows<R>(
        &self,
        _rows: Range<i32>,
        f: impl FnOnce(&Self::Fetch<'_>) -> R,
    ) -> Result<R, ImageFault> {
        check_size(self.width, self.height)?;
        if F::PLANE && self.alpha.len() < usize::from(self.width) * usize::from(self.height) {
            return Err(ImageFault::Truncated {
                needed: u32::from(self.width) * u32::from(self.height),
                have: u32::try_from(self.alpha.len()).unwrap_or(u32::MAX),
            });
        }
        Ok(f(&RawTexels { image: *self }))
    }
}

/// An embedded-graphics image read through its pixel access
/// (`GetPixel`: `ImageRaw`, `tinybmp`'s `Bmp`, your own), each pixel an
/// sRGB colour ([`IntoLinear`](crate::color::IntoLinear)), opaque.
///
/// ```
/// use embedded_graphics::image::ImageRawBE;
/// use embedded_graphics::pixelcolor::Rgb888;
/// use softedge::image::{AaImage, Pixels};
/// static DATA: [u8; 12] = [255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255];
/// let raw = ImageRawBE::<Rgb888>::new(&DATA, 2);
/// let pixels = Pixels(&raw);
/// let a = AaImage::new(&pixels); // or AaImage::new(&raw)
/// # let _ = a;
/// ```
#[cfg(feature = "embedded-graphics")]
#[derive(Debug, Clone, Copy)]
pub struct Pixels<'a, T>(pub &'a T);

#[cfg(feature = "embedded-graphics")]
mod eg {
    use embedded_graphics::image::{GetPixel, ImageRaw};
    use embedded_graphics_core::geometry::{OriginDimensions, Point};
    use embedded_graphics_core::pixelcolor::raw::ByteOrder;
    use embedded_graphics_core::pixelcolor::PixelColor;

    use super::*;
    use crate::color::IntoLinear;

    impl<T> Fetch for Pixels<'_, T>
    where
        T: GetPixel,
        T::Color: IntoLinear<3>,
    {
        const OPAQUE: bool = true;
        const MASK: bool = false;
        const GRAY: bool = false;
        #[inline]
        fn texel(&self, x: i32, y: i32) -> Lin {
            match self.0.pixel(Point::new(x, y)) {
                Some(c) => Lin {
                    c: c.into_linear().map(u32::from),
                    a: super::super::format::ALPHA_ONE,
                },
                None => Lin { c: [0; 3], a: 0 },
            }
        }

        /// An image of Rgb565 colours by their codes (the run's first
        /// texel tells; a pixel the image does not give is code 0, black:
        /// what `texel` gives it).
        #[inline]
        fn store_rgb565<const C: usize>(&self, x: i32, y: i32, n: usize, px: &mut [i32]) -> bool {
            let first = self.0.pixel(Point::new(x, y));
            if C == 0 || first.and_then(|c| c.rgb565_code()).is_none() {
                return false;
            }
            for (k, p) in px.chunks_exact_mut(C).take(n).enumerate() {
                let at = Point::new(x.wrapping_add(k as i32), y);
                let code = self.0.pixel(at).and_then(|c| c.rgb565_code());
                if let Some(p) = p.first_mut() {
                    *p = i32::from(code.unwrap_or(0));
                }
            }
            true
        }
    }

    /// An embedded-graphics image held by value (a copy of an `ImageRaw`).
    #[derive(Debug, Clone, Copy)]
    pub struct Owned<T>(pub T);

    impl<T> Fetch for Owned<T>
    where
        T: GetPixel,
        T::Color: IntoLinear<3>,
    {
        const OPAQUE: bool = true;
        const MASK: bool = false;
        const GRAY: bool = false;
        #[inline]
        fn texel(&self, x: i32, y: i32) -> Lin {
            Pixels(&self.0).texel(x, y)
        }

        #[inline]
        fn store_rgb565<const C: usize>(&self, x: i32, y: i32, n: usize, px: &mut [i32]) -> bool {
            Pixels(&self.0).store_rgb565::<C>(x, y, n, px)
        }
    }

    /// The size of an e-g image, clamped to what softedge draws (a larger
    /// one is refused).
    fn eg_size<T: OriginDimensions>(t: &T) -> (u16, u16) {
        let s = t.size();
        let c = |v: u32| u16::try_from(v).unwrap_or(u16::MAX);
        (c(s.width), c(s.height))
    }

    impl<'a, T> Source for Pixels<'a, T>
    where
        T: GetPixel + OriginDimensions,
        T::Color: IntoLinear<3>,
    {
        type Fetch<'f> = Pixels<'a, T>;
        fn size(&self) -> (u16, u16) {
            eg_size(self.0)
        }
        fn with_rows<R>(
            &self,
            _rows: Range<i32>,
            f: impl FnOnce(&Self::Fetch<'_>) -> R,
        ) -> Result<R, ImageFault> {
            let (w, h) = self.size();
            check_size(w, h)?;
            Ok(f(self))
        }
    }

    impl<'a, C, BO> Source for ImageRaw<'a, C, BO>
    where
        C: PixelColor + From<<C as PixelColor>::Raw> + IntoLinear<3> + Copy,
        BO: ByteOrder + Copy,
        ImageRaw<'a, C, BO>: GetPixel<Color = C> + OriginDimensions,
    {
        type Fetch<'f> = Owned<ImageRaw<'a, C, BO>>;
        fn size(&self) -> (u16, u16) {
            eg_size(self)
        }
        fn with_rows<R>(
            &self,
            _rows: Range<i32>,
            f: impl FnOnce(&Self::Fetch<'_>) -> R,
        ) -> Result<R, ImageFault> {
            let (w, h) = eg_size(self);
            check_size(w, h)?;
            Ok(f(&Owned(*self)))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::format::{
        Alpha1, Alpha2, Alpha4, Alpha8, Gray8, Keyed, PlaneAlpha, Rgb565, Rgb565Be, Rgb888,
        Rgba8888,
    };
    use crate::path::testing::Lcg;

    /// A row's texels and a pair's, read once per row, are the texels one
    /// by one, for every format (planes and keys included) and every run.
    fn rows_and_pairs_are_texels<F: TexelFormat>(rng: &mut Lcg) {
        extern crate std;
        use std::vec::Vec;
        let (w, h) = (1 + rng.below(19) as u16, 1 + rng.below(7) as u16);
        let stride = (usize::from(w) * F::BITS as usize).div_ceil(8);
        let data: Vec<u8> = (0..stride * usize::from(h))
            .map(|_| rng.below(256) as u8)
            .collect();
        let plane: Vec<u8> = (0..usize::from(w) * usize::from(h))
            .map(|_| rng.below(256) as u8)
            .collect();
        let mut img = RawImage::<F>::new(&data, w, h).unwrap();
        if F::PLANE {
            img = img.with_alpha_plane(&plane).unwrap();
        }
        let img = img.with_color_key(u32::from(data[0]) | u32::from(data[stride - 1]) << 8);
        img.with_rows(0..i32::from(h), |f| {
            for y in 0..i32::from(h) {
                for x0 in 0..i32::from(w) {
                    for x1 in x0..i32::from(w) {
                        assert_eq!(f.pair(x0, x1, y), (f.texel(x0, y), f.texel(x1, y)));
                        let n = (x1 - x0) as usize;
                        let mut got = Vec::new();
                        f.row(x0, y, n, |t| got.push(t));
                        let want: Vec<Lin> = (x0..x1).map(|x| f.texel(x, y)).collect();
                        assert_eq!(got, want, "{} bits, row {y}, {x0}..{x1}", F::BITS);
                    }
                }
            }
        })
        .unwrap();
    }

    #[test]
    fn rows_and_pairs_read_the_texels_of_every_format() {
        let mut rng = Lcg(0x7e_4e15);
        for _ in 0..20 {
            rows_and_pairs_are_texels::<Rgb565>(&mut rng);
            rows_and_pairs_are_texels::<Rgb565Be>(&mut rng);
            rows_and_pairs_are_texels::<Rgb888>(&mut rng);
            rows_and_pairs_are_texels::<Gray8>(&mut rng);
            rows_and_pairs_are_texels::<Rgba8888>(&mut rng);
            rows_and_pairs_are_texels::<Alpha1>(&mut rng);
            rows_and_pairs_are_texels::<Alpha2>(&mut rng);
            rows_and_pairs_are_texels::<Alpha4>(&mut rng);
            rows_and_pairs_are_texels::<Alpha8>(&mut rng);
            rows_and_pairs_are_texels::<Keyed<Rgb565>>(&mut rng);
            rows_and_pairs_are_texels::<PlaneAlpha<Rgb888>>(&mut rng);
        }
    }
}
