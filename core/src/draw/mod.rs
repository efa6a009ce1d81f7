//! Anti-aliased drawing in embedded-graphics' idiom (feature
//! `embedded-graphics`): a primitive styled with an [`AaStyle`] and drawn
//! into a band's [`Canvas`] with `draw`, as embedded-graphics draws a
//! `PrimitiveStyle`d one into a `DrawTarget`.
//!
//! The primitive is one of embedded-graphics' own (`Circle`, `Ellipse`,
//! `Arc`, `Sector`, `Rectangle`, `RoundedRectangle`, `Triangle`, `Line`,
//! `Polyline`: moving a UI to softedge changes the style, not the
//! geometry; see [`path::eg`](crate::path::eg) for the exact geometry each
//! one stands for) or a sub-pixel shape of [`path`](crate::path) (centres
//! and radii in 1/1024 px, SVG path data). Both get `into_styled` from
//! embedded-graphics' `Primitive` trait.
//!
//! The style's colours are any colour type the canvas converts
//! ([`IntoLinear`]: embedded-graphics' colours as sRGB, or linear
//! `[u16; C]`). The fill is drawn first, then the stroke, each one shape in
//! painter's order with the style's opacity and blend (as SVG draws
//! `fill` and `stroke`).
//!
//! ```
//! use embedded_graphics::pixelcolor::Rgb888;
//! use embedded_graphics::prelude::*;
//! use embedded_graphics::primitives::{Circle, Line};
//! use softedge::prelude::*;
//! # use softedge::{Band, BandBuffer};
//! # let (mut acc, mut cover) = ([0i32; 3 * 400], [0i32; BandBuffer::<3>::cover_len(20, 20)]);
//! # let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(20, 0, 20)).unwrap();
//! # buf.clear([0; 3]);
//! # let mut canvas: Canvas<'_, '_, 3, Rgb888> = Canvas::typed(&mut buf, None);
//! // A disc of diameter 12 at (4, 4) and a 3-px line over it at half opacity.
//! Circle::new(Point::new(4, 4), 12)
//!     .into_styled(AaStyle::with_fill(Rgb888::new(0, 128, 255)))
//!     .draw(&mut canvas)?;
//! Line::new(Point::new(0, 10), Point::new(19, 10))
//!     .into_styled(AaStyle::with_stroke(Rgb888::WHITE, 3).opacity(Opacity::from_percent(50)))
//!     .draw(&mut canvas)?;
//! # Ok::<(), softedge::DrawError>(())
//! ```

mod shapes;

pub use shapes::{eg_stroke, AaShape};

use embedded_graphics::primitives::{PrimitiveStyle, Styled};
use embedded_graphics_core::pixelcolor::PixelColor;

use crate::canvas::Canvas;
use crate::color::IntoLinear;
use crate::error::ShapeKind;
use crate::path::{Dash, LineCap, LineJoin, MiterLimit, StrokeAlignment, StrokeStyle};
use crate::raster::DrawError;
use crate::style::{Blend, Edges, FillRule, Gradient, Opacity};

/// How a primitive is drawn anti-aliased: fill and stroke colours, the
/// stroke (width down to hairlines, joins, caps, dashes, alignment), the
/// fill rule, opacity and blend.
///
/// Built like embedded-graphics' `PrimitiveStyle`
/// ([`with_fill`](Self::with_fill), [`with_stroke`](Self::with_stroke),
/// then the chained setters), or converted from one
/// (`AaStyle::from(style)`: the same colours, width and alignment).
///
/// On embedded-graphics' primitives a stroke of whole pixels lights the
/// pixels embedded-graphics lights where its edges are exact
/// (axis-aligned, integer geometry; see [`eg_stroke`]): a 1-px stroke of
/// a `Rectangle` is one whole pixel wide, not two half-bright ones.
///
/// **Half-pixel conventions.** `Circle::with_center(p, d)` with an even
/// `d` sits half a pixel right of and below pixel `p`'s centre
/// (embedded-graphics puts its corner at `p - (d - 1) / 2`), which
/// aliased drawing hid. To centre a circle on a pixel, use an odd `d`, or
/// softedge's circle: `path::Circle::new(FinePoint::centre_of(p.x, p.y),
/// d * 512)` (radius in 1/1024 px):
///
/// ```
/// use embedded_graphics::prelude::*;
/// use embedded_graphics::primitives::Circle;
/// use softedge::geom::FinePoint;
/// use softedge::path;
/// let p = Point::new(20, 20);
/// let eg: path::Circle = Circle::with_center(p, 10).into();
/// assert_eq!(eg.centre, FinePoint::from_px(21, 21)); // half a pixel off
/// let centred = path::Circle::new(FinePoint::centre_of(p.x, p.y), 10 * 512);
/// assert_eq!(centred.centre, FinePoint::new(20 * 1024 + 512, 20 * 1024 + 512));
/// let odd: path::Circle = Circle::with_center(p, 11).into();
/// assert_eq!(odd.centre, centred.centre);
/// ```
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use softedge::draw::AaStyle;
/// use softedge::path::{LineCap, LineJoin};
/// use softedge::style::Opacity;
/// const NEEDLE: AaStyle<'static, Rgb565> = AaStyle::with_stroke(Rgb565::RED, 3)
///     .cap(LineCap::Round)
///     .join(LineJoin::Round)
///     .opacity(Opacity::from_percent(75));
/// assert_eq!(NEEDLE.stroke.width, 3 * 1024);
/// assert!(NEEDLE.fill_color.is_none());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct AaStyle<'a, Col> {
    /// The fill's colour, `None` for no fill.
    pub fill_color: Option<Col>,
    /// The stroke's colour, `None` for no stroke.
    pub stroke_color: Option<Col>,
    /// The stroke's geometry (width in 1/1024 px; 0 strokes nothing).
    pub stroke: StrokeStyle<'a>,
    /// Which points the fill covers (paths that cross themselves or have
    /// holes).
    pub fill_rule: FillRule,
    /// The opacity of fill and stroke.
    pub opacity: Opacity,
    /// Painter's order (default) or seed 000's addition.
    pub blend: Blend,
    /// Exact coverage at the edges (default), or sharpened for a 1-bit
    /// display ([`Edges`]).
    pub edges: Edges,
}

impl<Col: Copy> Default for AaStyle<'_, Col> {
    fn default() -> Self {
        Self::new()
    }
}

impl<'a, Col: Copy> AaStyle<'a, Col> {
    /// Nothing drawn: no fill, no stroke (width 1 px when a colour is
    /// given), opaque, painter's order, nonzero rule.
    pub const fn new() -> Self {
        Self {
            fill_color: None,
            stroke_color: None,
            stroke: StrokeStyle::new(crate::geom::FINE_ONE as u32),
            fill_rule: FillRule::NonZero,
            opacity: Opacity::OPAQUE,
            blend: Blend::Over,
            edges: Edges::Smooth,
        }
    }

    /// A fill of `color`.
    pub const fn with_fill(color: Col) -> Self {
        Self::new().fill_color(color)
    }

    /// A stroke of `color`, `width` px wide, centred, miter joins (limit
    /// 4), butt caps (SVG's defaults).
    pub const fn with_stroke(color: Col, width: u32) -> Self {
        Self::new().stroke_color(color).stroke_width(width)
    }

    /// The fill's colour.
    pub const fn fill_color(mut self, color: Col) -> Self {
        self.fill_color = Some(color);
        self
    }

    /// The stroke's colour.
    pub const fn stroke_color(mut self, color: Col) -> Self {
        self.stroke_color = Some(color);
        self
    }

    /// The stroke's width in whole pixels.
    pub const fn stroke_width(mut self, px: u32) -> Self {
        self.stroke.width = px.saturating_mul(crate::geom::FINE_ONE as u32);
        self
    }

    /// The stroke's width in 1/1024 px (hairlines: 1024 is one pixel, 256
    /// a quarter of one, drawn as a quarter of the intensity).
    pub const fn stroke_width_fine(mut self, fine: u32) -> Self {
        self.stroke.width = fine;
        self
    }

    /// Which side of a closed outline the stroke lies on:
    /// embedded-graphics' `StrokeAlignment` (`Inside`, `Center`,
    /// `Outside`) or softedge's [`StrokeAlignment`]. On embedded-graphics'
    /// primitives a stroke of whole pixels lies on the pixels
    /// embedded-graphics lights (see [`eg_stroke`]).
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_graphics::primitives::StrokeAlignment;
    /// use softedge::prelude::*;
    /// let style = AaStyle::with_stroke(BinaryColor::On, 1).stroke_alignment(StrokeAlignment::Inside);
    /// assert_eq!(style.stroke.alignment, softedge::path::StrokeAlignment::Inside);
    /// ```
    pub fn stroke_alignment(mut self, alignment: impl Into<StrokeAlignment>) -> Self {
        self.stroke.alignment = alignment.into();
        self
    }

    /// The joins at a path's corners.
    pub const fn join(mut self, join: LineJoin) -> Self {
        self.stroke.join = join;
        self
    }

    /// The limit of miter joins.
    pub const fn miter_limit(mut self, limit: MiterLimit) -> Self {
        self.stroke.miter_limit = limit;
        self
    }

    /// The caps at the ends of open paths and dashes.
    pub const fn cap(mut self, cap: LineCap) -> Self {
        self.stroke.cap = cap;
        self
    }

    /// A dash pattern (SVG's `stroke-dasharray` and `-dashoffset`).
    pub const fn dash<'e>(self, dash: Dash<'e>) -> AaStyle<'e, Col> {
        AaStyle {
            fill_color: self.fill_color,
            stroke_color: self.stroke_color,
            stroke: self.stroke.with_dash(dash),
            fill_rule: self.fill_rule,
            opacity: self.opacity,
            blend: self.blend,
            edges: self.edges,
        }
    }

    /// The fill rule.
    pub const fn fill_rule(mut self, rule: FillRule) -> Self {
        self.fill_rule = rule;
        self
    }

    /// The opacity of fill and stroke.
    pub const fn opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// How the shape meets what is under it.
    pub const fn blend(mut self, blend: Blend) -> Self {
        self.blend = blend;
        self
    }

    /// How its edge pixels are drawn: [`Edges::Crisp`] (whole pixels) or
    /// [`Edges::Boost`] for text and lines that must stay legible on a
    /// 1-bit display, where the rest of the frame keeps its dithered
    /// half-tones.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use softedge::prelude::*;
    /// const VALUE_ARC: AaStyle<'static, BinaryColor> =
    ///     AaStyle::with_stroke(BinaryColor::On, 5).cap(LineCap::Round).edges(Edges::Crisp);
    /// assert_eq!(VALUE_ARC.edges, Edges::Crisp);
    /// ```
    pub const fn edges(mut self, edges: Edges) -> Self {
        self.edges = edges;
        self
    }
}

impl<Col: PixelColor> From<PrimitiveStyle<Col>> for AaStyle<'static, Col> {
    /// The same fill and stroke colours, stroke width and alignment
    /// (embedded-graphics' miter-or-bevel joins become miters of limit 4;
    /// butt caps).
    fn from(s: PrimitiveStyle<Col>) -> Self {
        let mut style = Self::new();
        style.fill_color = s.fill_color;
        if s.stroke_width > 0 {
            style.stroke_color = s.stroke_color;
        }
        style
            .stroke_width(s.stroke_width)
            .stroke_alignment(s.stroke_alignment)
    }
}

/// A styled primitive that draws itself, anti-aliased, into a band's
/// canvas of `C` channels (as embedded-graphics' `Drawable` draws into a
/// `DrawTarget`): a primitive with an [`AaStyle`] (colours the canvas
/// converts) or an [`AaGradient`] (a gradient of the canvas's channels).
///
/// **`draw` returns `Ok` for every shape**, so `?` in a drawing closure
/// never stops the frame. A shape the canvas rejects (a point outside
/// the ±2048 px range, a dash pattern of too many intervals) is not
/// drawn: it is counted in the canvas's [`skipped`](Canvas::skipped),
/// the first one named ([`DrawError::OutOfRange`]: its kind and the point,
/// in px) with its place in the drawing order, and the renderer returns
/// that record with the frame ([`FrameReport`](crate::render::FrameReport)),
/// every other shape drawn. Fill and stroke are each a shape of their
/// own. The `Result` is kept for embedded-graphics' idiom (`Drawable`
/// returns one) and for errors a future style may find before drawing.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use embedded_graphics::primitives::Circle;
/// use softedge::prelude::*;
/// # use softedge::{Band, BandBuffer};
/// # let (mut acc, mut cover) = ([0i32; BandBuffer::<3>::acc_len(20, 20)], [0i32; BandBuffer::<3>::cover_len(20, 20)]);
/// # let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(20, 0, 20)).unwrap();
/// # buf.clear([0; 3]);
/// # let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
/// let style = AaStyle::with_fill(Rgb565::BLUE);
/// Circle::new(Point::new(5000, 0), 8).into_styled(style).draw(&mut canvas)?; // rejected: Ok
/// Circle::new(Point::new(2, 2), 8).into_styled(style).draw(&mut canvas)?; // drawn
/// let (at, why) = canvas.skipped().first.unwrap();
/// assert_eq!(at, 0);
/// // "circle reaches (4999.9844, -0.0156) px, outside ±2048 px": a corner
/// // of the box of what it draws (the area-true polygon reaches a hair
/// // beyond the circle).
/// assert!(why.to_string().starts_with("circle reaches (4999.98"));
/// # Ok::<(), DrawError>(())
/// ```
pub trait AaDrawable<const C: usize> {
    /// Draws into `canvas`, whose band may hold only part of the shape
    /// (the rest is drawn in the other bands). `Ok` whether or not the
    /// canvas took the shape (see the trait's docs).
    fn draw<D>(&self, canvas: &mut Canvas<'_, '_, C, D>) -> Result<(), DrawError>;
}

/// Names the first rejection of the frame's band by `kind` when it was
/// recorded by the shape just drawn (`clean`: none was recorded before).
fn name_rejection<const C: usize, D>(
    canvas: &mut Canvas<'_, '_, C, D>,
    clean: bool,
    kind: ShapeKind,
) {
    if clean {
        if let Some((_, e)) = &mut canvas.skipped_mut().first {
            *e = e.of_shape(kind);
        }
    }
}

impl<P: AaShape, Col: Copy + IntoLinear<C>, const C: usize> AaDrawable<C>
    for Styled<P, AaStyle<'_, Col>>
{
    fn draw<D>(&self, canvas: &mut Canvas<'_, '_, C, D>) -> Result<(), DrawError> {
        let s = &self.style;
        let shape = self.primitive.shape();
        let clean = canvas.skipped().first.is_none();
        let edges = canvas.edges();
        canvas.set_edges(s.edges);
        // A rejection is recorded by the canvas (and named below): the
        // results are not returned (see `AaDrawable`).
        if let Some(c) = s.fill_color {
            let _ = canvas.fill_shape(&shape, c.into_linear(), s.fill_rule, s.blend, s.opacity);
        }
        match s.stroke_color {
            Some(c) if s.stroke.width > 0 => {
                let (on, stroke) = self.primitive.stroked(&s.stroke);
                let _ = canvas.stroke_shape(&on, &stroke, c.into_linear(), s.blend, s.opacity);
            }
            _ => {}
        }
        canvas.set_edges(edges);
        name_rejection(canvas, clean, P::KIND);
        Ok(())
    }
}

/// How a primitive is drawn with a [`Gradient`]: its fill, or its stroke
/// (width, joins, caps, dashes, alignment), with a fill rule, opacity and
/// blend. The gradient's stops are in the canvas's channels (`Gradient<3>`
/// on an RGB display); make it once, as a `const` or a `static` in flash
/// if it never changes.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use embedded_graphics::primitives::Circle;
/// use softedge::prelude::*;
/// use softedge::style::{Gradient, Offset, Stop};
/// # use softedge::{Band, BandBuffer};
/// # let (mut acc, mut cover) = ([0i32; 3 * 400], [0i32; BandBuffer::<3>::cover_len(20, 20)]);
/// # let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, Band::new(20, 0, 20)).unwrap();
/// # buf.clear([0; 3]);
/// # let mut canvas: Canvas<'_, '_, 3, Rgb565> = Canvas::typed(&mut buf, None);
/// let glow = Gradient::radial(
///     FinePoint::from_px(10, 10),
///     10 * 1024,
///     &[Stop::new(Offset::ZERO, Rgb565::WHITE), Stop::new(Offset::ONE, Rgb565::BLUE)],
/// )?;
/// Circle::new(Point::new(0, 0), 20).into_styled(AaGradient::fill(&glow)).draw(&mut canvas)?;
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[non_exhaustive]
pub struct AaGradient<'a, const C: usize> {
    /// The gradient.
    pub gradient: &'a Gradient<C>,
    /// `None`: the fill; `Some`: the stroke of this style.
    pub stroke: Option<StrokeStyle<'a>>,
    /// Which points the fill covers.
    pub fill_rule: FillRule,
    /// The opacity.
    pub opacity: Opacity,
    /// Painter's order (default) or seed 000's addition.
    pub blend: Blend,
}

impl<'a, const C: usize> AaGradient<'a, C> {
    /// The fill, by the gradient (nonzero, opaque, painter's order).
    pub const fn fill(gradient: &'a Gradient<C>) -> Self {
        Self {
            gradient,
            stroke: None,
            fill_rule: FillRule::NonZero,
            opacity: Opacity::OPAQUE,
            blend: Blend::Over,
        }
    }

    /// The stroke, `width` px wide (centred, miter joins, butt caps), by
    /// the gradient.
    pub const fn stroke(gradient: &'a Gradient<C>, width: u32) -> Self {
        let mut s = Self::fill(gradient);
        s.stroke = Some(StrokeStyle::new(
            width.saturating_mul(crate::geom::FINE_ONE as u32),
        ));
        s
    }

    /// The stroke's geometry (width in 1/1024 px, joins, caps, dashes,
    /// alignment): a stroke from now on.
    pub const fn stroke_style(mut self, stroke: StrokeStyle<'a>) -> Self {
        self.stroke = Some(stroke);
        self
    }

    /// The fill rule.
    pub const fn fill_rule(mut self, rule: FillRule) -> Self {
        self.fill_rule = rule;
        self
    }

    /// The opacity.
    pub const fn opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// How the shape meets what is under it.
    pub const fn blend(mut self, blend: Blend) -> Self {
        self.blend = blend;
        self
    }
}

impl<P: AaShape, const C: usize> AaDrawable<C> for Styled<P, AaGradient<'_, C>> {
    fn draw<D>(&self, canvas: &mut Canvas<'_, '_, C, D>) -> Result<(), DrawError> {
        let s = &self.style;
        let shape = self.primitive.shape();
        let clean = canvas.skipped().first.is_none();
        // Recorded by the canvas when rejected (see `AaDrawable`).
        let _ = match &s.stroke {
            None => canvas.fill_shape_gradient(&shape, s.gradient, s.fill_rule, s.blend, s.opacity),
            Some(st) => {
                let (on, stroke) = self.primitive.stroked(st);
                canvas.stroke_shape_gradient(&on, &stroke, s.gradient, s.blend, s.opacity)
            }
        };
        name_rejection(canvas, clean, P::KIND);
        Ok(())
    }
}
