//! Scene files: a frame described in TOML, checked, and turned into a
//! [`Scene`] for the band renderer plus the display it is shown on.
//!
//! The format is documented in the README ("Scene files"); in short:
//! `[display]` (size, pixel format, background), `[render]` (anti-aliasing,
//! pixel model, γ, band height, the lightness post-filter, dithering), 2D primitives `[[triangle]]`,
//! `[[polygon]]`, `[[line]]` in pixel units, and 3D objects `[[object]]`
//! seen by a `[camera]` and lit by a `[light]`.
//!
//! ## Decisions
//!
//! - **Colours.** A colour is linear 12-bit values (`[4095, 2048, 0]`, as
//!   the engine takes them) or `"#rrggbb"`, an sRGB colour decoded by
//!   `softedge::color`'s tables; on a one-channel display the hex form
//!   gives its linear luminance.
//! - **Order.** Primitives are accumulated in the order they appear in the
//!   file, across tables: every table is read with its byte span and the
//!   primitives are sorted by where their table starts. (Accumulation,
//!   `I_acc += I * S`, is a sum, so the order changes no pixel; it decides
//!   which primitive an error names first.) An object's triangles come at
//!   the object's place, in mesh order, after back-face culling.
//! - **Sub-pixel rounding.** Coordinates are pixels; the edge engine uses
//!   1/16 px. A coordinate that is not a multiple of 1/16 is rounded to the
//!   nearest 1/16 (halves away from zero) and a warning names it; the scene
//!   still renders.
//! - **Rejected** (an error naming file, line, column and field): unknown
//!   keys or tables, wrong types, NaN and infinities, coordinates beyond
//!   `±COORD_LIMIT_PX` (2048 px), colours outside `0..=4095`, hex colours
//!   that are not `"#rrggbb"`, a colour
//!   with the wrong number of channels (1 for gray and binary formats, 3
//!   for RGB), wrong vertex counts, sizes out of range, and anything core
//!   rejects when the primitive is drawn (a self-intersecting polygon) or
//!   the objects projected (a camera whose eye is its target).
//!
//! ```
//! use softedge_sim::scene_file::{parse, DisplayFormat, Frame};
//! let text = "[display]\nwidth = 8\nheight = 4\nformat = \"gray4\"\n\
//!             [[polygon]]\npoints = [[0, 0], [8, 0], [8, 2], [0, 2]]\ncolor = [4095]\n";
//! let file = parse(std::path::Path::new("doc.toml"), text).unwrap();
//! assert_eq!(file.format, DisplayFormat::Gray4);
//! let Frame::Gray(scene) = &file.frame else { panic!("a gray scene") };
//! assert_eq!(scene.primitives.len(), 1);
//! let lin = file.render_linear().unwrap();
//! let codes = file.tone(&lin);
//! assert_eq!(codes.bytes(), [[15u8; 8], [15; 8], [0; 8], [0; 8]].concat());
//! ```

mod diag;
mod display;
mod image;
mod objects;
mod raw;
mod shapes;
mod text;
#[cfg(feature = "window")]
pub mod window;

use std::ops::Range;
use std::path::{Path, PathBuf};

use softedge::color::LinRgb;
use softedge::hsr::DepthTriangle;
use softedge::tone::{Curve, Gamma};
use softedge::{
    Line, PixelModel, Polygon, PolygonColors, RenderStyle, SubPoint, Triangle, COORD_LIMIT_PX,
    LIN_MAX, MAX_POLYGON_VERTICES, SUB_ONE,
};
use toml::Spanned;

pub use diag::{Diagnostic, Severity};
pub use display::{pnm16, DisplayCodes, Linear};

use crate::scene::{draw_error_text, Hsr, PolyColors, Primitive, RenderError, Scene};
use crate::shape_item::MeshItem;
use diag::Source;
use softedge::style::{Blend, Opacity};

/// Largest frame side, pixels (the band buffer's limit).
pub const MAX_SIDE: i64 = softedge::band::MAX_WIDTH as i64;

/// Most `[[object]]` tables in a scene file. Each object is meshed and
/// projected on its own (its mesh and projection scratch, up to 65 536
/// vertices, are freed before the next); what stays is its triangles,
/// bounded by [`MAX_TRIANGLES`].
pub const MAX_OBJECTS: usize = 256;

/// Most triangles a scene file's frame may hold, counted as the file is
/// read: one per `[[triangle]]`, `n - 2` per polygon of `n` points, two
/// per line, and an object's whole mesh before back-face culling. At about
/// 110 bytes per triangle kept (the scene's primitive, its source index
/// and, with `hsr`, the sorted depth triangle and its index) that bounds
/// a frame's geometry at about 60 MB.
pub const MAX_TRIANGLES: usize = 1 << 19;

/// The pixel format of the display a scene is shown on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum DisplayFormat {
    /// 16-bit RGB 5-6-5.
    Rgb565,
    /// 24-bit RGB.
    Rgb888,
    /// 8-bit gray.
    Gray8,
    /// 4-bit gray.
    Gray4,
    /// 1 bit per pixel, Floyd–Steinberg dithered in linear light.
    Binary,
}

/// `[render] dither`: the tone stage's dithering of a multi-bit display.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Dither {
    /// Each pixel rounded to the nearest code (`softedge::tone::format`).
    #[default]
    None,
    /// Ordered dithering of the γ code over a 4x4 Bayer tile
    /// (`softedge::tone::ordered`): rgb565 and gray4 only.
    Ordered,
}

impl DisplayFormat {
    /// The name used in scene files.
    pub fn name(self) -> &'static str {
        match self {
            Self::Rgb565 => "rgb565",
            Self::Rgb888 => "rgb888",
            Self::Gray8 => "gray8",
            Self::Gray4 => "gray4",
            Self::Binary => "binary",
        }
    }

    /// All formats.
    pub const ALL: [Self; 5] = [
        Self::Rgb565,
        Self::Rgb888,
        Self::Gray8,
        Self::Gray4,
        Self::Binary,
    ];

    /// Colour channels of the scene's values: 3 for RGB, 1 otherwise.
    pub fn channels(self) -> usize {
        match self {
            Self::Rgb565 | Self::Rgb888 => 3,
            Self::Gray8 | Self::Gray4 | Self::Binary => 1,
        }
    }
}

/// The scene of a file, with its channel count.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Frame {
    /// One channel (gray formats, binary).
    Gray(Scene<1>),
    /// Three channels (RGB formats).
    Rgb(Scene<3>),
}

/// Where primitives of the scene came from, for error messages: one
/// table of the file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Origin {
    /// Its field path, `polygon[2]` or `object[0]`.
    pub field: String,
    /// Its table's byte span in the file.
    pub span: Range<usize>,
}

/// A checked scene file.
#[derive(Debug, Clone)]
pub struct SceneFile {
    /// The file.
    pub path: PathBuf,
    /// The file's text (for locating render errors).
    text: String,
    /// The display's pixel format.
    pub format: DisplayFormat,
    /// The display's transfer curve (the γ table sends its inverse).
    pub curve: Curve,
    /// `[render] lightness_filter`: run the CIELAB L* filter of seed 002
    /// between accumulation and tone.
    pub lightness_filter: bool,
    /// `[render] dither`.
    pub dither: Dither,
    /// The frame, ready for [`crate::scene::render`].
    pub frame: Frame,
    /// The tables the primitives of `frame` came from, in file order.
    pub origins: Vec<Origin>,
    /// For each primitive of `frame`, the index of its table in `origins`
    /// (an object's thousands of triangles share one [`Origin`]).
    pub primitive_origins: Vec<u32>,
    /// Warnings (coordinates rounded to 1/16 px).
    pub warnings: Vec<Diagnostic>,
    /// Spans for errors found when rendering: `[display]`, `[render] hsr`.
    display_span: Range<usize>,
    hsr_span: Option<Range<usize>>,
}

/// A pixel model's name in scene files (`[render] pixel_model`) and on
/// the command line (the bench's `model-<name>` frames).
pub fn model_name(model: PixelModel) -> &'static str {
    match model {
        PixelModel::Box => "box",
        PixelModel::BoxSeed => "box-seed",
        PixelModel::BedOfNails4 => "bed4",
        PixelModel::BedOfNails8 => "bed8",
        PixelModel::Hex7 => "hex7",
        PixelModel::Hex19 => "hex19",
        PixelModel::Cone => "cone",
        PixelModel::Gaussian => "gauss",
        PixelModel::Hamming => "hamming",
        // `PixelModel` is non-exhaustive; a model added to the core without
        // a name here fails `every_pixel_model_has_its_own_name`.
        _ => "?",
    }
}

/// The pixel model named `name` ([`model_name`]), if any.
pub fn model_named(name: &str) -> Option<PixelModel> {
    PixelModel::ALL.into_iter().find(|&m| model_name(m) == name)
}

/// Reads and checks a scene file; an unreadable file is a diagnostic
/// without a line.
pub fn load(path: &Path) -> Result<SceneFile, Diagnostic> {
    let text = std::fs::read_to_string(path).map_err(|e| Diagnostic {
        severity: Severity::Error,
        path: path.to_path_buf(),
        line: 0,
        column: 0,
        field: String::new(),
        message: format!("cannot read the scene file: {e}"),
    })?;
    parse(path, &text)
}

/// Checks the scene `text` of the file `path` (used in messages only).
pub fn parse(path: &Path, text: &str) -> Result<SceneFile, Diagnostic> {
    let src = Source { path, text };
    let file: raw::File = toml::from_str(text).map_err(|e| src.toml_error(&e))?;
    let mut ck = Checker {
        src: src.clone(),
        warnings: Vec::new(),
        triangles: 0,
    };
    let format = ck.format(&file.display.get_ref().format)?;
    let (style, curve, band_rows) = ck.render(file.render.as_ref())?;
    let lightness_filter = file
        .render
        .as_ref()
        .and_then(|r| r.get_ref().lightness_filter.as_ref())
        .is_some_and(|f| *f.get_ref());
    let (hsr, section) = ck.hsr(file.render.as_ref())?;
    let dither = ck.dither(file.render.as_ref(), format)?;
    let d = file.display.get_ref();
    let width = ck.int(&d.width, "display.width", 1, MAX_SIDE)? as u16;
    let height = ck.int(&d.height, "display.height", 1, MAX_SIDE)? as u16;
    let (frame, (origins, primitive_origins)) = match format.channels() {
        1 => {
            let (mut s, o) = ck.scene::<1>(&file, width, height, band_rows, style)?;
            (s.hsr, s.section) = (hsr, section);
            (Frame::Gray(s), o)
        }
        _ => {
            let (mut s, o) = ck.scene::<3>(&file, width, height, band_rows, style)?;
            (s.hsr, s.section) = (hsr, section);
            (Frame::Rgb(s), o)
        }
    };
    let hsr_span = file
        .render
        .as_ref()
        .and_then(|r| r.get_ref().hsr.as_ref())
        .map(|h| h.span());
    Ok(SceneFile {
        path: path.to_path_buf(),
        text: text.to_string(),
        format,
        curve,
        lightness_filter,
        dither,
        frame,
        origins,
        primitive_origins,
        warnings: ck.warnings,
        display_span: file.display.span(),
        hsr_span,
    })
}

impl SceneFile {
    /// The file name without its extension (for `crc`).
    pub fn stem(&self) -> String {
        self.path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    }

    /// Width and height in pixels.
    pub fn size(&self) -> (u16, u16) {
        match &self.frame {
            Frame::Gray(s) => (s.width, s.height),
            Frame::Rgb(s) => (s.width, s.height),
        }
    }

    /// Renders the frame band by band ([`crate::scene::render`]): the
    /// linear 12-bit values the tone stage receives. With
    /// [`lightness_filter`](Self::lightness_filter) on, that is the output
    /// of the filter ([`crate::scene::render_lightness_filtered`]). A
    /// primitive that core rejects is reported at its place in the file.
    pub fn render_linear(&self) -> Result<Linear, Diagnostic> {
        use crate::scene::{render, render_lightness_filtered as filtered};
        let out = match (&self.frame, self.lightness_filter) {
            (Frame::Gray(s), false) => render(s).map(Linear::Gray),
            (Frame::Rgb(s), false) => render(s).map(Linear::Rgb),
            (Frame::Gray(s), true) => filtered(s).map(|(img, _)| Linear::Gray(img)),
            (Frame::Rgb(s), true) => filtered(s).map(|(img, _)| Linear::Rgb(img)),
        };
        out.map_err(|e| self.render_error(e))
    }

    /// The display codes of a rendered frame, through `softedge::tone`.
    pub fn tone(&self, lin: &Linear) -> DisplayCodes {
        display::tone(lin, self.format, self.curve, self.dither)
    }

    /// The table primitive `index` of the frame came from.
    pub fn origin_of(&self, index: usize) -> Option<&Origin> {
        let k = *self.primitive_origins.get(index)?;
        self.origins.get(k as usize)
    }

    fn render_error(&self, e: RenderError) -> Diagnostic {
        let src = Source {
            path: &self.path,
            text: &self.text,
        };
        // An error about a primitive is placed at its table; one about the
        // frame at `[render] hsr` (or `[display]` for the frame's size).
        let hsr_at = || {
            self.hsr_span
                .clone()
                .map_or((self.display_span.clone(), "display"), |s| {
                    (s, "render.hsr")
                })
        };
        let at_primitive =
            |index: Option<usize>, message: String| match index.and_then(|i| self.origin_of(i)) {
                Some(o) => src.error(o.span.clone(), o.field.clone(), message),
                None => {
                    let (span, field) = hsr_at();
                    src.error(span, field, message)
                }
            };
        match e {
            RenderError::Draw { index, error } => at_primitive(Some(index), draw_error_text(error)),
            RenderError::Hsr {
                method,
                index,
                error,
            } => at_primitive(index, crate::scene::hsr_error_text(method, error)),
            RenderError::TooManyTriangles {
                method,
                index,
                count,
                limit,
            } => at_primitive(
                Some(index),
                format!(
                    "hsr = \"{}\" takes at most {limit} triangles per frame, and this one \
                     reaches {count} here (its work grows with the square of the count): \
                     use fewer or coarser objects, or hsr = \"zbuffer\"",
                    method.name()
                ),
            ),
            RenderError::Band { .. } | RenderError::Filter(_) => {
                src.error(self.display_span.clone(), "display", e.to_string())
            }
        }
    }
}

/// The primitives of one entry at `opacity` (unchanged when opaque).
fn faded<const C: usize>(prims: Vec<Primitive<C>>, opacity: Opacity) -> Vec<Primitive<C>> {
    if opacity == Opacity::OPAQUE {
        return prims;
    }
    prims
        .into_iter()
        .map(|p| Primitive::Faded(Box::new(p), opacity))
        .collect()
}

/// An entry of several triangles (each perhaps faded alike) as one mesh
/// of their vertices, so that painter's order composes it as one shape.
fn as_one_mesh<const C: usize>(prims: Vec<Primitive<C>>) -> Vec<Primitive<C>> {
    if prims.len() < 2 {
        return prims;
    }
    let mut opacity = None;
    let mut mesh = MeshItem {
        points: Vec::new(),
        triangles: Vec::new(),
        colors: PolyColors::PerVertex(Vec::new()),
        opacity: Opacity::OPAQUE,
    };
    for p in &prims {
        let (t, a) = match p {
            Primitive::Faded(q, a) => (&**q, *a),
            q => (q, Opacity::OPAQUE),
        };
        let t = match t {
            Primitive::Triangle(t) => *t,
            Primitive::Depth(t) => t.triangle(),
            _ => return prims,
        };
        if *opacity.get_or_insert(a) != a || mesh.points.len() > usize::from(u16::MAX) - 3 {
            return prims;
        }
        let k = mesh.points.len() as u16;
        mesh.points.extend(t.vertices);
        if let PolyColors::PerVertex(cs) = &mut mesh.colors {
            cs.extend(t.colors);
        }
        mesh.triangles.push([k, k + 1, k + 2]);
    }
    mesh.opacity = opacity.unwrap_or(Opacity::OPAQUE);
    vec![Primitive::Mesh(Box::new(mesh))]
}

/// A depth in `0..=1` (larger is nearer) as a 16-bit depth, rounded.
fn depth_code(z: f64) -> u16 {
    (z * f64::from(u16::MAX)).round() as u16
}

/// The checks, with the source for locating errors and the warnings so far.
struct Checker<'a> {
    src: Source<'a>,
    warnings: Vec<Diagnostic>,
    /// Triangles of the frame so far (see [`MAX_TRIANGLES`]).
    triangles: usize,
}

type Checked<T> = Result<T, Diagnostic>;

/// The tables of a scene, and the table of each primitive.
type Origins = (Vec<Origin>, Vec<u32>);

impl Checker<'_> {
    fn err<T>(&self, span: Range<usize>, field: &str, message: impl Into<String>) -> Checked<T> {
        Err(self.src.error(span, field, message))
    }

    /// Counts `n` more triangles of the entry `field` (at `span`) towards
    /// [`MAX_TRIANGLES`].
    fn count_triangles(&mut self, n: usize, span: Range<usize>, field: &str) -> Checked<()> {
        let total = self.triangles.saturating_add(n);
        if total > MAX_TRIANGLES {
            return self.err(
                span,
                field,
                format!(
                    "the frame would have {total} triangles with this one's {n}, more than \
                     the {MAX_TRIANGLES} a scene file may have (about {} MB of geometry); \
                     use fewer segments or objects",
                    MAX_TRIANGLES * 110 / 1_000_000
                ),
            );
        }
        self.triangles = total;
        Ok(())
    }

    fn int(&self, v: &raw::Int, field: &str, lo: i64, hi: i64) -> Checked<i64> {
        let x = *v.get_ref();
        if (lo..=hi).contains(&x) {
            Ok(x)
        } else {
            self.err(v.span(), field, format!("{x} is outside {lo}..={hi}"))
        }
    }

    /// A finite number within `lo..=hi`.
    fn num(&self, v: &raw::Num, field: &str, lo: f64, hi: f64) -> Checked<f64> {
        let x = *v.get_ref();
        if !x.is_finite() {
            return self.err(v.span(), field, format!("{x} is not a finite number"));
        }
        if !(lo..=hi).contains(&x) {
            return self.err(v.span(), field, format!("{x} is outside {lo}..={hi}"));
        }
        Ok(x)
    }

    /// Exactly `N` finite numbers, each within `lo..=hi`.
    fn nums<const N: usize>(
        &self,
        v: &raw::Nums,
        field: &str,
        lo: f64,
        hi: f64,
    ) -> Checked<[f64; N]> {
        let list = v.get_ref();
        if list.len() != N {
            return self.err(
                v.span(),
                field,
                format!("takes {N} numbers, not {}", list.len()),
            );
        }
        let mut out = [0.0; N];
        for (k, (o, x)) in out.iter_mut().zip(list).enumerate() {
            *o = self.num(x, &format!("{field}[{k}]"), lo, hi)?;
        }
        Ok(out)
    }

    /// A point in pixels to 1/16 px: range checked, rounded with a warning.
    fn point(&mut self, v: &raw::Nums, field: &str) -> Checked<SubPoint> {
        let lim = f64::from(COORD_LIMIT_PX);
        let [x, y] = self.nums::<2>(v, field, -lim, lim)?;
        let sub = |p: f64| (p * f64::from(SUB_ONE)).round();
        let (sx, sy) = (sub(x), sub(y));
        if sx != x * f64::from(SUB_ONE) || sy != y * f64::from(SUB_ONE) {
            let one = f64::from(SUB_ONE);
            let w = self.src.at(
                Severity::Warning,
                v.span(),
                field,
                format!(
                    "[{x}, {y}] is not on the 1/16 px grid; rounded to [{}, {}]",
                    sx / one,
                    sy / one
                ),
            );
            self.warnings.push(w);
        }
        Ok(SubPoint::new(sx as i32, sy as i32))
    }

    fn points(&mut self, v: &Spanned<Vec<raw::Nums>>, field: &str) -> Checked<Vec<SubPoint>> {
        v.get_ref()
            .iter()
            .enumerate()
            .map(|(k, p)| self.point(p, &format!("{field}[{k}]")))
            .collect()
    }

    /// A colour of `C` channels: linear 12-bit values as written, or
    /// `"#rrggbb"` sRGB decoded by `softedge::color` (on one channel, its
    /// linear luminance).
    fn color<const C: usize>(&self, v: &raw::Color, field: &str) -> Checked<[u16; C]> {
        let list = match v.get_ref() {
            raw::ColorValue::Linear(list) => list,
            raw::ColorValue::Hex(text) => return self.hex_color::<C>(text, v.span(), field),
        };
        if list.len() != C {
            let why = if C == 1 {
                "this display format has one channel (gray)"
            } else {
                "this display format has three channels (R, G, B)"
            };
            return self.err(
                v.span(),
                field,
                format!("a colour takes {C} value(s), not {}: {why}", list.len()),
            );
        }
        let mut out = [0u16; C];
        for (k, (o, c)) in out.iter_mut().zip(list).enumerate() {
            *o = self.int(c, &format!("{field}[{k}]"), 0, i64::from(LIN_MAX))? as u16;
        }
        Ok(out)
    }

    /// `"#rrggbb"`: sRGB to linear 12-bit through `softedge::color`'s
    /// tables; the luminance on a one-channel display.
    fn hex_color<const C: usize>(
        &self,
        text: &str,
        span: Range<usize>,
        field: &str,
    ) -> Checked<[u16; C]> {
        let rgb = match LinRgb::from_hex(text) {
            Ok(c) => c,
            Err(e) => return self.err(span, field, format!("\"{text}\": {e}")),
        };
        let values = if C == 1 {
            rgb.luminance().lin12().to_vec()
        } else {
            rgb.lin12().to_vec()
        };
        let mut out = [0u16; C];
        for (o, v) in out.iter_mut().zip(values) {
            *o = v;
        }
        Ok(out)
    }

    /// Per-vertex colours (`colors`, `n` of them) or one (`color`).
    fn vertex_colors<const C: usize>(
        &self,
        colors: Option<&raw::Colors>,
        color: Option<&raw::Color>,
        n: usize,
        field: &str,
        span: Range<usize>,
    ) -> Checked<PolyColors<C>> {
        match (colors, color) {
            (Some(_), Some(c)) => self.err(
                c.span(),
                &format!("{field}.color"),
                "give either `color` (one for all vertices) or `colors` (one per vertex), not both",
            ),
            (None, None) => self.err(
                span,
                field,
                "needs `color` (one for all vertices) or `colors` (one per vertex)",
            ),
            (None, Some(c)) => Ok(PolyColors::Flat(
                self.color::<C>(c, &format!("{field}.color"))?,
            )),
            (Some(cs), None) => {
                let list = cs.get_ref();
                if list.len() != n {
                    return self.err(
                        cs.span(),
                        &format!("{field}.colors"),
                        format!("{} colours for {n} vertices", list.len()),
                    );
                }
                let cols = list
                    .iter()
                    .enumerate()
                    .map(|(k, c)| self.color::<C>(c, &format!("{field}.colors[{k}]")))
                    .collect::<Checked<Vec<_>>>()?;
                Ok(PolyColors::PerVertex(cols))
            }
        }
    }

    fn format(&self, f: &Spanned<String>) -> Checked<DisplayFormat> {
        match DisplayFormat::ALL.iter().find(|x| x.name() == f.get_ref()) {
            Some(x) => Ok(*x),
            None => self.err(
                f.span(),
                "display.format",
                format!(
                    "unknown format `{}`; one of rgb565, rgb888, gray8, gray4, binary",
                    f.get_ref()
                ),
            ),
        }
    }

    /// `[render]`: style, curve, band rows (defaults: anti-aliased box, γ 2.2,
    /// 16 rows).
    fn render(&self, r: Option<&Spanned<raw::Render>>) -> Checked<(RenderStyle, Curve, u16)> {
        let mut style = RenderStyle::default();
        let mut curve = Curve::GAMMA_2_2;
        let mut rows = 16u16;
        let Some(r) = r.map(Spanned::get_ref) else {
            return Ok((style, curve, rows));
        };
        if let Some(a) = &r.antialias {
            style.antialias = *a.get_ref();
        }
        if let Some(m) = &r.pixel_model {
            let name = m.get_ref().as_str();
            style.model = match model_named(name) {
                Some(model) => model,
                None => {
                    let names: Vec<&str> = PixelModel::ALL.iter().map(|&m| model_name(m)).collect();
                    return self.err(
                        m.span(),
                        "render.pixel_model",
                        format!("unknown pixel model `{name}`; one of {}", names.join(", ")),
                    );
                }
            };
        }
        if let Some(g) = &r.gamma {
            curve = match g.get_ref() {
                raw::GammaValue::Name(n) if n == "srgb" => Curve::Srgb,
                raw::GammaValue::Name(n) => {
                    return self.err(
                        g.span(),
                        "render.gamma",
                        format!("unknown curve `{n}`; a number in 1.0..=5.0 or \"srgb\""),
                    )
                }
                raw::GammaValue::Power(x) => {
                    let x = *x;
                    if !x.is_finite() || !(1.0..=5.0).contains(&x) {
                        return self.err(
                            g.span(),
                            "render.gamma",
                            format!("{x} is not a display exponent in 1.0..=5.0"),
                        );
                    }
                    // γ as a ratio over 1000 (reduced by Gamma::new).
                    const DEN: u16 = 1000;
                    let num = (x * f64::from(DEN)).round() as u16;
                    Curve::Power(Gamma::new(num, DEN).unwrap_or(Gamma::G2_2))
                }
            };
        }
        if let Some(b) = &r.band_rows {
            rows = self.int(b, "render.band_rows", 1, MAX_SIDE)? as u16;
        }
        Ok((style, curve, rows))
    }

    /// `[render] dither` (default: none; `ordered` on rgb565 and gray4).
    fn dither(&self, r: Option<&Spanned<raw::Render>>, format: DisplayFormat) -> Checked<Dither> {
        let Some(d) = r.and_then(|r| r.get_ref().dither.as_ref()) else {
            return Ok(Dither::None);
        };
        match (d.get_ref().as_str(), format) {
            ("none", _) => Ok(Dither::None),
            ("ordered", DisplayFormat::Rgb565 | DisplayFormat::Gray4) => Ok(Dither::Ordered),
            ("ordered", f) => self.err(
                d.span(),
                "render.dither",
                format!(
                    "ordered dithering is for rgb565 and gray4 displays, not {}",
                    f.name()
                ),
            ),
            (other, _) => self.err(
                d.span(),
                "render.dither",
                format!("unknown dither `{other}`; one of none, ordered"),
            ),
        }
    }

    /// `[render] blend` (default: over).
    fn blend(&self, r: Option<&Spanned<raw::Render>>) -> Checked<Blend> {
        let b = r.and_then(|r| r.get_ref().blend.as_ref());
        let Some(b) = b else {
            return Ok(Blend::Over);
        };
        match b.get_ref().as_str() {
            "over" => Ok(Blend::Over),
            "add" => Ok(Blend::Add),
            other => self.err(
                b.span(),
                "render.blend",
                format!("unknown blend `{other}`; one of over, add"),
            ),
        }
    }

    /// `[render] hsr` and `section` (defaults: none, off).
    fn hsr(&self, r: Option<&Spanned<raw::Render>>) -> Checked<(Hsr, Option<u16>)> {
        let Some(r) = r.map(Spanned::get_ref) else {
            return Ok((Hsr::None, None));
        };
        let hsr = match &r.hsr {
            None => Hsr::None,
            Some(m) => match m.get_ref().as_str() {
                "none" => Hsr::None,
                "zbuffer" => Hsr::ZBuffer,
                "weiler-atherton" => Hsr::WeilerAtherton,
                "warnock" => Hsr::Warnock,
                other => {
                    return self.err(
                        m.span(),
                        "render.hsr",
                        format!(
                        "unknown method `{other}`; one of none, zbuffer, warnock, weiler-atherton"
                    ),
                    )
                }
            },
        };
        let section = match &r.section {
            None => None,
            Some(z) => Some(depth_code(self.num(z, "render.section", 0.0, 1.0)?)),
        };
        Ok((hsr, section))
    }

    /// `depths = [z0, z1, ...]`: one number in `0..=1` per vertex (larger
    /// is nearer), as 16-bit depths.
    fn depths(&self, v: &raw::Nums, field: &str, count: usize) -> Checked<Vec<u16>> {
        let list = v.get_ref();
        if list.len() != count {
            return self.err(
                v.span(),
                field,
                format!("takes one depth per point: {count}, not {}", list.len()),
            );
        }
        list.iter()
            .enumerate()
            .map(|(k, z)| {
                Ok(depth_code(self.num(
                    z,
                    &format!("{field}[{k}]"),
                    0.0,
                    1.0,
                )?))
            })
            .collect()
    }

    /// Everything drawn, in file order.
    fn scene<const C: usize>(
        &mut self,
        file: &raw::File,
        width: u16,
        height: u16,
        band_rows: u16,
        style: RenderStyle,
    ) -> Checked<(Scene<C>, Origins)> {
        let background = match &file.display.get_ref().background {
            Some(b) => self.color::<C>(b, "display.background")?,
            None => [0; C],
        };
        let mut items: Vec<(Origin, Vec<Primitive<C>>)> = Vec::new();
        for (k, t) in file.triangle.iter().enumerate() {
            let field = format!("triangle[{k}]");
            let tr = t.get_ref();
            let pts = self.points(&tr.points, &format!("{field}.points"))?;
            let [a, b, c] = pts[..] else {
                return self.err(
                    tr.points.span(),
                    &format!("{field}.points"),
                    format!("a triangle has 3 points, not {}", pts.len()),
                );
            };
            let colors = match self.vertex_colors::<C>(
                tr.colors.as_ref(),
                tr.color.as_ref(),
                3,
                &field,
                t.span(),
            )? {
                PolyColors::Flat(c) => [c; 3],
                PolyColors::PerVertex(cs) => [cs[0], cs[1], cs[2]],
            };
            self.count_triangles(1, t.span(), &field)?;
            let p = match &tr.depths {
                None => Primitive::Triangle(Triangle::new([a, b, c], colors)),
                Some(d) => {
                    let z = self.depths(d, &format!("{field}.depths"), 3)?;
                    Primitive::Depth(DepthTriangle::new([a, b, c], colors, [z[0], z[1], z[2]]))
                }
            };
            let op = self.opacity(tr.opacity.as_ref(), &format!("{field}.opacity"))?;
            items.push((
                Origin {
                    field,
                    span: t.span(),
                },
                faded(vec![p], op),
            ));
        }
        for (k, p) in file.polygon.iter().enumerate() {
            let field = format!("polygon[{k}]");
            let pr = p.get_ref();
            let pts = self.points(&pr.points, &format!("{field}.points"))?;
            if !(3..=MAX_POLYGON_VERTICES).contains(&pts.len()) {
                return self.err(
                    pr.points.span(),
                    &format!("{field}.points"),
                    format!(
                        "a polygon has 3..={MAX_POLYGON_VERTICES} points, not {}",
                        pts.len()
                    ),
                );
            }
            self.count_triangles(pts.len() - 2, p.span(), &field)?;
            let colors = self.vertex_colors::<C>(
                pr.colors.as_ref(),
                pr.color.as_ref(),
                pts.len(),
                &field,
                p.span(),
            )?;
            let prims = match &pr.depths {
                None => vec![Primitive::Polygon {
                    vertices: pts,
                    colors,
                }],
                Some(d) => {
                    let z = self.depths(d, &format!("{field}.depths"), pts.len())?;
                    let cs = match &colors {
                        PolyColors::Flat(c) => PolygonColors::Flat(*c),
                        PolyColors::PerVertex(cs) => PolygonColors::PerVertex(cs),
                    };
                    let mut tris = Vec::new();
                    Polygon::new(&pts, cs)
                        .depth_triangles(&z, |t| tris.push(Primitive::Depth(t)))
                        .or_else(|e| self.err(p.span(), &field, draw_error_text(e)))?;
                    tris
                }
            };
            let op = self.opacity(pr.opacity.as_ref(), &format!("{field}.opacity"))?;
            items.push((
                Origin {
                    field,
                    span: p.span(),
                },
                faded(prims, op),
            ));
        }
        for (k, l) in file.line.iter().enumerate() {
            let field = format!("line[{k}]");
            let lr = l.get_ref();
            let from = self.point(&lr.from, &format!("{field}.from"))?;
            let to = self.point(&lr.to, &format!("{field}.to"))?;
            let colors = match self.vertex_colors::<C>(
                lr.colors.as_ref(),
                lr.color.as_ref(),
                2,
                &field,
                l.span(),
            )? {
                PolyColors::Flat(c) => [c; 2],
                PolyColors::PerVertex(cs) => [cs[0], cs[1]],
            };
            self.count_triangles(2, l.span(), &field)?;
            let line = Line::new(from, to, colors);
            let p = match &lr.depths {
                None => Primitive::Line(line),
                Some(d) => {
                    let z = self.depths(d, &format!("{field}.depths"), 2)?;
                    Primitive::DepthLine(line, [z[0], z[1]])
                }
            };
            let op = self.opacity(lr.opacity.as_ref(), &format!("{field}.opacity"))?;
            items.push((
                Origin {
                    field,
                    span: l.span(),
                },
                faded(vec![p], op),
            ));
        }
        // Section mode cuts through back faces too; everything else culls them.
        let section = file
            .render
            .as_ref()
            .is_some_and(|r| r.get_ref().section.is_some());
        let faces = if section {
            softedge::scene3d::Faces::Both
        } else {
            softedge::scene3d::Faces::Front
        };
        items.extend(objects::objects::<C>(self, file, width, height, faces)?);
        items.extend(shapes::shapes::<C>(self, file)?);
        items.extend(text::texts::<C>(self, file)?);
        items.extend(image::images::<C>(self, file)?);
        // File order across tables (a stable sort keeps ties as read).
        items.sort_by_key(|(o, _)| o.span.start);
        let blend = self.blend(file.render.as_ref())?;
        let (hsr, section) = self.hsr(file.render.as_ref())?;
        // In painter's order an entry made of several triangles (a 3D
        // object, a polygon with depths) is one shape: its triangles become
        // one mesh, its opacity the mesh's.
        let one_shape = blend == Blend::Over && hsr == Hsr::None && section.is_none();
        let mut scene = Scene::new(width, height, background);
        scene.band_rows = band_rows;
        scene.style = style;
        scene.blend = blend;
        let mut origins = Vec::with_capacity(items.len());
        let mut primitive_origins = Vec::new();
        for (k, (origin, prims)) in items.into_iter().enumerate() {
            let mut prims = prims;
            if let Some(j) = origin
                .field
                .strip_prefix("object[")
                .and_then(|r| r.strip_suffix(']'))
            {
                let o = j.parse::<usize>().ok().and_then(|j| file.object.get(j));
                if let Some(o) = o {
                    let op = self.opacity(
                        o.get_ref().opacity.as_ref(),
                        &format!("{}.opacity", origin.field),
                    )?;
                    prims = faded(prims, op);
                }
            }
            if one_shape {
                prims = as_one_mesh(prims);
            }
            // At most MAX_TRIANGLES primitives and tables: k fits.
            let k = k as u32;
            primitive_origins.extend(std::iter::repeat_n(k, prims.len()));
            scene.primitives.extend(prims);
            origins.push(origin);
        }
        Ok((scene, (origins, primitive_origins)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_str(text: &str) -> Checked<SceneFile> {
        parse(Path::new("t.toml"), text)
    }

    const HEAD: &str = "[display]\nwidth = 16\nheight = 8\nformat = \"gray8\"\n";

    /// Every model of the core has a scene-file name of its own, which
    /// reads back as that model (through a scene file too), and the
    /// gallery a label.
    #[test]
    fn every_pixel_model_has_its_own_name() {
        let names: Vec<&str> = PixelModel::ALL.iter().map(|&m| model_name(m)).collect();
        for (i, &m) in PixelModel::ALL.iter().enumerate() {
            let name = model_name(m);
            assert_ne!(name, "?", "{m:?} has no scene-file name");
            assert!(!names[..i].contains(&name), "{name} twice");
            assert_eq!(model_named(name), Some(m));
            let text = format!("{HEAD}[render]\npixel_model = \"{name}\"\n");
            let file = parse_str(&text).unwrap_or_else(|e| panic!("{name}: {e:?}"));
            let Frame::Gray(scene) = &file.frame else {
                panic!("{name}: a gray8 display gives a one-channel frame");
            };
            assert_eq!(scene.style.model, m, "{name}");
        }
        assert_eq!(model_named("nearest"), None);
        let bad = parse_str(&format!("{HEAD}[render]\npixel_model = \"nearest\"\n"));
        assert!(bad.is_err());
    }

    #[test]
    fn primitives_keep_file_order_across_tables() {
        let text = format!(
            "{HEAD}[[line]]\nfrom = [0, 0]\nto = [4, 4]\ncolor = [1]\n\
             [[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = [2]\n\
             [[line]]\nfrom = [1, 0]\nto = [5, 4]\ncolor = [3]\n"
        );
        let f = parse_str(&text).unwrap();
        let fields: Vec<_> = (0..3)
            .map(|k| f.origin_of(k).unwrap().field.as_str())
            .collect();
        assert_eq!(fields, ["line[0]", "triangle[0]", "line[1]"]);
    }

    #[test]
    fn off_grid_coordinates_are_rounded_with_a_warning() {
        let text =
            format!("{HEAD}[[triangle]]\npoints = [[0.1, 0], [4, 0], [0, 4]]\ncolor = [2]\n");
        let f = parse_str(&text).unwrap();
        assert_eq!(f.warnings.len(), 1);
        assert_eq!(f.warnings[0].field, "triangle[0].points[0]");
        assert_eq!(f.warnings[0].line, 6);
        let Frame::Gray(s) = &f.frame else { panic!() };
        let Primitive::Triangle(t) = &s.primitives[0] else {
            panic!()
        };
        assert_eq!(t.vertices[0], SubPoint::new(2, 0)); // 0.1 * 16 = 1.6 -> 2
    }

    /// A pale RGB scene with the lightness filter on, in bands of `rows`.
    fn filtered_scene(rows: u16, antialias: bool) -> SceneFile {
        let text = format!(
            "[display]\nwidth = 37\nheight = 29\nformat = \"rgb888\"\nbackground = [2600, 2450, 2200]\n\
             [render]\nlightness_filter = true\nband_rows = {rows}\nantialias = {}\n\
             [[triangle]]\npoints = [[2.25, 1.5], [35.75, 9.0], [8.5, 27.25]]\n\
             colors = [[4095, 3500, 800], [700, 3900, 3900], [3900, 1400, 3900]]\n\
             [[line]]\nfrom = [0.5, 28.0]\nto = [36.5, 0.75]\ncolors = [[4095, 1000, 1000], [1000, 4095, 1000]]\n\
             [[polygon]]\npoints = [[20, 18], [34, 16], [30, 27]]\ncolor = [4095, 4095, 1200]\n",
            antialias
        );
        parse_str(&text).unwrap()
    }

    #[test]
    fn lightness_filter_output_is_the_same_for_every_band_height() {
        // 29 is the full height.
        for antialias in [true, false] {
            let full = filtered_scene(29, antialias).render_linear().unwrap();
            for rows in [1, 7, 16] {
                let f = filtered_scene(rows, antialias);
                assert!(f.lightness_filter);
                assert!(
                    f.render_linear().unwrap() == full,
                    "band rows {rows}, antialias {antialias}"
                );
            }
        }
    }

    #[test]
    fn lightness_filter_is_off_by_default_and_changes_the_frame_when_on() {
        let on = filtered_scene(16, true);
        let mut off = on.clone();
        off.lightness_filter = false;
        assert!(!parse_str(HEAD).unwrap().lightness_filter);
        assert_ne!(on.render_linear().unwrap(), off.render_linear().unwrap());
    }

    #[test]
    fn hex_colours_are_srgb_and_their_luminance_on_gray() {
        // sRGB 0x80 is 884 / 4095 of the light; red's luminance 0.2126 * 4095.
        let rgb =
            "[display]\nwidth = 4\nheight = 4\nformat = \"rgb565\"\nbackground = \"#ff8000\"\n\
                   [[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\n\
                   colors = [\"#808080\", [1, 2, 3], \"#FF0000\"]\n\
                   [[line]]\nfrom = [0, 0]\nto = [4, 4]\ncolor = \"#000000\"\n";
        let f = parse_str(rgb).unwrap();
        let Frame::Rgb(s) = &f.frame else { panic!() };
        assert_eq!(s.background, [4095, 884, 0]);
        let Primitive::Triangle(t) = &s.primitives[0] else {
            panic!()
        };
        assert_eq!(t.colors, [[884; 3], [1, 2, 3], [4095, 0, 0]]);
        let gray = format!(
            "{HEAD}background = \"#808080\"\n\
             [[polygon]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = \"#ff0000\"\n"
        );
        let f = parse_str(&gray).unwrap();
        let Frame::Gray(s) = &f.frame else { panic!() };
        assert_eq!(s.background, [884]);
        let Primitive::Polygon { colors, .. } = &s.primitives[0] else {
            panic!()
        };
        assert_eq!(*colors, PolyColors::Flat([871]));
    }

    #[test]
    fn gamma_accepts_numbers_and_srgb() {
        for (g, want) in [
            ("2.2", Curve::GAMMA_2_2),
            ("2.4", Curve::GAMMA_2_4),
            ("\"srgb\"", Curve::Srgb),
            ("1", Curve::Power(Gamma::new(1, 1).unwrap())),
        ] {
            let f = parse_str(&format!("{HEAD}[render]\ngamma = {g}\n")).unwrap();
            assert_eq!(f.curve, want, "{g}");
        }
    }

    #[test]
    fn ordered_dither_spreads_a_dark_rgb565_grey_over_two_codes() {
        let scene = |dither: &str| {
            let text = format!(
                "[display]\nwidth = 8\nheight = 8\nformat = \"rgb565\"\nbackground = [60, 60, 60]\n\
                 [render]\ngamma = \"srgb\"\n{dither}"
            );
            let f = parse_str(&text).unwrap();
            let lin = f.render_linear().unwrap();
            f.tone(&lin).codes
        };
        let flat = scene("");
        assert!(flat.iter().all(|&c| c == flat[0]));
        assert_eq!(scene("dither = \"none\"\n"), flat);
        let red = |c: &u16| u32::from(c >> 11);
        let dithered = scene("dither = \"ordered\"\n");
        // 31 V(60 / 4095) = 3.92 on sRGB: the fine table's 31 / 8 codes,
        // 14 of every 16 pixels red 4, 2 red 3.
        assert_eq!(dithered.iter().map(red).sum::<u32>(), 4 * 62);
        assert!(dithered.iter().map(red).all(|r| r == 3 || r == 4));
    }

    #[test]
    fn ordered_dither_is_refused_where_it_does_not_apply() {
        let e = parse_str(&format!("{HEAD}[render]\ndither = \"ordered\"\n")).unwrap_err();
        assert_eq!(e.field, "render.dither");
        assert!(e.message.contains("not gray8"), "{}", e.message);
        let e = parse_str(&format!("{HEAD}[render]\ndither = \"bayer\"\n")).unwrap_err();
        assert!(e.message.contains("unknown dither"), "{}", e.message);
        let gray4 = "[display]\nwidth = 4\nheight = 4\nformat = \"gray4\"\n[render]\ndither = \"ordered\"\n";
        assert_eq!(parse_str(gray4).unwrap().dither, Dither::Ordered);
    }
}
