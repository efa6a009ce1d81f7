//! Outlines kept from one frame to the next, in caller-provided segments.
//!
//! A shape is described again in every band it touches: for the curves of
//! a dial (circles, arcs, rounded corners) or a chart's stroke that is
//! most of a frame's cost after the flush. A [`ShapeCache`] keeps the
//! outline of every shape that has a key
//! ([`Shape::key`](crate::path::Shape::key): circles, ellipses, arcs,
//! sectors, rectangles, rounded rectangles and lines by their geometry;
//! polylines, polygons and SVG paths by their description), filled or
//! stroked without dashes: the first band that draws it describes it
//! whole into the cache's segments, and every later band, in this frame
//! and the next ones, walks the segments kept (only those crossing the
//! band's rows). The segments are those the shape describes, in the same
//! order and with the same numbers, so the pixels are those of the shape
//! drawn directly.
//!
//! An outline is found by its key (the shape's geometry, the stroke, the
//! tolerance), compared exactly, so a scene that changes keeps what did
//! not change and describes what did. A shape known by its description
//! has its description kept too, as the points its path sends (tag points
//! marking each call: `path::shape::key`), in the segments before its
//! outline; its key holds their number and a hash of them, and the kept
//! points are compared with the shape's, point for point, before its
//! outline is filled (16 bytes for every two points: a 60-point polyline
//! 31 segments). Entries not drawn in the current
//! frame make room when the segments run short (the segments kept are then
//! moved together); a shape whose outline still does not fit, or whose
//! stroke fails, is marked and drawn directly from then on.

use core::ops::Range;

use super::FineRect;
use crate::geom::PathSink;
use crate::path::shape::{same_stream, write_stream};
use crate::path::{
    LineCap, LineJoin, MiterLimit, Segment, SegmentBuffer, ShapeKey, StrokeAlignment, StrokeStyle,
    Tolerance,
};

/// What an outline is made of: a shape, and how it is outlined.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct OutlineKey {
    shape: ShapeKey,
    /// `None` for the shape's fill.
    stroke: Option<SolidStroke>,
    tol: Tolerance,
}

/// A stroke style without dashes, by value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct SolidStroke {
    width: u32,
    join: LineJoin,
    miter_limit: MiterLimit,
    cap: LineCap,
    alignment: StrokeAlignment,
}

impl OutlineKey {
    /// The fill of `shape`.
    pub(crate) fn fill(shape: ShapeKey, tol: Tolerance) -> Self {
        Self {
            shape,
            stroke: None,
            tol,
        }
    }

    /// The stroke of `shape` by `style`; `None` for a dashed style (its
    /// pattern is borrowed, not kept).
    pub(crate) fn stroke(shape: ShapeKey, style: &StrokeStyle<'_>, tol: Tolerance) -> Option<Self> {
        // Every field named: a new one must be considered here.
        let StrokeStyle {
            width,
            join,
            miter_limit,
            cap,
            dash,
            alignment,
        } = *style;
        if dash.is_some() {
            return None;
        }
        Some(Self {
            shape,
            stroke: Some(SolidStroke {
                width,
                join,
                miter_limit,
                cap,
                alignment,
            }),
            tol,
        })
    }
}

/// `len` of an entry whose shape is drawn directly (not kept).
const DIRECT: u32 = u32::MAX;

/// One kept outline of a [`ShapeCache`]; make arrays of them with
/// [`ShapeEntry::EMPTY`]. [`ShapeEntry::SIZE`] bytes each (about a hundred).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShapeEntry {
    key: Option<OutlineKey>,
    /// The outline's segments, `start..start + len` of the cache's; `len`
    /// is [`DIRECT`] for a shape drawn directly.
    start: u32,
    len: u32,
    /// The frame that last drew it.
    frame: u32,
    /// The shape's bounds, as the direct drawing finds them.
    bounds: Option<FineRect>,
}

impl ShapeEntry {
    /// An unused entry.
    pub const EMPTY: Self = Self {
        key: None,
        start: 0,
        len: 0,
        frame: 0,
        bounds: None,
    };

    /// Bytes an entry takes.
    pub const SIZE: usize = core::mem::size_of::<Self>();

    /// Holding segments.
    fn kept(&self) -> bool {
        self.key.is_some() && self.len != DIRECT
    }

    fn end(&self) -> usize {
        if self.kept() {
            self.start as usize + self.len as usize
        } else {
            0
        }
    }
}

impl Default for ShapeEntry {
    fn default() -> Self {
        Self::EMPTY
    }
}

/// The outlines of a scene's shapes, kept from band to band and frame to
/// frame: a view over caller-provided segments (16 bytes each) and entries
/// (one a shape), made for each band over the same slices. `frame` names
/// the frame being drawn: any number that changes from one frame to the
/// next (a [`Renderer`](crate::render::Renderer) with a shape cache counts
/// them itself); what the last frames drew and this one has not yet is
/// what makes room. Give every view the same slices, and do not write the
/// segments between frames: an entry knows where its outline lies, not
/// what it was (an outline beyond the segments given is described again,
/// but one overwritten in place would be filled as it now reads).
///
/// ```
/// use softedge::canvas::{Canvas, ShapeCache, ShapeEntry};
/// use softedge::geom::FinePoint;
/// use softedge::path::{Ellipse, Segment};
/// use softedge::style::{Blend, FillRule, Opacity};
/// use softedge::{Band, BandBuffer, Bands};
/// let mut segments = [Segment::default(); 256];
/// let mut entries = [ShapeEntry::EMPTY; 4];
/// let (mut acc, mut cover) = ([0i32; 40 * 8], [0i32; BandBuffer::<1>::cover_len(40, 8)]);
/// let disc = Ellipse::new(FinePoint::new(20 * 1024, 20 * 1024), 12 * 1024, 9 * 1024);
/// for frame in 0..2 {
///     for band in Bands::new(40, 40, 8) {
///         let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
///         buf.clear([0]);
///         let shapes = ShapeCache::new(&mut segments, &mut entries, frame);
///         let mut canvas = Canvas::new(&mut buf, None).with_shapes(shapes);
///         canvas.fill_shape(&disc, [4095], FillRule::NonZero, Blend::Over, Opacity::OPAQUE).unwrap();
///         // Described in the first band of the first frame, kept since.
///         let (kept, described) = canvas.shape_stats();
///         assert_eq!(described, u32::from(frame == 0 && band.y0 == 0));
///         assert_eq!(kept, 1 - described);
///     }
/// }
/// ```
#[derive(Debug)]
pub struct ShapeCache<'a> {
    segments: &'a mut [Segment],
    entries: &'a mut [ShapeEntry],
    frame: u32,
    /// Where the next lookup starts: after the last entry found. Shapes
    /// are drawn in the same order in every band, and their entries are
    /// made in that order, so a band's lookups each find their entry at
    /// the first compare.
    cursor: usize,
    /// Outlines found kept, and outlines described into the cache.
    hits: u32,
    records: u32,
}

impl<'a> ShapeCache<'a> {
    /// A view of `segments` and `entries` (any numbers; none is a valid,
    /// empty cache) for frame `frame`, keeping what they hold.
    pub fn new(segments: &'a mut [Segment], entries: &'a mut [ShapeEntry], frame: u32) -> Self {
        Self {
            segments,
            entries,
            frame,
            cursor: 0,
            hits: 0,
            records: 0,
        }
    }

    /// The frame after the last one `entries` were drawn in (for a frame
    /// counter that starts over, as a renderer made for each frame does).
    pub fn next_frame(entries: &[ShapeEntry]) -> u32 {
        entries
            .iter()
            .filter(|e| e.key.is_some())
            .map(|e| e.frame)
            .max()
            .map_or(1, |f| f.wrapping_add(1))
    }

    /// Forgets every outline.
    pub fn clear(&mut self) {
        self.entries.fill(ShapeEntry::EMPTY);
    }

    /// Outlines found kept, and outlines described into the cache, through
    /// this view.
    pub fn stats(&self) -> (u32, u32) {
        (self.hits, self.records)
    }

    /// Outlines kept, the segments they hold, and shapes marked to be
    /// drawn directly (their outline found no room, or their stroke
    /// failed): for sizing a cache, after the scene was drawn once. A
    /// cache that keeps every shape of its scene has none of the last.
    pub fn used(&self) -> (usize, usize, usize) {
        let kept = self.entries.iter().filter(|e| e.kept()).count();
        let segments = self
            .entries
            .iter()
            .filter(|e| e.kept())
            .map(|e| e.len as usize)
            .sum();
        let direct = self
            .entries
            .iter()
            .filter(|e| e.key.is_some() && !e.kept())
            .count();
        (kept, segments, direct)
    }

    /// The segments `r` of a kept outline.
    pub(crate) fn segments(&self, r: Range<usize>) -> &[Segment] {
        self.segments.get(r).unwrap_or_default()
    }

    /// The kept outline of `key`: its segments and its bounds. Not kept
    /// yet: `bounds` and `describe` (false on a failure) make it, into the
    /// free segments, if an entry and room are found. `None`: draw the
    /// shape directly. `path` describes the shape: for a shape known by
    /// its description (a polyline, a polygon, an SVG path) the entry keeps
    /// that description before the outline, and an outline is used only
    /// when the description kept is `path`'s, point for point.
    pub(crate) fn outline(
        &mut self,
        key: OutlineKey,
        bounds: impl FnOnce() -> Option<FineRect>,
        describe: impl Fn(&mut SegmentBuffer<'_>) -> bool,
        path: &dyn Fn(&mut dyn PathSink),
    ) -> Option<(Range<usize>, Option<FineRect>)> {
        // The description's segments at the front of the entry's.
        let head = key.shape.stream_segments();
        let frame = self.frame;
        let n = self.entries.len();
        let from = if self.cursor < n { self.cursor } else { 0 };
        let found = (from..n).chain(0..from).find(|&i| {
            self.entries
                .get(i)
                .is_some_and(|e| e.key.as_ref() == Some(&key))
        });
        let mut retry = None;
        let held = self.segments.len();
        if let Some(i) = found {
            self.cursor = i + 1;
            let e = self.entries.get_mut(i)?;
            let first_this_frame = e.frame != frame;
            e.frame = frame;
            let (start, end) = (e.start as usize, e.end());
            let (kept, bounds) = (e.kept(), e.bounds);
            if kept && end <= held && head <= end - start {
                let kept_path = self.segments.get(start..start + head).unwrap_or_default();
                if head == 0 || same_stream(path, kept_path, key.shape.stream_points()) {
                    self.hits += 1;
                    return Some((start + head..end, bounds));
                }
                // Another shape of the same hash: this one's outline
                // replaces it.
            } else if !kept && !first_this_frame {
                // Drawn directly (its outline found no room, or its stroke
                // failed): tried again once a frame, room may have been
                // freed since. (Or kept over other segments than these, the
                // entries given other slices: described again.)
                return None;
            }
            retry = Some(i);
        }
        // An empty entry, else the one drawn longest ago, not in this frame.
        let slot = match (retry, self.entries.iter().position(|e| e.key.is_none())) {
            (Some(i), _) | (None, Some(i)) => i,
            (None, None) => {
                self.entries
                    .iter()
                    .enumerate()
                    .filter(|(_, e)| e.frame != frame)
                    .max_by_key(|(_, e)| frame.wrapping_sub(e.frame))?
                    .0
            }
        };
        *self.entries.get_mut(slot)? = ShapeEntry::EMPTY;
        let bounds = bounds();
        let mut kept = None;
        for attempt in 0..2 {
            let start = self.entries.iter().map(ShapeEntry::end).max().unwrap_or(0);
            let free = self.segments.get_mut(start..).unwrap_or_default();
            let fits = head <= free.len();
            let (kept_path, rest) = free.split_at_mut(head.min(free.len()));
            let mut buf = SegmentBuffer::new(rest);
            if fits && !describe(&mut buf) {
                break;
            }
            if fits && !buf.overflowed() && (head == 0 || write_stream(path, kept_path)) {
                kept = Some((start, head + buf.segments().len()));
                break;
            }
            // Short of room: drop what this frame has not drawn and move
            // the rest together, then once more.
            if attempt > 0 || !self.compact() {
                break;
            }
        }
        let e = self.entries.get_mut(slot)?;
        *e = ShapeEntry {
            key: Some(key),
            start: 0,
            len: DIRECT,
            frame,
            bounds,
        };
        let (start, len) = kept?;
        (e.start, e.len) = (start as u32, len as u32);
        self.records += 1;
        Some((start + head..start + len, bounds))
    }

    /// Drops the outlines not drawn in this frame and moves the others to
    /// the front of the segments, in order; whether any room was made.
    fn compact(&mut self) -> bool {
        let frame = self.frame;
        let before = self.entries.iter().map(ShapeEntry::end).max().unwrap_or(0);
        let held = self.segments.len();
        for e in self.entries.iter_mut() {
            if e.frame != frame || (e.kept() && e.end() > held) {
                *e = ShapeEntry::EMPTY;
            } else if e.len == 0 {
                e.start = 0;
            }
        }
        let mut pos = 0usize;
        // Each kept outline in the order of its segments: the one starting
        // lowest at or after `pos` (those moved start below it, and the
        // empty ones are left at 0).
        while let Some(e) = self
            .entries
            .iter_mut()
            .filter(|e| e.kept() && e.len > 0 && e.start as usize >= pos)
            .min_by_key(|e| e.start)
        {
            let (start, len) = (e.start as usize, e.len as usize);
            // Kept outlines end within the segments and do not overlap, so
            // `pos <= start` and the move stays inside; checked all the
            // same (an outline that did not would be dropped), which keeps
            // `copy_within`'s panics out of the firmware.
            if pos > start || start.saturating_add(len) > self.segments.len() {
                *e = ShapeEntry::EMPTY;
                continue;
            }
            e.start = pos as u32;
            // Forwards, as the source starts at or after the destination.
            for k in 0..len {
                let v = self.segments.get(start + k).copied();
                if let (Some(v), Some(d)) = (v, self.segments.get_mut(pos + k)) {
                    *d = v;
                }
            }
            pos += len;
        }
        pos < before
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec::Vec;

    use super::*;
    use crate::band::{BandBuffer, Bands};
    use crate::canvas::{Canvas, WalkCache, WalkSlot};
    use crate::geom::FinePoint;
    use crate::path::testing::Lcg;
    use crate::path::{
        Arc, Circle, CornerRadii, Dash, Degrees, Ellipse, Line, Rectangle, RoundedRectangle, Sector,
    };
    use crate::style::{Blend, FillRule, Opacity};

    const DASHES: [u32; 2] = [3000, 1500];

    /// One drawn shape: the geometry, and a stroke (width, join, cap,
    /// alignment, dashed) or a fill.
    #[derive(Clone, Copy)]
    struct Item {
        kind: u32,
        c: FinePoint,
        r: u32,
        r2: u32,
        a: i32,
        s: i32,
        stroke: Option<(u32, u32, u32, u32, bool)>,
        color: u16,
        blend: Blend,
        op: Opacity,
    }

    fn random_item(next: &mut impl FnMut(u32) -> u32) -> Item {
        let stroke = (next(3) == 0).then(|| {
            let dashed = next(4) == 0;
            (1 + next(6000), next(3), next(3), next(3), dashed)
        });
        Item {
            kind: next(11),
            c: FinePoint::new(next(72 * 1024) as i32 - 4096, next(56 * 1024) as i32 - 4096),
            r: 1 + (next(30_000) >> next(6)),
            r2: 1 + (next(30_000) >> next(6)),
            a: next(720) as i32 - 360,
            s: next(720) as i32 - 360,
            stroke,
            color: next(4096) as u16,
            blend: if next(5) == 0 {
                Blend::Add
            } else {
                Blend::Over
            },
            op: Opacity::from_ratio(1 + next(4), 4).unwrap(),
        }
    }

    /// An opaque flat disc of radius `r` px centred on `(x, y)` px.
    fn disc(x: i32, y: i32, r: u32) -> Item {
        Item {
            kind: 0,
            c: FinePoint::new(x * 1024, y * 1024),
            r: r * 1024,
            r2: 0,
            a: 0,
            s: 0,
            stroke: None,
            color: 3000,
            blend: Blend::Over,
            op: Opacity::OPAQUE,
        }
    }

    /// The segments of a disc's fill (a round ellipse: a `Circle` is
    /// drawn from its exact areas, never kept).
    fn disc_segments(it: &Item) -> usize {
        let mut store = std::vec![Segment::default(); 4096];
        let mut buf = SegmentBuffer::new(&mut store);
        crate::path::Shape::fill(&Ellipse::new(it.c, it.r, it.r), &mut buf);
        buf.segments().len()
    }

    fn draw(c: &mut Canvas<'_, '_, 1>, it: &Item) {
        let rect = Rectangle::new(it.c, 2 * it.r, it.r2);
        let shape: &dyn Fn(&mut Canvas<'_, '_, 1>) = &|c| {
            let mut put = |s: &dyn Drawn| s.draw(c, it);
            match it.kind {
                0 => put(&Ellipse::new(it.c, it.r, it.r)),
                1 => {
                    let mut e = Ellipse::new(it.c, it.r, it.r2);
                    e.rotation = Degrees::new(it.a);
                    put(&e)
                }
                2 => put(&Arc::new(
                    it.c,
                    it.r,
                    Degrees::new(it.a),
                    Degrees::new(it.s),
                )),
                3 => put(&Sector::new(
                    it.c,
                    it.r,
                    Degrees::new(it.a),
                    Degrees::new(it.s),
                )),
                4 => put(&rect),
                5 => put(&RoundedRectangle::new(
                    rect,
                    CornerRadii::uniform(it.r.min(it.r2) / 3),
                )),
                6 => put(&Line::new(
                    it.c,
                    FinePoint::new(it.c.x + it.a * 97, it.c.y + it.s * 61),
                )),
                // Kept by their descriptions.
                7 => put(&crate::path::Polygon::new(&points(it))),
                8 => put(&crate::path::Polyline::new(&points(it))),
                9 => {
                    let [p, q, r] = points(it).map(|p| (p.x as f64 / 1024.0, p.y as f64 / 1024.0));
                    let d = std::format!(
                        "M {} {} Q {} {} {} {} C {} {} {} {} {} {} Z",
                        p.0,
                        p.1,
                        q.0,
                        q.1,
                        r.0,
                        r.1,
                        p.0,
                        r.1,
                        q.0,
                        p.1,
                        p.0 + 3.0,
                        p.1
                    );
                    if let Ok(svg) = crate::path::svg::SvgPath::new(&d) {
                        put(&svg)
                    }
                }
                // No key: drawn directly, between shapes kept.
                _ => put(&NoKey(crate::path::Polygon::new(&points(it)))),
            }
        };
        shape(c);
    }

    /// The three vertices of an item's polygon, polyline or SVG path.
    fn points(it: &Item) -> [FinePoint; 3] {
        [
            it.c,
            FinePoint::new(it.c.x + it.a * 97, it.c.y + it.s * 61),
            FinePoint::new(it.c.x + it.s * 53, it.c.y + it.r as i32),
        ]
    }

    /// A shape of another crate: described as the shape it wraps, without
    /// a key.
    struct NoKey<S>(S);

    impl<S: crate::path::Shape> crate::path::Shape for NoKey<S> {
        fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
            self.0.describe(sink);
        }
    }

    /// Object-safe drawing of one shape (fill or stroke).
    trait Drawn {
        fn draw(&self, c: &mut Canvas<'_, '_, 1>, it: &Item);
    }

    impl<S: crate::path::Shape> Drawn for S {
        fn draw(&self, c: &mut Canvas<'_, '_, 1>, it: &Item) {
            let r = match it.stroke {
                Some((w, j, cap, al, dashed)) => {
                    let joins = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel];
                    let caps = [LineCap::Butt, LineCap::Round, LineCap::Square];
                    let aligns = [
                        StrokeAlignment::Centre,
                        StrokeAlignment::Inside,
                        StrokeAlignment::Outside,
                    ];
                    let style = StrokeStyle::new(w)
                        .with_join(joins[j as usize])
                        .with_cap(caps[cap as usize])
                        .with_alignment(aligns[al as usize]);
                    if dashed {
                        let style = style.with_dash(Dash::new(&DASHES, 700));
                        c.stroke_shape(self, &style, [it.color], it.blend, it.op)
                    } else {
                        c.stroke_shape(self, &style, [it.color], it.blend, it.op)
                    }
                }
                None => c.fill_shape(self, [it.color], FillRule::NonZero, it.blend, it.op),
            };
            // Errors (a shape beyond the range, a failed stroke) are the
            // same either way; the pixels are compared.
            let _ = r;
        }
    }

    /// A 64x48 frame of `scene` in bands of `rows`, with the shape cache
    /// `shapes` (segments, entries, frame) or none; the resolved values,
    /// the shapes skipped, and the cache's (kept, described).
    fn frame(
        scene: &[Item],
        rows: u16,
        mut shapes: Option<(&mut [Segment], &mut [ShapeEntry], u32)>,
    ) -> (Vec<u16>, u32, (u32, u32)) {
        let (w, h) = (64u16, 48u16);
        let mut acc = std::vec![0i32; BandBuffer::<1>::acc_len(w, rows)];
        let mut cover = std::vec![0i32; BandBuffer::<1>::cover_len(w, rows)];
        let mut slots = std::vec![WalkSlot::<1>::EMPTY; 24];
        WalkCache::new(&mut slots).clear();
        let mut out = std::vec![0u16; usize::from(w) * usize::from(h)];
        let (mut skipped, mut stats) = (0, (0, 0));
        for band in Bands::new(w, h, rows) {
            let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
            buf.clear([250]);
            let mut canvas = Canvas::new(&mut buf, Some(WalkCache::new(&mut slots)));
            if let Some((segs, entries, f)) = shapes.as_mut() {
                canvas = canvas.with_shapes(ShapeCache::new(segs, entries, *f));
            }
            for it in scene {
                draw(&mut canvas, it);
            }
            skipped += canvas.skipped().count;
            let (k, d) = canvas.shape_stats();
            stats = (stats.0 + k, stats.1 + d);
            for y in band.row_range() {
                for x in 0..w {
                    out[y as usize * usize::from(w) + usize::from(x)] =
                        buf.lin12(i32::from(x), y).unwrap()[0];
                }
            }
        }
        (out, skipped, stats)
    }

    #[test]
    fn kept_outlines_fill_to_the_bits_of_the_shapes_drawn_directly() {
        let mut rng = Lcg(0x0c0f_fee5_7a7e_5eed);
        let mut next = |m: u32| rng.below(u64::from(m)) as u32;
        let mut kept_somewhere = 0;
        for case in 0..60 {
            let n = 1 + next(6) as usize;
            let scene: Vec<Item> = (0..n).map(|_| random_item(&mut next)).collect();
            // The same scene with one shape changed, and one more.
            let mut changed = scene.clone();
            let k = next(n as u32) as usize;
            changed[k] = random_item(&mut next);
            changed.push(random_item(&mut next));
            let direct = frame(&scene, 48, None);
            let direct2 = frame(&changed, 48, None);
            // Room for everything, for a little, for nothing.
            let cap = [8192, 40 + next(400) as usize, 0][case % 3];
            let n_entries = [16, 1 + next(4) as usize, 0][(case / 3) % 3];
            let mut segs = std::vec![Segment::default(); cap];
            let mut entries = std::vec![ShapeEntry::EMPTY; n_entries];
            let rows = [1, 5, 16, 48][case % 4];
            for (f, (s, want)) in [
                (&scene, &direct),
                (&scene, &direct),
                (&changed, &direct2),
                (&scene, &direct),
            ]
            .into_iter()
            .enumerate()
            {
                let got = frame(s, rows, Some((&mut segs, &mut entries, f as u32)));
                assert!(got.0 == want.0, "case {case}, frame {f}, {rows} rows");
                assert_eq!(got.1, want.1, "case {case}, frame {f}: skipped shapes");
                if f == 1 && cap == 8192 && n_entries == 16 {
                    // The second frame of the same scene describes nothing.
                    assert_eq!(got.2 .1, 0, "case {case}");
                    kept_somewhere += got.2 .0;
                }
            }
        }
        assert!(kept_somewhere > 50, "{kept_somewhere}");
    }

    #[test]
    fn a_full_cache_makes_room_from_what_the_frame_has_not_drawn() {
        let a = [disc(20, 20, 12)];
        let b = [disc(40, 24, 14)];
        let len = disc_segments(&a[0]).max(disc_segments(&b[0]));
        // Room for one disc's outline, not for two.
        let mut segs = std::vec![Segment::default(); len + len / 2];
        let mut entries = std::vec![ShapeEntry::EMPTY; 4];
        let want_a = frame(&a, 48, None).0;
        let want_b = frame(&b, 48, None).0;
        for (f, (scene, want)) in [(&a, &want_a), (&b, &want_b), (&a, &want_a)]
            .into_iter()
            .enumerate()
        {
            let (got, _, (kept, described)) =
                frame(scene, 8, Some((&mut segs, &mut entries, f as u32)));
            assert!(got == *want, "frame {f}");
            // Each frame's disc is described in its first band (the
            // other disc's outline moved out of its way) and kept for the
            // other five.
            assert_eq!((kept, described), (5, 1), "frame {f}");
        }
    }

    #[test]
    fn outlines_drawn_this_frame_move_together_to_make_room() {
        let disc = |x: i32, r: u32| Item {
            color: 1000 + 900 * x as u16 / 8,
            op: Opacity::from_percent(75),
            ..disc(x, 24, r)
        };
        let (a, b, c) = (disc(14, 10), disc(32, 12), disc(50, 11));
        let (na, nb, nc) = (disc_segments(&a), disc_segments(&b), disc_segments(&c));
        // Room for a and b, or b and c, not for all three: in the second
        // frame c is described after a's outline is dropped and b's moved
        // to the front.
        let mut segs = std::vec![Segment::default(); na.max(nc) + nb];
        let mut entries = std::vec![ShapeEntry::EMPTY; 4];
        for (f, scene) in [std::vec![a, b], std::vec![b, c], std::vec![b, c]]
            .into_iter()
            .enumerate()
        {
            let want = frame(&scene, 48, None).0;
            let (got, _, (_, described)) =
                frame(&scene, 6, Some((&mut segs, &mut entries, f as u32)));
            assert!(got == want, "frame {f}");
            assert_eq!(described, [2, 1, 0][f], "frame {f}");
        }
    }

    #[test]
    fn every_stroke_field_and_the_tolerance_are_in_the_key() {
        use crate::path::Shape;
        let k = Circle::new(FinePoint::new(9000, 9000), 5000).key().unwrap();
        let base = StrokeStyle::new(2048);
        let tol = Tolerance::DEFAULT;
        let styles = [
            StrokeStyle::new(2049),
            base.with_join(LineJoin::Round),
            base.with_miter_limit(MiterLimit::from_int(3)),
            base.with_cap(LineCap::Square),
            base.with_alignment(StrokeAlignment::Inside),
        ];
        let of = |s: &StrokeStyle<'_>| OutlineKey::stroke(k, s, tol).unwrap();
        for s in &styles {
            assert_ne!(of(s), of(&base), "{s:?}");
        }
        assert_eq!(of(&base), of(&StrokeStyle::new(2048)));
        assert_ne!(OutlineKey::fill(k, tol), of(&base));
        assert_ne!(
            OutlineKey::fill(k, tol),
            OutlineKey::fill(k, Tolerance::new(tol.fine() + 1))
        );
        let dashes = [100, 200];
        assert!(OutlineKey::stroke(k, &base.with_dash(Dash::new(&dashes, 0)), tol).is_none());
    }

    #[test]
    fn a_shape_without_a_key_leaves_the_cache_to_the_next() {
        let item = |kind: u32, x: i32| Item {
            kind,
            r2: 6 * 1024,
            a: 40,
            s: 90,
            color: 2000,
            ..disc(x, 20, 9)
        };
        // A disc, a shape without a key, a disc.
        let scene = [item(0, 16), item(10, 30), item(0, 44)];
        let mut segs = std::vec![Segment::default(); 2048];
        let mut entries = std::vec![ShapeEntry::EMPTY; 4];
        let want = frame(&scene, 48, None).0;
        for f in 0..2 {
            let (got, _, stats) = frame(&scene, 8, Some((&mut segs, &mut entries, f)));
            assert!(got == want, "frame {f}");
            // Both discs looked up in each of the 6 bands: described in
            // the first frame's first band, kept since.
            assert_eq!(stats, if f == 0 { (10, 2) } else { (12, 0) }, "frame {f}");
        }
    }

    #[test]
    fn a_shape_drawn_directly_for_lack_of_room_is_tried_again_next_frame() {
        let (a, b) = (disc(16, 24, 12), disc(46, 24, 12));
        // Room for one disc.
        let mut segs = std::vec![Segment::default(); disc_segments(&a) + 8];
        let mut entries = std::vec![ShapeEntry::EMPTY; 4];
        for (f, scene, described) in [
            (0, std::vec![a, b], 1),
            (1, std::vec![b], 1),
            (2, std::vec![b], 0),
        ] {
            let want = frame(&scene, 48, None).0;
            let (got, _, (_, d)) = frame(&scene, 12, Some((&mut segs, &mut entries, f)));
            assert!(got == want, "frame {f}");
            assert_eq!(d, described, "frame {f}");
        }
    }

    #[test]
    fn entries_given_other_segments_describe_again_without_a_panic() {
        let mut rng = Lcg(0x51ce_0f0e_77e2_4a11);
        let mut next = |m: u32| rng.below(u64::from(m)) as u32;
        let scene: Vec<Item> = (0..5).map(|_| random_item(&mut next)).collect();
        let want = frame(&scene, 48, None).0;
        let mut big = std::vec![Segment::default(); 8192];
        let mut entries = std::vec![ShapeEntry::EMPTY; 8];
        let got = frame(&scene, 16, Some((&mut big, &mut entries, 0))).0;
        assert!(got == want);
        // The same entries over fewer segments (a misuse): the outlines
        // that lie beyond them are described again, into these.
        for (f, len) in [(1u32, 40usize), (2, 0), (3, 300)] {
            let mut small = std::vec![Segment::default(); len];
            let got = frame(&scene, 16, Some((&mut small, &mut entries, f))).0;
            assert!(got == want, "frame {f}");
        }
    }

    /// A polyline, the polygon of the same points and the same polyline
    /// moved by one fine unit: three outlines, each kept by its own entry
    /// and found again in every band and frame; the pixels those of the
    /// shapes drawn directly.
    #[test]
    fn polylines_and_polygons_are_kept_by_their_points() {
        let line = |x: i32| Item {
            kind: 8,
            a: 30,
            s: -20,
            stroke: Some((2500, 1, 1, 0, false)),
            ..disc(x, 24, 9)
        };
        let moved = Item {
            c: FinePoint::new(line(20).c.x + 1, line(20).c.y),
            ..line(20)
        };
        let scene = [
            line(20),
            Item {
                kind: 7,
                ..line(20)
            },
            moved,
        ];
        let mut segs = std::vec![Segment::default(); 4096];
        let mut entries = std::vec![ShapeEntry::EMPTY; 4];
        let want = frame(&scene, 48, None).0;
        for f in 0..3 {
            let (got, _, stats) = frame(&scene, 8, Some((&mut segs, &mut entries, f)));
            assert!(got == want, "frame {f}");
            // Six bands: three outlines described in the first band of
            // the first frame, found in every other lookup.
            assert_eq!(stats, if f == 0 { (15, 3) } else { (18, 0) }, "frame {f}");
        }
        assert_eq!(ShapeCache::new(&mut segs, &mut entries, 3).used().0, 3);
    }

    /// Two different shapes under one key (what a hash's collision would
    /// give): the description kept is compared point for point, so the
    /// second never gets the first's outline; each takes the entry over.
    #[test]
    fn a_key_shared_by_two_descriptions_never_gives_the_wrong_outline() {
        use crate::path::{Polyline, Shape};
        let a = [FinePoint::new(0, 0), FinePoint::new(9000, 4000)];
        let b = [FinePoint::new(0, 0), FinePoint::new(9000, 4001)];
        let key = OutlineKey::fill(Polyline::new(&a).key().unwrap(), Tolerance::DEFAULT);
        let mut segs = std::vec![Segment::default(); 64];
        let mut entries = std::vec![ShapeEntry::EMPTY; 2];
        let mut cache = ShapeCache::new(&mut segs, &mut entries, 1);
        let mut lookup = |pts: &[FinePoint], mark: i32| {
            let shape = Polyline::new(pts);
            let r = cache.outline(
                key,
                || None,
                |buf| {
                    crate::path::SegmentSink::segment(
                        buf,
                        FinePoint::new(mark, 0),
                        FinePoint::new(mark, 1),
                    );
                    true
                },
                &|sink| shape.describe(sink),
            );
            let (range, _) = r.unwrap();
            let got = cache.segments(range);
            assert_eq!(got.len(), 1);
            got[0].from.x
        };
        assert_eq!(lookup(&a, 1), 1);
        assert_eq!(lookup(&a, 2), 1, "kept");
        assert_eq!(lookup(&b, 3), 3, "not a's outline");
        assert_eq!(lookup(&b, 4), 3, "kept");
        assert_eq!(lookup(&a, 5), 5, "not b's outline");
        assert_eq!(cache.stats(), (2, 3));
    }
}
