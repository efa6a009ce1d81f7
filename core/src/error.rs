//! What every drawing call returns when it does not draw: [`DrawError`],
//! shared by the primitives, the canvas, the styled shapes, text and
//! hidden-surface removal (kept below all of them).
//!
//! Messages are short, lower case, without a final full stop, and carry the
//! numbers that matter, so a firmware log line or a host tool's diagnostic
//! can show them as they are; every error type of the crate prints
//! (`Display`, `core::error::Error`, each beside its type) and, with the
//! `defmt` feature, logs (`defmt::Format`):
//!
//! ```
//! use softedge::{CoordError, DrawError, SubPoint};
//! let e = DrawError::Coord(CoordError { point: SubPoint::new(32_776, 160) });
//! assert_eq!(e.to_string(), "vertex (32776, 160) in 1/16 px is outside ±2048 px");
//! let source = core::error::Error::source(&e).map(|s| s.to_string());
//! assert_eq!(source.as_deref(), Some("vertex (32776, 160) in 1/16 px is outside ±2048 px"));
//! ```

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use crate::geom::{CoordError, FinePoint, COORD_LIMIT_PX};
use crate::units::MAX_POLYGON_VERTICES;

/// Why a primitive was not drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum DrawError {
    /// A vertex is outside the accepted coordinate range.
    Coord(CoordError),
    /// A point on the fine grid (1/1024 px) is outside the accepted
    /// coordinate range.
    FineCoord(FinePoint),
    /// A mesh's triangle names a point it does not have.
    BadIndex,
    /// A stroke was not drawn completely (its dash pattern needed too many
    /// intervals).
    Stroke(crate::path::StrokeError),
    /// More than [`MAX_POLYGON_VERTICES`] vertices.
    TooManyVertices,
    /// Per-vertex colours given for a different number of vertices.
    ColorCount,
    /// Two non-adjacent edges of the polygon touch or cross.
    SelfIntersecting,
    /// A recorded outline lost segments: its
    /// [`SegmentBuffer`](crate::path::SegmentBuffer) was too small.
    Incomplete,
    /// A [`TriangleList`](crate::canvas::TriangleList) has no room for
    /// another triangle.
    ListFull,
    /// A text has a character its font lacks (the first one; the
    /// characters the font has were drawn, this one and any other missing
    /// one were not).
    MissingGlyph(char),
}

impl From<CoordError> for DrawError {
    fn from(e: CoordError) -> Self {
        Self::Coord(e)
    }
}

impl Display for DrawError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::Coord(e) => e.fmt(f),
            Self::TooManyVertices => {
                write!(f, "polygon has more than {MAX_POLYGON_VERTICES} vertices")
            }
            Self::ColorCount => {
                f.write_str("per-vertex colours for a different number of vertices")
            }
            Self::SelfIntersecting => f.write_str("polygon intersects itself"),
            Self::Incomplete => {
                f.write_str("recorded outline lost segments (its buffer was too small)")
            }
            Self::FineCoord(p) => write!(
                f,
                "point ({}, {}) in 1/1024 px is outside ±{COORD_LIMIT_PX} px",
                p.x, p.y
            ),
            Self::ListFull => f.write_str("triangle list is full"),
            Self::MissingGlyph(c) => {
                write!(f, "the font has no glyph for {c:?} (U+{:04X})", *c as u32)
            }
            Self::BadIndex => f.write_str("a mesh triangle names a point the mesh does not have"),
            Self::Stroke(e) => e.fmt(f),
        }
    }
}

impl Error for DrawError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Coord(e) => Some(e),
            Self::Stroke(e) => Some(e),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::string::ToString;

    use super::*;
    use crate::band::BandError;
    use crate::color::ColorError;
    use crate::geom::SubPoint;
    use crate::hsr::HsrError;
    use crate::postfilter::FilterError;
    use crate::scene3d::SceneError;
    use crate::tone::ToneError;

    #[test]
    fn messages_carry_their_numbers() {
        let coord = CoordError {
            point: SubPoint::new(-40_000, 3),
        };
        assert_eq!(
            coord.to_string(),
            "vertex (-40000, 3) in 1/16 px is outside ±2048 px"
        );
        assert_eq!(
            HsrError::Draw(DrawError::TooManyVertices).to_string(),
            "polygon has more than 64 vertices"
        );
        assert_eq!(
            HsrError::Capacity { needed: 4097 }.to_string(),
            "scene needs storage for at least 4097 items"
        );
        assert_eq!(
            SceneError::Capacity {
                vertices: 300,
                triangles: 576
            }
            .to_string(),
            "mesh storage too small: 300 vertices and 576 triangles needed"
        );
        assert_eq!(
            BandError::BadBand.to_string(),
            "band is empty, wider than 2048 px or starts beyond ±2048 px"
        );
        assert_eq!(
            FilterError::BadSize.to_string(),
            "frame size is zero or wider than 2048 px"
        );
        assert_eq!(ToneError::Contrast.to_string(), "contrast K is below 2");
    }

    #[test]
    fn colour_errors_name_the_byte() {
        assert_eq!(
            ColorError::Digit {
                index: 3,
                byte: b'g'
            }
            .to_string(),
            "`g` at byte 3 is not a hex digit"
        );
        assert_eq!(
            ColorError::Digit {
                index: 1,
                byte: 0xc3
            }
            .to_string(),
            "byte 1 (0xc3) is not a hex digit"
        );
        assert_eq!(
            ColorError::Length { len: 4 }.to_string(),
            "hex colour `#rrggbb` has 7 characters, not 4"
        );
    }

    #[test]
    fn sources_chain_to_the_cause() {
        let coord = CoordError {
            point: SubPoint::new(0, 99_999),
        };
        let hsr = HsrError::Draw(DrawError::Coord(coord));
        let draw = hsr.source().map(ToString::to_string);
        assert_eq!(draw, Some(coord.to_string()));
        assert!(HsrError::BandMismatch.source().is_none());
    }

    #[cfg(feature = "embedded-graphics")]
    #[test]
    fn render_errors_print_the_display_error_with_debug() {
        use crate::render::RenderError;
        #[derive(Debug)]
        struct Spi;
        let e: RenderError<Spi, DrawError> = RenderError::Target(Spi);
        assert_eq!(e.to_string(), "display error: Spi");
        let e: RenderError<Spi, DrawError> = RenderError::Draw {
            band_y0: 16,
            error: DrawError::BadIndex,
        };
        assert_eq!(
            e.to_string(),
            "drawing failed in the band at row 16: a mesh triangle names a point the mesh does not have"
        );
        assert!(e.source().is_some());
        let e: RenderError<Spi, DrawError> = RenderError::Band(BandError::AccTooSmall);
        assert_eq!(
            e.to_string(),
            "band buffer: accumulation buffer is shorter than acc_len"
        );
        assert!(e.source().is_some());
    }
}
