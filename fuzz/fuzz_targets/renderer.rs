//! The `Renderer` itself (issue #36): random frames of every shape kind
//! embedded-graphics users draw with `AaStyle` / `AaGradient` (circles,
//! ellipses, arcs, sectors, rectangles, rounded rectangles, lines,
//! polylines, triangles, SVG paths), strokes of any width, join, cap,
//! dash pattern and alignment, linear and radial gradients, text in the
//! bundled font (`AaTextStyle` over `SANS_16`, any baseline and
//! alignment, any opacity), and a `TriangleList`, on an RGB565 display
//! (three channels), with coordinates near the frame and far beyond the
//! range.
//!
//! Oracles that can fail:
//! - band invariance: the same pixels and the same report in bands of
//!   16, 3 and 1 rows;
//! - cache invariance: the same pixels with and without walk-cache
//!   slots, and with a shape cache (of a size that may overflow) over two
//!   frames that share it;
//! - window = frame: `render_window` of a sub-rectangle gives that part
//!   of the whole frame, and sends nothing outside it;
//! - lent = streamed: the frame and the window made in a lent band
//!   buffer (`render_lent`, `render_window_lent`, a `BandTarget` whose
//!   buffer is scrambled between bands) are the streamed ones, report
//!   and all;
//! - the walk cache across frames: one `Renderer` kept over five
//!   frames (as firmware keeps it: its 1, 4 or 64 walk-cache slots, its
//!   band storage, maybe a shape cache), drawing the frame, a window of
//!   it, a changed frame (the items shuffled, one maybe dropped, one
//!   duplicated, one recoloured, the triangle list moved), a window of
//!   that, and the first frame again, gives each time the pixels (and,
//!   for whole frames, the report) of a fresh renderer without slots;
//! - text ink inside the measured box: each text item, drawn alone
//!   (white, opaque, over black), changes only pixels inside its
//!   `Text::bounding_box()` (embedded-graphics' `Dimensions` contract,
//!   "a rectangle that contains all drawn pixels"; `AaTextStyle`'s
//!   `measure_string` gives each line's box), for positions within
//!   2^16 px;
//! - rejected shapes reported, the rest drawn: every drawing the canvas
//!   rejected with a range error drew nothing (the frame without it is
//!   the same, its report one shorter), and every drawing counts in the
//!   report;
//! - no panic, and (with libFuzzer's `-timeout`) no frame that takes
//!   long: an input slower than the budget is a finding.
//!
//! The items are made in `Item::read`; the drawing API is used in `draw`.
#![no_main]

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    Arc, Circle, CornerRadii, Ellipse, Line, Polyline, Rectangle, RoundedRectangle, Sector,
    Triangle,
};
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use libfuzzer_sys::fuzz_target;
use softedge::canvas::ShapeEntry;
use softedge::path::svg::SvgPath;
use softedge::path::{Segment, StrokeAlignment};
use softedge::prelude::*;
use softedge::style::{Gradient, Offset, Stop};
use softedge::text::bundled::SANS_16;
use softedge::text::{AaTextStyle, RasterFont};
use softedge_fuzz::Input;

/// Items per frame.
const MAX_ITEMS: usize = 10;
/// Triangles in the frame's list.
const LIST: usize = 8;

/// What an item draws.
#[derive(Debug, Clone)]
enum Geometry {
    Circle(Point, u32),
    Ellipse(Point, Size),
    Arc(Point, u32, f32, f32),
    Sector(Point, u32, f32, f32),
    Rect(Point, Size),
    Rounded(Point, Size, [Size; 4]),
    Line(Point, Point),
    Polyline(Vec<Point>),
    Triangle(Point, Point, Point),
    Svg(String),
    /// The string, its position, and its layout: baseline `% 4`,
    /// alignment `/ 4 % 3`.
    Text(String, Point, u8),
}

/// How: a colour fill or stroke, or a gradient.
#[derive(Debug, Clone)]
struct Paint {
    stroke: bool,
    color: Rgb565,
    /// Stroke width in fine units.
    width: u32,
    join: LineJoin,
    cap: LineCap,
    alignment: u8,
    dash: Option<(Vec<u32>, i32)>,
    opacity: u16,
    even_odd: bool,
    /// A gradient instead of the colour: linear (false) or radial.
    gradient: Option<(bool, Point, Point, Rgb565)>,
}

#[derive(Debug, Clone)]
struct Item {
    geometry: Geometry,
    paint: Paint,
}

fn point(inp: &mut Input<'_>, w: u16, h: u16) -> Point {
    let mut c = |size: u16| match inp.u8() % 16 {
        0 => inp.u32() as i32,
        1 => inp.range(-6000, 6000),
        2 => inp.range(2030, 2070) * if inp.bool() { 1 } else { -1 },
        _ => inp.range(-8, i32::from(size) + 8),
    };
    Point::new(c(w), c(h))
}

fn size(inp: &mut Input<'_>, w: u16) -> u32 {
    match inp.u8() % 16 {
        0 => inp.u32(),
        1 => inp.range(0, 5000) as u32,
        _ => inp.range(0, i32::from(w) + 8) as u32,
    }
}

fn angle(inp: &mut Input<'_>) -> f32 {
    match inp.u8() % 12 {
        0 => f32::from_bits(inp.u32()),
        1 => f32::NAN,
        2 => f32::INFINITY,
        _ => inp.range(-720, 720) as f32 * 0.5,
    }
}

/// A window inside the `w x h` frame, at least a pixel each way.
fn window_in(inp: &mut Input<'_>, w: u16, h: u16) -> Rectangle {
    Rectangle::new(
        Point::new(
            inp.range(0, i32::from(w) - 1),
            inp.range(0, i32::from(h) - 1),
        ),
        Size::new(
            inp.range(1, i32::from(w)) as u32,
            inp.range(1, i32::from(h)) as u32,
        ),
    )
}

fn color(inp: &mut Input<'_>) -> Rgb565 {
    Rgb565::new(inp.u8() & 31, inp.u8() & 63, inp.u8() & 31)
}

impl Item {
    fn read(inp: &mut Input<'_>, w: u16, h: u16) -> Self {
        let geometry = match inp.u8() % 11 {
            0 => Geometry::Circle(point(inp, w, h), size(inp, w)),
            1 => Geometry::Ellipse(point(inp, w, h), Size::new(size(inp, w), size(inp, h))),
            2 => Geometry::Arc(point(inp, w, h), size(inp, w), angle(inp), angle(inp)),
            3 => Geometry::Sector(point(inp, w, h), size(inp, w), angle(inp), angle(inp)),
            4 => Geometry::Rect(point(inp, w, h), Size::new(size(inp, w), size(inp, h))),
            5 => {
                let at = point(inp, w, h);
                let s = Size::new(size(inp, w), size(inp, h));
                let r = core::array::from_fn(|_| Size::new(size(inp, w), size(inp, h)));
                Geometry::Rounded(at, s, r)
            }
            6 => Geometry::Line(point(inp, w, h), point(inp, w, h)),
            7 => {
                let n = 1 + usize::from(inp.u8() % 12);
                Geometry::Polyline((0..n).map(|_| point(inp, w, h)).collect())
            }
            8 => Geometry::Triangle(point(inp, w, h), point(inp, w, h), point(inp, w, h)),
            9 => {
                // Path data from a small alphabet of commands and numbers.
                let mut d = String::from("M");
                let n = 1 + inp.u8() % 12;
                for _ in 0..n {
                    let c = b"MLHVCSQTAZmlhvcsqtaz ,0123456789.-e"[usize::from(inp.u8() % 35)];
                    d.push(c as char);
                    if inp.bool() {
                        d.push_str(&format!(" {} ", inp.range(-60, 2100)));
                    }
                }
                Geometry::Svg(d)
            }
            _ => {
                let n = usize::from(inp.u8() % 8);
                let s: String = (0..n)
                    .map(|_| {
                        " AVTo!0123456789.%\nWaé"
                            .chars()
                            .nth(usize::from(inp.u8() % 21))
                            .unwrap_or(' ')
                    })
                    .collect();
                Geometry::Text(s, point(inp, w, h), inp.u8())
            }
        };
        let stroke = inp.bool();
        let width = match inp.u8() % 8 {
            0 => inp.u32() % (1 << 23),
            1 => inp.range(1, 1024) as u32,
            _ => inp.range(0, 12) as u32 * 1024,
        };
        let join = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel][usize::from(inp.u8() % 3)];
        let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][usize::from(inp.u8() % 3)];
        let dash = if inp.u8() % 4 == 0 {
            let n = 1 + usize::from(inp.u8() % 5);
            let pattern = (0..n)
                .map(|_| match inp.u8() % 6 {
                    0 => 0,
                    1 => inp.u32() % 4096,
                    _ => inp.range(1, 16) as u32 * 512,
                })
                .collect();
            Some((pattern, inp.range(-20_000, 20_000)))
        } else {
            None
        };
        let gradient = if inp.u8() % 4 == 0 {
            Some((inp.bool(), point(inp, w, h), point(inp, w, h), color(inp)))
        } else {
            None
        };
        Item {
            geometry,
            paint: Paint {
                stroke,
                color: color(inp),
                width,
                join,
                cap,
                alignment: inp.u8() % 3,
                dash,
                opacity: if inp.bool() { 4096 } else { inp.u16() % 4097 },
                even_odd: inp.bool(),
                gradient,
            },
        }
    }
}

/// The one use of the drawing API: every item, in order, into one band;
/// `alive[k]` false leaves item `k` out. Marks in `rejected[k]` the items
/// the canvas rejected (a new entry in its report while drawing them),
/// the first time (the report is per band: the frame's is the most any
/// band had).
fn draw(
    c: &mut Canvas<'_, '_, 3, Rgb565>,
    items: &[Item],
    alive: &[bool],
    list: &TriangleList<'_, 3>,
    list_first: usize,
    rejected: &mut [Option<DrawError>],
) -> Result<(), core::convert::Infallible> {
    for (k, item) in items.iter().enumerate() {
        if k == list_first {
            c.fill_triangles(list);
        }
        if !alive[k] {
            continue;
        }
        let before = c.skipped().count;
        draw_item(c, item);
        let after = c.skipped();
        if after.count > before {
            if let Some(r @ None) = rejected.get_mut(k) {
                // The band's first rejection is the one its canvas names;
                // a later one is marked by a stand-in (its error unknown).
                *r = Some(match (before, after.first) {
                    (0, Some((_, e))) => e,
                    _ => DrawError::Incomplete,
                });
            }
        }
    }
    if list_first >= items.len() {
        c.fill_triangles(list);
    }
    Ok(())
}

fn draw_item(c: &mut Canvas<'_, '_, 3, Rgb565>, item: &Item) {
    let p = &item.paint;
    let pattern;
    let mut style = if p.stroke {
        AaStyle::with_stroke(p.color, 0).stroke_width_fine(p.width)
    } else {
        AaStyle::with_fill(p.color)
    }
    .join(p.join)
    .cap(p.cap)
    .stroke_alignment(match p.alignment {
        0 => StrokeAlignment::Centre,
        1 => StrokeAlignment::Inside,
        _ => StrokeAlignment::Outside,
    })
    .opacity(Opacity::from_4096ths(p.opacity))
    .fill_rule(if p.even_odd {
        FillRule::EvenOdd
    } else {
        FillRule::NonZero
    });
    if let Some((pat, off)) = &p.dash {
        pattern = pat.clone();
        style = style.dash(Dash::new(&pattern, *off));
    }
    let gradient = p.gradient.and_then(|(radial, a, b, c2)| {
        let stops = [Stop::new(Offset::ZERO, p.color), Stop::new(Offset::ONE, c2)];
        let (fa, fb) = (FinePoint::from_px(a.x, a.y), FinePoint::from_px(b.x, b.y));
        if radial {
            let r = (b.x.wrapping_sub(a.x)).unsigned_abs().min(1 << 20) as i32 * 1024;
            Gradient::radial(fa, r, &stops).ok()
        } else {
            Gradient::linear(fa, fb, &stops).ok()
        }
    });
    let g_style = gradient.as_ref().map(|g| {
        let s = if p.stroke {
            AaGradient::stroke(g, 0).stroke_style(style.stroke)
        } else {
            AaGradient::fill(g)
        };
        s.fill_rule(style.fill_rule)
    });
    macro_rules! go {
        ($prim:expr) => {{
            let prim = $prim;
            match &g_style {
                Some(gs) => {
                    let _ = prim.into_styled(*gs).draw(c);
                }
                None => {
                    let _ = prim.into_styled(style).draw(c);
                }
            }
        }};
    }
    use embedded_graphics::geometry::AngleUnit;
    match &item.geometry {
        Geometry::Circle(at, d) => go!(Circle::new(*at, *d)),
        Geometry::Ellipse(at, s) => go!(Ellipse::new(*at, *s)),
        Geometry::Arc(at, d, a, b) => go!(Arc::new(*at, *d, a.deg(), b.deg())),
        Geometry::Sector(at, d, a, b) => go!(Sector::new(*at, *d, a.deg(), b.deg())),
        Geometry::Rect(at, s) => go!(Rectangle::new(*at, *s)),
        Geometry::Rounded(at, s, r) => go!(RoundedRectangle::new(
            Rectangle::new(*at, *s),
            CornerRadii {
                top_left: r[0],
                top_right: r[1],
                bottom_right: r[2],
                bottom_left: r[3],
            }
        )),
        Geometry::Line(a, b) => go!(Line::new(*a, *b)),
        Geometry::Polyline(v) => go!(Polyline::new(v)),
        Geometry::Triangle(a, b, t) => go!(Triangle::new(*a, *b, *t)),
        Geometry::Svg(d) => {
            if let Ok(path) = SvgPath::new(d) {
                go!(path)
            }
        }
        Geometry::Text(s, at, layout) => {
            let _ = text(s, *at, *layout, p.color, p.opacity).draw(c);
        }
    }
}

/// A text item's `Text`: in the bundled font, laid out as `layout` says.
fn text(
    s: &str,
    at: Point,
    layout: u8,
    color: Rgb565,
    opacity: u16,
) -> Text<'_, AaTextStyle<&'static RasterFont<'static>, Rgb565>> {
    let baseline = [
        Baseline::Alphabetic,
        Baseline::Top,
        Baseline::Middle,
        Baseline::Bottom,
    ][usize::from(layout % 4)];
    let alignment =
        [Alignment::Left, Alignment::Center, Alignment::Right][usize::from(layout / 4 % 3)];
    let style = AaTextStyle::new(&SANS_16, color).opacity(Opacity::from_4096ths(opacity));
    let layout = TextStyleBuilder::new()
        .baseline(baseline)
        .alignment(alignment)
        .build();
    Text::with_text_style(s, at, style, layout)
}

/// A display that keeps what it is sent, and whether anything was sent
/// outside its window.
struct Screen {
    w: u16,
    h: u16,
    px: Vec<Option<Rgb565>>,
}

impl Screen {
    fn new(w: u16, h: u16) -> Self {
        Self {
            w,
            h,
            px: vec![None; usize::from(w) * usize::from(h)],
        }
    }
}

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(u32::from(self.w), u32::from(self.h))
    }
}

impl DrawTarget for Screen {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            assert!(
                p.x >= 0 && p.y >= 0 && p.x < i32::from(self.w) && p.y < i32::from(self.h),
                "a pixel sent outside the display: {p:?}"
            );
            self.px[p.y as usize * usize::from(self.w) + p.x as usize] = Some(c);
        }
        Ok(())
    }
}

/// A display that lends a band buffer (`BandTarget`) and keeps what each
/// band sends in a `Screen`; the buffer is scrambled after each band.
struct Lending {
    screen: Screen,
    band: Vec<u16>,
}

impl OriginDimensions for Lending {
    fn size(&self) -> Size {
        self.screen.size()
    }
}

impl BandTarget for Lending {
    type Color = Rgb565;
    type Raw = u16;
    type Error = core::convert::Infallible;
    fn buffer(&mut self) -> &mut [u16] {
        &mut self.band
    }
    fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error> {
        let px: Vec<_> = area
            .points()
            .zip(&self.band)
            .map(|(p, &v)| {
                Pixel(
                    p,
                    Rgb565::from(embedded_graphics::pixelcolor::raw::RawU16::new(v)),
                )
            })
            .collect();
        let n = area.size.width as usize * area.size.height as usize;
        assert_eq!(px.len(), n, "a band larger than the lent buffer was sent");
        self.screen.draw_iter(px)?;
        self.band.fill(0x5a5a);
        Ok(())
    }
}

/// A frame: its pixels and report.
struct Frame {
    px: Vec<Option<Rgb565>>,
    skipped: (u32, Option<(u32, DrawError)>),
    rejected: Vec<Option<DrawError>>,
}

struct Scene<'a> {
    w: u16,
    h: u16,
    items: &'a [Item],
    tris: &'a [([FinePoint; 3], [Rgb565; 3])],
    list_first: usize,
}

impl Scene<'_> {
    /// Renders in bands of `rows`, with `slots` walk-cache slots, the
    /// whole frame or `window`, leaving out the items `alive` says.
    fn render(&self, rows: u16, slots: usize, window: Option<Rectangle>, alive: &[bool]) -> Frame {
        self.render_cached(rows, slots, window, alive, None)
    }

    /// [`render`](Self::render), with a shape cache over `shapes` (kept
    /// from frame to frame by the caller).
    fn render_cached(
        &self,
        rows: u16,
        slots: usize,
        window: Option<Rectangle>,
        alive: &[bool],
        shapes: Option<(&mut [Segment], &mut [ShapeEntry])>,
    ) -> Frame {
        self.render_on(rows, slots, window, alive, shapes, false)
    }

    /// A fresh renderer's frame: streamed, or `lent`.
    fn render_on(
        &self,
        rows: u16,
        slots: usize,
        window: Option<Rectangle>,
        alive: &[bool],
        shapes: Option<(&mut [Segment], &mut [ShapeEntry])>,
        lent: bool,
    ) -> Frame {
        let rows = rows.clamp(1, self.h);
        let mut acc = vec![0i32; BandBuffer::<3>::acc_len(self.w, rows)];
        let mut cover = vec![0i32; BandBuffer::<3>::cover_len(self.w, rows)];
        let mut slot_store = vec![WalkSlot::<3>::EMPTY; slots];
        let mut r = Renderer::new(&mut acc, &mut cover, &mut slot_store, self.w, self.h, rows)
            .expect("a valid frame");
        if let Some((segments, entries)) = shapes {
            r = r.with_shape_cache(segments, entries);
        }
        self.render_with(&mut r, window, alive, lent)
    }

    /// [`render`](Self::render) into a display that lends its band
    /// buffer (`Renderer::render_lent`, `render_window_lent`).
    fn render_lent(
        &self,
        rows: u16,
        slots: usize,
        window: Option<Rectangle>,
        alive: &[bool],
    ) -> Frame {
        self.render_on(rows, slots, window, alive, None, true)
    }

    /// One frame (or `window` of it) through renderer `r`, which the
    /// caller keeps from frame to frame (its walk-cache slots, band
    /// storage and shape cache with it).
    fn render_with(
        &self,
        r: &mut Renderer<'_, 3>,
        window: Option<Rectangle>,
        alive: &[bool],
        lent: bool,
    ) -> Frame {
        let mut store = [ListedTriangle::<3>::EMPTY; LIST];
        let mut list = TriangleList::new(&mut store);
        for (v, cs) in self.tris {
            let lin = cs.map(|c| softedge::color::IntoLinear::<3>::into_linear(c));
            let _ = list.push(*v, lin, Blend::Over, Opacity::OPAQUE);
        }
        let mut screen = Screen::new(self.w, self.h);
        let format = Rgb565Format::new(Curve::Srgb);
        let mut rejected = vec![None; self.items.len()];
        let f = |c: &mut Canvas<'_, '_, 3, Rgb565>| {
            draw(c, self.items, alive, &list, self.list_first, &mut rejected)
        };
        let mut lending = Lending {
            screen: Screen::new(self.w, self.h),
            band: vec![0x5a5a; usize::from(self.w) * usize::from(self.h)],
        };
        let report = match (window, lent) {
            (Some(w), false) => r.render_window(&mut screen, &format, Rgb565::BLACK, w, f),
            (None, false) => r.render(&mut screen, &format, Rgb565::BLACK, f),
            (Some(w), true) => r.render_window_lent(&mut lending, &format, Rgb565::BLACK, w, f),
            (None, true) => r.render_lent(&mut lending, &format, Rgb565::BLACK, f),
        }
        .unwrap_or_else(|e| panic!("render failed: {e:?}"));
        if lent {
            screen = lending.screen;
        }
        Frame {
            px: screen.px,
            skipped: (report.skipped.count, report.skipped.first),
            rejected,
        }
    }
}

/// Window = frame: `part`, rendered over `window`, is `whole` inside the
/// window (clipped to the display) and sent nothing outside it.
fn check_window(part: &Frame, whole: &Frame, window: Rectangle, w: u16, h: u16, what: &str) {
    let win = window.intersection(&Rectangle::new(
        Point::zero(),
        Size::new(u32::from(w), u32::from(h)),
    ));
    for y in 0..i32::from(h) {
        for x in 0..i32::from(w) {
            let k = y as usize * usize::from(w) + x as usize;
            if win.contains(Point::new(x, y)) {
                assert_eq!(
                    part.px[k], whole.px[k],
                    "{what}: window {window:?}: pixel ({x}, {y}) differs from the frame"
                );
            } else {
                assert_eq!(
                    part.px[k], None,
                    "{what}: window {window:?}: pixel ({x}, {y}) sent outside it"
                );
            }
        }
    }
}

/// The same pixels and report.
fn check_same(a: &Frame, b: &Frame, w: u16, what: &str) {
    if let Some(p) = diff(&a.px, &b.px, w) {
        panic!("{what}: pixel {p:?} differs");
    }
    assert_eq!(a.skipped, b.skipped, "{what}: the report differs");
    assert_eq!(a.rejected, b.rejected, "{what}: other rejections");
}

fn diff(a: &[Option<Rgb565>], b: &[Option<Rgb565>], w: u16) -> Option<(usize, usize)> {
    a.iter()
        .zip(b)
        .position(|(p, q)| p != q)
        .map(|k| (k % usize::from(w), k / usize::from(w)))
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let (w, h) = (inp.side(40), inp.side(32));
    let slots = [0, 4, 64][usize::from(inp.u8() % 3)];
    let cache_segments = [16, 256, 4096][usize::from(inp.u8() % 3)];
    let cache_entries = 1 + usize::from(inp.u8() % 8);
    let mut items = Vec::new();
    let n = usize::from(inp.u8()) % (MAX_ITEMS + 1);
    for _ in 0..n {
        items.push(Item::read(&mut inp, w, h));
    }
    let tris: Vec<_> = (0..usize::from(inp.u8()) % (LIST + 1))
        .map(|_| {
            let mut p = || {
                let q = point(&mut inp, w, h);
                FinePoint::new(
                    q.x.saturating_mul(1024).saturating_add(inp.range(0, 1023)),
                    q.y.saturating_mul(1024).saturating_add(inp.range(0, 1023)),
                )
            };
            let v = [p(), p(), p()];
            (v, [color(&mut inp), color(&mut inp), color(&mut inp)])
        })
        .collect();
    let list_first = usize::from(inp.u8()) % (items.len() + 1);
    let window = window_in(&mut inp, w, h);
    // The renderer kept over frames, and the frame that changes.
    let kept_slots = [1, 4, 64][usize::from(inp.u8() % 3)];
    let kept_rows = [1, 3, 16][usize::from(inp.u8() % 3)].min(h);
    let kept_shapes = inp.bool();
    let mut items_b = items.clone();
    for i in 0..items_b.len() {
        let j = i + usize::from(inp.u8()) % (items_b.len() - i);
        items_b.swap(i, j);
    }
    if !items_b.is_empty() && inp.u8() % 4 == 0 {
        items_b.remove(usize::from(inp.u8()) % items_b.len());
    }
    if !items_b.is_empty() && inp.u8() % 4 == 0 {
        let k = usize::from(inp.u8()) % items_b.len();
        let at = usize::from(inp.u8()) % (items_b.len() + 1);
        items_b.insert(at, items_b[k].clone());
    }
    if !items_b.is_empty() && inp.bool() {
        let k = usize::from(inp.u8()) % items_b.len();
        items_b[k].paint.color = color(&mut inp);
    }
    let list_first_b = usize::from(inp.u8()) % (items_b.len() + 1);
    let window_b = window_in(&mut inp, w, h);
    let scene = Scene {
        w,
        h,
        items: &items,
        tris: &tris,
        list_first,
    };
    let other = Scene {
        w,
        h,
        items: &items_b,
        tris: &tris,
        list_first: list_first_b,
    };
    let all_b = vec![true; items_b.len()];
    let all = vec![true; items.len()];

    let frame = scene.render(16, slots, None, &all);
    // Every pixel of the display is sent.
    assert!(frame.px.iter().all(Option::is_some), "a pixel not sent");

    // Band invariance, and walk-cache invariance.
    for (rows, s) in [(3, slots), (1, slots), (3, 0), (16, 64)] {
        let other = scene.render(rows, s, None, &all);
        if let Some(p) = diff(&frame.px, &other.px, w) {
            panic!("bands of 16 and {rows} rows, {slots} and {s} slots: pixel {p:?} differs");
        }
        assert_eq!(
            frame.skipped, other.skipped,
            "the report differs in bands of {rows}"
        );
        assert_eq!(
            frame.rejected, other.rejected,
            "other rejections in bands of {rows}"
        );
    }

    // Shape-cache invariance, over two frames sharing the cache (the
    // second draws from what the first kept; small caches overflow and
    // evict).
    let mut segments = vec![Segment::ZERO; cache_segments];
    let mut entries = vec![ShapeEntry::EMPTY; cache_entries];
    for pass in 0..2 {
        let cached = scene.render_cached(3, slots, None, &all, Some((&mut segments, &mut entries)));
        if let Some(p) = diff(&frame.px, &cached.px, w) {
            panic!("shape cache ({cache_segments} segments, {cache_entries} entries), frame {pass}: pixel {p:?} differs");
        }
        assert_eq!(
            frame.skipped, cached.skipped,
            "the report differs with a shape cache"
        );
    }

    // Window = frame.
    let part = scene.render(3, slots, Some(window), &all);
    check_window(&part, &frame, window, w, h, "a fresh renderer");

    // Lent = streamed: the frame and the window made in a lent band
    // buffer.
    let lent = scene.render_lent(3, slots, None, &all);
    check_same(&frame, &lent, w, "the frame into a lent band buffer");
    let lent = scene.render_lent(16, slots, Some(window), &all);
    check_window(
        &lent,
        &frame,
        window,
        w,
        h,
        "a window into a lent band buffer",
    );

    // The walk cache across frames: one renderer kept over frames, as
    // firmware keeps it (its slots, band storage and maybe a shape cache
    // with it), draws the frame, a window of it, another frame (the items
    // shuffled, one maybe dropped, one duplicated, one recoloured: its
    // edges the same, its colour not), a window of that, and the first
    // frame again: each the pixels and report of a fresh renderer without
    // slots (band invariance above makes `frame` one).
    {
        let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, kept_rows)];
        let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, kept_rows)];
        let mut slot_store = vec![WalkSlot::<3>::EMPTY; kept_slots];
        let mut segments = vec![Segment::ZERO; cache_segments];
        let mut entries = vec![ShapeEntry::EMPTY; cache_entries];
        let mut r = Renderer::new(&mut acc, &mut cover, &mut slot_store, w, h, kept_rows)
            .expect("a valid frame");
        if kept_shapes {
            r = r.with_shape_cache(&mut segments, &mut entries);
        }
        let what = format!(
            "one renderer, {kept_slots} slots, bands of {kept_rows}, shape cache {kept_shapes}"
        );
        let fresh_b = other.render(kept_rows, 0, None, &all_b);
        let a = scene.render_with(&mut r, None, &all, false);
        check_same(&frame, &a, w, &format!("{what}, frame 1"));
        let part = scene.render_with(&mut r, Some(window), &all, false);
        check_window(&part, &frame, window, w, h, &format!("{what}, frame 2"));
        let b = other.render_with(&mut r, None, &all_b, false);
        check_same(&fresh_b, &b, w, &format!("{what}, frame 3 (changed)"));
        let part = other.render_with(&mut r, Some(window_b), &all_b, false);
        check_window(&part, &fresh_b, window_b, w, h, &format!("{what}, frame 4"));
        let a = scene.render_with(&mut r, None, &all, false);
        check_same(&frame, &a, w, &format!("{what}, frame 5 (the first again)"));
    }

    // Text ink inside the measured box: each text item drawn alone (white,
    // opaque, over black) changes only pixels inside its `bounding_box()`
    // (embedded-graphics' `Dimensions`: "a rectangle that contains all
    // drawn pixels"; `AaTextStyle::measure_string` gives each line's).
    // Positions beyond 2^16 px are left out: embedded-graphics' own
    // layout arithmetic there overflows (and no ink reaches the display).
    for item in &items {
        let Geometry::Text(s, at, layout) = &item.geometry else {
            continue;
        };
        if at.x.unsigned_abs() >= 1 << 16 || at.y.unsigned_abs() >= 1 << 16 {
            continue;
        }
        let bb = text(s, *at, *layout, Rgb565::WHITE, 4096).bounding_box();
        let mut white = item.clone();
        white.paint.color = Rgb565::WHITE;
        white.paint.opacity = 4096;
        let alone = [white];
        let only = Scene {
            w,
            h,
            items: &alone,
            tris: &[],
            list_first: 1,
        };
        let f = only.render(16, 0, None, &[true]);
        let (x1, y1) = (
            i64::from(bb.top_left.x) + i64::from(bb.size.width),
            i64::from(bb.top_left.y) + i64::from(bb.size.height),
        );
        for (k, px) in f.px.iter().enumerate() {
            let (x, y) = ((k % usize::from(w)) as i32, (k / usize::from(w)) as i32);
            let inside =
                x >= bb.top_left.x && y >= bb.top_left.y && i64::from(x) < x1 && i64::from(y) < y1;
            assert!(
                inside || *px == Some(Rgb565::BLACK),
                "text {s:?} at {at:?} (layout {layout}) inks ({x}, {y}) outside its box {bb:?}"
            );
        }
    }

    // Rejected drawings: counted, and (a point out of range) drew nothing.
    let count = frame.rejected.iter().flatten().count() as u32;
    assert!(
        frame.skipped.0 >= count,
        "{} rejections reported, {count} seen",
        frame.skipped.0
    );
    let nothing_drawn = |e: &DrawError| {
        matches!(
            e,
            DrawError::OutOfRange { .. } | DrawError::FineCoord(_) | DrawError::Coord(_)
        )
    };
    let alive: Vec<bool> = frame
        .rejected
        .iter()
        .map(|r| !r.as_ref().is_some_and(nothing_drawn))
        .collect();
    let removed = alive.iter().filter(|a| !**a).count() as u32;
    if removed > 0 {
        let without = scene.render(16, slots, None, &alive);
        if let Some(p) = diff(&frame.px, &without.px, w) {
            panic!("a rejected drawing changed pixel {p:?}");
        }
        assert_eq!(
            without.skipped.0 + removed,
            frame.skipped.0,
            "the report does not count the rejected drawings"
        );
    }
});
