//! The outline of a stroke: bodies, joins and caps summed into closed
//! contours.
//!
//! Takes *runs* (maximal stretches of the stroke without a gap: a whole
//! contour, or one dash) as a sequence of pieces, each the body of one
//! segment of the flattened path; gives the [`SegmentSink`] the boundary
//! of the union of the runs' pieces.
//!
//! ## Pieces and their sum
//!
//! A piece is the quadrilateral swept by the stroke's cross-section along
//! one segment `s -> e`: its ends are the cross-sections at `s` (along the
//! unit normal `ns`) and at `e` (along `ne`), reaching `h_m` to the left
//! (`-n`, the `m` side) and `h_p` to the right (`+n`, the `p` side) of the
//! direction of travel, on screen. For a straight segment `ns = ne` (a
//! rectangle); on a curve they are the curve's normals at the two
//! vertices, so consecutive pieces share their cross-section exactly and
//! the offset edges are chords of the true offset curves. Joins (the
//! wedge between two cross-sections at a vertex, on the outer side of the
//! turn: a bevel triangle, a miter quadrilateral, a round sector) and caps
//! (a half disc or a half square beyond a run's end) are pieces too.
//!
//! Every piece is convex and clockwise on screen. Instead of emitting
//! each piece's boundary, the outline emits their **sum**: the edges two
//! neighbouring pieces share run in opposite directions and cancel, so
//! only the offset edges, the join and cap boundaries and the inner
//! corners remain — a closed contour per run whose winding number at any
//! point is the number of pieces covering it. A piece's `m` edge is
//! emitted forward (`sm -> em`) and its `p` edge backward (`ep -> sp`).
//!
//! ## Inner corners: tiling instead of overlapping
//!
//! At a turn, the two bodies overlap on the inner side in a kite
//! `V, A.e_in, I, B.s_in` (`I` where the two inner offset edges cross).
//! When `I` lies on both inner edges, the outline cuts both bodies along
//! `V -> I` (each gives up the half of the kite beyond the cut, which the
//! other still covers): the pieces then tile the stroke, winding exactly
//! one. When it does not (a segment shorter than the kite, a U-turn),
//! both bodies stay whole and the inner side runs `B.s_in -> V -> A.e_in`:
//! the kite is covered twice and the nonzero rule still gives the union
//! at every point (a pixel's mean winding counts the kite twice where the
//! pixel is also partly outside: a polyline's stroke gets the
//! intersection subtracted, see [`union`](super::union)).
//!
//! ## Order of emission
//!
//! A piece's offset edges are emitted once both of its ends are known:
//! when the next piece has been joined to it, or when its run ends. The
//! first piece of a contour is held back until the contour ends, since a
//! closed contour joins its last piece to it (and may cut its start).
//! Everything else is emitted at once, so the outline needs two pieces of
//! memory.

use crate::arith::mul_i128;
use crate::path::arc::{
    arc_count, arc_inner_vertices, ellipse_points, one_segment_sweep, EllipseFrame,
};
use crate::path::segment::{emit, numbers, Contour, SegmentSink, Vertices};
use crate::path::trig::{atan2, div_round, Q30, TURN};
use crate::path::vector::{Pt, Unit, UNIT_X};
use crate::path::Tolerance;

use super::{LineCap, LineJoin, MiterLimit};

/// What setting up one arc (its count, area factor, first vertex and y
/// estimate) costs, in segments' worth of work: measured on the host
/// (callgrind, issue #36), a round cap of a thin stroke costs about 40
/// segments' time for its 4 or 5 segments.
pub(crate) const ARC_SETUP: u64 = 32;

/// How far the stroke reaches on each side of the path, in half fine
/// units (1/2048 px): `m` to the left of the direction of travel on
/// screen, `p` to the right.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Sides {
    pub m: i64,
    pub p: i64,
}

impl Sides {
    /// The width of the stroke, in half fine units.
    pub fn width(self) -> i64 {
        self.m + self.p
    }
}

/// The body of one segment of the stroke (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Piece {
    pub s: Pt,
    pub e: Pt,
    pub ns: Unit,
    pub ne: Unit,
    pub sm: Pt,
    pub sp: Pt,
    pub em: Pt,
    pub ep: Pt,
    /// `floor(|e - s|)` in fine units.
    pub len: i64,
    /// Every segment of this piece, of its caps and of its joins lies
    /// outside the sink's window and within the range square (a dash that
    /// misses the band): none is sent, only counted as left out (one
    /// number each, so the numbers of what follows do not change), and
    /// no arc is computed; the piece takes part in its run as usual.
    pub quiet: bool,
}

impl Piece {
    /// The piece along `s -> e` with the normals `ns`, `ne` at its ends.
    pub fn new(s: Pt, e: Pt, ns: Unit, ne: Unit, sides: Sides) -> Piece {
        Piece {
            s,
            e,
            ns,
            ne,
            sm: s.offset(ns, -sides.m, 31),
            sp: s.offset(ns, sides.p, 31),
            em: e.offset(ne, -sides.m, 31),
            ep: e.offset(ne, sides.p, 31),
            len: e.sub(s).len(),
            quiet: false,
        }
    }

    /// The rectangle along a straight segment, `None` if it has no length.
    pub fn straight(s: Pt, e: Pt, sides: Sides) -> Option<Piece> {
        let n = e.sub(s).unit()?.right();
        Some(Piece::new(s, e, n, n, sides))
    }

    /// True when the quadrilateral `sm em ep sp` is convex and clockwise
    /// (degenerate edges allowed): a valid piece.
    pub fn is_convex(&self) -> bool {
        let q = [self.sm, self.em, self.ep, self.sp];
        (0..4).all(|k| {
            let (a, b, c) = (q[k], q[(k + 1) % 4], q[(k + 2) % 4]);
            b.sub(a).cross(c.sub(b)) >= 0
        })
    }

    /// The part of the piece between the lengths `u0 <= u1` along it
    /// (`0..=len`), cut straight across both offset edges.
    pub fn cut(&self, u0: i64, u1: i64) -> Piece {
        let lerp = |a: Pt, b: Pt, u: i64| -> Pt {
            if u <= 0 {
                return a;
            }
            if u >= self.len {
                return b;
            }
            let d = b.sub(a);
            let l = i128::from(self.len);
            Pt::new(
                a.x + div_round(i128::from(d.x) * i128::from(u), l) as i64,
                a.y + div_round(i128::from(d.y) * i128::from(u), l) as i64,
            )
        };
        Piece {
            s: lerp(self.s, self.e, u0),
            e: lerp(self.s, self.e, u1),
            ns: self.ns,
            ne: self.ne,
            sm: lerp(self.sm, self.em, u0),
            sp: lerp(self.sp, self.ep, u0),
            em: lerp(self.sm, self.em, u1),
            ep: lerp(self.sp, self.ep, u1),
            len: (u1 - u0).max(0),
            quiet: self.quiet,
        }
    }
}

/// What joins a piece to the one before it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum JoinKind {
    /// A vertex of the path: the style's join.
    Path,
    /// A vertex inside a flattened curve: always round (the true stroke of
    /// a smooth curve is the union of discs along it; this matters at a
    /// cusp).
    Curve,
}

/// Builds the outline of runs of pieces (see the module doc).
pub(crate) struct Outline<'s, S: SegmentSink + ?Sized> {
    sink: Counted<'s, S>,
    join: LineJoin,
    miter_limit: MiterLimit,
    cap: LineCap,
    sides: Sides,
    tol: Tolerance,
    /// The last piece of the current run; its end is not decided yet.
    pending: Option<Piece>,
    /// The pending piece is the contour's first, to be held.
    pending_held: bool,
    /// The first piece of the contour, held back: offset edges (and start
    /// cap) not emitted yet.
    held: Option<Piece>,
    /// The current run began at the contour's start.
    run_holds: bool,
    /// What is being sent belongs to a quiet piece: only its numbers go
    /// to the sink (see [`Piece::quiet`]).
    quiet: bool,
    /// For the `m` side's reach and the `p` side's, the bound `P` of
    /// [`Outline::one_chord`] once found: a round join whose turn has
    /// `cross 2^31 <= P dot` is one chord.
    one_chord: [Option<u64>; 2],
}

/// A lower bound of pi: `PI_LO / PI_DEN`.
const PI_LO: u64 = 314_159_265;
const PI_DEN: u64 = 100_000_000;
/// Binary units the integer [`atan2`] may give above the exact angle of
/// its vector (test: `atan2_is_within_its_slack_of_the_exact_angle`).
pub(crate) const ATAN2_SLACK: i64 = 16;

impl<'s, S: SegmentSink + ?Sized> Outline<'s, S> {
    pub fn new(
        sink: &'s mut S,
        join: LineJoin,
        miter_limit: MiterLimit,
        cap: LineCap,
        sides: Sides,
        tol: Tolerance,
    ) -> Self {
        Self {
            sink: Counted { sink, work: 0 },
            join,
            miter_limit,
            cap,
            sides,
            tol,
            pending: None,
            pending_held: false,
            held: None,
            run_holds: false,
            quiet: false,
            one_chord: [None; 2],
        }
    }

    /// True when a round join of reach `h_q1` turning from `ua` to `ub`
    /// (clockwise: `cross >= 0`, by less than a quarter turn: `dot > 0`)
    /// is drawn as one chord: when [`arc_count`] of its turn, `atan2(cross,
    /// dot)`, is 1, known without the `atan2`s. The turn is at most
    /// `atan(cross / dot) <= (cross / dot) 2^31 / pi` binary units, the
    /// integer `atan2` at most [`ATAN2_SLACK`] above that; so with `S` the
    /// widest one-chord sweep ([`one_segment_sweep`]) and `P = (S - slack)
    /// pi_lo`, `cross 2^31 <= P dot` puts the turn within `S`. `P` is found
    /// once a reach (the first round join of each side).
    fn one_chord(&mut self, h_q1: i64, cross: i64, dot: i64) -> bool {
        if dot <= 0 || cross < 0 {
            return false;
        }
        // `wedge` is given one side's reach or the other's.
        let slot = usize::from(h_q1 != self.sides.m);
        let tol = self.tol;
        let Some(entry) = self.one_chord.get_mut(slot) else {
            return false;
        };
        let p = *entry.get_or_insert_with(|| {
            // The arc's radius as `wedge` gives it to `arc`.
            let frame = EllipseFrame::with_q8(Pt::new(0, 0), h_q1 << 7, h_q1 << 7, UNIT_X);
            let s = one_segment_sweep(frame.major(), tol) - ATAN2_SLACK;
            (s.max(0) as u64 * PI_LO) / PI_DEN
        });
        // cross, dot < 2^31 and P < 2^31: both products below 2^62.
        (cross as u64) << 31 <= p.saturating_mul(dot as u64)
    }

    /// The rows the sink needs ([`SegmentSink::window`]).
    pub fn window(&self) -> Option<(i32, i32)> {
        self.sink.window()
    }

    /// What one cap costs, in segments: a butt cap one, a square cap
    /// three, a round cap twice its half turn of arc (each vertex is
    /// computed: on the host a segment of an arc costs about twice a
    /// straight one) plus [`ARC_SETUP`].
    pub fn cap_cost(&self) -> u64 {
        match self.cap {
            LineCap::Butt => 1,
            LineCap::Square => 3,
            LineCap::Round => {
                // Radius: half the width, in fine units (sides are in
                // half fine units).
                let r = self.sides.width() / 4;
                2 * u64::from(arc_count(r, crate::path::trig::HALF_TURN, self.tol)) + ARC_SETUP
            }
        }
    }

    /// True when a zero-length run shows (round or square caps).
    pub fn draws_dots(&self) -> bool {
        self.cap != LineCap::Butt
    }

    /// The work done so far, in segments' worth: the numbers given to the
    /// sink (segments sent and left out) and the set-ups of the pieces
    /// and arcs (`budget`'s units, counted as they are spent).
    pub fn work(&self) -> u32 {
        self.sink.work
    }

    /// Counts a set-up's work.
    fn set_up(&mut self, units: u64) {
        self.sink.work = self.sink.work.wrapping_add(units as u32);
    }

    /// `a -> b` to the sink, or, quiet, only its numbers.
    fn seg(&mut self, a: Pt, b: Pt) {
        if self.quiet {
            self.sink.skipped(numbers(a, b));
        } else {
            emit(&mut self.sink, a, b);
        }
    }

    /// Starts a run; `at_contour_start` when it begins where the contour
    /// begins (a closed contour may join its end to it).
    pub fn begin_run(&mut self, at_contour_start: bool) {
        if self.pending.is_some() {
            self.end_run();
        }
        self.run_holds = at_contour_start;
    }

    /// The next piece of the current run, joined to the previous one by
    /// `join` (ignored for a run's first piece).
    pub fn piece(&mut self, mut p: Piece, join: JoinKind) {
        self.set_up(super::budget::PIECE_SETUP);
        match self.pending.take() {
            None => {
                if self.run_holds && self.held.is_none() {
                    self.pending_held = true;
                } else {
                    self.pending_held = false;
                    self.start_cap(&p);
                }
                self.pending = Some(p);
            }
            Some(mut a) => {
                self.join_pieces(&mut a, &mut p, join);
                let held = self.pending_held;
                self.finish_piece(a, held);
                self.pending_held = false;
                self.pending = Some(p);
            }
        }
    }

    /// Ends the current run with a cap.
    pub fn end_run(&mut self) {
        if let Some(a) = self.pending.take() {
            self.end_cap(&a);
            let held = self.pending_held;
            self.finish_piece(a, held);
            self.pending_held = false;
        }
        self.run_holds = false;
    }

    /// Ends the contour: with `close`, the current run's last piece is
    /// joined to the held first piece; otherwise runs end with caps.
    pub fn end_contour(&mut self, close: bool) {
        // Join only when both ends are there: a dash pattern whose last
        // gap ends at the start leaves nothing pending, and a contour whose
        // first run began in a gap holds nothing; the fall-through below
        // caps whichever piece there is (taking neither before the test).
        if close && !self.pending_held && self.pending.is_some() && self.held.is_some() {
            if let (Some(mut a), Some(mut f)) = (self.pending.take(), self.held.take()) {
                self.join_pieces(&mut a, &mut f, JoinKind::Path);
                self.sides_of(&a);
                self.sides_of(&f);
                self.run_holds = false;
                return;
            }
        }
        self.end_run();
        if let Some(f) = self.held.take() {
            self.start_cap(&f);
            self.sides_of(&f);
        }
    }

    /// A dot: a zero-length contour or dash at `c` gets its caps as a
    /// whole disc (round) or an axis-aligned square (square), of the
    /// stroke's width; nothing for butt caps.
    pub fn dot(&mut self, c: Pt) {
        let w_q1 = self.sides.width();
        match self.cap {
            LineCap::Butt => {}
            LineCap::Round => {
                // Radius: half the width, w_q1 / 4 fine units, in Q8.
                let frame = EllipseFrame::with_q8(
                    Pt::new(c.x << 8, c.y << 8),
                    w_q1 << 6,
                    w_q1 << 6,
                    UNIT_X,
                );
                self.set_up(ARC_SETUP);
                let mut out = Contour::new(&mut self.sink);
                let mut first = true;
                ellipse_points(&frame, 0, false, self.tol, &mut |p| {
                    if first {
                        out.move_to(p);
                        first = false;
                    } else {
                        out.line_to(p);
                    }
                });
                out.close();
            }
            LineCap::Square => {
                // Half the width (w_q1 is in half fine units), rounded.
                let h = (w_q1 + 2) / 4;
                let q = [
                    Pt::new(c.x - h, c.y - h),
                    Pt::new(c.x + h, c.y - h),
                    Pt::new(c.x + h, c.y + h),
                    Pt::new(c.x - h, c.y + h),
                ];
                for k in 0..4 {
                    self.seg(q[k], q[(k + 1) % 4]);
                }
            }
        }
    }

    /// Emits the offset edges of a finished piece, or holds it.
    fn finish_piece(&mut self, p: Piece, held: bool) {
        if held {
            self.held = Some(p);
        } else {
            self.sides_of(&p);
        }
    }

    fn sides_of(&mut self, p: &Piece) {
        self.quiet = p.quiet;
        self.seg(p.sm, p.em);
        self.seg(p.ep, p.sp);
        self.quiet = false;
    }

    /// The join between `a` (ending at `v`) and `b` (starting there):
    /// emits the outer wedge's boundary and the inner corner, and cuts
    /// both pieces at the inner corner when they can tile.
    fn join_pieces(&mut self, a: &mut Piece, b: &mut Piece, kind: JoinKind) {
        let v = a.e;
        if a.ne == b.ns {
            return;
        }
        // A quiet piece's cross-section at `v` misses the window by the
        // stroke's reach, and so does everything the join sends.
        self.quiet = a.quiet || b.quiet;
        let (na, nb) = (a.ne, b.ns);
        let right_turn = is_right_turn(na, nb);
        let join = match kind {
            JoinKind::Path => self.join,
            JoinKind::Curve => LineJoin::Round,
        };
        if right_turn {
            // Outer: the m side, forward from A to B; the outward normals
            // are -na, -nb. Inner: the p side.
            self.wedge(v, a.em, b.sm, neg(na), neg(nb), self.sides.m, join);
            let i = inner_corner(v, na, nb, self.sides.p, 1);
            if !cut_inner(a.sp, &mut a.ep, &mut b.sp, b.ep, i) {
                self.seg(b.sp, v);
                self.seg(v, a.ep);
            }
        } else {
            // Outer: the p side, emitted backward from B to A; outward
            // normals nb then na. Inner: the m side.
            self.wedge(v, b.sp, a.ep, nb, na, self.sides.p, join);
            let i = inner_corner(v, na, nb, self.sides.m, -1);
            if !cut_inner(a.sm, &mut a.em, &mut b.sm, b.em, i) {
                self.seg(a.em, v);
                self.seg(v, b.sm);
            }
        }
        self.quiet = false;
    }

    /// The outer boundary of a join at `v` from `from` to `to` (offset
    /// points along the outward normals `ua`, `ub`, reaching `h_q1` half
    /// fine units), turning clockwise.
    #[allow(clippy::too_many_arguments)]
    fn wedge(&mut self, v: Pt, from: Pt, to: Pt, ua: Unit, ub: Unit, h_q1: i64, join: LineJoin) {
        if h_q1 == 0 || from == to {
            return;
        }
        let dot = ua.dot(ub);
        match join {
            LineJoin::Bevel => self.seg(from, to),
            LineJoin::Miter if self.miter_limit.allows(dot) && self.quiet => {
                // Two segments within the range square (a quiet piece's
                // reach): their numbers, without the tip's divisions.
                self.sink.skipped(2);
            }
            LineJoin::Miter if self.miter_limit.allows(dot) => {
                let tip = miter_tip(v, ua, ub, h_q1);
                self.seg(from, tip);
                self.seg(tip, to);
            }
            LineJoin::Miter => self.seg(from, to),
            LineJoin::Round => {
                let cross = ua.cross(ub);
                if self.one_chord(h_q1, cross, dot) {
                    // What `arc` sends for an arc of one segment.
                    if self.quiet {
                        self.sink.skipped(1);
                    } else {
                        emit(&mut self.sink, from, to);
                    }
                    return;
                }
                let t0 = i64::from(atan2(ua.y, ua.x));
                let turn = i64::from(atan2(cross, dot));
                let c_q8 = Pt::new(v.x << 8, v.y << 8);
                self.arc(c_q8, h_q1 << 7, t0, turn, from, to);
            }
        }
    }

    /// `from -> (inner points of the arc) -> to` about `c_q8`, radius
    /// `r_q8`, from parameter `t0` over `sweep` (clockwise, binary units).
    fn arc(&mut self, c_q8: Pt, r_q8: i64, t0: i64, sweep: i64, from: Pt, to: Pt) {
        let frame = EllipseFrame::with_q8(c_q8, r_q8, r_q8, UNIT_X);
        let tol = self.tol;
        self.set_up(ARC_SETUP);
        if self.quiet {
            // The arc's m segments (m - 1 inner vertices and the last
            // one), each within the range square: one number each.
            let m = arc_count(frame.major(), sweep.clamp(-TURN, TURN), tol);
            self.sink.skipped(m);
            return;
        }
        let mut out = ArcOut {
            sink: &mut self.sink,
            prev: from,
        };
        arc_inner_vertices(&frame, t0, sweep, tol, from, &mut out);
        let prev = out.prev;
        emit(&mut self.sink, prev, to);
    }

    /// The cap before a run's first piece: `sp -> ... -> sm`.
    fn start_cap(&mut self, p: &Piece) {
        self.quiet = p.quiet;
        self.cap_path(p.sp, p.sm);
        self.quiet = false;
    }

    /// The cap after a run's last piece: `em -> ... -> ep`.
    fn end_cap(&mut self, p: &Piece) {
        self.quiet = p.quiet;
        self.cap_path(p.em, p.ep);
        self.quiet = false;
    }

    /// A cap from `from` to `to` (the ends of a cross-section), bulging
    /// to the left of `from -> to` on screen, which is away from the body
    /// at both ends of a run.
    fn cap_path(&mut self, from: Pt, to: Pt) {
        if from == to {
            return;
        }
        match self.cap {
            LineCap::Butt => self.seg(from, to),
            LineCap::Square => {
                let (a, b) = square_cap_corners(from, to);
                self.seg(from, a);
                self.seg(a, b);
                self.seg(b, to);
            }
            LineCap::Round => {
                // Half a turn about the midpoint, clockwise from `from`.
                let c_q8 = Pt::new((from.x + to.x) << 7, (from.y + to.y) << 7);
                let r_q8 = self.sides.width() << 6;
                let t0 = i64::from(atan2(from.y - to.y, from.x - to.x));
                self.arc(c_q8, r_q8, t0, crate::path::trig::HALF_TURN, from, to);
            }
        }
    }
}

/// The inner vertices of a join's or cap's arc as segments from `prev`:
/// the pieces of the arc that miss the sink's window are jumped over
/// (their segments counted as left out), as the curves of fills are.
struct ArcOut<'a, S: SegmentSink + ?Sized> {
    sink: &'a mut S,
    prev: Pt,
}

impl<S: SegmentSink + ?Sized> Vertices for ArcOut<'_, S> {
    fn vertex(&mut self, p: Pt) {
        emit(self.sink, self.prev, p);
        self.prev = p;
    }
    fn window(&self) -> Option<(i32, i32)> {
        self.sink.window()
    }
    fn jump(&mut self, p: Pt, n: u32) {
        self.sink.skipped(n);
        self.prev = p;
    }
}

/// The outer corners of a square cap on the cross-section `from -> to`:
/// out by half the width, `(to - from)` turned a quarter counter-clockwise
/// on screen, halved (Q1, then rounded).
pub(super) fn square_cap_corners(from: Pt, to: Pt) -> (Pt, Pt) {
    let d = to.sub(from);
    let ext = Pt::new(div_half(d.y), div_half(-d.x));
    (from.add(ext), to.add(ext))
}

/// `v / 2` rounded half away from zero.
pub(super) fn div_half(v: i64) -> i64 {
    crate::path::trig::round_shift(v, 1)
}

pub(super) fn neg(u: Unit) -> Unit {
    Unit { x: -u.x, y: -u.y }
}

/// True when the path turns right (clockwise on screen) from the unit
/// normal `na` to `nb`, or turns back (a U-turn counts as right): the
/// outer side of the turn is then the `m` side.
pub(super) fn is_right_turn(na: Unit, nb: Unit) -> bool {
    let cross = na.cross(nb);
    cross > 0 || (cross == 0 && na.dot(nb) < 0)
}

/// The tip of a miter join at `v` between the outward unit normals `ua`,
/// `ub`, reaching `h_q1` half fine units: `v + h (ua + ub) / (1 + ua.ub)`,
/// `h = h_q1 / 2`.
pub(super) fn miter_tip(v: Pt, ua: Unit, ub: Unit, h_q1: i64) -> Pt {
    let den = 2 * i128::from(Q30 + ua.dot(ub));
    Pt::new(
        v.x + div_round(mul_i128(ua.x + ub.x, h_q1), den) as i64,
        v.y + div_round(mul_i128(ua.y + ub.y, h_q1), den) as i64,
    )
}

/// The inner corner at `v` of a turn between the unit normals `na`, `nb`,
/// `h_q1` half fine units to the side `side` (+1: the `p` side, -1: `m`):
/// where the two inner offset lines cross,
/// `v + side h (na + nb) / (1 + na.nb)` (the miter formula, well
/// conditioned even at slight turns, unlike intersecting two nearly
/// parallel rounded edges). `None` near a U-turn.
pub(super) fn inner_corner(v: Pt, na: Unit, nb: Unit, h_q1: i64, side: i64) -> Option<Pt> {
    let one_plus = Q30 + na.dot(nb);
    // Beyond about 179 degrees the corner runs off to infinity.
    if one_plus < Q30 >> 14 {
        return None;
    }
    let den = 2 * i128::from(one_plus);
    let k = side * h_q1;
    Some(Pt::new(
        v.x + div_round(mul_i128(na.x + nb.x, k), den) as i64,
        v.y + div_round(mul_i128(na.y + nb.y, k), den) as i64,
    ))
}

/// Moves the end `a1` of the inner edge `a0 -> a1` (the piece before the
/// vertex) and the start `b0` of `b0 -> b1` (after it) to the inner
/// corner `i`, if `i` lies on both edges (within two fine units beyond
/// either end: at a slight turn the kite is no bigger than the grid
/// rounding): the pieces then tile. False otherwise (the kite reaches
/// past a short piece), and nothing moves.
pub(super) fn cut_inner(a0: Pt, a1: &mut Pt, b0: &mut Pt, b1: Pt, i: Option<Pt>) -> bool {
    let Some(i) = i else {
        return false;
    };
    const SLACK: i128 = 2;
    // The parameter of i's projection on an edge, in [-2/len, 1 + 2/len].
    let on = |p0: Pt, p1: Pt| {
        let d = p1.sub(p0);
        let l2 = d.dot(d);
        if l2 == 0 {
            return i == p0;
        }
        let t = i.sub(p0).dot(d); // t / l2 is the parameter
        if 0 <= t && t <= l2 {
            // On the edge itself: within the slack whatever the length.
            return true;
        }
        let len = i128::from(d.len().max(1));
        t * len >= -SLACK * l2 && t * len <= l2 * (len + SLACK)
    };
    if !(on(a0, *a1) && on(*b0, b1)) {
        return false;
    }
    *a1 = i;
    *b0 = i;
    true
}

/// The outline's sink, with the numbers it is given (segments sent and
/// left out) counted, and the set-ups: the stroke's work. (It wraps after
/// 2^32 units, which the stroker's limit stops long before: a solid
/// stroke goes at most a few thousand units past it.)
struct Counted<'s, S: SegmentSink + ?Sized> {
    sink: &'s mut S,
    work: u32,
}

impl<S: SegmentSink + ?Sized> SegmentSink for Counted<'_, S> {
    fn segment(&mut self, from: crate::geom::FinePoint, to: crate::geom::FinePoint) {
        self.work = self.work.wrapping_add(1);
        self.sink.segment(from, to);
    }
    fn window(&self) -> Option<(i32, i32)> {
        self.sink.window()
    }
    fn skipped(&mut self, n: u32) {
        self.work = self.work.wrapping_add(n);
        self.sink.skipped(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::FinePoint;

    /// A sink that keeps nothing (the join's own test reads `one_chord`).
    struct Nothing;
    impl SegmentSink for Nothing {
        fn segment(&mut self, _: FinePoint, _: FinePoint) {}
    }

    /// A round join said to be one chord has an arc of one segment by
    /// the measured turn (`arc_count` of `atan2(cross, dot)`, what `arc`
    /// draws otherwise); and the test is not idle: the small turns of a
    /// flattened curve pass it.
    #[test]
    fn a_round_join_said_to_be_one_chord_has_one_segment() {
        let mut rng = crate::path::testing::Lcg(0x0c40_4d15);
        let mut passed = 0;
        for k in 0..40_000 {
            let h_q1 = match k % 3 {
                0 => 1 + rng.below(64) as i64,
                1 => 1 + rng.below(1 << 14) as i64,
                _ => 1 + rng.below(1 << 23) as i64,
            };
            let tol = Tolerance::new(1 + rng.below(8) as u16);
            let mut sink = Nothing;
            let sides = Sides { m: h_q1, p: h_q1 };
            let mut o = Outline::new(
                &mut sink,
                LineJoin::Round,
                MiterLimit::DEFAULT,
                LineCap::Butt,
                sides,
                tol,
            );
            let a = rng.below(1 << 32) as u32;
            // Turns of a few binary units up to about a degree.
            let bits = 1 + rng.below(24);
            let turn = (rng.below(1 << bits) as u32).max(1);
            let (ua, ub) = (Unit::from_angle(a), Unit::from_angle(a.wrapping_add(turn)));
            let (cross, dot) = (ua.cross(ub), ua.dot(ub));
            if o.one_chord(h_q1, cross, dot) {
                passed += 1;
                let frame = EllipseFrame::with_q8(Pt::new(0, 0), h_q1 << 7, h_q1 << 7, UNIT_X);
                let measured = i64::from(atan2(cross, dot));
                assert_eq!(
                    arc_count(frame.major(), measured, tol),
                    1,
                    "h {h_q1} turn {turn} ({cross}, {dot})"
                );
            }
        }
        assert!(passed > 5_000, "{passed}");
    }

    #[test]
    fn a_rectangle_piece_is_convex_and_its_cut_keeps_the_edges() {
        let s = Sides { m: 2048, p: 2048 };
        let p =
            Piece::straight(Pt::new(0, 0), Pt::new(10240, 0), s).unwrap_or_else(|| unreachable!());
        assert!(p.is_convex());
        assert_eq!((p.sm, p.sp), (Pt::new(0, -1024), Pt::new(0, 1024)));
        let c = p.cut(1024, 2048);
        assert_eq!((c.sm, c.ep), (Pt::new(1024, -1024), Pt::new(2048, 1024)));
        assert_eq!(c.len, 1024);
    }

    #[test]
    fn inner_corners_lie_on_both_edges_or_nowhere() {
        // Right, then down (a right turn): the inner side is below-left.
        let (na, nb) = (Unit { x: 0, y: Q30 }, Unit { x: -Q30, y: 0 });
        let v = Pt::new(1000, 0);
        let i = inner_corner(v, na, nb, 200, 1); // h = 100
        assert_eq!(i, Some(Pt::new(900, 100)));
        let (mut a1, mut b0) = (Pt::new(1000, 100), Pt::new(900, 0));
        assert!(cut_inner(
            Pt::new(0, 100),
            &mut a1,
            &mut b0,
            Pt::new(900, 1000),
            i
        ));
        assert_eq!((a1, b0), (Pt::new(900, 100), Pt::new(900, 100)));
        // The piece before is shorter than the kite: nothing moves.
        let (mut a1, mut b0) = (Pt::new(1000, 100), Pt::new(900, 0));
        assert!(!cut_inner(
            Pt::new(950, 100),
            &mut a1,
            &mut b0,
            Pt::new(900, 1000),
            i
        ));
        assert_eq!(a1, Pt::new(1000, 100));
        // A U-turn has no inner corner.
        assert_eq!(inner_corner(v, na, neg(na), 200, 1), None);
    }
}
