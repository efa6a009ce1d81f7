//! Consumer helpers: keeping a description's segments, and passing on only
//! those a band of rows needs.
//!
//! Takes segments from any description; gives either a caller-provided
//! slice filled with them ([`SegmentBuffer`], what a shape cache keeps an
//! outline in, so that a shape is described once and its segments walked
//! for every band), or a [`SegmentSink`] that forwards only the segments
//! whose vertical extent meets a band of rows ([`BandFilter`]).
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

/// A directed segment, as a [`ShapeCache`](crate::canvas::ShapeCache)
/// keeps it.
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
/// counted, not stored (check [`overflowed`](Self::overflowed)): how a
/// [`ShapeCache`](crate::canvas::ShapeCache) keeps an outline. 16 bytes a
/// segment.
#[derive(Debug)]
pub(crate) struct SegmentBuffer<'a> {
    store: &'a mut [Segment],
    len: usize,
    overflowed: bool,
}

impl<'a> SegmentBuffer<'a> {
    /// An empty buffer over `store`.
    pub(crate) fn new(store: &'a mut [Segment]) -> Self {
        Self {
            store,
            len: 0,
            overflowed: false,
        }
    }

    /// The segments kept, in the order received.
    pub(crate) fn segments(&self) -> &[Segment] {
        self.store.get(..self.len).unwrap_or_default()
    }

    /// True when segments were dropped for lack of room (the kept ones are
    /// then not closed contours).
    pub(crate) fn overflowed(&self) -> bool {
        self.overflowed
    }
}

impl SegmentSink for SegmentBuffer<'_> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        match self.store.get_mut(self.len) {
            Some(slot) => {
                *slot = Segment { from, to };
                self.len += 1;
            }
            None => self.overflowed = true,
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
/// use softedge::path::{BandFilter, Circle, SegmentSink, Shape};
/// #[derive(Default)]
/// struct Count(usize);
/// impl SegmentSink for Count {
///     fn segment(&mut self, _: FinePoint, _: FinePoint) {
///         self.0 += 1;
///     }
/// }
/// let disc = Circle::new(FinePoint::new(50 * 1024, 50 * 1024), 20 * 1024);
/// let (mut all, mut band) = (Count::default(), Count::default());
/// disc.fill(&mut all);
/// disc.fill(&mut BandFilter::new(&mut band, 48 * 1024, 56 * 1024)); // 8 rows
/// assert!(band.0 > 0 && band.0 < all.0 / 4);
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
    extern crate std;
    use super::*;

    #[test]
    fn a_full_buffer_keeps_what_fits_and_says_it_overflowed() {
        let mut store = [Segment::default(); 2];
        let mut b = SegmentBuffer::new(&mut store);
        for k in 0..2 {
            b.segment(FinePoint::new(k, 0), FinePoint::new(k, 1));
        }
        assert!(!b.overflowed());
        b.segment(FinePoint::new(7, 0), FinePoint::new(7, 1));
        assert!(b.overflowed());
        let kept: std::vec::Vec<i32> = b.segments().iter().map(|s| s.from.x).collect();
        assert_eq!(kept, [0, 1]);
        let mut empty: [Segment; 0] = [];
        let mut b = SegmentBuffer::new(&mut empty);
        b.segment(FinePoint::new(0, 0), FinePoint::new(1, 1));
        assert!(b.overflowed() && b.segments().is_empty());
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
