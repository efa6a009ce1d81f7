//! Weiler–Atherton hidden-surface removal (seed 004): object-space clipping
//! of the frame's triangles into **disjoint visible polygons**, which the
//! edge engine then accumulates exactly (seed 000: `I_acc += I * S` is exact
//! for disjoint polygons, so a pixel holding pieces of several surfaces gets
//! `sum(S_k * I_k)` with `sum(S_k)` its covered area).
//!
//! Takes the frame's [`DepthTriangle`]s once per frame
//! ([`VisibleSet::compute`]); gives [`VisiblePiece`]s, each a polygon on
//! the fine grid ([`FinePoint`], 1/1024 px) that remembers its source
//! triangle; every band then draws every
//! piece with its source triangle's Gouraud plane ([`VisibleSet::draw`]),
//! so a triangle's colours do not change where it is cut, and the frame
//! does not depend on the band height (the pieces are a function of the
//! triangles alone).
//!
//! ## The algorithm
//!
//! Seed 004's Weiler–Atherton sorts by the nearest depth, clips everything
//! by the front polygon into an inside and an outside list, deletes the
//! inside polygons behind it and recurses when an inside polygon is in
//! front somewhere. With planar triangles the recursion has a closed form,
//! which is what is computed here: within two overlapping triangles `P` and
//! `Q` the region where `Q` is nearer is a half-plane (both depths are
//! affine), so the part of `Q` that hides `P` is the convex polygon
//! `R_Q = Q ∩ {z_Q > z_P}` and
//!
//! ```text
//! visible(P) = P \ union over Q of R_Q
//! ```
//!
//! For every triangle `P`, its list of convex pieces (initially `P`) is
//! clipped by every `Q` whose bounding box meets it:
//!
//! 1. The pair's relation, from the exact depth difference `z_Q - z_P` at
//!    the six vertices (affine, so its sign on their hull follows): `Q`
//!    behind everywhere (nothing to do), in front everywhere (`R_Q = Q`),
//!    or the two interpenetrate (`R_Q = Q` cut by the pair's *depth line*).
//!    Coplanar triangles: the earlier one (smaller index) is in front, as
//!    in the tests' reference (`tests/src/visible.rs`) and the `z > Z`
//!    z-buffer.
//! 2. Each piece `X` is split by `R_Q`'s lines in turn (Sutherland–Hodgman
//!    inside and outside lists, seed 004's "inside / outside" clipping):
//!    the outside parts stay visible, the part inside all the lines is
//!    hidden and dropped. A piece that `R_Q` does not reach is kept whole.
//! 3. After all triangles, the pieces are *conformed*: every vertex lying on
//!    a cut line is inserted into every piece edge along that line that
//!    spans it, so the two sides of every cut have the same vertex chain
//!    (no T-junctions: the edge engine's cover changes cancel exactly).
//!
//! The result is the seed's visible-polygon list; the order of the input
//! does not matter except for ties between coplanar triangles.
//!
//! ## Shared rounded vertices
//!
//! Every piece edge lies on a *clip line*: a triangle edge or a pair's
//! depth line, interned in a table with canonical integer coefficients
//! (`a x + b y + c = 0`, reduced by their gcd, first non-zero of `a, b`
//! positive), so that a mesh's shared edge is one line for both triangles.
//! A cut vertex is the intersection of two clip lines, computed from the
//! two lines alone (never from the piece being clipped) and rounded to the
//! nearest 1/1024 px (the fine grid of [`geom`](crate::geom); the
//! triangles' own vertices lie on it exactly): every piece that has it gets
//! the same [`FinePoint`], and step 3 puts it on both sides of its line.
//! The band draws pieces with exact box coverage of those vertices
//! (`hsr::fine_fill`: edges between two 1/16-px points by the edge walker,
//! the others by exact areas per cell); other pixel models and aliased
//! drawing take the vertices rounded to 1/16 px (the error of issue #18's
//! measurement below, before the fine grid).
//!
//! ## Remaining error
//!
//! - Pieces sharing a cut have identical vertex chains, so their coverages
//!   sum exactly to the union's: a mesh, or a triangle cut in pieces, draws
//!   like the uncut polygon, bit for bit (`tests/tests/weiler.rs`: two
//!   interpenetrating meshes of 530 triangles cover their overlap exactly).
//! - Where the boundary between two *different* surfaces (or a surface and
//!   the background) ends in a cut vertex, that vertex is rounded: within
//!   1/2048 px of the true point per axis, `sqrt(2)/2048 ≈ 0.0007` px. The
//!   piece edges ending there tilt by that much at the vertex, tapering to
//!   zero at their other end, so a pixel's share of a surface changes by at
//!   most `0.0007` px times the length of such edges inside the pixel
//!   (`≤ sqrt(2)`): **at most 1/1024 of a pixel per moved edge** (4 levels
//!   of 4095), times the colour step between the two surfaces; the fine
//!   cells add at most 1/8192 px per edge. Every other pixel is exact to
//!   the engine's 1/256: the triangles' own vertices and the parts of their
//!   edges not ending in a cut vertex are never moved. Measured on random
//!   scenes of constant-depth triangles against the exact visible area
//!   (`tests/tests/weiler.rs`): max 0.00064 px (it was 0.042 px with cut
//!   vertices on the 1/16-px grid), and on random flat convex polygons at
//!   constant depths with random colours (`tests/tests/hsr_exact.rs`): worst
//!   pixel 2.4 levels of 4095 from the exact visible area (94.6 before),
//!   against the goal of `4095 / 256 + 1 = 17`.
//! - A visible part thinner than the rounding (a sliver between two nearly
//!   parallel lines) may round to zero area and is dropped; its area is
//!   within the bound above.
//! - With another pixel model than [`PixelModel::Box`], or aliased, the
//!   pieces are drawn with their vertices rounded to 1/16 px (those walks
//!   take no finer vertices yet): within 1/32 px per axis, at most 1/16 of
//!   a pixel per moved edge.
//! - Depth lines are kept to `|a|, |b| < 2^24` (see below): the line then
//!   differs from the exact intersection by under 1/2048 px in the
//!   coordinate range. Where three depth lines meet (three mutually
//!   interpenetrating triangles) the three rounded meeting points may differ
//!   by one sub-pixel step: a hole or overlap of at most 1/512 px there.
//!
//! ## Integer ranges
//!
//! Triangle coordinates are `|x|, |y| <= 2^15` sub-pixels
//! ([`geom`](crate::geom)), piece vertices `<= 2^21` fine units, depths
//! `< 2^16`. A triangle's depth plane `z = (A x + B y + C) / D` has
//! `|D|, |A|, |B| < 2^34`, `|C| < 2^51`; the depth difference of a pair,
//! scaled by `D_P D_Q`, has coefficients below `2^86` in `i128`. It is
//! reduced by its gcd and then shifted right until `|a|, |b| < 2^24`; it is
//! only used where the sign of the difference changes over the pair's
//! vertices, so the line passes through the coordinate box and
//! `|c| < 2^41`. Edge lines have `|a|, |b| <= 2^16`, `|c| <= 2^32`. Line
//! intersections then need `|a1 b2 - a2 b1| < 2^49` and numerators
//! `< 2^72` with the fine grid's factor 64 (`i128`); line values at a
//! fine vertex (`a x + b y + 64 c`) are `< 2^48`; the exact corners of a
//! hiding region have numerators below `2^64`, so the separating-axis
//! test's products stay below `2^90`.
//!
//! ## Storage
//!
//! A [`VisibleSet<N>`] holds up to `N` pieces and `N` distinct clip lines
//! in `heapless` vectors, no heap: a piece is
//! `size_of::<VisiblePiece>()` = 16 vertices × (8 bytes + a 2-byte line
//! index) + 4 = **164 bytes**, a line 24 bytes, so `N = 256` takes about
//! 48 KiB (place the set in a `static` or the frame's RAM, not the stack).
//! A scene that needs more returns [`HsrError::Capacity`] with the count
//! that ran out (pieces or lines, at least `N + 1`), and the set is left
//! empty: never a panic, never a silently truncated frame. An outline
//! longer than [`PIECE_VERTICES`] (a piece that collected many cut
//! vertices) is stored as several pieces split along a diagonal between
//! two of its vertices (both sides share it, so it adds no error); only an
//! outline beyond `2 * PIECE_VERTICES` vertices, or one too bent to split
//! with both parts keeping its orientation, reports
//! `Capacity { needed: PIECE_VERTICES + 1 }`.
//!
//! ## No panics
//!
//! Every index is a `get`, every division a `checked_div`; the magnitudes
//! above keep every product far inside `i128`. A firmware build that
//! calls [`VisibleSet::compute`] and [`VisibleSet::draw`] on run-time
//! triangles links with `boards/qemu-m0 --features no-panic` (checked by
//! hand with a temporary probe in `boards/common`, not committed).
//!
//! ## Cost
//!
//! Setup (everything in [`VisibleSet::compute`]) multiplies and divides
//! once per frame; the per-pixel work is the edge engine's. Clipping tests
//! every ordered pair of triangles whose bounding boxes meet (`O(n^2)`
//! box tests, exact work only for overlapping pairs); conforming scans,
//! for every piece edge, the vertices of all pieces (`O(E * V)`, with a
//! box test first): 25 ms on a desktop for 530 triangles cutting each
//! other (`tests/tests/weiler.rs`). Stack: about 3 KiB, estimated from
//! the outlines in flight while one piece is clipped (up to six 324-byte
//! working outlines and three 164-byte pieces); not measured on a board.

use heapless::Vec;

use super::fine_fill::{area2_fine, fill_fine};
use super::{DepthTriangle, HsrError};
use crate::band::BandBuffer;
use crate::geom::{FinePoint, SubPoint, FINE_BITS};
use crate::raster::{fill, DrawError, PixelModel, RenderStyle};
use crate::shade::Plane;
use crate::SUB_BITS;

/// Fine units per sub-pixel unit: `1024 / 16`.
const FINE_PER_SUB: i32 = 1 << (FINE_BITS - SUB_BITS);

/// A triangle vertex on the fine grid (exact).
fn fine(p: SubPoint) -> FinePoint {
    FinePoint::from(p)
}

/// Most vertices a [`VisiblePiece`] holds.
///
/// A triangle clipped by `k` lines is a convex polygon of at most `3 + k`
/// vertices; conforming adds the cut vertices of its neighbours.
pub const PIECE_VERTICES: usize = 16;

/// Depth lines are shifted right until `|a|, |b|` are below this (see the
/// module doc: the line then moves by under `2^16 / 2^23` sub-pixels).
const DEPTH_LINE_BITS: u32 = 24;

/// A clip line `a x + b y + c = 0` (x, y in 1/16 px), canonical: reduced by
/// the gcd of its coefficients, first non-zero of `a, b` positive.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
struct ClipLine {
    a: i64,
    b: i64,
    c: i64,
}

impl ClipLine {
    /// The line's value at the fine point `p`, scaled to fine units: 64
    /// times its value in sub-pixel units (`< 2^48` in magnitude, see the
    /// module doc), so its sign is the side of `p`.
    fn at(&self, p: FinePoint) -> i128 {
        i128::from(self.a) * i128::from(p.x)
            + i128::from(self.b) * i128::from(p.y)
            + i128::from(self.c) * i128::from(FINE_PER_SUB)
    }

    /// Position along the line (the direction `(-b, a)`), for sorting the
    /// vertices on it.
    fn along(&self, p: FinePoint) -> i128 {
        i128::from(self.a) * i128::from(p.y) - i128::from(self.b) * i128::from(p.x)
    }

    /// The canonical line through `a x + b y + c`, with the factor (`±1`)
    /// that turns the canonical line's values into the given ones' signs.
    /// `None` when `a = b = 0` or a coefficient does not fit.
    fn canonical(a: i128, b: i128, c: i128) -> Option<(Self, i8)> {
        if a == 0 && b == 0 {
            return None;
        }
        let g = gcd(gcd(a.unsigned_abs(), b.unsigned_abs()), c.unsigned_abs());
        let g = i128::try_from(g).ok()?;
        let (mut a, mut b, mut c) = (a.checked_div(g)?, b.checked_div(g)?, c.checked_div(g)?);
        let mut sign = 1;
        if a < 0 || (a == 0 && b < 0) {
            a = -a;
            b = -b;
            c = -c;
            sign = -1;
        }
        Some((
            Self {
                a: i64::try_from(a).ok()?,
                b: i64::try_from(b).ok()?,
                c: i64::try_from(c).ok()?,
            },
            sign,
        ))
    }

    /// The line through `p` and `q`, valued `cross(q - p, v - p)`.
    fn through(p: SubPoint, q: SubPoint) -> Option<(Self, i8)> {
        let (dx, dy) = (
            i128::from(q.x) - i128::from(p.x),
            i128::from(q.y) - i128::from(p.y),
        );
        // cross(q - p, v - p) = -dy x + dx y + (dy px - dx py)
        Self::canonical(-dy, dx, dy * i128::from(p.x) - dx * i128::from(p.y))
    }

    /// The intersection with `other`, rounded to the nearest 1/1024 px
    /// (the fine grid; halves away from zero); `None` for parallel lines.
    /// A function of the two lines alone, symmetric in them.
    fn meet(&self, other: &Self) -> Option<FinePoint> {
        let (a1, b1, c1) = (i128::from(self.a), i128::from(self.b), i128::from(self.c));
        let (a2, b2, c2) = (
            i128::from(other.a),
            i128::from(other.b),
            i128::from(other.c),
        );
        let den = a1 * b2 - a2 * b1;
        if den == 0 {
            return None;
        }
        let scale = i128::from(FINE_PER_SUB);
        let x = div_round(scale * (b1 * c2 - b2 * c1), den);
        let y = div_round(scale * (c1 * a2 - c2 * a1), den);
        Some(FinePoint::new(
            i32::try_from(x.clamp(i128::from(i32::MIN), i128::from(i32::MAX))).ok()?,
            i32::try_from(y.clamp(i128::from(i32::MIN), i128::from(i32::MAX))).ok()?,
        ))
    }
}

/// Largest line-table size (indices are `u16`, below [`DIAGONAL`]).
const LINE_INDEX_LIMIT: usize = DIAGONAL as usize;

/// `n / d` rounded to the nearest integer, halves away from zero; 0 for
/// `d = 0` (never reached: callers divide by non-zero determinants).
/// Operands are far below `2^126` (module doc), so nothing wraps.
fn div_round(n: i128, d: i128) -> i128 {
    let (nu, du) = (n.unsigned_abs(), d.unsigned_abs());
    let q = nu
        .checked_add(du / 2)
        .and_then(|x| x.checked_div(du))
        .and_then(|q| i128::try_from(q).ok())
        .unwrap_or(0);
    if (n < 0) != (d < 0) {
        -q
    } else {
        q
    }
}

/// A fine coordinate rounded to the nearest 1/16 px (halves away from
/// zero).
fn round_to_sub(v: i32) -> i32 {
    let half = FINE_PER_SUB / 2;
    let q = (v.unsigned_abs() + half as u32) / FINE_PER_SUB as u32;
    if v < 0 {
        -(q as i32)
    } else {
        q as i32
    }
}

fn gcd(mut a: u128, mut b: u128) -> u128 {
    while let Some(r) = a.checked_rem(b) {
        (a, b) = (b, r);
    }
    a
}

/// A polygon of at most `V` vertices under construction or stored: the
/// vertices and, per edge, the clip line it lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
struct Poly<const V: usize> {
    vertices: [FinePoint; V],
    /// `lines[k]`: the clip line (index into the set's table, or
    /// [`DIAGONAL`]) that the edge from vertex `k` to vertex `k + 1` lies on.
    lines: [u16; V],
    source: u16,
    len: u8,
}

/// The line tag of a diagonal that splits an outline too long for one
/// piece: both halves have the same two end points, so nothing is inserted
/// into it when conforming.
const DIAGONAL: u16 = u16::MAX;

/// Room for an outline while it is clipped or conformed, before it is
/// stored as pieces of at most [`PIECE_VERTICES`] vertices.
const WORK_VERTICES: usize = 2 * PIECE_VERTICES;

type Outline = Poly<WORK_VERTICES>;

impl<const V: usize> Poly<V> {
    const EMPTY: Self = Self {
        vertices: [FinePoint::new(0, 0); V],
        lines: [0; V],
        source: 0,
        len: 0,
    };

    fn with_source(source: u16) -> Self {
        Self {
            source,
            ..Self::EMPTY
        }
    }

    fn vertices(&self) -> &[FinePoint] {
        self.vertices.get(..usize::from(self.len)).unwrap_or(&[])
    }

    fn push(&mut self, v: FinePoint, line: u16) -> Result<(), HsrError> {
        let k = usize::from(self.len);
        match (self.vertices.get_mut(k), self.lines.get_mut(k)) {
            (Some(pv), Some(pl)) => {
                *pv = v;
                *pl = line;
                self.len += 1;
                Ok(())
            }
            _ => Err(HsrError::Capacity { needed: V + 1 }),
        }
    }

    /// Vertex `k` (cyclic) and the line of the edge leaving it.
    fn at(&self, k: usize) -> (FinePoint, u16) {
        let n = usize::from(self.len).max(1);
        let k = k.checked_rem(n).unwrap_or(0);
        (
            self.vertices.get(k).copied().unwrap_or_default(),
            self.lines.get(k).copied().unwrap_or(0),
        )
    }

    /// The same outline in another capacity.
    fn convert<const W: usize>(&self) -> Result<Poly<W>, HsrError> {
        let mut out = Poly::<W>::with_source(self.source);
        for k in 0..usize::from(self.len) {
            let (v, l) = self.at(k);
            out.push(v, l)?;
        }
        Ok(out)
    }

    /// Drops repeated consecutive vertices; `false` when fewer than three
    /// are left or the area is zero.
    fn tidy(&mut self) -> bool {
        let mut out = Self::with_source(self.source);
        let n = usize::from(self.len);
        for k in 0..n {
            let (v, l) = self.at(k);
            let (next, _) = self.at(k + 1);
            // A zero-length edge: keep the next vertex (and its line) only.
            if v != next && out.push(v, l).is_err() {
                return false;
            }
        }
        *self = out;
        self.len >= 3 && area2_fine(self.vertices()) != 0
    }

    fn bbox(&self) -> [i32; 4] {
        bbox(self.vertices())
    }
}

impl Outline {
    /// Stores the outline as pieces of at most [`PIECE_VERTICES`]
    /// vertices, cutting off the first `PIECE_VERTICES` vertices along a
    /// [`DIAGONAL`] until the rest fits. The parts keep the outline's
    /// orientation (checked; an outline so bent that a part would not is
    /// reported as [`HsrError::Capacity`]).
    fn chop(&self) -> Result<Vec<VisiblePiece, 3>, HsrError> {
        let too_long = HsrError::Capacity {
            needed: PIECE_VERTICES + 1,
        };
        let sign = area2_fine(self.vertices()).signum();
        let mut out: Vec<VisiblePiece, 3> = Vec::new();
        let mut rest = *self;
        while usize::from(rest.len) > PIECE_VERTICES {
            let n = usize::from(rest.len);
            // The first rotation whose two parts keep the orientation.
            let mut found = None;
            for r in 0..n {
                let (head, tail) = rest.cut_off(r)?;
                let same = |p: &[FinePoint]| area2_fine(p).signum() == sign;
                if same(head.vertices()) && same(tail.vertices()) {
                    found = Some((head, tail));
                    break;
                }
            }
            let (head, tail) = found.ok_or(too_long)?;
            out.push(VisiblePiece(head)).map_err(|_| too_long)?;
            rest = tail;
        }
        out.push(VisiblePiece(rest.convert()?))
            .map_err(|_| too_long)?;
        Ok(out)
    }

    /// The [`PIECE_VERTICES`] vertices from `r` on as one piece closed by a
    /// [`DIAGONAL`], and the rest of the outline.
    fn cut_off(&self, r: usize) -> Result<(Poly<PIECE_VERTICES>, Outline), HsrError> {
        let n = usize::from(self.len);
        let m = PIECE_VERTICES - 1;
        let mut head = Poly::<PIECE_VERTICES>::with_source(self.source);
        let mut tail = Outline::with_source(self.source);
        for k in 0..m {
            let (v, l) = self.at(r + k);
            head.push(v, l)?;
        }
        let (vm, _) = self.at(r + m);
        head.push(vm, DIAGONAL)?;
        let (v0, _) = self.at(r);
        tail.push(v0, DIAGONAL)?;
        for k in m..n {
            let (v, l) = self.at(r + k);
            tail.push(v, l)?;
        }
        Ok((head, tail))
    }
}

/// One disjoint visible polygon: a convex part of its source triangle
/// (plus the cut vertices of its neighbours on its edges), vertices on the
/// fine grid (1/1024 px: the triangles' own vertices exactly, cut vertices
/// rounded).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct VisiblePiece(Poly<PIECE_VERTICES>);

impl VisiblePiece {
    /// Index of the source triangle in the slice given to
    /// [`VisibleSet::compute`].
    pub fn source(&self) -> usize {
        usize::from(self.0.source)
    }

    /// The outline (at least 3 vertices, non-zero area), in 1/1024 px.
    pub fn vertices(&self) -> &[FinePoint] {
        self.0.vertices()
    }
}

fn bbox<P: Copy + Into<FinePoint>>(v: &[P]) -> [i32; 4] {
    let mut b = [i32::MAX, i32::MAX, i32::MIN, i32::MIN];
    for &p in v {
        let p: FinePoint = p.into();
        b = [b[0].min(p.x), b[1].min(p.y), b[2].max(p.x), b[3].max(p.y)];
    }
    b
}

/// A point with rational coordinates `(x / d, y / d)`, `d > 0` (a corner
/// of a hiding region `R_Q`).
#[derive(Clone, Copy)]
struct RatPoint {
    x: i128,
    y: i128,
    d: i128,
}

/// The corners of `R_Q`: the triangle `q`, cut by the depth line `depth`
/// when the pair interpenetrates (exact, in rationals: numerators below
/// `2^60`, denominators below `2^43`).
fn hider_corners(q: &[SubPoint; 3], depth: Option<&Cut>) -> Vec<RatPoint, 4> {
    let mut out: Vec<RatPoint, 4> = Vec::new();
    let int = |p: SubPoint| RatPoint {
        x: i128::from(p.x),
        y: i128::from(p.y),
        d: 1,
    };
    let Some(cut) = depth else {
        for p in q {
            let _ = out.push(int(*p));
        }
        return out;
    };
    for k in 0..3 {
        let (v, w) = (q[k], q[(k + 1) % 3]);
        let (fv, fw) = (cut.value(fine(v)), cut.value(fine(w)));
        if fv >= 0 {
            let _ = out.push(int(v));
        }
        if (fv > 0 && fw < 0) || (fv < 0 && fw > 0) {
            // v + (w - v) fv / (fv - fw)
            let d = fv - fw;
            let (x, y) = (
                i128::from(v.x) * d + (i128::from(w.x) - i128::from(v.x)) * fv,
                i128::from(v.y) * d + (i128::from(w.y) - i128::from(v.y)) * fv,
            );
            let (x, y, d) = if d < 0 { (-x, -y, -d) } else { (x, y, d) };
            let _ = out.push(RatPoint { x, y, d });
        }
    }
    out
}

/// Do the piece `x` and the convex region with corners `corners` and
/// lines `cuts` have disjoint interiors? Exact separating-axis test: a line
/// of the region with all of `x` outside or on it, or an edge of `x` with
/// all the corners outside or on it.
fn separated<const V: usize>(x: &Poly<V>, corners: &[RatPoint], cuts: &[Cut]) -> bool {
    if corners.len() < 3 {
        return true;
    }
    if cuts
        .iter()
        .any(|c| x.vertices().iter().all(|&v| c.value(v) <= 0))
    {
        return true;
    }
    let s = area2_fine(x.vertices()).signum();
    let v = x.vertices();
    // Corners are in sub-pixel units over `d`; the piece in fine units.
    let k = i128::from(FINE_PER_SUB);
    (0..v.len()).any(|j| {
        let (p, q) = (x.at(j).0, x.at(j + 1).0);
        let (ex, ey) = (
            i128::from(q.x) - i128::from(p.x),
            i128::from(q.y) - i128::from(p.y),
        );
        corners.iter().all(|r| {
            let c = ex * (k * r.y - i128::from(p.y) * r.d) - ey * (k * r.x - i128::from(p.x) * r.d);
            s * c <= 0
        })
    })
}

fn boxes_meet(a: [i32; 4], b: [i32; 4]) -> bool {
    a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3]
}

/// What [`VisibleSet::compute`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct WeilerStats {
    /// Visible pieces.
    pub pieces: usize,
    /// Distinct clip lines.
    pub lines: usize,
    /// Ordered pairs of triangles where one hides part of the other.
    pub occlusions: usize,
    /// Pairs (counted once) found interpenetrating, so cut along their
    /// depth line.
    pub interpenetrating: usize,
    /// Vertices inserted by conforming (step 3).
    pub conformed: usize,
    /// Most vertices in one piece (at most [`PIECE_VERTICES`]).
    pub max_vertices: usize,
}

/// The frame's visible pieces (bounded storage for `N` pieces and `N` clip
/// lines; see the module doc).
///
/// ```
/// use softedge::hsr::{DepthTriangle, VisibleSet};
/// use softedge::{Band, BandBuffer, RenderStyle, SubPoint};
/// let p = |x, y| SubPoint::from_px(x, y);
/// let tris = [
///     // Far, across the frame.
///     DepthTriangle::new([p(0, 0), p(16, 0), p(0, 16)], [[1000]; 3], [100; 3]),
///     // Near, over its corner.
///     DepthTriangle::new([p(0, 0), p(4, 0), p(0, 4)], [[3000]; 3], [900; 3]),
/// ];
/// let mut set = VisibleSet::<16>::new();
/// let stats = set.compute(&tris).unwrap();
/// assert_eq!(stats.occlusions, 1);
/// let band = Band::new(8, 0, 8);
/// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// buf.clear([0]);
/// set.draw(&tris, &mut buf, &RenderStyle::default()).unwrap();
/// assert_eq!(buf.lin12(1, 1), Some([3000]));
/// assert_eq!(buf.lin12(5, 1), Some([1000]));
/// ```
#[derive(Debug, Clone)]
pub struct VisibleSet<const N: usize> {
    pieces: Vec<VisiblePiece, N>,
    lines: Vec<ClipLine, N>,
    /// The triangle being clipped when the last `compute` failed.
    failed_at: Option<usize>,
}

impl<const N: usize> Default for VisibleSet<N> {
    fn default() -> Self {
        Self::new()
    }
}

/// A line of `R_Q`: the table index, the line, and the sign that makes its
/// value positive inside `R_Q`.
#[derive(Clone, Copy)]
struct Cut {
    index: Option<u16>,
    line: ClipLine,
    side: i8,
}

impl Cut {
    fn value(&self, p: FinePoint) -> i128 {
        i128::from(self.side) * self.line.at(p)
    }
}

/// The exact depth plane of a triangle: `z = N(x, y) / d` with
/// `N = a x + b y + c`, `d > 0`.
#[derive(Clone, Copy)]
struct ExactPlane {
    a: i128,
    b: i128,
    c: i128,
    d: i128,
}

impl ExactPlane {
    fn new(v: [SubPoint; 3], z: [u16; 3]) -> Option<Self> {
        let (x0, y0, z0) = (i128::from(v[0].x), i128::from(v[0].y), i128::from(z[0]));
        let [dx1, dx2] = [v[1], v[2]].map(|p| i128::from(p.x) - x0);
        let [dy1, dy2] = [v[1], v[2]].map(|p| i128::from(p.y) - y0);
        let [dz1, dz2] = [z[1], z[2]].map(|d| i128::from(d) - z0);
        let d = dx1 * dy2 - dx2 * dy1;
        if d == 0 {
            return None;
        }
        let s = d.signum();
        let (a, b, d) = (
            s * (dz1 * dy2 - dz2 * dy1),
            s * (dx1 * dz2 - dx2 * dz1),
            s * d,
        );
        Some(Self {
            a,
            b,
            c: z0 * d - a * x0 - b * y0,
            d,
        })
    }
}

/// How `Q` hides `P`.
enum Relation {
    /// Nowhere.
    Behind,
    /// Wherever they overlap.
    Front,
    /// Where the depth line's value (times the side) is positive.
    Cut(ClipLine, i8),
}

fn relation(tp: &Tri, tq: &Tri, p: usize, q: usize) -> Relation {
    // g = (z_hi - z_lo) * d_lo * d_hi with (lo, hi) the ordered pair, so
    // both triangles of the pair use the same line.
    let (lo, hi, q_is_hi) = if p < q {
        (tp, tq, true)
    } else {
        (tq, tp, false)
    };
    let (pl, ph) = (&lo.plane, &hi.plane);
    let a = ph.a * pl.d - pl.a * ph.d;
    let b = ph.b * pl.d - pl.b * ph.d;
    let c = ph.c * pl.d - pl.c * ph.d;
    let toward_q: i128 = if q_is_hi { 1 } else { -1 };
    let (mut pos, mut neg) = (false, false);
    for v in tp.v.iter().chain(tq.v.iter()) {
        let g = toward_q * (a * i128::from(v.x) + b * i128::from(v.y) + c);
        pos |= g > 0;
        neg |= g < 0;
    }
    match (pos, neg) {
        // Coplanar: the earlier triangle is in front.
        (false, false) if q < p => Relation::Front,
        (false, false) => Relation::Behind,
        (true, false) => Relation::Front,
        (false, true) => Relation::Behind,
        (true, true) => match depth_line(a, b, c) {
            Some((line, sign)) => Relation::Cut(line, sign * toward_q as i8),
            // Unreachable in range (see the module doc); keep a valid frame.
            None => Relation::Behind,
        },
    }
}

/// The canonical, shortened depth line of `a x + b y + c` (module doc).
fn depth_line(a: i128, b: i128, c: i128) -> Option<(ClipLine, i8)> {
    let g = i128::try_from(gcd(
        gcd(a.unsigned_abs(), b.unsigned_abs()),
        c.unsigned_abs(),
    ))
    .ok()?;
    if g == 0 {
        return None;
    }
    let (mut a, mut b, mut c) = (a.checked_div(g)?, b.checked_div(g)?, c.checked_div(g)?);
    let mut sign = 1i8;
    if a < 0 || (a == 0 && b < 0) {
        (a, b, c) = (-a, -b, -c);
        sign = -1;
    }
    let m = a.unsigned_abs().max(b.unsigned_abs());
    let bits = 128 - m.leading_zeros();
    if bits > DEPTH_LINE_BITS {
        let s = bits - DEPTH_LINE_BITS;
        let half = 1i128 << (s - 1);
        a >>= s;
        b >>= s;
        c = (c + half) >> s;
    }
    let (line, s2) = ClipLine::canonical(a, b, c)?;
    Some((line, sign * s2))
}

/// A triangle of the frame, set up once.
#[derive(Clone, Copy)]
struct Tri {
    v: [SubPoint; 3],
    plane: ExactPlane,
    bbox: [i32; 4],
}

fn setup<const C: usize>(t: &DepthTriangle<C>) -> Result<Option<Tri>, HsrError> {
    for v in t.vertices {
        v.check().map_err(DrawError::from)?;
    }
    if crate::geom::area2(&t.vertices) == 0 {
        return Ok(None);
    }
    Ok(ExactPlane::new(t.vertices, t.depth).map(|plane| Tri {
        v: t.vertices,
        plane,
        bbox: bbox(&t.vertices),
    }))
}

impl<const N: usize> VisibleSet<N> {
    /// An empty set.
    pub const fn new() -> Self {
        Self {
            pieces: Vec::new(),
            lines: Vec::new(),
            failed_at: None,
        }
    }

    /// After a failed [`compute`](Self::compute): the index of the
    /// triangle whose clipping (or, for the conforming step, whose pieces)
    /// ran out of storage or was rejected, so a caller can say which of its
    /// objects the frame failed at; `None` after a success, or when the
    /// input was refused before any triangle (more than `u16::MAX`).
    pub fn failed_at(&self) -> Option<usize> {
        self.failed_at
    }

    /// The visible pieces of the last [`compute`](Self::compute).
    pub fn pieces(&self) -> &[VisiblePiece] {
        &self.pieces
    }

    /// Splits the frame's triangles into disjoint visible pieces (once per
    /// frame; the module doc has the algorithm).
    ///
    /// Errors: a vertex outside the coordinate range,
    /// [`HsrError::Draw`]; more pieces or clip lines than `N`, more than
    /// `u16::MAX` triangles, or an outline that cannot be stored (module
    /// doc, Storage): [`HsrError::Capacity`]. After an error the set is
    /// empty.
    /// Triangles of zero area are skipped (they draw nothing, as in
    /// [`Triangle::draw`](crate::Triangle::draw)).
    pub fn compute<const C: usize>(
        &mut self,
        tris: &[DepthTriangle<C>],
    ) -> Result<WeilerStats, HsrError> {
        self.failed_at = None;
        let r = self.compute_inner(tris);
        if r.is_err() {
            self.pieces.clear();
            self.lines.clear();
        } else {
            self.failed_at = None;
        }
        r
    }

    fn compute_inner<const C: usize>(
        &mut self,
        tris: &[DepthTriangle<C>],
    ) -> Result<WeilerStats, HsrError> {
        self.pieces.clear();
        self.lines.clear();
        if tris.len() > usize::from(u16::MAX) {
            return Err(HsrError::Capacity { needed: tris.len() });
        }
        for (p, t) in tris.iter().enumerate() {
            self.failed_at = Some(p);
            setup(t)?;
        }
        let mut stats = WeilerStats::default();
        for (p, tp) in tris.iter().enumerate() {
            self.failed_at = Some(p);
            let Some(tp) = setup(tp)? else { continue };
            let start = self.pieces.len();
            let mut first = Poly::<PIECE_VERTICES>::with_source(p as u16);
            for k in 0..3 {
                let (a, b) = (tp.v[k], tp.v[(k + 1) % 3]);
                // Distinct vertices (non-zero area): the line exists.
                let Some((line, _)) = ClipLine::through(a, b) else {
                    continue;
                };
                let index = self.intern(line)?;
                first.push(fine(a), index)?;
            }
            self.push_piece(VisiblePiece(first))?;
            for (q, tq) in tris.iter().enumerate() {
                if q == p || self.pieces.len() == start || !boxes_meet(tp.bbox, bbox(&tq.vertices))
                {
                    continue;
                }
                let Some(tq) = setup(tq)? else { continue };
                // Lines are interned only when they cut a piece
                // (`subtract`); until then `index` is `None`.
                let mut cuts: Vec<Cut, 4> = Vec::new();
                let mut depth_cut = None;
                match relation(&tp, &tq, p, q) {
                    Relation::Behind => continue,
                    Relation::Front => {}
                    Relation::Cut(line, side) => {
                        stats.interpenetrating += usize::from(p < q);
                        let cut = Cut {
                            index: None,
                            line,
                            side,
                        };
                        depth_cut = Some(cut);
                        let _ = cuts.push(cut);
                    }
                }
                let inside = crate::geom::area2(&tq.v).signum() as i8;
                for k in 0..3 {
                    let (a, b) = (tq.v[k], tq.v[(k + 1) % 3]);
                    let Some((line, sign)) = ClipLine::through(a, b) else {
                        continue;
                    };
                    let _ = cuts.push(Cut {
                        index: None,
                        line,
                        side: sign * inside,
                    });
                }
                let corners = hider_corners(&tq.v, depth_cut.as_ref());
                // Boxes are in fine units.
                if self.subtract(start, tq.bbox, &corners, &mut cuts)? {
                    stats.occlusions += 1;
                }
            }
        }
        stats.conformed = self.conform()?;
        stats.max_vertices = self
            .pieces
            .iter()
            .map(|p| usize::from(p.0.len))
            .max()
            .unwrap_or(0);
        stats.pieces = self.pieces.len();
        stats.lines = self.lines.len();
        Ok(stats)
    }

    fn push_piece(&mut self, piece: VisiblePiece) -> Result<(), HsrError> {
        self.pieces
            .push(piece)
            .map_err(|_| HsrError::Capacity { needed: N + 1 })
    }

    /// The table index of `line`, added when new.
    fn intern(&mut self, line: ClipLine) -> Result<u16, HsrError> {
        let k = match self.lines.iter().position(|l| *l == line) {
            Some(k) => k,
            None => {
                self.lines
                    .push(line)
                    .map_err(|_| HsrError::Capacity { needed: N + 1 })?;
                self.lines.len() - 1
            }
        };
        if k >= LINE_INDEX_LIMIT {
            return Err(HsrError::Capacity { needed: k + 1 });
        }
        u16::try_from(k).map_err(|_| HsrError::Capacity { needed: k + 1 })
    }

    /// The clip line with table index `index`; `None` for a [`DIAGONAL`].
    fn line(&self, index: u16) -> Option<ClipLine> {
        self.lines.get(usize::from(index)).copied()
    }

    /// Removes the convex region `R` inside all `cuts` (corners `corners`)
    /// from the pieces `start..` (those of one source triangle). Returns
    /// whether any piece lost area.
    fn subtract(
        &mut self,
        start: usize,
        r_box: [i32; 4],
        corners: &Vec<RatPoint, 4>,
        cuts: &mut [Cut],
    ) -> Result<bool, HsrError> {
        let end = self.pieces.len();
        let mut touched = false;
        let mut k = start;
        // Pieces that end up hidden are marked `len = 0` and dropped below.
        while k < end {
            let Some(x) = self.pieces.get(k).copied() else {
                break;
            };
            k += 1;
            if !boxes_meet(x.0.bbox(), r_box) || separated(&x.0, corners, cuts) {
                continue;
            }
            touched = true;
            for cut in cuts.iter_mut() {
                if cut.index.is_none() {
                    cut.index = Some(self.intern(cut.line)?);
                }
            }
            let mut outs: Vec<Outline, 4> = Vec::new();
            let mut rest: Outline = x.0.convert()?;
            for cut in cuts.iter() {
                let (inner, outer) = self.split(&rest, cut)?;
                if let Some(o) = outer {
                    let _ = outs.push(o);
                }
                match inner {
                    Some(i) => rest = i,
                    None => break,
                }
            }
            let mut replaced = false;
            for o in &outs {
                for piece in o.chop()? {
                    match (replaced, self.pieces.get_mut(k - 1)) {
                        (false, Some(slot)) => {
                            *slot = piece;
                            replaced = true;
                        }
                        _ => self.push_piece(piece)?,
                    }
                }
            }
            if !replaced {
                if let Some(slot) = self.pieces.get_mut(k - 1) {
                    slot.0.len = 0;
                }
            }
        }
        // Compact the hidden ones away.
        let mut w = start;
        for r in start..self.pieces.len() {
            let Some(p) = self.pieces.get(r).copied() else {
                break;
            };
            if p.0.len > 0 {
                if let Some(slot) = self.pieces.get_mut(w) {
                    *slot = p;
                }
                w += 1;
            }
        }
        self.pieces.truncate(w);
        Ok(touched)
    }

    /// Sutherland–Hodgman: the parts of `x` inside (value > 0) and outside
    /// the cut, sharing the cut's vertices; `None` for an empty part.
    fn split(
        &self,
        x: &Outline,
        cut: &Cut,
    ) -> Result<(Option<Outline>, Option<Outline>), HsrError> {
        let Some(cut_index) = cut.index else {
            return Ok((Some(*x), None));
        };
        let mut inner = Outline::with_source(x.source);
        let mut outer = inner;
        for k in 0..usize::from(x.len) {
            let (v, e) = x.at(k);
            let (w, _) = x.at(k + 1);
            let (fv, fw) = (cut.value(v), cut.value(w));
            let crossing = (fv > 0 && fw < 0) || (fv < 0 && fw > 0);
            let cross_point = if crossing {
                Some(self.crossing(v, w, e, cut, fv, fw))
            } else {
                None
            };
            for (poly, s) in [(&mut inner, 1i128), (&mut outer, -1i128)] {
                let (sv, sw) = (s * fv, s * fw);
                if sv > 0 || (sv == 0 && sw >= 0) {
                    poly.push(v, e)?;
                    if let (true, Some(c)) = (sw < 0, cross_point) {
                        poly.push(c, cut_index)?;
                    }
                } else if sv == 0 {
                    // On the line, leaving the part: along the cut.
                    poly.push(v, cut_index)?;
                } else if let (true, Some(c)) = (sw > 0, cross_point) {
                    poly.push(c, e)?;
                }
            }
        }
        let keep = |mut p: Outline| if p.tidy() { Some(p) } else { None };
        Ok((keep(inner), keep(outer)))
    }

    /// Where the edge `v -> w` (on line `e`) crosses the cut: the two lines'
    /// intersection, rounded, kept inside the edge's box (rounding can put
    /// a nearly parallel pair's intersection far off).
    fn crossing(
        &self,
        v: FinePoint,
        w: FinePoint,
        e: u16,
        cut: &Cut,
        fv: i128,
        fw: i128,
    ) -> FinePoint {
        let b = bbox(&[v, w]);
        let clamp = |p: FinePoint| FinePoint::new(p.x.clamp(b[0], b[2]), p.y.clamp(b[1], b[3]));
        if let Some(p) = self.line(e).and_then(|l| l.meet(&cut.line)) {
            return clamp(p);
        }
        // A diagonal, or parallel lines that the rounded vertices straddle:
        // interpolate, from the lexicographically smaller end so both sides
        // agree.
        let ((p0, f0), (p1, f1)) = if (v.x, v.y) <= (w.x, w.y) {
            ((v, fv), (w, fw))
        } else {
            ((w, fw), (v, fv))
        };
        let den = f0 - f1;
        let t = |a: i32, b: i32| {
            let d = i128::from(b) - i128::from(a);
            i128::from(a) + div_round(d * f0, den)
        };
        let x = i32::try_from(t(p0.x, p1.x)).unwrap_or(p0.x);
        let y = i32::try_from(t(p0.y, p1.y)).unwrap_or(p0.y);
        clamp(FinePoint::new(x, y))
    }

    /// Step 3: inserts into every piece edge the vertices of all pieces
    /// that lie on its line strictly between its ends (not into
    /// [`DIAGONAL`]s, whose two sides share their ends). Returns how many
    /// were inserted.
    fn conform(&mut self) -> Result<usize, HsrError> {
        let mut inserted = 0;
        let count = self.pieces.len();
        for i in 0..count {
            let Some(x) = self.pieces.get(i).copied() else {
                break;
            };
            let x = x.0;
            self.failed_at = Some(usize::from(x.source));
            let mut out = Outline::with_source(x.source);
            for k in 0..usize::from(x.len) {
                let (p, e) = x.at(k);
                let (q, _) = x.at(k + 1);
                out.push(p, e)?;
                let Some(line) = self.line(e) else {
                    continue;
                };
                let key = |v: FinePoint| (line.along(v), v.x, v.y);
                let (kp, kq) = (key(p), key(q));
                let forward = kp < kq;
                let (lo, hi) = if forward { (kp, kq) } else { (kq, kp) };
                let b = bbox(&[p, q]);
                // Candidates in order along the edge, found by repeatedly
                // taking the nearest one after the last inserted.
                let mut last = if forward { lo } else { hi };
                loop {
                    let mut best: Option<((i128, i32, i32), FinePoint)> = None;
                    for y in self.pieces.iter() {
                        let y = &y.0;
                        for j in 0..usize::from(y.len) {
                            let (w, lw) = y.at(j);
                            if w.x < b[0] - 1 || w.x > b[2] + 1 || w.y < b[1] - 1 || w.y > b[3] + 1
                            {
                                continue;
                            }
                            let kw = key(w);
                            let inside = if forward {
                                kw > last && kw < hi
                            } else {
                                kw < last && kw > lo
                            };
                            if !inside {
                                continue;
                            }
                            let (_, lprev) = y.at(j + usize::from(y.len) - 1);
                            if lw != e && lprev != e && line.at(w) != 0 {
                                continue;
                            }
                            let better = match best {
                                None => true,
                                Some((kb, _)) => {
                                    if forward {
                                        kw < kb
                                    } else {
                                        kw > kb
                                    }
                                }
                            };
                            if better {
                                best = Some((kw, w));
                            }
                        }
                    }
                    let Some((kb, w)) = best else { break };
                    out.push(w, e)?;
                    inserted += 1;
                    last = kb;
                }
            }
            let mut first = true;
            for piece in out.chop()? {
                match (first, self.pieces.get_mut(i)) {
                    (true, Some(slot)) => *slot = piece,
                    _ => self.push_piece(piece)?,
                }
                first = false;
            }
        }
        Ok(inserted)
    }

    /// Accumulates every piece into the band with its source triangle's
    /// Gouraud plane (`tris` must be the slice given to
    /// [`compute`](Self::compute)). Call once per band; the frame does not
    /// depend on the band height.
    ///
    /// Error: a piece whose source triangle is not in `tris` (a shorter
    /// slice than the one given to `compute`): [`HsrError::Capacity`] with
    /// `needed` the length `tris` must have; nothing is skipped silently.
    pub fn draw<const C: usize>(
        &self,
        tris: &[DepthTriangle<C>],
        band: &mut BandBuffer<'_, C>,
        style: &RenderStyle,
    ) -> Result<(), HsrError> {
        let info = band.band();
        let (y0, y1) = (info.y0, info.y0 + i32::from(info.rows));
        // Exact box coverage takes the fine vertices as they are.
        let exact = style.antialias && style.model == PixelModel::Box;
        for piece in &self.pieces {
            let b = piece.0.bbox();
            // Two pixels of margin: the circular pixel models reach 1.5 px
            // beyond a pixel (the edge engine clips to the band itself;
            // this only skips pieces that cannot touch it).
            if (b[3] >> FINE_BITS) + 2 < y0 || (b[1] >> FINE_BITS) - 2 > y1 {
                continue;
            }
            let t = tris.get(piece.source()).ok_or(HsrError::Capacity {
                needed: piece.source() + 1,
            })?;
            let Some(plane) = Plane::triangle(t.vertices, t.colors, [0; C]) else {
                continue;
            };
            let add = crate::band::ComposeOp::Add(crate::style::Opacity::OPAQUE);
            if exact {
                fill_fine(band, piece.vertices(), &plane);
            } else {
                // Other pixel models take 1/16-px vertices: the cut
                // vertices rounded there (module doc, Remaining error).
                let mut sub = [SubPoint::new(0, 0); PIECE_VERTICES];
                for (s, v) in sub.iter_mut().zip(piece.vertices()) {
                    *s = SubPoint::new(round_to_sub(v.x), round_to_sub(v.y));
                }
                fill(
                    band,
                    sub.get(..piece.vertices().len()).unwrap_or(&[]),
                    &crate::band::Paint::Plane(&plane),
                    add,
                    style,
                );
            }
        }
        Ok(())
    }
}
