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
//! assert_eq!(e.to_string(), "vertex (2048.5, 10) px is outside ±2048 px");
//! let source = core::error::Error::source(&e).map(|s| s.to_string());
//! assert_eq!(source.as_deref(), Some("vertex (2048.5, 10) px is outside ±2048 px"));
//! ```
//!
//! Coordinates print in pixels (the engine's 1/16 and 1/1024 px units
//! converted, to 4 decimals), and a shape drawn with a style of
//! [`draw`](crate::draw) that is out of range is named by its kind
//! ([`DrawError::OutOfRange`]).

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use crate::geom::{CoordError, FinePoint, COORD_LIMIT_PX, FINE_BITS};
use crate::units::MAX_POLYGON_VERTICES;

/// A coordinate of `2^-bits` px printed in pixels: the integer part, then
/// up to 4 decimals (rounded half up in magnitude, trailing zeros left
/// out): `(32776, 4)` prints `2048.5`, `(5_119_984, 10)` `4999.9844`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Px {
    /// The value in `2^-bits` px.
    pub v: i64,
    /// Fraction bits of `v` (at most 32).
    pub bits: u32,
}

impl Px {
    /// A fine-grid (1/1024 px) coordinate.
    pub(crate) fn fine(v: i32) -> Self {
        Self {
            v: i64::from(v),
            bits: FINE_BITS,
        }
    }
}

impl Display for Px {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        const DECIMALS: u128 = 10_000;
        let bits = self.bits.min(32);
        let a = u128::from(self.v.unsigned_abs());
        // round(|v| * 10^4 / 2^bits), in u128: no overflow for any i64.
        let m = (a * DECIMALS + ((1u128 << bits) >> 1)) >> bits;
        let (int, mut frac) = (m / DECIMALS, m % DECIMALS);
        if self.v < 0 && m != 0 {
            f.write_str("-")?;
        }
        write!(f, "{int}")?;
        if frac != 0 {
            let mut digits = 4;
            while frac % 10 == 0 {
                frac /= 10;
                digits -= 1;
            }
            write!(f, ".{frac:0digits$}")?;
        }
        Ok(())
    }
}

/// What kind of shape a styled shape of [`draw`](crate::draw) is: how an
/// error names it (embedded-graphics' primitive or softedge's
/// [`path`](crate::path) shape of that name).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum ShapeKind {
    /// A circle.
    Circle,
    /// An ellipse.
    Ellipse,
    /// An arc.
    Arc,
    /// A sector.
    Sector,
    /// A rectangle.
    Rectangle,
    /// A rounded rectangle.
    RoundedRectangle,
    /// A line.
    Line,
    /// A polyline.
    Polyline,
    /// A triangle.
    Triangle,
    /// A polygon.
    Polygon,
    /// SVG path data.
    Path,
}

impl ShapeKind {
    /// The kind's name in lower case, as errors print it.
    pub const fn name(self) -> &'static str {
        match self {
            Self::Circle => "circle",
            Self::Ellipse => "ellipse",
            Self::Arc => "arc",
            Self::Sector => "sector",
            Self::Rectangle => "rectangle",
            Self::RoundedRectangle => "rounded rectangle",
            Self::Line => "line",
            Self::Polyline => "polyline",
            Self::Triangle => "triangle",
            Self::Polygon => "polygon",
            Self::Path => "path",
        }
    }
}

impl Display for ShapeKind {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

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
    /// An outline lost segments ([`Outline::complete`] is false: a
    /// recording that ran out of room).
    ///
    /// [`Outline::complete`]: crate::canvas::Outline::complete
    Incomplete,
    /// A [`TriangleList`](crate::canvas::TriangleList) has no room for
    /// another triangle.
    ListFull,
    /// A styled shape of [`draw`](crate::draw) reaches a point outside
    /// the accepted coordinate range (what [`FineCoord`](Self::FineCoord)
    /// becomes once the shape is known).
    OutOfRange {
        /// The kind of shape.
        shape: ShapeKind,
        /// A corner of the box of what it draws (fill or stroke), 1/1024
        /// px (printed in px).
        point: FinePoint,
    },
    /// An image was not drawn (its data, format or transform).
    Image(crate::image::ImageError),
    /// A text has a character its font lacks (the first one; the
    /// characters the font has were drawn, this one and any other missing
    /// one were not).
    MissingGlyph(char),
}

impl DrawError {
    /// The error named by the shape that caused it: a point out of range
    /// becomes [`OutOfRange`](Self::OutOfRange); the others stay as they
    /// are.
    pub const fn of_shape(self, shape: ShapeKind) -> Self {
        match self {
            Self::FineCoord(point) => Self::OutOfRange { shape, point },
            e => e,
        }
    }
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
                "point ({}, {}) px is outside ±{COORD_LIMIT_PX} px",
                Px::fine(p.x),
                Px::fine(p.y)
            ),
            Self::OutOfRange { shape, point: p } => write!(
                f,
                "{shape} reaches ({}, {}) px, outside ±{COORD_LIMIT_PX} px",
                Px::fine(p.x),
                Px::fine(p.y)
            ),
            Self::ListFull => f.write_str("triangle list is full"),
            Self::MissingGlyph(c) => {
                write!(f, "the font has no glyph for {c:?} (U+{:04X})", *c as u32)
            }
            Self::BadIndex => f.write_str("a mesh triangle names a point the mesh does not have"),
            Self::Stroke(e) => e.fmt(f),
            Self::Image(e) => e.fmt(f),
        }
    }
}

impl Error for DrawError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Coord(e) => Some(e),
            Self::Stroke(e) => Some(e),
            Self::Image(e) => Some(e),
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
            "vertex (-2500, 0.1875) px is outside ±2048 px"
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

    /// Pixels, not engine units: the message of issue #34's circle at
    /// x = 5000 (`point (5119984, 10224) in 1/1024 px` before), and the
    /// same point named by its shape. The decimals are checked against
    /// an `f64` division here.
    #[test]
    fn coordinates_print_in_pixels_and_name_the_shape() {
        let p = FinePoint::new(5_119_984, 10_224);
        assert_eq!(
            DrawError::FineCoord(p).to_string(),
            "point (4999.9844, 9.9844) px is outside ±2048 px"
        );
        assert_eq!(
            DrawError::FineCoord(p)
                .of_shape(ShapeKind::Circle)
                .to_string(),
            "circle reaches (4999.9844, 9.9844) px, outside ±2048 px"
        );
        assert_eq!(
            DrawError::BadIndex.of_shape(ShapeKind::Line),
            DrawError::BadIndex
        );
        for v in [
            0i64,
            1,
            -1,
            512,
            -512,
            1023,
            5_119_984,
            -2_097_153,
            i64::from(i32::MAX),
            i64::MIN,
            i64::MAX,
        ] {
            for bits in [0, 4, 10] {
                let s = Px { v, bits }.to_string();
                let back: f64 = s.parse().unwrap();
                let exact = v as f64 / f64::from(1u32 << bits);
                assert!(
                    (back - exact).abs() <= 0.5e-4 * (1.0 + exact.abs() * 1e-12),
                    "{v} / 2^{bits}: {s}"
                );
                assert!(!s.ends_with('0') || !s.contains('.'), "{s}");
            }
        }
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
