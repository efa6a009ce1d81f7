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

use crate::path::segment::SegmentSink;

use super::outline::{JoinKind, Outline, Piece};
use super::StrokeError;

/// The most pattern intervals (dashes and gaps) stepped through in one
/// contour.
pub const MAX_DASH_INTERVALS: u32 = 1 << 16;

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
}

impl<'d> Dasher<'d> {
    /// `None` for a pattern that changes nothing (see [`Dash::is_solid`]).
    pub fn new(dash: Dash<'d>) -> Option<Self> {
        if dash.is_solid() {
            return None;
        }
        Some(Self {
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
        self.stopped = false;
        self.run_active = false;
    }

    /// True when a contour starts on a dash (a zero-length contour then
    /// gets its dot).
    pub fn starts_on(&mut self) -> bool {
        self.reset();
        self.on
    }

    /// Starts a contour (its first piece follows).
    pub fn begin_contour<S: SegmentSink + ?Sized>(&mut self, out: &mut Outline<'_, S>) {
        self.reset();
        if self.on {
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
        if self.start_dot {
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
        // Each pass consumes the rest of the piece or the rest of an
        // interval (counted in `advance`): bounded.
        while !self.stopped {
            let take = self.rem.min(len - u);
            if self.on && take > 0 {
                out.piece(p.cut(u, u + take), join);
            }
            u += take;
            self.rem -= take;
            if self.rem > 0 {
                break;
            }
            self.advance(&p, u, out);
            if u >= len {
                break;
            }
        }
    }

    /// The interval ended at `u` along `p`: steps to the next interval of
    /// positive length, ending or starting runs (and dots) on the way.
    fn advance<S: SegmentSink + ?Sized>(&mut self, p: &Piece, u: i64, out: &mut Outline<'_, S>) {
        let was_on = self.on;
        let mut k = self.i;
        let mut passed_dash = false;
        // At most one period: the pattern has a positive length.
        for _ in 0..self.count {
            self.steps += 1;
            if self.steps > MAX_DASH_INTERVALS {
                self.stop(out);
                return;
            }
            k = (k + 1) % self.count.max(1);
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
                out.piece(p.cut(u, u), JoinKind::Path);
                out.end_run();
            }
            // Zero-length gaps inside one dash: the run goes on.
            _ => {}
        }
    }

    fn stop<S: SegmentSink + ?Sized>(&mut self, out: &mut Outline<'_, S>) {
        self.stopped = true;
        self.error = Some(StrokeError::TooManyDashes);
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
        let mut s = Dasher::new(d).unwrap_or_else(|| unreachable!());
        assert!(s.starts_on());
        assert_eq!((s.i, s.rem), (2, 25));
        let d = Dash::new(&[10, 20], -5);
        let mut s = Dasher::new(d).unwrap_or_else(|| unreachable!());
        assert!(!s.starts_on());
        assert_eq!((s.i, s.rem), (1, 5));
    }
}
