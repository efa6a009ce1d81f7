//! Paths (lines, quadratic and cubic Béziers, SVG arcs), shapes (circles,
//! rotated ellipses, arcs, sectors, rectangles, rounded rectangles,
//! polylines, polygons, lines) and SVG path data, filled by either rule
//! or stroked (any width, join, miter limit, cap, dash pattern and
//! alignment), with coordinates at and beyond the ±2048 px limit: no
//! panic, the same frame and the same errors for two band heights, and
//! what the path API promises its sinks (closed contours of non-zero
//! segments in range, shapes and strokes not negative, the same segment
//! numbers whatever rows a sink asks for).
//!
//! The shapes are made in one place (`with_shape`); the canvas is used in
//! `draw` (through `Painter`), the segment sinks in `Checker`.
#![no_main]

use std::collections::{BTreeSet, HashMap};
use std::fmt::Write as _;

use libfuzzer_sys::fuzz_target;
use softedge::canvas::Canvas;
use softedge::geom::{FinePoint, PathSink, FINE_LIMIT};
use softedge::path::svg::parse_path_data;
use softedge::path::{
    Arc, Circle, CornerRadii, Dash, Degrees, Ellipse, Line, LineCap, LineJoin, MiterLimit, Polygon,
    Polyline, Rectangle, RoundedRectangle, Sector, SegmentSink, Shape, StrokeAlignment,
    StrokeStyle, Tolerance, MAX_RADIUS, MAX_STROKE_WIDTH,
};
use softedge::style::{Blend, FillRule, Opacity};
use softedge::{BandBuffer, RenderStyle};
use softedge_fuzz::{assert_band_invariant, FrameSetup, Input};

/// Segments (path commands, polyline vertices) per frame, all shapes
/// together.
const MAX_SEGMENTS: usize = 320;
/// Shapes per frame.
const MAX_SHAPES: usize = 10;
/// One pixel in fine units.
const PX: i32 = 1024;

/// One command of a general path, in fine units.
#[derive(Debug, Clone, Copy)]
enum Cmd {
    Move(FinePoint),
    Line(FinePoint),
    Quad(FinePoint, FinePoint),
    Cubic(FinePoint, FinePoint, FinePoint),
    Close,
}

/// What is drawn, as plain numbers: `with_shape` makes the library's
/// shapes.
#[derive(Debug)]
enum Geometry {
    Path(Vec<Cmd>),
    /// SVG path data, checked (`SvgPath`) or not (parsed into the sink
    /// as far as it is valid).
    Svg(String, bool),
    Circle(FinePoint, u32),
    Ellipse(FinePoint, u32, u32, i32),
    Arc(FinePoint, u32, i32, i32),
    Sector(FinePoint, u32, i32, i32),
    Rect(FinePoint, u32, u32),
    Rounded(FinePoint, u32, u32, [(u32, u32); 4]),
    Polyline(Vec<FinePoint>),
    Polygon(Vec<FinePoint>),
    Line(FinePoint, FinePoint),
}

/// A stroke style, as plain numbers.
#[derive(Debug)]
struct Stroke {
    width: u32,
    join: LineJoin,
    miter_q16: u32,
    cap: LineCap,
    dash: Option<(Vec<u32>, i32)>,
    alignment: StrokeAlignment,
}

#[derive(Debug)]
enum Paint {
    Fill(FillRule),
    Stroke(Stroke),
}

#[derive(Debug)]
struct Item {
    geometry: Geometry,
    paint: Paint,
    color: [u16; 1],
    blend: Blend,
    opacity: u16,
}

/// A general path as a [`Shape`]: its commands, as given.
struct PathShape<'a>(&'a [Cmd]);

impl Shape for PathShape<'_> {
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        for c in self.0 {
            match *c {
                Cmd::Move(p) => sink.move_to(p),
                Cmd::Line(p) => sink.line_to(p),
                Cmd::Quad(c, p) => sink.quad_to(c, p),
                Cmd::Cubic(c1, c2, p) => sink.cubic_to(c1, c2, p),
                Cmd::Close => sink.close(),
            }
        }
    }
}

/// Unchecked SVG path data: whatever parses before the first error.
struct RawSvg<'a>(&'a str);

impl Shape for RawSvg<'_> {
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        let _ = parse_path_data(self.0, sink);
    }
}

/// Something done with each item's shape (drawing it, or checking its
/// segments): `with_shape` makes the shape, the visitor gets it.
trait Visit {
    fn visit<S: Shape + ?Sized>(&mut self, shape: &S, item: &Item);
}

/// Makes the library's shape of `item` and hands it to `v`: the one place
/// the shapes are made.
fn with_shape<V: Visit>(item: &Item, v: &mut V) {
    match &item.geometry {
        Geometry::Path(cmds) => v.visit(&PathShape(cmds), item),
        Geometry::Svg(d, checked) => {
            if *checked {
                if let Ok(p) = softedge::path::svg::SvgPath::new(d) {
                    v.visit(&p, item);
                }
            } else {
                v.visit(&RawSvg(d), item);
            }
        }
        &Geometry::Circle(c, r) => v.visit(&Circle::new(c, r), item),
        &Geometry::Ellipse(c, rx, ry, rot) => v.visit(
            &Ellipse::new(c, rx, ry).rotated(Degrees::from_bits(rot)),
            item,
        ),
        &Geometry::Arc(c, r, start, sweep) => v.visit(
            &Arc::new(c, r, Degrees::from_bits(start), Degrees::from_bits(sweep)),
            item,
        ),
        &Geometry::Sector(c, r, start, sweep) => v.visit(
            &Sector::new(c, r, Degrees::from_bits(start), Degrees::from_bits(sweep)),
            item,
        ),
        &Geometry::Rect(p, w, h) => v.visit(&Rectangle::new(p, w, h), item),
        &Geometry::Rounded(p, w, h, [tl, tr, br, bl]) => {
            let radii = CornerRadii {
                top_left: tl,
                top_right: tr,
                bottom_right: br,
                bottom_left: bl,
            };
            v.visit(&RoundedRectangle::new(Rectangle::new(p, w, h), radii), item);
        }
        Geometry::Polyline(p) => v.visit(&Polyline::new(p), item),
        Geometry::Polygon(p) => v.visit(&Polygon::new(p), item),
        &Geometry::Line(a, b) => v.visit(&Line::new(a, b), item),
    }
}

/// The stroke style of `s` for `shape`, its dash pattern in `pattern`
/// (coarsened when too costly, see [`affordable`]).
fn stroke_style<'d, S: Shape + ?Sized>(
    shape: &S,
    s: &Stroke,
    pattern: &'d mut Vec<u32>,
) -> StrokeStyle<'d> {
    let style = StrokeStyle::new(s.width)
        .with_join(s.join)
        .with_miter_limit(MiterLimit::from_q16(s.miter_q16))
        .with_cap(s.cap)
        .with_alignment(s.alignment);
    match &s.dash {
        Some((p, offset)) => {
            *pattern = affordable(shape, s, p);
            style.with_dash(Dash::new(pattern, *offset))
        }
        None => style,
    }
}

/// Draws into a band's canvas; records every rejected item with its
/// place (a documented result) and goes on with the rest.
struct Painter<'p, 'c, 'b> {
    canvas: Canvas<'c, 'b, 1>,
    k: usize,
    errors: &'p mut BTreeSet<(usize, String)>,
}

impl Visit for Painter<'_, '_, '_> {
    fn visit<S: Shape + ?Sized>(&mut self, shape: &S, item: &Item) {
        let opacity = Opacity::from_4096ths(item.opacity);
        let r = match &item.paint {
            &Paint::Fill(rule) => self
                .canvas
                .fill_shape(shape, item.color, rule, item.blend, opacity),
            Paint::Stroke(s) => {
                let mut pattern = Vec::new();
                let style = stroke_style(shape, s, &mut pattern);
                self.canvas
                    .stroke_shape(shape, &style, item.color, item.blend, opacity)
            }
        };
        if let Err(e) = r {
            self.errors.insert((self.k, format!("{e:?}")));
        }
    }
}

/// The one use of the drawing API: the items, in order, into one band.
fn draw(
    band: &mut BandBuffer<'_, 1>,
    items: &[Item],
    style: &RenderStyle,
    errors: &mut BTreeSet<(usize, String)>,
) {
    let mut canvas = Canvas::new(band, None);
    canvas.set_style(*style);
    let mut painter = Painter {
        canvas,
        k: 0,
        errors,
    };
    for (k, item) in items.iter().enumerate() {
        painter.k = k;
        with_shape(item, &mut painter);
    }
}

/// The most segments (and left-out ones) a description is recorded with
/// for the checks; longer ones are not checked.
const RECORD_LIMIT: usize = 200_000;

/// What a description sent, in order: each segment, or `None` for one
/// left out (skipped), with the rows it was asked for.
struct Record {
    window: Option<(i32, i32)>,
    events: Vec<Option<(FinePoint, FinePoint)>>,
    overflowed: bool,
}

impl Record {
    fn new(window: Option<(i32, i32)>) -> Self {
        Self {
            window,
            events: Vec::new(),
            overflowed: false,
        }
    }
}

impl SegmentSink for Record {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        if self.events.len() < RECORD_LIMIT {
            self.events.push(Some((from, to)));
        } else {
            self.overflowed = true;
        }
    }
    fn window(&self) -> Option<(i32, i32)> {
        self.window
    }
    fn skipped(&mut self, n: u32) {
        let n = n as usize;
        if self.events.len() + n <= RECORD_LIMIT {
            self.events.extend(core::iter::repeat_n(None, n));
        } else {
            self.overflowed = true;
        }
    }
}

/// Checks what the path API promises its sinks, for each item: closed
/// contours of non-zero-length segments in the coordinate range; shapes'
/// fills and every stroke with a shoelace sum that is not negative; and,
/// for sinks that name a window of rows, the same segments with the same
/// numbers, only segments wholly outside the window left out (what a
/// band's walk cache relies on).
struct Checker<'w> {
    windows: &'w [(i32, i32)],
}

impl Checker<'_> {
    fn describe<S: Shape + ?Sized>(&self, shape: &S, item: &Item, rec: &mut Record) -> String {
        match &item.paint {
            Paint::Fill(_) => {
                shape.fill_with(Tolerance::DEFAULT, rec);
                String::new()
            }
            Paint::Stroke(s) => {
                let mut pattern = Vec::new();
                let style = stroke_style(shape, s, &mut pattern);
                format!("{:?}", shape.stroke_with(&style, Tolerance::DEFAULT, rec))
            }
        }
    }
}

impl Visit for Checker<'_> {
    fn visit<S: Shape + ?Sized>(&mut self, shape: &S, item: &Item) {
        let mut full = Record::new(None);
        let result = self.describe(shape, item, &mut full);
        if full.overflowed {
            return;
        }
        let mut balance: HashMap<FinePoint, i64> = HashMap::new();
        let mut area2: i128 = 0;
        for &(a, b) in full.events.iter().flatten() {
            assert!(a != b, "a zero-length segment at {a:?}");
            assert!(
                a.in_range() && b.in_range(),
                "a segment out of range: {a:?} -> {b:?}"
            );
            *balance.entry(a).or_default() += 1;
            *balance.entry(b).or_default() -= 1;
            area2 += i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y);
        }
        if let Some((p, n)) = balance.iter().find(|(_, &n)| n != 0) {
            panic!("contours not closed: {n} more segments start than end at {p:?}");
        }
        let closed = balance.values().all(|&n| n == 0);
        let oriented = match (&item.geometry, &item.paint) {
            (_, Paint::Stroke(_)) => true,
            (
                Geometry::Path(_)
                | Geometry::Svg(..)
                | Geometry::Polygon(_)
                | Geometry::Polyline(_)
                | Geometry::Line(..),
                _,
            ) => false,
            _ => true,
        };
        // A square pixel (2^21 in doubled fine units squared) of slack for
        // slivers whose rounded vertices turn them over.
        assert!(
            !oriented || !closed || area2 >= -(1 << 21),
            "negative area: shoelace sum {area2} (doubled, fine units squared): {:?} {:?}",
            item.geometry,
            item.paint
        );
        for &w in self.windows {
            let mut win = Record::new(Some(w));
            let r = self.describe(shape, item, &mut win);
            if win.overflowed {
                continue;
            }
            assert_eq!(r, result, "the stroke's result differs in window {w:?}");
            assert!(
                win.events.len() <= full.events.len(),
                "window {w:?}: {} segments numbered, {} without a window",
                win.events.len(),
                full.events.len()
            );
            for (k, (f, g)) in full.events.iter().zip(&win.events).enumerate() {
                match (f, g) {
                    (Some(s), Some(t)) => {
                        assert_eq!(s, t, "window {w:?}: segment {k} differs")
                    }
                    (Some((a, b)), None) => assert!(
                        a.y.max(b.y) < w.0 || a.y.min(b.y) > w.1,
                        "window {w:?}: segment {k} {a:?} -> {b:?} meets it but was left out"
                    ),
                    (None, Some(t)) => {
                        panic!("window {w:?}: segment {k} {t:?} sent, left out without a window")
                    }
                    (None, None) => {}
                }
            }
        }
    }
}

/// Segments a dashed stroke may cost per description before its pattern
/// is coarsened: the work is bounded (at most `MAX_DASH_INTERVALS`
/// intervals per contour), but 65536 dots with round caps 4096 px wide
/// take a second per band, which would stall the fuzzer.
const DASH_COST_LIMIT: f64 = 300_000.0;

/// The length of a description's control polygon (which bounds its
/// curves' length) and its number of contours, at most.
#[derive(Default)]
struct Measure {
    len: f64,
    contours: f64,
    start: (f64, f64),
    at: (f64, f64),
}

impl Measure {
    fn to(&mut self, p: FinePoint) {
        let q = (f64::from(p.x), f64::from(p.y));
        self.len += (q.0 - self.at.0).hypot(q.1 - self.at.1);
        self.at = q;
    }
}

impl PathSink for Measure {
    fn move_to(&mut self, p: FinePoint) {
        self.contours += 1.0;
        self.at = (f64::from(p.x), f64::from(p.y));
        self.start = self.at;
    }
    fn line_to(&mut self, p: FinePoint) {
        self.to(p);
    }
    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        self.to(c);
        self.to(p);
    }
    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        self.to(c1);
        self.to(c2);
        self.to(p);
    }
    fn close(&mut self) {
        let s = self.start;
        self.len += (s.0 - self.at.0).hypot(s.1 - self.at.1);
        self.at = s;
        // What follows a close is another contour.
        self.contours += 1.0;
    }
}

/// The dash pattern of `s`, coarsened (every entry doubled, as often as
/// needed) until stroking `shape` with it costs at most
/// [`DASH_COST_LIMIT`] segments by a rough estimate (part of `draw`).
fn affordable<S: Shape + ?Sized>(shape: &S, s: &Stroke, pattern: &[u32]) -> Vec<u32> {
    let mut m = Measure::default();
    shape.describe(&mut m);
    let contours = m.contours.max(1.0);
    let r_px = f64::from(s.width.min(MAX_STROKE_WIDTH)) / 2048.0;
    let per_interval = match s.cap {
        LineCap::Butt => 6.0,
        LineCap::Square => 10.0,
        LineCap::Round => 40.0 + 35.0 * r_px.sqrt(),
    };
    let mut p = pattern.to_vec();
    for _ in 0..40 {
        let n = if p.len() % 2 == 1 {
            2 * p.len()
        } else {
            p.len()
        };
        let period: f64 =
            p.iter().map(|&v| f64::from(v)).sum::<f64>() * (n / p.len().max(1)) as f64;
        let solid = period == 0.0 || !(0..n).any(|i| i % 2 == 1 && p[i % p.len()] > 0);
        if solid {
            break;
        }
        let intervals = (contours + m.len * n as f64 / period).min(65537.0 * contours);
        if intervals * per_interval <= DASH_COST_LIMIT {
            break;
        }
        for v in &mut p {
            *v = v.saturating_mul(2);
        }
    }
    p
}

/// Reads the items of a frame of `w x h` px.
struct Reader<'a, 'b> {
    inp: &'b mut Input<'a>,
    w: i32,
    h: i32,
    /// Points given so far (for coincident and collinear ones).
    points: Vec<FinePoint>,
    /// Segments left in the frame's budget.
    budget: usize,
}

impl Reader<'_, '_> {
    /// A fine coordinate along a side of `size` px: mostly near the frame,
    /// sometimes at, just inside or beyond the limit, or anything.
    fn coord(&mut self, size: i32) -> i32 {
        let inp = &mut *self.inp;
        match inp.u8() % 16 {
            0 => FINE_LIMIT - inp.range(-64, 64),
            1 => -FINE_LIMIT + inp.range(-64, 64),
            2 => inp.range(-FINE_LIMIT - 8 * PX, FINE_LIMIT + 8 * PX),
            3 => inp.u32() as i32,
            // On whole and half pixels.
            4 => inp.range(-2, size + 2) * PX,
            5 => inp.range(-4, 2 * size + 4) * (PX / 2),
            _ => inp.range(-4 * PX, (size + 4) * PX),
        }
    }

    fn fresh(&mut self) -> FinePoint {
        FinePoint::new(self.coord(self.w), self.coord(self.h))
    }

    /// A point: fresh, or one given before, beside one, or on the line
    /// through two (for zero-length, collinear and cusp segments).
    fn point(&mut self) -> FinePoint {
        let n = self.points.len();
        let p = match self.inp.u8() % 10 {
            0 | 1 if n > 0 => self.points[n - 1],
            2 if n > 0 => {
                let k = usize::from(self.inp.u8()) % n;
                self.points[k]
            }
            3 if n > 0 => {
                let q = self.points[n - 1];
                let (dx, dy) = (self.inp.range(-3, 3), self.inp.range(-3, 3));
                FinePoint::new(q.x.saturating_add(dx), q.y.saturating_add(dy))
            }
            4 if n > 1 => {
                // a + (b - a) t / 4 for t in -8..=8: on the line through
                // the last two, before, between or after them.
                let (a, b) = (self.points[n - 2], self.points[n - 1]);
                let t = i64::from(self.inp.range(-8, 8));
                let at = |a: i32, b: i32| {
                    let v = i64::from(a) + (i64::from(b) - i64::from(a)) * t / 4;
                    v.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32
                };
                FinePoint::new(at(a.x, b.x), at(a.y, b.y))
            }
            _ => self.fresh(),
        };
        if n < 64 {
            self.points.push(p);
        } else {
            self.points[n - 1] = p;
        }
        p
    }

    /// A radius or side, fine units: mostly up to the frame's size, at
    /// times zero, tiny, at the radius limit, or anything.
    fn length(&mut self) -> u32 {
        let size = self.w.max(self.h) as u32 * PX as u32;
        let inp = &mut *self.inp;
        match inp.u8() % 12 {
            0 => 0,
            1 => inp.range(1, 16) as u32,
            2 => inp.u32(),
            3 => (MAX_RADIUS as i64 + i64::from(inp.range(-2, 2))) as u32,
            4 => inp.range(0, 1 << 24) as u32,
            5 => inp.range(0, 8) as u32 * (PX as u32 / 2),
            _ => inp.u32() % (size + 1),
        }
    }

    /// An angle in 1/65536 degree: whole and right angles, tiny ones,
    /// full turns and more, or anything.
    fn angle(&mut self) -> i32 {
        let inp = &mut *self.inp;
        match inp.u8() % 8 {
            0 => inp.range(-8, 8) * (90 << 16),
            1 => inp.range(-16, 16),
            2 => inp.u32() as i32,
            3 => inp.range(-720, 720) << 16,
            4 => (360 << 16) + inp.range(-2, 2),
            _ => inp.range(-(720 << 16), 720 << 16),
        }
    }

    fn stroke(&mut self) -> Stroke {
        let inp = &mut *self.inp;
        // Huge widths (a stroke of a small curve 4096 px wide is some 10^5
        // segments in every band) one time in eight.
        let width = match inp.u8() % 16 {
            0 | 1 => inp.range(0, 64) as u32,
            2 => inp.range(64 * PX, 4096 * PX) as u32,
            3 if inp.bool() => MAX_STROKE_WIDTH.wrapping_add(inp.range(-2, 2) as u32),
            3 => inp.u32(),
            4 | 5 => inp.range(0, 8) as u32 * (PX as u32 / 2),
            _ => inp.range(1, 24 * PX) as u32,
        };
        let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][usize::from(inp.u8() % 3)];
        let miter_q16 = match inp.u8() % 6 {
            0 => 4 << 16,
            1 => inp.range((1 << 16) - 16, (1 << 16) + 64) as u32,
            2 => inp.u32(),
            3 => inp.range(0, 1 << 16) as u32,
            _ => inp.range(1 << 16, 16 << 16) as u32,
        };
        let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][usize::from(inp.u8() % 3)];
        let alignment = [
            StrokeAlignment::Centre,
            StrokeAlignment::Inside,
            StrokeAlignment::Outside,
        ][usize::from(inp.u8() % 3)];
        let dash = if inp.u8().is_multiple_of(3) {
            let n = usize::from(inp.u8() % 7);
            let pattern = (0..n)
                .map(|_| match inp.u8() % 8 {
                    0 => 0,
                    1 => inp.range(1, 8) as u32,
                    2 => inp.u32(),
                    3 => inp.range(0, 64) as u32 * (PX as u32 / 4),
                    _ => inp.range(1, 16 * PX) as u32,
                })
                .collect();
            let offset = match inp.u8() % 4 {
                0 => 0,
                1 => inp.u32() as i32,
                _ => inp.range(-64 * PX, 64 * PX),
            };
            Some((pattern, offset))
        } else {
            None
        };
        Stroke {
            width,
            join,
            miter_q16,
            cap,
            dash,
            alignment,
        }
    }

    /// A number of SVG path data, in one of its spellings.
    fn svg_number(&mut self, out: &mut String, size: i32) {
        let inp = &mut *self.inp;
        let _ = match inp.u8() % 10 {
            0 => write!(out, "{}", inp.range(-9000, 9000)),
            1 => write!(out, "{}e{}", inp.range(-99, 99), inp.range(-30, 30)),
            2 => write!(out, "-.{}", inp.u16()),
            3 => write!(out, "{}.{:03}", inp.range(-2, size + 2), inp.u16() % 1000),
            4 => write!(out, "0.0009765625"),
            5 => write!(out, "{}", 2048 + inp.range(-1, 1)),
            _ => write!(out, "{}", inp.range(-2, size + 2)),
        };
    }

    /// Path data made of commands with numbers (arcs most of all).
    fn svg_commands(&mut self) -> String {
        let mut d = String::new();
        let n = 1 + usize::from(self.inp.u8() % 12).min(self.budget);
        self.budget = self.budget.saturating_sub(n);
        for k in 0..n {
            const CMDS: &[u8] = b"MmLlHhVvCcSsQqTtAaAaZz";
            let c = if k == 0 {
                b'M'
            } else {
                CMDS[usize::from(self.inp.u8()) % CMDS.len()]
            };
            d.push(char::from(c));
            let args: &[u8] = match c.to_ascii_uppercase() {
                b'M' | b'L' | b'T' => b"xy",
                b'H' => b"x",
                b'V' => b"y",
                b'C' => b"xyxyxy",
                b'S' | b'Q' => b"xyxy",
                b'A' => b"rraffxy",
                _ => b"",
            };
            for &a in args {
                d.push(' ');
                match a {
                    b'x' => self.svg_number(&mut d, self.w),
                    b'y' => self.svg_number(&mut d, self.h),
                    b'r' => self.svg_number(&mut d, self.w.max(self.h)),
                    b'a' => self.svg_number(&mut d, 360),
                    _ => d.push(if self.inp.u8().is_multiple_of(8) {
                        '2'
                    } else {
                        '1'
                    }),
                }
            }
            d.push(' ');
        }
        d
    }

    fn path(&mut self) -> Vec<Cmd> {
        let n = 1 + usize::from(self.inp.u8()).min(self.budget);
        self.budget = self.budget.saturating_sub(n);
        let mut cmds = Vec::with_capacity(n);
        // Mostly starting with a move, as paths do; not always.
        if !self.inp.u8().is_multiple_of(8) {
            cmds.push(Cmd::Move(self.point()));
        }
        for _ in 0..n {
            cmds.push(match self.inp.u8() % 12 {
                0 => Cmd::Move(self.point()),
                1 => Cmd::Close,
                2..=4 => Cmd::Quad(self.point(), self.point()),
                5..=7 => Cmd::Cubic(self.point(), self.point(), self.point()),
                _ => Cmd::Line(self.point()),
            });
        }
        cmds
    }

    fn vertices(&mut self) -> Vec<FinePoint> {
        let n = usize::from(self.inp.u8() % 80).min(self.budget);
        self.budget = self.budget.saturating_sub(n);
        (0..n).map(|_| self.point()).collect()
    }

    fn geometry(&mut self) -> Geometry {
        match self.inp.u8() % 14 {
            0..=2 => Geometry::Path(self.path()),
            3 => Geometry::Svg(self.svg_commands(), self.inp.bool()),
            4 => {
                // Fuzzer bytes as path data.
                let n = usize::from(self.inp.u8());
                let bytes: Vec<u8> = (0..n).map(|_| self.inp.u8()).collect();
                let d = String::from_utf8_lossy(&bytes).into_owned();
                Geometry::Svg(d, self.inp.bool())
            }
            5 => Geometry::Circle(self.point(), self.length()),
            6 => Geometry::Ellipse(self.point(), self.length(), self.length(), self.angle()),
            7 => Geometry::Arc(self.point(), self.length(), self.angle(), self.angle()),
            8 => Geometry::Sector(self.point(), self.length(), self.angle(), self.angle()),
            9 => Geometry::Rect(self.point(), self.length(), self.length()),
            10 => {
                let (p, w, h) = (self.point(), self.length(), self.length());
                let mut radii = [(0, 0); 4];
                for r in &mut radii {
                    *r = (self.length(), self.length());
                }
                Geometry::Rounded(p, w, h, radii)
            }
            11 => Geometry::Polyline(self.vertices()),
            12 => Geometry::Polygon(self.vertices()),
            _ => Geometry::Line(self.point(), self.point()),
        }
    }

    fn item(&mut self) -> Item {
        let geometry = self.geometry();
        let paint = match self.inp.u8() % 4 {
            0 => Paint::Fill(FillRule::NonZero),
            1 => Paint::Fill(FillRule::EvenOdd),
            _ => Paint::Stroke(self.stroke()),
        };
        let inp = &mut *self.inp;
        let color = [inp.lin12()];
        let blend = if inp.u8().is_multiple_of(4) {
            Blend::Add
        } else {
            Blend::Over
        };
        let opacity = match inp.u8() % 4 {
            0 => inp.u16() % 4097,
            _ => 4096,
        };
        Item {
            geometry,
            paint,
            color,
            blend,
            opacity,
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let FrameSetup {
        w,
        h,
        style,
        background,
        rows: (rows_a, rows_b),
    } = inp.frame_setup();
    let mut reader = Reader {
        inp: &mut inp,
        w: i32::from(w),
        h: i32::from(h),
        points: Vec::new(),
        budget: MAX_SEGMENTS,
    };
    let mut items = Vec::new();
    while !reader.inp.is_empty() && items.len() < MAX_SHAPES {
        items.push(reader.item());
    }
    // The errors of each rendering, by item: a band's canvas reports an
    // item's error only when the item meets the band, so the union over
    // the bands of a frame is what must not depend on the band height.
    let mut errors = [BTreeSet::new(), BTreeSet::new()];
    let mut pass = 0;
    let _ = assert_band_invariant(w, h, rows_a, rows_b, background, |band, b| {
        if b.y0 == 0 {
            pass += 1;
        }
        draw(band, &items, &style, &mut errors[(pass - 1).min(1)]);
        Ok::<(), ()>(())
    });
    assert_eq!(
        errors[0], errors[1],
        "errors differ between band heights {rows_a} and {rows_b}"
    );
    // The rows of a few bands of each height, widened by two pixels as a
    // band's canvas widens them, as windows.
    let mut windows = Vec::new();
    for rows in [rows_a, rows_b] {
        let bands: Vec<_> = softedge::Bands::new(w, h, rows).collect();
        for band in [bands.first(), bands.get(bands.len() / 2)]
            .into_iter()
            .flatten()
        {
            let y0 = band.y0 - 2;
            let y1 = band.y0 + i32::from(band.rows) + 2;
            windows.push((y0 * PX, y1 * PX - 1));
        }
    }
    windows.dedup();
    let mut checker = Checker { windows: &windows };
    for item in &items {
        with_shape(item, &mut checker);
    }
});
