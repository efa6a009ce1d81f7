//! Image 10: the lightness filter of seed 002 beside a plain RGB blur.
//!
//! Four light, colourful frames with jaggies or texture (thin shapes drawn
//! aliased and anti-aliased, a gradient quantised to 2 bits per channel
//! with ordered dithering, fine Gouraud texture) are shown three ways:
//!
//! - plain;
//! - through [`LightnessFilter`]: only CIELAB `L*` is smoothed, `a*` and
//!   `b*` are kept, so edges and dots keep their colour;
//! - through a plain 3x3 box blur of each linear RGB channel (edge pixels
//!   repeated, as the filter does): colours of neighbouring pixels mix, so
//!   a magenta line on a pale ground turns pale pink and two hues meeting
//!   give a third.
//!
//! Three more panels map the per-pixel change: of `L*` by the filter
//! (where it acted), and of colour, `sqrt(Δa*² + Δb*²)`, by the filter and
//! by the blur (black 0, white [`SHIFT_WHITE`] CIELAB units or more). The shifts are measured here in
//! f64, with CIELAB computed from its definition (sRGB primaries, D65
//! white, the CIE `f` with its linear segment), independently of core's
//! fixed-point tables.
//!
//! The scenes are light on purpose: table 4.1 gives `k > 0` only for
//! `L*` 55..97, where the seed found jaggies and texture most visible.

use softedge::postfilter::{FilterStats, LightnessFilter};
use softedge::{Line, RenderStyle, Triangle, LIN_MAX};

use super::{lin, sp, Jitter, PolyColors, Primitive};
use crate::image::{Image8, LinImage};
use crate::scene::{render, RenderError, Scene};

/// Frame size of every scene.
pub(super) const WIDTH: u16 = 48;
pub(super) const HEIGHT: u16 = 32;

/// A colour shift of this many CIELAB units shows as white in the shift
/// maps.
pub(super) const SHIFT_WHITE: f64 = 10.0;

/// Light warm gray ground, `L*` about 75 (`k = 0.1`).
const GROUND: [u16; 3] = [2050, 1950, 1800];

/// Light colours (linear 12-bit), `L*` from 67 (magenta) to 88 (yellow),
/// every channel in `700..=3300`: saturated enough that blurring shows,
/// inside the gamut with room for the filter's lightness changes.
const PALETTE: [[u16; 3]; 6] = [
    [3300, 800, 3300],  // magenta
    [700, 3000, 3300],  // cyan
    [3300, 3100, 700],  // yellow
    [3300, 1700, 700],  // orange
    [1200, 3300, 900],  // green
    [3300, 1800, 2200], // pink
];

/// One frame of the image, its three versions and the measured shifts.
pub(super) struct Comparison {
    /// Row caption.
    pub name: &'static str,
    /// The frame as rendered.
    pub plain: LinImage<3>,
    /// Through the lightness filter.
    pub filtered: LinImage<3>,
    /// What the filter reported.
    pub stats: FilterStats,
    /// Through the 3x3 RGB box blur.
    pub blurred: LinImage<3>,
    /// Shifts of the filter over every pixel.
    pub filter_shift: Shift,
    /// Shifts of the filter over the pixels that stayed inside the RGB
    /// gamut (no channel at 0 or 4095 after a change).
    pub filter_shift_in_gamut: Shift,
    /// Shifts of the blur over every pixel.
    pub blur_shift: Shift,
}

/// The largest change of `a*` and of `b*`, and of `sqrt(Δa*² + Δb*²)`,
/// over a set of pixels.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(super) struct Shift {
    /// Max `|Δa*|`.
    pub a: f64,
    /// Max `|Δb*|`.
    pub b: f64,
    /// Max `sqrt(Δa*² + Δb*²)`.
    pub ab: f64,
}

impl Shift {
    fn add(&mut self, da: f64, db: f64) {
        self.a = self.a.max(da.abs());
        self.b = self.b.max(db.abs());
        self.ab = self.ab.max(da.hypot(db));
    }
}

/// CIELAB `[L*, a*, b*]` of a linear 12-bit sRGB pixel, in f64 from the
/// definitions (IEC 61966-2-1 primaries, D65 white as the matrix's image of
/// RGB white, so grays have `a* = b* = 0`).
pub(super) fn lab(p: [u16; 3]) -> [f64; 3] {
    const M: [[f64; 3]; 3] = [
        [0.412_456_4, 0.357_576_1, 0.180_437_5],
        [0.212_672_9, 0.715_152_2, 0.072_175_0],
        [0.019_333_9, 0.119_192_0, 0.950_304_1],
    ];
    let rgb = p.map(|v| f64::from(v.min(LIN_MAX)) / f64::from(LIN_MAX));
    let row = |r: [f64; 3]| r[0] * rgb[0] + r[1] * rgb[1] + r[2] * rgb[2];
    let white = |r: [f64; 3]| r[0] + r[1] + r[2];
    let d = 6.0 / 29.0;
    let f = |t: f64| {
        if t > d * d * d {
            t.cbrt()
        } else {
            t / (3.0 * d * d) + 4.0 / 29.0
        }
    };
    let [fx, fy, fz] = M.map(|r| f(row(r) / white(r)));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

/// The 3x3 box blur of every linear channel, rounded; neighbours outside
/// the frame repeat the edge pixel.
pub(super) fn box_blur(img: &LinImage<3>) -> LinImage<3> {
    let (w, h) = (img.width(), img.height());
    let mut out = LinImage::new(w, h);
    let mut row = vec![[0u16; 3]; w as usize];
    for y in 0..h {
        for (x, o) in (0..w).zip(row.iter_mut()) {
            let mut sum = [0u32; 3];
            for dy in [-1i64, 0, 1] {
                for dx in [-1i64, 0, 1] {
                    let xx = (i64::from(x) + dx).clamp(0, i64::from(w) - 1) as u32;
                    let yy = (i64::from(y) + dy).clamp(0, i64::from(h) - 1) as u32;
                    for (s, &v) in sum.iter_mut().zip(img.get(xx, yy)) {
                        *s += u32::from(v);
                    }
                }
            }
            *o = sum.map(|s| ((s + 4) / 9) as u16);
        }
        out.set_row(y, &row);
    }
    out
}

/// The frame through [`LightnessFilter::filter_frame`].
fn lightness_filter(img: &LinImage<3>) -> (LinImage<3>, FilterStats) {
    let (w, h) = (img.width(), img.height());
    let input: Vec<[u16; 3]> = img.pixels().collect();
    let mut out = vec![[0u16; 3]; input.len()];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w as u16)];
    // The gallery's frames are small and valid: the filter accepts them.
    let stats = LightnessFilter::new(w as u16, h as u16)
        .and_then(|f| f.filter_frame(&input, &mut out, &mut scratch))
        .unwrap_or_default();
    let mut img = LinImage::new(w, h);
    for (y, row) in out.chunks_exact(w as usize).enumerate() {
        img.set_row(y as u32, row);
    }
    (img, stats)
}

/// Shifts of `after` against `before`: over all pixels, and over pixels
/// that are unchanged or changed without touching the gamut's walls.
fn shifts(before: &LinImage<3>, after: &LinImage<3>) -> (Shift, Shift) {
    let (mut all, mut in_gamut) = (Shift::default(), Shift::default());
    for (p, q) in before.pixels().zip(after.pixels()) {
        let ([_, a0, b0], [_, a1, b1]) = (lab(p), lab(q));
        let (da, db) = (a1 - a0, b1 - b0);
        all.add(da, db);
        let on_wall = p != q && q.iter().any(|&v| v == 0 || v >= LIN_MAX);
        if !on_wall {
            in_gamut.add(da, db);
        }
    }
    (all, in_gamut)
}

/// What a map panel shows of a pixel's change.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Change {
    /// `|ΔL*|`.
    Lightness,
    /// `sqrt(Δa*² + Δb*²)`.
    Colour,
}

/// The per-pixel change as gray: 0 black, [`SHIFT_WHITE`] CIELAB units or
/// more white (linear light, shown as sRGB).
pub(super) fn change_map(before: &LinImage<3>, after: &LinImage<3>, what: Change) -> Image8 {
    let mut map = LinImage::<1>::new(before.width(), before.height());
    let vals: Vec<[u16; 1]> = before
        .pixels()
        .zip(after.pixels())
        .map(|(p, q)| {
            let ([l0, a0, b0], [l1, a1, b1]) = (lab(p), lab(q));
            let d = match what {
                Change::Lightness => (l1 - l0).abs(),
                Change::Colour => (a1 - a0).hypot(b1 - b0),
            };
            [lin(d / SHIFT_WHITE)]
        })
        .collect();
    for (y, row) in vals.chunks_exact(before.width() as usize).enumerate() {
        map.set_row(y as u32, row);
    }
    map.to_srgb8()
}

/// Thin triangles and 1-px lines in the palette on the pale ground.
fn thin_shapes(style: RenderStyle) -> Scene<3> {
    let mut s = Scene::new(WIDTH, HEIGHT, GROUND);
    s.style = style;
    for (k, &c) in PALETTE.iter().enumerate() {
        let y = 2.3 + 4.9 * k as f64;
        // Slivers from 1/2 to 2 px thick, nearly horizontal.
        s.primitives.push(Primitive::Triangle(Triangle::flat(
            [sp(1.4, y), sp(29.0, y + 3.1), sp(1.4, y + 1.3)],
            c,
        )));
    }
    // Lines at steep and shallow angles, crossing each other.
    for (k, &c) in PALETTE.iter().enumerate() {
        let x = 31.2 + 2.6 * k as f64;
        s.primitives.push(Primitive::Line(Line::new(
            sp(x, 1.2),
            sp(x + 6.4 - 1.9 * k as f64, 30.7),
            [c, c],
        )));
    }
    s.primitives.push(Primitive::Polygon {
        vertices: vec![sp(20.3, 19.6), sp(28.7, 28.1), sp(12.2, 30.4)],
        colors: PolyColors::PerVertex(vec![PALETTE[1], PALETTE[0], PALETTE[2]]),
    });
    s
}

/// A light colour gradient, quantised to 8 sRGB levels per channel
/// (a 9-bit colour panel) with 4x4 Bayer dithering. The corners are the
/// palette at 85 %, so the top level used is 6/7 and no pixel sits on the
/// gamut's wall.
fn dithered_gradient() -> Result<LinImage<3>, RenderError> {
    let mut s = Scene::new(WIDTH, HEIGHT, GROUND);
    let (w, h) = (f64::from(WIDTH), f64::from(HEIGHT));
    s.primitives.push(Primitive::Polygon {
        vertices: vec![sp(0.0, 0.0), sp(w, 0.0), sp(w, h), sp(0.0, h)],
        colors: PolyColors::PerVertex(
            [PALETTE[2], PALETTE[1], PALETTE[5], PALETTE[4]]
                .map(|c| c.map(|v| v * 17 / 20))
                .to_vec(),
        ),
    });
    let img = render(&s)?;
    const BAYER4: [[u32; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];
    const LEVELS: f64 = 7.0; // steps between the 8 levels
    let to_srgb = |l: f64| {
        if l <= 0.003_130_8 {
            12.92 * l
        } else {
            1.055 * l.powf(1.0 / 2.4) - 0.055
        }
    };
    let to_linear = |s: f64| {
        if s <= 0.040_45 {
            s / 12.92
        } else {
            ((s + 0.055) / 1.055).powf(2.4)
        }
    };
    let mut out = LinImage::new(img.width(), img.height());
    for y in 0..img.height() {
        let row: Vec<[u16; 3]> = (0..img.width())
            .map(|x| {
                let t = (f64::from(BAYER4[(y % 4) as usize][(x % 4) as usize]) + 0.5) / 16.0;
                img.get(x, y).map(|v| {
                    let s = to_srgb(f64::from(v) / f64::from(LIN_MAX));
                    let q = ((s * LEVELS + t).floor() / LEVELS).min(1.0);
                    lin(to_linear(q))
                })
            })
            .collect();
        out.set_row(y, &row);
    }
    Ok(out)
}

/// A 16x11 grid of 3 px cells split into Gouraud triangles, each vertex a
/// palette colour picked at random: colour texture at the scale of a few
/// pixels.
fn gouraud_texture() -> Scene<3> {
    let mut s = Scene::new(WIDTH, HEIGHT, GROUND);
    let (nx, ny, cell) = (16usize, 11usize, 3.0);
    let mut rng = Jitter(0x0B5E_55ED);
    let colors: Vec<Vec<[u16; 3]>> = (0..=ny)
        .map(|_| {
            (0..=nx)
                .map(|_| {
                    let k = ((rng.next() + 1.0) / 2.0 * PALETTE.len() as f64) as usize;
                    PALETTE[k.min(PALETTE.len() - 1)]
                })
                .collect()
        })
        .collect();
    let p = |i: usize, j: usize| sp(i as f64 * cell, j as f64 * cell - 0.5);
    for j in 0..ny {
        for i in 0..nx {
            let c = |di: usize, dj: usize| colors[j + dj][i + di];
            s.primitives.push(Primitive::Triangle(Triangle::new(
                [p(i, j), p(i + 1, j), p(i + 1, j + 1)],
                [c(0, 0), c(1, 0), c(1, 1)],
            )));
            s.primitives.push(Primitive::Triangle(Triangle::new(
                [p(i, j), p(i + 1, j + 1), p(i, j + 1)],
                [c(0, 0), c(1, 1), c(0, 1)],
            )));
        }
    }
    s
}

/// The four frames, each filtered and blurred, with their shifts.
pub(super) fn comparisons(band_rows: u16) -> Result<Vec<Comparison>, RenderError> {
    let frames = [
        (
            "ALIASED THIN SHAPES",
            render(&thin_shapes(RenderStyle::ALIASED).with_band_rows(band_rows))?,
        ),
        (
            "AA THIN SHAPES",
            render(&thin_shapes(RenderStyle::default()).with_band_rows(band_rows))?,
        ),
        ("DITHERED 3-BIT GRADIENT", dithered_gradient()?),
        (
            "FINE GOURAUD TEXTURE",
            render(&gouraud_texture().with_band_rows(band_rows))?,
        ),
    ];
    Ok(frames
        .into_iter()
        .map(|(name, plain)| {
            let (filtered, stats) = lightness_filter(&plain);
            let blurred = box_blur(&plain);
            let (filter_shift, filter_shift_in_gamut) = shifts(&plain, &filtered);
            let (blur_shift, _) = shifts(&plain, &blurred);
            Comparison {
                name,
                plain,
                filtered,
                stats,
                blurred,
                filter_shift,
                filter_shift_in_gamut,
                blur_shift,
            }
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lab_of_white_gray_and_primaries() {
        let [l, a, b] = lab([LIN_MAX; 3]);
        assert!((l - 100.0).abs() < 1e-9 && a.abs() < 1e-9 && b.abs() < 1e-9);
        let [l, a, b] = lab([737; 3]); // 18 % gray: L* 49.5
        assert!((l - 49.5).abs() < 0.1 && a.abs() < 1e-9 && b.abs() < 1e-9);
        // Published sRGB red: L* 53.24, a* 80.09, b* 67.20.
        let [l, a, b] = lab([LIN_MAX, 0, 0]);
        assert!((l - 53.24).abs() < 0.05, "{l}");
        assert!((a - 80.09).abs() < 0.1, "{a}");
        assert!((b - 67.20).abs() < 0.1, "{b}");
        assert_eq!(lab([0; 3])[0], 0.0);
    }

    #[test]
    fn box_blur_keeps_flat_frames_and_averages_a_dot() {
        let mut img = LinImage::<3>::new(3, 3);
        img.set_row(1, &[[0; 3], [900, 0, 90], [0; 3]]);
        let b = box_blur(&img);
        assert_eq!(b.get(0, 0), &[100, 0, 10]);
        assert_eq!(b.get(1, 1), &[100, 0, 10]);
        let mut flat = LinImage::<3>::new(2, 2);
        for y in 0..2 {
            flat.set_row(y, &[[7, 8, 9]; 2]);
        }
        assert_eq!(box_blur(&flat), flat);
    }

    #[test]
    fn filter_keeps_colours_and_the_blur_does_not() {
        for c in comparisons(8).unwrap() {
            assert!(c.stats.changed > 100, "{}: {:?}", c.name, c.stats);
            // Seed 002's promise, away from the gamut's walls.
            assert!(
                c.filter_shift_in_gamut.a <= 1.0 && c.filter_shift_in_gamut.b <= 1.0,
                "{}: {:?}",
                c.name,
                c.filter_shift_in_gamut
            );
            assert!(c.blur_shift.ab > 10.0, "{}: {:?}", c.name, c.blur_shift);
            assert_ne!(c.plain, c.filtered, "{}", c.name);
        }
    }
}
