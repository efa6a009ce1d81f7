//! The γ ramp: one gray frame shown on a simulated γ = 2.4 display twice,
//! with linear codes and through the γ table.
//!
//! The frame (128x56, linear light) holds, top to bottom:
//!
//! - a horizontal Gouraud ramp `0..4095`;
//! - three blocks that all emit half of white on a linear display: six
//!   1-px lines centred on pixel rows (full rows, then empty ones), the same
//!   six lines moved down half a pixel (every row half covered), and a flat
//!   polygon of intensity 2048;
//! - nine 1x1 px squares and nine short vertical 1-px lines, each 1/8 px
//!   further right than the one before (from pixel-aligned to half a pixel
//!   off, where each pixel they touch is half covered, and back).
//!
//! Without correction the half-covered blocks, squares and lines come out
//! far darker than the aligned ones (seed 000: `2 (1/2)^2.4 = 0.38`, -62 %);
//! with the table they match.

use softedge::{Line, LIN_MAX};

use super::display::Codes;
use super::{sp, PolyColors, Primitive};
use crate::font::draw_text;
use crate::image::{Image8, LinImage};
use crate::scene::Scene;

/// Frame size.
pub(super) const WIDTH: u16 = 128;
pub(super) const HEIGHT: u16 = 56;

/// Top row of the stripe blocks and the row of the squares.
const STRIPES_Y: f64 = 26.0;
const STRIPE_LINES: usize = 6;
const DOTS_Y: f64 = 48.0;
/// Left edges of the three stripe blocks, and their width.
const BLOCKS_X: [f64; 3] = [4.0, 46.0, 88.0];
const BLOCK_W: f64 = 36.0;
/// Where the squares start, their pitch, and the sub-pixel step.
const DOTS_X: f64 = 4.0;
const LINES_X: f64 = 68.5;
const PITCH: f64 = 7.0;
const STEP: f64 = 1.0 / 8.0;

/// Captions, drawn on the viewed image (not part of the frame).
const CAPTIONS: [(i64, i64, &str); 5] = [
    (4, 1, "LINEAR RAMP 0-4095"),
    (4, 19, "ON ROWS"),
    (46, 19, "ON EDGES"),
    (88, 19, "FLAT 1/2"),
    (4, 40, "1 PX DOTS, LINES: 1/8 PX STEPS"),
];
const CAPTION: [u8; 1] = [150];

/// The frame.
pub(super) fn scene() -> Scene<1> {
    let mut s = Scene::new(WIDTH, HEIGHT, [0]);
    let (w, top, bottom) = (f64::from(WIDTH), 7.0, 17.0);
    s.primitives.push(Primitive::Polygon {
        vertices: vec![sp(0.0, top), sp(w, top), sp(w, bottom), sp(0.0, bottom)],
        colors: PolyColors::PerVertex(vec![[0], [LIN_MAX], [LIN_MAX], [0]]),
    });
    for (block, &x0) in BLOCKS_X.iter().enumerate() {
        let x1 = x0 + BLOCK_W;
        match block {
            0 | 1 => {
                // Centred on a row (y + 1/2) or on the border between two.
                let shift = if block == 0 { 0.5 } else { 1.0 };
                for k in 0..STRIPE_LINES {
                    let y = STRIPES_Y + shift + 2.0 * k as f64;
                    s.primitives.push(Primitive::Line(Line::new(
                        sp(x0, y),
                        sp(x1, y),
                        [[LIN_MAX]; 2],
                    )));
                }
            }
            _ => {
                let y1 = STRIPES_Y + 2.0 * STRIPE_LINES as f64;
                s.primitives.push(Primitive::flat_polygon(
                    vec![sp(x0, STRIPES_Y), sp(x1, STRIPES_Y), sp(x1, y1), sp(x0, y1)],
                    [LIN_MAX.div_ceil(2)],
                ));
            }
        }
    }
    for k in 0..9 {
        let f = k as f64 * STEP;
        let x = DOTS_X + PITCH * k as f64 + f;
        s.primitives.push(Primitive::flat_polygon(
            vec![
                sp(x, DOTS_Y),
                sp(x + 1.0, DOTS_Y),
                sp(x + 1.0, DOTS_Y + 1.0),
                sp(x, DOTS_Y + 1.0),
            ],
            [LIN_MAX],
        ));
        let lx = LINES_X + PITCH * k as f64 + f;
        s.primitives.push(Primitive::Line(Line::new(
            sp(lx, DOTS_Y - 2.0),
            sp(lx, DOTS_Y + 5.0),
            [[LIN_MAX]; 2],
        )));
    }
    s
}

/// The frame as the simulated display shows it, with captions.
pub(super) fn view(img: &LinImage<1>, codes: Codes) -> Image8 {
    let mut out = super::display::show(img, codes);
    for (x, y, text) in CAPTIONS {
        draw_text(&mut out, x, y, 1, text, &CAPTION);
    }
    out
}

/// Light emitted over the `w x h` px rectangle at `(x, y)`, in pixels of
/// full white.
fn emitted(img: &LinImage<1>, codes: Codes, x: u32, y: u32, w: u32, h: u32) -> f64 {
    let mut sum = 0.0;
    for yy in y..(y + h).min(img.height()) {
        for xx in x..(x + w).min(img.width()) {
            sum += codes.emitted(img.get(xx, yy)[0]);
        }
    }
    sum
}

/// What the display does to half-covered pixels, relative to the aligned
/// version of the same thing (`-0.62` is 62 % too dark).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct HalfCover {
    /// The square half a pixel right (two pixels, half each) against the
    /// aligned square.
    pub square: f64,
    /// The stripe block on row borders against the one on rows.
    pub stripes: f64,
}

/// Measures [`HalfCover`] on a rendered frame.
pub(super) fn half_cover(img: &LinImage<1>, codes: Codes) -> HalfCover {
    let dot = |k: u32| {
        let x = DOTS_X as u32 + PITCH as u32 * k;
        emitted(img, codes, x, DOTS_Y as u32, 2, 1)
    };
    let block = |b: usize| {
        emitted(
            img,
            codes,
            BLOCKS_X[b] as u32,
            STRIPES_Y as u32,
            BLOCK_W as u32,
            2 * STRIPE_LINES as u32,
        )
    };
    HalfCover {
        square: dot(4) / dot(0) - 1.0,
        stripes: block(1) / block(0) - 1.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::render;

    #[test]
    fn half_covered_pixels_lose_62_percent_without_the_table() {
        let img = render(&scene()).unwrap();
        let bad = half_cover(&img, Codes::Uncorrected);
        let good = half_cover(&img, Codes::Corrected);
        for v in [bad.square, bad.stripes] {
            assert!((-0.63..-0.61).contains(&v), "uncorrected {v}");
        }
        for v in [good.square, good.stripes] {
            assert!(v.abs() < 0.01, "corrected {v}");
        }
    }

    #[test]
    fn the_ramp_rises_and_the_blocks_hold_half_of_white() {
        let img = render(&scene()).unwrap();
        let row: Vec<u16> = (0..u32::from(WIDTH)).map(|x| img.get(x, 12)[0]).collect();
        assert!(row.windows(2).all(|w| w[0] < w[1]));
        let lin = |b: usize| {
            let mut s = 0u64;
            for y in 0..12 {
                for x in 0..BLOCK_W as u32 {
                    s += u64::from(img.get(BLOCKS_X[b] as u32 + x, STRIPES_Y as u32 + y)[0]);
                }
            }
            s
        };
        let (rows, edges, flat) = (lin(0), lin(1), lin(2));
        // The same light in each block, up to the one rounding per pixel
        // (half of 4095 is 2047.5, resolved to 2048).
        let pixels = 12 * BLOCK_W as u64;
        assert!(edges.abs_diff(rows) <= pixels, "{edges} vs {rows}");
        assert!(flat.abs_diff(rows) <= pixels, "{flat} vs {rows}");
    }
}
