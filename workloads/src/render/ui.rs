//! Shapes and partial redraw (issues 16 and 15): embedded-graphics
//! primitives drawn by softedge (anti-aliased, `AaStyle` through the
//! frame loop) and by embedded-graphics itself (aliased, `PrimitiveStyle`
//! into a framebuffer), on a 240x240 Rgb565 frame, black background.
//!
//! - [`Shape`]: one shape alone on the frame: the [`disc`] (a filled
//!   circle of radius 50 centred on (120, 120)) or the [`gauge`] (an arc
//!   of radius 90 on the same centre, stroke 12 px, from 135° sweeping
//!   270° clockwise, butt caps), or nothing (the fixed cost the marginal
//!   costs are taken against).
//! - [`softedge_scene`] / [`eg_scene`]: a small dial screen (a panel,
//!   the gauge's track and value, the disc, a read-out in its centre, a header and two buttons)
//!   rendered whole or only inside a dirty rectangle ([`DIRTY`]: the
//!   read-out's 20x20 pixels): softedge with `Renderer::render_window`,
//!   embedded-graphics by clearing the rectangle in its framebuffer and
//!   redrawing, clipped to it, the shapes whose bounding box meets it.
//!   [`softedge_scene_cached`]: the same scene through a renderer with a
//!   shape cache ([`SceneCache`]), the same pixels.
//!
//! Both sides draw the very same primitives (embedded-graphics geometry)
//! in the same colours (Rgb565, which softedge takes as sRGB).

use core::hint::black_box;

use embedded_graphics::geometry::AngleUnit;
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, Polyline, PrimitiveStyle, Rectangle};
use softedge::canvas::ShapeEntry;
use softedge::path::Segment;
use softedge::prelude::*;
use softedge::render::{BandTarget, Renderer as FrameRenderer};
use softedge::tone::Curve;

use super::softedge_side::{Buffers, FrameError};
use super::targets::BandStream;
use crate::FRAME;

/// Band height of every softedge frame here (as the triangle bench's).
pub const BAND_ROWS: u16 = 16;

/// The display's tone stage: sRGB γ, Rgb565 (tables in flash).
static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// Centre of the disc and of the gauge.
const CENTRE: Point = Point::new(120, 120);
/// The disc's diameter: radius 50 px.
const DISC_DIAMETER: u32 = 100;
/// The gauge's diameter: radius 90 px (the stroke's centre line).
const GAUGE_DIAMETER: u32 = 180;
/// The gauge's stroke width, px.
pub const GAUGE_STROKE: u32 = 12;
/// Where the gauge starts, degrees clockwise from +x (bottom left).
const GAUGE_START_DEG: f32 = 135.0;
/// The gauge's sweep, degrees clockwise.
const GAUGE_SWEEP_DEG: f32 = 270.0;
/// The value arc's sweep over the track, degrees (the needle's reading).
const VALUE_SWEEP_DEG: f32 = 200.0;

/// The filled circle: radius 50, centre (120, 120).
pub fn disc() -> Circle {
    Circle::with_center(CENTRE, DISC_DIAMETER)
}

/// The gauge arc: radius 90, centre (120, 120), from 135° over 270°.
pub fn gauge() -> Arc {
    Arc::with_center(
        CENTRE,
        GAUGE_DIAMETER,
        GAUGE_START_DEG.deg(),
        GAUGE_SWEEP_DEG.deg(),
    )
}

/// Points of the line chart.
pub const CHART_POINTS: usize = 60;
/// The chart's stroke width, px.
pub const CHART_STROKE: u32 = 3;

/// A line chart: 60 points, 4 px apart from x = 2, a pseudo-random walk
/// about y = 120 within 60..180 (integers only: the series is a `const`).
pub const CHART: [Point; CHART_POINTS] = chart_points();

const fn chart_points() -> [Point; CHART_POINTS] {
    let mut p = [Point::zero(); CHART_POINTS];
    let (mut y, mut seed) = (120i32, 12_345u32);
    let mut k = 0;
    while k < CHART_POINTS {
        p[k] = Point::new(2 + 4 * k as i32, y);
        seed = seed.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        let step = ((seed >> 16) % 25) as i32 - 12;
        y += step;
        if y < 60 || y > 180 {
            y -= 2 * step;
        }
        k += 1;
    }
    p
}

/// The line chart as an embedded-graphics polyline.
pub fn chart() -> Polyline<'static> {
    Polyline::new(&CHART)
}

const DISC_COLOR: Rgb565 = Rgb565::new(4, 20, 26);
const GAUGE_COLOR: Rgb565 = Rgb565::new(26, 52, 8);

/// What one shape frame draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// Nothing: the frame's fixed cost.
    None,
    /// [`disc`], filled.
    Disc,
    /// [`gauge`], stroked [`GAUGE_STROKE`] px, butt caps.
    Gauge,
    /// [`gauge`], stroked [`GAUGE_STROKE`] px, round caps
    /// (embedded-graphics has no caps: its arc keeps butt ends).
    GaugeRound,
    /// [`chart`], stroked [`CHART_STROKE`] px, miter joins (e-g's
    /// polyline joins), butt caps.
    Chart,
    /// The same chart drawn the same way through a renderer with a shape
    /// cache, empty when the frame starts: the chart's stroke is described
    /// in the first band and filled from the cache in the others
    /// (embedded-graphics draws [`Chart`](Self::Chart) again).
    ChartCached,
}

impl Shape {
    /// Every shape, in the order of the output.
    pub const ALL: [Shape; 6] = [
        Shape::None,
        Shape::Disc,
        Shape::Gauge,
        Shape::GaugeRound,
        Shape::Chart,
        Shape::ChartCached,
    ];

    /// The name printed in the output.
    pub fn name(self) -> &'static str {
        match self {
            Shape::None => "none",
            Shape::Disc => "circle",
            Shape::Gauge => "gauge",
            Shape::GaugeRound => "gauge_round",
            Shape::Chart => "chart",
            Shape::ChartCached => "chart_cached",
        }
    }
}

/// A softedge frame of `shape` alone, 16-row bands, into `bufs.out16`.
pub fn softedge_shape(shape: Shape, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    shape_stream(shape, bufs, false)
}

/// [`softedge_shape`] into the same buffer lent as the band's
/// (`Renderer::render_lent`): the band's colours made in it, not
/// streamed into it.
pub fn softedge_shape_lent(shape: Shape, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    shape_stream(shape, bufs, true)
}

/// A frame of `shape` into `bufs.out16`: streamed, or `lent`.
#[inline(never)]
fn shape_stream(shape: Shape, bufs: &mut Buffers<'_>, lent: bool) -> Result<(), FrameError> {
    let out = &mut *bufs.out16;
    let mut sink = BandStream::new(out, u32::from(FRAME), u32::from(FRAME));
    let parts = Buffers {
        acc: &mut *bufs.acc,
        cover: &mut *bufs.cover,
        out16: &mut [],
        out8: &mut *bufs.out8,
        slots3: &mut *bufs.slots3,
        slots1: &mut *bufs.slots1,
        list3: &mut *bufs.list3,
    };
    if lent {
        shape_into(shape, parts, &mut Lent(&mut sink))?;
    } else {
        shape_into(shape, parts, &mut sink)?;
    }
    black_box(sink.pixels());
    Ok(())
}

/// Segments of the chart's shape cache: its stroke has 228, its
/// description (kept to compare) 31.
pub const CHART_SEGMENTS: usize = 288;

/// [`softedge_shape`] into any display; the shape cache's (kept,
/// described) outlines.
fn shape_into<D>(shape: Shape, bufs: Buffers<'_>, target: &mut D) -> Result<(u32, u32), FrameError>
where
    D: Frames,
{
    if shape == Shape::ChartCached {
        return chart_cached(bufs, target);
    }
    shape_frame(
        shape,
        &mut renderer(bufs.acc, bufs.cover, bufs.slots3)?,
        target,
    )
}

/// The chart through a renderer with a shape cache on the stack (as a
/// firmware's frame function would hold it), empty when the frame starts.
#[inline(never)]
fn chart_cached<D>(bufs: Buffers<'_>, target: &mut D) -> Result<(u32, u32), FrameError>
where
    D: Frames,
{
    let mut segments = [Segment::ZERO; CHART_SEGMENTS];
    let mut entries = [ShapeEntry::EMPTY; 2];
    let r = renderer(bufs.acc, bufs.cover, bufs.slots3)?;
    let mut r = r.with_shape_cache(&mut segments, &mut entries);
    shape_frame(Shape::Chart, &mut r, target)
}

/// One frame of `shape` by `r`; the shape cache's (kept, described).
fn shape_frame<D>(
    shape: Shape,
    r: &mut FrameRenderer<'_, 3>,
    target: &mut D,
) -> Result<(u32, u32), FrameError>
where
    D: Frames,
{
    target.frame(r, None, |c| match shape {
        Shape::None => Ok(()),
        Shape::Disc => disc().into_styled(AaStyle::with_fill(DISC_COLOR)).draw(c),
        Shape::Gauge => gauge()
            .into_styled(AaStyle::with_stroke(GAUGE_COLOR, GAUGE_STROKE))
            .draw(c),
        Shape::GaugeRound => gauge()
            .into_styled(AaStyle::with_stroke(GAUGE_COLOR, GAUGE_STROKE).cap(LineCap::Round))
            .draw(c),
        Shape::Chart | Shape::ChartCached => chart().into_styled(chart_style()).draw(c),
    })?;
    Ok(r.shape_stats())
}

/// The chart's style: [`CHART_STROKE`] px, miter joins, butt caps.
fn chart_style() -> AaStyle<'static, Rgb565> {
    AaStyle::with_stroke(GAUGE_COLOR, CHART_STROKE)
}

/// An embedded-graphics frame of `shape` alone: `clear`, then the shape
/// with `PrimitiveStyle` fill or stroke (aliased).
#[inline(never)]
pub fn eg_shape<D: DrawTarget<Color = Rgb565>>(shape: Shape, target: &mut D) {
    // The benchmark's targets are infallible.
    let _ = target.clear(Rgb565::BLACK);
    let _ = match shape {
        Shape::None => Ok(()),
        Shape::Disc => disc()
            .into_styled(PrimitiveStyle::with_fill(DISC_COLOR))
            .draw(target),
        Shape::Gauge | Shape::GaugeRound => gauge()
            .into_styled(PrimitiveStyle::with_stroke(GAUGE_COLOR, GAUGE_STROKE))
            .draw(target),
        Shape::Chart | Shape::ChartCached => chart()
            .into_styled(PrimitiveStyle::with_stroke(GAUGE_COLOR, CHART_STROKE))
            .draw(target),
    };
}

/// The dirty rectangle of the partial redraws: 20x20 at (110, 110), the
/// read-out in the disc's centre.
pub const DIRTY: Rectangle = Rectangle::new(Point::new(110, 110), Size::new(20, 20));

/// The panel behind everything.
const PANEL: Rectangle = Rectangle::new(Point::new(8, 8), Size::new(224, 224));
/// The header bar, the two buttons and the read-out.
const BARS: [Rectangle; 4] = [
    Rectangle::new(Point::new(8, 8), Size::new(224, 20)),
    Rectangle::new(Point::new(24, 200), Size::new(80, 24)),
    Rectangle::new(Point::new(136, 200), Size::new(80, 24)),
    Rectangle::new(Point::new(112, 112), Size::new(16, 16)),
];
const PANEL_COLOR: Rgb565 = Rgb565::new(3, 6, 4);
const TRACK_COLOR: Rgb565 = Rgb565::new(8, 16, 10);
const BAR_COLORS: [Rgb565; 4] = [
    Rgb565::new(6, 12, 10),
    Rgb565::new(20, 40, 20),
    Rgb565::new(24, 12, 4),
    Rgb565::WHITE,
];

/// The value arc: the gauge's first [`VALUE_SWEEP_DEG`] degrees.
fn value_arc() -> Arc {
    Arc::with_center(
        CENTRE,
        GAUGE_DIAMETER,
        GAUGE_START_DEG.deg(),
        VALUE_SWEEP_DEG.deg(),
    )
}

/// The scene's shapes, in painter's order: panel, gauge track, value arc,
/// disc, header, two buttons, read-out (8 shapes).
pub const SCENE_SHAPES: usize = 8;
/// Of them, drawn from their circles' exact areas (the gauge's track and
/// value arc, the disc), never described into a shape cache.
pub const SCENE_CURVES: usize = 3;

/// Draws the scene with softedge into one band's canvas.
fn softedge_scene_band(c: &mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError> {
    PANEL.into_styled(AaStyle::with_fill(PANEL_COLOR)).draw(c)?;
    gauge()
        .into_styled(AaStyle::with_stroke(TRACK_COLOR, GAUGE_STROKE))
        .draw(c)?;
    value_arc()
        .into_styled(AaStyle::with_stroke(GAUGE_COLOR, GAUGE_STROKE))
        .draw(c)?;
    disc().into_styled(AaStyle::with_fill(DISC_COLOR)).draw(c)?;
    for (r, col) in BARS.iter().zip(BAR_COLORS) {
        r.into_styled(AaStyle::with_fill(col)).draw(c)?;
    }
    Ok(())
}

/// The scene by softedge into `target`: the whole frame (`window` `None`,
/// `Renderer::render`) or only `window` (`Renderer::render_window`), in
/// 16-row bands (the output buffer of `bufs` is not used).
#[inline(never)]
pub fn softedge_scene<D>(
    window: Option<Rectangle>,
    bufs: &mut Buffers<'_>,
    target: &mut D,
) -> Result<(), FrameError>
where
    D: Frames,
{
    let mut r = renderer(&mut *bufs.acc, &mut *bufs.cover, &mut *bufs.slots3)?;
    render_scene(&mut r, window, target, softedge_scene_band)
}

/// The whole softedge scene frame in bands of `rows` rows (at most
/// [`BAND_ROWS`]) into the one-band DMA buffer `bufs.out16`, without a
/// walk cache: what the dial's RAM is at each band height.
pub fn softedge_scene_rows(rows: u16, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    if rows == 0 || rows > BAND_ROWS {
        return Err(FrameError);
    }
    scene_stream(bufs, |b, sink| {
        let mut r =
            FrameRenderer::<3>::new(&mut *b.acc, &mut *b.cover, &mut [], FRAME, FRAME, rows)
                .map_err(|_| FrameError)?;
        render_scene(&mut r, None, sink, softedge_scene_band)
    })
}

/// A softedge scene frame into the one-band DMA buffer `bufs.out16` (what
/// is measured).
pub fn softedge_scene_stream(
    window: Option<Rectangle>,
    bufs: &mut Buffers<'_>,
) -> Result<(), FrameError> {
    scene_stream(bufs, |b, sink| softedge_scene(window, b, sink))
}

/// [`softedge_scene_stream`] with the one-band buffer lent
/// (`Renderer::render_lent`, `render_window_lent`).
pub fn softedge_scene_lent(
    window: Option<Rectangle>,
    bufs: &mut Buffers<'_>,
) -> Result<(), FrameError> {
    scene_stream(bufs, |b, sink| softedge_scene(window, b, &mut Lent(sink)))
}

/// One frame of the scene by `r` into `target`, `band` drawing each band:
/// the whole frame (`window` `None`, `Renderer::render`) or only `window`
/// (`Renderer::render_window`).
fn render_scene<D, F>(
    r: &mut FrameRenderer<'_, 3>,
    window: Option<Rectangle>,
    target: &mut D,
    band: F,
) -> Result<(), FrameError>
where
    D: Frames,
    F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
{
    target.frame(r, window, band)
}

/// How a frame reaches the display: streamed to an embedded-graphics
/// `DrawTarget` (`Renderer::render`, `render_window`), or made in the
/// band buffer a [`Lent`] display lends (`Renderer::render_lent`,
/// `render_window_lent`).
pub trait Frames {
    /// One frame of `band` by `r`, whole or only `window`.
    fn frame<F>(
        &mut self,
        r: &mut FrameRenderer<'_, 3>,
        window: Option<Rectangle>,
        band: F,
    ) -> Result<(), FrameError>
    where
        F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>;
}

impl<D: DrawTarget<Color = Rgb565> + OriginDimensions> Frames for D {
    #[inline(always)]
    fn frame<F>(
        &mut self,
        r: &mut FrameRenderer<'_, 3>,
        window: Option<Rectangle>,
        band: F,
    ) -> Result<(), FrameError>
    where
        F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
    {
        let report = match window {
            None => r.render(self, &RGB565, [0; 3], band),
            Some(w) => r.render_window(self, &RGB565, [0; 3], w, band),
        }
        .map_err(|_| FrameError)?;
        black_box(report);
        Ok(())
    }
}

/// A display that lends its band buffer (`softedge::render::BandTarget`).
pub struct Lent<'t, T>(pub &'t mut T);

impl<T: BandTarget<Color = Rgb565>> Frames for Lent<'_, T> {
    #[inline(always)]
    fn frame<F>(
        &mut self,
        r: &mut FrameRenderer<'_, 3>,
        window: Option<Rectangle>,
        band: F,
    ) -> Result<(), FrameError>
    where
        F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
    {
        let report = match window {
            None => r.render_lent(&mut *self.0, &RGB565, [0; 3], band),
            Some(w) => r.render_window_lent(&mut *self.0, &RGB565, [0; 3], w, band),
        }
        .map_err(|_| FrameError)?;
        black_box(report);
        Ok(())
    }
}

/// `scene` (one of this module's) into the one-band DMA buffer `bufs.out16`
/// (what is measured).
pub fn scene_stream(
    bufs: &mut Buffers<'_>,
    scene: impl FnOnce(&mut Buffers<'_>, &mut BandStream<'_, Rgb565>) -> Result<(), FrameError>,
) -> Result<(), FrameError> {
    let out = core::mem::take(&mut bufs.out16);
    let mut sink = BandStream::new(&mut *out, u32::from(FRAME), u32::from(FRAME));
    let r = scene(bufs, &mut sink);
    black_box(sink.pixels());
    bufs.out16 = out;
    r
}

/// Segments of the scene's shape cache: its outlines have 1 493 (the
/// two arc strokes 703 and 522, the disc 248, the panel and bars 20).
pub const CACHE_SEGMENTS: usize = 1600;
/// Entries of the scene's shape cache: one a shape (8), and a margin.
pub const CACHE_ENTRIES: usize = 12;

/// A shape cache for the scene ([`Renderer::with_shape_cache`]), kept
/// from frame to frame.
///
/// [`Renderer::with_shape_cache`]: softedge::render::Renderer::with_shape_cache
pub struct SceneCache {
    /// The outlines' segments.
    pub segments: [Segment; CACHE_SEGMENTS],
    /// One a shape.
    pub entries: [ShapeEntry; CACHE_ENTRIES],
}

impl SceneCache {
    /// Empty.
    pub const fn new() -> Self {
        Self {
            segments: [Segment::ZERO; CACHE_SEGMENTS],
            entries: [ShapeEntry::EMPTY; CACHE_ENTRIES],
        }
    }
}

impl Default for SceneCache {
    fn default() -> Self {
        Self::new()
    }
}

/// The scene drawn as [`softedge_scene`] draws it (the same closure),
/// through a renderer with `cache` as its shape cache: the first frame
/// describes every shape into it, the later ones fill them from it.
/// Returns the cache's (kept, described) of the frame.
#[inline(never)]
pub fn softedge_scene_cached<D>(
    window: Option<Rectangle>,
    bufs: &mut Buffers<'_>,
    cache: &mut SceneCache,
    target: &mut D,
) -> Result<(u32, u32), FrameError>
where
    D: Frames,
{
    let r = renderer(&mut *bufs.acc, &mut *bufs.cover, &mut *bufs.slots3)?;
    let mut r = r.with_shape_cache(&mut cache.segments, &mut cache.entries);
    render_scene(&mut r, window, target, softedge_scene_band)?;
    Ok(r.shape_stats())
}

/// Draws the scene with embedded-graphics (aliased) into `target`.
fn eg_scene_shapes<D: DrawTarget<Color = Rgb565>>(target: &mut D, only: Option<Rectangle>) {
    let meets = |b: Rectangle| only.is_none_or(|d| !d.intersection(&b).is_zero_sized());
    // The benchmark's targets are infallible.
    if meets(PANEL.bounding_box()) {
        let _ = PANEL
            .into_styled(PrimitiveStyle::with_fill(PANEL_COLOR))
            .draw(target);
    }
    let track = gauge().into_styled(PrimitiveStyle::with_stroke(TRACK_COLOR, GAUGE_STROKE));
    if meets(track.bounding_box()) {
        let _ = track.draw(target);
    }
    let value = value_arc().into_styled(PrimitiveStyle::with_stroke(GAUGE_COLOR, GAUGE_STROKE));
    if meets(value.bounding_box()) {
        let _ = value.draw(target);
    }
    let d = disc().into_styled(PrimitiveStyle::with_fill(DISC_COLOR));
    if meets(d.bounding_box()) {
        let _ = d.draw(target);
    }
    for (r, col) in BARS.iter().zip(BAR_COLORS) {
        if meets(*r) {
            let _ = r.into_styled(PrimitiveStyle::with_fill(col)).draw(target);
        }
    }
}

/// The scene by embedded-graphics into a framebuffer: the whole frame
/// (`clear`, every shape), or only `dirty` (the rectangle filled with the
/// background, then the shapes whose bounding box meets it, drawn through
/// `clipped(dirty)`).
#[inline(never)]
pub fn eg_scene<D: DrawTarget<Color = Rgb565>>(dirty: Option<Rectangle>, target: &mut D) {
    match dirty {
        None => {
            let _ = target.clear(Rgb565::BLACK);
            eg_scene_shapes(target, None);
        }
        Some(d) => {
            let _ = target.fill_solid(&d, Rgb565::BLACK);
            eg_scene_shapes(&mut target.clipped(&d), Some(d));
        }
    }
}

fn renderer<'b>(
    acc: &'b mut [i32],
    cover: &'b mut [i32],
    slots: &'b mut [WalkSlot<3>],
) -> Result<FrameRenderer<'b, 3>, FrameError> {
    FrameRenderer::<3>::new(acc, cover, slots, FRAME, FRAME, BAND_ROWS).map_err(|_| FrameError)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;
    use std::vec::Vec;

    use super::*;
    use crate::render::softedge_side::{ACC_LEN, COVER_LEN, OUT_LEN, SLOTS};
    use crate::render::targets::SpiCounter;

    /// A whole 240x240 Rgb565 frame that keeps what it is sent.
    struct Screen(Vec<u16>);

    impl OriginDimensions for Screen {
        fn size(&self) -> Size {
            Size::new(240, 240)
        }
    }

    impl DrawTarget for Screen {
        type Color = Rgb565;
        type Error = core::convert::Infallible;
        fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
            &mut self,
            px: I,
        ) -> Result<(), Self::Error> {
            use embedded_graphics::pixelcolor::IntoStorage;
            for Pixel(p, c) in px {
                if let Some(slot) = self.0.get_mut(p.y as usize * 240 + p.x as usize) {
                    *slot = c.into_storage();
                }
            }
            Ok(())
        }
    }

    struct Storage {
        acc: Vec<i32>,
        cover: Vec<i32>,
        out16: Vec<u16>,
        out8: Vec<u8>,
        slots3: Vec<WalkSlot<3>>,
        slots1: Vec<WalkSlot<1>>,
        /// Not drawn from here: no entries.
        list3: Vec<softedge::canvas::ListedTriangle<3>>,
    }

    impl Storage {
        fn new() -> Self {
            Self {
                acc: vec![0; ACC_LEN],
                cover: vec![0; COVER_LEN],
                out16: vec![0; OUT_LEN],
                out8: vec![0; OUT_LEN],
                slots3: vec![WalkSlot::EMPTY; SLOTS],
                slots1: vec![WalkSlot::EMPTY; SLOTS],
                list3: Vec::new(),
            }
        }

        fn bufs(&mut self) -> Buffers<'_> {
            Buffers {
                acc: &mut self.acc,
                cover: &mut self.cover,
                out16: &mut self.out16,
                out8: &mut self.out8,
                slots3: &mut self.slots3,
                slots1: &mut self.slots1,
                list3: &mut self.list3,
            }
        }
    }

    #[test]
    fn the_cached_chart_is_the_chart_bit_for_bit() {
        let mut s = Storage::new();
        let mut frames = [Screen(vec![0; 240 * 240]), Screen(vec![0; 240 * 240])];
        let mut stats = [(0, 0); 2];
        for ((shape, screen), st) in [Shape::Chart, Shape::ChartCached]
            .into_iter()
            .zip(&mut frames)
            .zip(&mut stats)
        {
            *st = shape_into(shape, s.bufs(), screen).unwrap();
        }
        assert!(frames[0].0.iter().filter(|&&p| p != 0).count() > 500);
        assert!(frames[0].0 == frames[1].0);
        // Without a cache nothing is kept; with one the stroke is
        // described in the first of the 15 bands and found in the others.
        assert_eq!(stats, [(0, 0), (14, 1)]);
        // The outline and its description take 228 + 31 segments today:
        // the cache's 288 leave a margin, and this says when the
        // stroker's output grows past it.
        let mut segments = vec![Segment::ZERO; 4096];
        let mut entries = [ShapeEntry::EMPTY; 2];
        {
            let r = renderer(&mut s.acc, &mut s.cover, &mut s.slots3).unwrap();
            let mut r = r.with_shape_cache(&mut segments, &mut entries);
            let mut screen = Screen(vec![0; 240 * 240]);
            r.render(&mut screen, &RGB565, [0; 3], |c| {
                chart().into_styled(chart_style()).draw(c)
            })
            .unwrap();
        }
        let used = softedge::canvas::ShapeCache::new(&mut segments, &mut entries, 0).used();
        assert_eq!((used.0, used.2), (1, 0));
        assert!((240..=CHART_SEGMENTS).contains(&used.1), "{used:?}");
    }

    #[test]
    fn the_cached_scene_is_the_scene_bit_for_bit() {
        let mut s = Storage::new();
        let mut cache = std::boxed::Box::new(SceneCache::new());
        let full = {
            let mut f = Screen(vec![0x1234; 240 * 240]);
            softedge_scene(None, &mut s.bufs(), &mut f).unwrap();
            f
        };
        // The first frame describes the 5 shapes that are not circles or
        // arcs, the next ones none; the windows in between neither.
        for (k, window) in [None, Some(DIRTY), None, Some(DIRTY)]
            .into_iter()
            .enumerate()
        {
            let mut f = Screen(vec![0x1234; 240 * 240]);
            let (kept, described) =
                softedge_scene_cached(window, &mut s.bufs(), &mut cache, &mut f).unwrap();
            assert_eq!(
                described,
                if k == 0 {
                    (SCENE_SHAPES - SCENE_CURVES) as u32
                } else {
                    0
                },
                "frame {k}"
            );
            assert!(kept > 0);
            for (i, (&a, &b)) in full.0.iter().zip(&f.0).enumerate() {
                let p = Point::new((i % 240) as i32, (i / 240) as i32);
                if window.is_none_or(|w| w.contains(p)) {
                    assert_eq!(a, b, "frame {k}, {p:?}");
                }
            }
        }
        let used = cache
            .entries
            .iter()
            .filter(|e| **e != ShapeEntry::EMPTY)
            .count();
        assert_eq!(used, SCENE_SHAPES - SCENE_CURVES);
    }

    #[test]
    fn every_shape_frame_renders() {
        let mut s = Storage::new();
        for shape in Shape::ALL {
            assert!(
                softedge_shape(shape, &mut s.bufs()).is_ok(),
                "{}",
                shape.name()
            );
        }
    }

    #[test]
    fn the_dirty_window_gets_the_full_frame_pixels() {
        let mut s = Storage::new();
        let mut full = Screen(vec![0; 240 * 240]);
        assert!(softedge_scene(None, &mut s.bufs(), &mut full).is_ok());
        let mut part = Screen(vec![0xffff; 240 * 240]);
        assert!(softedge_scene(Some(DIRTY), &mut s.bufs(), &mut part).is_ok());
        for (k, (&a, &b)) in full.0.iter().zip(&part.0).enumerate() {
            let p = Point::new((k % 240) as i32, (k / 240) as i32);
            if DIRTY.contains(p) {
                assert_eq!(a, b, "{p:?}");
            } else {
                assert_eq!(b, 0xffff, "{p:?} outside the window was sent");
            }
        }
    }

    /// A 240x240 display that lends a band buffer of 16 rows and keeps
    /// what each band sends (the buffer scrambled after each).
    struct LentScreen {
        frame: Screen,
        band: Vec<u16>,
    }

    impl OriginDimensions for LentScreen {
        fn size(&self) -> Size {
            Size::new(240, 240)
        }
    }

    impl BandTarget for LentScreen {
        type Color = Rgb565;
        type Raw = u16;
        type Error = core::convert::Infallible;
        fn buffer(&mut self) -> &mut [u16] {
            &mut self.band
        }
        fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error> {
            for (p, &v) in area.points().zip(&self.band) {
                self.frame.0[p.y as usize * 240 + p.x as usize] = v;
            }
            self.band.fill(0x5a5a);
            Ok(())
        }
    }

    /// Every shape frame, and the scene whole and in its window, made in
    /// a lent band buffer are the frames streamed, bit for bit.
    #[test]
    fn lent_frames_are_the_streamed_frames() {
        let mut s = Storage::new();
        let lent = || LentScreen {
            frame: Screen(vec![0xffff; 240 * 240]),
            band: vec![0x5a5a; 240 * usize::from(BAND_ROWS)],
        };
        for shape in Shape::ALL {
            let mut streamed = Screen(vec![0xffff; 240 * 240]);
            shape_into(shape, s.bufs(), &mut streamed).unwrap();
            let mut l = lent();
            shape_into(shape, s.bufs(), &mut Lent(&mut l)).unwrap();
            assert!(l.frame.0 == streamed.0, "{}", shape.name());
        }
        for window in [None, Some(DIRTY)] {
            let mut streamed = Screen(vec![0xffff; 240 * 240]);
            softedge_scene(window, &mut s.bufs(), &mut streamed).unwrap();
            let mut l = lent();
            softedge_scene(window, &mut s.bufs(), &mut Lent(&mut l)).unwrap();
            assert!(l.frame.0 == streamed.0, "{window:?}");
        }
        assert!(softedge_scene_lent(None, &mut s.bufs()).is_ok());
        for shape in Shape::ALL {
            assert!(softedge_shape_lent(shape, &mut s.bufs()).is_ok());
        }
    }

    #[test]
    fn embedded_graphics_redraws_the_dirty_rectangle_as_the_full_frame() {
        let mut full = Screen(vec![0; 240 * 240]);
        eg_scene(None, &mut full);
        let mut part = Screen(vec![0xffff; 240 * 240]);
        eg_scene(Some(DIRTY), &mut part);
        for (k, (&a, &b)) in full.0.iter().zip(&part.0).enumerate() {
            let p = Point::new((k % 240) as i32, (k / 240) as i32);
            if DIRTY.contains(p) {
                assert_eq!(a, b, "{p:?}");
            } else {
                assert_eq!(b, 0xffff, "{p:?} outside the rectangle was drawn");
            }
        }
    }

    #[test]
    fn the_spi_counter_counts_the_window() {
        let mut s = Storage::new();
        let mut spi = SpiCounter::new(240, 240);
        assert!(softedge_scene(Some(DIRTY), &mut s.bufs(), &mut spi).is_ok());
        // Rows 110..130 in 16-row bands from the window's top: 16 + 4.
        assert_eq!((spi.windows, spi.pixels), (2, 400));
        assert_eq!(spi.bytes(), 400 * 2 + 2 * 11);
    }
}
