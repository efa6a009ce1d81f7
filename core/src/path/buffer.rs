//! Consumer helpers: keeping a description's segments, and passing on only
//! those a band of rows needs.
//!
//! Takes segments from any description; gives either a caller-provided
//! slice filled with them ([`SegmentBuffer`], so that a shape is described
//! once per frame and its segments walked for every band), or a
//! [`SegmentSink`] that forwards only the segments whose vertical extent
//! meets a band of rows ([`BandFilter`]).
//!
//! Per band, a segment entirely above or below the band's rows
//! contributes nothing to any pixel in it (coverage accumulated along a
//! row only sees the segments that cross that row), so a band engine may
//! drop those; the contours it keeps are then no longer closed, which an
//! accumulating engine does not need. Segments to the left or right of
//! the band's columns must be kept: they move the winding of everything to
//! their right.

use crate::geom::FinePoint;

use super::SegmentSink;

/// A directed segment, as kept by [`SegmentBuffer`].
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::Segment;
/// let s = Segment { from: FinePoint::new(0, 0), to: FinePoint::new(1024, 0) };
/// assert_ne!(s.from, s.to);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Segment {
    /// Where it starts.
    pub from: FinePoint,
    /// Where it ends.
    pub to: FinePoint,
}

impl Segment {
    /// From the origin to the origin: the `Default`, usable in a `const`
    /// or `static` array (a shape cache's segments in `.bss`).
    pub const ZERO: Self = Self {
        from: FinePoint::new(0, 0),
        to: FinePoint::new(0, 0),
    };
}

/// Collects segments into a caller-provided slice; what does not fit is
/// counted, not stored (check [`overflowed`](Self::overflowed)).
///
/// A shape recorded once per frame (a stroke, a path, a run of glyphs)
/// can then be filled in every band from the buffer (a
/// [`canvas::Outline`](crate::canvas::Outline), filled by the nonzero
/// rule for a stroke): the band walks only the segments that cross its
/// rows, instead of describing, flattening and stroking the shape again.
/// The segments, their order and so the pixels are those of the shape
/// drawn directly. 16 bytes a segment.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Rectangle, Segment, SegmentBuffer, Shape};
/// let mut store = [Segment::default(); 8];
/// let mut buf = SegmentBuffer::new(&mut store);
/// Rectangle::new(FinePoint::new(0, 0), 4096, 2048).fill(&mut buf);
/// assert_eq!(buf.segments().len(), 4);
/// assert!(!buf.overflowed());
/// ```
#[derive(Debug)]
pub struct SegmentBuffer<'a> {
    store: &'a mut [Segment],
    len: usize,
    dropped: usize,
    /// The corners of the box around the kept segments (meaningful when
    /// `len > 0`).
    lo: FinePoint,
    hi: FinePoint,
}

impl<'a> SegmentBuffer<'a> {
    /// An empty buffer over `store`.
    pub fn new(store: &'a mut [Segment]) -> Self {
        Self {
            store,
            len: 0,
            dropped: 0,
            lo: FinePoint::new(0, 0),
            hi: FinePoint::new(0, 0),
        }
    }

    /// The box around every point of the kept segments, as its smallest
    /// and largest corners; `None` when none is kept.
    pub fn extent(&self) -> Option<(FinePoint, FinePoint)> {
        (self.len > 0).then_some((self.lo, self.hi))
    }

    /// The segments kept, in the order received.
    pub fn segments(&self) -> &[Segment] {
        self.store.get(..self.len).unwrap_or_default()
    }

    /// True when segments were dropped for lack of room (the kept ones are
    /// then not closed contours).
    pub fn overflowed(&self) -> bool {
        self.dropped > 0
    }

    /// How many segments were dropped.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Empties the buffer.
    pub fn clear(&mut self) {
        self.len = 0;
        self.dropped = 0;
    }

    /// Sends every kept segment to `sink`.
    pub fn replay<S: SegmentSink + ?Sized>(&self, sink: &mut S) {
        for s in self.segments() {
            sink.segment(s.from, s.to);
        }
    }
}

impl SegmentSink for SegmentBuffer<'_> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        match self.store.get_mut(self.len) {
            Some(slot) => {
                *slot = Segment { from, to };
                if self.len == 0 {
                    (self.lo, self.hi) = (from, from);
                }
                for p in [from, to] {
                    self.lo = FinePoint::new(self.lo.x.min(p.x), self.lo.y.min(p.y));
                    self.hi = FinePoint::new(self.hi.x.max(p.x), self.hi.y.max(p.y));
                }
                self.len += 1;
            }
            None => self.dropped = self.dropped.saturating_add(1),
        }
    }
}

/// Forwards to `sink` only the segments that meet the rows
/// `[y0, y1)` (fine units): those whose y-extent, closed, overlaps the
/// half-open band (horizontal segments contribute nothing and are
/// dropped too).
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{BandFilter, Circle, SegmentBuffer, Segment, Shape};
/// let disc = Circle::new(FinePoint::new(50 * 1024, 50 * 1024), 20 * 1024);
/// let mut store = [Segment::default(); 512];
/// let mut buf = SegmentBuffer::new(&mut store);
/// disc.fill(&mut buf);
/// let all = buf.segments().len();
/// buf.clear();
/// disc.fill(&mut BandFilter::new(&mut buf, 48 * 1024, 56 * 1024)); // 8 rows
/// assert!(buf.segments().len() < all / 4);
/// ```
#[derive(Debug)]
pub struct BandFilter<'s, S: SegmentSink + ?Sized> {
    sink: &'s mut S,
    y0: i32,
    y1: i32,
}

impl<'s, S: SegmentSink + ?Sized> BandFilter<'s, S> {
    /// A filter for the rows `[y0, y1)`, fine units.
    pub fn new(sink: &'s mut S, y0: i32, y1: i32) -> Self {
        Self { sink, y0, y1 }
    }
}

impl<S: SegmentSink + ?Sized> SegmentSink for BandFilter<'_, S> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        let (lo, hi) = if from.y <= to.y {
            (from.y, to.y)
        } else {
            (to.y, from.y)
        };
        if lo != hi && hi > self.y0 && lo < self.y1 {
            self.sink.segment(from, to);
        } else {
            self.sink.skipped(1);
        }
    }

    /// The rows kept, within the sink's own: a segment that ends at or
    /// above `y0`, or starts at or below `y1`, is dropped anyway.
    fn window(&self) -> Option<(i32, i32)> {
        let (lo, hi) = (self.y0.saturating_add(1), self.y1.saturating_sub(1));
        Some(match self.sink.window() {
            Some((a, b)) => (lo.max(a), hi.min(b)),
            None => (lo, hi),
        })
    }

    fn skipped(&mut self, n: u32) {
        self.sink.skipped(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_buffer_counts_what_it_drops() {
        let mut store = [Segment::default(); 2];
        let mut b = SegmentBuffer::new(&mut store);
        for k in 0..5 {
            b.segment(FinePoint::new(k, 0), FinePoint::new(k, 1));
        }
        assert_eq!((b.segments().len(), b.dropped()), (2, 3));
        // The box holds the kept segments only.
        assert_eq!(
            b.extent(),
            Some((FinePoint::new(0, 0), FinePoint::new(1, 1)))
        );
        b.clear();
        assert!(!b.overflowed() && b.segments().is_empty());
        assert_eq!(b.extent(), None);
        b.segment(FinePoint::new(-5, 7), FinePoint::new(3, -2));
        assert_eq!(
            b.extent(),
            Some((FinePoint::new(-5, -2), FinePoint::new(3, 7)))
        );
        let mut empty: [Segment; 0] = [];
        let mut b = SegmentBuffer::new(&mut empty);
        b.segment(FinePoint::new(0, 0), FinePoint::new(1, 1));
        assert!(b.overflowed());
    }

    #[test]
    fn the_band_filter_keeps_segments_that_cross_its_rows() {
        let mut store = [Segment::default(); 8];
        let mut b = SegmentBuffer::new(&mut store);
        {
            let mut f = BandFilter::new(&mut b, 100, 200);
            f.segment(FinePoint::new(0, 0), FinePoint::new(0, 100)); // ends at the top: out
            f.segment(FinePoint::new(0, 0), FinePoint::new(0, 101)); // in
            f.segment(FinePoint::new(-9, 150), FinePoint::new(99, 150)); // horizontal: out
            f.segment(FinePoint::new(5, 250), FinePoint::new(5, 199)); // in
            f.segment(FinePoint::new(5, 200), FinePoint::new(5, 300)); // below: out
        }
        assert_eq!(b.segments().len(), 2);
    }
}
