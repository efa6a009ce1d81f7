//! Paths, shapes and strokes as outlines the canvas fills: the bridge from
//! [`path`](crate::path)'s geometry to the band.
//!
//! A shape is described again in every band it touches (paths are not
//! stored: a path of any size works, at the cost of describing it per
//! band); its bounds, for rejecting the bands it misses, come from its
//! control points, which hold every curve (a Bézier lies in the hull of
//! its control polygon), widened by a stroke's reach. Inside a band the
//! canvas names its rows ([`SegmentSink::window`]), so the curves of
//! circles, ellipses, arcs, sectors and rounded corners compute only the
//! ends of the pieces of 8 vertices that miss them; the segments left out
//! are counted ([`SegmentSink::skipped`]), so every segment keeps its
//! number, by which the walk cache finds it in the next band.
//!
//! Or a shape's outline (its fill or its stroke's, 16 bytes a segment) is
//! kept in a [`ShapeCache`](super::ShapeCache) and the kept segments are
//! the outline ([`Kept`]): each band then visits them and walks those that
//! cross its rows (one compare of the y extent for the others). The same
//! segments in the same order: the same bits as the shape drawn directly.

use super::{FineRect, Outline};
use crate::geom::{FinePoint, PathSink, FINE_LIMIT};
use crate::path::{Segment, SegmentSink, Shape, StrokeError, StrokeStyle, Tolerance};

/// The box around every point a description names.
#[derive(Default)]
struct Bounds(Option<FineRect>);

impl Bounds {
    fn add(&mut self, p: FinePoint) {
        let r = self.0.get_or_insert(FineRect {
            x0: p.x,
            y0: p.y,
            x1: p.x,
            y1: p.y,
        });
        r.x0 = r.x0.min(p.x);
        r.y0 = r.y0.min(p.y);
        r.x1 = r.x1.max(p.x);
        r.y1 = r.y1.max(p.y);
    }
}

impl PathSink for Bounds {
    fn needs_clockwise(&self) -> bool {
        false
    }
    fn move_to(&mut self, p: FinePoint) {
        self.add(p);
    }
    fn line_to(&mut self, p: FinePoint) {
        self.add(p);
    }
    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        self.add(c);
        self.add(p);
    }
    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        self.add(c1);
        self.add(c2);
        self.add(p);
    }
    fn close(&mut self) {}
}

/// How far a filled or stroked shape's points may lie outside its
/// description's box, fine units: the area-preserving polygons of curves
/// put their vertices out of the curve by `(f - 1) r`, about `2.8` fine
/// units at every radius (the vertex count grows as `sqrt(r)`, see
/// [`arc`](crate::path::arc)), plus the grid rounding; the cubics of the
/// description stay within a quarter unit of the curve, their control
/// points (rounded) hold them.
const CURVE_MARGIN: i32 = 16;

/// The box around a shape's description (`None`: nothing described),
/// widened by [`CURVE_MARGIN`] so that it holds the shape's fill and its
/// stroke's ring too. A side within the coordinate range stays within it
/// (segments are clamped into the range, so none lies beyond it); a side
/// beyond it stays beyond, and the shape is rejected.
pub(crate) fn shape_bounds<S: Shape + ?Sized>(shape: &S) -> Option<FineRect> {
    let mut b = Bounds::default();
    shape.describe(&mut b);
    let grow = |v: i32, by: i32| {
        let w = v.saturating_add(by);
        if (-FINE_LIMIT..=FINE_LIMIT).contains(&v) {
            w.clamp(-FINE_LIMIT, FINE_LIMIT)
        } else {
            w
        }
    };
    b.0.map(|r| FineRect {
        x0: grow(r.x0, -CURVE_MARGIN),
        y0: grow(r.y0, -CURVE_MARGIN),
        x1: grow(r.x1, CURVE_MARGIN),
        y1: grow(r.y1, CURVE_MARGIN),
    })
}

/// Segments to a closure.
struct Segments<F>(F);

impl<F: FnMut(FinePoint, FinePoint)> SegmentSink for Segments<F> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        (self.0)(from, to);
    }
}

/// A shape's inside.
pub(crate) struct Filled<'s, S: ?Sized> {
    pub shape: &'s S,
    pub tol: Tolerance,
    pub bounds: Option<FineRect>,
}

impl<S: Shape + ?Sized> Outline for Filled<'_, S> {
    fn bounds(&self) -> Option<FineRect> {
        self.bounds
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, f: F) {
        self.shape.fill_with(self.tol, &mut Segments(f));
    }
    fn segments_into<K: SegmentSink>(&self, sink: &mut K) {
        self.shape.fill_with(self.tol, sink);
    }
}

/// A shape's stroke.
pub(crate) struct Stroked<'s, 'd, S: ?Sized> {
    pub shape: &'s S,
    pub style: &'s StrokeStyle<'d>,
    pub tol: Tolerance,
    pub bounds: Option<FineRect>,
    /// What the stroker reported (the first time).
    pub error: core::cell::Cell<Option<StrokeError>>,
}

impl<S: Shape + ?Sized> Stroked<'_, '_, S> {
    /// The shape's bounds widened by the stroke's reach. The stroke of a
    /// path within the coordinate range may reach beyond it (a line on the
    /// limit, half its width): its bounds are clamped to the range, as the
    /// stroker clamps its points; a path beyond the range keeps its bounds,
    /// and is rejected.
    pub(crate) fn widen(b: Option<FineRect>, style: &StrokeStyle<'_>) -> Option<FineRect> {
        let r = style.reach().min(i64::from(i32::MAX / 4)) as i32;
        b.map(|b| {
            let inside = [(b.x0, b.y0), (b.x1, b.y1)]
                .iter()
                .all(|&(x, y)| FinePoint::new(x, y).in_range());
            let lim = if inside { FINE_LIMIT } else { i32::MAX };
            FineRect {
                x0: b.x0.saturating_sub(r).max(-lim),
                y0: b.y0.saturating_sub(r).max(-lim),
                x1: b.x1.saturating_add(r).min(lim),
                y1: b.y1.saturating_add(r).min(lim),
            }
        })
    }
}

impl<S: Shape + ?Sized> Outline for Stroked<'_, '_, S> {
    fn bounds(&self) -> Option<FineRect> {
        self.bounds
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, f: F) {
        self.segments_into(&mut Segments(f));
    }
    fn segments_into<K: SegmentSink>(&self, sink: &mut K) {
        if let Err(e) = self.shape.stroke_with(self.style, self.tol, sink) {
            if self.error.get().is_none() {
                self.error.set(Some(e));
            }
        }
    }
}

/// `segments` to `sink`, in order; those whose y extent lies wholly
/// outside the sink's window are counted instead (they keep their
/// numbers).
fn replay_window<K: SegmentSink>(segments: &[Segment], sink: &mut K) {
    let Some((lo, hi)) = sink.window() else {
        for s in segments {
            sink.segment(s.from, s.to);
        }
        return;
    };
    for s in segments {
        let (a, b) = (s.from.y, s.to.y);
        if (a < lo && b < lo) || (a > hi && b > hi) {
            sink.skipped(1);
        } else {
            sink.segment(s.from, s.to);
        }
    }
}

/// An outline kept in a [`ShapeCache`](super::ShapeCache): its segments
/// (in each band, those whose y extent lies wholly outside the band's
/// rows are left out and counted: they keep their numbers for the walk
/// cache), and the bounds the shape drawn directly has (so that the bands
/// it is drawn in and the errors it gives are the same).
pub(crate) struct Kept<'s> {
    pub segments: &'s [Segment],
    pub bounds: Option<FineRect>,
}

impl Outline for Kept<'_> {
    fn bounds(&self) -> Option<FineRect> {
        self.bounds
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, mut f: F) {
        for s in self.segments {
            f(s.from, s.to);
        }
    }
    fn segments_into<K: SegmentSink>(&self, sink: &mut K) {
        replay_window(self.segments, sink);
    }
}

#[cfg(test)]
mod tests {
    extern crate std;

    use super::*;
    use crate::canvas::Canvas;
    use crate::path::testing::Lcg;
    use crate::path::{
        Arc, Circle, CornerRadii, Degrees, Ellipse, LineCap, LineJoin, Rectangle, RoundedRectangle,
        Sector,
    };

    /// Checks that every point a sink receives lies in a box.
    struct Inside(FineRect, u32);

    impl SegmentSink for Inside {
        fn segment(&mut self, a: FinePoint, b: FinePoint) {
            for p in [a, b] {
                let r = &self.0;
                if p.x < r.x0 || p.x > r.x1 || p.y < r.y0 || p.y > r.y1 {
                    self.1 += 1;
                }
            }
        }
    }

    fn check<S: Shape>(shape: &S, case: u32) {
        let tol = Tolerance::DEFAULT;
        if let Some(b) = shape_bounds(shape) {
            let mut k = Inside(b, 0);
            shape.fill_with(tol, &mut k);
            assert_eq!(k.1, 0, "case {case}: a fill point outside the bounds");
        }
        // The shape's own stroke; and the stroker's at the coarser
        // tolerances a stroke past its work budget is built with
        // (`path::stroke::budget`), whose round parts stand out more.
        let coarse = crate::path::stroke::budget::COARSEST;
        let tols = [Tolerance::coarse(768), Tolerance::coarse(coarse)];
        for cap in [LineCap::Butt, LineCap::Round, LineCap::Square] {
            let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][case as usize % 3];
            let style = StrokeStyle::new(300 + case * 37 % 4000)
                .with_cap(cap)
                .with_join(join);
            if let Some(b) = Stroked::<S>::widen(shape_bounds(shape), &style) {
                let mut k = Inside(b, 0);
                let _ = shape.stroke_with(&style, tol, &mut k);
                assert_eq!(k.1, 0, "case {case}: a stroke point outside the bounds");
                for t in tols {
                    let mut k = Inside(b, 0);
                    let mut st = crate::path::Stroker::with_tolerance(&style, t, &mut k);
                    shape.describe(&mut st);
                    let _ = st.finish();
                    assert_eq!(
                        k.1, 0,
                        "case {case} {t:?}: a stroke point outside the bounds"
                    );
                }
            }
        }
    }

    #[test]
    fn every_point_of_a_shape_lies_in_its_bounds() {
        // Small radii most of all: there the area-preserving polygons'
        // vertices stand out of the curve by a few fine units.
        let mut rng = Lcg(0x1f2e_3d4c_5b6a_7988);
        let mut next = |m: u32| rng.below(u64::from(m)) as u32;
        for case in 0..3000 {
            let c = FinePoint::new(50_000 + next(4096) as i32, 50_000 + next(4096) as i32);
            let r = 1 + (next(40_000) >> next(12));
            let r2 = 1 + (next(40_000) >> next(12));
            let (a, s) = (
                Degrees::new(next(720) as i32 - 360),
                Degrees::new(next(720) as i32 - 360),
            );
            check(&Circle::new(c, r), case);
            check(&Ellipse::new(c, r, r2), case);
            check(&Arc::new(c, r, a, s), case);
            check(&Sector::new(c, r, a, s), case);
            let rect = Rectangle::new(c, 2 * r, 2 * r2);
            check(
                &RoundedRectangle::new(rect, CornerRadii::uniform(r.min(r2) / 2)),
                case,
            );
            let pts = [
                c,
                FinePoint::new(c.x + r as i32, c.y),
                FinePoint::new(c.x, c.y + r2 as i32),
            ];
            check(&crate::path::Polyline::new(&pts), case);
        }
    }

    /// [`frame`] through a canvas with a shape cache over `segments` and
    /// `entries` (frame `frame_no`) and no walk cache; the resolved linear
    /// values, and the cache's (kept, described).
    fn kept_frame(
        w: u16,
        rows: u16,
        (segments, entries, frame_no): (&mut [Segment], &mut [crate::canvas::ShapeEntry], u32),
        mut draw: impl FnMut(&mut Canvas<'_, '_, 1>),
    ) -> (std::vec::Vec<u16>, (u32, u32)) {
        use crate::band::{BandBuffer, Bands};
        use crate::canvas::ShapeCache;
        let mut acc = std::vec![0i32; BandBuffer::<1>::acc_len(w, rows)];
        let mut cover = std::vec![0i32; BandBuffer::<1>::cover_len(w, rows)];
        let mut out = std::vec![0u16; usize::from(w) * 48];
        let mut stats = (0, 0);
        for band in Bands::new(w, 48, rows) {
            let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
            buf.clear([300]);
            let (k, d) = {
                let view = ShapeCache::new(segments, entries, frame_no);
                let mut canvas = Canvas::new(&mut buf, None).with_shapes(view);
                draw(&mut canvas);
                canvas.shape_stats()
            };
            stats = (stats.0 + k, stats.1 + d);
            for y in band.row_range() {
                for x in 0..w {
                    out[y as usize * usize::from(w) + usize::from(x)] =
                        buf.lin12(i32::from(x), y).unwrap()[0];
                }
            }
        }
        (out, stats)
    }

    /// A `w x 48` frame in bands of `rows`, each drawn by `draw` on a
    /// canvas with a walk cache; the resolved linear values, and the
    /// shapes the bands skipped.
    fn frame(
        w: u16,
        rows: u16,
        mut draw: impl FnMut(&mut Canvas<'_, '_, 1>),
    ) -> (std::vec::Vec<u16>, u32) {
        use crate::band::{BandBuffer, Bands};
        use crate::canvas::{WalkCache, WalkSlot};
        let h = 48;
        let mut acc = std::vec![0i32; BandBuffer::<1>::acc_len(w, rows)];
        let mut cover = std::vec![0i32; BandBuffer::<1>::cover_len(w, rows)];
        let mut slots = std::vec![WalkSlot::<1>::EMPTY; 32];
        WalkCache::new(&mut slots).clear();
        let mut out = std::vec![0u16; usize::from(w) * usize::from(h)];
        let mut skipped = 0;
        for band in Bands::new(w, h, rows) {
            let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
            buf.clear([300]);
            let mut canvas = Canvas::new(&mut buf, Some(WalkCache::new(&mut slots)));
            draw(&mut canvas);
            skipped += canvas.skipped().count;
            for y in band.row_range() {
                for x in 0..w {
                    out[y as usize * usize::from(w) + usize::from(x)] =
                        buf.lin12(i32::from(x), y).unwrap()[0];
                }
            }
        }
        (out, skipped)
    }

    #[test]
    fn a_kept_outline_fills_to_the_bits_of_the_shape_drawn_directly() {
        use crate::canvas::ShapeEntry;
        use crate::path::{LineJoin, Polyline, Segment, StrokeStyle};
        use crate::style::{Blend, FillRule, Opacity};
        let mut rng = Lcg(0x5eed_0f5e_9b0f_f00d);
        let mut next = |m: u32| rng.below(u64::from(m)) as i32;
        for case in 0..40 {
            // A chart-like polyline (some segments shorter than the width),
            // and a disc.
            let n = 3 + next(30) as usize;
            let pts: std::vec::Vec<FinePoint> = (0..n)
                .map(|k| FinePoint::new(1024 + k as i32 * next(4096), 2048 + next(44 * 1024)))
                .collect();
            let line = Polyline::new(&pts);
            let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][case % 3];
            let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][case / 3 % 3];
            let style = StrokeStyle::new(200 + next(5000) as u32)
                .with_join(join)
                .with_cap(cap);
            // A round ellipse: a `Circle` is drawn from its exact areas,
            // not its outline (`edge::disc`).
            let rr = 1 + next(20_000) as u32;
            let disc = Ellipse::new(FinePoint::new(next(64 * 1024), next(48 * 1024)), rr, rr);
            let blend = if case % 4 == 3 {
                Blend::Add
            } else {
                Blend::Over
            };
            let op = Opacity::from_ratio(2 + (case % 3) as u32, 4).unwrap();
            let direct = |c: &mut Canvas<'_, '_, 1>| {
                c.stroke_shape(&line, &style, [3000], blend, op).unwrap();
                c.fill_shape(&disc, [900], FillRule::EvenOdd, blend, op)
                    .unwrap();
            };
            // Kept over several frames: described in the first band of
            // the first frame, found kept in every other band.
            let mut segments = std::vec![Segment::ZERO; 4096];
            let mut entries = [ShapeEntry::EMPTY; 2];
            let mut kept = |rows: u16, frame_no: u32| {
                let cache = (&mut segments[..], &mut entries[..], frame_no);
                let (out, (hits, described)) = kept_frame(64, rows, cache, direct);
                assert_eq!(hits + described, 2 * 48u32.div_ceil(rows.into()));
                assert_eq!(described, if frame_no == 0 { 2 } else { 0 });
                out
            };
            let (whole, _) = frame(64, 48, direct);
            assert!(
                whole.iter().any(|&v| v != 300),
                "case {case}: something is drawn"
            );
            for rows in [1, 3, 16, 48] {
                assert_eq!(
                    frame(64, rows, direct).0,
                    whole,
                    "case {case}, direct, {rows} rows"
                );
                let first = if rows == 1 { 0 } else { rows.into() };
                assert_eq!(kept(rows, first), whole, "case {case}, kept, {rows} rows");
            }
        }
    }

    /// A circle drawn by the canvas (filled, or through embedded-graphics'
    /// `AaStyle`) has every pixel within 1/256 of its exact area (plus the
    /// 12-bit rounding), the same bits in bands of 48, 16, 7, 3 and 1 rows
    /// (its rows walked from the circle in each band), and differs from
    /// its flattened outline (a round ellipse's) by less than 1/256 too.
    #[test]
    fn a_circle_is_filled_by_its_exact_areas_in_every_band_height() {
        use crate::edge::disc::reference::exact;
        use crate::style::{Blend, FillRule, Opacity};
        let mut rng = Lcg(0xc1c1_e5ee_d0d1_5c00);
        let mut next = |m: u32| rng.below(u64::from(m)) as i32;
        let mut worst = (0.0f64, 0.0f64);
        for case in 0..120 {
            let r = 8 + (next(30 * 1024) >> next(8)) as u32;
            let c = FinePoint::new(next(72 * 1024) - 4096, next(56 * 1024) - 4096);
            let disc = Circle::new(c, r);
            let draw = |k: &mut Canvas<'_, '_, 1>| {
                k.fill_shape(
                    &disc,
                    [4095],
                    FillRule::NonZero,
                    Blend::Over,
                    Opacity::OPAQUE,
                )
                .unwrap();
            };
            let (whole, _) = frame(64, 48, |k| {
                k.buffer().clear([0]);
                draw(k);
            });
            for rows in [1, 3, 7, 16] {
                let (got, _) = frame(64, rows, |k| {
                    k.buffer().clear([0]);
                    draw(k);
                });
                assert_eq!(got, whole, "case {case}: {rows} rows");
            }
            let (flat, _) = frame(64, 48, |k| {
                k.buffer().clear([0]);
                k.fill_shape(
                    &Ellipse::new(c, r, r),
                    [4095],
                    FillRule::NonZero,
                    Blend::Over,
                    Opacity::OPAQUE,
                )
                .unwrap();
            });
            let (cx, cy, rf) = (
                f64::from(c.x) / 1024.0,
                f64::from(c.y) / 1024.0,
                f64::from(r) / 1024.0,
            );
            for (k, (&v, &f)) in whole.iter().zip(&flat).enumerate() {
                let (x, y) = (k as i32 % 64, k as i32 / 64);
                let e = exact(cx, cy, rf, x, y);
                let d = (f64::from(v) / 4095.0 - e).abs();
                let df = (f64::from(v) - f64::from(f)).abs() / 4095.0;
                worst = (worst.0.max(d), worst.1.max(df));
                assert!(
                    d <= 1.0 / 256.0 + 0.5 / 4095.0,
                    "case {case}: pixel ({x}, {y}) {v} against {e}"
                );
                assert!(
                    df < 1.0 / 256.0,
                    "case {case}: pixel ({x}, {y}) {v} flattened {f}"
                );
            }
        }
        std::println!(
            "worst against exact {:.6}, against flattened {:.6}",
            worst.0,
            worst.1
        );
    }

    /// A stroked circle (a ring, or a disc where the stroke reaches the
    /// centre; centred, inside and outside alignments) has every pixel
    /// within 1/256 of the exact area between its two circles, the same
    /// bits in bands of 48, 16, 7, 3 and 1 rows.
    #[test]
    fn a_ring_is_stroked_by_its_exact_areas_in_every_band_height() {
        use crate::edge::disc::reference::exact;
        use crate::path::StrokeAlignment;
        use crate::style::{Blend, Opacity};
        let mut rng = Lcg(0x0a22_1f5e_ed00_1234);
        let mut next = |m: u32| rng.below(u64::from(m)) as i32;
        let mut worst = 0.0f64;
        for case in 0..120 {
            let r = 8 + (next(30 * 1024) >> next(8)) as u32;
            let c = FinePoint::new(next(72 * 1024) - 4096, next(56 * 1024) - 4096);
            let w = 1 + (next(12 * 1024) >> next(6)) as u32;
            let (align, out, inn) = match case % 3 {
                0 => (
                    StrokeAlignment::Centre,
                    f64::from(w) / 2.0,
                    f64::from(w) / 2.0,
                ),
                1 => (StrokeAlignment::Inside, 0.0, f64::from(w)),
                _ => (StrokeAlignment::Outside, f64::from(w), 0.0),
            };
            let style = StrokeStyle::new(w).with_alignment(align);
            let ring = Circle::new(c, r);
            let draw = |k: &mut Canvas<'_, '_, 1>| {
                k.buffer().clear([0]);
                k.stroke_shape(&ring, &style, [4095], Blend::Over, Opacity::OPAQUE)
                    .unwrap();
            };
            let (whole, _) = frame(64, 48, draw);
            for rows in [1, 3, 7, 16] {
                assert_eq!(frame(64, rows, draw).0, whole, "case {case}: {rows} rows");
            }
            let (cx, cy) = (f64::from(c.x) / 1024.0, f64::from(c.y) / 1024.0);
            let ro = (f64::from(r) + out) / 1024.0;
            let ri = (f64::from(r) - inn) / 1024.0;
            for (k, &v) in whole.iter().enumerate() {
                let (x, y) = (k as i32 % 64, k as i32 / 64);
                let hole = if ri > 0.0 {
                    exact(cx, cy, ri, x, y)
                } else {
                    0.0
                };
                let e = exact(cx, cy, ro, x, y) - hole;
                let d = (f64::from(v) / 4095.0 - e).abs();
                worst = worst.max(d);
                assert!(
                    d <= 1.0 / 256.0 + 0.5 / 4095.0,
                    "case {case}: r {r} w {w} {align:?} pixel ({x}, {y}) {v} against {e}"
                );
            }
        }
        std::println!("worst against exact {worst:.6}");
    }

    /// The exact (f64) coverage of the `w x h` frame's pixels by the union
    /// of an annular sector (centre, outer and inner radii, start and
    /// sweep in radians, clockwise on screen) and discs, px: per pixel row
    /// the integral over `m` sub-rows (midpoint rule) of the union's
    /// slice, found exactly (the chords, split where the sector's rays
    /// cross).
    fn sector_reference(
        w: usize,
        h: usize,
        c: (f64, f64),
        (ro, ri): (f64, f64),
        (a, s): (f64, f64),
        discs: &[(f64, f64, f64)],
    ) -> std::vec::Vec<f64> {
        use core::f64::consts::TAU;
        let m = 1024;
        let mut out = std::vec![0.0; w * h];
        let chord = |v: f64, r: f64| (r * r - v * v).max(0.0).sqrt();
        for y in 0..h {
            for k in 0..m {
                let yy = y as f64 + (k as f64 + 0.5) / m as f64;
                let v = yy - c.1;
                let mut iv: std::vec::Vec<(f64, f64)> = std::vec::Vec::new();
                if v.abs() < ro {
                    let wo = chord(v, ro);
                    let mut cuts = std::vec![c.0 - wo, c.0 + wo];
                    if v.abs() < ri {
                        let wi = chord(v, ri);
                        cuts.extend([c.0 - wi, c.0 + wi]);
                    }
                    for t in [a, a + s] {
                        let sn = t.sin();
                        if sn.abs() > 1e-12 && v / sn > 0.0 {
                            cuts.push(c.0 + v * t.cos() / sn);
                        }
                    }
                    cuts.sort_by(|p, q| p.partial_cmp(q).unwrap());
                    for p in cuts.windows(2) {
                        let (x0, x1) = (p[0].max(c.0 - wo), p[1].min(c.0 + wo));
                        if x1 <= x0 {
                            continue;
                        }
                        let xm = (x0 + x1) / 2.0;
                        let d = ((xm - c.0).powi(2) + v * v).sqrt();
                        let ang = v.atan2(xm - c.0).rem_euclid(TAU);
                        if d <= ro && d >= ri && (ang - a).rem_euclid(TAU) <= s {
                            iv.push((x0, x1));
                        }
                    }
                }
                for &(dx, dy, r) in discs {
                    let v = yy - dy;
                    if v.abs() < r {
                        let wd = chord(v, r);
                        iv.push((dx - wd, dx + wd));
                    }
                }
                iv.sort_by(|p, q| p.partial_cmp(q).unwrap());
                let mut merged: std::vec::Vec<(f64, f64)> = std::vec::Vec::new();
                for (x0, x1) in iv {
                    match merged.last_mut() {
                        Some(l) if x0 <= l.1 => l.1 = l.1.max(x1),
                        _ => merged.push((x0, x1)),
                    }
                }
                for (x0, x1) in merged {
                    let (lo, hi) = (x0.max(0.0), x1.min(w as f64));
                    let mut x = lo.floor() as usize;
                    while (x as f64) < hi && x < w {
                        let part = hi.min(x as f64 + 1.0) - lo.max(x as f64);
                        if part > 0.0 {
                            out[y * w + x] += part / m as f64;
                        }
                        x += 1;
                    }
                }
            }
        }
        out
    }

    /// A stroked arc (butt caps, any alignment; centred round caps) has
    /// every pixel within 1/256 of the exact area of its annular sector
    /// (and cap discs), the same bits in bands of 48, 16, 7, 3 and 1 rows.
    #[test]
    fn an_arc_is_stroked_by_its_exact_areas_in_every_band_height() {
        use crate::path::{Arc, Degrees, StrokeAlignment};
        use crate::style::{Blend, Opacity};
        let mut rng = Lcg(0xa2c5_0f00_1234_5678);
        let mut next = |m: u32| rng.below(u64::from(m)) as i32;
        let mut worst = 0.0f64;
        let mut drawn = 0;
        for case in 0..100 {
            let round = case % 2 == 1;
            let r = 2048 + next(24 * 1024) as u32;
            let c = FinePoint::new(8 * 1024 + next(48 * 1024), 8 * 1024 + next(32 * 1024));
            let (start, mut sweep) = (next(720) - 360, next(700) - 350);
            let mut wd = 512 + next(8 * 1024) as u32;
            if round {
                // Caps the exact path takes: a hole, and ends at least the
                // width and 2 px apart (a gap of 60 degrees or more).
                let r = r.max(4096);
                wd = wd.min(r - 2048);
                sweep = sweep.clamp(-300, 300);
            }
            let r = if round { r.max(4096) } else { r };
            let (align, out, inn) = match (round, case / 2 % 3) {
                (false, 1) => (StrokeAlignment::Inside, 0.0, f64::from(wd)),
                (false, 2) => (StrokeAlignment::Outside, f64::from(wd), 0.0),
                _ => (
                    StrokeAlignment::Centre,
                    f64::from(wd) / 2.0,
                    f64::from(wd) / 2.0,
                ),
            };
            let cap = if round { LineCap::Round } else { LineCap::Butt };
            let style = StrokeStyle::new(wd).with_alignment(align).with_cap(cap);
            let arc = Arc::new(c, r, Degrees::new(start), Degrees::new(sweep));
            let draw = |k: &mut Canvas<'_, '_, 1>| {
                k.buffer().clear([0]);
                k.stroke_shape(&arc, &style, [4095], Blend::Over, Opacity::OPAQUE)
                    .unwrap();
            };
            let (whole, _) = frame(64, 48, draw);
            for rows in [1, 3, 7, 16] {
                assert_eq!(frame(64, rows, draw).0, whole, "case {case}: {rows} rows");
            }
            let px = |v: f64| v / 1024.0;
            let (cx, cy, rf) = (px(f64::from(c.x)), px(f64::from(c.y)), px(f64::from(r)));
            let (ro, ri) = (rf + px(out), (rf - px(inn)).max(0.0));
            // Clockwise from the start, as the arc runs.
            let deg = |d: i32| f64::from(d).to_radians();
            let (a, s) = if sweep < 0 {
                (deg(start + sweep), deg(-sweep))
            } else {
                (deg(start), deg(sweep))
            };
            let mut discs = std::vec::Vec::new();
            if round && sweep != 0 {
                let hw = px(f64::from(wd)) / 2.0;
                for t in [a, a + s] {
                    discs.push((cx + rf * t.cos(), cy + rf * t.sin(), hw));
                }
            }
            let want = sector_reference(64, 48, (cx, cy), (ro, ri), (a, s), &discs);
            for (k, (&v, &e)) in whole.iter().zip(&want).enumerate() {
                let d = (f64::from(v) / 4095.0 - e).abs();
                worst = worst.max(d);
                assert!(
                    d <= 1.0 / 256.0 + 0.5 / 4095.0,
                    "case {case}: r {r} w {wd} {start}+{sweep} {cap:?} {align:?} pixel ({}, {}) \
                     {v} against {e}",
                    k % 64,
                    k / 64
                );
            }
            drawn += usize::from(whole.iter().any(|&v| v != 0));
        }
        assert!(drawn > 90);
        std::println!("worst against exact {worst:.6}");
    }

    #[cfg(feature = "embedded-graphics")]
    #[test]
    fn an_embedded_graphics_circle_takes_the_exact_path() {
        use crate::draw::{AaDrawable, AaStyle};
        use crate::style::{Blend, FillRule, Opacity};
        use embedded_graphics::pixelcolor::Gray8;
        use embedded_graphics::prelude::*;
        use embedded_graphics::primitives::Circle as EgCircle;
        let eg = EgCircle::new(Point::new(5, 7), 23);
        let disc: Circle = eg.into();
        let (direct, _) = frame(40, 16, |k| {
            k.buffer().clear([0]);
            k.fill_shape(
                &disc,
                [4095],
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        let mut exact_pixels = 0;
        let (styled, _) = frame(40, 16, |k| {
            k.buffer().clear([0]);
            let s = eg.into_styled(AaStyle::new().fill_color(Gray8::WHITE));
            AaDrawable::<1>::draw(&s, k).unwrap();
        });
        for (a, b) in direct.iter().zip(&styled) {
            assert_eq!(a, b);
            exact_pixels += usize::from(*a != 0);
        }
        assert!(exact_pixels > 300);
    }

    #[test]
    fn an_outline_that_lost_segments_is_refused_and_the_rest_drawn() {
        use crate::error::DrawError;
        use crate::style::{Blend, FillRule, Opacity};
        /// Half of a disc's outline, known to be incomplete.
        struct Half(std::vec::Vec<(FinePoint, FinePoint)>);
        impl Outline for Half {
            fn bounds(&self) -> Option<FineRect> {
                Some(FineRect {
                    x0: 0,
                    y0: 0,
                    x1: 40 * 1024,
                    y1: 48 * 1024,
                })
            }
            fn segments<F: FnMut(FinePoint, FinePoint)>(&self, mut f: F) {
                self.0.iter().for_each(|&(a, b)| f(a, b));
            }
            fn complete(&self) -> bool {
                false
            }
        }
        struct Collect(std::vec::Vec<(FinePoint, FinePoint)>);
        impl SegmentSink for Collect {
            fn segment(&mut self, a: FinePoint, b: FinePoint) {
                self.0.push((a, b));
            }
        }
        let disc = Circle::new(FinePoint::new(20 * 1024, 20 * 1024), 15 * 1024);
        let mut all = Collect(std::vec::Vec::new());
        disc.fill(&mut all);
        let n = all.0.len() / 2;
        all.0.truncate(n);
        let short = Half(all.0);
        let (out, skipped) = frame(40, 8, |c| {
            assert_eq!(
                c.fill(
                    &short,
                    [4000],
                    FillRule::NonZero,
                    Blend::Over,
                    Opacity::OPAQUE
                ),
                Err(DrawError::Incomplete)
            );
            c.fill_shape(
                &disc,
                [2000],
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        // Every band refuses the incomplete outline (6 bands of 8 rows), as
        // every band reports a vertex out of range; the disc itself is
        // drawn.
        assert_eq!(skipped, 6);
        assert_eq!(out[20 * 40 + 20], 2000);
    }
}
