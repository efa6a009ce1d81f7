//! Image 11: every pixel model on the same small content, magnified.
//!
//! A thin five-pointed star turned off the axes, a 1-px line at 20° and a
//! sliver triangle, 32x24 px, drawn with each `PixelModel` (box exact,
//! seed-001 formula, bed-of-nails 4x4 and 8x8 of seed 000, the 7- and
//! 19-point hexagonal pixels and the cone, Gaussian and Hamming filters of
//! seed 003). The wider filters blur more and ring less; the coarsely
//! sampled ones show their sample lattice along the edges. The summed
//! linear intensity of each panel relative to the box model is logged and
//! printed in its label (the same shapes, so it stays near 0 %: the
//! equal-energy models move energy between pixels, they do not lose it).

use std::f64::consts::PI;

use softedge::{PixelModel, RenderStyle, LIN_MAX};

use super::{compose, lin, pct, sp, GalleryError, Panel};
use crate::image::Image8;
use crate::scene::{render, Primitive, Scene};

/// A model's label on the sheet (the models are shown in
/// `PixelModel::ALL`'s order).
fn label(model: PixelModel) -> &'static str {
    match model {
        PixelModel::Box => "BOX",
        PixelModel::BoxSeed => "BOX SEED-001",
        PixelModel::BedOfNails4 => "BED 4X4",
        PixelModel::BedOfNails8 => "BED 8X8",
        PixelModel::Hex7 => "HEX 7",
        PixelModel::Hex19 => "HEX 19",
        PixelModel::Cone => "CONE R=1",
        PixelModel::Gaussian => "GAUSS S=1/2",
        PixelModel::Hamming => "HAMMING E=2",
        // Non-exhaustive: a new model shows as "?" until it has a label.
        _ => "?",
    }
}

/// The content: 32x24, white on black.
pub(super) fn scene() -> Scene<1> {
    let white = [LIN_MAX];
    let mut s = Scene::new(32, 24, [0]);
    let (cx, cy, r_out, r_in, turn) = (10.3, 11.6, 8.6, 3.1, 0.13);
    let star = (0..10)
        .map(|k| {
            let a = -PI / 2.0 + turn + f64::from(k) * PI / 5.0;
            let r = if k % 2 == 0 { r_out } else { r_in };
            sp(cx + r * a.cos(), cy + r * a.sin())
        })
        .collect();
    s.primitives.push(Primitive::flat_polygon(star, white));
    s.primitives.push(Primitive::Line(softedge::Line::new(
        sp(20.4, 3.3),
        sp(30.6, 7.0),
        [white, white],
    )));
    s.primitives
        .push(Primitive::Triangle(softedge::Triangle::flat(
            [sp(20.2, 21.5), sp(30.8, 12.2), sp(21.4, 21.9)],
            [lin(0.75)],
        )));
    s
}

/// Renders the sheet: two rows of panels, magnified `4 * scale`.
pub(super) fn sheet(
    band_rows: u16,
    scale: u32,
    log: &mut dyn FnMut(&str),
) -> Result<Image8, GalleryError> {
    let base = scene().with_band_rows(band_rows);
    let mut panels = Vec::new();
    let mut box_sum = None;
    for model in PixelModel::ALL {
        let label = label(model);
        let style = RenderStyle {
            antialias: true,
            model,
        };
        let img = render(&base.with_style(style)).map_err(|source| GalleryError::Render {
            image: "pixel models",
            source,
        })?;
        let sum = img.sum() as f64;
        let reference = *box_sum.get_or_insert(sum);
        let rel = sum / reference - 1.0;
        log(&format!(
            "models, {label}: summed intensity {} vs box",
            pct(rel)
        ));
        panels.push(Panel::new(
            &format!("{label} {}", pct(rel)),
            img.to_srgb8(),
            scale * 4,
        ));
    }
    let second = panels.split_off(5);
    Ok(compose(
        "PIXEL MODELS: BOX / BED-OF-NAILS / HEXAGONAL / CONE, GAUSS, HAMMING",
        &[panels, second],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every model of the core has a label of its own on the sheet.
    #[test]
    fn every_pixel_model_has_a_label() {
        let labels: Vec<&str> = PixelModel::ALL.into_iter().map(label).collect();
        for (i, l) in labels.iter().enumerate() {
            assert_ne!(*l, "?", "{:?} has no label", PixelModel::ALL[i]);
            assert!(!labels[..i].contains(l), "{l} twice");
        }
    }
}
