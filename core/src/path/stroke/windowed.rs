//! A polyline's stroke built only where it meets a band.
//!
//! Takes a polyline (its points by index), a solid stroke style and a
//! sink with a window (a band's rows); gives the sink, for the window's
//! rows, exactly the segments of the whole stroke, having built only the
//! pieces and joins near the window.
//!
//! ## Why
//!
//! A band of a line chart meets a few of its segments, but the stroke of
//! the whole line builds every piece (a unit normal: a square root and two
//! divisions; its offset points) and every join in every band: on the
//! Cortex-M0 two thirds of a 60-point chart's frame.
//!
//! ## Method
//!
//! Each run of consecutive segments whose rows, widened by the stroke's
//! reach, meet the window is stroked as a polyline of its own, from some
//! segments before it to one segment of length after it:
//!
//! - A join sees the piece after it as it is built (its far end not yet
//!   cut by the next join), so one segment of length after the run makes
//!   the run's last join the whole stroke's. The caps at the new ends,
//!   and the pieces of the segments outside the run, lie beyond the
//!   reach: outside the window.
//! - A join sees the piece before it as the join before that left it: a
//!   turn cuts both pieces' inner sides at the inner corner where it can
//!   (`outline::cut_inner`), and whether the next turn to the same side
//!   can cut depends on where that cut left the piece's start. So the
//!   stroke starts one segment of length before the run and goes further
//!   back while the turn at its start is to the same side as the turn at
//!   its end (the stroker's own test on its own unit normals): where the
//!   turns alternate (or the line goes straight on), the run's first join
//!   sees what the whole stroke's does.
//!
//! Runs closer than that are stroked as one. Test:
//! `a_windowed_stroke_sends_the_window_the_whole_strokes_segments`
//! (`path::shape::polyline`), the segments reaching into the window
//! compared with the whole stroke's.
//!
//! ## When
//!
//! Only where nothing else depends on the whole line: a solid stroke
//! (dashes run along the whole line) of more than
//! [`MAX_UNION_POINTS`] points (no union treatment), plainly within its
//! work budget (neither stroke stops short), every point inside the
//! stroker's clipping square (no segment is cut there).
//!
//! ## Numbers
//!
//! A band's cached walks are found by their segment numbers, so a segment
//! takes the same numbers in every band: what the stroker sends when it is
//! given segment `k` starts at number `k` times the most one drawing
//! command takes ([`budget::numbers_per_command`]), the numbers between
//! counted as left out. (The stroker holds a contour's first piece to its
//! end, so the line's first piece takes numbers after the run that starts
//! the line, which differ from band to band: its walks are set up again in
//! each band it reaches, as a band's first walks are.)

use crate::geom::{FinePoint, PathSink};
use crate::path::segment::SegmentSink;
use crate::path::vector::{Pt, Unit};
use crate::path::{StrokeAlignment, StrokeStyle, Stroker, Tolerance};

use super::outline::is_right_turn;
use super::union::MAX_UNION_POINTS;
use super::{budget, STROKE_BOX};

/// Fine units added to a stroke's reach where a windowed stroke tests
/// which segments meet the window (the grid rounding of offset points).
const REACH_SLACK: i64 = 16;

/// Strokes the polyline of `n` points `at(0..n)` in `style` at `tol`
/// (already fitted to the budget) into `sink`, only where it meets the
/// sink's window (see the module doc); false, with nothing sent, where
/// that may not give the window the whole stroke's segments.
pub(crate) fn polyline<S: SegmentSink + ?Sized>(
    n: usize,
    at: impl Fn(usize) -> FinePoint,
    style: &StrokeStyle<'_>,
    tol: Tolerance,
    sink: &mut S,
) -> bool {
    let Some((lo, hi)) = sink.window() else {
        return false;
    };
    if n <= MAX_UNION_POINTS || style.dash.is_some() || !budget::plainly_within(style, tol, n) {
        return false;
    }
    let inside =
        |p: FinePoint| i64::from(p.x).abs() < STROKE_BOX && i64::from(p.y).abs() < STROKE_BOX;
    if !(0..n).all(|k| inside(at(k))) {
        return false;
    }
    // How far the stroke reaches beyond its path: half the width times
    // the larger of the miter limit and 3/2 (a miter's tip, a square
    // cap's corner, a round join), half the style's reach (which is
    // twice that, the widest of any stroke's bounds).
    let reach = (style.reach() / 2).saturating_add(REACH_SLACK);
    let line = Line {
        at: &at,
        segments: n - 1,
        lo: i64::from(lo) - reach,
        hi: i64::from(hi) + reach,
    };
    let per = budget::numbers_per_command(style, tol);
    let style = style.with_alignment(StrokeAlignment::Centre);
    let next = core::cell::Cell::new(0u32);
    let mut seek = Seek {
        sink,
        at: 0,
        next: &next,
    };
    let mut next_run = line.run_from(0);
    while let Some((first, mut end)) = next_run {
        // Runs that would overlap or touch are one.
        next_run = loop {
            match line.run_from(end + 1) {
                Some((f, e)) if f <= end + 1 => end = e,
                later => break later,
            }
        };
        let mut stroker = Stroker::with_tolerance(&style, tol, &mut seek);
        stroker.move_to(at(first));
        for s in first..=end {
            next.set((s as u32).saturating_mul(per));
            stroker.line_to(at(s + 1));
        }
        next.set(((end + 1) as u32).saturating_mul(per));
        // Plainly within its budget: a run never stops short.
        let _ = stroker.finish();
    }
    true
}

/// A polyline's segments and the window widened by the reach.
struct Line<'a, F> {
    at: &'a F,
    segments: usize,
    lo: i64,
    hi: i64,
}

impl<F: Fn(usize) -> FinePoint> Line<'_, F> {
    /// Segment `k` reaches the widened window.
    fn meets(&self, k: usize) -> bool {
        let (a, b) = (i64::from((self.at)(k).y), i64::from((self.at)(k + 1).y));
        a.min(b) <= self.hi && a.max(b) >= self.lo
    }

    /// Segment `k` has length: a piece of its own.
    fn long(&self, k: usize) -> bool {
        (self.at)(k) != (self.at)(k + 1)
    }

    /// The stroker's unit normal of segment `k` (a long one).
    fn normal(&self, k: usize) -> Option<Unit> {
        let d = Pt::from((self.at)(k + 1)).sub(Pt::from((self.at)(k)));
        Some(d.unit()?.right())
    }

    /// The segments of length before `k`, nearest first.
    fn long_before(&self, k: usize) -> Option<usize> {
        (0..k).rev().find(|&j| self.long(j))
    }

    /// The next segment of length after `k`.
    fn long_after(&self, k: usize) -> Option<usize> {
        (k + 1..self.segments).find(|&j| self.long(j))
    }

    /// The segments to stroke for the next run of segments meeting the
    /// window from segment `k` on (see the module doc), or `None`.
    fn run_from(&self, k: usize) -> Option<(usize, usize)> {
        let k = (k..self.segments).find(|&j| self.meets(j))?;
        // The run's last segment: runs less than two segments of length
        // apart are one.
        let (mut last, mut gap, mut j) = (k, 0, k + 1);
        while j < self.segments && gap < 2 {
            if self.meets(j) {
                (last, gap) = (j, 0);
            } else if self.long(j) {
                gap += 1;
            }
            j += 1;
        }
        let end = self.long_after(last).unwrap_or(self.segments - 1);
        // Back one segment of length, then on while the turns at both
        // ends of the first segment are to the same side.
        let Some(mut first) = self.long_before(k) else {
            return Some((0, end));
        };
        // The normals of `first` and of the segment of length after it
        // (each found once: a square root and two divisions).
        let (Some(mut f), Some(mut q)) = (
            self.normal(first),
            self.long_after(first).and_then(|a| self.normal(a)),
        ) else {
            return Some((first, end));
        };
        loop {
            let Some(before) = self.long_before(first) else {
                // The line's first piece: from its start.
                return Some((0, end));
            };
            let Some(p) = self.normal(before) else {
                return Some((first, end));
            };
            if p == f || f == q || is_right_turn(p, f) != is_right_turn(f, q) {
                return Some((first, end));
            }
            (first, f, q) = (before, p, f);
        }
    }
}

/// A sink that numbers from where it is told (`next`, never back), so
/// that a windowed stroke's segments take their numbers in every band.
struct Seek<'s, 'c, S: ?Sized> {
    sink: &'s mut S,
    /// Numbers given so far.
    at: u32,
    /// The number the next segment takes at least.
    next: &'c core::cell::Cell<u32>,
}

impl<S: SegmentSink + ?Sized> Seek<'_, '_, S> {
    fn catch_up(&mut self) {
        let to = self.next.get();
        if to > self.at {
            self.sink.skipped(to - self.at);
            self.at = to;
        }
    }
}

impl<S: SegmentSink + ?Sized> SegmentSink for Seek<'_, '_, S> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        self.catch_up();
        self.sink.segment(from, to);
        self.at = self.at.wrapping_add(1);
    }
    fn window(&self) -> Option<(i32, i32)> {
        self.sink.window()
    }
    fn skipped(&mut self, n: u32) {
        self.catch_up();
        self.sink.skipped(n);
        self.at = self.at.wrapping_add(n);
    }
}
