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
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]
// Per-channel loops index several arrays of the same length at once.
#![allow(clippy::needless_range_loop)]

mod arith;
pub mod band;
pub mod edge;
#[cfg(feature = "embedded-graphics")]
pub mod eg;
pub mod geom;
pub mod hsr;
pub mod path;
pub mod pixel_model;
pub mod postfilter;
pub mod raster;
pub mod scene3d;
pub mod shade;
pub mod tone;

pub use band::{Band, BandBuffer, BandError, Bands};
pub use geom::{CoordError, SubPoint, COORD_LIMIT_PX, SUB_BITS, SUB_ONE};
pub use raster::{
    DrawError, Line, PixelModel, Polygon, PolygonColors, RenderStyle, Triangle,
    MAX_POLYGON_VERTICES,
};
pub use shade::LIN_MAX;

/// Coverage of one whole pixel in the units every stage uses: `4096 = 2^12`.
///
/// Edge-pixel areas are floors in these units (error below 3/4096 px per
/// edge, far inside the 1/256 the box model promises); a pixel value in the
/// accumulation buffer is `lin12 * coverage`, so a fully covered pixel of
/// intensity 4095 holds `4095 * 4096 < 2^24`.
pub const COVER_ONE: i32 = 1 << COVER_BITS;
/// `log2(COVER_ONE)`.
pub const COVER_BITS: u32 = 12;
