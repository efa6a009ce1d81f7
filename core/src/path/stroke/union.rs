//! Where a polyline's or a polygon's stroke overlaps itself: the union
//! of its pieces, not their sum.
//!
//! Takes a polyline or a closed polygon (random access to its points:
//! a polygon's body from its last point back to the first and its join
//! at the first are the outline's closing ones) and the style its
//! outline ([`outline`](super::outline)) was built with; gives the
//! [`SegmentSink`], after that outline, closed contours that turn the
//! outline's winding number (the number of pieces covering a point) into
//! the union's indicator (one wherever a piece covers the point).
//!
//! ## Why
//!
//! The edge engine applies the nonzero rule to each pixel's *mean*
//! winding number (the clamped sum of signed areas, as FreeType's smooth
//! rasterizer does). Where pieces overlap without tiling (a polyline
//! crossing itself, a segment shorter than its inner corner needs, a
//! U-turn, a cap on another segment), a pixel that holds both area
//! covered twice and uncovered area is covered too much: measured up to
//! half a pixel, and up to 4.8 % of a thin stroke's area.
//!
//! ## Method: inclusion and exclusion
//!
//! Coverage is linear in the signed area, so contours can be added and
//! subtracted. With `P_1 ... P_n` the pieces (convex, clockwise; see
//! [`outline`](super::outline)),
//!
//! ```text
//! 1[P_1 u ... u P_n] = sum 1[P_i] - sum_{i<j} 1[P_i n P_j]
//!                      + sum_{i<j<k} 1[P_i n P_j n P_k] - ...
//! ```
//!
//! The outline is the first sum. This module adds every further term up
//! to order [`MAX_ORDER`] (5): the intersection of two pieces
//! counter-clockwise (winding -1), of three clockwise, and so on, for
//! every set of pieces that pairwise overlap. The winding number is then
//! exactly one wherever at most five pieces overlap. Truncated after a
//! positive term, inclusion and exclusion is never below one inside the
//! union (Bonferroni), so nothing is uncovered; where six or more pieces
//! overlap it may be more than one, and such a pixel keeps the mean
//! winding's error of before.
//!
//! The intersection of convex polygons is convex. One piece of a term,
//! the *subject* (a round one if there is one), streams its vertices
//! through one Sutherland-Hodgman stage per edge of the others, the
//! *clippers* (stored polygons); the result is emitted as it comes out,
//! its edges reversed for terms of even order. A round clipper (a join's
//! or cap's arc) is cut into parts, fans from its first vertex that tile
//! it, so that each part fits the stages (the term is then the sum over
//! the parts). Vertices are the pieces' own (the same computations as the
//! outline's, the same arcs) or crossings of their edges rounded to the
//! fine grid, so the corrections cancel the outline's overlaps to the
//! grid's rounding: measured against an exact union, every pixel within
//! 1/256 (`tests/tests/shapes_render.rs`).
//!
//! Pairs that cannot overlap with area are left out: a body and the join
//! or cap at either end of it, two consecutive bodies that the outline
//! cut at their inner corner (they tile), and pieces that a separating
//! edge (or the boxes) shows to be apart.
//!
//! ## Bounded, and the same in every band
//!
//! Only solid polylines and centred polygons of at most
//! [`MAX_UNION_POINTS`] points, within the coordinate range by the
//! stroke's reach, are treated (a longer one
//! pays one comparison: a chart's strokes are unchanged). The terms are
//! found from the pieces alone (the same in every band), and their work
//! (subject vertices times clipper edges, over the parts) is summed
//! first: past [`MAX_UNION_WORK`] the overlaps of two round pieces are
//! left out (still never below the union: the terms left are all those
//! with at most one round piece, whose truncated sums are alternating
//! sums of binomials, never negative), and if that is still too much,
//! the whole treatment (the stroke keeps its outline). Every term takes a
//! fixed count of segment numbers (its subject's vertex bound plus its
//! clippers' edges): what it sends, the rest reported skipped, so that a
//! band's walk cache finds every segment at its number; a term whose
//! boxes miss the sink's window is not computed, only skipped.
//!
//! Memory, on the stack: the points, a cut and a box per piece, 24
//! stages and what waits to enter them (no recursion in the clipping); on
//! a Cortex-M3 (qemu-m3) a 7-point round-joined polyline's stroke went
//! 1.7 KB deeper with the treatment than without (the stroker's own path
//! was 4.5 KB deeper than the reference scenes').

use crate::geom::FINE_LIMIT;
use crate::path::arc::{arc_count, arc_inner_vertices, EllipseFrame};
use crate::path::segment::{emit, SegmentSink};
use crate::path::trig::{atan2, div_round, HALF_TURN};
use crate::path::vector::{Pt, UNIT_X};
use crate::path::Tolerance;

use super::outline::{
    cut_inner, inner_corner, is_right_turn, miter_tip, neg, square_cap_corners, Piece, Sides,
};
use super::{LineCap, LineJoin, MiterLimit, StrokeAlignment, StrokeStyle};

/// The most points (repeated ones counted) of a polyline or polygon
/// whose stroke gets the union treatment.
pub const MAX_UNION_POINTS: usize = 16;

/// The most work, in stage steps (a subject vertex through one clipping
/// stage), of a polyline's union treatment; beyond it the stroke keeps
/// its plain outline.
pub const MAX_UNION_WORK: u32 = 1 << 16;

/// Pieces of a polygon of `MAX_UNION_POINTS` points: a join per point, a
/// body per side (a polyline's: a cap or join per point, a body per
/// segment, one fewer).
const MAX_PIECES: usize = 2 * MAX_UNION_POINTS;

/// The most vertices of a clipper: a body cut at both ends (a pentagon
/// plus one) — bevel, miter and square-cap pieces have three or four.
const MAX_CLIP: usize = 6;

/// Fine units around a round piece's radius in its box: the
/// area-preserving arcs put their inner vertices out by the factor `g`
/// (under 1.25 for arcs of at least two steps), plus the grid rounding.
fn round_margin(r: i64) -> i64 {
    r / 4 + 16
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Form {
    /// No area (a butt cap, no turn, a zero-length wedge).
    Empty,
    /// A polygon of at most [`MAX_CLIP`] vertices: can clip.
    Clip,
    /// A join's or cap's arc: only a subject.
    Round,
}

/// A convex polygon of at most [`MAX_STAGES`] vertices, clockwise: a
/// clipper, or a part of a round one (within the range: `i32`).
#[derive(Debug, Clone, Copy)]
struct Poly {
    v: [[i32; 2]; MAX_STAGES],
    n: usize,
}

impl Poly {
    fn new() -> Self {
        Self {
            v: [[0; 2]; MAX_STAGES],
            n: 0,
        }
    }

    fn push(&mut self, p: Pt) {
        if let Some(slot) = self.v.get_mut(self.n) {
            *slot = pack(p);
            self.n += 1;
        }
    }

    /// Vertex `k`, cyclically.
    fn at(&self, k: usize) -> Pt {
        let i = if self.n == 0 { 0 } else { k % self.n };
        unpack(self.v.get(i).copied().unwrap_or_default())
    }
}

/// A box `[x0, x1] x [y0, y1]`, fine units (within the range: `i32`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Box4 {
    x0: i32,
    y0: i32,
    x1: i32,
    y1: i32,
}

impl Box4 {
    const EMPTY: Box4 = Box4 {
        x0: i32::MAX,
        y0: i32::MAX,
        x1: i32::MIN,
        y1: i32::MIN,
    };

    fn around(c: Pt, r: i64) -> Box4 {
        let mut b = Box4::EMPTY;
        b.add(Pt::new(c.x - r, c.y - r));
        b.add(Pt::new(c.x + r, c.y + r));
        b
    }

    fn add(&mut self, p: Pt) {
        let [x, y] = pack(p);
        self.x0 = self.x0.min(x);
        self.y0 = self.y0.min(y);
        self.x1 = self.x1.max(x);
        self.y1 = self.y1.max(y);
    }

    fn meet(self, o: Box4) -> Box4 {
        Box4 {
            x0: self.x0.max(o.x0),
            y0: self.y0.max(o.y0),
            x1: self.x1.min(o.x1),
            y1: self.y1.min(o.y1),
        }
    }

    /// True when the box has area (two boxes that only touch share none).
    fn has_area(self) -> bool {
        self.x0 < self.x1 && self.y0 < self.y1
    }
}

/// The outer wedge of a join (see `Outline::wedge`).
#[derive(Debug, Clone, Copy)]
struct Wedge {
    v: Pt,
    from: Pt,
    to: Pt,
    ua: crate::path::vector::Unit,
    ub: crate::path::vector::Unit,
    h_q1: i64,
}

/// A polyline's pieces, regenerated on demand as the outline built them.
struct Pieces<'a> {
    pts: &'a [Pt],
    /// A closed polygon: a body from the last point back to the first,
    /// and a join at every point (no caps).
    closed: bool,
    sides: Sides,
    join: LineJoin,
    miter_limit: MiterLimit,
    cap: LineCap,
    tol: Tolerance,
    /// The inner corner at each point where the outline cut the two
    /// bodies meeting there (they tile).
    cuts: [Option<[i32; 2]>; MAX_UNION_POINTS],
    /// Vertices of a round piece, at most (a half turn of arc, its two
    /// ends and the centre).
    round_count: u32,
}

impl Pieces<'_> {
    /// Bodies: `pts.len() - 1`, or closed `pts.len()`.
    fn bodies(&self) -> usize {
        if self.closed {
            self.pts.len()
        } else {
            self.pts.len().saturating_sub(1)
        }
    }

    /// The point after point `k` along the path (closed: after the last,
    /// the first).
    fn next(&self, k: usize) -> usize {
        if self.closed && k + 1 == self.pts.len() {
            0
        } else {
            k + 1
        }
    }

    /// The body before point `k`, if any (closed: before the first, the
    /// last).
    fn before(&self, k: usize) -> Option<usize> {
        match k.checked_sub(1) {
            None if self.closed => self.pts.len().checked_sub(1),
            j => j,
        }
    }

    /// The body `k`, uncut.
    fn body(&self, k: usize) -> Option<Piece> {
        if k >= self.bodies() {
            return None;
        }
        let (a, b) = (*self.pts.get(k)?, *self.pts.get(self.next(k))?);
        Piece::straight(a, b, self.sides)
    }

    /// Joins body `a` (ending at the join's point) to body `b` as the
    /// outline does: the inner corner where it cut them (they tile).
    fn join_cut(&self, a: &mut Piece, b: &mut Piece) -> Option<[i32; 2]> {
        if a.ne == b.ns {
            return None;
        }
        let (v, na, nb) = (a.e, a.ne, b.ns);
        let cut = if is_right_turn(na, nb) {
            let i = inner_corner(v, na, nb, self.sides.p, 1);
            cut_inner(a.sp, &mut a.ep, &mut b.sp, b.ep, i).then_some(i)
        } else {
            let i = inner_corner(v, na, nb, self.sides.m, -1);
            cut_inner(a.sm, &mut a.em, &mut b.sm, b.em, i).then_some(i)
        };
        cut.flatten().map(pack)
    }

    /// Pieces: a cap or join before each body and after the last (open),
    /// a join before each body (closed).
    fn count(&self) -> usize {
        (2 * self.bodies() + usize::from(!self.closed)).min(MAX_PIECES)
    }

    /// Walks the outline's joins in order, recording where it cut the
    /// bodies (a cut depends on the cut before on the same side).
    /// (Closed: the first body is held until the last is joined back to
    /// it, its end cut by the join after it.)
    fn find_cuts(&mut self) {
        let Some(mut a) = self.body(0) else {
            return;
        };
        let mut first = None;
        for k in 1..self.bodies() {
            let Some(mut b) = self.body(k) else {
                return;
            };
            let cut = self.join_cut(&mut a, &mut b);
            if let Some(slot) = self.cuts.get_mut(k) {
                *slot = cut;
            }
            if k == 1 {
                first = Some(a);
            }
            a = b;
        }
        if self.closed {
            if let Some(mut f) = first {
                let cut = self.join_cut(&mut a, &mut f);
                if let Some(slot) = self.cuts.get_mut(0) {
                    *slot = cut;
                }
            }
        }
    }

    fn cut(&self, k: usize) -> Option<Pt> {
        self.cuts.get(k).copied().flatten().map(unpack)
    }

    /// Body `k` as the outline left it: `sm em (e) ep sp (s)`, the
    /// path's point on a cross-section where the path turns (the join's
    /// wedge and the inner corner meet there; a cut moves the inner
    /// corner of the cross-section to the cut).
    fn body_poly(&self, k: usize) -> Option<Poly> {
        let mut b = self.body(k)?;
        let prev = self.before(k).and_then(|j| self.body(j));
        let next = self.body(self.next(k));
        let start_turn = prev.filter(|a| a.ne != b.ns);
        let end_turn = next.filter(|n| b.ne != n.ns);
        if let (Some(a), Some(i)) = (start_turn, self.cut(k)) {
            if is_right_turn(a.ne, b.ns) {
                b.sp = i;
            } else {
                b.sm = i;
            }
        }
        if let (Some(n), Some(i)) = (end_turn, self.cut(self.next(k))) {
            if is_right_turn(b.ne, n.ns) {
                b.ep = i;
            } else {
                b.em = i;
            }
        }
        let mut p = Poly::new();
        p.push(b.sm);
        p.push(b.em);
        if end_turn.is_some() {
            p.push(b.e);
        }
        p.push(b.ep);
        p.push(b.sp);
        if start_turn.is_some() {
            p.push(b.s);
        }
        Some(p)
    }

    /// The wedge of the join at point `k` (`1..bodies`, closed any), if
    /// it has area.
    fn wedge(&self, k: usize) -> Option<Wedge> {
        let a = self.body(self.before(k)?)?;
        let b = self.body(k)?;
        if a.ne == b.ns {
            return None;
        }
        let (na, nb) = (a.ne, b.ns);
        let w = if is_right_turn(na, nb) {
            Wedge {
                v: a.e,
                from: a.em,
                to: b.sm,
                ua: neg(na),
                ub: neg(nb),
                h_q1: self.sides.m,
            }
        } else {
            Wedge {
                v: a.e,
                from: b.sp,
                to: a.ep,
                ua: nb,
                ub: na,
                h_q1: self.sides.p,
            }
        };
        (w.h_q1 != 0 && w.from != w.to).then_some(w)
    }

    /// The cross-section a cap at point `k` (0 or the last) closes:
    /// `(from, to)` as the outline's `cap_path` takes them.
    fn cap_ends(&self, k: usize) -> Option<(Pt, Pt)> {
        if k == 0 {
            let b = self.body(0)?;
            Some((b.sp, b.sm))
        } else {
            let b = self.body(k.checked_sub(1)?)?;
            Some((b.em, b.ep))
        }
    }

    /// What piece `t` is: even `t` the cap or join at point `t / 2`, odd
    /// the body `(t - 1) / 2`.
    fn form(&self, t: usize) -> Form {
        if t % 2 == 1 {
            return if self.body(t / 2).is_some() {
                Form::Clip
            } else {
                Form::Empty
            };
        }
        let k = t / 2;
        if !self.closed && (k == 0 || k == self.bodies()) {
            match self.cap {
                LineCap::Butt => Form::Empty,
                LineCap::Square => Form::Clip,
                LineCap::Round => Form::Round,
            }
        } else if self.wedge(k).is_none() {
            Form::Empty
        } else if self.join == LineJoin::Round {
            Form::Round
        } else {
            Form::Clip
        }
    }

    /// The vertices of piece `t`, clockwise, into `out`.
    fn points(&self, t: usize, out: &mut impl FnMut(Pt)) {
        if t % 2 == 1 {
            if let Some(p) = self.body_poly(t / 2) {
                (0..p.n).for_each(|k| out(p.at(k)));
            }
            return;
        }
        let k = t / 2;
        if !self.closed && (k == 0 || k == self.bodies()) {
            let Some((from, to)) = self.cap_ends(k) else {
                return;
            };
            if from == to {
                return;
            }
            match self.cap {
                LineCap::Butt => {}
                LineCap::Square => {
                    let (a, b) = square_cap_corners(from, to);
                    [from, a, b, to].into_iter().for_each(&mut *out);
                }
                LineCap::Round => {
                    // As `Outline::cap_path`: half a turn about the
                    // midpoint, clockwise from `from`.
                    let c_q8 = Pt::new((from.x + to.x) << 7, (from.y + to.y) << 7);
                    let r_q8 = self.sides.width() << 6;
                    let t0 = i64::from(atan2(from.y - to.y, from.x - to.x));
                    self.arc(c_q8, r_q8, t0, HALF_TURN, from, to, out);
                }
            }
            return;
        }
        let Some(w) = self.wedge(k) else {
            return;
        };
        let dot = w.ua.dot(w.ub);
        match self.join {
            LineJoin::Miter if self.miter_limit.allows(dot) => {
                let tip = miter_tip(w.v, w.ua, w.ub, w.h_q1);
                [w.from, tip, w.to, w.v].into_iter().for_each(&mut *out);
            }
            LineJoin::Miter | LineJoin::Bevel => {
                [w.from, w.to, w.v].into_iter().for_each(&mut *out);
            }
            LineJoin::Round => {
                // As `Outline::wedge`.
                let t0 = i64::from(atan2(w.ua.y, w.ua.x));
                let turn = i64::from(atan2(w.ua.cross(w.ub), dot));
                let c_q8 = Pt::new(w.v.x << 8, w.v.y << 8);
                self.arc(c_q8, w.h_q1 << 7, t0, turn, w.from, w.to, out);
                out(w.v);
            }
        }
    }

    /// `from`, the inner vertices of the arc, `to` (as `Outline::arc`).
    #[allow(clippy::too_many_arguments)]
    fn arc(
        &self,
        c_q8: Pt,
        r_q8: i64,
        t0: i64,
        sweep: i64,
        from: Pt,
        to: Pt,
        out: &mut impl FnMut(Pt),
    ) {
        let frame = EllipseFrame::with_q8(c_q8, r_q8, r_q8, UNIT_X);
        out(from);
        arc_inner_vertices(&frame, t0, sweep, self.tol, from, &mut |p: Pt| out(p));
        out(to);
    }

    /// Part `s` of piece `t` as one of `n_clip` clippers of a term (its
    /// vertices stored): the whole piece if it is a [`Form::Clip`]; of a
    /// round piece `q_0 ... q_(n-1)`, the fan `q_0, q_(fs+1) ...
    /// q_(fs+f+1)` of `f` triangles from `q_0` (see [`fan`]): the parts
    /// tile the piece, sharing its diagonals from `q_0`.
    fn clipper(&self, t: usize, form: Form, s: u32, n_clip: usize) -> Poly {
        let mut p = Poly::new();
        if form == Form::Round {
            let f = fan(n_clip) as usize;
            let lo = f * s as usize + 1;
            let mut idx = 0usize;
            self.points(t, &mut |q| {
                if idx == 0 || (lo..=lo + f).contains(&idx) {
                    p.push(q);
                }
                idx += 1;
            });
        } else {
            self.points(t, &mut |q| p.push(q));
        }
        p
    }

    /// How many parts a clipper of `form` is cut into as one of `n_clip`
    /// clippers (see [`clipper`](Self::clipper)).
    fn parts(&self, form: Form, n_clip: usize) -> u32 {
        match form {
            Form::Round => self.round_count.saturating_sub(2).div_ceil(fan(n_clip)),
            _ => 1,
        }
    }

    /// The box of piece `t` (exact for clippers, a bound for arcs).
    fn bounds(&self, t: usize, form: Form) -> Box4 {
        match form {
            Form::Empty => Box4::EMPTY,
            Form::Clip => {
                let mut b = Box4::EMPTY;
                self.points(t, &mut |q| b.add(q));
                b
            }
            Form::Round => {
                let r = self.sides.width() / 4;
                match self.pts.get(t / 2) {
                    Some(&c) => Box4::around(c, r + round_margin(r)),
                    None => Box4::EMPTY,
                }
            }
        }
    }

    /// True when pieces `i` and `j` are found not to overlap with area: a
    /// line through an edge of a polygon piece has the other wholly on
    /// its outer side (the other's vertices, or for a round piece its
    /// bounding disc). Exact for two polygons (separating axes: convex
    /// polygons that do not overlap have an edge of one separating
    /// them); a bound for round pieces. The same in every band.
    fn apart(&self, i: usize, fi: Form, j: usize, fj: Form) -> bool {
        let r = self.sides.width() / 4;
        let disc = |t: usize| {
            let c = self.pts.get(t / 2).copied().unwrap_or_default();
            Outside::Disc(c, r + round_margin(r))
        };
        match (fi, fj) {
            (Form::Clip, Form::Clip) => {
                let (pi, pj) = (self.clipper(i, fi, 0, 1), self.clipper(j, fj, 0, 1));
                separates(&pi, Outside::Poly(&pj)) || separates(&pj, Outside::Poly(&pi))
            }
            (Form::Clip, Form::Round) => separates(&self.clipper(i, fi, 0, 1), disc(j)),
            (Form::Round, Form::Clip) => separates(&self.clipper(j, fj, 0, 1), disc(i)),
            _ => false,
        }
    }

    /// The most vertices piece `t` of `form` has.
    fn vertex_bound(&self, form: Form) -> u32 {
        match form {
            Form::Empty => 0,
            Form::Clip => MAX_CLIP as u32,
            Form::Round => self.round_count,
        }
    }
}

/// Triangles in a part of a round clipper, as one of `n_clip` clippers
/// of a term: its share of the stages, less the two edges from the fan's
/// apex.
fn fan(n_clip: usize) -> u32 {
    (MAX_STAGES / n_clip.max(1)).saturating_sub(2).max(1) as u32
}

/// What must lie outside an edge's line for the edge to separate.
#[derive(Clone, Copy)]
enum Outside<'p> {
    Poly(&'p Poly),
    /// A disc: centre and radius.
    Disc(Pt, i64),
}

/// True when some edge of `a` has all of `b` on its outer side (or on
/// its line).
fn separates(a: &Poly, b: Outside<'_>) -> bool {
    (0..a.n).any(|k| {
        let (p, q) = (a.at(k), a.at(k + 1));
        let d = q.sub(p);
        p != q
            && match b {
                Outside::Poly(b) => (0..b.n).all(|j| d.cross(b.at(j).sub(p)) <= 0),
                Outside::Disc(c, r) => {
                    // At least r outside: d x (c - p) <= -r |d|, squared.
                    let s = d.cross(c.sub(p));
                    s < 0
                        && s.unsigned_abs().pow(2)
                            >= (r.unsigned_abs() as u128).pow(2) * d.dot(d).unsigned_abs()
                }
            }
    })
}

/// One Sutherland-Hodgman stage: keeps the part of a closed polygon
/// streamed through it on the inner (right, on screen) side of the line
/// `a -> a + d`. Coordinates in `i32` (within the range, `2^21`; a
/// difference within `2^22`), sides in `i64` (products within `2^45`),
/// recomputed rather than kept (the stages are most of the stack).
#[derive(Debug, Clone, Copy, Default)]
struct Stage {
    a: [i32; 2],
    d: [i32; 2],
    first: [i32; 2],
    prev: [i32; 2],
    started: bool,
}

fn pack(p: Pt) -> [i32; 2] {
    [p.x as i32, p.y as i32]
}

fn unpack(p: [i32; 2]) -> Pt {
    Pt::new(i64::from(p[0]), i64::from(p[1]))
}

impl Stage {
    fn new(a: Pt, b: Pt) -> Self {
        Self {
            a: pack(a),
            d: pack(b.sub(a)),
            ..Self::default()
        }
    }

    /// `d x (p - a)`: `>= 0` inside.
    fn side(&self, p: Pt) -> i64 {
        let (qx, qy) = (p.x - i64::from(self.a[0]), p.y - i64::from(self.a[1]));
        i64::from(self.d[0]) * qy - i64::from(self.d[1]) * qx
    }
}

/// Where `p -> q` crosses a stage's line, the sides `sp`, `sq` of
/// opposite signs: `p + (q - p) sp / (sp - sq)`, rounded to the grid.
fn crossing(p: Pt, sp: i64, q: Pt, sq: i64) -> Pt {
    let den = i128::from(sp) - i128::from(sq);
    let d = q.sub(p);
    Pt::new(
        p.x + div_round(i128::from(d.x) * i128::from(sp), den) as i64,
        p.y + div_round(i128::from(d.y) * i128::from(sp), den) as i64,
    )
}

/// The highest order of inclusion and exclusion: odd, so that the
/// truncated sum is never below the union's indicator (Bonferroni);
/// exact wherever at most this many pieces overlap.
pub const MAX_ORDER: usize = 5;

/// Stages: a clipper's edges for every piece of a term but its subject.
const MAX_STAGES: usize = (MAX_ORDER - 1) * MAX_CLIP;

/// Vertices waiting to enter a stage, last in first out.
struct Waiting {
    items: [(u8, [i32; 2]); MAX_STAGES + 2],
    top: usize,
}

impl Waiting {
    fn put(&mut self, s: usize, p: Pt) {
        if let Some(slot) = self.items.get_mut(self.top) {
            *slot = (s as u8, pack(p));
            self.top += 1;
        }
    }

    fn take(&mut self) -> Option<(usize, Pt)> {
        self.top = self.top.checked_sub(1)?;
        let &(s, p) = self.items.get(self.top)?;
        Some((usize::from(s), unpack(p)))
    }
}

/// A chain of stages and the contour its output becomes.
struct Clip<'s, S: SegmentSink + ?Sized> {
    stages: [Stage; MAX_STAGES],
    count: usize,
    sink: &'s mut S,
    /// Emit edges backwards (winding -1: terms of even order).
    reverse: bool,
    out_first: Option<Pt>,
    out_prev: Pt,
    /// Numbers taken so far, and the most this term may take.
    taken: u32,
    limit: u32,
}

impl<S: SegmentSink + ?Sized> Clip<'_, S> {
    /// Adds the edges of the convex polygon `p` as stages.
    fn add_clipper(&mut self, p: &Poly) {
        for k in 0..p.n {
            let (a, b) = (p.at(k), p.at(k + 1));
            if a != b {
                if let Some(st) = self.stages.get_mut(self.count) {
                    *st = Stage::new(a, b);
                    self.count += 1;
                }
            }
        }
    }

    /// Feeds vertex `v` to stage `s0` and on, without recursion: a stage
    /// passes on at most a crossing and then the vertex, so a stack of
    /// what waits (the vertex under the crossing, at most one per stage)
    /// keeps the order.
    fn feed(&mut self, s0: usize, v: Pt) {
        let mut wait = Waiting {
            items: [(0, [0; 2]); MAX_STAGES + 2],
            top: 0,
        };
        wait.put(s0, v);
        while let Some((s, v)) = wait.take() {
            let Some(st) = self.stages.get_mut(s).filter(|_| s < self.count) else {
                self.output(v);
                continue;
            };
            let sv = st.side(v);
            if !st.started {
                st.started = true;
                st.first = pack(v);
                st.prev = pack(v);
                if sv >= 0 {
                    wait.put(s + 1, v);
                }
                continue;
            }
            let p = unpack(st.prev);
            let sp = st.side(p);
            st.prev = pack(v);
            // The vertex waits under the crossing (taken first).
            if sv >= 0 {
                wait.put(s + 1, v);
            }
            if (sp >= 0) != (sv >= 0) {
                wait.put(s + 1, crossing(p, sp, v, sv));
            }
        }
    }

    /// Closes every stage in order (the edge back to its first vertex
    /// passes on only its crossing), then the output contour.
    fn close(&mut self) {
        for s in 0..self.count {
            let Some(st) = self.stages.get(s).copied() else {
                break;
            };
            if st.started {
                let (p, f) = (unpack(st.prev), unpack(st.first));
                let (sp, sf) = (st.side(p), st.side(f));
                if (sp >= 0) != (sf >= 0) {
                    self.feed(s + 1, crossing(p, sp, f, sf));
                }
            }
        }
        if let Some(f) = self.out_first.take() {
            self.segment(self.out_prev, f);
        }
    }

    fn output(&mut self, v: Pt) {
        match self.out_first {
            None => {
                self.out_first = Some(v);
                self.out_prev = v;
            }
            // Keep one number for the closing edge: past the limit (only
            // by rounding), vertices are dropped.
            Some(_) if self.taken + 1 < self.limit => {
                self.segment(self.out_prev, v);
                self.out_prev = v;
            }
            Some(_) => {}
        }
    }

    fn segment(&mut self, a: Pt, b: Pt) {
        if self.reverse {
            emit(self.sink, b, a);
        } else {
            emit(self.sink, a, b);
        }
        self.taken += 1;
    }
}

/// A term of inclusion and exclusion: pieces (`count` of them, in
/// increasing order) that pairwise may overlap, and the meet of their
/// boxes.
#[derive(Debug, Clone, Copy)]
struct Term {
    pieces: [usize; MAX_ORDER],
    count: usize,
    meet: Box4,
}

impl Term {
    fn pieces(&self) -> &[usize] {
        self.pieces.get(..self.count).unwrap_or(&[])
    }

    /// The subject (the first round piece, if any, else the first) and
    /// the clippers.
    fn roles(&self, forms: &[Form; MAX_PIECES]) -> (usize, [usize; MAX_ORDER], usize) {
        let ps = self.pieces();
        let subject = ps
            .iter()
            .copied()
            .find(|&t| form_of(forms, t) == Form::Round)
            .or(ps.first().copied())
            .unwrap_or(0);
        let mut clippers = [0; MAX_ORDER];
        let mut n = 0;
        for &t in ps.iter().filter(|&&t| t != subject) {
            if let Some(slot) = clippers.get_mut(n) {
                *slot = t;
                n += 1;
            }
        }
        (subject, clippers, n)
    }
}

/// How much of the union a polyline's stroke got.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Treatment {
    /// None: beyond the limits (the plain outline).
    None,
    /// Every overlap but those of two round pieces (the full work would
    /// pass [`MAX_UNION_WORK`]).
    WithoutRoundPairs,
    /// Every overlap.
    Full,
}

/// Adds the union's corrections of a polyline's stroke (see the module
/// doc) to `sink`, after the outline the stroker gave it; nothing for a
/// polyline beyond the treatment's limits. `closed`: a polygon's (its
/// points once each, in the order its description sends them), stroked
/// centred.
pub(crate) fn polyline_union<S: SegmentSink + ?Sized>(
    points: impl ExactSizeIterator<Item = Pt>,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    closed: bool,
    sink: &mut S,
) -> Treatment {
    // Longer polylines (a chart's) pay one comparison.
    if points.len() > MAX_UNION_POINTS || style.dash.is_some_and(|d| !d.is_solid()) {
        return Treatment::None;
    }
    // An open path is stroked centred whatever the alignment; a polygon
    // stroked inside or outside is left as it is (its joins' radii
    // differ from the pieces' bounds taken here).
    if closed && style.alignment != StrokeAlignment::Centre {
        return Treatment::None;
    }
    let style = style.with_alignment(StrokeAlignment::Centre);
    let sides = style.sides();
    if sides.width() == 0 {
        return Treatment::None;
    }
    // Every piece and crossing within the range (so every segment takes
    // one number, and the stages' coordinates fit `i32`).
    let room = i64::from(FINE_LIMIT) - style.reach() - 64;
    let mut pts = [Pt::default(); MAX_UNION_POINTS];
    let mut n = 0;
    for p in points {
        if n > 0 && pts.get(n - 1) == Some(&p) {
            continue;
        }
        if p.x.abs() > room || p.y.abs() > room {
            return Treatment::None;
        }
        match pts.get_mut(n) {
            Some(slot) => *slot = p,
            None => return Treatment::None,
        }
        n += 1;
    }
    // A polygon whose last point is its first: one closing body less
    // (the stroker's `close` has no length to draw).
    if closed && n > 1 && pts.first() == pts.get(n - 1) {
        n -= 1;
    }
    let Some(pts) = pts.get(..n).filter(|p| p.len() >= 2) else {
        return Treatment::None;
    };
    let r = sides.width() / 4;
    let mut pieces = Pieces {
        pts,
        closed,
        sides,
        join: style.join,
        miter_limit: style.miter_limit,
        cap: style.cap,
        tol,
        cuts: [None; MAX_UNION_POINTS],
        // A half turn's `m` steps: `m + 1` arc points and the centre
        // (`arc_count` grows with the radius, and the arcs' radius is
        // rounded up).
        round_count: arc_count(r + 1, HALF_TURN, tol) + 2,
    };
    pieces.find_cuts();
    let count = pieces.count();
    let mut forms = [Form::Empty; MAX_PIECES];
    let mut boxes = [Box4::EMPTY; MAX_PIECES];
    for (t, (f, b)) in forms
        .iter_mut()
        .zip(boxes.iter_mut())
        .enumerate()
        .take(count)
    {
        *f = pieces.form(t);
        *b = pieces.bounds(t, *f);
    }
    // The pairs that may overlap with area, as bits.
    let mut pairs = [0u32; MAX_PIECES];
    for i in 0..count {
        for j in i + 1..count {
            let (fi, fj) = (form_of(&forms, i), form_of(&forms, j));
            // A body and the join or cap at its end; two bodies the
            // outline cut at their inner corner, or that go straight on.
            // Closed, around the first point: its join and the last
            // body; the first and the last body.
            let last = count.saturating_sub(1);
            let tiles = j == i + 1
                || (i % 2 == 1
                    && j == i + 2
                    && (pieces.cut(j / 2).is_some() || form_of(&forms, i + 1) == Form::Empty))
                || (closed && i == 0 && j == last)
                || (closed
                    && i == 1
                    && j == last
                    && (pieces.cut(0).is_some() || form_of(&forms, 0) == Form::Empty));
            let meet = box_of(&boxes, i).meet(box_of(&boxes, j));
            if fi == Form::Empty
                || fj == Form::Empty
                || tiles
                || !meet.has_area()
                || pieces.apart(i, fi, j, fj)
            {
                continue;
            }
            if let Some(m) = pairs.get_mut(i) {
                *m |= 1 << j;
            }
            if let Some(m) = pairs.get_mut(j) {
                *m |= 1 << i;
            }
        }
    }
    // The work, counted before any is done (the same in every band).
    let work = |pairs: &[u32; MAX_PIECES]| {
        let mut work = 0u64;
        each_term(count, pairs, &boxes, &mut |term| {
            let (subject, clippers, n_clip) = term.roles(&forms);
            let bound = u64::from(pieces.vertex_bound(form_of(&forms, subject)));
            let parts = clippers
                .iter()
                .take(n_clip)
                .map(|&c| u64::from(pieces.parts(form_of(&forms, c), n_clip)))
                .product::<u64>();
            let st = stages(clippers.get(..n_clip).unwrap_or(&[]), &forms);
            work = work.saturating_add(bound * st as u64 * parts);
        });
        work
    };
    let mut treatment = Treatment::Full;
    if work(&pairs) > u64::from(MAX_UNION_WORK) {
        treatment = Treatment::WithoutRoundPairs;
        // Without the overlaps of two round pieces (which cost the most:
        // a round clipper is cut into parts): still never below the
        // union (see the module doc), exact where at most one round
        // piece is among those overlapping.
        for (i, m) in pairs.iter_mut().enumerate().take(count) {
            if form_of(&forms, i) == Form::Round {
                for j in 0..count {
                    if form_of(&forms, j) == Form::Round {
                        *m &= !(1 << j);
                    }
                }
            }
        }
        if work(&pairs) > u64::from(MAX_UNION_WORK) {
            return Treatment::None;
        }
    }
    let window = sink.window();
    each_term(count, &pairs, &boxes, &mut |term| {
        let (subject, clippers, n_clip) = term.roles(&forms);
        let clippers = clippers.get(..n_clip).unwrap_or(&[]);
        let limit = pieces.vertex_bound(form_of(&forms, subject)) + stages(clippers, &forms) as u32;
        let meet = term.meet;
        let misses = window.is_some_and(|(lo, hi)| meet.y1 < lo || meet.y0 > hi);
        // Every combination of the clippers' parts, as a mixed-radix
        // counter.
        let mut part = [0u32; MAX_ORDER];
        loop {
            if misses {
                sink.skipped(limit);
            } else {
                let mut clip = Clip {
                    stages: [Stage::default(); MAX_STAGES],
                    count: 0,
                    sink: &mut *sink,
                    reverse: term.count % 2 == 0,
                    out_first: None,
                    out_prev: Pt::default(),
                    taken: 0,
                    limit,
                };
                let mut empty = false;
                for (&c, &s) in clippers.iter().zip(part.iter()) {
                    let q = pieces.clipper(c, form_of(&forms, c), s, clippers.len());
                    empty |= q.n < 3;
                    clip.add_clipper(&q);
                }
                if !empty {
                    pieces.points(subject, &mut |p| clip.feed(0, p));
                    clip.close();
                }
                let taken = clip.taken;
                sink.skipped(limit.saturating_sub(taken));
            }
            // The next combination.
            let mut k = 0;
            loop {
                let (Some(&c), Some(d)) = (clippers.get(k), part.get_mut(k)) else {
                    return;
                };
                *d += 1;
                if *d < pieces.parts(form_of(&forms, c), clippers.len()) {
                    break;
                }
                *d = 0;
                k += 1;
            }
        }
    });
    treatment
}

/// The most stages the `clippers` of a term use: a polygon piece's
/// edges, a round part's triangles and the two edges from its apex.
fn stages(clippers: &[usize], forms: &[Form; MAX_PIECES]) -> usize {
    clippers
        .iter()
        .map(|&c| match form_of(forms, c) {
            Form::Round => fan(clippers.len()) as usize + 2,
            _ => MAX_CLIP,
        })
        .sum()
}

fn form_of(forms: &[Form; MAX_PIECES], t: usize) -> Form {
    forms.get(t).copied().unwrap_or(Form::Empty)
}

fn box_of(boxes: &[Box4; MAX_PIECES], t: usize) -> Box4 {
    boxes.get(t).copied().unwrap_or(Box4::EMPTY)
}

/// Calls `f` with every term: every set of 2 to [`MAX_ORDER`] pieces that
/// pairwise may overlap and whose boxes meet with area, in a fixed order
/// (depth first, pieces increasing).
fn each_term(
    count: usize,
    pairs: &[u32; MAX_PIECES],
    boxes: &[Box4; MAX_PIECES],
    f: &mut impl FnMut(&Term),
) {
    for i in 0..count {
        let mut pieces = [0; MAX_ORDER];
        if let Some(first) = pieces.first_mut() {
            *first = i;
        }
        let term = Term {
            pieces,
            count: 1,
            meet: box_of(boxes, i),
        };
        let later = pairs.get(i).copied().unwrap_or(0);
        grow(&term, later, count, pairs, boxes, f);
    }
}

/// The terms that extend `term` by pieces in `candidates` (bits; each
/// overlaps every piece of `term`), then by more.
fn grow(
    term: &Term,
    candidates: u32,
    count: usize,
    pairs: &[u32; MAX_PIECES],
    boxes: &[Box4; MAX_PIECES],
    f: &mut impl FnMut(&Term),
) {
    let last = term.pieces().last().copied().unwrap_or(0);
    if term.count >= MAX_ORDER {
        return;
    }
    for j in last + 1..count {
        if candidates & (1 << j) == 0 {
            continue;
        }
        let meet = term.meet.meet(box_of(boxes, j));
        if !meet.has_area() {
            continue;
        }
        let mut next = *term;
        if let Some(slot) = next.pieces.get_mut(next.count) {
            *slot = j;
        }
        next.count += 1;
        next.meet = meet;
        f(&next);
        let more = candidates & pairs.get(j).copied().unwrap_or(0);
        grow(&next, more, count, pairs, boxes, f);
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::geom::FinePoint;
    use crate::path::testing::{Lcg, Numbering, Tally};
    use crate::path::{Polygon, Polyline, Shape};

    const JOINS: [LineJoin; 3] = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel];
    const CAPS: [LineCap; 3] = [LineCap::Butt, LineCap::Round, LineCap::Square];

    /// A random polyline of `n` points in a 48-px square, and a style.
    fn case(rng: &mut Lcg, n: usize, k: usize) -> (Vec<FinePoint>, StrokeStyle<'static>) {
        let pts = (0..n)
            .map(|_| {
                let c = |r: &mut Lcg| 8 * 1024 + r.below(48 * 1024) as i32;
                FinePoint::new(c(rng), c(rng))
            })
            .collect();
        let style = StrokeStyle::new(256 + rng.below(6 * 1024) as u32)
            .with_join(JOINS[k % 3])
            .with_cap(CAPS[k / 3 % 3]);
        (pts, style)
    }

    fn pieces_of<'a>(pts: &'a [Pt], style: &StrokeStyle<'_>, closed: bool) -> Pieces<'a> {
        let sides = style.sides();
        let mut p = Pieces {
            pts,
            closed,
            sides,
            join: style.join,
            miter_limit: style.miter_limit,
            cap: style.cap,
            tol: Tolerance::DEFAULT,
            cuts: [None; MAX_UNION_POINTS],
            round_count: arc_count(sides.width() / 4 + 1, HALF_TURN, Tolerance::DEFAULT) + 2,
        };
        p.find_cuts();
        p
    }

    /// The pieces regenerated here are the outline's, vertex for vertex:
    /// their shoelace sums add up to the outline's, exactly; each is
    /// convex and clockwise; and no round piece has more vertices than
    /// its bound. Polylines and (every other case) closed polygons,
    /// their points in the order their description sends them.
    #[test]
    fn the_regenerated_pieces_sum_to_the_outline() {
        let mut rng = Lcg(0x0a17_0b1e_2c3d_4e5f);
        for k in 0..1200 {
            let n = 2 + k % 15;
            let closed = k % 2 == 1;
            let (pts, style) = case(&mut rng, n, k);
            let polygon = Polygon::new(&pts);
            let area2: i128 = (0..pts.len())
                .map(|i| Pt::from(pts[i]).cross(Pt::from(pts[(i + 1) % pts.len()])))
                .sum();
            let forward = area2 >= 0;
            // With the corrections: still closed contours, in range.
            let mut outline = Tally::default();
            // The outline alone: the stroker, without the corrections.
            let mut alone = Tally::default();
            {
                let mut s = crate::path::Stroker::new(&style, &mut alone);
                if closed {
                    polygon.stroke(&style, &mut outline).unwrap_or(());
                    polygon.describe(&mut s);
                } else {
                    Polyline::new(&pts)
                        .stroke(&style, &mut outline)
                        .unwrap_or(());
                    Polyline::new(&pts).describe(&mut s);
                }
                s.finish().unwrap_or(());
            }
            let mut ps: Vec<Pt> = pts.iter().map(|&p| Pt::from(p)).collect();
            if closed && !forward {
                ps.reverse();
            }
            let pieces = pieces_of(&ps, &style, closed);
            let mut sum = 0i128;
            for t in 0..pieces.count() {
                let mut v = Vec::new();
                pieces.points(t, &mut |p| v.push(p));
                let form = pieces.form(t);
                if form == Form::Round {
                    assert!(v.len() as u32 <= pieces.round_count, "case {k}: piece {t}");
                }
                for j in 0..v.len() {
                    let (a, b, c) = (v[j], v[(j + 1) % v.len()], v[(j + 2) % v.len()]);
                    sum += a.cross(b);
                    // Convex and clockwise, to the grid's rounding (a
                    // cross-section's three points are collinear up to
                    // it).
                    let turn = b.sub(a).cross(c.sub(b));
                    let slack = 2 * (b.sub(a).len() + c.sub(b).len()) as i128 + 4;
                    assert!(turn >= -slack, "case {k}: piece {t} turns left at {j}");
                }
            }
            assert_eq!(sum, alone.area2, "case {k} (closed {closed})");
            assert!(outline.closed(), "case {k}");
        }
    }

    /// A band's view of the stroke numbers every segment as the whole
    /// stroke does, and has every segment that meets its rows.
    #[test]
    fn the_corrections_take_the_same_numbers_in_every_band() {
        let mut rng = Lcg(0x0b1e_0a17_5f4e_3d2c);
        for k in 0..600 {
            let n = 3 + k % 14;
            let (pts, style) = case(&mut rng, n, k);
            let (line, polygon) = (Polyline::new(&pts), Polygon::new(&pts));
            // Polylines, and (every other case) closed polygons.
            let stroke = |sink: &mut Numbering| {
                if k % 2 == 0 {
                    line.stroke(&style, sink).unwrap_or(());
                } else {
                    polygon.stroke(&style, sink).unwrap_or(());
                }
            };
            let mut whole = Numbering {
                window: None,
                next: 0,
                segs: Vec::new(),
            };
            stroke(&mut whole);
            for lo in (0..64 * 1024).step_by(7 * 1024) {
                let w = (lo, lo + 3 * 1024);
                let mut band = Numbering {
                    window: Some(w),
                    next: 0,
                    segs: Vec::new(),
                };
                stroke(&mut band);
                assert_eq!(band.next, whole.next, "case {k}, band {w:?}");
                let meets = |s: &&(u32, FinePoint, FinePoint)| {
                    s.1.y.max(s.2.y) >= w.0 && s.1.y.min(s.2.y) <= w.1
                };
                let a: Vec<_> = whole.segs.iter().filter(meets).collect();
                let b: Vec<_> = band.segs.iter().filter(meets).collect();
                assert_eq!(a, b, "case {k}, band {w:?}");
            }
        }
    }

    /// How often the treatment is full, without round pairs or none, for
    /// polylines as the issue's test draws them (3 to 7 points, up to 6
    /// px wide) and longer ones.
    #[test]
    fn short_polylines_get_the_full_treatment() {
        let mut rng = Lcg(0x5eed_3636);
        let mut counts = [[[0u32; 3]; 2]; 2];
        for k in 0..400 {
            let long = k % 2 == 1;
            let n = if long { 8 + k % 9 } else { 3 + k % 5 };
            let (pts, style) = case(&mut rng, n, k);
            for closed in [false, true] {
                let mut t = Tally::default();
                let got = polyline_union(
                    pts.iter().map(|&p| Pt::from(p)),
                    &style,
                    Tolerance::DEFAULT,
                    closed,
                    &mut t,
                );
                let i = match got {
                    Treatment::Full => 0,
                    Treatment::WithoutRoundPairs => 1,
                    Treatment::None => 2,
                };
                counts[usize::from(closed)][usize::from(long)][i] += 1;
                if !long {
                    assert_eq!(got, Treatment::Full, "case {k} (closed {closed})");
                }
            }
        }
        std::println!(
            "full / without round pairs / none: polylines of 3..7 points {:?}, 8..16 points \
             {:?}; polygons {:?}, {:?}",
            counts[0][0],
            counts[0][1],
            counts[1][0],
            counts[1][1]
        );
    }
}
