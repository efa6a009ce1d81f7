//! The scenes themselves: constant data, and `const fn`s that generate the
//! regular ones (mesh, line star, comb) with integer arithmetic only, so
//! every target gets the very same vertices.
//!
//! Sizes are chosen for a 16 KiB Cortex-M0: the largest scene needs
//! `ACC_LEN + COVER_LEN` `i32`s (about 6 KiB) of band buffers.

use crate::stream::Format;
use crate::{Fill, Object3d, Pen, Scene, Shape};
use softedge::geom::FinePoint;
use softedge::path::{Arc, Circle, Degrees, LineCap};
use softedge::scene3d;
use softedge::{PixelModel, RenderStyle, SubPoint, LIN_MAX, SUB_ONE};

/// Sub-pixel units per pixel, short for the coordinate tables below.
const S: i32 = SUB_ONE;
/// Full linear intensity.
const F: u16 = LIN_MAX;
/// Half linear intensity.
const H: u16 = LIN_MAX / 2;

const RED: [u16; 3] = [F, 0, 0];
const GREEN: [u16; 3] = [0, F, 0];
const BLUE: [u16; 3] = [0, 0, F];
const YELLOW: [u16; 3] = [F, F, 0];
const CYAN: [u16; 3] = [0, F, F];
const MAGENTA: [u16; 3] = [F, 0, F];
const WHITE: [u16; 3] = [F, F, F];
const BLACK: [u16; 3] = [0, 0, 0];
const GRAY: [u16; 3] = [H, H, H];

/// A point from sub-pixel units.
const fn s(x_sub: i32, y_sub: i32) -> SubPoint {
    SubPoint::new(x_sub, y_sub)
}

/// A gray colour given for three channels.
const fn g(lin12: u16) -> [u16; 3] {
    [lin12, lin12, lin12]
}

/// Anti-aliased, exact box coverage (`RenderStyle::default()` as a const).
const AA: RenderStyle = RenderStyle {
    antialias: true,
    model: PixelModel::Box,
};

/// One step of the linear congruential generator of Numerical Recipes
/// (2nd ed., §7.1, "ranqd1": `x' = 1664525 x + 1013904223 mod 2^32`):
/// deterministic jitter and intensities for the generated scenes.
const fn lcg(x: u32) -> u32 {
    x.wrapping_mul(1_664_525).wrapping_add(1_013_904_223)
}

/// The top bits of an LCG state, in `0..n` (the low bits of a power-of-two
/// LCG are poorly distributed).
const fn below(state: u32, n: u32) -> u32 {
    (((state >> 16) as u64 * n as u64) >> 16) as u32
}

// ---------------------------------------------------------------- gouraud

/// A concave pentagon with a colour per vertex (split into triangles by
/// core's ear clipping).
const ARROW: [SubPoint; 5] = [
    s(44 * S + 3, 28 * S + 9),
    s(60 * S + 7, 33 * S),
    s(52 * S + 12, 36 * S + 4),
    s(61 * S + 1, 45 * S + 15),
    s(42 * S + 8, 44 * S + 2),
];
const ARROW_COLORS: [[u16; 3]; 5] = [WHITE, RED, GRAY, BLUE, YELLOW];

/// A flat quadrilateral.
const QUAD: [SubPoint; 4] = [
    s(3 * S + 8, 30 * S + 8),
    s(17 * S + 2, 27 * S + 13),
    s(21 * S + 14, 40 * S + 1),
    s(6 * S + 5, 43 * S + 11),
];

/// Gouraud triangles at sub-pixel positions, overlapping, one crossing the
/// frame's left and bottom edges, a sliver, a degenerate one, and two
/// polygons.
const GOURAUD_SHAPES: [Shape; 8] = [
    Shape::Triangle(
        [
            s(2 * S + 5, S + 11),
            s(40 * S + 10, 6 * S + 2),
            s(10 * S + 3, 44 * S + 14),
        ],
        [RED, GREEN, BLUE],
    ),
    Shape::Triangle(
        [
            s(30 * S, 4 * S + 8),
            s(62 * S + 6, 20 * S + 5),
            s(36 * S + 15, 46 * S + 3),
        ],
        [YELLOW, CYAN, MAGENTA],
    ),
    Shape::Triangle(
        [
            s(-10 * S, 30 * S),
            s(20 * S + 4, 60 * S),
            s(50 * S + 9, 38 * S + 7),
        ],
        [WHITE, BLACK, GRAY],
    ),
    // A sliver thinner than a pixel across most of the frame.
    Shape::Triangle(
        [
            s(5 * S, 20 * S),
            s(60 * S + 3, 22 * S + 1),
            s(5 * S, 20 * S + 9),
        ],
        [CYAN, WHITE, CYAN],
    ),
    // Collinear: nothing drawn.
    Shape::Triangle(
        [s(S, S), s(9 * S, 5 * S), s(17 * S, 9 * S)],
        [WHITE, WHITE, WHITE],
    ),
    // Inside one pixel.
    Shape::Triangle(
        [
            s(50 * S + 2, 10 * S + 3),
            s(50 * S + 13, 10 * S + 6),
            s(50 * S + 5, 10 * S + 14),
        ],
        [WHITE, YELLOW, WHITE],
    ),
    Shape::Polygon(&ARROW, Fill::PerVertex(&ARROW_COLORS)),
    Shape::Polygon(&QUAD, Fill::Flat([F, H, 0])),
];

/// Gouraud-shaded RGB triangles and polygons, anti-aliased.
pub const GOURAUD: Scene = Scene {
    name: "gouraud",
    width: 64,
    height: 48,
    channels: 3,
    format: Format::Rgb565,
    band_rows: 4,
    style: AA,
    background: [200, 300, 600],
    shapes: &GOURAUD_SHAPES,
    zbuffer: false,
};

/// The same as [`GOURAUD`], aliased (top-left rule).
pub const ALIASED: Scene = Scene {
    name: "aliased",
    style: RenderStyle::ALIASED,
    ..GOURAUD
};

/// The same as [`GOURAUD`] with the single-formula coverage of seed 001.
pub const SEEDBOX: Scene = Scene {
    name: "seedbox",
    style: RenderStyle {
        antialias: true,
        model: PixelModel::BoxSeed,
    },
    ..GOURAUD
};

// ------------------------------------------------------------------- mesh

const MESH_COLS: usize = 8;
const MESH_ROWS: usize = 6;
const MESH_CELL_PX: i32 = 8;
/// Interior vertices move by at most this many sub-pixel units per axis.
/// A cell's triangles have legs of `MESH_CELL_PX` and a smallest altitude
/// of `MESH_CELL_PX / sqrt 2` (5.66 px); moving every vertex by less than
/// half of that (here at most `1.5 * sqrt 2 = 2.1` px) cannot flip one, so
/// the mesh stays a tiling: every shared edge is drawn by both neighbours.
const MESH_JITTER_SUB: i32 = 3 * S / 2;
const MESH_TRIANGLES: usize = 2 * MESH_COLS * MESH_ROWS;

/// An 8x6 grid of 8-px cells over the 64x48 frame; interior vertices
/// jittered, each cell split along a randomly chosen diagonal, a random gray
/// per vertex. Border vertices stay on the frame's edges, so the mesh tiles
/// the frame exactly.
const fn mesh_shapes() -> [Shape; MESH_TRIANGLES] {
    const NV: usize = (MESH_COLS + 1) * (MESH_ROWS + 1);
    let mut pos = [s(0, 0); NV];
    let mut lum = [0u16; NV];
    let mut rng = 1u32;
    let mut j = 0;
    while j <= MESH_ROWS {
        let mut i = 0;
        while i <= MESH_COLS {
            let mut x = i as i32 * MESH_CELL_PX * S;
            let mut y = j as i32 * MESH_CELL_PX * S;
            rng = lcg(rng);
            let dx = below(rng, 2 * MESH_JITTER_SUB as u32 + 1) as i32 - MESH_JITTER_SUB;
            rng = lcg(rng);
            let dy = below(rng, 2 * MESH_JITTER_SUB as u32 + 1) as i32 - MESH_JITTER_SUB;
            if i > 0 && i < MESH_COLS {
                x += dx;
            }
            if j > 0 && j < MESH_ROWS {
                y += dy;
            }
            rng = lcg(rng);
            pos[j * (MESH_COLS + 1) + i] = s(x, y);
            lum[j * (MESH_COLS + 1) + i] = below(rng, F as u32 + 1) as u16;
            i += 1;
        }
        j += 1;
    }
    let mut out = [Shape::Triangle([s(0, 0); 3], [BLACK; 3]); MESH_TRIANGLES];
    let mut k = 0;
    let mut j = 0;
    while j < MESH_ROWS {
        let mut i = 0;
        while i < MESH_COLS {
            let a = j * (MESH_COLS + 1) + i; // top left
            let b = a + 1; // top right
            let c = a + MESH_COLS + 1; // bottom left
            let d = c + 1; // bottom right
            rng = lcg(rng);
            let (t0, t1) = if rng >> 31 == 0 {
                ([a, b, d], [a, d, c])
            } else {
                ([a, b, c], [b, d, c])
            };
            out[k] = Shape::Triangle(
                [pos[t0[0]], pos[t0[1]], pos[t0[2]]],
                [g(lum[t0[0]]), g(lum[t0[1]]), g(lum[t0[2]])],
            );
            out[k + 1] = Shape::Triangle(
                [pos[t1[0]], pos[t1[1]], pos[t1[2]]],
                [g(lum[t1[0]]), g(lum[t1[1]]), g(lum[t1[2]])],
            );
            k += 2;
            i += 1;
        }
        j += 1;
    }
    out
}

const MESH_SHAPES: [Shape; MESH_TRIANGLES] = mesh_shapes();

/// A triangulated gray mesh sharing every interior edge.
pub const MESH: Scene = Scene {
    name: "mesh",
    width: MESH_COLS as u16 * MESH_CELL_PX as u16,
    height: MESH_ROWS as u16 * MESH_CELL_PX as u16,
    channels: 1,
    format: Format::Gray8,
    band_rows: 8,
    style: AA,
    background: [0; 3],
    shapes: &MESH_SHAPES,
    zbuffer: false,
};

// ------------------------------------------------------------------ lines

const STAR_LINES: usize = 32;
const LINES_TOTAL: usize = STAR_LINES + 4;
/// The star's ends lie on this rectangle (pixels), inset from 64x48.
const RIM_X0: i32 = 2;
const RIM_Y0: i32 = 2;
const RIM_W: i32 = 60;
const RIM_H: i32 = 44;

/// The point `t` sub-pixel units clockwise along the rim from its top-left
/// corner.
const fn rim(t: i32) -> SubPoint {
    let (w, h) = (RIM_W * S, RIM_H * S);
    let t = t % (2 * (w + h));
    let (x, y) = if t < w {
        (t, 0)
    } else if t < w + h {
        (w, t - w)
    } else if t < 2 * w + h {
        (2 * w + h - t, h)
    } else {
        (0, 2 * (w + h) - t)
    };
    s(RIM_X0 * S + x, RIM_Y0 * S + y)
}

/// 32 lines radiating from an off-grid centre to points spread evenly (plus
/// an odd sub-pixel offset, so no two angles repeat a pattern) along the
/// rim, each shading from one colour to another; then an exactly
/// horizontal, an exactly vertical, an exactly diagonal and a zero-length
/// line.
const fn line_shapes() -> [Shape; LINES_TOTAL] {
    let centre = s(32 * S + 5, 24 * S + 3);
    let perimeter = 2 * (RIM_W + RIM_H) * S;
    let mut out = [Shape::Line(centre, centre, [BLACK; 2]); LINES_TOTAL];
    let mut k = 0;
    while k < STAR_LINES {
        let end = rim(k as i32 * (perimeter / STAR_LINES as i32) + 7 * k as i32);
        // Start a sixth of the way out, so the centre is not 32 lines deep.
        let start = s(
            centre.x + (end.x - centre.x) / 6,
            centre.y + (end.y - centre.y) / 6,
        );
        let step = (F as usize / STAR_LINES) as u16;
        let up = k as u16 * step;
        out[k] = Shape::Line(start, end, [[F - up, up, H], [up, F, F - up]]);
        k += 1;
    }
    out[STAR_LINES] = Shape::Line(s(S, S + S / 2), s(30 * S, S + S / 2), [WHITE, RED]);
    out[STAR_LINES + 1] = Shape::Line(s(62 * S, 3 * S), s(62 * S, 45 * S), [GREEN, BLUE]);
    out[STAR_LINES + 2] = Shape::Line(s(S, 46 * S), s(12 * S, 35 * S), [YELLOW, WHITE]);
    out[STAR_LINES + 3] = Shape::Line(s(40 * S, 40 * S), s(40 * S, 40 * S), [WHITE, WHITE]);
    out
}

const LINE_SHAPES: [Shape; LINES_TOTAL] = line_shapes();

/// Anti-aliased 1-px lines at many angles, RGB.
pub const LINES: Scene = Scene {
    name: "lines",
    width: 64,
    height: 48,
    channels: 3,
    format: Format::Rgb888,
    band_rows: 4,
    style: AA,
    background: [0; 3],
    shapes: &LINE_SHAPES,
    zbuffer: false,
};

// ----------------------------------------------------------------- onebit

/// A five-pointed star (concave), outer radius 22 px, inner radius 9 px,
/// centre (30, 32) px, vertices rounded to 1/16 px.
const STAR: [SubPoint; 10] = [
    s(480, 160),
    s(565, 395),
    s(814, 403),
    s(618, 557),
    s(686, 797),
    s(480, 656),
    s(274, 797),
    s(342, 557),
    s(146, 403),
    s(395, 395),
];

/// Shapes for a 1-bit display: a flat star, a full-range gradient (what
/// dithering must render), thin lines and a sub-pixel triangle.
const ONEBIT_SHAPES: [Shape; 6] = [
    Shape::Polygon(&STAR, Fill::Flat(WHITE)),
    Shape::Triangle(
        [
            s(58 * S, 4 * S),
            s(94 * S + 8, 4 * S),
            s(76 * S + 3, 61 * S + 5),
        ],
        [g(0), g(F), g(H)],
    ),
    Shape::Line(s(2 * S, 60 * S), s(93 * S, 56 * S + 7), [g(F), g(F)]),
    Shape::Line(s(56 * S, 2 * S), s(60 * S + 5, 62 * S), [g(F), g(0)]),
    Shape::Line(s(3 * S, 3 * S), s(20 * S, 12 * S + 9), [g(H), g(F)]),
    Shape::Triangle(
        [
            s(88 * S + 4, 50 * S + 4),
            s(88 * S + 12, 50 * S + 6),
            s(88 * S + 6, 50 * S + 13),
        ],
        [g(F), g(F), g(F)],
    ),
];

/// Gray, for a 1-bit display once the tone stage dithers (bands of 6
/// rows: the bits do not depend on it, and the Cortex-M0's RAM does).
pub const ONEBIT: Scene = Scene {
    name: "onebit",
    width: 96,
    height: 64,
    channels: 1,
    format: Format::Binary,
    band_rows: 6,
    style: AA,
    background: [0; 3],
    shapes: &ONEBIT_SHAPES,
    zbuffer: false,
};

// ----------------------------------------------------------------- limits

/// Largest accepted coordinate, in sub-pixel units.
const L: i32 = softedge::COORD_LIMIT_PX * S;
const COMB_TEETH: usize = (softedge::MAX_POLYGON_VERTICES - 2) / 2;

/// A saw of `MAX_POLYGON_VERTICES` vertices (concave, Gouraud per vertex):
/// 31 triangular teeth, 2 px apart, alternately long and short, hanging
/// from a bar across the frame.
const fn comb() -> (
    [SubPoint; softedge::MAX_POLYGON_VERTICES],
    [[u16; 3]; softedge::MAX_POLYGON_VERTICES],
) {
    let mut v = [s(0, 0); softedge::MAX_POLYGON_VERTICES];
    let mut c = [BLACK; softedge::MAX_POLYGON_VERTICES];
    let (top, bar, tip) = (30 * S, 33 * S, 46 * S + 5);
    let mut k = 0;
    while k < COMB_TEETH {
        // Tooth k: its tip at x = 2k + 1/4 px, then up to the bar 1 px
        // further right; left to right.
        let x = k as i32 * 2 * S;
        v[2 * k] = s(x + S / 4, if k % 2 == 0 { tip } else { tip - 5 * S });
        v[2 * k + 1] = s(x + S + S / 4, bar);
        let ramp = (k * (F as usize) / COMB_TEETH) as u16;
        c[2 * k] = [ramp, F - ramp, H];
        c[2 * k + 1] = g(H);
        k += 1;
    }
    v[2 * COMB_TEETH] = s(2 * COMB_TEETH as i32 * S, top);
    v[2 * COMB_TEETH + 1] = s(0, top);
    c[2 * COMB_TEETH] = WHITE;
    c[2 * COMB_TEETH + 1] = BLACK;
    (v, c)
}

const COMB: (
    [SubPoint; softedge::MAX_POLYGON_VERTICES],
    [[u16; 3]; softedge::MAX_POLYGON_VERTICES],
) = comb();

/// The documented limits: vertices at `±COORD_LIMIT_PX`, primitives wholly
/// outside the frame on every side, degenerate ones, colours above 4095
/// (clamped), a polygon of `MAX_POLYGON_VERTICES` vertices.
const LIMITS_SHAPES: [Shape; 12] = [
    Shape::Triangle([s(-L, -L), s(L, 17 * S + 9), s(-L, L)], [g(F), g(0), g(H)]),
    Shape::Triangle(
        [s(-L, 10 * S), s(L, 12 * S + 1), s(-L, 10 * S + 8)],
        [g(0), g(F), g(F)],
    ),
    Shape::Line(s(-L, -L), s(L, L), [g(F), g(0)]),
    // Slope -1 through (20, 20) px, ends at the limit, colour clamped.
    Shape::Line(
        s(L, 40 * S - L),
        s(40 * S - L, L),
        [g(u16::MAX), g(u16::MAX)],
    ),
    // Wholly above, below, left and right of the frame.
    Shape::Triangle([s(0, -L), s(L, -L), s(S, -S)], [WHITE; 3]),
    Shape::Triangle([s(0, L), s(L, L), s(S, 48 * S)], [WHITE; 3]),
    Shape::Triangle([s(-L, 0), s(-S, 0), s(-L, L)], [WHITE; 3]),
    Shape::Triangle([s(64 * S, 0), s(L, 0), s(L, L)], [WHITE; 3]),
    // Repeated vertices.
    Shape::Triangle(
        [s(5 * S, 5 * S), s(5 * S, 5 * S), s(9 * S, 2 * S)],
        [WHITE; 3],
    ),
    Shape::Triangle([s(7 * S, 7 * S); 3], [WHITE; 3]),
    Shape::Polygon(&COMB.0, Fill::PerVertex(&COMB.1)),
    // Colours above range, clamped.
    Shape::Triangle(
        [
            s(40 * S + 1, 2 * S + 2),
            s(62 * S + 3, 3 * S),
            s(50 * S, 9 * S + 11),
        ],
        [[u16::MAX, 5000, 4096]; 3],
    ),
];

/// Coordinates and inputs at the limits core documents.
pub const LIMITS: Scene = Scene {
    name: "limits",
    width: 64,
    height: 48,
    channels: 1,
    format: Format::Gray4,
    band_rows: 8,
    style: AA,
    background: [300; 3],
    shapes: &LIMITS_SHAPES,
    zbuffer: false,
};

/// A lit sphere (8 segments, RGB) through an orthographic camera: the 3D
/// stage (transform, Lambert lighting, projection, back-face culling) joins
/// the scenes every target must agree on.
pub const SPHERE3D: Scene = Scene {
    name: "sphere3d",
    width: 64,
    height: 48,
    channels: 3,
    format: Format::Rgb565,
    band_rows: 4,
    style: RenderStyle {
        antialias: true,
        model: PixelModel::Box,
    },
    background: [200, 300, 600],
    shapes: &[Shape::Object(&Object3d {
        shape: scene3d::Shape::Sphere {
            radius: scene3d::I16F16::from_bits(2 << 16),
            segments: 8,
        },
        rotation: [
            scene3d::Angle::from_degrees(25),
            scene3d::Angle::from_degrees(40),
            scene3d::Angle::from_degrees(0),
        ],
        color: [3900, 2600, 900],
        camera: scene3d::Camera::orthographic(
            scene3d::Vec3::from_int(0, 0, 10),
            scene3d::Vec3::ZERO,
            scene3d::Vec3::from_int(0, 1, 0),
            scene3d::I16F16::from_bits(10 << 16),
        ),
        to_light: scene3d::Vec3::from_int(-1, -1, 2),
        ambient_diffuse: [600, 3400],
    })],
    zbuffer: false,
};

/// Depth triangles of [`ZBUFFER`], front to back.
const Z_SHAPES: [Shape; 10] = {
    // A pyramid seen from above (apex nearest): four triangles sharing
    // edges, Gouraud gray.
    let apex = s(20 * S + 5, 18 * S + 9);
    let (a, b, c, d) = (
        s(6 * S, 5 * S + 3),
        s(35 * S + 2, 7 * S),
        s(33 * S + 11, 33 * S + 6),
        s(4 * S + 9, 30 * S),
    );
    let (top, rim) = (50_000, 30_000);
    // In the order sort_front_to_back gives (a test checks it).
    [
        // A thin sliver in front of everything.
        Shape::Depth(
            [
                s(2 * S, 44 * S),
                s(62 * S + 9, 38 * S + 2),
                s(62 * S, 39 * S + 8),
            ],
            [g(F), g(F), g(F)],
            [64_000, 64_000, 64_000],
        ),
        Shape::Depth([apex, a, b], [g(F), g(H), g(H)], [top, rim, rim]),
        Shape::Depth([apex, b, c], [g(F), g(H), g(900)], [top, rim, rim]),
        Shape::Depth([apex, d, a], [g(F), g(900), g(H)], [top, rim, rim]),
        Shape::Depth([apex, c, d], [g(F), g(900), g(900)], [top, rim, rim]),
        // Two triangles crossing each other (interpenetrating), with a
        // blade leaning through the pyramid and the wall between them.
        Shape::Depth(
            [s(40 * S, 44 * S), s(58 * S + 6, 30 * S), s(62 * S, 47 * S)],
            [g(2000), g(2000), g(2000)],
            [30_000, 30_000, 20_000],
        ),
        Shape::Depth(
            [
                s(15 * S, 40 * S + 7),
                s(58 * S + 3, 2 * S),
                s(61 * S, 12 * S + 5),
            ],
            [g(3600), g(3600), g(2600)],
            [60_000, 8_000, 8_000],
        ),
        Shape::Depth(
            [
                s(38 * S, 24 * S),
                s(60 * S, 26 * S + 8),
                s(46 * S + 4, 46 * S),
            ],
            [g(700), g(700), g(700)],
            [10_000, 40_000, 25_000],
        ),
        // A far wall over the whole frame, tilted.
        Shape::Depth(
            [s(0, 0), s(64 * S, 48 * S), s(0, 48 * S)],
            [g(400), g(1200), g(1200)],
            [2_000, 1_500, 2_500],
        ),
        Shape::Depth(
            [s(0, 0), s(64 * S, 0), s(64 * S, 48 * S)],
            [g(400), g(400), g(1200)],
            [2_000, 1_000, 1_500],
        ),
    ]
};

/// Hidden surfaces by the z-buffer in 2-row bands, anti-aliased: a Gouraud
/// pyramid (a mesh seen from its apex), a blade leaning through it, two
/// interpenetrating triangles and a sliver in front, over a tilted wall.
pub const ZBUFFER: Scene = Scene {
    name: "zbuffer",
    width: 64,
    height: 48,
    channels: 1,
    format: Format::Gray8,
    band_rows: 2,
    style: AA,
    background: [0; 3],
    shapes: &Z_SHAPES,
    zbuffer: true,
};

/// A 32x32 RGBA image (straight alpha): red along x, green along y, blue
/// in 8-texel checks; alpha a disc of radius 14 about the centre, opaque
/// inside radius 10 and fading to 0 at 14 (`refscenes/scenes/image32.png`
/// holds the same texels).
pub static IMAGE32: [u8; 32 * 32 * 4] = image32();

const fn image32() -> [u8; 32 * 32 * 4] {
    let mut d = [0u8; 32 * 32 * 4];
    let mut j = 0;
    while j < 32 {
        let mut i = 0;
        while i < 32 {
            let k = 4 * (j * 32 + i);
            d[k] = (i * 8) as u8;
            d[k + 1] = (j * 8) as u8;
            d[k + 2] = if (i / 8 + j / 8) % 2 == 0 { 230 } else { 40 };
            // Twice the offsets of the texel centre from (16, 16).
            let (dx, dy) = (2 * i as i32 + 1 - 32, 2 * j as i32 + 1 - 32);
            let r2 = dx * dx + dy * dy;
            d[k + 3] = if r2 <= 4 * 10 * 10 {
                255
            } else if r2 >= 4 * 14 * 14 {
                0
            } else {
                // Linear in r^2 between the two radii.
                (255 * (4 * 14 * 14 - r2) / (4 * (14 * 14 - 10 * 10))) as u8
            };
            i += 1;
        }
        j += 1;
    }
    d
}

const IMAGE_ROTATED: crate::ImageShape = crate::ImageShape {
    width: 32,
    height: 32,
    rgba: &IMAGE32,
    file: "image32.png",
    center: (20 * 1024 + 512, 22 * 1024),
    scale: (3 << 15, 3 << 15),
    rotate: 30 << 16,
    opacity: 4096,
};

/// Minified (the box filter).
const IMAGE_SMALL: crate::ImageShape = crate::ImageShape {
    center: (52 * 1024 + 256, 10 * 1024),
    scale: (1 << 14, 3 << 13),
    rotate: -(10 << 16),
    opacity: 3072,
    ..IMAGE_ROTATED
};

/// Magnified, unrotated, at half opacity.
const IMAGE_TINTED: crate::ImageShape = crate::ImageShape {
    center: (48 * 1024, 34 * 1024 + 100),
    scale: (5 << 14, 5 << 14),
    rotate: 0,
    opacity: 2048,
    ..IMAGE_ROTATED
};

const IMAGE_SHAPES: [Shape; 4] = [
    Shape::Polygon(
        &[s(0, 0), s(40 * S, 0), s(8 * S, 48 * S)],
        Fill::Flat([600, 900, 1500]),
    ),
    Shape::Image(&IMAGE_ROTATED),
    Shape::Image(&IMAGE_SMALL),
    Shape::Image(&IMAGE_TINTED),
];

/// Images (issue 35): an RGBA image rotated and magnified (bilinear),
/// minified and rotated (box), and magnified at half opacity, over a
/// triangle, in 4-row bands.
pub const IMAGE: Scene = Scene {
    name: "image",
    width: 64,
    height: 48,
    channels: 3,
    format: Format::Rgb565,
    band_rows: 4,
    style: AA,
    background: [200, 300, 600],
    shapes: &IMAGE_SHAPES,
    zbuffer: false,
};

// ------------------------------------------------------------------- dial

/// Fine units (1/1024 px) per pixel, for the circles and arcs below.
const P: i32 = softedge::geom::FINE_ONE;

/// A point from fine units.
const fn fine(x: i32, y: i32) -> FinePoint {
    FinePoint::new(x, y)
}

/// Degrees from 1/65536 degree.
const fn deg(bits: i32) -> Degrees {
    Degrees::from_bits(bits)
}

/// A centred stroke of `width` fine units.
const fn stroke(width: i32, cap: LineCap) -> Pen {
    Pen::Stroke {
        width: width as u32,
        cap,
    }
}

/// The dial's centre, (47.3, 31.6) px to the fine grid.
const DIAL_CENTRE: FinePoint = fine(47 * P + 307, 31 * P + 614);

const DIAL_SHAPES: [Shape; 12] = [
    // The face: sub-pixel centre, radius 27.7 px.
    Shape::Circle(
        Circle::new(DIAL_CENTRE, (27 * P + 717) as u32),
        Pen::Fill,
        [700, 760, 900],
    ),
    // Its bezel, a ring of 2.25 px about radius 29.5 px (reaching row 62).
    Shape::Circle(
        Circle::new(DIAL_CENTRE, (29 * P + P / 2) as u32),
        stroke(2 * P + P / 4, LineCap::Butt),
        [3300, 3300, 3500],
    ),
    // The gauge's track: 270 degrees clockwise from 135, 5 px wide, butt.
    Shape::Arc(
        Arc::new(DIAL_CENTRE, 22 * P as u32, deg(135 << 16), deg(270 << 16)),
        stroke(5 * P, LineCap::Butt),
        [300, 330, 400],
    ),
    // Its value over it: 170.5 degrees, round caps.
    Shape::Arc(
        Arc::new(
            DIAL_CENTRE,
            22 * P as u32,
            deg(135 << 16),
            deg((170 << 16) + (1 << 15)),
        ),
        stroke(5 * P, LineCap::Round),
        [F, 2400, 300],
    ),
    // An inner scale: round caps, 4.5 px wide, radius 14.6 px, 262.25
    // degrees from 138.5, drawn counter-clockwise from its far end.
    Shape::Arc(
        Arc::new(
            DIAL_CENTRE,
            (14 * P + 614) as u32,
            deg((40 << 16) + (3 << 14)),
            deg(-((262 << 16) + (1 << 14))),
        ),
        stroke(4 * P + P / 2, LineCap::Round),
        [600, 2600, 3000],
    ),
    // A butt-capped arc of 4 px across the face's edge, 98 degrees.
    Shape::Arc(
        Arc::new(
            DIAL_CENTRE,
            (27 * P + 300) as u32,
            deg(200 << 16),
            deg(98 << 16),
        ),
        stroke(4 * P, LineCap::Butt),
        [F, F, F],
    ),
    // The hub.
    Shape::Circle(
        Circle::new(DIAL_CENTRE, (3 * P + 100) as u32),
        Pen::Fill,
        [F, F, F],
    ),
    // Small discs: one centred 3/1024 px below the boundary of two bands
    // (row 10, the scene's bands being 2 rows), one radius 0.7 px across
    // the boundary at row 56, one of 1.9 px centred on row 40.
    Shape::Circle(
        Circle::new(fine(8 * P + 410, 10 * P + 3), (P + 700) as u32),
        Pen::Fill,
        [F, 600, 600],
    ),
    Shape::Circle(
        Circle::new(fine(6 * P + 512, 56 * P + 77), 717),
        Pen::Fill,
        [F, F, 200],
    ),
    Shape::Circle(
        Circle::new(fine(87 * P + 900, 40 * P), (P + 922) as u32),
        Pen::Fill,
        [400, F, 900],
    ),
    // Cut by the frame: a disc across its top right corner, and a ring
    // (1.5 px) across its left edge at the bottom.
    Shape::Circle(
        Circle::new(fine(93 * P + 512, 3 * P + 205), (7 * P + 307) as u32),
        Pen::Fill,
        [2400, 900, F],
    ),
    Shape::Circle(
        Circle::new(fine(-(2 * P + 307), 57 * P + 100), (6 * P + 205) as u32),
        stroke(3 * P / 2, LineCap::Butt),
        [F, 1600, 400],
    ),
];

/// A gauge dial of circles and arcs drawn through the canvas, in painter's
/// order over the background (issue 32: core's exact circle areas on every
/// target): a face (a filled disc of sub-pixel centre and radius), a bezel
/// ring, a 270-degree butt-capped track, a round-capped value arc over it,
/// a counter-clockwise round-capped inner scale, a butt arc across the
/// face's edge, the hub, small discs at band boundaries, a disc and a ring
/// cut by the frame, RGB565 in 2-row bands.
pub const DIAL: Scene = Scene {
    name: "dial",
    width: 96,
    height: 64,
    channels: 3,
    format: Format::Rgb565,
    band_rows: 2,
    style: AA,
    background: [120, 140, 220],
    shapes: &DIAL_SHAPES,
    zbuffer: false,
};
