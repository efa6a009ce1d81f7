//! Shapes filled and stroked with a [`Gradient`]: the same outlines,
//! walks and compose as a flat colour ([`Canvas::fill_shape`],
//! [`Canvas::stroke_shape`]), the colour varying per pixel.
//!
//! The gradient was set up when it was made; drawing it adds no division
//! per band. A gradient of one colour (degenerate geometry, one stop) is
//! drawn as that flat colour.

use super::{Canvas, Fill, Outline};
use crate::path::{Shape, StrokeStyle};
use crate::raster::DrawError;
use crate::style::{Blend, FillRule, Gradient, Opacity};

impl<const C: usize, Col> Canvas<'_, '_, C, Col> {
    /// Fills `outline` by `rule` with a gradient (see [`Canvas::fill`]).
    ///
    /// ```
    /// use softedge::canvas::{Canvas, Contour};
    /// use softedge::geom::FinePoint;
    /// use softedge::style::{Blend, FillRule, Gradient, Offset, Opacity, Stop};
    /// use softedge::{Band, BandBuffer};
    /// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(16, 4)]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(16, 0, 4)).unwrap();
    /// buf.clear([0]);
    /// let mut canvas: Canvas<'_, '_, 1> = Canvas::new(&mut buf, None);
    /// let p = |x, y| FinePoint::from_px(x, y);
    /// let ramp = Gradient::linear(
    ///     p(0, 0),
    ///     p(16, 0),
    ///     &[Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])],
    /// )
    /// .unwrap();
    /// let all = [p(0, 0), p(16, 0), p(16, 4), p(0, 4)];
    /// canvas
    ///     .fill_gradient(&Contour(&all), &ramp, FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
    ///     .unwrap();
    /// // Pixel 7's centre is 7.5 px along 16 px: 1920 of 4095.
    /// assert_eq!(canvas.buffer().lin12(7, 2), Some([1920]));
    /// ```
    pub fn fill_gradient<O: Outline + ?Sized>(
        &mut self,
        outline: &O,
        gradient: &Gradient<C>,
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.fill_with(outline, Fill::Gradient(gradient), rule, blend, opacity)
    }

    /// Fills a shape or path ([`Shape`]) by `rule` with a gradient in
    /// linear light (see [`Canvas::fill_shape`]).
    ///
    /// ```
    /// use softedge::canvas::Canvas;
    /// use softedge::geom::FinePoint;
    /// use softedge::path::Circle;
    /// use softedge::style::{Blend, FillRule, Gradient, Offset, Opacity, Stop};
    /// use softedge::{Band, BandBuffer};
    /// let (mut acc, mut cover) = ([0i32; 400], [0i32; BandBuffer::<1>::cover_len(20, 20)]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(20, 0, 20)).unwrap();
    /// buf.clear([0]);
    /// let mut canvas: Canvas<'_, '_, 1> = Canvas::new(&mut buf, None);
    /// let centre = FinePoint::centre_of(9, 9);
    /// // White at the centre, black at 8 px and beyond.
    /// let glow = Gradient::radial(
    ///     centre,
    ///     8 * 1024,
    ///     &[Stop::lin(Offset::ZERO, [4095]), Stop::lin(Offset::ONE, [0])],
    /// )
    /// .unwrap();
    /// let disc = Circle::new(centre, 6 * 1024);
    /// canvas
    ///     .fill_shape_gradient(&disc, &glow, FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
    ///     .unwrap();
    /// // 4 px from the centre: half way, half the light (2047.5 exactly;
    /// // the distance is coloured at the middle of its 1/128-px quantum,
    /// // 4.004 px here, and this ramp falls by 512 levels per pixel).
    /// assert_eq!(canvas.buffer().lin12(13, 9), Some([2046]));
    /// // At the centre: 4095 within the bound of the radial quantum
    /// // (0.0095 px at 512 levels per pixel).
    /// assert!(canvas.buffer().lin12(9, 9).unwrap()[0] >= 4092);
    /// ```
    pub fn fill_shape_gradient<S: Shape + ?Sized>(
        &mut self,
        shape: &S,
        gradient: &Gradient<C>,
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.fill_shape_with(shape, Fill::Gradient(gradient), rule, blend, opacity)
    }

    /// Strokes a shape's or path's outline with `style` and a gradient
    /// (see [`Canvas::stroke_shape`]): the stroke is one shape, the
    /// gradient's colours lie where the stroke's pixels lie.
    ///
    /// ```
    /// use softedge::canvas::Canvas;
    /// use softedge::geom::FinePoint;
    /// use softedge::path::{Line, StrokeStyle};
    /// use softedge::style::{Blend, Gradient, Offset, Opacity, Stop};
    /// use softedge::{Band, BandBuffer};
    /// let (mut acc, mut cover) = ([0i32; 3 * 32 * 8], [0i32; BandBuffer::<3>::cover_len(32, 8)]);
    /// let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(32, 0, 8)).unwrap();
    /// buf.clear([0; 3]);
    /// let mut canvas: Canvas<'_, '_, 3> = Canvas::new(&mut buf, None);
    /// let (a, b) = (FinePoint::from_px(2, 4), FinePoint::from_px(30, 4));
    /// let red_to_blue = Gradient::linear(
    ///     a,
    ///     b,
    ///     &[Stop::lin(Offset::ZERO, [4095, 0, 0]), Stop::lin(Offset::ONE, [0, 0, 4095])],
    /// )
    /// .unwrap();
    /// let line = Line::new(a, b);
    /// canvas
    ///     .stroke_shape_gradient(&line, &StrokeStyle::new(2048), &red_to_blue, Blend::Over, Opacity::OPAQUE)
    ///     .unwrap();
    /// let [r, _, b] = canvas.buffer().lin12(3, 4).unwrap();
    /// assert!(r > 3800 && b < 300);
    /// let [r, _, b] = canvas.buffer().lin12(28, 3).unwrap();
    /// assert!(r < 300 && b > 3800);
    /// ```
    pub fn stroke_shape_gradient<S: Shape + ?Sized>(
        &mut self,
        shape: &S,
        style: &StrokeStyle<'_>,
        gradient: &Gradient<C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.stroke_shape_with(shape, style, Fill::Gradient(gradient), blend, opacity)
    }
}
