//! # softedge
//!
//! Anti-aliased, gamma-correct, Gouraud-shading rasterizer for the small
//! displays of microcontrollers: `#![no_std]`, no heap, no floating point and
//! no multiply or divide in the per-pixel loops (integer add, subtract,
//! compare, shift and table look-up only; products appear once per
//! primitive, per edge or per span, as stated where they occur).
//!
//! One frame flows through the stages in the order of the modules below:
//!
//! 1. [`geom`]: vertices in sub-pixel fixed point (1/16 px), checked against
//!    the documented coordinate range; [`path`]: paths, shapes, strokes and
//!    SVG path data as closed contours of segments on the 1/1024-px grid.
//! 2. [`shade`]: per-primitive setup of the Gouraud plane (the only place
//!    colour gradients are divided).
//! 3. [`edge`]: the Bresenham evaluation-function edge walker of seed 001,
//!    computing each edge pixel's address, covered area and `I * S` with
//!    additions.
//! 4. [`band`]: the caller-provided accumulation buffer of one band of rows,
//!    `I_acc += I * S` (seed 000, eq. 3), the span sweep that fills interior
//!    pixels, and the one rounding of the frame, at resolve.
//! 5. [`raster`]: the primitives users draw (triangles, polygons, lines),
//!    with the pixel models of [`pixel_model`] (bed-of-nails, hexagonal,
//!    circular filters; seeds 000 and 003).
//! 6. [`hsr`]: hidden surfaces (seed 004) for primitives with depths and
//!    the 3D objects of [`scene3d`]: the z-buffer in bands, section mode,
//!    Warnock's subdivision, Weiler–Atherton clipping.
//! 7. [`postfilter`]: seed 002's lightness-adaptive smoothing (optional).
//! 8. [`tone`]: γ tables and logarithmic intensity codes (seed 000).
//! 9. `eg` (feature `embedded-graphics`, on by default): flushing each
//!    finished band to any embedded-graphics `DrawTarget`.
//!
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
//! ```
//! use softedge::{BandBuffer, Bands, RenderStyle, SubPoint, Triangle};
//!
//! const W: usize = 32;
//! const H: usize = 16;
//! const ROWS: usize = 8;
//! let mut acc = [0i32; BandBuffer::<1>::acc_len(W as u16, ROWS as u16)];
//! let mut cover = [0i32; BandBuffer::<1>::cover_len(W as u16, ROWS as u16)];
//! let tri = Triangle::new(
//!     [SubPoint::from_px(2, 1), SubPoint::new(29 * 16 + 5, 7 * 16), SubPoint::from_px(8, 15)],
//!     [[4095], [2048], [0]],
//! );
//! let mut total = 0u32;
//! for band in Bands::new(W as u16, H as u16, ROWS as u16) {
//!     let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
//!     buf.clear([0]);
//!     tri.draw(&mut buf, &RenderStyle::default()).unwrap();
//!     for y in band.y0..band.y0 + band.rows as i32 {
//!         for x in 0..W as i32 {
//!             total += u32::from(buf.lin12(x, y).unwrap()[0]);
//!         }
//!     }
//! }
//! assert!(total > 0);
//! ```
//!
//! ## Features
//!
//! - `embedded-graphics` (default): the `eg` glue, the embedded-graphics
//!   colour types of [`tone::format`] and [`dither`](tone::dither), and
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
#![deny(missing_docs)]
// Per-channel loops index several arrays of the same length at once.
#![allow(clippy::needless_range_loop)]

mod arith;
pub mod band;
pub mod canvas;
pub mod color;
pub mod edge;
mod errors;
pub mod geom;
pub mod hsr;
pub mod path;
pub mod pixel_model;
pub mod postfilter;
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

pub use band::{Band, BandBuffer, BandError, Bands};
pub use geom::{CoordError, SubPoint, COORD_LIMIT_PX, SUB_BITS, SUB_ONE};
pub use raster::{
    DrawError, Line, PixelModel, Polygon, PolygonColors, RenderStyle, Triangle,
    MAX_POLYGON_VERTICES,
};
pub use shade::LIN_MAX;

pub use units::{COVER_BITS, COVER_ONE};
