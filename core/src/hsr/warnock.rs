//! Warnock's subdivision (seed 004, rules 1-6), with windows down to the
//! vertex grid and pixels resolved by area.
//!
//! ## The idea
//!
//! A window (a square of the screen) is looked at with the list of the
//! triangles that overlap it. If the content is simple enough it is drawn;
//! otherwise the window is split into four and each quarter is looked at
//! with the part of the list that overlaps it. Seed 004's rules, and how
//! they read here:
//!
//! 1. no triangle overlaps the window: background (nothing to add, the band
//!    was cleared to it);
//! 2. / 3. one triangle alone, inside or cutting the window: its area is
//!    drawn over the background;
//! 4. / 5. a triangle *surrounds* the window and is nearer than every
//!    other triangle of the window: it fills the window.
//! 6. otherwise: split.
//!
//! One rule joins them all and makes them exact down to any window size:
//! pick `S`, the nearest surrounding triangle (or the background, which
//! surrounds everything and is farther than all), drop every triangle `S`
//! hides in the whole window, and let `P` be the rest. If every member of
//! `P` is nearer than `S` in the whole window and the members of `P` do
//! not overlap one another, the window is resolved exactly: each member of
//! `P` shows its exact area in the window, `S` shows the rest. Rules 1-5
//! are the cases `P = {}` with or without `S`, and `P = {T}` over the
//! background; the general case also resolves a silhouette over a farther
//! surface and the shared edges of a mesh (triangles sharing an edge are
//! separated by that edge's line) without going further down.
//!
//! Windows larger than a pixel are drawn only when `P` is empty (a filled
//! window: one addition per pixel); windows with visible edges go down to
//! one pixel, where the areas are computed. At one pixel or less one more
//! exact rule: when exactly two triangles are left, both surrounding the
//! window and passing through each other in it, each shows where its plane
//! is nearer, split by their intersection line (the area of a half-plane in
//! a square). A pixel that is still not simple enough (two visible edges
//! overlapping in it, a visible edge meeting an intersection line) is split
//! further, down to windows of 1/16 px: the vertex grid, the finest grid
//! the geometry has. A 1/16-px window that is still not simple is point
//! sampled: each of its 4 x 4 points (1/4096 px each) goes to the surface
//! nearest there, with exact depths, under the top-left rule.
//!
//! ## Accuracy
//!
//! - Coverage is exact but for rounding wherever a window is resolved by
//!   the rules: each triangle's area in a pixel or sub-pixel window is a
//!   sum of three per-edge terms, each rounded to 1/2^20 px, and a split by
//!   an intersection line is rounded to 2^-17 of its window; summed over
//!   all the windows of a pixel this stays below 1/4096 px.
//! - A 1/16-px window that had to be sampled is off by at most its own area,
//!   1/256 px (by at most 7/16 of it for one straight boundary through it:
//!   a line crosses at most 7 of the 4 x 4 sample squares). Such windows
//!   lie only where two visible edges, or an edge and an intersection line,
//!   pass within 1/16 px of each other (crossings of silhouettes, where a
//!   triangle's edge pierces another surface), never along a silhouette
//!   over a farther surface, a mesh's shared edges or an intersection line
//!   alone.
//! - Intensity: each surface's Gouraud plane at the pixel centre
//!   ([`Plane::at`]), the same value the other methods use, times its
//!   visible area; the background shows through the uncovered rest.
//!
//! ## Exact decisions
//!
//! Whether a triangle misses, cuts or surrounds a window is decided with
//! its three edge functions at the window's corners and its bounding box
//! (two convex shapes are disjoint iff a line along an edge of one of them
//! separates them), in `i64`. Depth is the exact plane through the vertex
//! depths, `z = N(x, y) / D`; whether `S` is nearer than `T` in the whole
//! window is decided by the sign of the affine function
//! `N_S D_T - N_T D_S` at the window corner where it is smallest (a
//! plane's minimum over a rectangle is at a corner), in `i128`. Equal
//! depths go to the earlier triangle in the slice, as in the reference of
//! the tests. No depth is rounded: [`DepthPlane`](super::DepthPlane) is
//! not used here.
//!
//! ## Windows and bands
//!
//! The windows form a fixed quadtree over the screen: root windows of
//! `2^ROOT_LOG2_SUB` sub-pixels (256 px) at multiples of their size, each
//! split into four down to 1 sub-pixel (13 levels). A band visits only the
//! windows that meet its rows and writes only its own pixels, but decides
//! every window over the whole window; the decisions, and therefore the
//! pixels, do not depend on the band height (bit for bit).
//!
//! ## Storage and cost
//!
//! The candidate lists of the windows on the current path of the
//! depth-first walk live in the caller's `scratch: &mut [u16]` (one index
//! per triangle per level); a child's list is a subset of its parent's, so
//! [`scratch_len`]`(n) = 13 n` indices always suffice, and a scene needing
//! more than the caller gave stops with [`HsrError::Capacity`]. The walk's
//! stack is a fixed array of 13 windows on the call stack; no recursion.
//! Two small direct-mapped caches live on the call stack too: the Gouraud
//! planes (8) and the outlines with depth planes (8) of the triangles met
//! last. Measured on a Cortex-M0 (QEMU, the no-panic firmware build): about
//! 5.5 KB of stack for a call, caches included.
//!
//! Multiplies happen in window setup: the classification of each candidate
//! (edge functions at corners, a few `i64` products per candidate per
//! window), depth comparisons (`i128` products), the area of a triangle in
//! a pixel or sub-pixel window (per edge: a few products and one division),
//! the split by an intersection line (`i128` products, one division), the
//! 16 point tests of a sampled window, and the Gouraud plane of each surface drawn in a resolved window (the
//! divisions of [`Plane::triangle`]). Filling a window of whole pixels is
//! one addition and one shift per pixel and channel.
//!
//! Measured: a lit torus of 576 triangles (284 facing the camera) on
//! 240x240 takes 37 M x86 instructions in 16-row bands, 33 M as one band,
//! 135 M in 1-row bands (the windows above a band are decided again in
//! every band); four interpenetrating triangles on 64x64 RGB in 4-row bands
//! take 19.5 M instructions on a Cortex-M0, where every `i64` and `i128`
//! product and division is a library call: far more than the z-buffer.

use super::{DepthTriangle, HsrError};
use crate::band::BandBuffer;
use crate::raster::DrawError;
use crate::shade::{Plane, PLANE_FRAC};
use crate::{COVER_BITS, SUB_BITS};

/// Size of a root window, `log2` of sub-pixels: 4096 sub-pixels = 256 px.
pub const ROOT_LOG2_SUB: u32 = 12;

/// Levels of the window tree, from a root window down to 1/16 px windows.
pub const LEVELS: usize = ROOT_LOG2_SUB as usize + 1;

/// Most triangles that may show partly in one resolved window.
pub const MAX_PARTIAL: usize = 4;

/// Most triangles one call takes: a candidate is a 15-bit index, the top
/// bit of its `u16` flags "surrounds the window".
pub const MAX_TRIANGLES: usize = 1 << 15;

/// Sample points per axis in a 1/16-px window that the rule cannot
/// resolve: 4 x 4 points, each standing for 1/4096 px.
const SAMPLES: i64 = 4;

/// The flag of a candidate that surrounds its window.
const SURROUNDS: u16 = 1 << 15;

/// Scratch `u16`s that always suffice for `triangles` triangles: one index
/// per triangle per level of the window tree.
pub const fn scratch_len(triangles: usize) -> usize {
    triangles * LEVELS
}

/// What a [`draw_warnock`] call did (for tests and profiles).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct WarnockStats {
    /// Windows looked at (each with its candidate list).
    pub windows: u32,
    /// Windows of whole pixels filled by one surface (rules 4-5).
    pub filled: u32,
    /// Pixel or sub-pixel windows resolved by exact areas.
    pub by_area: u32,
    /// 1/16-px windows given to the surface nearest at their centre.
    pub sampled: u32,
    /// Most scratch `u16`s in use at once.
    pub peak_scratch: usize,
}

/// Draws the visible surfaces of `tris` into `band` by Warnock's
/// subdivision. The band must be cleared to the background; triangles of
/// zero area are skipped (nothing drawn).
///
/// A window of a fixed quadtree (roots of 256 px, down to 1/16 px) is drawn
/// when, behind all that shows in it, one triangle (or the background)
/// surrounds it and the triangles in front of that do not overlap one
/// another (exact integer tests at the window's corners); else it is split
/// in four. Windows bigger than a pixel are drawn only when one surface
/// fills them (one addition per pixel).
///
/// - Accuracy: coverage exact within 1/4096 px per pixel wherever a window
///   is resolved by the rules, which includes every silhouette over a
///   farther surface, every shared edge of a mesh and every intersection
///   line of two surfaces; a 1/16-px window that is still not simple
///   (visible edges crossing, an edge piercing another surface) is point
///   sampled 4 x 4: at most 1/256 px off. Intensity: each surface's
///   Gouraud plane at the pixel centre times its area; the background on
///   the rest.
/// - The pixels do not depend on the band height (bit for bit).
/// - Storage: `scratch` holds the candidate lists of the windows on the
///   current path, [`scratch_len`]`(n) = 13 n` `u16`s always suffice (26
///   bytes per triangle); the walk's stack is a fixed array of 13 windows.
///
/// Errors: a vertex outside the coordinate range, [`HsrError::Draw`],
/// nothing drawn; more than [`MAX_TRIANGLES`], or a scene needing more
/// `scratch` than given ([`scratch_len`] always suffices),
/// [`HsrError::Capacity`] with the length needed at least (the band may
/// then be partly drawn).
///
/// ```
/// use softedge::hsr::{draw_warnock, scratch_len, DepthTriangle};
/// use softedge::{Band, BandBuffer, SubPoint};
/// let band = Band::new(8, 0, 8);
/// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// buf.clear([0]);
/// let p = |x, y| SubPoint::from_px(x, y);
/// let far = DepthTriangle::new([p(0, 0), p(8, 0), p(0, 8)], [[1000]; 3], [100; 3]);
/// let near = DepthTriangle::new([p(0, 0), p(4, 0), p(0, 4)], [[3000]; 3], [900; 3]);
/// let mut scratch = [0u16; scratch_len(2)];
/// draw_warnock(&[far, near], &mut buf, &mut scratch).unwrap();
/// assert_eq!(buf.lin12(1, 1), Some([3000]));
/// assert_eq!(buf.lin12(5, 1), Some([1000]));
/// // Half of pixel (3, 0) is the near triangle, half the far one.
/// assert_eq!(buf.lin12(3, 0), Some([2000]));
/// ```
pub fn draw_warnock<const C: usize>(
    tris: &[DepthTriangle<C>],
    band: &mut BandBuffer<'_, C>,
    scratch: &mut [u16],
) -> Result<WarnockStats, HsrError> {
    for t in tris {
        for v in t.vertices {
            v.check().map_err(DrawError::from)?;
        }
    }
    if tris.len() > MAX_TRIANGLES {
        return Err(HsrError::Capacity { needed: tris.len() });
    }
    let info = band.band();
    let one = crate::SUB_ONE;
    let area = Rect {
        x0: 0,
        y0: info.y0 * one,
        x1: i32::from(info.width) * one,
        y1: (info.y0 + i32::from(info.rows)) * one,
    };
    let mut walk = Walk {
        tris,
        band,
        scratch,
        area,
        stats: WarnockStats::default(),
        planes: [None; PLANE_CACHE],
        geos: [None; GEO_CACHE],
    };
    let r = ROOT_LOG2_SUB;
    for ty in (area.y0 >> r)..=((area.y1 - 1) >> r) {
        for tx in (area.x0 >> r)..=((area.x1 - 1) >> r) {
            walk.root(Window {
                x: tx << r,
                y: ty << r,
                log: r,
            })?;
        }
    }
    Ok(walk.stats)
}

/// A square window: `[x, x + 2^log) x [y, y + 2^log)` in sub-pixels.
#[derive(Debug, Clone, Copy)]
struct Window {
    x: i32,
    y: i32,
    log: u32,
}

impl Window {
    fn size(&self) -> i32 {
        1 << self.log
    }

    /// Quarter `q` (0..4, row-major).
    fn child(&self, q: u8) -> Self {
        let h = self.size() >> 1;
        Self {
            x: self.x + if q & 1 != 0 { h } else { 0 },
            y: self.y + if q & 2 != 0 { h } else { 0 },
            log: self.log.saturating_sub(1),
        }
    }

    fn meets(&self, r: &Rect) -> bool {
        self.x < r.x1 && self.x + self.size() > r.x0 && self.y < r.y1 && self.y + self.size() > r.y0
    }
}

/// The band's pixels, in sub-pixels.
#[derive(Debug, Clone, Copy)]
struct Rect {
    x0: i32,
    y0: i32,
    x1: i32,
    y1: i32,
}

/// How a triangle lies towards a window.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Relation {
    /// No common area.
    Outside,
    /// Cuts the window or lies inside it.
    Partial,
    /// The window is inside the (closed) triangle.
    Surrounds,
}

/// The outline of one triangle for the exact window tests (computed where
/// needed: a few products, no division).
#[derive(Debug, Clone, Copy)]
struct Outline {
    /// Vertices, sub-pixels.
    v: [(i32, i32); 3],
    /// Edge functions `a x + b y + c`, positive inside: `[a, b, c]`.
    edges: [[i64; 3]; 3],
    /// Bounding box `(x_min, y_min, x_max, y_max)`.
    bbox: (i32, i32, i32, i32),
}

/// The exact depth plane of one triangle: `z = (nx x + ny y + n0) / den`.
#[derive(Debug, Clone, Copy)]
struct DepthFn {
    nx: i64,
    ny: i64,
    n0: i64,
    /// Twice the area, `> 0`.
    den: i64,
}

/// Twice the signed area of a triangle (sub-pixels²): `|d| <= 2^33` for
/// vertices in range (`|x|, |y| <= 2^15`).
fn doubled_area(v: &[(i64, i64); 3]) -> i64 {
    (v[1].0 - v[0].0) * (v[2].1 - v[0].1) - (v[2].0 - v[0].0) * (v[1].1 - v[0].1)
}

impl DepthFn {
    /// `None` for a triangle of zero area. `|nx|, |ny| <= 2^34`,
    /// `|n0| < 2^51`, all in `i64`.
    fn new<const C: usize>(t: &DepthTriangle<C>) -> Option<Self> {
        let v = t.vertices.map(|p| (i64::from(p.x), i64::from(p.y)));
        let d = doubled_area(&v);
        if d == 0 {
            return None;
        }
        let s = d.signum();
        let (x0, y0) = v[0];
        let (ex1, ey1) = (v[1].0 - x0, v[1].1 - y0);
        let (ex2, ey2) = (v[2].0 - x0, v[2].1 - y0);
        let z = t.depth.map(i64::from);
        let (dz1, dz2) = (z[1] - z[0], z[2] - z[0]);
        // N = z0 d + dz1 ((p - v0) x e2) + dz2 (e1 x (p - v0)).
        let nx = dz1 * ey2 - dz2 * ey1;
        let ny = dz2 * ex1 - dz1 * ex2;
        let n0 = z[0] * d - nx * x0 - ny * y0;
        Some(Self {
            nx: s * nx,
            ny: s * ny,
            n0: s * n0,
            den: s * d,
        })
    }

    /// `m N` at the point `(px / m, py / m)` (sub-pixels).
    fn numerator_at(&self, px: i64, py: i64, m: i64) -> i128 {
        i128::from(self.nx) * i128::from(px)
            + i128::from(self.ny) * i128::from(py)
            + i128::from(m) * i128::from(self.n0)
    }
}

impl Outline {
    /// `None` for a triangle of zero area.
    fn new<const C: usize>(t: &DepthTriangle<C>) -> Option<Self> {
        let v = t.vertices.map(|p| (i64::from(p.x), i64::from(p.y)));
        let d = doubled_area(&v);
        if d == 0 {
            return None;
        }
        let s = d.signum();
        let mut edges = [[0i64; 3]; 3];
        for k in 0..3 {
            let (ax, ay) = v[k];
            let (bx, by) = v[(k + 1) % 3];
            // s * cross(b - a, p - a) > 0 inside.
            let a = -s * (by - ay);
            let b = s * (bx - ax);
            edges[k] = [a, b, -(a * ax + b * ay)];
        }
        let xs = t.vertices.map(|p| p.x);
        let ys = t.vertices.map(|p| p.y);
        Some(Self {
            v: t.vertices.map(|p| (p.x, p.y)),
            edges,
            bbox: (
                xs[0].min(xs[1]).min(xs[2]),
                ys[0].min(ys[1]).min(ys[2]),
                xs[0].max(xs[1]).max(xs[2]),
                ys[0].max(ys[1]).max(ys[2]),
            ),
        })
    }

    fn relation(&self, w: &Window) -> Relation {
        let (x0, y0) = (i64::from(w.x), i64::from(w.y));
        let (x1, y1) = (x0 + i64::from(w.size()), y0 + i64::from(w.size()));
        let (bx0, by0, bx1, by1) = self.bbox;
        let (bx0, by0, bx1, by1) = (
            i64::from(bx0),
            i64::from(by0),
            i64::from(bx1),
            i64::from(by1),
        );
        if bx1 <= x0 || bx0 >= x1 || by1 <= y0 || by0 >= y1 {
            return Relation::Outside;
        }
        let mut surrounds = true;
        for [a, b, c] in self.edges {
            // The corner where the edge function is largest, and smallest.
            let (xh, xl) = if a > 0 { (x1, x0) } else { (x0, x1) };
            let (yh, yl) = if b > 0 { (y1, y0) } else { (y0, y1) };
            if a * xh + b * yh + c <= 0 {
                return Relation::Outside;
            }
            if a * xl + b * yl + c < 0 {
                surrounds = false;
            }
        }
        if surrounds {
            Relation::Surrounds
        } else {
            Relation::Partial
        }
    }

    /// Is the point `(px / m, py / m)` (sub-pixels) inside, under the
    /// top-left rule (nudged by `(ε, ε²)`, as the tests' reference)?
    /// `m <= 8`: products below `2^38`.
    fn holds(&self, px: i64, py: i64, m: i64) -> bool {
        self.edges.iter().all(|&[a, b, c]| {
            let e = a * px + b * py + m * c;
            e > 0 || (e == 0 && (a > 0 || (a == 0 && b > 0)))
        })
    }

    /// Are the two triangles' interiors disjoint? (A line along an edge of
    /// one of them has the other wholly on its outer side.)
    fn separated(&self, other: &Self) -> bool {
        let apart = |g: &Self, h: &Self| {
            g.edges.iter().any(|&[a, b, c]| {
                h.v.iter()
                    .all(|&(x, y)| a * i64::from(x) + b * i64::from(y) + c <= 0)
            })
        };
        apart(self, other) || apart(other, self)
    }
}

/// Is `s` (index `is`) nearer than `t` (index `it`) everywhere in `w`?
/// Ties go to the smaller index. `N_s D_t - N_t D_s` is affine: its
/// smallest value over the window is at a corner; products below `2^87`.
fn nearer_in(s: &DepthFn, is: usize, t: &DepthFn, it: usize, w: &Window) -> bool {
    let (ds, dt) = (i128::from(s.den), i128::from(t.den));
    let cx = i128::from(s.nx) * dt - i128::from(t.nx) * ds;
    let cy = i128::from(s.ny) * dt - i128::from(t.ny) * ds;
    let c0 = i128::from(s.n0) * dt - i128::from(t.n0) * ds;
    let (x0, y0) = (i128::from(w.x), i128::from(w.y));
    let size = i128::from(w.size());
    let x = if cx >= 0 { x0 } else { x0 + size };
    let y = if cy >= 0 { y0 } else { y0 + size };
    let low = cx * x + cy * y + c0;
    low > 0 || (low == 0 && is < it)
}

/// Is `s` nearer than `t` at the centre of the 1-sub-pixel window at
/// `(x, y)`? (Ties to the smaller index.)
fn nearer_at_centre(s: &DepthFn, is: usize, t: &DepthFn, it: usize, x: i64, y: i64) -> bool {
    let a = s.numerator_at(2 * x + 1, 2 * y + 1, 2) * i128::from(t.den);
    let b = t.numerator_at(2 * x + 1, 2 * y + 1, 2) * i128::from(s.den);
    a > b || (a == b && is < it)
}

/// `round(n / d)` for `d > 0`.
fn div_round(n: i64, d: i64) -> i64 {
    crate::arith::div_floor(2 * n + d, 2 * d)
}

/// `2 dy k` times the area, within `y` in `[ya, yb]`, right of `x = l` and
/// left of the edge through `(ax, ay)` with direction `(dx, dy)`, `dy > 0`,
/// `k = max(|dx|, 1)`. `u = (x(y) - l) dy` at both ends: a trapezoid if
/// both are `>= 0`, nothing if both are `<= 0`, else the triangle
/// `u^2 / (2 dy |dx|)`. With `yb - ya <= 16` and coordinates below
/// `2^15.2`: `|u| < 2^33.2`, the trapezoid term below `2^55`, the triangle's
/// `u <= 16 |dx|`.
fn right_of(ax: i64, ay: i64, dx: i64, dy: i64, ya: i64, yb: i64, l: i64) -> i64 {
    let k = dx.abs().max(1);
    let ua = (ax - l) * dy + dx * (ya - ay);
    let ub = (ax - l) * dy + dx * (yb - ay);
    if ua >= 0 && ub >= 0 {
        (ua + ub) * (yb - ya) * k
    } else if ua <= 0 && ub <= 0 {
        0
    } else {
        let u = ua.max(ub);
        u * u
    }
}

/// Fraction bits of the areas [`area_in`] gives: 1/2^20 px, so the
/// rounding of its three terms, `1.5 / 2^20` px per triangle per window,
/// stays below 1/4096 px even summed over every window of a pixel.
const AREA_FRAC: u32 = 20;

/// The area of triangle `v` inside the rectangle `[x0, x1] x [y0, y1]`
/// (sub-pixels, at most one pixel wide and tall), in `1/2^AREA_FRAC` px:
/// the boundary integral of `clamp(x, x0, x1) - x0` over the three edges,
/// each edge's term rounded once.
fn area_in(v: &[(i64, i64); 3], x0: i64, y0: i64, x1: i64, y1: i64) -> i64 {
    let mut total = 0i64;
    for k in 0..3 {
        let (p, q) = (v[k], v[(k + 1) % 3]);
        if p.1 == q.1 {
            continue;
        }
        let (a, b, sign) = if p.1 < q.1 { (p, q, 1) } else { (q, p, -1) };
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let (ya, yb) = (a.1.max(y0), b.1.min(y1));
        if ya >= yb {
            continue;
        }
        let k = dx.abs().max(1);
        // The difference is at most (x1 - x0)(yb - ya) 2 dy k < 2^42.
        let r = right_of(a.0, a.1, dx, dy, ya, yb, x0) - right_of(a.0, a.1, dx, dy, ya, yb, x1);
        // r / (2 dy k) sub², one sub² being 2^(AREA_FRAC - 8) units.
        total += sign * div_round(r << (AREA_FRAC - 9), dy * k);
    }
    total.abs()
}

/// The share of a window where `f(u, v) = cx u + cy v + d0 >= 0`, for
/// `u, v` in `[0, 1]`, in `1/2^AREA_FRAC` of the window: where the nearer
/// of two planes crossing in the window is the one `f` favours.
///
/// Exact but for one normalisation: when the line crosses the window the
/// coefficients are shifted right until the larger slope is below `2^20`,
/// which moves the line by less than `2^-18` of the window (the share by
/// less than `2^-17`). Then, with `cy > 0` and `cx >= 0` (mirroring `u`,
/// `v` or swapping them does not change the share), the part below the
/// line is `∫ clamp(g(u), 0, 1) du` for `g = -(d0 + cx u) / cy`, the same
/// trapezoid-or-triangle integral as [`right_of`]; every product stays
/// below `2^61`.
fn half_plane_share(cx: i128, cy: i128, d0: i128) -> i64 {
    let one = 1i64 << AREA_FRAC;
    let corners = [d0, d0 + cx, d0 + cy, d0 + cx + cy];
    if corners.iter().all(|&f| f >= 0) {
        return one;
    }
    if corners.iter().all(|&f| f <= 0) {
        return 0;
    }
    // The line crosses the window: |d0| <= |cx| + |cy|.
    let m = cx.unsigned_abs().max(cy.unsigned_abs());
    let k = (128 - m.leading_zeros()).saturating_sub(20);
    let narrow = |v: i128| (v >> k) as i64;
    let (mut cx, mut cy, mut d0) = (narrow(cx), narrow(cy), narrow(d0));
    if cy.abs() < cx.abs() {
        core::mem::swap(&mut cx, &mut cy);
    }
    if cy < 0 {
        // v -> 1 - v.
        d0 += cy;
        cy = -cy;
    }
    if cx < 0 {
        // u -> 1 - u.
        d0 += cx;
        cx = -cx;
    }
    if cy == 0 {
        return if d0 >= 0 { one } else { 0 };
    }
    let kk = cx.max(1);
    // 2 kk times the integral of max(G(u) - h, 0), G(u) = -d0 - cx u
    // (decreasing), over [0, 1].
    let part = |h: i64| {
        let (a, b) = (-d0 - h, -d0 - cx - h);
        if b >= 0 {
            (a + b) * kk
        } else if a <= 0 {
            0
        } else {
            a * a
        }
    };
    let below = div_round((part(0) - part(cy)) << (AREA_FRAC - 1), kk * cy);
    (one - below).clamp(0, one)
}

/// One window of the depth-first walk: its candidates are
/// `scratch[start..start + len]`; `next` is the next quarter to visit.
#[derive(Debug, Clone, Copy)]
struct Frame {
    w: Window,
    start: usize,
    len: usize,
    next: u8,
}

/// The state of one [`draw_warnock`] call.
struct Walk<'t, 's, 'b, 'a, const C: usize> {
    tris: &'t [DepthTriangle<C>],
    band: &'b mut BandBuffer<'a, C>,
    scratch: &'s mut [u16],
    area: Rect,
    stats: WarnockStats,
    /// The Gouraud planes set up last, direct-mapped by triangle index:
    /// the windows along an edge ask for the same few planes over and over,
    /// and each costs divisions to set up.
    planes: [Option<(u16, Plane<C>)>; PLANE_CACHE],
    /// The outlines and depth planes set up last, direct-mapped by triangle
    /// index: a candidate is tested in every window on its way down.
    geos: [Option<(u16, Outline, DepthFn)>; GEO_CACHE],
}

/// Entries of the outline cache (a power of two).
const GEO_CACHE: usize = 8;

/// Entries of the plane cache (a power of two).
const PLANE_CACHE: usize = 8;

/// What the rule made of a window.
enum Outcome {
    /// Drawn.
    Done,
    /// To be split; the candidate list, with hidden triangles dropped, now
    /// has this length.
    Split(usize),
}

impl<const C: usize> Walk<'_, '_, '_, '_, C> {
    /// The cached outline and depth plane of triangle `idx`, if cached.
    fn cached(&self, idx: u16) -> Option<(Outline, DepthFn)> {
        let idx = idx & !SURROUNDS;
        match self.geos.get(usize::from(idx) & (GEO_CACHE - 1)) {
            Some(Some((cached, o, d))) if *cached == idx => Some((*o, *d)),
            _ => None,
        }
    }

    /// The outline of triangle `idx` (a miss is set up but not cached: the
    /// long lists of the large windows would only flush the cache).
    fn outline(&mut self, idx: u16) -> Option<Outline> {
        match self.cached(idx) {
            Some((o, _)) => Some(o),
            None => Outline::new(self.tris.get(usize::from(idx & !SURROUNDS))?),
        }
    }

    /// The depth plane of triangle `idx`; a miss sets up and caches the
    /// outline too (depths are asked for in the small windows, where the
    /// same few triangles come back).
    fn depth(&mut self, idx: u16) -> Option<DepthFn> {
        if let Some((_, d)) = self.cached(idx) {
            return Some(d);
        }
        let idx = idx & !SURROUNDS;
        let t = self.tris.get(usize::from(idx))?;
        let (o, d) = (Outline::new(t)?, DepthFn::new(t)?);
        if let Some(entry) = self.geos.get_mut(usize::from(idx) & (GEO_CACHE - 1)) {
            *entry = Some((idx, o, d));
        }
        Some(d)
    }

    fn put(&mut self, at: usize, entry: u16) -> Result<(), HsrError> {
        match self.scratch.get_mut(at) {
            Some(s) => {
                *s = entry;
                self.stats.peak_scratch = self.stats.peak_scratch.max(at + 1);
                Ok(())
            }
            None => Err(HsrError::Capacity { needed: at + 1 }),
        }
    }

    /// The list entry of a triangle towards window `w`: its index, flagged
    /// when it surrounds the window; `None` when it misses it.
    fn entry(&mut self, idx: u16, w: &Window) -> Option<u16> {
        match self.outline(idx)?.relation(w) {
            Relation::Outside => None,
            Relation::Partial => Some(idx),
            Relation::Surrounds => Some(idx | SURROUNDS),
        }
    }

    /// Walks the window tree under one root window.
    fn root(&mut self, w: Window) -> Result<(), HsrError> {
        let mut len = 0;
        for k in 0..self.tris.len() {
            if let Some(e) = self.entry(k as u16, &w) {
                self.put(len, e)?;
                len += 1;
            }
        }
        let mut stack: heapless::Vec<Frame, LEVELS> = heapless::Vec::new();
        if let Outcome::Split(len) = self.decide(&w, 0, len) {
            let _ = stack.push(Frame {
                w,
                start: 0,
                len,
                next: 0,
            });
        }
        while let Some(top) = stack.last_mut() {
            if top.next >= 4 {
                stack.pop();
                continue;
            }
            let f = *top;
            top.next += 1;
            let cw = f.w.child(f.next);
            if !cw.meets(&self.area) {
                continue;
            }
            // The quarter's candidates, after its parent's. What surrounds
            // the parent surrounds the quarter.
            let start = f.start + f.len;
            let mut len = 0;
            for k in f.start..f.start + f.len {
                let Some(&e) = self.scratch.get(k) else {
                    break;
                };
                let child = if e & SURROUNDS != 0 {
                    Some(e)
                } else {
                    self.entry(e, &cw)
                };
                if let Some(e) = child {
                    self.put(start + len, e)?;
                    len += 1;
                }
            }
            if let Outcome::Split(len) = self.decide(&cw, start, len) {
                // The depth of the tree bounds the stack: a window of one
                // sub-pixel is never split.
                let pushed = stack.push(Frame {
                    w: cw,
                    start,
                    len,
                    next: 0,
                });
                if pushed.is_err() {
                    return Err(HsrError::Capacity { needed: LEVELS + 1 });
                }
            }
        }
        Ok(())
    }

    /// Applies the rule to window `w` with candidates
    /// `scratch[start..start + len]`: draws it, or drops the triangles the
    /// nearest surrounding one hides and asks for a split.
    fn decide(&mut self, w: &Window, start: usize, len: usize) -> Outcome {
        self.stats.windows = self.stats.windows.saturating_add(1);
        if len == 0 {
            return Outcome::Done;
        }
        let end = start + len;
        let (wx, wy) = (i64::from(w.x), i64::from(w.y));
        // S: the surrounding triangle nearest at the window's centre (the
        // centre of its top-left sub-pixel: any interior point would do).
        let mut s: Option<(u16, DepthFn)> = None;
        for k in start..end {
            let Some(&e) = self.scratch.get(k) else {
                break;
            };
            if e & SURROUNDS == 0 {
                continue;
            }
            let idx = e & !SURROUNDS;
            let Some(d) = self.depth(idx) else { continue };
            let better = match &s {
                None => true,
                Some((si, sd)) => {
                    nearer_at_centre(&d, usize::from(idx), sd, usize::from(*si), wx, wy)
                }
            };
            if better {
                s = Some((idx, d));
            }
        }
        // Without a surrounding triangle nothing can be dropped: more
        // candidates than P may hold must be split.
        if s.is_none() && len > MAX_PARTIAL {
            return if w.log == 0 {
                self.stats.sampled = self.stats.sampled.saturating_add(1);
                self.sample(w, start, end);
                Outcome::Done
            } else {
                Outcome::Split(len)
            };
        }
        // Drop what S hides; collect P, the rest.
        let mut p: heapless::Vec<u16, MAX_PARTIAL> = heapless::Vec::new();
        let mut simple = true;
        let mut kept = start;
        for k in start..end {
            let Some(&e) = self.scratch.get(k) else {
                break;
            };
            let idx = e & !SURROUNDS;
            let is_s = s.as_ref().is_some_and(|(si, _)| *si == idx);
            if let (false, Some((si, sd))) = (is_s, &s) {
                let Some(d) = self.depth(idx) else { continue };
                let (i, si) = (usize::from(idx), usize::from(*si));
                if nearer_in(sd, si, &d, i, w) {
                    continue;
                }
                // Visible somewhere: it must be a partial one in front of
                // S everywhere.
                if e & SURROUNDS != 0 || !nearer_in(&d, i, sd, si, w) {
                    simple = false;
                }
            }
            if !is_s && simple && p.push(idx).is_err() {
                simple = false;
            }
            if let Some(slot) = self.scratch.get_mut(kept) {
                *slot = e;
            }
            kept += 1;
        }
        let pixel = w.log <= SUB_BITS;
        if simple && (p.is_empty() || pixel) {
            let mut outlines: heapless::Vec<(u16, Outline), MAX_PARTIAL> = heapless::Vec::new();
            for &idx in &p {
                if let Some(o) = self.outline(idx) {
                    let _ = outlines.push((idx, o));
                }
            }
            for (a, (_, oa)) in outlines.iter().enumerate() {
                for (_, ob) in outlines.iter().skip(a + 1) {
                    if !oa.separated(ob) {
                        simple = false;
                    }
                }
            }
            if simple {
                let surface = s.map(|(idx, _)| idx);
                if pixel {
                    self.stats.by_area = self.stats.by_area.saturating_add(1);
                    self.draw_small(w, surface, &outlines);
                } else {
                    self.stats.filled = self.stats.filled.saturating_add(1);
                    if let Some(idx) = surface {
                        self.fill(w, idx);
                    }
                }
                return Outcome::Done;
            }
        }
        if pixel && kept - start == 2 {
            // Two surfaces that both cover the window and pass through
            // each other: split exactly by their intersection line.
            let pair = (self.scratch.get(start), self.scratch.get(start + 1));
            if let (Some(&a), Some(&b)) = pair {
                if a & b & SURROUNDS != 0 {
                    self.stats.by_area = self.stats.by_area.saturating_add(1);
                    self.draw_crossing(w, a & !SURROUNDS, b & !SURROUNDS);
                    return Outcome::Done;
                }
            }
        }
        if w.log == 0 {
            self.stats.sampled = self.stats.sampled.saturating_add(1);
            self.sample(w, start, kept);
            return Outcome::Done;
        }
        Outcome::Split(kept - start)
    }

    /// The Gouraud plane of triangle `idx`, relative to the background
    /// (from the cache, or set up and cached).
    fn plane(&mut self, idx: u16) -> Option<Plane<C>> {
        let idx = idx & !SURROUNDS;
        let slot = usize::from(idx) & (PLANE_CACHE - 1);
        if let Some(Some((cached, plane))) = self.planes.get(slot) {
            if *cached == idx {
                return Some(*plane);
            }
        }
        let t = self.tris.get(usize::from(idx))?;
        let plane = Plane::triangle(t.vertices, t.colors, self.band.background())?;
        if let Some(entry) = self.planes.get_mut(slot) {
            *entry = Some((idx, plane));
        }
        Some(plane)
    }

    /// Fills the band's pixels of window `w` (whole pixels) with triangle
    /// `idx`: per pixel, `(I * 4096) >> 16`, stepped by one addition.
    fn fill(&mut self, w: &Window, idx: u16) {
        let Some(plane) = self.plane(idx) else {
            return;
        };
        let a = self.area;
        let (x0, x1) = (
            w.x.max(a.x0) >> SUB_BITS,
            (w.x + w.size()).min(a.x1) >> SUB_BITS,
        );
        let (y0, y1) = (
            w.y.max(a.y0) >> SUB_BITS,
            (w.y + w.size()).min(a.y1) >> SUB_BITS,
        );
        let gx = plane.gx.map(|g| i64::from(g) << COVER_BITS);
        for j in y0..y1 {
            // Row setup: two multiplies per channel.
            let mut v = plane.at(x0, j).map(|i| i << COVER_BITS);
            for i in x0..x1 {
                let mut cell = [0i32; C];
                for ch in 0..C {
                    cell[ch] = (v[ch] >> PLANE_FRAC) as i32;
                    v[ch] += gx[ch];
                }
                self.band.add_cell(i, j, &cell);
            }
        }
    }

    /// Draws a window of one pixel or less: each of `p` with its exact area
    /// in the window, `s` (or the background) on the rest.
    fn draw_small(&mut self, w: &Window, s: Option<u16>, p: &[(u16, Outline)]) {
        let (i, j) = (w.x >> SUB_BITS, w.y >> SUB_BITS);
        let (x0, y0) = (i64::from(w.x), i64::from(w.y));
        let size = i64::from(w.size());
        // The window's area in 1/2^AREA_FRAC px: 2^(AREA_FRAC - 8) per
        // sub-pixel². Intensities below 2^30 times areas up to 2^20 fit.
        let mut rest = (size * size) << (AREA_FRAC - 8);
        let shift = PLANE_FRAC + AREA_FRAC - COVER_BITS;
        let mut cell = [0i64; C];
        for (idx, o) in p {
            let v = o.v.map(|(x, y)| (i64::from(x), i64::from(y)));
            let a = area_in(&v, x0, y0, x0 + size, y0 + size).min(rest);
            rest -= a;
            if let Some(plane) = self.plane(*idx) {
                let at = plane.at(i, j);
                for ch in 0..C {
                    cell[ch] += (at[ch] * a) >> shift;
                }
            }
        }
        if let Some(plane) = s.and_then(|idx| self.plane(idx)) {
            let at = plane.at(i, j);
            for ch in 0..C {
                cell[ch] += (at[ch] * rest) >> shift;
            }
        }
        self.band.add_cell(i, j, &cell.map(saturate));
    }

    /// Draws a window of one pixel or less covered by two triangles `a`
    /// and `b` whose planes cross in it: each where it is nearer.
    fn draw_crossing(&mut self, w: &Window, a: u16, b: u16) {
        let (Some(da), Some(db)) = (self.depth(a), self.depth(b)) else {
            return;
        };
        // f = N_a D_b - N_b D_a (> 0 where a is nearer), over the window
        // as the unit square: products below 2^88.
        let (ta, tb) = (i128::from(da.den), i128::from(db.den));
        let size = i128::from(w.size());
        let cx = i128::from(da.nx) * tb - i128::from(db.nx) * ta;
        let cy = i128::from(da.ny) * tb - i128::from(db.ny) * ta;
        let d0 = cx * i128::from(w.x) + cy * i128::from(w.y) + i128::from(da.n0) * tb
            - i128::from(db.n0) * ta;
        let share = half_plane_share(cx * size, cy * size, d0);
        let (i, j) = (w.x >> SUB_BITS, w.y >> SUB_BITS);
        let whole = i64::from(w.size() * w.size()) << (AREA_FRAC - 8);
        let area_a = (share * whole) >> AREA_FRAC;
        let shift = PLANE_FRAC + AREA_FRAC - COVER_BITS;
        let mut cell = [0i64; C];
        for (idx, area) in [(a, area_a), (b, whole - area_a)] {
            if let Some(plane) = self.plane(idx) {
                let at = plane.at(i, j);
                for ch in 0..C {
                    cell[ch] += (at[ch] * area) >> shift;
                }
            }
        }
        self.band.add_cell(i, j, &cell.map(saturate));
    }

    /// A 1/16-px window not simple enough: each of its 4 x 4 sample
    /// points (1/4096 px each) goes to the candidate nearest there, under
    /// the top-left rule with exact depths. (Out of line: its frame is not
    /// kept on the stack through the walk.)
    #[inline(never)]
    fn sample(&mut self, w: &Window, start: usize, end: usize) {
        const N: usize = (SAMPLES * SAMPLES) as usize;
        let (x, y) = (i64::from(w.x), i64::from(w.y));
        let point = |n: usize| {
            let (s, t) = ((n as i64) % SAMPLES, (n as i64) / SAMPLES);
            (2 * SAMPLES * x + 2 * s + 1, 2 * SAMPLES * y + 2 * t + 1)
        };
        // Per point: the nearest candidate holding it, with its depth
        // numerator there and its denominator.
        let mut best: [Option<(u16, i128, i64)>; N] = [None; N];
        for k in start..end {
            let Some(&e) = self.scratch.get(k) else {
                break;
            };
            let idx = e & !SURROUNDS;
            let (Some(o), Some(d)) = (self.outline(idx), self.depth(idx)) else {
                continue;
            };
            for (n, slot) in best.iter_mut().enumerate() {
                let (px, py) = point(n);
                if e & SURROUNDS == 0 && !o.holds(px, py, 2 * SAMPLES) {
                    continue;
                }
                let z = d.numerator_at(px, py, 2 * SAMPLES);
                let better = match slot {
                    None => true,
                    Some((bi, bz, bden)) => {
                        let (a, b) = (z * i128::from(*bden), *bz * i128::from(d.den));
                        a > b || (a == b && idx < *bi)
                    }
                };
                if better {
                    *slot = Some((idx, z, d.den));
                }
            }
        }
        // Each point is 1/16 of 1/256 px: 2^-12 of a pixel.
        const POINT_BITS: u32 = 12;
        let shift = PLANE_FRAC + POINT_BITS - COVER_BITS;
        let (i, j) = (w.x >> SUB_BITS, w.y >> SUB_BITS);
        let mut cell = [0i64; C];
        for n in 0..N {
            let Some(Some((idx, _, _))) = best.get(n).copied() else {
                continue;
            };
            if best
                .get(..n)
                .is_some_and(|b| b.iter().any(|p| p.is_some_and(|p| p.0 == idx)))
            {
                continue; // counted with its first point
            }
            let count = best
                .iter()
                .filter(|p| p.is_some_and(|p| p.0 == idx))
                .count() as i64;
            if let Some(plane) = self.plane(idx) {
                let at = plane.at(i, j);
                for ch in 0..C {
                    cell[ch] += (at[ch] * count) >> shift;
                }
            }
        }
        self.band.add_cell(i, j, &cell.map(saturate));
    }
}

fn saturate(v: i64) -> i32 {
    crate::arith::limit(v, i64::from(i32::MIN), i64::from(i32::MAX)) as i32
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::SubPoint;

    fn pts(v: [(i32, i32); 3]) -> [SubPoint; 3] {
        v.map(|(x, y)| SubPoint::new(x, y))
    }

    #[test]
    fn area_of_half_pixel_triangle() {
        let v = [(0, 0), (16, 0), (0, 16)];
        let px = 1 << AREA_FRAC;
        assert_eq!(area_in(&v, 0, 0, 16, 16), px / 2);
        assert_eq!(area_in(&v, 0, 0, 8, 8), px / 4);
        assert_eq!(area_in(&v, 8, 8, 16, 16), 0);
        // A triangle much larger than the rectangle covers all of it.
        let big = [(-1000, -1000), (3000, -1000), (-1000, 3000)];
        assert_eq!(area_in(&big, 32, 48, 48, 64), px);
        // A thin sliver: 1/3 of a sub-pixel row across the pixel.
        let thin = [(0, 4), (48, 4), (0, 5)];
        assert_eq!(area_in(&thin, 0, 0, 16, 16), (px / 256) * 16 * 5 / 6);
    }

    #[test]
    fn half_plane_shares() {
        let one = 1i64 << AREA_FRAC;
        // u >= 1/2, u <= 1/2, v >= 1/4, the diagonal u + v >= 1.
        assert_eq!(half_plane_share(2, 0, -1), one / 2);
        assert_eq!(half_plane_share(-2, 0, 1), one / 2);
        assert_eq!(half_plane_share(0, 4, -1), one * 3 / 4);
        assert_eq!(half_plane_share(1, 1, -1), one / 2);
        // u + v <= 1/2: a corner triangle of area 1/8; huge coefficients.
        let big = 1i128 << 80;
        assert_eq!(half_plane_share(-2 * big, -2 * big, big), one / 8);
        assert_eq!(half_plane_share(3, 5, 1), one);
        assert_eq!(half_plane_share(-3, -5, -1), 0);
        // 2u + v >= 1: below the line v = 1 - 2u lies 1/4.
        assert_eq!(half_plane_share(2, 1, -1), one * 3 / 4);
    }

    #[test]
    fn relations_are_exact() {
        let t = DepthTriangle::<1>::new(pts([(0, 0), (64, 0), (0, 64)]), [[0]; 3], [0; 3]);
        let g = Outline::new(&t).unwrap();
        let w = |x, y, log| Window { x, y, log };
        assert_eq!(g.relation(&w(0, 0, 4)), Relation::Surrounds);
        // The window's corner (32, 32) lies on the hypotenuse: still inside.
        assert_eq!(g.relation(&w(16, 16, 4)), Relation::Surrounds);
        assert_eq!(g.relation(&w(32, 32, 4)), Relation::Outside);
        assert_eq!(g.relation(&w(24, 24, 4)), Relation::Partial);
        assert_eq!(g.relation(&w(64, 0, 4)), Relation::Outside);
    }

    #[test]
    fn depth_order_is_exact_over_the_window() {
        // Two planes crossing along x = 32.
        let a = DepthTriangle::<1>::new(pts([(0, 0), (64, 0), (0, 64)]), [[0]; 3], [0, 64, 0]);
        let b = DepthTriangle::<1>::new(pts([(0, 0), (64, 0), (0, 64)]), [[0]; 3], [32; 3]);
        let (ga, gb) = (DepthFn::new(&a).unwrap(), DepthFn::new(&b).unwrap());
        let w = |x| Window { x, y: 0, log: 4 };
        assert!(nearer_in(&gb, 1, &ga, 0, &w(0)));
        assert!(nearer_in(&ga, 0, &gb, 1, &w(32)));
        assert!(!nearer_in(&gb, 1, &ga, 0, &w(32)));
        assert!(!nearer_in(&ga, 0, &gb, 1, &w(24)));
        assert!(!nearer_in(&gb, 1, &ga, 0, &w(24)));
    }
}
