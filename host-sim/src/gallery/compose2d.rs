//! Images 15 to 17: drawing a user interface. Painter's order, opacity
//! and meshes composed as one shape (15); every shape and stroke, the
//! fill rules, and embedded-graphics' aliased primitives beside the same
//! geometry anti-aliased (16); the instrument panel example scene on a
//! 240x240 Rgb565 TFT and a 128x64 1-bit OLED (17).
//!
//! Scenes are scene-file text (the format users write); the
//! embedded-graphics panels draw through the canvas as a `DrawTarget`.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, Line, PrimitiveStyle, RoundedRectangle};
use softedge::band::{BandBuffer, Bands};
use softedge::canvas::Canvas;
use softedge::draw::{AaDrawable, AaStyle};
use softedge::path::LineCap;

use super::{compose, diff_panel, GalleryError, Panel};
use crate::image::{Image8, LinImage};
use crate::scene::render;
use crate::scene_file::{parse, Frame, SceneFile};

const PANEL_SCENE: &str = include_str!("../../../examples/scenes/panel.toml");
const PANEL_OLED_SCENE: &str = include_str!("../../../examples/scenes/panel_oled.toml");

fn scene_file(name: &'static str, text: &str) -> Result<SceneFile, GalleryError> {
    parse(std::path::Path::new(name), text).map_err(|d| GalleryError::Geometry {
        image: name,
        object: "scene",
        detail: d.to_string(),
    })
}

/// An RGB scene file's frame, linear.
fn rgb(name: &'static str, text: &str, band_rows: u16) -> Result<LinImage<3>, GalleryError> {
    let file = scene_file(name, text)?;
    let Frame::Rgb(s) = &file.frame else {
        return Err(GalleryError::Geometry {
            image: name,
            object: "scene",
            detail: "expected an RGB scene".into(),
        });
    };
    render(&s.with_band_rows(band_rows)).map_err(|source| GalleryError::Render {
        image: name,
        source,
    })
}

const HEAD: &str =
    "[display]\nwidth = 96\nheight = 96\nformat = \"rgb888\"\nbackground = \"#202830\"\n";

/// Three discs, red, green and blue, overlapping.
fn discs(blend: &str) -> String {
    format!(
        "{HEAD}[render]\nblend = \"{blend}\"\n\
         [[circle]]\ncentre = [36, 38]\nradius = 24\ncolor = \"#ff2020\"\n\
         [[circle]]\ncentre = [60, 38]\nradius = 24\ncolor = \"#20ff20\"\n\
         [[circle]]\ncentre = [48, 60]\nradius = 24\ncolor = \"#2040ff\"\n"
    )
}

/// White squares at opacity 1/8 .. 1 over black and white stripes.
fn opacity_steps() -> String {
    let mut t = HEAD.to_string();
    for k in 0..6 {
        t += &format!(
            "[[rect]]\nposition = [0, {}]\nsize = [96, 8]\ncolor = \"#000000\"\n",
            k * 16
        );
    }
    for (k, a) in [0.125, 0.25, 0.375, 0.5, 0.75, 1.0].iter().enumerate() {
        let (x, y) = (6 + (k % 3) * 30, 10 + (k / 3) * 44);
        t += &format!(
            "[[rect]]\nposition = [{x}, {y}]\nsize = [24, 32]\nradius = 4\ncolor = \"#ff9020\"\nopacity = {a}\n"
        );
    }
    t
}

/// A Gouraud grid of 4x4 cells at half opacity over stripes: one
/// `[[mesh]]`, or its 32 triangles as entries of their own.
fn half_mesh(as_one: bool) -> String {
    let mut t = HEAD.to_string();
    for k in 0..6 {
        t += &format!(
            "[[rect]]\nposition = [{}, 0]\nsize = [8, 96]\ncolor = \"#e0e0e0\"\n",
            k * 16
        );
    }
    let hue = |a: usize, b: usize| {
        format!(
            "[{}, {}, {}]",
            600 + a * 800,
            600 + b * 800,
            3800 - (a + b) * 350
        )
    };
    let (mut pts, mut colors, mut tris) = (vec![], vec![], vec![]);
    for b in 0..=4 {
        for a in 0..=4 {
            pts.push(format!("[{}, {}]", 8 + a * 20, 8 + b * 20));
            colors.push(hue(a, b));
        }
    }
    for b in 0..4 {
        for a in 0..4 {
            let at = |a: usize, b: usize| b * 5 + a;
            tris.push([at(a, b), at(a + 1, b), at(a + 1, b + 1)]);
            tris.push([at(a, b), at(a + 1, b + 1), at(a, b + 1)]);
        }
    }
    if as_one {
        let tri_text: Vec<String> = tris
            .iter()
            .map(|t| format!("[{}, {}, {}]", t[0], t[1], t[2]))
            .collect();
        t += &format!(
            "[[mesh]]\npoints = [{}]\ntriangles = [{}]\ncolors = [{}]\nopacity = 0.5\n",
            pts.join(", "),
            tri_text.join(", "),
            colors.join(", ")
        );
    } else {
        for tr in &tris {
            t += &format!(
                "[[triangle]]\npoints = [{}, {}, {}]\ncolors = [{}, {}, {}]\nopacity = 0.5\n",
                pts[tr[0]], pts[tr[1]], pts[tr[2]], colors[tr[0]], colors[tr[1]], colors[tr[2]]
            );
        }
    }
    t
}

/// Image 15: painter's order, opacity, a mesh as one shape.
pub(super) fn compositing_sheet(
    band_rows: u16,
    scale: u32,
    log: &mut dyn FnMut(&str),
) -> Result<Image8, GalleryError> {
    let add = rgb("discs-add", &discs("add"), band_rows)?;
    let over = rgb("discs-over", &discs("over"), band_rows)?;
    let steps = rgb("opacity", &opacity_steps(), band_rows)?;
    let one = rgb("mesh-one", &half_mesh(true), band_rows)?;
    let each = rgb("mesh-each", &half_mesh(false), band_rows)?;
    let (diff, differ) = diff_panel(&one, &each);
    log(&format!(
        "      half-opacity mesh: {differ} pixels differ between one shape and 32 triangles"
    ));
    Ok(compose(
        "COMPOSITING IN LINEAR LIGHT: ADD, OVER, OPACITY, A MESH AS ONE SHAPE",
        &[
            vec![
                Panel::new("ADD (SEED 000)", add.to_srgb8(), scale),
                Panel::new("OVER (PAINTER)", over.to_srgb8(), scale),
                Panel::new("OPACITY 1/8 .. 1", steps.to_srgb8(), scale),
            ],
            vec![
                Panel::new("MESH, 50%", one.to_srgb8(), scale),
                Panel::new("32 TRIANGLES", each.to_srgb8(), scale),
                Panel::new(&format!("DIFF: {differ} PX"), diff.to_srgb8(), scale),
            ],
        ],
    ))
}

/// Every shape, filled and stroked.
const SHAPES: &str = "[display]\nwidth = 128\nheight = 96\nformat = \"rgb888\"\nbackground = \"#202830\"\n\
[[circle]]\ncentre = [20, 20]\nradius = 14\ncolor = \"#e04040\"\nstroke_color = \"#ffffff\"\nstroke_width = 1.5\n\
[[ellipse]]\ncentre = [60, 20]\nradii = [20, 9]\nrotation = 25\ncolor = \"#40c060\"\n\
[[sector]]\ncentre = [104, 24]\nradius = 18\nstart = -120\nsweep = 250\ncolor = \"#4080ff\"\nstroke_color = \"#c0d8ff\"\nstroke_width = 1\njoin = \"round\"\n\
[[rect]]\nposition = [6, 44]\nsize = [36, 24]\nradius = [10, 2, 10, 2]\ncolor = \"#e0a020\"\n\
[[arc]]\ncentre = [64, 60]\nradius = 14\nstart = 150\nsweep = 240\nstroke_color = \"#ff60c0\"\nstroke_width = 5\ncap = \"round\"\n\
[[path]]\nd = \"M 88 48 C 100 30 124 40 118 56 Q 112 70 124 80 L 92 84 Q 80 66 88 48 Z\"\ncolor = \"#60d0d0\"\nopacity = 0.8\n\
[[polyline]]\npoints = [[6, 90], [24, 74], [40, 86], [58, 72], [76, 88], [94, 74], [122, 90]]\nstroke_color = \"#ffffff\"\nstroke_width = 2\njoin = \"round\"\ncap = \"round\"\n";

/// Joins (rows: miter, round, bevel) and caps (columns: butt, round,
/// square), dashes, alignment, hairlines.
fn strokes() -> String {
    let mut t = String::from(
        "[display]\nwidth = 128\nheight = 96\nformat = \"rgb888\"\nbackground = \"#202830\"\n",
    );
    for (r, join) in ["miter", "round", "bevel"].iter().enumerate() {
        for (c, cap) in ["butt", "round", "square"].iter().enumerate() {
            let (x, y) = (6.0 + c as f64 * 24.0, 8.0 + r as f64 * 22.0);
            t += &format!(
                "[[polyline]]\npoints = [[{x}, {}], [{}, {y}], [{}, {}]]\nstroke_color = \"#ffd040\"\nstroke_width = 5\njoin = \"{join}\"\ncap = \"{cap}\"\n",
                y + 12.0,
                x + 8.0,
                x + 16.0,
                y + 12.0
            );
        }
    }
    t += "[[circle]]\ncentre = [100, 22]\nradius = 16\nstroke_color = \"#80c0ff\"\nstroke_width = 3\ndash = [6, 3]\ncap = \"round\"\n";
    for (k, a) in ["inside", "centre", "outside"].iter().enumerate() {
        let x = 82 + k * 15;
        t += &format!(
            "[[rect]]\nposition = [{x}, 48]\nsize = [10, 14]\ncolor = \"#404850\"\n\
             [[rect]]\nposition = [{x}, 48]\nsize = [10, 14]\nstroke_color = \"#ff8080\"\nstroke_width = 2\nstroke_alignment = \"{a}\"\n"
        );
    }
    for (k, w) in [0.25, 0.5, 1.0, 2.0].iter().enumerate() {
        let y = 72.0 + k as f64 * 6.0;
        t += &format!(
            "[[polyline]]\npoints = [[6, {y}], [122, {}]]\nstroke_color = \"#ffffff\"\nstroke_width = {w}\n",
            y + 3.0
        );
    }
    t
}

/// A pentagram and nested squares, nonzero and even-odd.
fn rules(rule: &str) -> String {
    let star: Vec<String> = (0..5)
        .map(|k| {
            let t = -std::f64::consts::FRAC_PI_2 + f64::from(k) * 4.0 * std::f64::consts::PI / 5.0;
            format!("{:.3} {:.3}", 30.0 + 26.0 * t.cos(), 32.0 + 26.0 * t.sin())
        })
        .collect();
    format!(
        "[display]\nwidth = 128\nheight = 64\nformat = \"rgb888\"\nbackground = \"#202830\"\n\
         [[path]]\nd = \"M {} L {} L {} L {} L {} Z\"\nfill_rule = \"{rule}\"\ncolor = \"#f0c040\"\n\
         [[path]]\nd = \"M 66 6 h 56 v 52 h -56 Z M 76 16 h 36 v 32 h -36 Z M 86 26 h 16 v 12 h -16 Z\"\nfill_rule = \"{rule}\"\ncolor = \"#40c0f0\"\n",
        star[0], star[1], star[2], star[3], star[4]
    )
}

/// Renders `draw` through the canvas, band by band, into a linear image.
fn canvas_image(
    w: u16,
    h: u16,
    bg: [u16; 3],
    band_rows: u16,
    mut draw: impl FnMut(&mut Canvas<'_, '_, 3, Rgb888>),
) -> LinImage<3> {
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, band_rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, band_rows)];
    let mut img = LinImage::new(u32::from(w), u32::from(h));
    let mut row = vec![[0u16; 3]; usize::from(w)];
    for band in Bands::new(w, h, band_rows) {
        let Ok(mut buf) = BandBuffer::<3>::new(&mut acc, &mut cover, band) else {
            continue;
        };
        buf.clear(bg);
        {
            let mut canvas = Canvas::typed(&mut buf, None).with_frame(w, h);
            draw(&mut canvas);
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            let n = buf.resolve_row(y, &mut row);
            img.set_row(y as u32, &row[..n]);
        }
    }
    img
}

/// The same dial in embedded-graphics geometry: its own aliased drawing
/// (`PrimitiveStyle`) or softedge's (`AaStyle` of the same colours).
fn dial(c: &mut Canvas<'_, '_, 3, Rgb888>, aa: bool) {
    let face = Rgb888::new(0x1c, 0x24, 0x30);
    let rim = Rgb888::new(0x80, 0x90, 0xa0);
    let track = Rgb888::new(0x30, 0x3a, 0x48);
    let value = Rgb888::new(0x30, 0xd0, 0x80);
    let needle = Rgb888::new(0xff, 0x50, 0x30);
    let disc = Circle::new(Point::new(8, 8), 80);
    let arc = |sweep: f32| Arc::new(Point::new(16, 16), 64, 135.0.deg(), sweep.deg());
    let hand = Line::new(Point::new(48, 48), Point::new(70, 24));
    let button = RoundedRectangle::with_equal_corners(
        embedded_graphics::primitives::Rectangle::new(Point::new(28, 70), Size::new(40, 16)),
        Size::new(6, 6),
    );
    if aa {
        let _ = disc
            .into_styled(AaStyle::with_fill(face).stroke_color(rim).stroke_width(2))
            .draw(c);
        let _ = arc(270.0)
            .into_styled(AaStyle::with_stroke(track, 6).cap(LineCap::Round))
            .draw(c);
        let _ = arc(190.0)
            .into_styled(AaStyle::with_stroke(value, 6).cap(LineCap::Round))
            .draw(c);
        let _ = hand
            .into_styled(AaStyle::with_stroke(needle, 3).cap(LineCap::Round))
            .draw(c);
        let _ = button.into_styled(AaStyle::with_fill(rim)).draw(c);
    } else {
        let _ = disc
            .into_styled(
                embedded_graphics::primitives::PrimitiveStyleBuilder::new()
                    .fill_color(face)
                    .stroke_color(rim)
                    .stroke_width(2)
                    .build(),
            )
            .draw(c);
        let _ = arc(270.0)
            .into_styled(PrimitiveStyle::with_stroke(track, 6))
            .draw(c);
        let _ = arc(190.0)
            .into_styled(PrimitiveStyle::with_stroke(value, 6))
            .draw(c);
        let _ = hand
            .into_styled(PrimitiveStyle::with_stroke(needle, 3))
            .draw(c);
        let _ = button.into_styled(PrimitiveStyle::with_fill(rim)).draw(c);
    }
}

/// Image 16: shapes, strokes, fill rules; embedded-graphics vs softedge.
pub(super) fn shapes_sheet(band_rows: u16, scale: u32) -> Result<Image8, GalleryError> {
    let shapes = rgb("shapes", SHAPES, band_rows)?;
    let strokes = rgb("strokes", &strokes(), band_rows)?;
    let nonzero = rgb("nonzero", &rules("nonzero"), band_rows)?;
    let evenodd = rgb("evenodd", &rules("evenodd"), band_rows)?;
    let bg = softedge::color::IntoLinear::<3>::into_linear(Rgb888::new(0x20, 0x28, 0x30));
    let aliased = canvas_image(96, 96, bg, band_rows, |c| dial(c, false));
    let aa = canvas_image(96, 96, bg, band_rows, |c| dial(c, true));
    Ok(compose(
        "SHAPES AND STROKES: ONE SHAPE EACH, EXACT AREA, LINEAR LIGHT",
        &[
            vec![
                Panel::new("SHAPES, PATHS", shapes.to_srgb8(), scale),
                Panel::new("STROKES", strokes.to_srgb8(), scale),
            ],
            vec![
                Panel::new("NONZERO", nonzero.to_srgb8(), scale),
                Panel::new("EVEN-ODD", evenodd.to_srgb8(), scale),
            ],
            vec![
                Panel::new("E-G PRIMITIVESTYLE", aliased.to_srgb8(), scale),
                Panel::new("SAME GEOMETRY, AASTYLE", aa.to_srgb8(), scale),
            ],
        ],
    ))
}

/// Image 17: the instrument panel scene as its two displays show it.
pub(super) fn panel_sheet(scale: u32) -> Result<Image8, GalleryError> {
    let mut panels = Vec::new();
    for (name, text, label, zoom) in [
        ("panel.toml", PANEL_SCENE, "240X240 RGB565, SRGB", 1),
        (
            "panel_oled.toml",
            PANEL_OLED_SCENE,
            "128X64 1-BIT, FLOYD-STEINBERG",
            2,
        ),
    ] {
        let file = scene_file(name, text)?;
        let lin = file.render_linear().map_err(|d| GalleryError::Geometry {
            image: name,
            object: "scene",
            detail: d.to_string(),
        })?;
        let shown = file.tone(&lin).to_image8();
        panels.push(Panel::new(label, shown, scale * zoom));
    }
    Ok(compose(
        "AN INSTRUMENT PANEL (EXAMPLES/SCENES/PANEL*.TOML)",
        &[panels],
    ))
}
