//! # softedge
//!
//! Anti-aliased, gamma-correct, Gouraud-shading rasterizer for the small
//! displays of microcontrollers: `#![no_std]`, no heap, no floating point and
//! no multiply or divide in the per-pixel loops (integer add, subtract,
//! compare, shift and table look-up only; products appear once per
//! primitive, per edge or per span, as stated where they occur).
//!
//! ```
//! use embedded_graphics::mock_display::MockDisplay;
//! use embedded_graphics::pixelcolor::Rgb565;
//! use embedded_graphics::prelude::*;
//! use embedded_graphics::primitives::{Circle, Line, Rectangle, RoundedRectangle};
//! use softedge::prelude::*;
//!
//! let mut display = MockDisplay::<Rgb565>::new(); // any DrawTarget: mipidsi, ssd1306, ...
//! let mut acc = [0; BandBuffer::<3>::acc_len(64, 8)];
//! let mut cover = [0; BandBuffer::<3>::cover_len(64, 8)];
//! let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 64, 64, 8)?;
//! let button = Rectangle::new(Point::new(8, 36), Size::new(48, 20));
//! renderer.render(&mut display, &Rgb565Format::new(Curve::Srgb), Rgb565::BLACK, |canvas| {
//!     Circle::new(Point::new(4, 4), 40).into_styled(AaStyle::with_fill(Rgb565::BLUE)).draw(canvas)?;
//!     RoundedRectangle::with_equal_corners(button, Size::new(6, 6))
//!         .into_styled(AaStyle::with_fill(Rgb565::RED).opacity(Opacity::from_percent(50)))
//!         .draw(canvas)?;
//!     Line::new(Point::new(2, 61), Point::new(61, 2))
//!         .into_styled(AaStyle::with_stroke(Rgb565::WHITE, 3).cap(LineCap::Round))
//!         .draw(canvas)
//! })?;
//! # assert_eq!(display.get_pixel(Point::new(20, 14)), Some(Rgb565::BLUE));
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! One frame flows through the stages in the order of the modules below:
//!
//! 1. Geometry and paths: [`geom`] (points on the 1/1024-px grid,
//!    [`FinePoint`](geom::FinePoint), and the 1/16-px
//!    [`SubPoint`] of the seed primitives, checked against
//!    the coordinate range of ±2048 px); [`path`] (shapes, paths, strokes,
//!    dashes and SVG path data as closed contours of segments).
//! 2. Shading: [`shade`], the Gouraud plane of a primitive (the only place
//!    colour gradients are divided); [`style`]: fill rule, blend, opacity.
//! 3. Edges and coverage: `edge` (the Bresenham evaluation-function edge
//!    walker of seed 001: each edge pixel's address and covered area by
//!    additions), [`pixel_model`] (bed-of-nails, hexagonal and circular
//!    filters, seeds 000 and 003).
//! 4. Compose: [`band`], the caller-provided buffers of one band of rows,
//!    the span sweep that composes a shape's coverage into them (over;
//!    add, `I_acc += I * S` of seed 000, eq. 3; depth, for [`hsr`]), and the
//!    one rounding of the frame. [`raster`] (seed 000's triangles, polygons
//!    and lines), [`hsr`] (hidden surfaces of seed 004, for the objects of
//!    [`scene3d`]) and [`postfilter`] (seed 002's lightness filter) work
//!    here.
//! 5. Tone: [`tone`], γ tables and logarithmic codes of seed 000, pixel
//!    formats, Bayer and Floyd–Steinberg dithering in linear light, display
//!    profiles.
//! 6. Flush: [`render`] (feature `embedded-graphics`), the frame loop into
//!    any embedded-graphics `DrawTarget`, or into the band buffer a DMA
//!    display lends ([`render::BandTarget`]), whole frames or a dirty
//!    window.
//!
//! Users draw through [`canvas`] (a band's canvas: any shape, mesh or
//! outline, in painter's order; also an embedded-graphics `DrawTarget`) and
//! [`draw`] (embedded-graphics' primitives styled with an
//! [`AaStyle`](draw::AaStyle)); [`prelude`] has what a frame needs.
//! Text (feature `text`, on by default): [`text`] lays out strings in
//! TrueType / OpenType fonts (`ttf-parser`) and hands their glyph outlines
//! to the canvas as paths.
//!
//! Colours come in through [`color`]: sRGB colours (embedded-graphics
//! colour types, 8-bit triples, `#rrggbb`) decoded to the linear 12-bit
//! intensity every stage works in, or their luminance on one channel.
//! Every error type prints (`Display`, `core::error::Error`) and, with the
//! `defmt` feature, logs (`defmt::Format`).
//!
//! ## Features
//!
//! - `embedded-graphics` (default): [`render`], [`draw`], [`prelude`], the
//!   canvas as a `DrawTarget`, the embedded-graphics colour types of
//!   [`tone::format`] and [`dither`](tone::dither), and
//!   [`IntoLinear`](color::IntoLinear) for embedded-graphics' colour types.
//! - `text` (default): [`text`], outline fonts through `ttf-parser`
//!   (`no_std`, no heap), and the bundled Softedge Sans Subset font.
//! - `defmt`: `defmt::Format` (defmt 1) for the public types, errors
//!   included, so firmware can log them.
//!
//! ## References
//!
//! The methods come from five papers, called *seed 000* to *seed 004* in
//! these docs and in the code's comments (equation and figure numbers are the
//! papers' own):
//!
//! 1. **[seed 000]** A. M. Kovalev, A. S. Tokarev, «Синтез изображений без
//!    элайсинга и оконтуривания» (*Image synthesis without aliasing and
//!    contouring*), *Avtometriya* (Novosibirsk), 1990 (received 12 February
//!    1990). Equal-energy filters and the accumulation `I += I_j S_j`
//!    (eqs. 2-5), bed-of-nails filters (fig. 4), γ correction and contrast
//!    (eqs. 6-8), bit depths (eqs. 9-10), logarithmic intensity codes
//!    (eqs. 11-15, fig. 7).
//! 2. **[seed 001]** A Ukrainian paper on combining, in one computation, the
//!    addresses of an edge's pixels, their Gouraud intensities and their
//!    covered areas (anti-aliasing by the Bresenham evaluation function with
//!    additions only); author, title and venue are not preserved in the copy
//!    the project worked from.
//! 3. **[seed 002]** T. Naka, A. Nishimura, Y. Nakase (Matsushita Electric
//!    Industrial Co., Information and Communications Research Center),
//!    «高品質なCG画像生成におけるアンチエイリアシング手法» (*Anti-aliasing
//!    technique for high quality computer graphics*), c. 1989-1990 (venue not
//!    named in the copy; its latest reference is from 1989). The CIELAB
//!    `L*`-adaptive 3x3 filter.
//! 4. **[seed 003]** O. N. Romanyuk, O. V. Melnyk (Vinnytsia National
//!    Technical University), «Особливості гексагональної моделі піксела»
//!    (*Peculiarities of a hexagonal pixel model*), *Visnyk Khmelnytskoho
//!    natsionalnoho universytetu* (Herald of Khmelnytskyi National
//!    University), 2014 (printed 26 March 2014). Pixel models: hexagonal
//!    pixels of 7 and 19 sub-pixels, the cone, Gaussian and Hamming filters.
//! 5. **[seed 004]** «Удаление невидимых поверхностей и линий» (*Removal of
//!    hidden surfaces and lines*), lecture 6 of a course of the Internet
//!    University of Information Technologies (INTUIT, Moscow), published 20
//!    October 2007, ISBN 978-5-94774-654-9. Warnock's subdivision,
//!    Weiler–Atherton clipping, the z-buffer and its section mode.
#![no_std]
#![cfg_attr(docsrs, feature(doc_cfg))]
#![forbid(unsafe_code)]
// Without embedded-graphics there is no renderer: the band's flush and
// pixel-store paths and the display profiles' constructors go unused.
#![cfg_attr(not(feature = "embedded-graphics"), allow(dead_code))]
#![deny(missing_docs)]
// Per-channel loops index several arrays of the same length at once.
#![allow(clippy::needless_range_loop)]

mod arith;
pub mod band;
pub mod canvas;
pub mod color;
#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
pub mod draw;
/// The edge walker of seed 001 (feature `internals`: softedge's own tests;
/// no stability promised).
#[cfg(feature = "internals")]
pub mod edge;
#[cfg(not(feature = "internals"))]
mod edge;
mod error;
pub mod geom;
pub mod hsr;
pub mod image;
pub mod path;
pub mod pixel_model;
pub mod postfilter;
#[cfg(feature = "embedded-graphics")]
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
pub mod prelude;
pub mod raster;
#[cfg(feature = "embedded-graphics")]
pub mod render;
pub mod scene3d;
pub mod shade;
pub mod style;
#[cfg(feature = "text")]
#[cfg_attr(docsrs, doc(cfg(feature = "text")))]
pub mod text;
pub mod tone;
mod units;

/// The fixed-point crate whose types appear in the API (`I22F10`
/// coordinates, `I16F16` angles and 3D math).
pub use fixed;

pub use band::{Band, BandBuffer, BandError, Bands};
pub use error::ShapeKind;
pub use geom::{CoordError, SubPoint, COORD_LIMIT_PX, SUB_BITS, SUB_ONE};
pub use raster::{
    DrawError, Line, PixelModel, Polygon, PolygonColors, RenderStyle, Triangle,
    MAX_POLYGON_VERTICES,
};
pub use shade::LIN_MAX;

pub use units::{COVER_BITS, COVER_ONE};
