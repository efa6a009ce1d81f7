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
    pub circle: Vec<Spanned<Circle>>,
    #[serde(default)]
    pub ellipse: Vec<Spanned<Ellipse>>,
    #[serde(default)]
    pub arc: Vec<Spanned<Arc>>,
    #[serde(default)]
    pub sector: Vec<Spanned<Arc>>,
    #[serde(default)]
    pub rect: Vec<Spanned<Rect>>,
    #[serde(default)]
    pub polyline: Vec<Spanned<Polyline>>,
    #[serde(default)]
    pub path: Vec<Spanned<Path>>,
    #[serde(default)]
    pub mesh: Vec<Spanned<Mesh>>,
    #[serde(default)]
    pub text: Vec<Spanned<Text>>,
    #[serde(default)]
    pub image: Vec<Spanned<Image>>,
}

/// `[[image]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Image {
    pub path: Spanned<String>,
    pub center: Nums,
    pub scale: Option<Spanned<ScaleValue>>,
    pub rotate: Option<Num>,
    pub opacity: Option<Num>,
    pub tint: Option<Color>,
}

/// A scale: one number for both axes, or `[sx, sy]`.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub enum ScaleValue {
    One(f64),
    Two([f64; 2]),
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
    pub blend: Option<Spanned<String>>,
    pub dither: Option<Spanned<String>>,
}

/// `[[triangle]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Triangle {
    pub points: Spanned<Vec<Nums>>,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub depths: Option<Nums>,
    pub opacity: Option<Num>,
}

/// `[[polygon]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Polygon {
    pub points: Spanned<Vec<Nums>>,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub depths: Option<Nums>,
    pub opacity: Option<Num>,
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
    pub opacity: Option<Num>,
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
    pub opacity: Option<Num>,
}

/// `radius = 4` or `radius = [tl, tr, br, bl]` of a `[[rect]]`.
#[derive(Debug, Clone, PartialEq)]
pub enum RadiusValue {
    /// One radius for every corner.
    One(f64),
    /// Four, clockwise from the top left.
    Four(Vec<Num>),
}

/// A radius with its place in the file.
pub type Radius = Spanned<RadiusValue>;

impl<'de> Deserialize<'de> for RadiusValue {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = RadiusValue;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a corner radius in px, or four of them")
            }
            fn visit_f64<E>(self, v: f64) -> Result<RadiusValue, E> {
                Ok(RadiusValue::One(v))
            }
            fn visit_i64<E>(self, v: i64) -> Result<RadiusValue, E> {
                Ok(RadiusValue::One(v as f64))
            }
            fn visit_u64<E>(self, v: u64) -> Result<RadiusValue, E> {
                Ok(RadiusValue::One(v as f64))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<RadiusValue, A::Error> {
                let mut values = Vec::new();
                while let Some(v) = seq.next_element::<Num>()? {
                    values.push(v);
                }
                Ok(RadiusValue::Four(values))
            }
        }
        d.deserialize_any(V)
    }
}

/// The paint and stroke keys every shape takes, borrowed from its table.
#[derive(Debug, Clone, Copy)]
pub struct Paint<'a> {
    pub color: Option<&'a Color>,
    pub gradient: Option<&'a Spanned<Gradient>>,
    pub fill_rule: Option<&'a Spanned<String>>,
    pub stroke_color: Option<&'a Color>,
    pub stroke_width: Option<&'a Num>,
    pub join: Option<&'a Spanned<String>>,
    pub miter_limit: Option<&'a Num>,
    pub cap: Option<&'a Spanned<String>>,
    pub dash: Option<&'a Nums>,
    pub dash_offset: Option<&'a Num>,
    pub stroke_alignment: Option<&'a Spanned<String>>,
    pub opacity: Option<&'a Num>,
}

/// A shape's table: its own keys, then the paint and stroke keys.
macro_rules! shape_table {
    ($(#[$doc:meta])* $name:ident { $($(#[$a:meta])* $field:ident: $ty:ty,)* }) => {
        $(#[$doc])*
        #[derive(Debug, Deserialize)]
        #[serde(deny_unknown_fields)]
        pub struct $name {
            $($(#[$a])* pub $field: $ty,)*
            pub color: Option<Color>,
            pub gradient: Option<Spanned<Gradient>>,
            pub fill_rule: Option<Spanned<String>>,
            pub stroke_color: Option<Color>,
            pub stroke_width: Option<Num>,
            pub join: Option<Spanned<String>>,
            pub miter_limit: Option<Num>,
            pub cap: Option<Spanned<String>>,
            pub dash: Option<Nums>,
            pub dash_offset: Option<Num>,
            pub stroke_alignment: Option<Spanned<String>>,
            pub opacity: Option<Num>,
        }

        impl $name {
            /// The paint and stroke keys.
            pub fn paint(&self) -> Paint<'_> {
                Paint {
                    color: self.color.as_ref(),
                    gradient: self.gradient.as_ref(),
                    fill_rule: self.fill_rule.as_ref(),
                    stroke_color: self.stroke_color.as_ref(),
                    stroke_width: self.stroke_width.as_ref(),
                    join: self.join.as_ref(),
                    miter_limit: self.miter_limit.as_ref(),
                    cap: self.cap.as_ref(),
                    dash: self.dash.as_ref(),
                    dash_offset: self.dash_offset.as_ref(),
                    stroke_alignment: self.stroke_alignment.as_ref(),
                    opacity: self.opacity.as_ref(),
                }
            }
        }
    };
}

shape_table! {
    /// `[[circle]]`.
    Circle {
        #[serde(alias = "center")]
        centre: Nums,
        radius: Num,
    }
}

shape_table! {
    /// `[[ellipse]]`.
    Ellipse {
        #[serde(alias = "center")]
        centre: Nums,
        radii: Nums,
        rotation: Option<Num>,
    }
}

shape_table! {
    /// `[[arc]]` and `[[sector]]`.
    Arc {
        #[serde(alias = "center")]
        centre: Nums,
        radius: Num,
        start: Num,
        sweep: Num,
    }
}

shape_table! {
    /// `[[rect]]`.
    Rect {
        position: Nums,
        size: Nums,
        radius: Option<Radius>,
    }
}

shape_table! {
    /// `[[polyline]]`.
    Polyline {
        points: Spanned<Vec<Nums>>,
    }
}

shape_table! {
    /// `[[path]]`.
    Path {
        d: Spanned<String>,
    }
}

/// `[[mesh]]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Mesh {
    pub points: Spanned<Vec<Nums>>,
    pub triangles: Spanned<Vec<Spanned<Vec<Int>>>>,
    pub colors: Option<Colors>,
    pub color: Option<Color>,
    pub opacity: Option<Num>,
}

/// `gradient = { kind = "linear", from = [x, y], to = [x, y], stops = [...] }`
/// or `{ kind = "radial", centre = [x, y], radius = r, stops = [...] }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Gradient {
    pub kind: Spanned<String>,
    pub from: Option<Nums>,
    pub to: Option<Nums>,
    #[serde(alias = "center")]
    pub centre: Option<Nums>,
    pub radius: Option<Num>,
    pub stops: Spanned<Vec<Spanned<GradientStop>>>,
}

/// `{ offset = 0.5, color = "#ff8000" }`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GradientStop {
    pub offset: Num,
    pub color: Color,
}
