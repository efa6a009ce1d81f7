//! The segment interface: what the edge engine receives from every path,
//! shape and stroke.
//!
//! Takes the set-up's vertices (fine units in `i64`, possibly far outside
//! the coordinate range); gives a [`SegmentSink`] directed straight
//! segments between [`FinePoint`]s such that
//!
//! - the segments form **closed contours** (every point is the end of as
//!   many segments as it is the start of), so the winding number of every
//!   point not on a segment is well defined: the number of contours around
//!   it counted with their direction (clockwise on screen, y down, counts
//!   `+1`);
//! - no segment has zero length;
//! - every endpoint lies in the accepted range, `|x|, |y| <=`
//!   [`FINE_LIMIT`].
//!
//! ## Clamping to the range, exactly
//!
//! A segment that leaves the range square `Q = [-L, L]^2` is cut where it
//! crosses the lines `x = +-L` and `y = +-L`, and each piece is replaced by
//! its image under the clamp `(x, y) -> (clamp(x), clamp(y))`: pieces
//! outside run along the border of `Q` (or collapse to a corner and
//! vanish). The clamped contours are still closed, and every point
//! strictly inside `Q` keeps its winding number: the straight homotopy
//! from a point `q` outside `Q` to its clamp never enters the interior of
//! `Q` (a coordinate beyond `L` stays `>= L` along it), so no curve crosses
//! an inner point while it is deformed. Cut points are rounded to the grid
//! (the coordinate on the border line is exact).

use crate::geom::{FinePoint, FINE_LIMIT};

use super::vector::Pt;

/// Receives the directed straight segments of closed contours, on the fine
/// grid (1/1024 px).
///
/// The edge engine implements it; every path, shape and stroke in
/// [`path`](crate::path) describes itself into one. See the
/// [module](crate::path) for the guarantees (closed contours, no
/// zero-length segment, every point in range, orientation conventions).
/// Segments arrive in no particular order: a consumer must not rely on
/// consecutive calls forming a contour.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::SegmentSink;
///
/// /// Twice the signed area of everything received (shoelace).
/// struct Area2(i64);
/// impl SegmentSink for Area2 {
///     fn segment(&mut self, a: FinePoint, b: FinePoint) {
///         self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
///     }
/// }
/// let mut area = Area2(0);
/// let sq = [(0, 0), (1024, 0), (1024, 1024), (0, 1024)].map(|(x, y)| FinePoint::new(x, y));
/// for k in 0..4 {
///     area.segment(sq[k], sq[(k + 1) % 4]);
/// }
/// assert_eq!(area.0, 2 * 1024 * 1024); // clockwise on screen: positive
/// ```
pub trait SegmentSink {
    /// A directed segment from `from` to `to`.
    fn segment(&mut self, from: FinePoint, to: FinePoint);

    /// The rows this sink needs, as a closed range of y in fine units:
    /// a segment whose y-extent lies wholly above or below it may be left
    /// out (reported to [`skipped`](Self::skipped) instead). A band's
    /// canvas gives its rows, so curves skip the vertices of pieces that
    /// miss the band. `None` (the default): every segment.
    fn window(&self) -> Option<(i32, i32)> {
        None
    }

    /// `n` segments were left out: each lies wholly outside the
    /// [`window`](Self::window), had zero length, or was dropped by a
    /// filter on the way (a [`BandFilter`](crate::path::BandFilter)'s
    /// horizontal ones). For sinks that number
    /// their segments (a band's walks are cached by their place in the
    /// outline): the numbering stays the same whichever segments are left
    /// out. The default ignores it.
    fn skipped(&mut self, n: u32) {
        let _ = n;
    }
}

impl<S: SegmentSink + ?Sized> SegmentSink for &mut S {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        (**self).segment(from, to);
    }
    fn window(&self) -> Option<(i32, i32)> {
        (**self).window()
    }
    fn skipped(&mut self, n: u32) {
        (**self).skipped(n);
    }
}

/// The range square's half side, in fine units.
const L: i64 = FINE_LIMIT as i64;

/// The numbers a segment leaving the range square takes: its clamped
/// pieces (up to five: four cuts), the rest counted as skipped.
pub(crate) const CLAMPED_NUMBERS: u32 = 5;

/// Sends the segment `a -> b` to `sink`, clamped to the range square (see
/// the module doc); zero-length pieces are dropped. A segment within the
/// square takes one number of the sink's count (sent, or skipped when it
/// has no length), one leaving it [`CLAMPED_NUMBERS`] (pieces sent, the
/// rest skipped), so that the numbers of what follows do not depend on
/// how it was cut.
pub(crate) fn emit<S: SegmentSink + ?Sized>(sink: &mut S, a: Pt, b: Pt) {
    if a == b {
        sink.skipped(1);
        return;
    }
    if in_square(a) && in_square(b) {
        sink.segment(a.to_fine(), b.to_fine());
        return;
    }
    let mut sent = 0;
    clip_to_square(a, b, L, |p, q| {
        if p != q {
            sink.segment(p.to_fine(), q.to_fine());
            sent += 1;
        }
    });
    sink.skipped(CLAMPED_NUMBERS - sent);
}

/// The numbers [`emit`] takes for `a -> b`: one within the range square
/// (or with no length), [`CLAMPED_NUMBERS`] leaving it.
pub(crate) fn numbers(a: Pt, b: Pt) -> u32 {
    if a == b || (in_square(a) && in_square(b)) {
        1
    } else {
        CLAMPED_NUMBERS
    }
}

/// `p` lies in the range square (its segments are sent unclamped).
#[inline]
pub(crate) fn in_square(p: Pt) -> bool {
    p.x.abs() <= L && p.y.abs() <= L
}

/// Cuts `a -> b` where it crosses `x = +-half` and `y = +-half` and gives
/// `out` the clamped image of every piece, in order (pieces may have zero
/// length; the caller drops those). `half > 0`; `|a|, |b| < 2^40`.
pub(crate) fn clip_to_square(a: Pt, b: Pt, half: i64, mut out: impl FnMut(Pt, Pt)) {
    let d = b.sub(a);
    // Crossing parameters t = num / den in (0, 1), den = |d.x| or |d.y|;
    // `(1, 1)` (t = 1) marks an unused slot and sorts last.
    let cut = |coord_a: i64, delta: i64, line: i64| -> (i128, i128) {
        if delta == 0 {
            return (1, 1);
        }
        let num = i128::from(line - coord_a);
        let den = i128::from(delta);
        let (num, den) = if den < 0 { (-num, -den) } else { (num, den) };
        if num > 0 && num < den {
            (num, den)
        } else {
            (1, 1)
        }
    };
    let mut cuts = [
        cut(a.x, d.x, half),
        cut(a.x, d.x, -half),
        cut(a.y, d.y, half),
        cut(a.y, d.y, -half),
    ];
    // A sorting network on four entries, compared exactly.
    let mut order = |i: usize, j: usize| {
        let (p, q) = (cuts[i], cuts[j]);
        if p.0 * q.1 > q.0 * p.1 {
            cuts[i] = q;
            cuts[j] = p;
        }
    };
    order(0, 1);
    order(2, 3);
    order(0, 2);
    order(1, 3);
    order(1, 2);
    let clamp = |p: Pt| Pt::new(p.x.clamp(-half, half), p.y.clamp(-half, half));
    let at = |(num, den): (i128, i128)| {
        // a + d t, rounded; the coordinate whose line this is comes out
        // exact (num/den was formed from it).
        let x = i128::from(a.x) + super::trig::div_round(i128::from(d.x) * num, den);
        let y = i128::from(a.y) + super::trig::div_round(i128::from(d.y) * num, den);
        Pt::new(x as i64, y as i64)
    };
    let mut prev = clamp(a);
    for &c in cuts.iter().filter(|c| c.0 < c.1) {
        let p = clamp(at(c));
        out(prev, p);
        prev = p;
    }
    out(prev, clamp(b));
}

/// Sends consecutive points as a closed contour: tracks the first point
/// and closes back to it. The building block of every contour the path
/// code emits; clamps through [`emit`].
pub(crate) struct Contour<'s, S: SegmentSink + ?Sized> {
    pub sink: &'s mut S,
    first: Pt,
    last: Pt,
    open: bool,
}

impl<'s, S: SegmentSink + ?Sized> Contour<'s, S> {
    pub fn new(sink: &'s mut S) -> Self {
        Self {
            sink,
            first: Pt::default(),
            last: Pt::default(),
            open: false,
        }
    }

    /// Starts a contour at `p`, closing the one before.
    pub fn move_to(&mut self, p: Pt) {
        self.close();
        self.first = p;
        self.last = p;
        self.open = true;
    }

    /// A segment from the last point to `p` (starts a contour at the last
    /// point if none is open).
    pub fn line_to(&mut self, p: Pt) {
        if !self.open {
            self.first = self.last;
            self.open = true;
        }
        emit(self.sink, self.last, p);
        self.last = p;
    }

    /// Closes the open contour back to its first point.
    pub fn close(&mut self) {
        if self.open {
            emit(self.sink, self.last, self.first);
            self.last = self.first;
            self.open = false;
        }
    }

    /// The last point.
    pub fn last(&self) -> Pt {
        self.last
    }

    /// Moves on to `p` without sending the `n` segments from the last
    /// point to it, which the caller knows to lie wholly outside the
    /// sink's window (see [`Vertices::jump`]); the sink is told they were
    /// left out.
    pub fn jump(&mut self, p: Pt, n: u32) {
        if !self.open {
            self.first = self.last;
            self.open = true;
        }
        self.sink.skipped(n);
        self.last = p;
    }
}

/// The vertices of one contour, in order: what the curve flatteners
/// ([`arc`](super::arc)) write, into a closure or into a [`Contour`]
/// ([`ContourVertices`]).
pub(crate) trait Vertices {
    /// The next vertex.
    fn vertex(&mut self, p: Pt);

    /// The rows that matter (see [`SegmentSink::window`]); `None`: every
    /// vertex is wanted.
    fn window(&self) -> Option<(i32, i32)> {
        None
    }

    /// The next vertex is `p`, `n` segments on from the last: the `n - 1`
    /// vertices between are left out, so the caller must know that every
    /// segment from the last vertex to `p` lies wholly outside the window.
    fn jump(&mut self, p: Pt, n: u32) {
        let _ = n;
        self.vertex(p);
    }
}

impl<F: FnMut(Pt) + ?Sized> Vertices for F {
    fn vertex(&mut self, p: Pt) {
        self(p);
    }
}

/// A closed [`Contour`] fed vertex by vertex: the first vertex starts it,
/// [`close`](Self::close) joins the last to it. Curves written into it
/// may leave out the vertices of pieces outside the sink's window.
pub(crate) struct ContourVertices<'s, S: SegmentSink + ?Sized> {
    contour: Contour<'s, S>,
    started: bool,
}

impl<'s, S: SegmentSink + ?Sized> ContourVertices<'s, S> {
    pub fn new(sink: &'s mut S) -> Self {
        Self {
            contour: Contour::new(sink),
            started: false,
        }
    }

    pub fn close(mut self) {
        self.contour.close();
    }
}

impl<S: SegmentSink + ?Sized> Vertices for ContourVertices<'_, S> {
    fn vertex(&mut self, p: Pt) {
        if self.started {
            self.contour.line_to(p);
        } else {
            self.contour.move_to(p);
            self.started = true;
        }
    }

    fn window(&self) -> Option<(i32, i32)> {
        self.contour.sink.window()
    }

    fn jump(&mut self, p: Pt, n: u32) {
        if self.started {
            self.contour.jump(p, n);
        } else {
            self.vertex(p);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Rec {
        segs: [(FinePoint, FinePoint); 32],
        n: usize,
    }
    impl SegmentSink for Rec {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            if let Some(s) = self.segs.get_mut(self.n) {
                *s = (a, b);
            }
            self.n += 1;
        }
    }
    fn rec() -> Rec {
        Rec {
            segs: [(FinePoint::default(), FinePoint::default()); 32],
            n: 0,
        }
    }
    fn area2(r: &Rec) -> i128 {
        r.segs[..r.n]
            .iter()
            .map(|(a, b)| i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y))
            .sum()
    }

    #[test]
    fn segments_inside_pass_unchanged_and_zero_length_ones_vanish() {
        let mut r = rec();
        emit(&mut r, Pt::new(1, 2), Pt::new(3, 4));
        emit(&mut r, Pt::new(5, 5), Pt::new(5, 5));
        assert_eq!(r.n, 1);
        assert_eq!(r.segs[0], (FinePoint::new(1, 2), FinePoint::new(3, 4)));
    }

    #[test]
    fn clamped_triangle_keeps_its_closed_shape_and_all_points_in_range() {
        // A triangle with a vertex far beyond the right border.
        let p = [Pt::new(0, 0), Pt::new(10 * L, L / 2), Pt::new(0, L / 2)];
        let mut r = rec();
        let mut c = Contour::new(&mut r);
        c.move_to(p[0]);
        c.line_to(p[1]);
        c.line_to(p[2]);
        c.close();
        for (a, b) in &r.segs[..r.n] {
            assert!(a.in_range() && b.in_range() && a != b);
        }
        // Closed: the end points balance.
        let mut sum = (0i64, 0i64);
        for (a, b) in &r.segs[..r.n] {
            sum.0 += i64::from(b.x - a.x);
            sum.1 += i64::from(b.y - a.y);
        }
        assert_eq!(sum, (0, 0));
        // The part inside: the triangle cut at x = L (a trapezoid) plus a
        // zero-area stretch along the border. Exact area of the inside
        // part: the triangle (0,0) (10L, L/2) (0, L/2) cut at x = L.
        let want2 = {
            // Inside: quadrilateral (0,0) (L, L/20) (L, L/2) (0, L/2).
            let q = [
                (0i128, 0i128),
                (L as i128, (L / 20) as i128),
                (L as i128, (L / 2) as i128),
                (0, (L / 2) as i128),
            ];
            (0..4)
                .map(|k| q[k].0 * q[(k + 1) % 4].1 - q[(k + 1) % 4].0 * q[k].1)
                .sum::<i128>()
        };
        assert!(
            (area2(&r) - want2).abs() <= 4 * L as i128,
            "{} vs {want2}",
            area2(&r)
        );
    }

    #[test]
    fn a_segment_outside_on_the_left_becomes_a_border_segment() {
        let mut r = rec();
        emit(&mut r, Pt::new(-5 * L, -10), Pt::new(-3 * L, 20));
        assert_eq!(r.n, 1);
        assert_eq!(
            r.segs[0],
            (
                FinePoint::new(-FINE_LIMIT, -10),
                FinePoint::new(-FINE_LIMIT, 20)
            )
        );
        let mut r = rec();
        emit(&mut r, Pt::new(-5 * L, -5 * L), Pt::new(-3 * L, -4 * L));
        assert_eq!(r.n, 0);
    }

    #[test]
    fn a_diagonal_through_the_corner_region_is_cut_in_order() {
        let mut r = rec();
        emit(&mut r, Pt::new(-2 * L, -3 * L), Pt::new(2 * L, 3 * L));
        for (a, b) in &r.segs[..r.n] {
            assert!(a.in_range() && b.in_range());
        }
        for w in r.segs[..r.n].windows(2) {
            assert_eq!(w[0].1, w[1].0);
        }
        assert_eq!(r.segs[0].0, FinePoint::new(-FINE_LIMIT, -FINE_LIMIT));
        assert_eq!(r.segs[r.n - 1].1, FinePoint::new(FINE_LIMIT, FINE_LIMIT));
    }
}
