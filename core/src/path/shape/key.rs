//! What a shape's outline is made from, exactly: the key by which a
//! [`ShapeCache`](crate::canvas::ShapeCache) keeps the outline from one
//! band and one frame to the next.
//!
//! A shape whose geometry is a few numbers is its own key. A shape that
//! borrows its points (a polyline, a polygon, an SVG path) is known by its
//! *description*: the stream of points its [`PathSink`] calls send, each
//! call's kind marked by a tag point ([`Stream`]). Its key holds the
//! shape's kind, the stream's length and a hash of it; the cache keeps the
//! stream itself beside the outline and compares it point by point before
//! it fills a kept outline, so two shapes are never confused by a hash.

use super::{Arc, Circle, Ellipse, Line, Rectangle, RoundedRectangle, Sector, Shape};
use crate::geom::{FinePoint, PathSink};
use crate::path::Segment;

/// A shape's geometry, whole: two shapes with equal keys describe the
/// same segments (at the same tolerance, with the same stroke). The
/// shapes whose geometry is a few numbers give one
/// ([`Shape::key`](super::Shape::key)); polylines, polygons and SVG paths
/// give their kind, the length of their description and a hash of it (a
/// [`ShapeCache`](crate::canvas::ShapeCache) compares their descriptions
/// exactly before it uses an outline it keeps); glyphs and shapes of
/// other crates give none, and are described again wherever they are
/// drawn.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{Circle, Shape};
/// let c = FinePoint::new(20 * 1024, 20 * 1024);
/// assert_eq!(Circle::new(c, 5 * 1024).key(), Circle::new(c, 5 * 1024).key());
/// assert_ne!(Circle::new(c, 5 * 1024).key(), Circle::new(c, 5 * 1024 + 1).key());
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShapeKey(Known);

/// The shapes a key is made of, by value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Known {
    Circle(Circle),
    Ellipse(Ellipse),
    Arc(Arc),
    Sector(Sector),
    Rectangle(Rectangle),
    Rounded(RoundedRectangle),
    Line(Line),
    Described(Described),
}

/// The shapes known by their description.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    Polyline,
    Polygon,
    Svg,
}

/// A shape known by its description: its kind, the points of its
/// [`Stream`] and their hash.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Described {
    kind: Kind,
    points: u32,
    hash: u32,
}

macro_rules! keys {
    ($($t:ident => $v:ident),* $(,)?) => {$(
        impl From<$t> for ShapeKey {
            fn from(s: $t) -> Self {
                ShapeKey(Known::$v(s))
            }
        }
    )*};
}

keys! {
    Circle => Circle,
    Ellipse => Ellipse,
    Arc => Arc,
    Sector => Sector,
    Rectangle => Rectangle,
    RoundedRectangle => Rounded,
    Line => Line,
}

impl ShapeKey {
    /// The circle the key is made of, if it is one.
    pub(crate) fn circle(&self) -> Option<Circle> {
        match self.0 {
            Known::Circle(c) => Some(c),
            _ => None,
        }
    }

    /// The arc the key is made of, if it is one.
    pub(crate) fn arc(&self) -> Option<Arc> {
        match self.0 {
            Known::Arc(a) => Some(a),
            _ => None,
        }
    }

    /// The key of `shape`, of kind `kind`, by its description; `None` for
    /// a description of more than [`MAX_POINTS`] stream points.
    pub(crate) fn described<S: Shape + ?Sized>(kind: Kind, shape: &S) -> Option<Self> {
        let mut h = Hash {
            points: 0,
            hash: HASH_SEED,
        };
        shape.describe(&mut Stream(|p| h.add(p)));
        (h.points <= MAX_POINTS).then_some(ShapeKey(Known::Described(Described {
            kind,
            points: h.points,
            hash: h.hash,
        })))
    }

    /// The stream points of a described shape's description; 0 for the
    /// others.
    pub(crate) fn stream_points(&self) -> usize {
        match self.0 {
            Known::Described(d) => d.points as usize,
            _ => 0,
        }
    }

    /// Segments the description of a described shape takes in a cache
    /// (two stream points a segment); 0 for the others.
    pub(crate) fn stream_segments(&self) -> usize {
        match self.0 {
            Known::Described(d) => (d.points as usize).div_ceil(2),
            _ => 0,
        }
    }
}

/// The longest description kept: 2^20 stream points (8 MiB of segments,
/// more than any cache holds; the count cannot wrap).
const MAX_POINTS: u32 = 1 << 20;

/// FNV-1a's offset basis and prime (32 bits), over the stream's words.
const HASH_SEED: u32 = 0x811c_9dc5;
const HASH_PRIME: u32 = 0x0100_0193;

/// A stream's length and hash, as its points come.
struct Hash {
    points: u32,
    hash: u32,
}

impl Hash {
    fn add(&mut self, p: FinePoint) {
        self.points = self.points.saturating_add(1);
        for w in [p.x, p.y] {
            self.hash = (self.hash ^ w as u32).wrapping_mul(HASH_PRIME);
        }
    }
}

/// The `x` of a tag point: no point of a description is marked by it
/// alone (a point with this `x` is sent after a [`LINE`] tag).
const TAG_X: i32 = i32::MIN;
/// Tags: what the points after them are.
const MOVE: i32 = 0;
const LINE: i32 = 1;
const QUAD: i32 = 2;
const CUBIC: i32 = 3;
const CLOSE: i32 = 4;

const fn tag(kind: i32) -> FinePoint {
    FinePoint::new(TAG_X, kind)
}

/// A description as a stream of points, given one by one to the closure:
/// `move_to(p)` as a [`MOVE`] tag and `p`; `line_to(p)` as `p` (after a
/// [`LINE`] tag when `p.x` is [`TAG_X`]); `quad_to` and `cubic_to` as
/// their tag and points; `close` as its tag. Two descriptions are the
/// same calls with the same points exactly when their streams are equal.
/// Asks for no orientation ([`PathSink::needs_clockwise`] false): the
/// points as the shape holds them.
struct Stream<F: FnMut(FinePoint)>(F);

impl<F: FnMut(FinePoint)> PathSink for Stream<F> {
    fn needs_clockwise(&self) -> bool {
        false
    }

    fn move_to(&mut self, p: FinePoint) {
        (self.0)(tag(MOVE));
        (self.0)(p);
    }

    fn line_to(&mut self, p: FinePoint) {
        if p.x == TAG_X {
            (self.0)(tag(LINE));
        }
        (self.0)(p);
    }

    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        (self.0)(tag(QUAD));
        (self.0)(c);
        (self.0)(p);
    }

    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        (self.0)(tag(CUBIC));
        (self.0)(c1);
        (self.0)(c2);
        (self.0)(p);
    }

    fn close(&mut self) {
        (self.0)(tag(CLOSE));
    }
}

/// The `k`-th stream point of `segments` (two a segment, `from` then
/// `to`).
fn stream_point(segments: &[Segment], k: usize) -> Option<FinePoint> {
    let s = segments.get(k / 2)?;
    Some(if k % 2 == 0 { s.from } else { s.to })
}

/// Writes the description of `shape` into `segments` (its
/// [`ShapeKey::stream_segments`] of them, the last one's `to` zero when the
/// stream is odd); false when they are too few.
pub(crate) fn write_stream(shape: &dyn Fn(&mut dyn PathSink), segments: &mut [Segment]) -> bool {
    let mut k = 0usize;
    let mut fits = true;
    shape(&mut Stream(|p| {
        match segments.get_mut(k / 2) {
            Some(s) if k % 2 == 0 => {
                *s = Segment {
                    from: p,
                    to: FinePoint::new(0, 0),
                }
            }
            Some(s) => s.to = p,
            None => fits = false,
        }
        k += 1;
    }));
    fits
}

/// True when the description of `shape` is the stream `segments` hold
/// (as [`write_stream`] wrote it, `points` long).
pub(crate) fn same_stream(
    shape: &dyn Fn(&mut dyn PathSink),
    segments: &[Segment],
    points: usize,
) -> bool {
    let mut k = 0usize;
    let mut same = true;
    shape(&mut Stream(|p| {
        same &= stream_point(segments, k) == Some(p);
        k += 1;
    }));
    same && k == points
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::path::svg::SvgPath;
    use crate::path::testing::Lcg;
    use crate::path::{Polygon, Polyline};

    /// The calls of a description, as written down.
    #[derive(Debug, Clone, PartialEq, Eq)]
    enum Call {
        Move(FinePoint),
        Line(FinePoint),
        Quad(FinePoint, FinePoint),
        Cubic(FinePoint, FinePoint, FinePoint),
        Close,
    }

    fn replay(calls: &[Call], sink: &mut dyn PathSink) {
        for c in calls {
            match *c {
                Call::Move(p) => sink.move_to(p),
                Call::Line(p) => sink.line_to(p),
                Call::Quad(c, p) => sink.quad_to(c, p),
                Call::Cubic(a, b, p) => sink.cubic_to(a, b, p),
                Call::Close => sink.close(),
            }
        }
    }

    /// Random calls over few coordinate values (so that equal points and
    /// tag-like points, `x = i32::MIN`, are common).
    fn random_calls(rng: &mut Lcg) -> Vec<Call> {
        let vals = [i32::MIN, i32::MIN + 1, -1, 0, 1, 2, 3, 4, i32::MAX];
        let pt = |rng: &mut Lcg| {
            let x = vals[rng.below(vals.len() as u64) as usize];
            let y = vals[rng.below(vals.len() as u64) as usize];
            FinePoint::new(x, y)
        };
        let n = rng.below(7) as usize;
        (0..n)
            .map(|_| match rng.below(5) {
                0 => Call::Move(pt(rng)),
                1 => Call::Line(pt(rng)),
                2 => Call::Quad(pt(rng), pt(rng)),
                3 => Call::Cubic(pt(rng), pt(rng), pt(rng)),
                _ => Call::Close,
            })
            .collect()
    }

    fn stream_of(calls: &[Call]) -> (Vec<Segment>, usize) {
        let mut n = 0usize;
        replay(calls, &mut Stream(|_| n += 1));
        let mut segs = std::vec![Segment::default(); n.div_ceil(2)];
        assert!(write_stream(&|s| replay(calls, s), &mut segs));
        (segs, n)
    }

    /// The stream is a faithful record: two descriptions have the same
    /// stream exactly when they are the same calls with the same points
    /// (the calls compared as written down, not through the stream).
    #[test]
    fn streams_are_equal_exactly_when_the_calls_are() {
        let mut rng = Lcg(0x57e4_3a11_0b5e_55ed);
        let (mut same, mut differ) = (0, 0);
        for _ in 0..20_000 {
            let a = random_calls(&mut rng);
            let b = if rng.below(3) == 0 {
                a.clone()
            } else {
                random_calls(&mut rng)
            };
            let (sa, na) = stream_of(&a);
            let equal = same_stream(&|s| replay(&b, s), &sa, na);
            assert_eq!(equal, a == b, "{a:?} / {b:?}");
            if a == b {
                same += 1;
            } else {
                differ += 1;
            }
        }
        assert!(same > 5000 && differ > 5000, "{same} {differ}");
    }

    #[test]
    fn a_stream_that_does_not_fit_is_refused() {
        let calls = [
            Call::Move(FinePoint::new(1, 2)),
            Call::Line(FinePoint::new(3, 4)),
        ];
        let mut short = [Segment::default(); 1];
        assert!(!write_stream(&|s| replay(&calls, s), &mut short));
        let mut room = [Segment::default(); 2];
        assert!(write_stream(&|s| replay(&calls, s), &mut room));
    }

    /// Keys of described shapes: equal for equal shapes of one kind, apart
    /// for another kind, another point, another order; their length is the
    /// stream's.
    #[test]
    fn described_keys_tell_shapes_apart() {
        let p = [
            FinePoint::new(0, 0),
            FinePoint::new(4096, 1024),
            FinePoint::new(2048, 5000),
        ];
        let mut q = p;
        q[2].y += 1;
        let line = |v: &[FinePoint]| Polyline::new(v).key().unwrap();
        let gon = |v: &[FinePoint]| Polygon::new(v).key().unwrap();
        assert_eq!(line(&p), line(&p.clone()));
        assert_ne!(line(&p), line(&q));
        assert_ne!(line(&p), gon(&p));
        let mut r = p;
        r.swap(0, 1);
        assert_ne!(line(&p), line(&r));
        // Move tag and point, two lines: 4 points in 2 segments; the
        // polygon closes: 5 points in 3.
        assert_eq!(
            (line(&p).stream_points(), line(&p).stream_segments()),
            (4, 2)
        );
        assert_eq!((gon(&p).stream_points(), gon(&p).stream_segments()), (5, 3));
        let svg = SvgPath::new("M 0 0 L 4 1 L 2 5").unwrap();
        assert_ne!(svg.key().unwrap(), line(&p));
        assert_eq!(svg.key(), SvgPath::new("M0,0 4,1 2,5").unwrap().key());
        assert_eq!(
            Polyline::<FinePoint>::new(&[])
                .key()
                .unwrap()
                .stream_points(),
            0
        );
    }
}
