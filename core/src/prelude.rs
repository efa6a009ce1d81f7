//! What drawing a frame needs, in one `use`: names that do not clash with
//! `embedded_graphics::prelude::*` beside it.
//!
//! ```
//! use embedded_graphics::prelude::*;
//! use softedge::prelude::*;
//! let style: AaStyle<'_, embedded_graphics::pixelcolor::Rgb565> = AaStyle::new();
//! assert_eq!(style.opacity, Opacity::OPAQUE);
//! ```

pub use crate::band::BandBuffer;
pub use crate::canvas::{Canvas, ListedTriangle, TriangleList, WalkSlot};
pub use crate::draw::{AaDrawable, AaGradient, AaStyle};
pub use crate::geom::FinePoint;
pub use crate::path::{Dash, LineCap, LineJoin, MiterLimit};
pub use crate::raster::DrawError;
pub use crate::render::{BandTarget, FrameReport, RenderError, Renderer};
pub use crate::style::{Blend, Edges, FillRule, Opacity};
#[cfg(feature = "text")]
pub use crate::text::DrawAaText;
pub use crate::tone::format::{Gray4Format, Gray8Format, Rgb565Format, Rgb888Format};
pub use crate::tone::ordered::{Gray4Dither, Rgb565Dither};
pub use crate::tone::{Bayer8, Curve, DiffusionProfile};
