//! # softedge-workloads
//!
//! The triangles of the Cortex-M0 benchmark (`boards/bench-m0`) and of the
//! host bench (`softedge-sim`'s `bench` binary): the same bytes on both,
//! generated at compile time by `const fn`s from fixed seeds, so a count
//! measured on one side can be set beside the other's.
//!
//! - [`SMALL`], [`MEDIUM`], [`LARGE`]: [`COUNT`] random triangles each, mean
//!   areas about 27, 437 and 3 900 px² (measured: 28.5, 434.8, 3 814.8),
//!   inside a [`FRAME`] x [`FRAME`] frame.
//! - [`SCREEN`]: 132 triangles covering the frame exactly once, an 11 x 6
//!   grid of cells each split along its diagonal into two triangles of
//!   about 436 px².
//!
//! - [`WELL_SMALL`], [`WELL_MEDIUM`], [`WELL_LARGE`]: [`COUNT`]
//!   well-shaped random triangles each (random size, rotation and 1/16-px
//!   position, no angle below 40°), mean areas about 27, 437 and 3 900 px².
//!
//! Vertices are on a 1/16-px grid ([`Tri`]); those of every workload but
//! the well-shaped ones are whole pixels, so embedded-graphics (integer
//! `Point`s) draws the same triangles as softedge; the well-shaped ones it
//! draws rounded to whole pixels ([`Tri::px`]). Both put a whole-pixel
//! vertex `(x, y)` at the centre of pixel `(x, y)`
//! (`FinePoint::centre_of`); the areas below are the exact areas,
//! `|cross| / 2`.
//!
//! ## How a random triangle is made
//!
//! A class has a box side `L` ([`SIDE_SMALL`], ...): the box's top-left
//! corner is uniform in `0..FRAME-L` on each axis, the three vertices
//! uniform in the box `[x0, x0+L] x [y0, y0+L]` (integers, so every vertex
//! lies in `0..=FRAME-1`), and a triangle of zero area is drawn again. The
//! mean area of a triangle with uniform vertices in a square of side `L` is
//! `11 L² / 144`, which gives the sides (18, 75, 226 px); the shapes are
//! those of random triangles, slivers included. Colours are linear 12-bit,
//! uniform in `0..=4095`, per channel and per vertex. All draws come, in a
//! fixed order (box x, box y, vertex 0 x, y, vertex 1, vertex 2, then the
//! nine colours), from one [`Pcg32`] stream per workload.
//!
//! ## The marginal cost per pixel
//!
//! A benchmark renders a whole frame with `N` = 0, 1 and [`COUNT`]
//! triangles of a workload; `(insns(COUNT) - insns(1)) /`
//! [`Workload::marginal_area`] is the cost per pixel of triangle area, the
//! frame's fixed cost and the first triangle's set-up taken out
//! ([`Workload::prefix`] gives the first `N`).
//!
//! With the feature `render`, [`render`] has the frames both benchmarks
//! measure (softedge's renderers and embedded-graphics' triangle fill).
//!
//! ```
//! use softedge_workloads::{COUNT, MEDIUM, SCREEN};
//! assert_eq!(MEDIUM.tris.len(), COUNT);
//! assert_eq!(MEDIUM.prefix(1).len(), 1);
//! // Instructions of a frame with 1 and with all triangles, say:
//! let (one, all) = (3_500_000u64, 580_000_000u64);
//! let per_px = (all - one) as f64 / MEDIUM.marginal_area() as f64;
//! assert!(per_px > 600.0 && per_px < 700.0);
//! assert_eq!(SCREEN.twice_area(), 2 * 240 * 240);
//! ```
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod pcg;
#[cfg(feature = "render")]
pub mod render;

pub use pcg::Pcg32;

/// Width and height of the frame, in pixels.
pub const FRAME: u16 = 240;
/// Triangles of each random workload.
pub const COUNT: usize = 2000;
/// Box side of [`SMALL`]'s triangles, px: `11 L² / 144 = 24.75` px² before
/// zero-area triangles are drawn again.
pub const SIDE_SMALL: u16 = 18;
/// Box side of [`MEDIUM`]'s triangles, px (`11 L² / 144 = 429.7` px²).
pub const SIDE_MEDIUM: u16 = 75;
/// Box side of [`LARGE`]'s triangles, px (`11 L² / 144 = 3 901.8` px²).
pub const SIDE_LARGE: u16 = 226;
/// Columns of [`SCREEN`]'s grid.
pub const SCREEN_COLS: u16 = 11;
/// Rows of [`SCREEN`]'s grid.
pub const SCREEN_ROWS: u16 = 6;
/// The PCG stream (`initseq`) every workload draws from; the workloads
/// differ by their `initstate` seed.
const STREAM: u64 = 0x5eed;

/// One triangle: vertices on a 1/16-px grid and a linear 12-bit RGB colour
/// per vertex. Flat renderers use [`flat_rgb`](Self::flat_rgb) (vertex 0's
/// colour), gray ones [`gray`](Self::gray).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tri {
    /// Vertices `[x, y]` in 1/16 px, `0..=16 FRAME` (`16 x` is pixel `x`:
    /// whole pixels for every workload but the well-shaped ones;
    /// [`px`](Self::px) gives them rounded).
    pub v: [[i16; 2]; 3],
    /// Linear 12-bit colour `[r, g, b]` of each vertex, `0..=4095`.
    pub rgb: [[u16; 3]; 3],
}

impl Tri {
    const ZERO: Tri = Tri {
        v: [[0; 2]; 3],
        rgb: [[0; 3]; 3],
    };

    /// Twice the exact area in 1/256 px² (`|cross product|` of two edges,
    /// in 1/16 px).
    pub const fn twice_area_256(&self) -> u32 {
        let [[x0, y0], [x1, y1], [x2, y2]] = self.v;
        let (x0, y0) = (x0 as i32, y0 as i32);
        let cross = (x1 as i32 - x0) * (y2 as i32 - y0) - (x2 as i32 - x0) * (y1 as i32 - y0);
        cross.unsigned_abs()
    }

    /// Twice the area in px², rounded (exact for whole-pixel vertices).
    pub const fn twice_area(&self) -> u32 {
        (self.twice_area_256() + 128) / 256
    }

    /// The vertices rounded to whole pixels (what embedded-graphics, whose
    /// `Point`s are whole pixels, draws).
    pub const fn px(&self) -> [[i32; 2]; 3] {
        let mut out = [[0; 2]; 3];
        let mut i = 0;
        while i < 3 {
            out[i] = [
                (self.v[i][0] as i32 + 8) >> 4,
                (self.v[i][1] as i32 + 8) >> 4,
            ];
            i += 1;
        }
        out
    }

    /// The colour of a flat-shaded triangle: vertex 0's.
    pub const fn flat_rgb(&self) -> [u16; 3] {
        self.rgb[0]
    }

    /// The intensity of a flat gray triangle: vertex 0's green.
    pub const fn gray(&self) -> u16 {
        self.rgb[0][1]
    }
}

/// A named list of triangles.
#[derive(Debug, Clone, Copy)]
pub struct Workload {
    /// Short name, used in the benchmarks' output (`small`, `medium`,
    /// `large`, `screen`).
    pub name: &'static str,
    /// The triangles, drawn in this order.
    pub tris: &'static [Tri],
}

impl Workload {
    /// The first `n` triangles (all of them when `n` is larger).
    pub fn prefix(&self, n: usize) -> &'static [Tri] {
        self.tris.get(..n).unwrap_or(self.tris)
    }

    /// Twice the summed exact area of all triangles, px².
    pub const fn twice_area(&self) -> u64 {
        twice_area_sum(self.tris)
    }

    /// Twice the summed area of triangles `2..=N` (all but the first): the
    /// denominator of the marginal cost per pixel.
    pub const fn twice_marginal_area(&self) -> u64 {
        match self.tris.split_first() {
            Some((_, rest)) => twice_area_sum(rest),
            None => 0,
        }
    }

    /// Summed area of triangles `2..=N`, px², rounded down.
    pub const fn marginal_area(&self) -> u64 {
        self.twice_marginal_area() / 2
    }
}

/// Twice the summed exact area of `tris`, px², rounded (exact for
/// whole-pixel vertices).
pub const fn twice_area_sum(tris: &[Tri]) -> u64 {
    let mut sum = 0u64;
    let mut k = 0;
    while k < tris.len() {
        sum += tris[k].twice_area_256() as u64;
        k += 1;
    }
    (sum + 128) / 256
}

/// `n` random triangles with vertices in boxes of side `side` (see the
/// crate docs), from the stream seeded `seed`.
const fn random_triangles<const N: usize>(seed: u64, side: u16) -> [Tri; N] {
    let mut rng = Pcg32::new(seed, STREAM);
    let mut out = [Tri::ZERO; N];
    // Box corners in 0..FRAME-side: vertices end at FRAME-1 at most.
    let corners = (FRAME - side) as u32;
    let mut k = 0;
    while k < N {
        let x0 = rng.below(corners) as i16;
        let y0 = rng.below(corners) as i16;
        let mut t = Tri::ZERO;
        let mut i = 0;
        while i < 3 {
            let x = x0 + rng.below(side as u32 + 1) as i16;
            let y = y0 + rng.below(side as u32 + 1) as i16;
            t.v[i] = [16 * x, 16 * y];
            i += 1;
        }
        if t.twice_area() == 0 {
            continue;
        }
        t.rgb = random_colors(&mut rng);
        out[k] = t;
        k += 1;
    }
    out
}

/// Nine uniform linear 12-bit values: `[r, g, b]` of three vertices.
const fn random_colors(rng: &mut Pcg32) -> [[u16; 3]; 3] {
    let mut rgb = [[0u16; 3]; 3];
    let mut i = 0;
    while i < 9 {
        rgb[i / 3][i % 3] = rng.below(4096) as u16;
        i += 1;
    }
    rgb
}

/// Whole pixel `(x, y)` on the 1/16-px grid of [`Tri`].
const fn px(x: i16, y: i16) -> [i16; 2] {
    [16 * x, 16 * y]
}

/// Triangles of [`SCREEN`].
pub const SCREEN_LEN: usize = 2 * SCREEN_COLS as usize * SCREEN_ROWS as usize;

/// The screen: column `i` of the grid spans `[x_i, x_{i+1}]` with
/// `x_i = round(i * FRAME / 11)` (cells 21 or 22 px wide), row `j` spans
/// `[40 j, 40 (j + 1)]`; each cell is split along its top-left to
/// bottom-right diagonal, the upper-right triangle first. Random colours
/// as for the random workloads. With `slant`, each cell's bottom corners
/// are `slant` px right of its top ones (parallelograms: no edge is
/// vertical; the frame's left edge shows a sliver of background, the
/// right column reaches past the frame).
const fn screen_triangles(seed: u64, slant: i16) -> [Tri; SCREEN_LEN] {
    let mut rng = Pcg32::new(seed, STREAM);
    let mut out = [Tri::ZERO; SCREEN_LEN];
    let (cols, rows, frame) = (SCREEN_COLS as i32, SCREEN_ROWS as i32, FRAME as i32);
    let mut k = 0;
    let mut j = 0;
    while j < rows {
        let (y0, y1) = ((j * frame / rows) as i16, ((j + 1) * frame / rows) as i16);
        let mut i = 0;
        while i < cols {
            let x0 = ((2 * i * frame + cols) / (2 * cols)) as i16;
            let x1 = ((2 * (i + 1) * frame + cols) / (2 * cols)) as i16;
            let (b0, b1) = (x0 + slant, x1 + slant);
            out[k] = Tri {
                v: [px(x0, y0), px(x1, y0), px(b1, y1)],
                rgb: random_colors(&mut rng),
            };
            out[k + 1] = Tri {
                v: [px(x0, y0), px(b1, y1), px(b0, y1)],
                rgb: random_colors(&mut rng),
            };
            k += 2;
            i += 1;
        }
        j += 1;
    }
    out
}

/// `sin` of `x` radians, `|x| <= 2 pi` (Taylor series around the nearest
/// multiple of pi/2: error below 1e-12 there; compile time only).
const fn sin(x: f64) -> f64 {
    const PI: f64 = core::f64::consts::PI;
    // Reduce to [-pi, pi], then to [-pi/2, pi/2] by sin(pi - x) = sin(x).
    let mut x = x;
    while x > PI {
        x -= 2.0 * PI;
    }
    while x < -PI {
        x += 2.0 * PI;
    }
    if x > PI / 2.0 {
        x = PI - x;
    } else if x < -PI / 2.0 {
        x = -PI - x;
    }
    let (mut term, mut sum, mut n) = (x, x, 1.0);
    while n < 40.0 {
        term = -term * x * x / ((n + 1.0) * (n + 2.0));
        sum += term;
        n += 2.0;
    }
    sum
}

/// `sqrt(a)`, `a >= 0` (Newton's iteration; compile time only).
const fn sqrt(a: f64) -> f64 {
    if a <= 0.0 {
        return 0.0;
    }
    let mut x = if a > 1.0 { a } else { 1.0 };
    let mut k = 0;
    while k < 64 {
        x = 0.5 * (x + a / x);
        k += 1;
    }
    x
}

/// `x` rounded to the nearest integer, halves away from zero.
const fn round(x: f64) -> i32 {
    if x >= 0.0 {
        (x + 0.5) as i32
    } else {
        (x - 0.5) as i32
    }
}

/// `n` well-shaped random triangles of mean area about `area` px² (see the
/// crate docs): each inscribed in a circle of random centre (1/16 px) and
/// radius, its vertices `120° ± 20°` apart from a random rotation, so no
/// angle is below 40°; from the stream seeded `seed`.
const fn well_shaped_triangles<const N: usize>(seed: u64, area: u32) -> [Tri; N] {
    const DEG: f64 = core::f64::consts::PI / 180.0;
    let mut rng = Pcg32::new(seed, STREAM);
    let mut out = [Tri::ZERO; N];
    let mut k = 0;
    while k < N {
        // The area uniform in [area / 2, 3 area / 2]; a triangle inscribed
        // in radius r with central angles near 120° has about 3 sqrt(3) /
        // 4 r² (the equilateral's; within 6 % for these angles).
        let a = area as f64 * (0.5 + rng.below(1001) as f64 / 1000.0);
        let r = sqrt(a / 1.299_038_105_676_658);
        let r16 = 16.0 * r;
        // The centre at least r + 1 px from the frame's edges.
        let margin = 16 * (r as i32 + 2);
        let span = (16 * FRAME as i32 - 2 * margin) as u32;
        let cx = margin + rng.below(span) as i32;
        let cy = margin + rng.below(span) as i32;
        let theta = rng.below(360 * 16) as f64 / 16.0;
        let j1 = rng.below(41) as f64 - 20.0;
        let j2 = rng.below(41) as f64 - 20.0;
        let angles = [theta, theta + 120.0 + j1, theta + 240.0 + j2];
        let mut t = Tri::ZERO;
        let mut i = 0;
        while i < 3 {
            let phi = angles[i] * DEG;
            let x = cx + round(r16 * sin(phi + 90.0 * DEG));
            let y = cy + round(r16 * sin(phi));
            t.v[i] = [x as i16, y as i16];
            i += 1;
        }
        if t.twice_area_256() == 0 {
            continue;
        }
        t.rgb = random_colors(&mut rng);
        out[k] = t;
        k += 1;
    }
    out
}

static SMALL_TRIS: [Tri; COUNT] = random_triangles(27, SIDE_SMALL);
static MEDIUM_TRIS: [Tri; COUNT] = random_triangles(437, SIDE_MEDIUM);
static LARGE_TRIS: [Tri; COUNT] = random_triangles(3900, SIDE_LARGE);
static SCREEN_TRIS: [Tri; SCREEN_LEN] = screen_triangles(132, 0);
static SLANTED_TRIS: [Tri; SCREEN_LEN] = screen_triangles(132, SLANT);

/// How far right [`SLANTED`]'s cells' bottom corners are of their top
/// ones, px (over 40 px).
pub const SLANT: i16 = 7;

/// [`COUNT`] random triangles of mean area about 27 px².
pub static SMALL: Workload = Workload {
    name: "small",
    tris: &SMALL_TRIS,
};
/// [`COUNT`] random triangles of mean area about 437 px².
pub static MEDIUM: Workload = Workload {
    name: "medium",
    tris: &MEDIUM_TRIS,
};
/// [`COUNT`] random triangles of mean area about 3 900 px².
pub static LARGE: Workload = Workload {
    name: "large",
    tris: &LARGE_TRIS,
};
/// The 132-triangle screen covering the frame once.
pub static SCREEN: Workload = Workload {
    name: "screen",
    tris: &SCREEN_TRIS,
};

/// [`SCREEN`] with its cells slanted ([`SLANT`] px right over each row
/// of cells, the same colours): the same structure without vertical
/// edges, which `softedge` walks without set-up or state (measured
/// beside the screen, so that what that path gives the screen shows).
pub static SLANTED: Workload = Workload {
    name: "slanted",
    tris: &SLANTED_TRIS,
};

/// The three random workloads, small to large.
pub static CLASSES: [&Workload; 3] = [&SMALL, &MEDIUM, &LARGE];

static WELL_SMALL_TRIS: [Tri; COUNT] = well_shaped_triangles(2700, 27);
static WELL_MEDIUM_TRIS: [Tri; COUNT] = well_shaped_triangles(43700, 437);
static WELL_LARGE_TRIS: [Tri; COUNT] = well_shaped_triangles(390000, 3900);

/// [`COUNT`] well-shaped random triangles (no angle below 40°, random size,
/// rotation and 1/16-px position) of mean area about 27 px².
pub static WELL_SMALL: Workload = Workload {
    name: "wsmall",
    tris: &WELL_SMALL_TRIS,
};
/// As [`WELL_SMALL`], about 437 px².
pub static WELL_MEDIUM: Workload = Workload {
    name: "wmedium",
    tris: &WELL_MEDIUM_TRIS,
};
/// As [`WELL_SMALL`], about 3 900 px².
pub static WELL_LARGE: Workload = Workload {
    name: "wlarge",
    tris: &WELL_LARGE_TRIS,
};

/// The three well-shaped workloads, small to large: the shapes a mesh or a
/// user interface has, beside [`CLASSES`]' uniform vertices (about a
/// third of them slivers).
pub static WELL_CLASSES: [&Workload; 3] = [&WELL_SMALL, &WELL_MEDIUM, &WELL_LARGE];

#[cfg(test)]
mod tests {
    use super::*;

    fn mean_area(w: &Workload) -> f64 {
        w.twice_area() as f64 / 2.0 / w.tris.len() as f64
    }

    #[test]
    fn mean_areas_are_those_of_the_size_classes() {
        for (w, target) in [(&SMALL, 27.0), (&MEDIUM, 437.0), (&LARGE, 3900.0)] {
            assert_eq!(w.tris.len(), COUNT);
            let m = mean_area(w);
            // 2 000 random triangles: the sample mean's standard error is
            // about 2 % of the mean; 28.5, 434.8 and 3 814.8 are measured.
            assert!((m / target - 1.0).abs() < 0.06, "{}: {m}", w.name);
        }
    }

    #[test]
    fn workloads_are_reproducible() {
        // Twice the summed areas, computed by an independent Python
        // implementation of the same generator (PCG32 from its reference
        // description): any change to the stream or the draw order shows.
        assert_eq!(SMALL.twice_area(), 113_965);
        assert_eq!(MEDIUM.twice_area(), 1_739_248);
        assert_eq!(LARGE.twice_area(), 15_259_116);
        assert_eq!(
            SMALL.tris[0].v,
            [[185, 13], [183, 13], [180, 10]].map(|[x, y]| [16 * x, 16 * y])
        );
        assert_eq!(
            SMALL.tris[0].rgb,
            [[257, 1133, 405], [823, 325, 1007], [476, 3924, 2304]]
        );
    }

    #[test]
    fn vertices_lie_in_the_frame_and_no_triangle_is_degenerate() {
        for w in CLASSES {
            for t in w.tris {
                assert!(t.twice_area() > 0);
                for [x, y] in t.px() {
                    assert!(
                        (0..i32::from(FRAME)).contains(&x) && (0..i32::from(FRAME)).contains(&y)
                    );
                }
                assert!(t.v.iter().flatten().all(|&c| c % 16 == 0));
                assert!(t.rgb.iter().flatten().all(|&c| c <= 4095));
            }
        }
    }

    #[test]
    fn marginal_area_leaves_out_the_first_triangle() {
        for w in CLASSES.iter().copied().chain([&SCREEN]) {
            let first = u64::from(w.tris[0].twice_area());
            assert_eq!(w.twice_marginal_area() + first, w.twice_area());
            assert_eq!(w.prefix(1).len(), 1);
            assert_eq!(w.prefix(0).len(), 0);
            assert_eq!(w.prefix(usize::MAX).len(), w.tris.len());
        }
    }

    /// Is the pixel centre `(x + 1/2, y + 1/2)` strictly inside `t`?
    /// (Exact, in doubled coordinates.)
    fn centre_inside(t: &Tri, x: i32, y: i32) -> bool {
        // In 1/32 px: the centre of the pixel whose top-left corner is
        // whole-pixel vertex (x, y).
        let (px, py) = (32 * x + 16, 32 * y + 16);
        let p = t.v.map(|[vx, vy]| (2 * i32::from(vx), 2 * i32::from(vy)));
        let side = |a: (i32, i32), b: (i32, i32)| {
            (i64::from(b.0 - a.0) * i64::from(py - a.1)
                - i64::from(b.1 - a.1) * i64::from(px - a.0))
            .signum()
        };
        let s = [side(p[0], p[1]), side(p[1], p[2]), side(p[2], p[0])];
        s.iter().all(|&v| v > 0) || s.iter().all(|&v| v < 0)
    }

    /// How many of `w`'s triangles hold pixel `(x, y)`'s centre.
    fn centre_hits(w: &Workload, x: i32, y: i32) -> usize {
        w.tris.iter().filter(|t| centre_inside(t, x, y)).count()
    }

    #[test]
    fn screen_covers_every_pixel_centre_exactly_once() {
        assert_eq!(SCREEN.tris.len(), 132);
        let frame = i32::from(FRAME);
        assert_eq!(SCREEN.twice_area(), 2 * (frame * frame) as u64);
        for y in 0..frame {
            for x in 0..frame {
                assert_eq!(centre_hits(&SCREEN, x, y), 1, "pixel ({x}, {y})");
            }
        }
        for t in SCREEN.tris {
            let a = f64::from(t.twice_area()) / 2.0;
            assert!((420.0..=440.0).contains(&a), "{a}");
        }
    }

    #[test]
    fn slanted_screen_is_the_screen_sheared_without_vertical_edges() {
        assert_eq!(SLANTED.tris.len(), SCREEN.tris.len());
        // A shear keeps every area; the colours are the screen's.
        assert_eq!(SLANTED.twice_area(), SCREEN.twice_area());
        for (s, t) in SLANTED.tris.iter().zip(SCREEN.tris) {
            assert_eq!(s.rgb, t.rgb);
            assert_eq!(s.twice_area(), t.twice_area());
            for k in 0..3 {
                let (p, q) = (s.v[k], s.v[(k + 1) % 3]);
                assert!(p[0] != q[0] || p[1] == q[1], "vertical edge {p:?} {q:?}");
            }
        }
        // Still a mesh: no pixel centre in two triangles.
        let frame = i32::from(FRAME);
        for y in 0..frame {
            for x in 0..frame {
                assert!(centre_hits(&SLANTED, x, y) <= 1, "pixel ({x}, {y})");
            }
        }
    }

    /// The smallest angle of `t`, degrees (`f64` from its vertices).
    fn min_angle(t: &Tri) -> f64 {
        let p = t.v.map(|[x, y]| (f64::from(x), f64::from(y)));
        (0..3)
            .map(|i| {
                let (a, b, c) = (p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
                let (u, v) = ((b.0 - a.0, b.1 - a.1), (c.0 - a.0, c.1 - a.1));
                let cos = (u.0 * v.0 + u.1 * v.1) / (u.0.hypot(u.1) * v.0.hypot(v.1));
                cos.clamp(-1.0, 1.0).acos().to_degrees()
            })
            .fold(180.0, f64::min)
    }

    #[test]
    fn well_shaped_triangles_are_well_shaped_and_of_their_classes() {
        for (w, target) in [
            (&WELL_SMALL, 27.0),
            (&WELL_MEDIUM, 437.0),
            (&WELL_LARGE, 3900.0),
        ] {
            assert_eq!(w.tris.len(), COUNT);
            let m = mean_area(w);
            // The area is uniform in [a/2, 3a/2] before the angles' jitter
            // (which makes it at most 6 % smaller).
            assert!(m / target > 0.9 && m / target < 1.03, "{}: {m}", w.name);
            let mut off_grid = 0;
            for t in w.tris {
                // 40° before the vertices are rounded to 1/16 px.
                assert!(min_angle(t) > 38.0, "{}: {t:?}", w.name);
                let frame = 16 * i32::from(FRAME);
                for [x, y] in t.v {
                    assert!(
                        (0..frame).contains(&i32::from(x)) && (0..frame).contains(&i32::from(y))
                    );
                    off_grid += usize::from(x % 16 != 0 || y % 16 != 0);
                }
                for [x, y] in t.px() {
                    assert!(
                        (0..=i32::from(FRAME)).contains(&x) && (0..=i32::from(FRAME)).contains(&y)
                    );
                }
            }
            // Sub-pixel positions: most vertices are off the whole pixels.
            assert!(off_grid > 3 * COUNT * 9 / 10, "{}: {off_grid}", w.name);
        }
    }
}
