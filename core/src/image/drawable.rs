//! [`AaImage`]: an image with its transform, tint, opacity and blend, drawn
//! into a band's canvas (`draw`, as embedded-graphics draws an `Image`).

use super::transform::Mapping;
use super::{ImageFault, ImageSource, ImageTransform, Scale};
use crate::color::IntoLinear;
use crate::geom::{FinePoint, FINE_BITS};
use crate::path::Degrees;
use crate::style::{Blend, Opacity};

/// No clip shape: an [`AaImage`] fills its own transformed rectangle
/// (its default; a shape of no outline, so that the clip's code is not
/// built for images without one).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NoClip;

impl crate::path::Shape for NoClip {
    fn describe<P: crate::geom::PathSink + ?Sized>(&self, _: &mut P) {}
}

/// An image drawn anti-aliased: filtered in linear light under an affine
/// transform, its outline by exact area, composed like a shape.
///
/// Built from any [`ImageSource`] and chained setters; drawn with
/// `.draw(canvas)` (the [`AaDrawable`](crate::draw::AaDrawable) of every
/// styled shape) or [`Canvas::draw_image`](crate::canvas::Canvas::draw_image).
/// embedded-graphics' own `Image::new(&raw, point)` still draws into the
/// canvas as before (aliased, opaque); `AaImage` is the transformed,
/// anti-aliased form.
///
/// ```
/// use embedded_graphics::image::ImageRawLE;
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use softedge::image::{AaImage, Scale};
/// use softedge::path::Degrees;
/// use softedge::prelude::*;
/// # use softedge::{Band, BandBuffer};
/// # let (mut acc, mut cover) = ([0i32; 3 * 64 * 64], [0i32; BandBuffer::<3>::cover_len(64, 64)]);
/// # let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(64, 0, 64)).unwrap();
/// # buf.clear([0; 3]);
/// # let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
/// static NEEDLE: [u8; 2 * 4 * 2] = [0xff; 16]; // 4x2 white Rgb565 texels
/// let raw = ImageRawLE::<Rgb565>::new(&NEEDLE, 4);
/// AaImage::new(&raw)
///     .center(FinePoint::from_px(32, 32))
///     .scale(Scale::from_int(6))
///     .rotate(Degrees::new(30))
///     .opacity(Opacity::from_percent(75))
///     .draw(&mut canvas)?;
/// # Ok::<(), softedge::DrawError>(())
/// ```
#[derive(Debug, Clone, Copy)]
pub struct AaImage<'a, S: ?Sized, K = NoClip> {
    source: &'a S,
    transform: ImageTransform,
    tint: Option<[u16; 3]>,
    opacity: Opacity,
    blend: Blend,
    name: &'static str,
    clip: Option<&'a K>,
}

impl<'a, S: ImageSource + ?Sized> AaImage<'a, S> {
    /// The image unscaled, its top-left corner at the frame's origin,
    /// opaque, painter's order.
    pub fn new(source: &'a S) -> Self {
        Self {
            source,
            transform: ImageTransform::default(),
            tint: None,
            opacity: Opacity::OPAQUE,
            blend: Blend::Over,
            name: "",
            clip: None,
        }
    }
}

impl<'a, S: ImageSource + ?Sized, K> AaImage<'a, S, K> {
    /// The image's top-left corner at the corner of pixel `p` (as
    /// embedded-graphics' `Image::new(&raw, p)`), scaling and rotating
    /// about it.
    #[cfg(feature = "embedded-graphics")]
    pub fn at(self, p: embedded_graphics_core::geometry::Point) -> Self {
        self.pivot(FinePoint::new(0, 0))
            .position(FinePoint::from_px(p.x, p.y))
    }

    /// The image's centre at `p` (1/1024 px), scaling and rotating about
    /// its centre.
    pub fn center(self, p: FinePoint) -> Self {
        let (w, h) = self.source.size();
        let half = 1 << (FINE_BITS - 1);
        self.pivot(FinePoint::new(i32::from(w) * half, i32::from(h) * half))
            .position(p)
    }

    /// Where the pivot lands (1/1024 px).
    pub fn position(mut self, p: FinePoint) -> Self {
        self.transform.position = p;
        self
    }

    /// The point of the image (1/1024 texel from its top-left corner) the
    /// image is scaled and rotated about, which lands at the position.
    pub fn pivot(mut self, t: FinePoint) -> Self {
        self.transform.pivot = t;
        self
    }

    /// Scaled by `s` both ways.
    pub fn scale(self, s: Scale) -> Self {
        self.scale_xy(s, s)
    }

    /// Scaled by `sx` along the image's rows, `sy` along its columns.
    pub fn scale_xy(mut self, sx: Scale, sy: Scale) -> Self {
        self.transform.scale = (sx, sy);
        self
    }

    /// Rotated clockwise on screen about the pivot.
    pub fn rotate(mut self, angle: Degrees) -> Self {
        self.transform.angle = angle;
        self
    }

    /// The whole transform at once.
    pub fn transform(mut self, t: ImageTransform) -> Self {
        self.transform = t;
        self
    }

    /// Drawn in `color`: a mask's alpha, or the image's alpha (an image
    /// with alpha) or linear luminance (an opaque one), as the coverage of
    /// the colour. A mask without a tint is white.
    pub fn tint<T: IntoLinear<3>>(mut self, color: T) -> Self {
        self.tint = Some(color.into_linear());
        self
    }

    /// The opacity of the whole image.
    pub fn opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// Painter's order (default) or seed 000's addition.
    pub fn blend(mut self, blend: Blend) -> Self {
        self.blend = blend;
        self
    }

    /// A name that errors carry ([`ImageError::image`](super::ImageError)).
    pub fn name(mut self, name: &'static str) -> Self {
        self.name = name;
        self
    }

    /// Draws the image inside `shape` instead of its own rectangle (a
    /// rounded icon, a disc): the shape's exact area, the image's texels
    /// (beyond the image's edges, its edge texels).
    pub fn clip<K2>(self, shape: &'a K2) -> AaImage<'a, S, K2> {
        AaImage {
            source: self.source,
            transform: self.transform,
            tint: self.tint,
            opacity: self.opacity,
            blend: self.blend,
            name: self.name,
            clip: Some(shape),
        }
    }

    /// The transform as set.
    pub fn image_transform(&self) -> ImageTransform {
        self.transform
    }

    pub(crate) fn mapping(&self) -> Result<Mapping, ImageFault> {
        Mapping::new(&self.transform, self.source.size())
    }

    pub(crate) fn source(&self) -> &'a S {
        self.source
    }

    pub(crate) fn name_str(&self) -> &'static str {
        self.name
    }

    pub(crate) fn clip_shape(&self) -> Option<&'a K> {
        self.clip
    }

    pub(crate) fn blend_mode(&self) -> Blend {
        self.blend
    }

    pub(crate) fn opacity_value(&self) -> Opacity {
        self.opacity
    }

    /// The tint on `C` channels (the luminance on one).
    pub(crate) fn tint_lin<const C: usize>(&self) -> Option<[u16; C]> {
        self.tint.map(|t| {
            if C == 1 {
                [crate::color::srgb::luminance(t); C]
            } else {
                core::array::from_fn(|ch| t[ch.min(2)])
            }
        })
    }
}

#[cfg(feature = "embedded-graphics")]
impl<S: ImageSource + ?Sized, K: crate::path::Shape, const C: usize> crate::draw::AaDrawable<C>
    for AaImage<'_, S, K>
{
    fn draw<D>(
        &self,
        canvas: &mut crate::canvas::Canvas<'_, '_, C, D>,
    ) -> Result<(), crate::DrawError> {
        canvas.draw_image(self)
    }
}
