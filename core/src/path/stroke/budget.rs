//! What a solid stroke will cost, known from its description before it
//! is built; the tolerance that keeps that within [`MAX_STROKE_WORK`];
//! and the limit past which the stroker stops.
//!
//! Takes a shape's description (through [`PathSink`]) and a stroke style;
//! gives the tolerance to stroke it with: the one asked for, or a coarser
//! one (4, 16, ... times it, at most [`COARSEST`]) when the stroke would
//! otherwise build more than the budget. [`Shape::stroke_with`] strokes
//! so wherever it goes through the [`Stroker`](super::Stroker).
//!
//! ## Why
//!
//! A band builds every piece of a solid stroke (its unit normals and
//! offset points) to know whether it meets the band (but a polyline of
//! more than 16 points plainly within the budget: only its segments near
//! the band, [`windowed`](super::windowed)), and the round parts
//! and curve pieces of a wide stroke are many: a 2000-px ellipse stroked
//! 4 096 px wide is 3 696 pieces, a 250-point zigzag with round joins
//! 139 512 segments, and each band built them all again (9.7 M and 65 M
//! host instructions a band; issue #36 asks at most 10 M for any
//! description of at most 1 KiB). Their number falls as the tolerance
//! grows (as `1/sqrt(tol)`), so the stroke is built at the finest
//! tolerance tried that fits the budget, the same in every band (a
//! function of the description alone). A round part's vertices stand out
//! of their arc by at most 5.4 % of its radius whatever the tolerance (an
//! area-preserving polygon of at least 8 sides a turn), well inside the
//! reach the stroke's bounds allow, so a coarser tolerance never draws
//! outside them (test: `every_point_of_a_shape_lies_in_its_bounds`).
//!
//! ## The count
//!
//! In units of one segment sent (or counted as left out: the same in
//! every band), with a piece's own work (its unit normal, offset points
//! and the test whether it meets the band) [`PIECE_SETUP`] units and an
//! arc's set-up `ARC_SETUP`:
//!
//! - a straight piece: its set-up and two offset edges; one that leaves
//!   the stroker's clipping square, five pieces and their four round
//!   joins;
//! - a join: two segments of inner corner and the outer wedge (bevel 1,
//!   miter 2, round: the arc of a half turn and its set-up);
//! - an open contour's ends: two caps (butt 1, square 3, round twice the
//!   half turn's arc and its set-up, as a dash's cap is charged); a closed
//!   contour's end: a join and two caps; a dot: the whole disc;
//! - a curve of `n` pieces (the stroker's own count at that tolerance):
//!   per piece its set-up, two offset edges, an inner corner and two
//!   segments of join. Chords are joined only where a piece between the
//!   curve's true normals would fold and the chord's rectangle stands in;
//!   on the [`PARTS`] parameter intervals where the curve is nowhere
//!   sharper than the stroke is wide (from its derivative's control
//!   points, exactly) there is none, and beside a sharp interval each
//!   join's arc has one segment per one-segment sweep of its turn and
//!   one more, the turns adding up to twice the curve's turning (a join
//!   turns within the curve's turning over the chords beside it, a Bézier
//!   curve turns no more than its control polygon); where the curve is
//!   no longer than the stroke's width times its turning, the chords'
//!   directions as rounded to the grid stray by more than that, and each
//!   join there is taken as a half turn;
//! - a segment where the stroke may reach beyond the range square counts
//!   as the [`CLAMPED_NUMBERS`] pieces of its clamped image.
//!
//! That is an upper bound of what the stroker sends (test:
//! `the_bound_is_never_below_what_the_stroker_sends`, 3 000 random paths
//! of lines and curves at scales from a pixel to beyond the clipping
//! square, any width, join, cap and tolerance; 60 000 when it was
//! written), found in one pass over the description, without a normal,
//! square root or division per segment (a polyline's
//! [`plainly_within`] answers from its number of points alone).
//!
//! ## The limit
//!
//! The stroker counts the work it does as it goes (segments sent and left
//! out, set-ups) and stops a solid stroke past [`limit`] of its drawing
//! commands so far: twice the budget and [`WORK_PER_COMMAND`] a command,
//! reporting [`StrokeError::TooComplex`](super::StrokeError::TooComplex)
//! (the rest is not stroked; the count is the same in every band, so is
//! where it stops). A stroke fitted to the budget stays within it, and
//! so does any long path of straight segments whose joins and caps are a
//! few segments each (test: `random_solid_strokes_are_fitted_within_the_limit`);
//! it is the guarantee where the count above would not be (none found).
//! A description of at most 1 KiB has at most 512 drawing commands
//! (`h1` is two bytes), so a band builds at most 40 960 units of it. On
//! the host (callgrind, `tests/examples/stroke_work.rs`, one 1-row band
//! of a 16-px frame, less the empty frame) the worst measured is about
//! 225 instructions a unit (the ellipse's curve pieces, most of their
//! segments beyond the range square): 9.2 M for a whole limit. Measured
//! on the worst descriptions found (cases `i` to `m`): at most 5.4 M a band
//! (5.7 M in a 240-px frame).

use crate::geom::{FinePoint, PathSink, FINE_LIMIT};
use crate::path::arc::{full_count, one_segment_sweep};
use crate::path::bezier::{cubic_count, offset_count, quad_count, turn_count};
use crate::path::segment::CLAMPED_NUMBERS;
use crate::path::shape::Shape;
use crate::path::vector::Pt;
use crate::path::Tolerance;

use super::outline::ARC_SETUP;
use super::{legs_turning, LineCap, LineJoin, StrokeStyle, MAX_STROKE_WORK, STROKE_BOX};

/// A piece's own work in segments' worth: its unit normal, four offset
/// points and the test whether it meets the band (measured on the host,
/// callgrind, issue #36: a curve piece of a wide stroke costs about as
/// much as six segments of a round join's arc).
pub(crate) const PIECE_SETUP: u64 = 6;

/// What a drawing command of a solid stroke may cost beyond the budget
/// before the stroker stops ([`limit`]): a straight piece, its join and a
/// share of caps.
pub(crate) const WORK_PER_COMMAND: u32 = 16;

/// The most work a solid stroke of `commands` drawing commands builds
/// (the [`Stroker`](super::Stroker) stops past it and reports
/// [`StrokeError::TooComplex`](super::StrokeError::TooComplex)): twice
/// the budget and [`WORK_PER_COMMAND`] a command. A stroke fitted to the
/// budget stays within it (the fitting's count is an upper bound but for
/// the joins inside curves, which it takes within twice the curve's
/// turning); so does any long path of straight segments with joins and
/// caps of a few segments.
pub(crate) fn limit(commands: u32) -> u32 {
    (2 * MAX_STROKE_WORK).saturating_add(WORK_PER_COMMAND.saturating_mul(commands))
}

/// At least [`arc_count`] of a half turn at radius `r` (fine units) and
/// tolerance `tol`, in 32-bit steps: `arc_count` takes the larger of 4
/// (a segment per eighth of a turn) and `ceil(sqrt(9 pi^2 r / (50
/// tol)))` (`9 pi^2 / 50 < 2`), in 128-bit products and a division that
/// cost a library call each on the Cortex-M0 (test:
/// `the_half_turn_bound_is_at_least_the_arc_count`).
fn half_turn(r: i64, tol: Tolerance) -> u64 {
    let r = r.clamp(0, 1 << 29) as u32;
    let q = 2 * r / u32::from(tol.fine().max(1)) + 2;
    u64::from((crate::arith::isqrt32(q) + 2).clamp(4, crate::path::arc::MAX_ARC_SEGMENTS))
}

/// The coarsest tolerance a stroke is fitted to, fine units (12 px).
pub(crate) const COARSEST: u16 = 12_288;

/// Tolerances tried: the one asked for times `4^k`.
const STEPS: usize = 7;

/// What was counted of one kind of part (within the range square, or
/// reaching beyond it), at each tolerance tried where that matters.
#[derive(Clone, Copy, Default)]
struct Tally {
    /// Straight pieces in the stroker's clipping square, straight
    /// segments that leave it, joins of the style, round joins (of
    /// clipped segments), open ends, closed ends, dots.
    pieces: u32,
    clipped: u32,
    joins: u32,
    round_joins: u32,
    ends: u32,
    closed: u32,
    dots: u32,
    /// Curves' pieces, their joins' arc segments and set-ups, and the
    /// joins of curves shorter than their stroke is wide (a half turn
    /// each), at each tolerance.
    curve_pieces: [u32; STEPS],
    curve_arc_segments: [u32; STEPS],
    curve_arc_setups: [u32; STEPS],
    wide_joins: [u32; STEPS],
}

/// The units of a stroke's description at each tolerance tried (see the
/// module doc), counted as a [`PathSink`].
struct Bound {
    /// The tolerances tried (`tries` of them).
    tols: [Tolerance; STEPS],
    tries: usize,
    /// What lies within the range square by the stroke's reach, and what
    /// may reach beyond it (each of its segments then numbered as up to
    /// [`CLAMPED_NUMBERS`] pieces).
    tally: [Tally; 2],
    style: (LineJoin, LineCap),
    /// Half fine units each side (the stroker's `Sides`).
    sides: (i64, i64),
    start: FinePoint,
    current: FinePoint,
    /// The stroke about the start, and about the current point, may reach
    /// beyond the range square.
    start_far: bool,
    current_far: bool,
    open: bool,
    drawn: bool,
    pieced: bool,
    empty: bool,
    /// How far a point may lie from the origin (each coordinate) for the
    /// stroke about it to stay within the range square: the range less
    /// the stroke's reach.
    room: u32,
    /// [`Bound::sweep`] at each tolerance, 0 until found.
    sweeps: [u64; STEPS],
}

impl Bound {
    fn new(style: &StrokeStyle<'_>, tol: Tolerance) -> Self {
        let s = style.sides();
        let mut tols = [tol; STEPS];
        let mut tries = 1;
        // A round part's vertices stand out of their arc by at most 5.4 %
        // of its radius (an area-preserving polygon of at least 8 sides a
        // turn) and the rounding, well within the width the stroke's
        // bounds allow beyond the round parts (`StrokeStyle::reach`),
        // whatever the tolerance.
        let mut t = u64::from(tol.fine());
        while tries < STEPS && t * 4 <= u64::from(COARSEST) {
            t *= 4;
            tols[tries] = Tolerance::coarse(t as u16);
            tries += 1;
        }
        Self {
            tols,
            tries,
            tally: [Tally::default(); 2],
            style: (style.join, style.cap),
            sides: (s.m, s.p),
            start: FinePoint::new(0, 0),
            current: FinePoint::new(0, 0),
            start_far: false,
            current_far: false,
            open: false,
            drawn: false,
            pieced: false,
            empty: s.width() == 0,
            room: i64::from(FINE_LIMIT).saturating_sub(style.reach()).max(0) as u32,
            sweeps: [0; STEPS],
        }
    }

    /// The join's arc radius (the wider side), fine units, rounded up.
    fn join_radius(&self) -> i64 {
        (self.sides.0.max(self.sides.1) + 1) / 2 + 1
    }

    /// The cap's radius: half the width, fine units, rounded up.
    fn cap_radius(&self) -> i64 {
        (self.sides.0 + self.sides.1 + 3) / 4 + 1
    }

    /// The units at tolerance `k`; without the set-ups' (`setups`
    /// false), the segments alone.
    fn units(&self, k: usize, setups: bool) -> u64 {
        let k = k.min(STEPS - 1);
        let tol = self.tols[k];
        // Arcs only where there are any (their counts cost 128-bit
        // products: a library call on the Cortex-M0).
        let any = |f: &dyn Fn(&Tally) -> u32| self.tally.iter().any(|t| f(t) > 0);
        let round_joins = (self.style.0 == LineJoin::Round && any(&|t| t.joins | t.closed))
            || any(&|t| t.round_joins | t.clipped | t.wide_joins[k]);
        let round_caps = self.style.1 == LineCap::Round && any(&|t| t.ends | t.closed);
        let dots = self.style.1 == LineCap::Round && any(&|t| t.dots);
        // (segments, set-up units) of each thing counted.
        let round_join = if round_joins {
            (2 + half_turn(self.join_radius(), tol), ARC_SETUP)
        } else {
            (0, 0)
        };
        let join = match self.style.0 {
            LineJoin::Bevel => (3, 0),
            LineJoin::Miter => (4, 0),
            LineJoin::Round => round_join,
        };
        let cap = match self.style.1 {
            LineCap::Butt => (1, 0),
            LineCap::Square => (3, 0),
            LineCap::Round if round_caps => (2 * half_turn(self.cap_radius(), tol), ARC_SETUP),
            LineCap::Round => (0, 0),
        };
        let dot = match self.style.1 {
            LineCap::Butt => (0, 0),
            LineCap::Square => (4, 0),
            LineCap::Round if dots => (u64::from(full_count(self.cap_radius(), tol)), ARC_SETUP),
            LineCap::Round => (0, 0),
        };
        let piece = (2, PIECE_SETUP);
        let add = |a: (u64, u64), b: (u64, u64)| (a.0 + b.0, a.1 + b.1);
        let times = |n: u64, a: (u64, u64)| (n * a.0, n * a.1);
        let clipped = add(times(5, piece), times(4, round_join));
        // In 32 bits (the Cortex-M0 multiplies 64-bit numbers by a library
        // call): a count of 2^16 or more is past any budget (every thing
        // counted is at least a unit), each unit cost is below 2^14.
        const BIG: u32 = 1 << 16;
        let mut total = 0u32;
        for (far, t) in self.tally.iter().enumerate() {
            let counted = [
                (t.pieces, piece),
                (t.clipped, clipped),
                (t.joins, join),
                (t.round_joins, round_join),
                (t.ends, times(2, cap)),
                (t.closed, add(join, times(2, cap))),
                (t.dots, dot),
                (t.curve_pieces[k], (6, PIECE_SETUP)),
                (t.curve_arc_segments[k], (1, 0)),
                (t.curve_arc_setups[k], (0, ARC_SETUP)),
                (t.wide_joins[k], round_join),
            ];
            let (mut segments, mut setup) = (0u32, 0u32);
            for &(n, (cs, cu)) in &counted {
                if n >= BIG {
                    return u64::MAX;
                }
                segments = segments.saturating_add(n * cs as u32);
                setup = setup.saturating_add(n * cu as u32);
            }
            // A segment beyond the range square is sent as the pieces of
            // its clamped image, numbered each.
            let numbers = if far == 1 { CLAMPED_NUMBERS } else { 1 };
            total = total.saturating_add(segments.saturating_mul(numbers));
            if setups {
                total = total.saturating_add(setup);
            }
        }
        u64::from(total)
    }

    /// The finest tolerance tried whose units fit the budget, else the
    /// coarsest tried.
    fn choose(&self) -> Tolerance {
        let last = self.tries.clamp(1, STEPS) - 1;
        (0..last)
            .find(|&k| self.units(k, true) <= u64::from(MAX_STROKE_WORK))
            .map_or(self.tols[last], |k| self.tols[k.min(last)])
    }

    /// True when the stroke about `p` may reach beyond the range square
    /// (its parts are then counted in the second tally).
    fn far(&self, p: FinePoint) -> bool {
        p.x.unsigned_abs() > self.room || p.y.unsigned_abs() > self.room
    }

    fn begin_drawing(&mut self) {
        if !self.open {
            self.start = self.current;
            self.start_far = self.current_far;
            self.open = true;
        }
        self.drawn = true;
    }

    /// A join at the current point before the next piece, if the contour
    /// has one already.
    fn join_before(&mut self) {
        if self.pieced {
            let t = &mut self.tally[usize::from(self.current_far)];
            t.joins = t.joins.saturating_add(1);
        }
        self.pieced = true;
    }

    /// A straight segment from the current point to `b` (which becomes
    /// the current point).
    fn straight(&mut self, b: FinePoint) {
        let a = self.current;
        if a == b {
            return;
        }
        self.join_before();
        let b_far = self.far(b);
        let t = &mut self.tally[usize::from(self.current_far || b_far)];
        if inside(a) && inside(b) {
            t.pieces = t.pieces.saturating_add(1);
        } else {
            t.clipped = t.clipped.saturating_add(1);
        }
        self.current = b;
        self.current_far = b_far;
    }

    /// A curve from the current point through control points `c` (the
    /// last its end, which becomes the current point).
    fn curve(&mut self, c: &[FinePoint]) {
        let Some(&end) = c.last() else {
            return;
        };
        self.join_before();
        let mut q = [Pt::default(); 4];
        q[0] = self.current.into();
        for (slot, &p) in q[1..].iter_mut().zip(c) {
            *slot = p.into();
        }
        let q = &q[..=c.len()];
        let legs = [
            q[1].sub(q[0]),
            q[2].sub(q[1]),
            q.get(3).map_or(Pt::default(), |p| p.sub(q[2])),
        ];
        let turn = legs_turning(&legs[..c.len()]);
        let f = usize::from(self.current_far || c.iter().any(|&p| self.far(p)));
        self.current = end;
        self.current_far = self.far(end);
        if !c.iter().all(|&p| inside(p)) || !inside(self.current) {
            // Its chords go through the clipping, each a straight
            // segment that may leave the square: at most the count at
            // the asked tolerance (the finest) of them.
            let n = self.count(q, turn, 0);
            let t = &mut self.tally[f];
            t.clipped = t.clipped.saturating_add(n);
            t.round_joins = t.round_joins.saturating_add(n);
            return;
        }
        // Joins between its chords: none on a part where it bends
        // gently beside the stroke's width and the chords
        // ([`Bends::sharp`]), so only about the pieces of its sharp parts.
        // On a curve no longer than the stroke's width times its turning
        // (its length is at most three times its longest leg) the chords
        // are short beside the width, their directions as rounded to the
        // grid stray by more than its turning, and each such join is taken
        // as a half turn; otherwise the joins turn by twice the curve's
        // turning in all.
        let h = (self.sides.0.max(self.sides.1) + 1) / 2;
        let bends = Bends::of(q);
        let longest = q
            .windows(2)
            .map(|w| w[1].sub(w[0]))
            .map(|d| d.x.unsigned_abs() + d.y.unsigned_abs())
            .max()
            .unwrap_or(0);
        let wide = (3 * u128::from(longest)) << 32 < u128::from(turn) * 7 * h.max(0) as u128;
        for k in 0..self.tries.min(STEPS) {
            let n32 = self.count(q, turn, k);
            let sharp = u64::from(bends.sharp(h, n32));
            let t = &mut self.tally[f];
            t.curve_pieces[k] = t.curve_pieces[k].saturating_add(n32);
            if sharp == 0 {
                continue;
            }
            let n = u64::from(n32);
            // Joins beside a sharp part's pieces.
            let joins = (sharp * (n.div_ceil(PARTS as u64) + 2)).min(n + 1);
            let joins = joins.min(u64::from(u32::MAX)) as u32;
            if wide {
                let t = &mut self.tally[f];
                t.wide_joins[k] = t.wide_joins[k].saturating_add(joins);
                continue;
            }
            // The joins' turns add up to at most `x` (twice the turning,
            // and the integer atan2's slack at each join, 16 binary units
            // twice over); a join's arc has a segment per `s1` (the
            // one-segment sweep, halved for the one-chord test's slack) of
            // its turn and one more, and a set-up unless it is one chord.
            let x = turn.saturating_mul(2).saturating_add(n * 64);
            let arcs = (x / self.sweep(k)).min(u64::from(u32::MAX)) as u32;
            let t = &mut self.tally[f];
            t.curve_arc_segments[k] =
                t.curve_arc_segments[k].saturating_add(joins.saturating_add(arcs));
            t.curve_arc_setups[k] = t.curve_arc_setups[k].saturating_add(joins.min(arcs));
        }
    }

    /// Half the one-segment sweep of a join's arc at tolerance `k`
    /// (found once).
    fn sweep(&mut self, k: usize) -> u64 {
        let k = k.min(STEPS - 1);
        if self.sweeps[k] == 0 {
            self.sweeps[k] =
                (one_segment_sweep(self.join_radius(), self.tols[k]).max(2) / 2) as u64;
        }
        self.sweeps[k]
    }

    /// The stroker's piece count for curve `q` at tolerance `k`.
    fn count(&self, q: &[Pt], turn: u64, k: usize) -> u32 {
        let tol = i64::from(self.tols[k.min(STEPS - 1)].fine());
        let h = self.sides.0.max(self.sides.1) / 2;
        let c = match q {
            [a, b, c] => quad_count(&[*a, *b, *c], tol),
            [a, b, c, d] => cubic_count(&[*a, *b, *c, *d], tol),
            _ => 1,
        };
        offset_count(c, turn_count(turn, h, tol))
    }

    fn end_contour(&mut self, closed: bool) {
        if !self.open {
            return;
        }
        self.open = false;
        let t = &mut self.tally[usize::from(self.start_far || self.current_far)];
        if self.pieced {
            if closed {
                t.closed = t.closed.saturating_add(1);
            } else {
                t.ends = t.ends.saturating_add(1);
            }
        } else if self.drawn {
            t.dots = t.dots.saturating_add(1);
        }
        self.pieced = false;
        self.drawn = false;
    }
}

/// Parts of a curve tested for sharp bends: equal parameter intervals.
const PARTS: i64 = 8;

/// For each of the [`PARTS`] equal parameter intervals of curve `q` (a
/// quadratic or a cubic Bézier): lower bounds of its squared speed and of
/// its speed, and an upper bound of its acceleration there, all scaled
/// (see [`Bends::of`]); `None` for a part whose speed may vanish.
struct Bends {
    parts: [Option<(u128, u128, u128)>; PARTS as usize],
    /// The speed is scaled by `m^d`, the acceleration by `m^(d - 1)`
    /// (`m` = [`PARTS`], `d` the curve's degree - 1: 1 or 2).
    cubic: bool,
}

impl Bends {
    /// `|B'|` is at least the distance from the origin to the hull of the
    /// derivative's control points on the interval (the derivative is a
    /// Bézier curve of one degree less, restricted to the interval by its
    /// blossom), `|B''|` at most its larger end (a constant or a line).
    /// Exact integers, rounded the safe way.
    fn of(q: &[Pt]) -> Bends {
        let m = PARTS;
        let scale = |v: Pt, k: i64| Pt::new(k * v.x, k * v.y);
        let sum = |terms: &[(Pt, i64)]| {
            terms
                .iter()
                .fold(Pt::new(0, 0), |acc, &(v, k)| acc.add(scale(v, k)))
        };
        let mut parts = [None; PARTS as usize];
        let cubic = q.len() == 4;
        for (i, part) in (0..m).zip(parts.iter_mut()) {
            let j = i + 1;
            *part = match *q {
                [a, b, c] => {
                    // B' = D0 (1 - t) + D1 t, times m on the interval;
                    // B'' = D1 - D0.
                    let (d0, d1) = (scale(b.sub(a), 2), scale(c.sub(b), 2));
                    let hull = [sum(&[(d0, m - i), (d1, i)]), sum(&[(d0, m - j), (d1, j)])];
                    let acc = d1.sub(d0).len() as u128 + 1;
                    speed2(&hull).map(|s2| (s2, s2.isqrt(), acc))
                }
                [a, b, c, d] => {
                    // B' a quadratic Bézier of D0, D1, D2; on the interval
                    // its controls times m^2 are its blossoms at (i/m,
                    // i/m), (i/m, j/m), (j/m, j/m); m B'' is linear from
                    // 2 ((D1 - D0) (m - i) + (D2 - D1) i).
                    let (d0, d1, d2) = (scale(b.sub(a), 3), scale(c.sub(b), 3), scale(d.sub(c), 3));
                    let blossom = |u: i64, v: i64| {
                        sum(&[
                            (d0, (m - u) * (m - v)),
                            (d1, (m - u) * v + u * (m - v)),
                            (d2, u * v),
                        ])
                    };
                    let hull = [blossom(i, i), blossom(i, j), blossom(j, j)];
                    let second = |u: i64| scale(sum(&[(d1.sub(d0), m - u), (d2.sub(d1), u)]), 2);
                    let acc = second(i).len().max(second(j).len()) as u128 + 1;
                    speed2(&hull).map(|s2| (s2, s2.isqrt(), acc))
                }
                _ => None,
            };
        }
        Bends { parts, cubic }
    }

    /// How many parts may give the stroker a join between chords when the
    /// curve is cut into `n` chords and stroked with reach `h` (fine
    /// units) each side. A chord's piece lies between the curve's true
    /// normals at its ends, and the next starts on the same normal (no
    /// join), wherever it is convex and its chord runs with the tangents:
    /// where the radius of curvature `|B'|^3 / |B' x B''| >= |B'|^2 /
    /// |B''|` is at least `2 h`, the chord turns by at most `|B''| / (|B'|
    /// n) <= 3/4` radian (43 degrees), and the piece is large beside the
    /// grid's rounding (its chord at least 32 cos 43° > 16 fine units long,
    /// `h` at least 8).
    fn sharp(&self, h: i64, n: u32) -> u32 {
        let m = PARTS as u128;
        let (n, h) = (u128::from(n), h.max(0) as u128);
        self.parts
            .iter()
            .filter(|part| {
                let Some((s2, s, acc)) = **part else {
                    return true;
                };
                // Speed times m^d, acceleration times m^(d - 1).
                let (sm, am) = if self.cubic { (m * m, m) } else { (m, 1) };
                // |B'|^2 >= 2 h |B''|; |B''| / |B'| <= 3 n / 4; |B'| / n >= 32.
                let round = s2 >= (2 * h * acc * sm * sm).div_ceil(am);
                let turn = 4 * acc * sm <= 3 * n * s * am;
                let long = s >= 32 * n * sm;
                !(h >= 8 && round && turn && long)
            })
            .count() as u32
    }
}

/// The squared distance from the origin to the hull of `pts` (a segment
/// or a triangle), floored; `None` when the origin lies in it.
fn speed2<const N: usize>(pts: &[Pt; N]) -> Option<u128> {
    if N == 3 {
        let signs = (0..N)
            .map(|k| pts[k].cross(pts[(k + 1) % N]).signum())
            .fold(0u8, |m, s| {
                m | if s > 0 {
                    1
                } else if s < 0 {
                    2
                } else {
                    0
                }
            });
        // The origin inside (or on the edge of) a triangle with area.
        if signs != 3 && signs != 0 {
            return None;
        }
    }
    let d2 = (0..N)
        .map(|k| {
            let (a, b) = (pts[k], pts[(k + 1) % N]);
            let ab = b.sub(a);
            let len2 = ab.dot(ab).unsigned_abs();
            let t = -a.dot(ab);
            if len2 == 0 || t <= 0 {
                a.dot(a).unsigned_abs()
            } else if t as u128 >= len2 {
                b.dot(b).unsigned_abs()
            } else {
                // |a x b| / |ab|, floored (the square root rounded up).
                let d = a.cross(b).unsigned_abs() / (len2.isqrt() + 1);
                d * d
            }
        })
        .min()
        .unwrap_or(0);
    (d2 > 0).then_some(d2)
}

/// True when `p` lies in the stroker's clipping square.
fn inside(p: FinePoint) -> bool {
    i64::from(p.x.unsigned_abs()) <= STROKE_BOX && i64::from(p.y.unsigned_abs()) <= STROKE_BOX
}

impl PathSink for Bound {
    fn move_to(&mut self, p: FinePoint) {
        self.end_contour(false);
        self.start = p;
        self.current = p;
        self.start_far = self.far(p);
        self.current_far = self.start_far;
        self.open = !self.empty;
        self.drawn = false;
    }

    fn line_to(&mut self, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        self.straight(p);
    }

    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        self.curve(&[c, p]);
    }

    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        if self.empty {
            return;
        }
        self.begin_drawing();
        self.curve(&[c1, c2, p]);
    }

    fn close(&mut self) {
        if self.empty || !self.open {
            return;
        }
        self.drawn = true;
        self.straight(self.start);
        self.end_contour(true);
    }
}

/// True when a path of `commands` straight drawing commands stroked in
/// `style` is within the budget at `tol` whatever its points: each a
/// piece and a join, as if reaching beyond the range square, and each
/// its own contour's caps. (A polyline's quick answer, without a pass
/// over its points.)
pub(crate) fn plainly_within(style: &StrokeStyle<'_>, tol: Tolerance, commands: usize) -> bool {
    let (segments, setups) = per_command(style, tol);
    let each = segments + setups;
    let n = commands.min(u32::MAX as usize) as u32;
    // Both below 2^16: the product in 32 bits.
    each <= u64::from(MAX_STROKE_WORK) && n < 1 << 16 && n * (each as u32) <= MAX_STROKE_WORK
}

/// The most segment numbers a straight drawing command of a solid stroke
/// in `style` at `tol` takes (its piece's two offset edges, a join, and
/// as if it were a contour of its own two caps, each segment beyond the
/// range square: [`CLAMPED_NUMBERS`]); at most `2^16` when
/// [`plainly_within`] holds.
pub(crate) fn numbers_per_command(style: &StrokeStyle<'_>, tol: Tolerance) -> u32 {
    per_command(style, tol).0.min(u64::from(u32::MAX)) as u32
}

/// [`Bound::units`] of one straight drawing command as a piece, a join
/// and an open contour's two ends beyond the range square, without the
/// tallies: its segment numbers, and its set-ups.
fn per_command(style: &StrokeStyle<'_>, tol: Tolerance) -> (u64, u64) {
    let s = style.sides();
    let join_r = (s.m.max(s.p) + 1) / 2 + 1;
    let cap_r = (s.m + s.p + 3) / 4 + 1;
    let (join, join_setup) = match style.join {
        LineJoin::Bevel => (3, 0),
        LineJoin::Miter => (4, 0),
        LineJoin::Round => (2 + half_turn(join_r, tol), ARC_SETUP),
    };
    let (cap, cap_setup) = match style.cap {
        LineCap::Butt => (1, 0),
        LineCap::Square => (3, 0),
        LineCap::Round => (2 * half_turn(cap_r, tol), ARC_SETUP),
    };
    let segments = (2 + join + 2 * cap) * u64::from(CLAMPED_NUMBERS);
    (segments, PIECE_SETUP + join_setup + 2 * cap_setup)
}

/// The tolerance to stroke `shape` with in `style` when `tol` is asked
/// for: `tol` if the stroke's units there are within [`MAX_STROKE_WORK`],
/// else the finest of `4 tol`, `16 tol`, ... (at most [`COARSEST`])
/// whose units are, else the coarsest of those.
pub(crate) fn fitted<S: Shape + ?Sized>(
    shape: &S,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
) -> Tolerance {
    let mut b = Bound::new(style, tol);
    if b.tries == 1 {
        return tol;
    }
    shape.describe(&mut b);
    b.end_contour(false);
    b.choose()
}

/// The bound at `tol` (no coarser one): its units, with the set-ups or
/// (`setups` false) the segments alone.
#[cfg(test)]
fn units<S: Shape + ?Sized>(
    shape: &S,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    setups: bool,
) -> u64 {
    let mut b = Bound::new(style, tol);
    b.tries = 1;
    shape.describe(&mut b);
    b.end_contour(false);
    b.units(0, setups)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::path::arc::arc_count;
    use crate::path::segment::SegmentSink;
    use crate::path::testing::Lcg;
    use crate::path::trig::HALF_TURN;
    use crate::path::{Ellipse, Polyline};

    /// A path given command by command.
    #[derive(Debug, Clone)]
    enum Cmd {
        Move(FinePoint),
        Line(FinePoint),
        Quad(FinePoint, FinePoint),
        Cubic(FinePoint, FinePoint, FinePoint),
        Close,
    }

    struct Script(Vec<Cmd>);

    impl Shape for Script {
        fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
            for c in &self.0 {
                match *c {
                    Cmd::Move(p) => sink.move_to(p),
                    Cmd::Line(p) => sink.line_to(p),
                    Cmd::Quad(c, p) => sink.quad_to(c, p),
                    Cmd::Cubic(a, b, p) => sink.cubic_to(a, b, p),
                    Cmd::Close => sink.close(),
                }
            }
        }
    }

    /// Every number the stroker gives out: segments sent and left out.
    #[derive(Default)]
    struct Numbers(u64);

    impl SegmentSink for Numbers {
        fn segment(&mut self, _: FinePoint, _: FinePoint) {
            self.0 += 1;
        }
        fn skipped(&mut self, n: u32) {
            self.0 += u64::from(n);
        }
    }

    /// A random path of up to three contours at a scale from a pixel to
    /// the whole coordinate range, or (`beyond`) sometimes far beyond the
    /// stroker's clipping square.
    fn random_script(rng: &mut Lcg, beyond: bool) -> Script {
        let mut next = |m: u64| rng.below(m) as i64;
        let mut cmds = Vec::new();
        let scales = [1 << 10, 1 << 14, 1 << 18, 1 << 21, 1 << 26];
        let scale = scales[next(if beyond { 5 } else { 4 }) as usize];
        let pt = |next: &mut dyn FnMut(u64) -> i64| {
            FinePoint::new(
                (next(2 * scale as u64) - scale) as i32,
                (next(2 * scale as u64) - scale) as i32,
            )
        };
        for _ in 0..1 + next(3) {
            cmds.push(Cmd::Move(pt(&mut next)));
            for _ in 0..next(9) {
                cmds.push(match next(4) {
                    0 => Cmd::Line(pt(&mut next)),
                    1 => Cmd::Quad(pt(&mut next), pt(&mut next)),
                    _ => Cmd::Cubic(pt(&mut next), pt(&mut next), pt(&mut next)),
                });
            }
            if next(2) == 0 {
                cmds.push(Cmd::Close);
            }
        }
        Script(cmds)
    }

    fn random_style(rng: &mut Lcg) -> StrokeStyle<'static> {
        let w = (rng.below(1 << 22) as u32 >> rng.below(20)).max(1);
        let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][rng.below(3) as usize];
        let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][rng.below(3) as usize];
        StrokeStyle::new(w).with_join(join).with_cap(cap)
    }

    #[test]
    fn the_bound_is_never_below_what_the_stroker_sends() {
        let mut rng = Lcg(0x5eed_b0d9_e7a1_1c0d);
        let tols = [3u16, 12, 48, 768, 12_288];
        let mut tightest = f64::MAX;
        for case in 0..3000 {
            let script = random_script(&mut rng, true);
            let style = random_style(&mut rng);
            let tol = Tolerance::coarse(tols[rng.below(tols.len() as u64) as usize]);
            // The stroker itself at `tol` (a shape's `stroke_with` would
            // fit the tolerance first), never stopped: its whole work,
            // segments and set-ups.
            let mut sent = Numbers::default();
            let mut s = super::super::Stroker::with_tolerance(&style, tol, &mut sent);
            s.limit = u32::MAX;
            script.describe(&mut s);
            let work = u64::from(s.outline.work());
            assert_eq!(s.finish(), Ok(()));
            let bound = units(&script, &style, tol, false);
            assert!(
                bound >= sent.0,
                "case {case}: bound {bound} < {} sent; {style:?} {tol:?} {:?}",
                sent.0,
                script.0
            );
            let with_setups = units(&script, &style, tol, true);
            assert!(
                with_setups >= work,
                "case {case}: bound {with_setups} < work {work}; {style:?} {tol:?} {:?}",
                script.0
            );
            if sent.0 > 100 {
                tightest = tightest.min(bound as f64 / sent.0 as f64);
            }
        }
        // Not so loose that it says nothing.
        assert!(tightest < 3.0, "bound / sent at best {tightest}");
    }

    #[test]
    fn a_stroke_past_its_budget_is_fitted_to_it_and_others_keep_their_tolerance() {
        let tol = Tolerance::DEFAULT;
        // Issue #36's widest strokes: fitted, within the budget.
        let ellipse = Ellipse::new(FinePoint::new(0, 0), 2000 * 1024, 1900 * 1024);
        let wide = StrokeStyle::new(4096 * 1024);
        let zig: Vec<FinePoint> = (0..250)
            .map(|i| FinePoint::new((i % 2) * 9 * 1024, i * 8 * 1024))
            .collect();
        let zigzag = Polyline::new(&zig);
        let round = wide.with_join(LineJoin::Round);
        fn past<S: Shape>(shape: &S, style: &StrokeStyle<'_>) -> Tolerance {
            let (budget, tol) = (u64::from(MAX_STROKE_WORK), Tolerance::DEFAULT);
            assert!(units(shape, style, tol, true) > budget);
            let fit = fitted(shape, style, tol);
            assert!(fit.fine() > tol.fine());
            // The finest that fits: a quarter of it does not.
            let finer = Tolerance::coarse(fit.fine() / 4);
            assert!(units(shape, style, finer, true) > budget, "{fit:?}");
            // And drawn whole at it.
            assert_eq!(
                shape.stroke_with(style, fit, &mut Numbers::default()),
                Ok(())
            );
            fit
        }
        let fit = past(&ellipse, &wide);
        assert!(units(&ellipse, &wide, fit, true) <= u64::from(MAX_STROKE_WORK));
        // The zigzag's round joins reach beyond the range square (each
        // segment there counted as its clamped pieces): past the budget
        // even at the coarsest tolerance, within the stroker's limit.
        assert_eq!(past(&zigzag, &round).fine(), COARSEST);
        // A chart, a gauge's ellipse and an S-curve across the screen,
        // 3 px or 20 px wide with round joins and caps: as asked.
        let chart: Vec<FinePoint> = (0..60)
            .map(|i| FinePoint::new(i * 4 * 1024, ((i * 37) % 50) * 1024))
            .collect();
        let chart = Polyline::new(&chart);
        let thick = StrokeStyle::new(20 * 1024)
            .with_join(LineJoin::Round)
            .with_cap(LineCap::Round);
        let gauge = Ellipse::new(FinePoint::new(120 * 1024, 120 * 1024), 90 * 1024, 80 * 1024);
        let px = |x: i32, y: i32| FinePoint::new(x * 1024, y * 1024);
        let s = Script(std::vec![
            Cmd::Move(px(10, 120)),
            Cmd::Cubic(px(90, -60), px(150, 300), px(230, 120)),
        ]);
        for style in [StrokeStyle::new(3 * 1024), thick] {
            assert_eq!(fitted(&chart, &style, tol), tol, "chart {style:?}");
            assert_eq!(fitted(&gauge, &style, tol), tol, "gauge {style:?}");
            assert_eq!(fitted(&s, &style, tol), tol, "S {style:?}");
        }
    }

    #[test]
    fn a_solid_stroke_stops_at_its_work_limit_and_says_so() {
        // The zigzag of 250 round joins 4 096 px wide at the default
        // tolerance (not fitted): its joins alone are some 140 000
        // segments; the stroker stops within its limit, plus the arc it
        // was building and the caps of the contour it ends.
        let zig: Vec<FinePoint> = (0..250)
            .map(|i| FinePoint::new((i % 2) * 9 * 1024, i * 8 * 1024))
            .collect();
        let style = StrokeStyle::new(4096 * 1024).with_join(LineJoin::Round);
        let mut sent = Numbers::default();
        let mut s = super::super::Stroker::new(&style, &mut sent);
        Polyline::new(&zig).describe(&mut s);
        let (work, at) = (s.outline.work(), s.limit);
        assert_eq!(s.finish(), Err(super::super::StrokeError::TooComplex));
        // Its limit: 249 drawing commands.
        assert_eq!(at, limit(249));
        let round = arc_count(2 << 20, HALF_TURN, Tolerance::DEFAULT);
        let overshoot = 2 * (CLAMPED_NUMBERS * round + ARC_SETUP as u32 + 16);
        assert!(work <= at + overshoot && work > limit(0), "{work} {at}");
        // Fitted, the same zigzag is drawn whole.
        let fit = fitted(&Polyline::new(&zig), &style, Tolerance::DEFAULT);
        let mut whole = Numbers::default();
        assert_eq!(
            Polyline::new(&zig).stroke_with(&style, fit, &mut whole),
            Ok(())
        );
    }

    #[test]
    fn random_solid_strokes_are_fitted_within_the_limit() {
        // Wide and thin, curved and straight, within the coordinate range
        // (a canvas rejects paths beyond it): fitted, none is stopped, and
        // none builds more than its limit.
        let mut rng = Lcg(0x0b0d_9e75_11e1_7a11);
        for case in 0..1500 {
            let script = random_script(&mut rng, false);
            let style = random_style(&mut rng);
            let fit = fitted(&script, &style, Tolerance::DEFAULT);
            let mut sent = Numbers::default();
            let mut s = super::super::Stroker::with_tolerance(&style, fit, &mut sent);
            script.describe(&mut s);
            let (work, at) = (s.outline.work(), s.limit);
            assert_eq!(
                s.finish(),
                Ok(()),
                "case {case}: {style:?} {fit:?} {:?}",
                script.0
            );
            assert!(work <= at, "case {case}");
        }
    }

    #[test]
    fn the_half_turn_bound_is_at_least_the_arc_count() {
        let mut rng = Lcg(0x4a1f_7e11_5e6e_0b0d);
        for _ in 0..200_000 {
            let r = 1 + (rng.below(1 << 23) >> rng.below(23)) as i64;
            let tol = Tolerance::coarse(1 + (rng.below(1 << 14) >> rng.below(14)) as u16);
            let (b, a) = (half_turn(r, tol), u64::from(arc_count(r, HALF_TURN, tol)));
            assert!(b >= a, "r {r} {tol:?}: {b} < {a}");
            assert!(b <= a + a / 8 + 3, "r {r} {tol:?}: {b} for {a}");
        }
    }
}
