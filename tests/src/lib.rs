//! Independent reference for `softedge`'s tests.
//!
//! - [`exact`]: exact areas (Sutherland–Hodgman clipping in rational
//!   arithmetic), the exact Gouraud plane and the aliased top-left rule,
//!   written from the definitions.
//! - [`ratio`]: the exact rational they use (checked `i128`).
//! - [`frame`]: drawing a whole frame through bands and reading it back;
//!   an [`EdgeSink`](softedge::edge::EdgeSink) that records what an edge walk
//!   reports.
//! - [`shapes`]: test shapes made from random numbers: star-shaped simple
//!   polygons and triangulations of a square.
//! - [`visible`]: which triangle is visible where (seed 004), by point
//!   sampling with exact depth comparisons: the hidden-surface reference.
//! - [`path_ref`]: `f64` winding numbers, scanline areas, exact disc areas,
//!   curve distances and stroke unions: the reference of the path tests.
//! - [`raster_font`]: fonts rasterized ahead of time, made at run time
//!   (the code under test's own rasterizer: what the text tests draw, not
//!   a reference).
//! - [`lcg`]: a small deterministic generator for random cases.
//! - [`screen`]: a display that keeps the pixels and windows it is sent,
//!   for the renderer's tests.
//! - [`glyph_ref`]: glyph outlines read by `ttf-parser`, flattened in `f64`
//!   within 1e-5 px, and their exact area in every pixel: the reference of
//!   the text tests.
#![forbid(unsafe_code)]

pub mod exact;
pub mod frame;
pub mod glyph_ref;
pub mod lcg;
pub mod path_ref;
pub mod raster_font;
pub mod ratio;
pub mod screen;
pub mod shapes;
pub mod visible;
