//! Dashes: cutting a stroke's pieces into runs by a dash pattern.
//!
//! Takes a [`Dash`] (lengths of alternating dashes and gaps in fine units,
//! and an offset into the pattern) and the pieces of one contour in order;
//! gives the outline ([`outline`](super::outline)) its runs: each dash becomes a run of (parts of)
//! pieces with caps at both ends, and joins inside it where it passes a
//! vertex. The pattern restarts at every contour (SVG); an odd-length
//! pattern is repeated twice (SVG); a pattern with no positive gap is a
//! solid line and one with zero total length is ignored (SVG: as `none`).
//!
//! A zero-length dash is a dot: both caps at one point (a disc for round
//! caps, a square along the path for square caps, nothing for butt
//! caps). A zero-length gap does not split the dash around it (two caps
//! would cover the same place twice). On a closed contour, when both the
//! first and the last dash touch the start point, they are one dash
//! joined there (SVG, Skia).
//!
//! ## Bounded work
//!
//! Each step from one pattern interval to the next counts; after
//! [`MAX_DASH_INTERVALS`] in one contour the rest of the contour is not
//! stroked and the stroker reports [`StrokeError::TooManyDashes`]. So a
//! pattern of 1/1024-px dashes along a long path costs at most that many
//! steps per contour.
//!
//! A band needs only the dashes that reach its rows. A dash whose part of
//! the path, widened by the stroke's reach, lies wholly above or below the
//! sink's [`window`](SegmentSink::window) (and within the range square)
//! is *quiet*: its caps, joins and edges are not built, only their
//! segments counted as left out (so every segment keeps its number, which
//! a band's walk cache relies on). A band builds the dashes near it; the
//! others cost their stepping and bookkeeping.
//!
//! And every stroke's dashes are charged against [`MAX_STROKE_WORK`], the
//! same way whether they are built or quiet (so that every band stops at
//! the same dash): one unit per interval stepped and, for each dash, the
//! cost of its two caps plus four (a cap's segments; a
//! round cap's arc twice its segments and its setup, `ARC_SETUP` = 32). Past the budget the rest of the
//! stroke is not stroked and the stroker reports
//! [`StrokeError::TooComplex`]. So a band builds at most about
//! `MAX_STROKE_WORK` segments of dashes, whatever the pattern, width and
//! caps. Butt-capped dashes cost 8 units a period: a stroke has at most
//! about 2 000 of them.

use crate::geom::FINE_LIMIT;
use crate::path::segment::SegmentSink;
use crate::path::vector::Pt;

use super::outline::{JoinKind, Outline, Piece};
use super::StrokeError;

/// The most pattern intervals (dashes and gaps) stepped through in one
/// contour.
pub const MAX_DASH_INTERVALS: u32 = 1 << 16;

/// The most segments one dashed stroke may build, as charged (see
/// "Bounded work" in [`dash`](self)): units of one segment.
pub const MAX_STROKE_WORK: u32 = 1 << 14;

/// A dash pattern: lengths in fine units (1/1024 px) of dash, gap, dash,
/// gap, ... and the distance into the pattern at which each contour
/// starts.
///
/// ```
/// use softedge::path::Dash;
/// let d = Dash::new(&[3072, 1024], 0); // 3 px on, 1 px off
/// assert_eq!(d.period(), 4096);
/// assert_eq!(Dash::new(&[3072], 512).period(), 6144); // odd: repeated twice
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Dash<'d> {
    pattern: &'d [u32],
    offset: i64,
}

impl<'d> Dash<'d> {
    /// A pattern starting `offset` fine units into it (negative offsets
    /// count back from the end, as in SVG).
    pub const fn new(pattern: &'d [u32], offset: i32) -> Self {
        Self {
            pattern,
            offset: offset as i64,
        }
    }

    /// The pattern's lengths.
    pub const fn pattern(&self) -> &'d [u32] {
        self.pattern
    }

    /// The number of intervals in one period (twice the pattern's length
    /// when that is odd).
    fn count(&self) -> usize {
        let n = self.pattern.len();
        if n % 2 == 1 {
            n.saturating_mul(2)
        } else {
            n
        }
    }

    /// The length of interval `i` (`0..count`).
    fn interval(&self, i: usize) -> i64 {
        let n = self.pattern.len();
        if n == 0 {
            return 0;
        }
        i64::from(self.pattern.get(i % n).copied().unwrap_or(0))
    }

    /// The length of one period, in fine units.
    pub fn period(&self) -> u64 {
        let sum: u64 = self.pattern.iter().map(|&v| u64::from(v)).sum();
        if self.pattern.len() % 2 == 1 {
            sum.saturating_mul(2)
        } else {
            sum
        }
    }

    /// True when the pattern changes nothing: no positive gap, or zero
    /// length in all.
    pub(crate) fn is_solid(&self) -> bool {
        let count = self.count();
        self.period() == 0 || !(0..count).any(|i| i % 2 == 1 && self.interval(i) > 0)
    }
}

/// Fine units of slack around a dash's reach when culling it: the
/// area-preserving arcs of round caps put vertices a few units out, plus
/// the grid rounding.
const CULL_SLACK: i64 = 16;

/// True when everything a whole piece of `p` sends (its edges, the caps
/// and joins at its ends, all within `reach` of its corners) lies wholly
/// above or below `window` and inside the range square: the piece can be
/// quiet ([`Piece::quiet`]), solid or dashed, and its joins with its
/// neighbours too. A band of a long or wide curved stroke then computes
/// the arcs of only the joins near it.
pub(crate) fn misses(p: &Piece, window: Option<(i32, i32)>, reach: i64) -> bool {
    let Some((lo, hi)) = window else {
        return false;
    };
    let r = reach.saturating_add(CULL_SLACK);
    let room = i64::from(FINE_LIMIT).saturating_sub(r);
    let corners = [p.sm, p.sp, p.em, p.ep];
    if !corners
        .iter()
        .all(|q| q.x.abs() <= room && q.y.abs() <= room)
    {
        return false;
    }
    let (mut y0, mut y1) = (p.sm.y, p.sm.y);
    for q in corners {
        y0 = y0.min(q.y);
        y1 = y1.max(q.y);
    }
    y1.saturating_add(r) < i64::from(lo) || y0.saturating_sub(r) > i64::from(hi)
}

/// Where along a piece its dashes miss a window: the cross-section of the
/// piece at `u` runs from its `m` edge to its `p` edge (the path's point
/// between them), both edges straight in `u`; the segments of dashes
/// (parts of the piece, their caps, dots) lie within `reach` of the
/// cross-sections they span.
struct Clear {
    /// The two edges' y at the piece's start and end, fine units.
    edges: [(i64, i64); 2],
    len: i64,
    /// The window widened by the reach.
    lo: i64,
    hi: i64,
}

impl Clear {
    /// `None` without a window (nothing can be skipped).
    fn new(p: &Piece, window: Option<(i32, i32)>, reach: i64) -> Option<Self> {
        let (lo, hi) = window?;
        // Quiet pieces' segments must each take one number: everything
        // they send within the range square.
        let room = i64::from(FINE_LIMIT).saturating_sub(reach);
        let ok = |q: Pt| q.x.abs() <= room && q.y.abs() <= room;
        if ![p.sm, p.sp, p.em, p.ep].into_iter().all(ok) {
            return None;
        }
        let c = Self {
            edges: [(p.sm.y, p.em.y), (p.sp.y, p.ep.y)],
            len: p.len.max(1),
            lo: i64::from(lo).saturating_sub(reach),
            hi: i64::from(hi).saturating_add(reach),
        };
        // A piece within the widened window has no cross-section that
        // misses it: nothing to look for.
        let inside = |y: i64| (c.lo..=c.hi).contains(&y);
        let [(a, b), (d, e)] = c.edges;
        if inside(a) && inside(b) && inside(d) && inside(e) {
            return None;
        }
        Some(c)
    }

    /// The furthest `v >= u` such that the cross-sections over `[u, v]`
    /// all lie wholly above the widened window or all wholly below it;
    /// `None` when the one at `u` meets it. Exact: an edge's y at `u` is
    /// `(y0 len + (y1 - y0) u) / len`, compared multiplied out in `i128`.
    fn until(&self, u: i64) -> Option<i64> {
        let len = i128::from(self.len);
        let u128_ = i128::from(u);
        // y(u) * len for each edge.
        let at = |(y0, y1): (i64, i64)| i128::from(y0) * len + i128::from(y1 - y0) * u128_;
        let above = self
            .edges
            .iter()
            .all(|&e| at(e) < i128::from(self.lo) * len);
        let below = self
            .edges
            .iter()
            .all(|&e| at(e) > i128::from(self.hi) * len);
        if !above && !below {
            return None;
        }
        let mut v = i128::from(self.len);
        for &(y0, y1) in &self.edges {
            let d = i128::from(y1) - i128::from(y0);
            // Above: y0 len + d w < lo len while w < (lo - y0) len / d
            // (d > 0); below: y0 len + d w > hi len while
            // w < (y0 - hi) len / (-d) (d < 0). The last whole w before.
            let bound = if above && d > 0 {
                Some(((i128::from(self.lo) - i128::from(y0)) * len, d))
            } else if below && d < 0 {
                Some(((i128::from(y0) - i128::from(self.hi)) * len, -d))
            } else {
                None
            };
            if let Some((num, den)) = bound {
                // Largest w with w * den < num: ceil(num / den) - 1.
                let w = (num + den - 1).div_euclid(den) - 1;
                v = v.min(w);
            }
        }
        Some(v.max(u128_).min(i128::from(self.len)) as i64)
    }
}

/// Walks one contour's pieces through the pattern.
pub(crate) struct Dasher<'d> {
    dash: Dash<'d>,
    count: usize,
    /// The current interval, its remaining length, whether it is a dash.
    i: usize,
    rem: i64,
    on: bool,
    /// A run is open in the outline.
    run_active: bool,
    steps: u32,
    stopped: bool,
    /// A zero-length dash sits exactly at the contour's start.
    start_dot: bool,
    error: Option<StrokeError>,
    /// Work charged so far in the stroke (all contours), segments.
    work: u64,
    /// The charge of one dash: its caps and a body, segments.
    dash_cost: u64,
    /// How far a dash's segments reach beyond its piece, fine units.
    reach: i64,
}

impl<'d> Dasher<'d> {
    /// `None` for a pattern that changes nothing (see [`Dash::is_solid`]).
    /// `dash_cost` is what one dash is charged (segments of its caps and
    /// body); `reach` how far its caps reach beyond its piece (fine units).
    pub fn new(dash: Dash<'d>, dash_cost: u64, reach: i64) -> Option<Self> {
        if dash.is_solid() {
            return None;
        }
        Some(Self {
            work: 0,
            dash_cost,
            reach,
            dash,
            count: dash.count(),
            i: 0,
            rem: 0,
            on: true,
            run_active: false,
            steps: 0,
            stopped: false,
            start_dot: false,
            error: None,
        })
    }

    /// The first error, if the pattern was cut short.
    pub fn error(&self) -> Option<StrokeError> {
        self.error
    }

    /// Sets the phase for a new contour: is the contour's start on a dash?
    fn reset(&mut self) {
        let period = self.dash.period().min(i64::MAX as u64) as i64;
        let mut off = self.dash.offset.rem_euclid(period.max(1));
        self.i = 0;
        self.start_dot = false;
        for i in 0..self.count {
            let len = self.dash.interval(i);
            self.i = i;
            if off < len {
                break;
            }
            self.start_dot |= off == 0 && len == 0 && i % 2 == 0;
            off -= len;
        }
        self.rem = (self.dash.interval(self.i) - off).max(0);
        self.on = self.i % 2 == 0;
        self.steps = 0;
        // Past the budget, the rest of the stroke draws nothing.
        self.stopped = self.error == Some(StrokeError::TooComplex);
        self.run_active = false;
    }

    /// True when a contour starts on a dash (a zero-length contour then
    /// gets its dot).
    pub fn starts_on(&mut self) -> bool {
        self.reset();
        if self.on && !self.stopped {
            self.charge(self.dash_cost);
        }
        self.on && !self.stopped
    }

    /// Charges `units` of work; false (and the stroke stopped) past the
    /// budget.
    fn charge(&mut self, units: u64) -> bool {
        self.work = self.work.saturating_add(units);
        if self.work > u64::from(MAX_STROKE_WORK) {
            self.stopped = true;
            if self.error.is_none() {
                self.error = Some(StrokeError::TooComplex);
            }
            return false;
        }
        true
    }

    /// Starts a contour (its first piece follows).
    pub fn begin_contour<S: SegmentSink + ?Sized>(&mut self, out: &mut Outline<'_, S>) {
        self.reset();
        if self.on && !self.stopped && self.charge(self.dash_cost) {
            out.begin_run(true);
            self.run_active = true;
        }
    }

    /// The next piece of the contour, joined to the one before by `join`.
    pub fn piece<S: SegmentSink + ?Sized>(
        &mut self,
        p: Piece,
        join: JoinKind,
        out: &mut Outline<'_, S>,
    ) {
        if self.start_dot && !self.stopped {
            self.start_dot = false;
            // (When the contour starts on a dash, the dot lies under its cap.)
            if out.draws_dots() && !self.on {
                out.begin_run(false);
                out.piece(p.cut(0, 0), JoinKind::Path);
                out.end_run();
            }
        }
        let len = p.len;
        let mut u = 0i64;
        let clear = Clear::new(&p, out.window(), self.reach.saturating_add(CULL_SLACK));
        // Each pass consumes the rest of the piece or the rest of an
        // interval (counted in `advance`): bounded.
        while !self.stopped {
            let take = self.rem.min(len - u);
            if self.on && take > 0 {
                let mut cut = p.cut(u, u + take);
                cut.quiet = clear
                    .as_ref()
                    .and_then(|c| c.until(u))
                    .is_some_and(|v| v >= u + take);
                out.piece(cut, join);
            }
            u += take;
            self.rem -= take;
            if self.rem > 0 {
                break;
            }
            self.advance(&p, u, clear.as_ref(), out);
            if u >= len {
                break;
            }
        }
    }

    /// The interval ended at `u` along `p`: steps to the next interval of
    /// positive length, ending or starting runs (and dots) on the way.
    fn advance<S: SegmentSink + ?Sized>(
        &mut self,
        p: &Piece,
        u: i64,
        clear: Option<&Clear>,
        out: &mut Outline<'_, S>,
    ) {
        let was_on = self.on;
        let mut k = self.i;
        let mut passed_dash = false;
        // At most one period: the pattern has a positive length.
        for _ in 0..self.count {
            self.steps += 1;
            if self.steps > MAX_DASH_INTERVALS {
                self.stop(StrokeError::TooManyDashes, out);
                return;
            }
            k = (k + 1) % self.count.max(1);
            let cost = if k % 2 == 0 { 1 + self.dash_cost } else { 1 };
            if !self.charge(cost) {
                self.stop(StrokeError::TooComplex, out);
                return;
            }
            let len = self.dash.interval(k);
            if len > 0 {
                break;
            }
            passed_dash |= k % 2 == 0;
        }
        self.i = k;
        self.rem = self.dash.interval(k);
        self.on = k % 2 == 0;
        match (was_on, self.on) {
            (true, false) => {
                out.end_run();
                self.run_active = false;
            }
            (false, true) => {
                out.begin_run(false);
                self.run_active = true;
            }
            (false, false) if passed_dash && out.draws_dots() => {
                // A zero-length dash between two gaps: a dot.
                out.begin_run(false);
                let mut dot = p.cut(u, u);
                dot.quiet = clear.is_some_and(|c| c.until(u).is_some());
                out.piece(dot, JoinKind::Path);
                out.end_run();
            }
            // Zero-length gaps inside one dash: the run goes on.
            _ => {}
        }
    }

    fn stop<S: SegmentSink + ?Sized>(&mut self, e: StrokeError, out: &mut Outline<'_, S>) {
        self.stopped = true;
        if self.error.is_none() {
            self.error = Some(e);
        }
        if self.run_active {
            out.end_run();
            self.run_active = false;
        }
    }

    /// Ends the contour; `closed` joins a dash through the start point.
    pub fn end_contour<S: SegmentSink + ?Sized>(&mut self, closed: bool, out: &mut Outline<'_, S>) {
        let join = closed && self.run_active && !self.stopped;
        out.end_contour(join);
        self.run_active = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solid_patterns_are_recognised() {
        assert!(Dash::new(&[], 0).is_solid());
        assert!(Dash::new(&[0, 0], 0).is_solid());
        assert!(Dash::new(&[10, 0], 5).is_solid());
        assert!(!Dash::new(&[10], 0).is_solid()); // 10 on, 10 off
        assert!(!Dash::new(&[0, 10], 0).is_solid()); // dots
    }

    #[test]
    fn the_phase_starts_inside_the_right_interval() {
        let d = Dash::new(&[10, 20, 30, 40], 35);
        let mut s = Dasher::new(d, 4, 0).unwrap_or_else(|| unreachable!());
        assert!(s.starts_on());
        assert_eq!((s.i, s.rem), (2, 25));
        let d = Dash::new(&[10, 20], -5);
        let mut s = Dasher::new(d, 4, 0).unwrap_or_else(|| unreachable!());
        assert!(!s.starts_on());
        assert_eq!((s.i, s.rem), (1, 5));
    }
}
