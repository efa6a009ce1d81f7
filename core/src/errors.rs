//! Errors that print: `core::fmt::Display` and `core::error::Error` for
//! every public error type of the crate, in one place (the types stay in
//! their modules).
//!
//! Messages are short, lower case, without a final full stop, and carry the
//! numbers that matter, so a firmware log line or a host tool's diagnostic
//! can show them as they are:
//!
//! ```
//! use softedge::{CoordError, DrawError, SubPoint};
//! let e = DrawError::Coord(CoordError { point: SubPoint::new(32_776, 160) });
//! assert_eq!(e.to_string(), "vertex (32776, 160) in 1/16 px is outside ±2048 px");
//! let source = core::error::Error::source(&e).map(|s| s.to_string());
//! assert_eq!(source.as_deref(), Some("vertex (32776, 160) in 1/16 px is outside ±2048 px"));
//! ```
//!
//! With the `defmt` feature every one of them is also `defmt::Format`
//! (derived beside the type; [`RenderError`](crate::render::RenderError)'s
//! generic impl is here).

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use crate::band::{BandError, MAX_WIDTH};
use crate::color::ColorError;
use crate::geom::{CoordError, COORD_LIMIT_PX};
use crate::hsr::HsrError;
use crate::postfilter::FilterError;
use crate::raster::{DrawError, MAX_POLYGON_VERTICES};
use crate::scene3d::{SceneError, MAX_FOCAL_PX, MAX_MESH_VERTICES, MAX_SEGMENTS, MIN_SEGMENTS};
use crate::tone::ToneError;

impl Display for CoordError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "vertex ({}, {}) in 1/16 px is outside ±{COORD_LIMIT_PX} px",
            self.point.x, self.point.y
        )
    }
}

impl Error for CoordError {}

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
            Self::FineCoord(p) => write!(
                f,
                "point ({}, {}) in 1/1024 px is outside ±{COORD_LIMIT_PX} px",
                p.x, p.y
            ),
            Self::BadIndex => f.write_str("a mesh triangle names a point the mesh does not have"),
            Self::Stroke(e) => e.fmt(f),
        }
    }
}

impl Error for crate::path::StrokeError {}

impl Error for crate::path::svg::SvgError {}

impl Error for DrawError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Coord(e) => Some(e),
            Self::Stroke(e) => Some(e),
            _ => None,
        }
    }
}

impl Display for BandError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadBand => write!(
                f,
                "band is empty, wider than {MAX_WIDTH} px or starts beyond ±{COORD_LIMIT_PX} px"
            ),
            Self::AccTooSmall => f.write_str("accumulation buffer is shorter than acc_len"),
            Self::CoverTooSmall => f.write_str("cover buffer is shorter than cover_len"),
            Self::DepthTooSmall => f.write_str("depth buffer is shorter than DepthBuffer::len"),
        }
    }
}

impl Error for BandError {}

impl Display for HsrError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::Draw(e) => e.fmt(f),
            Self::BandMismatch => {
                f.write_str("depth buffer holds another band than the band buffer")
            }
            Self::Capacity { needed } => {
                write!(f, "scene needs storage for at least {needed} items")
            }
        }
    }
}

impl Error for HsrError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Draw(e) => Some(e),
            _ => None,
        }
    }
}

impl Display for ToneError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Contrast => "contrast K is below 2",
            Self::Gradations => "number of gradations m is zero",
            Self::GaussTooLong => {
                "gaussian-logarithm table does not reach zero: gradation step too fine for the contrast"
            }
            Self::PlanInput => "planning input out of range (K <= 1, δ <= 0, γ <= 1 or not finite)",
        })
    }
}

impl Error for ToneError {}

impl Display for SceneError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::OutOfRange => f.write_str("coordinate, size, scale or matrix entry out of range"),
            Self::NonPositive => f.write_str("size, scale or distance is not positive"),
            Self::Segments => write!(
                f,
                "segment count outside {MIN_SEGMENTS}..={MAX_SEGMENTS} or over {MAX_MESH_VERTICES} vertices"
            ),
            Self::Capacity {
                vertices,
                triangles,
            } => write!(
                f,
                "mesh storage too small: {vertices} vertices and {triangles} triangles needed"
            ),
            Self::Scratch { needed } => {
                write!(f, "projection scratch too small: {needed} vertices needed")
            }
            Self::BadIndex => f.write_str("triangle refers to a vertex beyond its mesh"),
            Self::EyeAtTarget => f.write_str("camera eye is at its target"),
            Self::UpParallel => f.write_str("camera up is zero or parallel to the view direction"),
            Self::FieldOfView => write!(
                f,
                "field of view outside (0, 180) degrees or focal length over {MAX_FOCAL_PX} px"
            ),
            Self::ZeroDirection => f.write_str("light direction is zero with a diffuse factor"),
        }
    }
}

impl Error for SceneError {}

impl Display for FilterError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadSize => write!(f, "frame size is zero or wider than {MAX_WIDTH} px"),
            Self::InputTooShort => f.write_str("filter input holds fewer pixels than its rows"),
            Self::ScratchTooSmall => f.write_str("filter scratch is shorter than scratch_len"),
            Self::OutputTooSmall => f.write_str("filter output is shorter than its row or frame"),
        }
    }
}

impl Error for FilterError {}

impl Display for ColorError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match *self {
            Self::MissingHash => f.write_str("hex colour must start with `#` (`#rrggbb`)"),
            Self::Length { len } => {
                write!(f, "hex colour `#rrggbb` has 7 characters, not {len}")
            }
            Self::Digit { index, byte } if byte.is_ascii_graphic() => write!(
                f,
                "`{}` at byte {index} is not a hex digit",
                char::from(byte)
            ),
            Self::Digit { index, byte } => {
                write!(f, "byte {index} (0x{byte:02x}) is not a hex digit")
            }
        }
    }
}

impl Error for ColorError {}

#[cfg(feature = "embedded-graphics")]
mod render {
    use core::error::Error;
    use core::fmt::{self, Debug, Display, Formatter};

    use crate::render::RenderError;

    /// The display's own error is printed with `Debug`: embedded-graphics
    /// drivers rarely implement `Display`.
    #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
    impl<T: Debug, E: Display> Display for RenderError<T, E> {
        fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
            match self {
                Self::Band(e) => write!(f, "band buffer: {e}"),
                Self::Size { frame, display } => write!(
                    f,
                    "frame {}x{} is larger than the display, {}x{}",
                    frame.0, frame.1, display.0, display.1
                ),
                Self::Draw { band_y0, error } => {
                    write!(f, "drawing failed in the band at row {band_y0}: {error}")
                }
                Self::Target(e) => write!(f, "display error: {e:?}"),
            }
        }
    }

    /// `source` is the band buffer's or the drawing closure's error; a
    /// display error is not one (its type need not implement `Error`).
    #[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
    impl<T: Debug, E: Error + 'static> Error for RenderError<T, E> {
        fn source(&self) -> Option<&(dyn Error + 'static)> {
            match self {
                Self::Band(e) => Some(e),
                Self::Draw { error, .. } => Some(error),
                Self::Size { .. } | Self::Target(_) => None,
            }
        }
    }

    #[cfg(feature = "defmt")]
    #[cfg_attr(
        docsrs,
        doc(cfg(all(feature = "embedded-graphics", feature = "defmt")))
    )]
    impl<T: defmt::Format, E: defmt::Format> defmt::Format for RenderError<T, E> {
        fn format(&self, f: defmt::Formatter<'_>) {
            match self {
                Self::Band(e) => defmt::write!(f, "Band({})", e),
                Self::Size { frame, display } => {
                    defmt::write!(
                        f,
                        "Size({}x{} > {}x{})",
                        frame.0,
                        frame.1,
                        display.0,
                        display.1
                    )
                }
                Self::Draw { band_y0, error } => {
                    defmt::write!(f, "Draw(row {}: {})", band_y0, error)
                }
                Self::Target(e) => defmt::write!(f, "Target({})", e),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::string::ToString;

    use super::*;
    use crate::geom::SubPoint;

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
