//! The scene file as TOML gives it: serde structs, every value spanned so
//! that the checks in [`super`] can say where a bad value is. Unknown keys
//! are rejected here (`deny_unknown_fields`); ranges, channel counts and
//! cross-field rules are checked in [`super`].

use serde::Deserialize;
use toml::Spanned;

/// A number with its place in the file.
pub type Num = Spanned<f64>;
/// An integer with its place in the file.
pub type Int = Spanned<i64>;
/// A list of numbers (a point, a vector) with its place.
pub type Nums = Spanned<Vec<Num>>;
/// A colour with its place in the file.
pub type Color = Spanned<ColorValue>;
/// A list of colours (one per vertex).
pub type Colors = Spanned<Vec<Color>>;

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct File {
    pub display: Spanned<Display>,
    pub render: Option<Spanned<Render>>,
    #[serde(default)]
    pub triangle: Vec<Spanned<Triangle>>,
    #[serde(default)]
    pub polygon: Vec<Spanned<Polygon>>,
    #[serde(default)]
    pub line: Vec<Spanned<Line>>,
    pub camera: Option<Spanned<Camera>>,
    pub light: Option<Spanned<Light>>,
    #[serde(default)]
    pub object: Vec<Spanned<Object>>,
    #[serde(default)]
    pub text: Vec<Spanned<Text>>,
}

/// `[[text]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Text {
    pub text: Spanned<String>,
    pub position: Nums,
    pub size: Num,
    pub font: Option<Spanned<String>>,
    pub align: Option<Spanned<String>>,
    pub baseline: Option<Spanned<String>>,
    pub line_height: Option<Num>,
    pub color: Option<Color>,
    pub opacity: Option<Num>,
    pub sharpen: Option<Spanned<String>>,
}

/// `[display]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Display {
    pub width: Int,
    pub height: Int,
    pub format: Spanned<String>,
    pub background: Option<Color>,
}

/// `gamma = 2.2` or `gamma = "srgb"`.
#[derive(Debug, Clone, PartialEq)]
pub enum GammaValue {
    /// A power-curve exponent.
    Power(f64),
    /// A named curve.
    Name(String),
}

impl<'de> Deserialize<'de> for GammaValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl serde::de::Visitor<'_> for V {
            type Value = GammaValue;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a display exponent such as 2.2, or \"srgb\"")
            }
            fn visit_f64<E>(self, v: f64) -> Result<GammaValue, E> {
                Ok(GammaValue::Power(v))
            }
            fn visit_i64<E>(self, v: i64) -> Result<GammaValue, E> {
                Ok(GammaValue::Power(v as f64))
            }
            fn visit_u64<E>(self, v: u64) -> Result<GammaValue, E> {
                Ok(GammaValue::Power(v as f64))
            }
            fn visit_str<E>(self, v: &str) -> Result<GammaValue, E> {
                Ok(GammaValue::Name(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

/// A colour as written: `[4095, 2048, 0]` (linear 12-bit, one value per
/// channel) or `"#rrggbb"` (sRGB, checked and converted in [`super`]).
#[derive(Debug, Clone, PartialEq)]
pub enum ColorValue {
    /// Linear 12-bit values, one per channel.
    Linear(Vec<Int>),
    /// `#rrggbb` text, sRGB.
    Hex(String),
}

impl<'de> Deserialize<'de> for ColorValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = ColorValue;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str(
                    "a colour: linear 12-bit values such as [4095, 2048, 0], or sRGB \"#rrggbb\"",
                )
            }
            fn visit_str<E>(self, v: &str) -> Result<ColorValue, E> {
                Ok(ColorValue::Hex(v.to_string()))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<ColorValue, A::Error> {
                let mut values = Vec::new();
                while let Some(v) = seq.next_element::<Int>()? {
                    values.push(v);
                }
                Ok(ColorValue::Linear(values))
            }
        }
        d.deserialize_any(V)
    }
}

/// `[render]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Render {
    pub antialias: Option<Spanned<bool>>,
    pub pixel_model: Option<Spanned<String>>,
    pub gamma: Option<Spanned<GammaValue>>,
    pub band_rows: Option<Int>,
    pub lightness_filter: Option<Spanned<bool>>,
    pub hsr: Option<Spanned<String>>,
    pub section: Option<Num>,
}

/// `[[triangle]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Triangle {
    pub points: Spanned<Vec<Nums>>,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub depths: Option<Nums>,
}

/// `[[polygon]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Polygon {
    pub points: Spanned<Vec<Nums>>,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub depths: Option<Nums>,
}

/// `[[line]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Line {
    pub from: Nums,
    pub to: Nums,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub depths: Option<Nums>,
}

/// `[camera]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Camera {
    pub projection: Spanned<String>,
    pub eye: Nums,
    pub target: Option<Nums>,
    pub up: Option<Nums>,
    pub scale: Option<Num>,
    pub fov_y: Option<Num>,
    pub near: Option<Num>,
    pub far: Option<Num>,
}

/// `[light]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Light {
    pub direction: Nums,
    pub ambient: Option<Num>,
    pub diffuse: Option<Num>,
}

/// `[[object]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Object {
    pub shape: Spanned<String>,
    pub radius: Option<Num>,
    pub minor_radius: Option<Num>,
    pub height: Option<Num>,
    pub size: Option<Nums>,
    pub segments: Option<Int>,
    pub tube_segments: Option<Int>,
    pub position: Option<Nums>,
    pub rotation: Option<Nums>,
    pub color: Color,
}
