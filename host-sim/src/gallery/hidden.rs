//! Image 11: hidden surfaces (seed 004) on the example scene
//! `examples/scenes/hidden_surfaces.toml`: a tilted torus, a sphere cutting
//! into it, a cylinder through its hole and a card with per-corner depths
//! slicing through the ring; without hidden-surface removal, with the
//! z-buffer aliased and anti-aliased, with Warnock's subdivision (edges
//! resolved by area) and Weiler–Atherton's disjoint visible polygons
//! (anti-aliased intersection curves too, with both), and the section at
//! depth 0.5.

use std::path::Path;

use softedge::style::Blend;
use softedge::RenderStyle;

use super::{compose, GalleryError, Panel};
use crate::image::{Image8, LinImage};
use crate::scene::{render, Hsr, Scene};
use crate::scene_file::{parse, Frame};

const SCENE: &str = include_str!("../../../examples/scenes/hidden_surfaces.toml");
const SECTION: &str = include_str!("../../../examples/scenes/section.toml");

/// The RGB scene of a scene file's text.
fn scene(name: &str, text: &str) -> Result<Scene<3>, GalleryError> {
    let file = parse(Path::new(name), text).map_err(|d| GalleryError::Geometry {
        image: "hidden-surfaces",
        object: "scene file",
        detail: d.to_string(),
    })?;
    match file.frame {
        Frame::Rgb(s) => Ok(s),
        Frame::Gray(_) => Err(GalleryError::Geometry {
            image: "hidden-surfaces",
            object: "scene file",
            detail: "expected an RGB scene".into(),
        }),
    }
}

/// The panels' scenes: label and scene.
pub(super) fn variants(band_rows: u16) -> Result<Vec<(&'static str, Scene<3>)>, GalleryError> {
    let z = scene("hidden_surfaces.toml", SCENE)?.with_band_rows(band_rows);
    let none = Scene {
        hsr: Hsr::None,
        blend: Blend::Add,
        ..z.clone()
    };
    let aliased = z.with_style(RenderStyle::ALIASED);
    let weiler = Scene {
        hsr: Hsr::WeilerAtherton,
        ..z.clone()
    };
    let warnock = Scene {
        hsr: Hsr::Warnock,
        ..z.clone()
    };
    let section = scene("section.toml", SECTION)?.with_band_rows(band_rows);
    Ok(vec![
        ("NO HSR: SURFACES ADD", none),
        ("Z-BUFFER, ALIASED", aliased),
        ("Z-BUFFER, ANTI-ALIASED", z),
        ("WARNOCK", warnock),
        ("WEILER-ATHERTON", weiler),
        ("SECTION AT DEPTH 0.5", section),
    ])
}

/// The sheet: the variants side by side, three per row.
pub(super) fn sheet(
    band_rows: u16,
    scale: u32,
    log: &mut dyn FnMut(&str),
) -> Result<Image8, GalleryError> {
    let mag = (scale / 2).max(1);
    let mut panels: Vec<Panel> = Vec::new();
    for (label, s) in variants(band_rows)? {
        let img: LinImage<3> = render(&s).map_err(|source| GalleryError::Render {
            image: "hidden-surfaces",
            source,
        })?;
        log(&format!(
            "      {}: {} primitives",
            label.to_lowercase(),
            s.primitives.len()
        ));
        panels.push(Panel::new(label, img.to_srgb8(), mag));
    }
    let mut rows = Vec::new();
    while !panels.is_empty() {
        let rest = panels.split_off(panels.len().min(3));
        rows.push(panels);
        panels = rest;
    }
    Ok(compose(
        "HIDDEN SURFACES (SEED 004): NONE / Z-BUFFER / WARNOCK / WEILER-ATHERTON / SECTION",
        &rows,
    ))
}
