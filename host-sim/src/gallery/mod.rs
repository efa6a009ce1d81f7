//! The demo gallery: PNG images a person can look at to judge softedge.
//!
//! | file | panels, left to right |
//! | --- | --- |
//! | `01-edges_aliased-vs-aa-exact-vs-aa-seed.png` | one scene (star polygon, 45° and near-horizontal edges, slivers, lines at 32 angles) drawn aliased, anti-aliased with exact box coverage, anti-aliased with the seed-001 single formula |
//! | `02-edges-detail_aliased-vs-aa-exact-vs-aa-seed-vs-diff.png` | a 32x24 crop of the same three around the 45° edge, magnified more, and the difference between the two anti-aliased modes times 8 |
//! | `03-gouraud-gray.png` | gray Gouraud triangles, a linear ramp and a fan |
//! | `04-gouraud-rgb_wheel-vs-triangle.png` | an RGB colour wheel (a fan of 36 triangles), an RGB triangle |
//! | `05-seams_triangles-vs-mesh-vs-polygon-vs-diff.png` | top row: a jittered mesh of 108 triangles each in its own colour (to show them), the same triangles in one flat colour, the outline as one polygon, the difference of the last two (any difference white); bottom row: the same for a fan of 64 triangles and a 64-gon |
//! | `06-gamma_uncorrected-vs-corrected.png` | one gray frame (a linear ramp, 1-px lines on pixel rows and on row borders, a flat half gray, dots and lines stepped by 1/8 px) as a γ = 2.4 display shows it with linear codes and through the γ table (module `gamma`) |
//! | `07-oled-1bit_reference-vs-aliased-vs-bayer-vs-floyd-steinberg.png` | a 128x64 SSD1306 frame rendered page by page: the anti-aliased linear frame in gray, aliased 1-bit, Bayer 8x8 and Floyd–Steinberg dithered (module `oled`) |
//! | `08-flicker_chart.png` | summed linear intensity and perceived brightness (with and without γ correction) of a 1x1 px square and two short lines over 16x16 sub-pixel offsets, each twice: 0.88-1.12 and 0-1.2 (module `flicker`) |
//! | `09-objects-3d_lod-low-vs-high.png` | sphere, torus, cone, cylinder, box and a composite, lit and anti-aliased, at a low and a high level of detail (module `objects`) |
//! | `10-lightness-filter_plain-vs-lstar-vs-rgb-blur.png` | light colourful frames (thin shapes aliased and anti-aliased, a dithered 3-bit gradient, fine Gouraud texture): plain, through seed 002's L* filter, through a 3x3 RGB box blur, and maps of the filter's L* change and of the a*/b* shift of filter and blur; the measured shifts are printed (module `lightness`) |
//! | `11-pixel-models_box-bed-hex-cone-gauss-hamming.png` | one small scene (a thin star, a 1-px line, a sliver) drawn with each pixel model — box exact and seed-001 formula, bed-of-nails 4x4 and 8x8, hexagonal 7 and 19 points, cone, Gaussian, Hamming — magnified four times more; each label gives the summed intensity against the box model (module `models`) |
//! | `13-text_outlines-8-48px-vs-eg-mono-fonts.png` | text in the bundled outline font at 8 to 48 px on an RGB display, anti-aliased in linear light, beside embedded-graphics' mono fonts 4x6 to 10x20 drawn by e-g, and e-g's `Text` with softedge's `AaTextStyle` (the font rasterized ahead at 12 and 16 px, through a glyph cache at 20-32 px) (module `text`) |
//! | `14-text-1bit_gray-threshold-bayer-fs-grid-boost-vs-eg.png` | four lines of an instrument display on a 128x64 1-bit OLED at 10, 11 and 12 px: the gray frame, its threshold at 1/2, Bayer 8x8, Floyd–Steinberg, Floyd–Steinberg with `Sharpen::GRID` and `ContrastBoost`; e-g's `FONT_6X10` and `FONT_6X13` (module `text`) |
//!
//! Every panel is rendered band by band ([`render`]), converted to sRGB by
//! [`lin12_to_srgb8`](crate::image::lin12_to_srgb8) (image 06 goes through
//! a simulated γ = 2.4 display first, module `display`; image 08 is a chart
//! of numbers measured on that display), magnified by an integer factor and
//! labelled with the built-in 3x5 font.

use std::f64::consts::PI;
use std::fmt;
use std::io;
use std::path::{Path, PathBuf};

use softedge::{DrawError, Line, RenderStyle, SubPoint, Triangle, LIN_MAX, SUB_ONE};

use crate::font::{draw_text, text_width, GLYPH_H};
use crate::image::{Channels, Image8, LinImage};
use crate::png_out::write_png;
use crate::scene::{render, PolyColors, Primitive, RenderError, Scene};

mod compose2d;
mod display;
mod flicker;
mod gamma;
mod hidden;
mod images;
mod lightness;
mod models;
mod objects;
mod oled;
mod text;

/// Options of [`write_gallery`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct GalleryOptions {
    /// Magnification of the panels (nearest neighbour); the detail image
    /// uses three times this.
    pub scale: u32,
    /// Rows per band used for every render.
    pub band_rows: u16,
}

impl Default for GalleryOptions {
    fn default() -> Self {
        Self {
            scale: 4,
            band_rows: 8,
        }
    }
}

/// A file the gallery wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// Where.
    pub path: PathBuf,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

/// Why the gallery stopped.
#[derive(Debug)]
pub enum GalleryError {
    /// A directory or file could not be made or written.
    Io {
        /// The path involved.
        path: PathBuf,
        /// The cause.
        source: io::Error,
    },
    /// A scene was rejected by the rasterizer (a bug in the gallery or in
    /// core: the gallery's scenes are all valid).
    Render {
        /// The image being made.
        image: &'static str,
        /// The cause.
        source: RenderError,
    },
    /// A primitive drawn directly into a band was rejected (a bug in the
    /// gallery or in core).
    Draw {
        /// The image being made.
        image: &'static str,
        /// The cause.
        source: DrawError,
    },
    /// A 3D object could not be meshed, placed or projected (a bug in the
    /// gallery or in core).
    Geometry {
        /// The image being made.
        image: &'static str,
        /// The object.
        object: &'static str,
        /// The cause, as core reported it.
        detail: String,
    },
}

impl fmt::Display for GalleryError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Io { path, source } => write!(f, "{}: {source}", path.display()),
            Self::Render { image, source } => write!(f, "rendering {image}: {source}"),
            Self::Draw { image, source } => write!(f, "drawing {image}: {source:?}"),
            Self::Geometry {
                image,
                object,
                detail,
            } => write!(f, "{image}: object {object}: {detail}"),
        }
    }
}

impl std::error::Error for GalleryError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            Self::Io { source, .. } => Some(source),
            Self::Render { source, .. } => Some(source),
            Self::Draw { .. } | Self::Geometry { .. } => None,
        }
    }
}

/// Number of files [`write_gallery`] writes.
pub const GALLERY_FILES: usize = 18;

/// Renders the gallery into `dir` (created if missing). `log` receives one
/// progress line per image and one `wrote PATH (WxH)` line per file.
pub fn write_gallery(
    dir: &Path,
    opts: &GalleryOptions,
    log: &mut dyn FnMut(&str),
) -> Result<Vec<Written>, GalleryError> {
    std::fs::create_dir_all(dir).map_err(|source| GalleryError::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let scale = opts.scale.max(1);
    let mut written = Vec::new();
    let mut save = |name: &str, img: &Image8, log: &mut dyn FnMut(&str)| {
        let path = dir.join(name);
        write_png(&path, img).map_err(|source| GalleryError::Io {
            path: path.clone(),
            source,
        })?;
        log(&format!(
            "wrote {} ({}x{})",
            path.display(),
            img.width(),
            img.height()
        ));
        written.push(Written {
            path,
            width: img.width(),
            height: img.height(),
        });
        Ok::<(), GalleryError>(())
    };
    let n = GALLERY_FILES;

    // (a) Anti-aliasing modes on one scene.
    log(&format!(
        "[1/{n}] edges: aliased | AA exact box | AA seed box"
    ));
    let edges = edges_scene().with_band_rows(opts.band_rows);
    let modes = [
        ("ALIASED", RenderStyle::ALIASED),
        ("AA EXACT BOX", RenderStyle::default()),
        (
            "AA SEED BOX",
            RenderStyle {
                antialias: true,
                model: softedge::PixelModel::BoxSeed,
            },
        ),
    ];
    let mut renders = Vec::new();
    for (label, style) in modes {
        let img = render(&edges.with_style(style)).map_err(|source| GalleryError::Render {
            image: "edges",
            source,
        })?;
        renders.push((label, img));
    }
    let panels: Vec<Panel> = renders
        .iter()
        .map(|(label, img)| Panel::new(label, img.to_srgb8(), scale))
        .collect();
    let sheet = compose(
        "EDGES: ALIASED / AA EXACT BOX / AA SEED-001 FORMULA",
        &[panels],
    );
    save("01-edges_aliased-vs-aa-exact-vs-aa-seed.png", &sheet, log)?;

    log(&format!("[2/{n}] edge detail, magnified"));
    let (cx, cy, cw, ch) = DETAIL;
    let crops: Vec<LinImage<3>> = renders
        .iter()
        .map(|(_, img)| img.crop(cx, cy, cw, ch))
        .collect();
    let mut panels: Vec<Panel> = renders
        .iter()
        .zip(&crops)
        .map(|((label, _), crop)| Panel::new(label, crop.to_srgb8(), scale * 3))
        .collect();
    if let Some((diff, _)) = crops[1].abs_diff(&crops[2], DETAIL_DIFF_GAIN) {
        panels.push(Panel::new(
            &format!("|EXACT-SEED| X{DETAIL_DIFF_GAIN}"),
            diff.to_srgb8(),
            scale * 3,
        ));
    }
    let sheet = compose(
        &format!("DETAIL {cw}X{ch} PX AT ({cx},{cy}): 45 DEG EDGE (SEED WORST CASE)"),
        &[panels],
    );
    save(
        "02-edges-detail_aliased-vs-aa-exact-vs-aa-seed-vs-diff.png",
        &sheet,
        log,
    )?;

    // (b) Gouraud shading.
    log(&format!("[3/{n}] gouraud gray"));
    let gray = render(&gouraud_gray_scene().with_band_rows(opts.band_rows)).map_err(|source| {
        GalleryError::Render {
            image: "gouraud gray",
            source,
        }
    })?;
    let sheet = compose(
        "GOURAUD GRAY (LINEAR LIGHT, SHOWN AS SRGB)",
        &[vec![Panel::new("AA EXACT BOX", gray.to_srgb8(), scale)]],
    );
    save("03-gouraud-gray.png", &sheet, log)?;

    log(&format!("[4/{n}] gouraud RGB: wheel | triangle"));
    let mut panels = Vec::new();
    for (label, scene) in [
        ("WHEEL: FAN OF 36", rgb_wheel_scene()),
        ("RGB TRIANGLE", rgb_triangle_scene()),
    ] {
        let img = render(&scene.with_band_rows(opts.band_rows)).map_err(|source| {
            GalleryError::Render {
                image: "gouraud rgb",
                source,
            }
        })?;
        panels.push(Panel::new(label, img.to_srgb8(), scale));
    }
    let sheet = compose("GOURAUD RGB", &[panels]);
    save("04-gouraud-rgb_wheel-vs-triangle.png", &sheet, log)?;

    // (c) Seams.
    log(&format!("[5/{n}] seams: mesh | one polygon | difference"));
    let mut rows = Vec::new();
    for (what, (tiles, outline)) in [("MESH", mesh_scenes()), ("FAN OF 64", fan_scenes())] {
        let err = |source| GalleryError::Render {
            image: "seams",
            source,
        };
        let shown = render(&patchwork(&tiles).with_band_rows(opts.band_rows)).map_err(err)?;
        let tiles_img = render(&tiles.with_band_rows(opts.band_rows)).map_err(err)?;
        let outline_img = render(&outline.with_band_rows(opts.band_rows)).map_err(err)?;
        let (diff, differ) = diff_panel(&tiles_img, &outline_img);
        // The aliased walk must tile as well (top-left rule).
        let aliased = |s: &Scene<3>| render(&s.with_style(RenderStyle::ALIASED)).map_err(err);
        let (_, differ_aliased) = diff_panel(&aliased(&tiles)?, &aliased(&outline)?);
        log(&format!(
            "      {} vs one polygon: {differ} of {} pixels differ anti-aliased, {differ_aliased} aliased",
            what.to_lowercase(),
            tiles_img.width() * tiles_img.height()
        ));
        rows.push(vec![
            Panel::new(
                &format!("{what}: {} TRIANGLES", tiles.primitives.len()),
                shown.to_srgb8(),
                scale,
            ),
            Panel::new("ONE COLOUR", tiles_img.to_srgb8(), scale),
            Panel::new("ONE POLYGON", outline_img.to_srgb8(), scale),
            Panel::new(&format!("DIFF: {differ} PX"), diff.to_srgb8(), scale),
        ]);
    }
    let sheet = compose("SEAMS: TILES VS ONE POLYGON, FLAT COLOUR", &rows);
    save(
        "05-seams_triangles-vs-mesh-vs-polygon-vs-diff.png",
        &sheet,
        log,
    )?;

    // (d) Tone: γ, 1-bit dithering, flicker.
    log(&format!(
        "[6/{n}] gamma: linear codes | gamma table, on a gamma 2.4 display"
    ));
    let sheet = gamma_sheet(opts.band_rows, scale, log)?;
    save("06-gamma_uncorrected-vs-corrected.png", &sheet, log)?;

    log(&format!(
        "[7/{n}] 1-bit OLED 128x64: reference | aliased | Bayer 8x8 | Floyd-Steinberg"
    ));
    let sheet = oled_sheet(scale, log)?;
    save(
        "07-oled-1bit_reference-vs-aliased-vs-bayer-vs-floyd-steinberg.png",
        &sheet,
        log,
    )?;

    log(&format!("[8/{n}] flicker: 256 sub-pixel offsets"));
    let sheet = flicker_sheet(log)?;
    save("08-flicker_chart.png", &sheet, log)?;

    // (e) 3D.
    log(&format!("[9/{n}] 3D objects at two levels of detail"));
    let sheet = objects_sheet(scale, log)?;
    save("09-objects-3d_lod-low-vs-high.png", &sheet, log)?;

    // (f) Post-filter.
    log(&format!(
        "[10/{n}] lightness filter: plain | L* filter | RGB 3x3 blur | a*b* shifts"
    ));
    let sheet = lightness_sheet(opts.band_rows, scale, log)?;
    save(
        "10-lightness-filter_plain-vs-lstar-vs-rgb-blur.png",
        &sheet,
        log,
    )?;

    // (g) Pixel models.
    log(&format!(
        "[11/{n}] pixel models: box | bed-of-nails | hexagonal | cone, gauss, hamming"
    ));
    let sheet = models::sheet(opts.band_rows, scale, log)?;
    save(
        "11-pixel-models_box-bed-hex-cone-gauss-hamming.png",
        &sheet,
        log,
    )?;

    // (h) Hidden surfaces.
    log(&format!(
        "[12/{n}] hidden surfaces: none | z-buffer aliased, AA | Warnock | Weiler-Atherton | section"
    ));
    let sheet = hidden::sheet(opts.band_rows, scale, log)?;
    save(
        "12-hidden-surfaces_none-vs-zbuffer-vs-section.png",
        &sheet,
        log,
    )?;

    // (m) Text: sizes on a colour display, beside e-g's mono fonts.
    log(&format!(
        "[13/{n}] text: softedge outlines 8-48 px | e-g mono fonts"
    ));
    let sheet = text::sizes_sheet(opts.band_rows, scale)?;
    save("13-text_outlines-8-48px-vs-eg-mono-fonts.png", &sheet, log)?;

    // (n) Text on a 1-bit OLED.
    log(&format!(
        "[14/{n}] text on 1 bit: gray | threshold | Bayer | Floyd-Steinberg | grid + boost | e-g mono"
    ));
    let sheet = text::one_bit_sheet(scale)?;
    save(
        "14-text-1bit_gray-threshold-bayer-fs-grid-boost-vs-eg.png",
        &sheet,
        log,
    )?;
    // (j) Drawing a user interface.
    log(&format!(
        "[15/{n}] compositing: add | over | opacity | a mesh as one shape vs its triangles"
    ));
    let sheet = compose2d::compositing_sheet(opts.band_rows, scale, log)?;
    save(
        "15-compositing_add-vs-over-opacity-mesh-as-one-shape.png",
        &sheet,
        log,
    )?;
    log(&format!(
        "[16/{n}] shapes and strokes: shapes | joins, caps, dashes | fill rules | e-g vs softedge"
    ));
    let sheet = compose2d::shapes_sheet(opts.band_rows, scale)?;
    save(
        "16-shapes-strokes_fill-rules_eg-aliased-vs-aa.png",
        &sheet,
        log,
    )?;
    log(&format!(
        "[17/{n}] instrument panel: 240x240 Rgb565 | 128x64 1-bit"
    ));
    let sheet = compose2d::panel_sheet(scale)?;
    save("17-instrument-panel_rgb565-vs-oled.png", &sheet, log)?;
    log(&format!(
        "[18/{n}] images: a rotated needle sprite | tinted 1-bpp icons"
    ));
    let sheet = images::images_sheet(scale)?;
    save("18-images_rotated-needle-tinted-icons.png", &sheet, log)?;

    Ok(written)
}

/// Image 06: the γ frame on a simulated γ = 2.4 display, uncorrected and
/// corrected, with the measured half-cover error in the labels.
fn gamma_sheet(
    band_rows: u16,
    scale: u32,
    log: &mut dyn FnMut(&str),
) -> Result<Image8, GalleryError> {
    use display::Codes;
    let img = render(&gamma::scene().with_band_rows(band_rows)).map_err(|source| {
        GalleryError::Render {
            image: "gamma",
            source,
        }
    })?;
    let mut panels = Vec::new();
    for (codes, name) in [
        (Codes::Uncorrected, "A: CODE = LIN12/16"),
        (Codes::Corrected, "B: GAMMALUT 2.4"),
    ] {
        let h = gamma::half_cover(&img, codes);
        log(&format!(
            "      {}: half-covered square {}, stripes on row borders {}",
            if codes == Codes::Corrected {
                "gamma table"
            } else {
                "linear codes"
            },
            pct(h.square),
            pct(h.stripes)
        ));
        panels.push(Panel::new(
            &format!("{name}, HALF PX {}", pct(h.square)),
            gamma::view(&img, codes),
            scale,
        ));
    }
    Ok(compose(
        "GAMMA 2.4 DISPLAY (SHOWN AS SRGB): UNCORRECTED / CORRECTED",
        &[panels],
    ))
}

/// Image 07: the SSD1306 frame, 1-bit.
fn oled_sheet(scale: u32, log: &mut dyn FnMut(&str)) -> Result<Image8, GalleryError> {
    let o = oled::render(&oled::shapes()).map_err(|source| GalleryError::Draw {
        image: "oled",
        source,
    })?;
    let mean = o.linear.sum() as f64
        / f64::from(LIN_MAX)
        / f64::from(o.linear.width() * o.linear.height());
    log(&format!(
        "      mean linear intensity {:.2} %, lit: bayer {:.2} %, floyd-steinberg {:.2} %, aliased {:.2} %",
        mean * 100.0,
        oled::lit_fraction(&o.bayer) * 100.0,
        oled::lit_fraction(&o.floyd) * 100.0,
        oled::lit_fraction(&o.aliased) * 100.0
    ));
    let rows = vec![
        vec![
            Panel::new("AA, LINEAR GRAY (REFERENCE)", o.linear.to_srgb8(), scale),
            Panel::new("ALIASED, COVERED = ON", oled::show(&o.aliased), scale),
        ],
        vec![
            Panel::new("AA, BAYER 8X8", oled::show(&o.bayer), scale),
            Panel::new(
                "AA, FLOYD-STEINBERG ACROSS PAGES",
                oled::show(&o.floyd),
                scale,
            ),
        ],
    ];
    Ok(compose("1-BIT OLED 128X64, 8-ROW PAGES", &rows))
}

/// Image 08: the flicker chart; prints the worst deviations.
fn flicker_sheet(log: &mut dyn FnMut(&str)) -> Result<Image8, GalleryError> {
    let mut rows = Vec::new();
    for (probe, name) in flicker::Probe::ALL {
        let c = flicker::measure(probe).map_err(|source| GalleryError::Draw {
            image: "flicker",
            source,
        })?;
        let (lin, cor, unc) = (
            flicker::worst(&c.linear),
            flicker::worst(&c.corrected),
            flicker::worst(&c.uncorrected),
        );
        log(&format!(
            "flicker, {}: linear {}, gamma-corrected {}, uncorrected {} (worst of {} offsets)",
            name.to_lowercase(),
            pct(lin),
            pct(cor),
            pct(unc),
            flicker::OFFSETS
        ));
        rows.push(vec![
            Panel::new(
                &format!("{name}: LIN {}, GAMMA {}", pct(lin), pct(cor)),
                flicker::chart(&c, 0.88, 1.12, &[0.9, 1.0, 1.1], true),
                1,
            ),
            Panel::new(
                &format!("FULL SCALE: UNCORRECTED {}", pct(unc)),
                flicker::chart(&c, 0.0, 1.2, &[0.0, 0.5, 1.0], false),
                1,
            ),
        ]);
    }
    Ok(compose(
        "FLICKER: RELATIVE BRIGHTNESS OVER 16X16 SUB-PIXEL OFFSETS (X: 16*DY+DX)",
        &rows,
    ))
}

/// Image 09: the 3D objects, low detail above, high detail below.
fn objects_sheet(scale: u32, log: &mut dyn FnMut(&str)) -> Result<Image8, GalleryError> {
    let mag = (scale * 3 / 4).max(1);
    let mut rows = Vec::new();
    for (segments, coarse) in [(8u16, true), (24, false)] {
        let geometry = |object: &'static str, e: &dyn fmt::Debug| GalleryError::Geometry {
            image: "objects",
            object,
            detail: format!("{e:?}"),
        };
        let objs = objects::objects(segments, coarse).map_err(|e| geometry("all", &e))?;
        let mut panels = Vec::new();
        for obj in &objs {
            let (img, stats) = objects::render_object(obj).map_err(|e| geometry(obj.name, &e))?;
            let twice = objects::overlap(obj).map_err(|e| geometry(obj.name, &e))?;
            log(&format!(
                "      {} {}: {} triangles drawn, {} back-facing culled, {twice} px covered twice",
                obj.name.to_lowercase(),
                obj.lod.to_lowercase(),
                stats.emitted,
                stats.back_facing
            ));
            panels.push(Panel::new(
                &format!("{} {}", obj.name, obj.lod),
                img.to_srgb8(),
                mag,
            ));
        }
        rows.push(panels);
    }
    Ok(compose(
        "3D: AMBIENT + LAMBERT, BACK-FACE CULLING ONLY: TORUS ALONG ITS AXIS, COMPOSITE FROM ABOVE",
        &rows,
    ))
}

/// Image 10: seed 002's L* filter beside a plain RGB blur, magnified 1.5
/// times the gallery scale; prints the measured a*/b* shifts.
fn lightness_sheet(
    band_rows: u16,
    scale: u32,
    log: &mut dyn FnMut(&str),
) -> Result<Image8, GalleryError> {
    let mag = (scale * 3 / 2).max(1);
    let frames = lightness::comparisons(band_rows).map_err(|source| GalleryError::Render {
        image: "lightness filter",
        source,
    })?;
    let (mut worst_filter, mut worst_in_gamut, mut worst_blur) = (0.0f64, 0.0f64, 0.0f64);
    let mut rows = Vec::new();
    for c in &frames {
        let (f, g, b) = (c.filter_shift, c.filter_shift_in_gamut, c.blur_shift);
        log(&format!(
            "lightness, {}: L* filter max |da*| {:.2}, |db*| {:.2} ({} px changed, {} clamped to the gamut; \
             in gamut |da*| {:.2}, |db*| {:.2}); RGB 3x3 blur max |da*| {:.1}, |db*| {:.1}",
            c.name.to_lowercase(),
            f.a,
            f.b,
            c.stats.changed,
            c.stats.clamped,
            g.a,
            g.b,
            b.a,
            b.b
        ));
        worst_filter = worst_filter.max(f.a.max(f.b));
        worst_in_gamut = worst_in_gamut.max(g.a.max(g.b));
        worst_blur = worst_blur.max(b.a.max(b.b));
        let map = |after: &LinImage<3>, what| lightness::change_map(&c.plain, after, what);
        rows.push(vec![
            Panel::new(c.name, c.plain.to_srgb8(), mag),
            Panel::new(
                &format!("L*: DA* {:.2} DB* {:.2}", f.a, f.b),
                c.filtered.to_srgb8(),
                mag,
            ),
            Panel::new(
                &format!("BLUR: DA* {:.0} DB* {:.0}", b.a, b.b),
                c.blurred.to_srgb8(),
                mag,
            ),
            Panel::new(
                "L*: DL*",
                map(&c.filtered, lightness::Change::Lightness),
                mag,
            ),
            Panel::new("L*: DAB", map(&c.filtered, lightness::Change::Colour), mag),
            Panel::new("BLUR: DAB", map(&c.blurred, lightness::Change::Colour), mag),
        ]);
    }
    log(&format!(
        "lightness, all frames: max a*/b* shift {worst_filter:.2} with the L* filter \
         ({worst_in_gamut:.2} where no channel was clamped), {worst_blur:.1} with the RGB 3x3 blur"
    ));
    Ok(compose(
        &format!(
            "PLAIN / SEED-002 L* FILTER / RGB 3X3 BOX BLUR. CHANGE MAPS: DL*, DAB = SQRT(DA*2+DB*2), WHITE = {}",
            lightness::SHIFT_WHITE
        ),
        &rows,
    ))
}

/// A relative deviation as a signed percentage: two decimals below 1 %,
/// one above.
fn pct(v: f64) -> String {
    if v.abs() < 0.01 {
        format!("{:+.2} %", v * 100.0)
    } else {
        format!("{:+.1} %", v * 100.0)
    }
}

/// The crop of the edge scene shown magnified: `(x, y, w, h)`.
const DETAIL: (u32, u32, u32, u32) = (36, 2, 32, 24);

/// Gain of the detail difference panel: the seed formula's worst error,
/// 1/8 of full scale at 45°, shows as full white.
const DETAIL_DIFF_GAIN: u32 = 8;

/// A labelled, magnified panel.
struct Panel {
    label: String,
    image: Image8,
}

impl Panel {
    fn new(label: &str, image: Image8, scale: u32) -> Self {
        Self {
            label: label.to_string(),
            image: image.to_rgb().upscale(scale),
        }
    }
}

const SHEET_BG: [u8; 3] = [48, 48, 48];
const TEXT: [u8; 3] = [235, 235, 235];
const TEXT_SCALE: u32 = 3;
const MARGIN: u32 = 12;

/// Lays out rows of panels under a title, each panel under its label
/// (drawn smaller when it would run into the next panel's).
fn compose(title: &str, rows: &[Vec<Panel>]) -> Image8 {
    let line = GLYPH_H * TEXT_SCALE;
    let label_h = line + MARGIN / 2;
    let row_w =
        |row: &Vec<Panel>| row.iter().map(|p| p.image.width() + MARGIN).sum::<u32>() + MARGIN;
    let row_h = |row: &Vec<Panel>| {
        row.iter().map(|p| p.image.height()).max().unwrap_or(0) + label_h + MARGIN
    };
    let width = rows
        .iter()
        .map(row_w)
        .max()
        .unwrap_or(0)
        .max(text_width(title, TEXT_SCALE) + 2 * MARGIN);
    let height = MARGIN + line + MARGIN + rows.iter().map(row_h).sum::<u32>();
    let mut sheet = Image8::new(width, height, Channels::Rgb, &SHEET_BG);
    draw_text(
        &mut sheet,
        i64::from(MARGIN),
        i64::from(MARGIN),
        TEXT_SCALE,
        title,
        &TEXT,
    );
    let mut y = MARGIN + line + MARGIN;
    for row in rows {
        let mut x = MARGIN;
        for p in row {
            // A label wider than its panel (small scales) is drawn smaller,
            // down to 1, rather than over the next panel's label.
            let room = p.image.width() + MARGIN;
            let ts = (1..=TEXT_SCALE)
                .rev()
                .find(|&s| text_width(&p.label, s) <= room)
                .unwrap_or(1);
            draw_text(
                &mut sheet,
                i64::from(x),
                i64::from(y + (TEXT_SCALE - ts) * GLYPH_H),
                ts,
                &p.label,
                &TEXT,
            );
            sheet.blit(&p.image, x, y + label_h);
            x += p.image.width() + MARGIN;
        }
        y += row_h(row);
    }
    sheet
}

/// `|a - b|` with any difference shown at full white, and the count.
fn diff_panel(a: &LinImage<3>, b: &LinImage<3>) -> (LinImage<3>, usize) {
    a.abs_diff(b, u32::from(LIN_MAX))
        .unwrap_or_else(|| (LinImage::new(a.width(), a.height()), 0))
}

// --- Scene building (host side: floats are fine here, vertices are rounded
// to 1/16 px once). ---

/// A point in pixels, rounded to the nearest 1/16 px.
fn sp(x: f64, y: f64) -> SubPoint {
    let s = f64::from(SUB_ONE);
    SubPoint::new((x * s).round() as i32, (y * s).round() as i32)
}

/// A fraction `0..=1` of full linear intensity.
fn lin(f: f64) -> u16 {
    (f.clamp(0.0, 1.0) * f64::from(LIN_MAX)).round() as u16
}

/// The fully saturated colour of hue `h` (turns), as linear 12-bit RGB:
/// the HSV hue in sRGB, decoded to linear light.
fn hue_lin(h: f64) -> [u16; 3] {
    let channel = |offset: f64| {
        let t = (h + offset).rem_euclid(1.0) * 6.0;
        let srgb = ((t - 3.0).abs() - 1.0).clamp(0.0, 1.0);
        let linear = if srgb <= 0.040_45 {
            srgb / 12.92
        } else {
            ((srgb + 0.055) / 1.055).powf(2.4)
        };
        lin(linear)
    };
    [channel(0.0), channel(2.0 / 3.0), channel(1.0 / 3.0)]
}

/// The edge scene: 128x80, white on black.
fn edges_scene() -> Scene<3> {
    let white = [LIN_MAX; 3];
    let mut s = Scene::new(128, 80, [0; 3]);
    // A five-pointed star as a simple concave 10-gon, tip up.
    let (cx, cy, r_out, r_in) = (20.3, 22.1, 17.0, 7.0);
    let star: Vec<SubPoint> = (0..10)
        .map(|k| {
            let a = -PI / 2.0 + f64::from(k) * PI / 5.0;
            let r = if k % 2 == 0 { r_out } else { r_in };
            sp(cx + r * a.cos(), cy + r * a.sin())
        })
        .collect();
    s.primitives.push(Primitive::flat_polygon(star, white));
    // Right triangle with a 45° hypotenuse, off the pixel grid.
    s.primitives.push(Primitive::Triangle(Triangle::flat(
        // Half a pixel between the x and y offsets: the hypotenuse crosses
        // row boundaries at column centres, the seed formula's worst case.
        [sp(40.3, 3.8), sp(62.3, 3.8), sp(62.3, 25.8)],
        white,
    )));
    // A wedge whose two edges are near-horizontal (slope ±1/20).
    s.primitives.push(Primitive::Triangle(Triangle::flat(
        [sp(2.5, 42.0), sp(62.5, 45.0), sp(2.5, 48.0)],
        white,
    )));
    // Slivers, 1/4 to 2 px thick at their wide end.
    for (k, t) in [0.25, 0.5, 0.75, 1.0, 1.5, 2.0].into_iter().enumerate() {
        let y = 53.0 + 4.2 * k as f64;
        s.primitives.push(Primitive::Triangle(Triangle::flat(
            [sp(3.0, y + 1.0), sp(62.0, y), sp(62.0, y + t)],
            white,
        )));
    }
    // Lines at 32 angles, 11.25° apart.
    let (lx, ly) = (96.2, 40.1);
    for k in 0..32 {
        let a = f64::from(k) * PI / 16.0;
        s.primitives.push(Primitive::Line(Line::new(
            sp(lx + 6.0 * a.cos(), ly + 6.0 * a.sin()),
            sp(lx + 29.0 * a.cos(), ly + 29.0 * a.sin()),
            [white, white],
        )));
    }
    // Very shallow lines (slope 1/30 and 1/60).
    s.primitives.push(Primitive::Line(Line::new(
        sp(67.0, 3.0),
        sp(126.0, 5.0),
        [white, white],
    )));
    s.primitives.push(Primitive::Line(Line::new(
        sp(67.0, 76.0),
        sp(126.0, 77.0),
        [white, white],
    )));
    s
}

/// Gray Gouraud: 128x80.
fn gouraud_gray_scene() -> Scene<1> {
    let mut s = Scene::new(128, 80, [lin(0.05)]);
    s.primitives.push(Primitive::Triangle(Triangle::new(
        [sp(4.0, 4.0), sp(60.0, 12.0), sp(18.0, 76.0)],
        [[0], [LIN_MAX], [lin(0.5)]],
    )));
    // A horizontal linear ramp, black to white.
    s.primitives.push(Primitive::Polygon {
        vertices: vec![
            sp(66.0, 4.0),
            sp(124.0, 4.0),
            sp(124.0, 22.0),
            sp(66.0, 22.0),
        ],
        colors: PolyColors::PerVertex(vec![[0], [LIN_MAX], [LIN_MAX], [0]]),
    });
    // A fan of 12 around a white centre, rim alternating black and dark gray.
    let (cx, cy, r) = (95.0, 52.0, 24.0);
    for k in 0..12 {
        let a0 = f64::from(k) * PI / 6.0;
        let a1 = f64::from(k + 1) * PI / 6.0;
        let rim = |k: i32| if k % 2 == 0 { [0] } else { [lin(0.25)] };
        s.primitives.push(Primitive::Triangle(Triangle::new(
            [
                sp(cx, cy),
                sp(cx + r * a0.cos(), cy + r * a0.sin()),
                sp(cx + r * a1.cos(), cy + r * a1.sin()),
            ],
            [[LIN_MAX], rim(k), rim(k + 1)],
        )));
    }
    s
}

/// RGB colour wheel: a fan of 36 triangles, white centre, hues on the rim.
fn rgb_wheel_scene() -> Scene<3> {
    let mut s = Scene::new(96, 96, [lin(0.02); 3]);
    let (cx, cy, r) = (48.0, 48.0, 44.0);
    let n = 36;
    for k in 0..n {
        let h0 = f64::from(k) / f64::from(n);
        let h1 = f64::from(k + 1) / f64::from(n);
        let (a0, a1) = (h0 * 2.0 * PI, h1 * 2.0 * PI);
        s.primitives.push(Primitive::Triangle(Triangle::new(
            [
                sp(cx, cy),
                sp(cx + r * a0.cos(), cy - r * a0.sin()),
                sp(cx + r * a1.cos(), cy - r * a1.sin()),
            ],
            [[LIN_MAX; 3], hue_lin(h0), hue_lin(h1)],
        )));
    }
    s
}

/// The classic red-green-blue triangle.
fn rgb_triangle_scene() -> Scene<3> {
    let mut s = Scene::new(96, 96, [lin(0.02); 3]);
    s.primitives.push(Primitive::Triangle(Triangle::new(
        [sp(48.0, 4.0), sp(92.0, 88.0), sp(4.0, 88.0)],
        [[LIN_MAX, 0, 0], [0, LIN_MAX, 0], [0, 0, LIN_MAX]],
    )));
    s
}

const MESH_BG: [u16; 3] = [120, 220, 560];
const MESH_FG: [u16; 3] = [4095, 1400, 160];

/// The same scene with each primitive in its own colour (hues a golden
/// ratio apart, at 3/4 intensity), to show the tiling.
fn patchwork(s: &Scene<3>) -> Scene<3> {
    let mut out = s.clone();
    for (k, p) in out.primitives.iter_mut().enumerate() {
        let hue = (k as f64 * 0.618_034).fract();
        let c = hue_lin(hue).map(|v| v - v / 4);
        if let Primitive::Triangle(t) = p {
            t.colors = [c; 3];
        }
    }
    out
}

/// A deterministic generator for jitter (xorshift32).
struct Jitter(u32);

impl Jitter {
    /// A value in `[-1, 1)`.
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        f64::from(self.0) / f64::from(u32::MAX) * 2.0 - 1.0
    }
}

/// A 9x6-cell mesh of 108 flat triangles with jittered vertices, and the
/// same outline drawn as one polygon.
fn mesh_scenes() -> (Scene<3>, Scene<3>) {
    let (nx, ny) = (9usize, 6usize);
    let (x0, y0, x1, y1) = (6.3, 5.2, 105.7, 74.6);
    let (cw, ch) = ((x1 - x0) / nx as f64, (y1 - y0) / ny as f64);
    let mut rng = Jitter(0x5EED_ED6E);
    let mut grid = vec![vec![SubPoint::default(); nx + 1]; ny + 1];
    for (j, row) in grid.iter_mut().enumerate() {
        for (i, p) in row.iter_mut().enumerate() {
            let (jx, jy) = (rng.next() * 0.35 * cw, rng.next() * 0.35 * ch);
            // Boundary points move only along the boundary; corners stay.
            let jx = if i == 0 || i == nx { 0.0 } else { jx };
            let jy = if j == 0 || j == ny { 0.0 } else { jy };
            *p = sp(x0 + i as f64 * cw + jx, y0 + j as f64 * ch + jy);
        }
    }
    let mut tiles = Scene::new(112, 80, MESH_BG);
    for j in 0..ny {
        for i in 0..nx {
            let (a, b) = (grid[j][i], grid[j][i + 1]);
            let (c, d) = (grid[j + 1][i + 1], grid[j + 1][i]);
            let tris = if (i + j) % 2 == 0 {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [b, c, d]]
            };
            for t in tris {
                tiles
                    .primitives
                    .push(Primitive::Triangle(Triangle::flat(t, MESH_FG)));
            }
        }
    }
    let mut outline = Vec::new();
    outline.extend((0..nx).map(|i| grid[0][i]));
    outline.extend((0..ny).map(|j| grid[j][nx]));
    outline.extend((1..=nx).rev().map(|i| grid[ny][i]));
    outline.extend((1..=ny).rev().map(|j| grid[j][0]));
    let mut one = Scene::new(112, 80, MESH_BG);
    one.primitives
        .push(Primitive::flat_polygon(outline, MESH_FG));
    (tiles, one)
}

/// A fan of 64 triangles around an off-grid centre, and the 64-gon.
fn fan_scenes() -> (Scene<3>, Scene<3>) {
    let (cx, cy, r) = (55.6, 40.3, 36.0);
    let rim: Vec<SubPoint> = (0..64)
        .map(|k| {
            let a = f64::from(k) * PI / 32.0;
            sp(cx + r * a.cos(), cy + r * a.sin())
        })
        .collect();
    let mut tiles = Scene::new(112, 80, MESH_BG);
    for k in 0..rim.len() {
        tiles.primitives.push(Primitive::Triangle(Triangle::flat(
            [sp(cx, cy), rim[k], rim[(k + 1) % rim.len()]],
            MESH_FG,
        )));
    }
    let mut one = Scene::new(112, 80, MESH_BG);
    one.primitives.push(Primitive::flat_polygon(rim, MESH_FG));
    (tiles, one)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(tag: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("softedge-sim-gallery-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        d
    }

    fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
        let file = std::fs::File::open(path).unwrap();
        let mut reader = png::Decoder::new(std::io::BufReader::new(file))
            .read_info()
            .unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        buf.truncate(info.buffer_size());
        (info.width, info.height, buf)
    }

    #[test]
    fn gallery_writes_non_uniform_pngs() {
        let dir = temp_dir("ok");
        let mut lines = Vec::new();
        let opts = GalleryOptions {
            scale: 2,
            band_rows: 8,
        };
        let written = write_gallery(&dir, &opts, &mut |l| lines.push(l.to_string())).unwrap();
        assert_eq!(written.len(), GALLERY_FILES);
        let mut names: Vec<String> = written
            .iter()
            .map(|w| w.path.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        names.dedup();
        assert_eq!(names.len(), GALLERY_FILES, "{names:?}");
        for prefix in [
            "06-gamma",
            "07-oled-1bit",
            "08-flicker",
            "09-objects-3d",
            "10-lightness-filter",
            "11-pixel-models",
            "15-compositing",
            "16-shapes-strokes",
            "17-instrument-panel",
            "18-images",
        ] {
            assert!(names.iter().any(|n| n.starts_with(prefix)), "{prefix}");
        }
        // The flicker numbers are printed, one line per object.
        assert_eq!(
            lines.iter().filter(|l| l.starts_with("flicker, ")).count(),
            3
        );
        // The a*/b* shifts: one line per frame and the summary.
        assert_eq!(
            lines
                .iter()
                .filter(|l| l.starts_with("lightness, ") && l.contains("|db*|"))
                .count(),
            4
        );
        assert!(lines
            .iter()
            .any(|l| l.starts_with("lightness, all frames: max a*/b* shift")));
        for w in &written {
            let meta = std::fs::metadata(&w.path).unwrap();
            assert!(meta.len() > 0, "{} is empty", w.path.display());
            let (width, height, pixels) = decode(&w.path);
            assert_eq!((width, height), (w.width, w.height));
            let first = &pixels[..3];
            assert!(
                pixels.chunks_exact(3).any(|p| p != first),
                "{} is uniform",
                w.path.display()
            );
            assert!(lines
                .iter()
                .any(|l| l.starts_with("wrote ") && l.contains(&*w.path.to_string_lossy())));
        }
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn unwritable_dir_is_an_error() {
        let file = temp_dir("file");
        std::fs::write(&file, b"not a dir").unwrap();
        let err = write_gallery(&file.join("sub"), &GalleryOptions::default(), &mut |_| {});
        std::fs::remove_file(&file).unwrap();
        assert!(matches!(err, Err(GalleryError::Io { .. })));
    }

    #[test]
    fn every_gallery_scene_renders() {
        for s in [edges_scene(), rgb_wheel_scene(), rgb_triangle_scene()] {
            let img = render(&s).unwrap();
            assert!(img.sum() > 0);
        }
        assert!(render(&gouraud_gray_scene()).unwrap().sum() > 0);
    }

    #[test]
    fn aa_modes_differ_and_keep_the_energy() {
        let s = edges_scene();
        let aliased = render(&s.with_style(RenderStyle::ALIASED)).unwrap();
        let exact = render(&s).unwrap();
        assert_ne!(aliased, exact);
        // The same shapes: summed linear intensity within 2 % (aliased
        // lines cover their rectangles with corners rounded to 1/16 px,
        // whose width is off by up to 7 % at some angles; anti-aliased lines
        // are scaled back to their ideal energy).
        let (a, e) = (aliased.sum() as f64, exact.sum() as f64);
        assert!((a - e).abs() / e < 0.02, "aliased {a} vs exact {e}");
    }

    #[test]
    fn hues_are_saturated() {
        assert_eq!(hue_lin(0.0), [LIN_MAX, 0, 0]);
        assert_eq!(hue_lin(1.0 / 3.0), [0, LIN_MAX, 0]);
        assert_eq!(hue_lin(2.0 / 3.0), [0, 0, LIN_MAX]);
    }
}
