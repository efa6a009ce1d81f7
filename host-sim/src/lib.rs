//! # softedge-sim
//!
//! The host side of softedge: everything that needs `std` (files, PNG, the
//! command line) and none of it in the firmware.
//!
//! - [`scene`]: a frame described as data (primitives with per-vertex
//!   colours, frame size, band height, style, background) and
//!   [`render`](scene::render), which draws it band by band exactly as
//!   firmware does: one [`BandBuffer`](softedge::BandBuffer) of `band_rows`
//!   rows, cleared, every primitive drawn into it, rows resolved, next band.
//!   The result is a [`LinImage`](image::LinImage) of linear 12-bit values,
//!   the bits a display driver would receive before its tone stage.
//!   [`render_lightness_filtered`](scene::render_lightness_filtered) adds
//!   seed 002's `L*` post-filter, each band rendered with one halo row
//!   above and below.
//! - [`image`]: linear and 8-bit images, the linear-to-sRGB conversion for
//!   viewing on a PC, nearest-neighbour upscaling and simple compositing.
//! - [`font`]: a 3x5 bitmap font for panel labels.
//! - [`font_gen`]: fonts rasterized ahead of time for flash
//!   (`softedge-sim font`).
//! - [`png_out`]: PNG encoding with the `png` crate (fast, or compact for
//!   the committed golden images) and reading back.
//! - [`gallery`]: the demo images of `softedge-sim gallery`.
//! - [`memory`]: the band buffers' RAM (`softedge-sim memory`).
//!
//! ```
//! use softedge::style::Blend;
//! use softedge::{Line, RenderStyle, SubPoint};
//! use softedge_sim::scene::{render, Hsr, Primitive, Scene};
//!
//! let scene = Scene::<1> {
//!     width: 16,
//!     height: 8,
//!     band_rows: 8,
//!     style: RenderStyle::default(),
//!     background: [0],
//!     primitives: vec![Primitive::Line(Line::new(
//!         SubPoint::from_px(1, 4),
//!         SubPoint::from_px(15, 4),
//!         [[4094], [4094]],
//!     ))],
//!     hsr: Hsr::None,
//!     section: None,
//!     blend: Blend::Add,
//! };
//! let img = render(&scene).unwrap();
//! assert_eq!(img.get(8, 3), &[2047]); // half of the 1-px line in each row
//! assert_eq!(img.get(8, 4), &[2047]);
//! ```

pub mod font;
pub mod font_gen;
pub mod gallery;
pub mod image;
pub mod image_item;
pub mod memory;
pub mod png_out;
pub mod scene;
pub mod scene_file;
pub mod shape_item;
pub mod text_item;

/// The repository README's code blocks, compiled and run as doc tests.
#[cfg(doctest)]
#[doc = include_str!("../../README.md")]
pub struct ReadmeDoctests;
