//! The band canvas: what a drawing closure draws into, one band at a time.
//!
//! Takes shapes (outlines of straight segments on the fine 1/1024-px grid:
//! triangles, polygons, meshes, and the paths, shapes, strokes and glyphs
//! built on them) with a paint (a flat colour, Gouraud colours per vertex)
//! and a blend; gives the band's accumulator their exact-area, linear-light
//! composite. Every shape is walked edge by edge into the band's coverage
//! scratch and composed once, as a whole ([`band`](crate::band)), so a
//! mesh's shared edges stay seamless in painter's order too.
//!
//! The canvas counts the shapes drawn into it: the `n`-th shape of every
//! band is the same shape, and with a [`WalkCache`] each of its edges
//! resumes its walk where the band above left it, and its Gouraud planes
//! are fitted once per frame. A shape that misses the band is rejected by
//! its bounds before any set-up. A frame's triangles may also be recorded
//! once into a [`TriangleList`] and drawn from it in every band
//! ([`Canvas::fill_triangles`]): the per-band cost of a triangle that
//! misses the band is then two compares.
//!
//! Rejected shapes (a vertex outside the coordinate range, too many
//! vertices for a Gouraud polygon) are not drawn, counted, and the first
//! reason kept ([`Canvas::skipped`]): the rest of the frame is drawn. The
//! canvas's methods also return the rejection; the styled shapes of
//! [`draw`](crate::draw) return `Ok` (the record names the shape), so a
//! drawing closure can `?` them without stopping the band.

mod cache;
mod gradient;
mod image;
mod list;
pub(crate) mod paths;
mod retained;
#[cfg(feature = "embedded-graphics")]
mod target;

use cache::ShapeBand;
pub use cache::{WalkCache, WalkSlot};
pub use list::{ListedTriangle, TriangleList};
pub use retained::{ShapeCache, ShapeEntry};

use core::ops::Range;

use crate::band::{BandBuffer, ComposeOp, Coverage, Paint};
use crate::edge::{AliasedWalk, AreaMode};
use crate::geom::{in_fine_range, FinePoint, SubPoint, FINE_BITS};
use crate::path::SegmentSink;
use crate::pixel_model::{walk_bed_of_nails, walk_circular, walk_hex19, walk_hex7, CircularFilter};
use crate::raster::{DrawError, PixelModel, RenderStyle};
use crate::shade::Plane;
use crate::style::{Blend, Edges, FillRule, Opacity};

/// A box in fine units, `x0..x1` by `y0..y1` (half-open).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FineRect {
    /// Left, fine units.
    pub x0: i32,
    /// Top, fine units.
    pub y0: i32,
    /// Right (exclusive), fine units.
    pub x1: i32,
    /// Bottom (exclusive), fine units.
    pub y1: i32,
}

impl FineRect {
    /// The box around `points`, or `None` for none.
    pub fn around(points: impl IntoIterator<Item = FinePoint>) -> Option<Self> {
        let mut it = points.into_iter();
        let first = it.next()?;
        let mut r = Self {
            x0: first.x,
            y0: first.y,
            x1: first.x,
            y1: first.y,
        };
        for p in it {
            r.x0 = r.x0.min(p.x);
            r.y0 = r.y0.min(p.y);
            r.x1 = r.x1.max(p.x);
            r.y1 = r.y1.max(p.y);
        }
        Some(r)
    }
}

/// Something the canvas can fill: closed contours of straight segments on
/// the fine grid.
///
/// `segments` must report the same segments in the same order every time
/// (a band's cached walks are found by their place in it), and every point
/// must lie in `bounds`.
pub trait Outline {
    /// A box holding every point of every segment.
    fn bounds(&self) -> Option<FineRect>;
    /// Calls `f` with every directed segment of the closed contours.
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, f: F);

    /// The segments into `sink`, which may name the rows it needs
    /// ([`SegmentSink::window`]): segments wholly outside them may be left
    /// out and counted ([`SegmentSink::skipped`]), so that the ones sent
    /// keep their places in [`segments`](Self::segments)' order. The
    /// default sends every segment.
    fn segments_into<K: SegmentSink>(&self, sink: &mut K) {
        self.segments(|a, b| sink.segment(a, b));
    }

    /// False when the outline is known to have lost segments (a recording
    /// that ran out of room): it is then refused with
    /// [`DrawError::Incomplete`] in every band. The default is true.
    fn complete(&self) -> bool {
        true
    }
}

/// A closed polygon given by its vertices (the last joins the first).
#[derive(Debug, Clone, Copy)]
pub struct Contour<'a>(pub &'a [FinePoint]);

impl Outline for Contour<'_> {
    fn bounds(&self) -> Option<FineRect> {
        FineRect::around(self.0.iter().copied())
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, mut f: F) {
        let v = self.0;
        if let (Some(&last), true) = (v.last(), v.len() >= 2) {
            let mut prev = last;
            for &p in v {
                f(prev, p);
                prev = p;
            }
        }
    }
}

impl Outline for [FinePoint; 3] {
    fn bounds(&self) -> Option<FineRect> {
        Some(triangle_box(self))
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, mut f: F) {
        let [a, b, c] = *self;
        f(a, b);
        f(b, c);
        f(c, a);
    }
}

/// The box around a triangle's vertices ([`FineRect::around`] unrolled:
/// every shape in every band is tested against the band with it).
#[inline]
fn triangle_box(v: &[FinePoint; 3]) -> FineRect {
    let [a, b, c] = v;
    FineRect {
        x0: a.x.min(b.x).min(c.x),
        y0: a.y.min(b.y).min(c.y),
        x1: a.x.max(b.x).max(c.x),
        y1: a.y.max(b.y).max(c.y),
    }
}

/// How many shapes a band's canvas skipped, and the first reason.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Skipped {
    /// Shapes not drawn.
    pub count: u32,
    /// The first one's place in the drawing order and why.
    pub first: Option<(u32, DrawError)>,
}

/// What a shape is painted with (crate-internal: the public methods take
/// a colour or a gradient).
#[derive(Clone, Copy)]
pub(super) enum Fill<'g, const C: usize> {
    /// One linear colour.
    Flat([u16; C]),
    /// A gradient.
    Gradient(&'g crate::style::Gradient<C>),
}

/// The canvas of one band: a [`BandBuffer`] with the frame's
/// [`WalkCache`] and the count of shapes drawn.
///
/// `Col` is the display's colour type (any embedded-graphics colour, taken
/// as sRGB, or linear `[u16; C]`): the canvas is an embedded-graphics
/// `DrawTarget` of it, and the styles of [`draw`](crate::draw) take it.
#[derive(Debug)]
pub struct Canvas<'c, 'b, const C: usize, Col = [u16; C]> {
    buf: &'c mut BandBuffer<'b, C>,
    cache: Option<WalkCache<'c, C>>,
    /// Outlines kept from band to band and frame to frame.
    shapes: Option<ShapeCache<'c>>,
    serial: u32,
    style: RenderStyle,
    /// How the next outlines' edge pixels are drawn (1-bit displays).
    edges: Edges,
    skipped: Skipped,
    /// The whole frame, for embedded-graphics' clipping.
    frame: (u16, u16),
    /// The band's rows and columns widened by a margin, whole pixels:
    /// what a shape's bounds must reach to be drawn (see `touches`).
    reach: Reach,
    color: core::marker::PhantomData<Col>,
}

/// A band's rows `y_lo..y_hi` and columns `x_lo..x_hi`, each widened by
/// [`Reach::MARGIN`] pixels (saturating), found once per band: the test
/// every shape of every band starts with is then four compares.
#[derive(Debug, Clone, Copy)]
struct Reach {
    y_lo: i32,
    y_hi: i32,
    x_lo: i32,
    x_hi: i32,
}

impl Reach {
    /// Pixels a shape's bounds may fall short of the band and still be
    /// walked (its edges' cells reach that far).
    const MARGIN: i32 = 2;

    /// True when fine rows `y0..=y1` can touch the band's rows (the row
    /// half of `Canvas::touches`).
    #[inline]
    fn rows(&self, y0: i32, y1: i32) -> bool {
        (y1 >> FINE_BITS) >= self.y_lo && (y0 >> FINE_BITS) < self.y_hi
    }

    fn of(band: crate::band::Band) -> Self {
        let (rows, cols) = (band.row_range(), band.column_range());
        Self {
            y_lo: rows.start.saturating_sub(Self::MARGIN),
            y_hi: rows.end.saturating_add(Self::MARGIN),
            x_lo: cols.start.saturating_sub(Self::MARGIN),
            x_hi: cols.end.saturating_add(Self::MARGIN),
        }
    }
}

/// A band as the triangles drawn into it see it
/// ([`Canvas::triangle_band`]).
pub(super) struct TriangleBand {
    kind: WalkKind,
    rows: Range<i32>,
    cols: Range<i32>,
}

/// Which walk an edge takes under a style.
#[derive(Clone, Copy, PartialEq, Eq)]
enum WalkKind {
    Box(AreaMode),
    Aliased,
    Sampled,
}

impl WalkKind {
    fn of(style: RenderStyle) -> Self {
        match style {
            s if !s.antialias => WalkKind::Aliased,
            RenderStyle {
                model: PixelModel::Box,
                ..
            } => WalkKind::Box(AreaMode::Exact),
            RenderStyle {
                model: PixelModel::BoxSeed,
                ..
            } => WalkKind::Box(AreaMode::SeedFormula),
            _ => WalkKind::Sampled,
        }
    }
}

impl<'c, 'b, const C: usize> Canvas<'c, 'b, C> {
    /// A canvas of linear colours over a cleared band buffer, with or
    /// without a cache (give every band of a frame a view of the same
    /// slots, cleared when the frame starts). Its frame is the band's
    /// columns and rows from 0; see [`with_frame`](Self::with_frame).
    pub fn new(buf: &'c mut BandBuffer<'b, C>, cache: Option<WalkCache<'c, C>>) -> Self {
        Self::typed(buf, cache)
    }
}

impl<'c, 'b, const C: usize, Col> Canvas<'c, 'b, C, Col> {
    /// [`new`](Canvas::new) for a display of colour type `Col` (the
    /// canvas is then an embedded-graphics `DrawTarget` of it).
    pub fn typed(buf: &'c mut BandBuffer<'b, C>, cache: Option<WalkCache<'c, C>>) -> Self {
        let band = buf.band();
        let frame = (
            band.column_range().end.clamp(0, i32::from(u16::MAX)) as u16,
            band.row_range().end.clamp(0, i32::from(u16::MAX)) as u16,
        );
        Self {
            buf,
            cache,
            shapes: None,
            serial: 0,
            style: RenderStyle::default(),
            edges: Edges::Smooth,
            skipped: Skipped::default(),
            frame,
            reach: Reach::of(band),
            color: core::marker::PhantomData,
        }
    }

    /// The size of the whole frame the band belongs to (what
    /// embedded-graphics drawings are clipped to).
    pub fn with_frame(mut self, width: u16, height: u16) -> Self {
        self.frame = (width, height);
        self
    }

    /// With a cache of shape outlines: the shapes that have a key
    /// ([`Shape::key`](crate::path::Shape::key)), filled or stroked without
    /// dashes, are described once into it and filled from it in this band
    /// and, given views of the same slices, in every later band and frame
    /// (see [`ShapeCache`]). The same pixels as without.
    pub fn with_shapes(mut self, shapes: ShapeCache<'c>) -> Self {
        self.shapes = Some(shapes);
        self
    }

    /// The shape cache's outlines found kept, and outlines described into
    /// it, in this band.
    pub fn shape_stats(&self) -> (u32, u32) {
        self.shapes.as_ref().map_or((0, 0), |c| c.stats())
    }

    /// The frame's width and height.
    pub fn frame_size(&self) -> (u16, u16) {
        self.frame
    }

    /// The band drawn.
    pub fn band(&self) -> crate::band::Band {
        self.buf.band()
    }

    /// The pixel model every following shape is drawn with (anti-aliased
    /// exact area by default).
    pub fn set_style(&mut self, style: RenderStyle) {
        self.style = style;
    }

    /// How the edge pixels of every following outline (shapes, strokes,
    /// paths, text; not triangles and meshes) are drawn: exact coverage
    /// ([`Edges::Smooth`], the default) or sharpened for a 1-bit display
    /// (see [`Edges`]). A styled shape's own
    /// [`AaStyle::edges`](crate::draw::AaStyle::edges) sets it for that
    /// shape; set it around text: `canvas.set_edges(Edges::Crisp);
    /// text.draw(canvas)?; canvas.set_edges(Edges::Smooth);`.
    pub fn set_edges(&mut self, edges: Edges) {
        self.edges = edges;
    }

    /// How the edge pixels of the next outlines are drawn.
    pub fn edges(&self) -> Edges {
        self.edges
    }

    /// Shapes skipped so far in this band.
    pub fn skipped(&self) -> Skipped {
        self.skipped
    }

    /// The cache's hits and misses in this band.
    pub fn cache_stats(&self) -> (u32, u32) {
        self.cache.as_ref().map_or((0, 0), |c| c.stats())
    }

    /// The band buffer under the canvas.
    pub fn buffer(&mut self) -> &mut BandBuffer<'b, C> {
        self.buf
    }

    /// The record of skipped shapes, for the styled shapes of
    /// [`draw`](crate::draw) to name theirs ([`DrawError::of_shape`]).
    #[cfg(feature = "embedded-graphics")]
    pub(crate) fn skipped_mut(&mut self) -> &mut Skipped {
        &mut self.skipped
    }

    /// Counts a shape that was rejected.
    fn skip(&mut self, serial: u32, e: DrawError) {
        self.skipped.count += 1;
        if self.skipped.first.is_none() {
            self.skipped.first = Some((serial, e));
        }
    }

    /// The next shape's place in the drawing order.
    fn next_serial(&mut self) -> u32 {
        let s = self.serial;
        self.serial = self.serial.wrapping_add(1);
        s
    }

    /// Fills `outline` by `rule` with one flat linear colour.
    ///
    /// ```
    /// use softedge::canvas::{Canvas, Contour};
    /// use softedge::geom::FinePoint;
    /// use softedge::style::{Blend, FillRule, Opacity};
    /// use softedge::{Band, BandBuffer};
    /// let (mut acc, mut cover) = ([0i32; 16], [0i32; BandBuffer::<1>::cover_len(4, 4)]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(4, 0, 4)).unwrap();
    /// buf.clear([1000]);
    /// let mut canvas = Canvas::new(&mut buf, None);
    /// let p = |x, y| FinePoint::from_px(x, y);
    /// let square = [p(0, 0), p(2, 0), p(2, 2), p(0, 2)];
    /// canvas
    ///     .fill(&Contour(&square), [3000], FillRule::NonZero, Blend::Over, Opacity::from_percent(50))
    ///     .unwrap();
    /// // Half of 3000 over 1000: the linear midpoint.
    /// assert_eq!(canvas.buffer().lin12(1, 1), Some([2000]));
    /// assert_eq!(canvas.buffer().lin12(3, 3), Some([1000]));
    /// ```
    pub fn fill<O: Outline + ?Sized>(
        &mut self,
        outline: &O,
        color: [u16; C],
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.fill_with(outline, Fill::Flat(color), rule, blend, opacity)
    }

    /// [`fill`](Self::fill) with any paint.
    pub(super) fn fill_with<O: Outline + ?Sized>(
        &mut self,
        outline: &O,
        fill: Fill<'_, C>,
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let serial = self.next_serial();
        self.paint_outline(serial, outline, rule, fill, blend, opacity)
            .inspect_err(|&e| self.skip(serial, e))
    }

    /// Fills a shape or path ([`Shape`](crate::path::Shape): circles,
    /// ellipses, arcs, sectors, rectangles, rounded rectangles, polylines,
    /// SVG path data, glyph outlines) by `rule` with one flat linear colour.
    ///
    /// ```
    /// use softedge::canvas::Canvas;
    /// use softedge::geom::FinePoint;
    /// use softedge::path::Circle;
    /// use softedge::style::{Blend, FillRule, Opacity};
    /// use softedge::{Band, BandBuffer};
    /// let (mut acc, mut cover) = ([0i32; 400], [0i32; BandBuffer::<1>::cover_len(20, 20)]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(20, 0, 20)).unwrap();
    /// buf.clear([0]);
    /// let mut canvas = Canvas::new(&mut buf, None);
    /// let disc = Circle::new(FinePoint::centre_of(9, 9), 6 * 1024);
    /// canvas.fill_shape(&disc, [4095], FillRule::NonZero, Blend::Over, Opacity::OPAQUE).unwrap();
    /// assert_eq!(canvas.buffer().lin12(10, 10), Some([4095]));
    /// assert_eq!(canvas.buffer().lin12(0, 0), Some([0]));
    /// ```
    pub fn fill_shape<S: crate::path::Shape + ?Sized>(
        &mut self,
        shape: &S,
        color: [u16; C],
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.fill_shape_with(shape, Fill::Flat(color), rule, blend, opacity)
    }

    /// [`fill_shape`](Self::fill_shape) with any paint.
    pub(super) fn fill_shape_with<S: crate::path::Shape + ?Sized>(
        &mut self,
        shape: &S,
        fill: Fill<'_, C>,
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let key = self.key_of(shape);
        if let Some(c) = key.and_then(|k| k.circle()) {
            let q = u64::from(c.radius) * 4;
            if let Some(r) = self.exact_circle(c.centre, q, 0, fill, rule, blend, opacity) {
                return r;
            }
        }
        let tol = crate::path::Tolerance::DEFAULT;
        let kept = self.kept_outline(
            || key.map(|k| retained::OutlineKey::fill(k, tol)),
            || paths::shape_bounds(shape),
            |buf| {
                shape.fill_with(tol, buf);
                true
            },
            &|sink| shape.describe(sink),
            |c, outline| c.fill_with(outline, fill, rule, blend, opacity),
        );
        if let Some(r) = kept {
            return r;
        }
        let outline = paths::Filled {
            shape,
            tol,
            bounds: paths::shape_bounds(shape),
        };
        self.fill_with(&outline, fill, rule, blend, opacity)
    }

    /// Strokes a shape's or path's outline with `style` (width, joins,
    /// caps, dashes, alignment) in one flat linear colour. The stroke is
    /// one shape: where its pieces meet nothing is covered twice.
    pub fn stroke_shape<S: crate::path::Shape + ?Sized>(
        &mut self,
        shape: &S,
        style: &crate::path::StrokeStyle<'_>,
        color: [u16; C],
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        self.stroke_shape_with(shape, style, Fill::Flat(color), blend, opacity)
    }

    /// [`stroke_shape`](Self::stroke_shape) with any paint.
    pub(super) fn stroke_shape_with<S: crate::path::Shape + ?Sized>(
        &mut self,
        shape: &S,
        style: &crate::path::StrokeStyle<'_>,
        fill: Fill<'_, C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let key = self.key_of(shape);
        if let Some(c) = key.and_then(|k| k.circle()) {
            // Without dashes, the ring between radii `r + o` and `r - i`
            // (`Circle::stroke_with`), exact in quarter fine units.
            let dashed = style.dash.is_some_and(|d| !d.is_solid());
            if !dashed && c.radius > 0 && style.width > 0 {
                let (o, i) = style.reach_q1();
                let r = i64::from(c.radius) * 4;
                let (outer, inner) = (r + 2 * o, (r - 2 * i).max(0));
                if let (Ok(outer), Ok(inner)) = (u64::try_from(outer), u64::try_from(inner)) {
                    let nz = FillRule::NonZero;
                    let r = self.exact_circle(c.centre, outer, inner, fill, nz, blend, opacity);
                    if let Some(r) = r {
                        return r;
                    }
                }
            }
        }
        if let Some(a) = key.and_then(|k| k.arc()) {
            if let Some(r) = self.exact_arc(&a, style, fill, blend, opacity) {
                return r;
            }
        }
        let serial = self.next_serial();
        let tol = crate::path::Tolerance::DEFAULT;
        let kept = self.kept_outline(
            || key.and_then(|k| retained::OutlineKey::stroke(k, style, tol)),
            || paths::Stroked::<S>::widen(paths::shape_bounds(shape), style),
            |buf| shape.stroke_with(style, tol, buf).is_ok(),
            &|sink| shape.describe(sink),
            |c, outline| {
                c.paint_outline(serial, outline, FillRule::NonZero, fill, blend, opacity)
                    .inspect_err(|&e| c.skip(serial, e))
            },
        );
        if let Some(r) = kept {
            return r;
        }
        let outline = paths::Stroked {
            shape,
            style,
            tol,
            bounds: paths::Stroked::<S>::widen(paths::shape_bounds(shape), style),
            error: core::cell::Cell::new(None),
        };
        let r = self
            .paint_outline(serial, &outline, FillRule::NonZero, fill, blend, opacity)
            .and_then(|()| {
                outline
                    .error
                    .get()
                    .map_or(Ok(()), |e| Err(DrawError::Stroke(e)))
            });
        r.inspect_err(|&e| self.skip(serial, e))
    }

    /// The rows of `span` (frame rows) in this band, `None` when none.
    fn band_rows(&self, span: core::ops::Range<i32>) -> Option<core::ops::Range<i32>> {
        let band = self.buf.band();
        let rows = span.start.max(band.y0)..span.end.min(band.y0 + i32::from(band.rows));
        (rows.start < rows.end).then_some(rows)
    }

    /// A disc (`inner` 0) or a ring of centre `c` and radii `outer >
    /// inner` (quarter fine units) by its circles' exact areas
    /// ([`edge::disc`](crate::edge::disc)), for the exact box model, in
    /// any paint; `None` for anything else (drawn from its outline).
    #[allow(clippy::too_many_arguments)]
    fn exact_circle(
        &mut self,
        c: FinePoint,
        outer: u64,
        inner: u64,
        fill: Fill<'_, C>,
        rule: FillRule,
        blend: Blend,
        opacity: Opacity,
    ) -> Option<Result<(), DrawError>> {
        use crate::edge::disc::{CircleEdge, MAX_RADIUS_Q};
        if WalkKind::of(self.style) != WalkKind::Box(AreaMode::Exact) || outer <= inner {
            return None;
        }
        if outer > u64::from(MAX_RADIUS_Q) {
            return None;
        }
        // Its box as its outline's (`paths::shape_bounds`, widened by the
        // curves' margin), all in range: out of range, the outline path
        // reports it.
        let b = circle_box(c, u32::try_from(outer).ok()?)?;
        let out = CircleEdge::new(c.x * 4, c.y * 4, outer as u32)?;
        let hole = if inner > 0 {
            Some(CircleEdge::new(c.x * 4, c.y * 4, inner as u32)?)
        } else {
            None
        };
        let _serial = self.next_serial();
        if !self.touches(&b) {
            return Some(Ok(()));
        }
        let Some(rows) = self.band_rows(out.rows()) else {
            return Some(Ok(()));
        };
        if ring_misses(c, outer, inner, &rows, &self.buf.band().column_range()) {
            return Some(Ok(()));
        }
        let mut d = self.buf.deltas(rows.clone());
        out.walk(rows.clone(), 1, &mut d);
        if let Some(h) = hole {
            h.walk(rows.clone(), -1, &mut d);
        }
        let paint = match fill {
            Fill::Flat(color) => Paint::Flat(color.map(|v| v.min(crate::LIN_MAX))),
            Fill::Gradient(g) => g.flat().map_or(Paint::Gradient(g), Paint::Flat),
        };
        let coverage = match self.edges {
            Edges::Smooth => Coverage::Rule(rule),
            e => Coverage::Sharpened(rule, e),
        };
        let op = op_of(blend, opacity);
        self.buf.compose(rows.start, rows.end, coverage, &paint, op);
        Some(Ok(()))
    }

    /// A stroked [`Arc`](crate::path::Arc) without dashes, butt caps or
    /// centred round ones (`Arc::stroke_with`'s annular sector), from its
    /// circles' exact areas: the outer circle's part `+`, the inner's
    /// `-`, and the two ends (radial lines, walked as any edge, or the
    /// caps' half circles), every part cut at the same points so that the
    /// contour closes exactly. `None` for anything else (and for caps
    /// that could overlap each other: a gap narrower than the stroke).
    ///
    /// Inlined: its locals then share the stack of its caller's other
    /// branches (the stroker's); out of line the two frames were stacked
    /// (the dial frame's stack 1.1 KB deeper on the Cortex-M0).
    #[inline(always)]
    fn exact_arc(
        &mut self,
        arc: &crate::path::Arc,
        style: &crate::path::StrokeStyle<'_>,
        fill: Fill<'_, C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Option<Result<(), DrawError>> {
        use crate::edge::disc::CircleEdge;
        use crate::path::arc::EllipseFrame;
        use crate::path::trig::{HALF_TURN, Q30, TURN};
        use crate::path::vector::{Pt, UNIT_X};
        use crate::path::LineCap;
        if WalkKind::of(self.style) != WalkKind::Box(AreaMode::Exact)
            || style.dash.is_some_and(|d| !d.is_solid())
            || arc.radius == 0
            || style.width == 0
        {
            return None;
        }
        let (t0, s) = crate::path::shape::sector::clockwise(arc.start, arc.sweep);
        let (o, i) = style.reach_q1();
        let r4 = i64::from(arc.radius) * 4;
        let (outer, inner) = (r4 + 2 * o, (r4 - 2 * i).max(0));
        if s >= TURN {
            // A whole turn: the ring (its caps lie inside it).
            let (outer, inner) = (u64::try_from(outer).ok()?, u64::try_from(inner).ok()?);
            let nz = FillRule::NonZero;
            return self.exact_circle(arc.centre, outer, inner, fill, nz, blend, opacity);
        }
        let round = match style.cap {
            LineCap::Butt => false,
            // Centred, leaving a hole (as `Arc::stroke_with`).
            LineCap::Round if o == i && inner > 0 => true,
            _ => return None,
        };
        if s == 0 || outer > i64::from(crate::edge::disc::MAX_RADIUS_Q) {
            return None;
        }
        let c = arc.centre;
        let b = circle_box(c, u32::try_from(outer).ok()?)?;
        let out_edge = CircleEdge::new(c.x * 4, c.y * 4, u32::try_from(outer).ok()?)?;
        // A band whose pixels the ring misses gets nothing from the arc
        // (its caps lie in the ring too): numbered, not set up. (Where the
        // caps' test below sends the arc to its outline, that draws
        // nothing here either, under the same number.)
        let rows = self.band_rows(out_edge.rows()).filter(|rows| {
            let (o, i) = (u64::try_from(outer).ok(), u64::try_from(inner).ok());
            let cols = self.buf.band().column_range();
            self.touches(&b)
                && !matches!((o, i), (Some(o), Some(i)) if ring_misses(c, o, i, rows, &cols))
        });
        let Some(rows) = rows else {
            self.next_serial();
            return Some(Ok(()));
        };
        // The ends, as `Arc::stroke_with` finds them (fine units).
        let c_q8 = Pt::new(i64::from(c.x) << 8, i64::from(c.y) << 8);
        let r_q8 = i64::from(arc.radius) << 8;
        let (ro, ri) = (r_q8 + (o << 7), (r_q8 - (i << 7)).max(0));
        let fo = EllipseFrame::with_q8(c_q8, ro, ro, UNIT_X);
        let fi = EllipseFrame::with_q8(c_q8, ri, ri, UNIT_X);
        let (tb, q4) = (t0 + s, |p: FinePoint| (p.x * 4, p.y * 4));
        let (oa, ob) = (fo.point(t0, Q30).to_fine(), fo.point(tb, Q30).to_fine());
        let (ia, ib) = if inner > 0 {
            (fi.point(t0, Q30).to_fine(), fi.point(tb, Q30).to_fine())
        } else {
            (c, c)
        };
        let out_spans = out_edge.arc_spans(t0, s, q4(oa), q4(ob));
        let hole = if inner > 0 {
            let e = CircleEdge::new(c.x * 4, c.y * 4, u32::try_from(inner).ok()?)?;
            Some((e, e.arc_spans(t0, s, q4(ia), q4(ib))))
        } else {
            None
        };
        // Round caps: half circles of radius h about the centre line's
        // ends, from the outer end to the inner one (at the arc's end) and
        // back (at its start); their ends at least 2 h + 2 px apart.
        let caps = if round {
            let mid = EllipseFrame::with_q8(c_q8, r_q8, r_q8, UNIT_X);
            let q = |p: Pt| {
                let f = |v: i64| i32::try_from((v + 32) >> 6).ok();
                Some((f(p.x)?, f(p.y)?))
            };
            let (ea, eb) = (q(mid.point_q8(t0))?, q(mid.point_q8(tb))?);
            let h = u32::try_from(2 * o).ok()?;
            let (dx, dy) = (i64::from(ea.0 - eb.0), i64::from(ea.1 - eb.1));
            let apart = 2 * i64::from(h) + 2 * 4096;
            if dx * dx + dy * dy < apart * apart {
                return None;
            }
            let ca = CircleEdge::new(ea.0, ea.1, h)?;
            let cb = CircleEdge::new(eb.0, eb.1, h)?;
            let sa = ca.arc_spans(t0 + HALF_TURN, HALF_TURN, q4(ia), q4(oa));
            let sb = cb.arc_spans(tb, HALF_TURN, q4(ob), q4(ib));
            Some([(ca, sa), (cb, sb)])
        } else {
            None
        };
        let serial = self.next_serial();
        let shape = ShapeBand {
            serial,
            mode: AreaMode::Exact,
            cols: self.buf.band().column_range(),
            rows: rows.clone(),
        };
        let mut cache = self.cache.as_mut();
        let mut d = self.buf.deltas(rows.clone());
        out_edge.walk_spans(rows.clone(), 1, &out_spans, &mut d);
        if let Some((e, sp)) = &hole {
            e.walk_spans(rows.clone(), -1, sp, &mut d);
        }
        match &caps {
            Some(caps) => {
                for (e, sp) in caps {
                    e.walk_spans(rows.clone(), 1, sp, &mut d);
                }
            }
            None => {
                // The ends: outward at the start, inward at the end (the
                // outer part runs counter-clockwise, `walk`'s `+`).
                for (k, (p0, p1)) in [(0, (oa, ia)), (1, (ib, ob))] {
                    cache::walk_edge(cache.as_deref_mut(), &shape, k, (p0, p1), &mut d);
                }
            }
        }
        let paint = match fill {
            Fill::Flat(color) => Paint::Flat(color.map(|v| v.min(crate::LIN_MAX))),
            Fill::Gradient(g) => g.flat().map_or(Paint::Gradient(g), Paint::Flat),
        };
        let coverage = match self.edges {
            Edges::Smooth => Coverage::Rule(FillRule::NonZero),
            e => Coverage::Sharpened(FillRule::NonZero, e),
        };
        let op = op_of(blend, opacity);
        self.buf.compose(rows.start, rows.end, coverage, &paint, op);
        Some(Ok(()))
    }

    /// The key of `shape` ([`Shape::key`](crate::path::Shape::key)); not
    /// asked for without a shape cache when it would read the shape's
    /// points ([`Shape::key_reads_points`](crate::path::Shape::key_reads_points)):
    /// only a cache uses such a key.
    fn key_of<S: crate::path::Shape + ?Sized>(&self, shape: &S) -> Option<crate::path::ShapeKey> {
        if self.shapes.is_none() && shape.key_reads_points() {
            return None;
        }
        shape.key()
    }

    /// `paint` of the shape cache's outline of `key` (made from `bounds`
    /// and `describe` if the cache has none yet; `path` describes the
    /// shape: see [`ShapeCache`]); `None` without a cache, a key or a kept
    /// outline: draw the shape directly. The cache is taken out of the
    /// canvas for the painting and put back.
    fn kept_outline<R>(
        &mut self,
        key: impl FnOnce() -> Option<retained::OutlineKey>,
        bounds: impl FnOnce() -> Option<FineRect>,
        describe: impl Fn(&mut crate::path::SegmentBuffer<'_>) -> bool,
        path: &dyn Fn(&mut dyn crate::geom::PathSink),
        paint: impl FnOnce(&mut Self, &paths::Kept<'_>) -> R,
    ) -> Option<R> {
        self.shapes.as_ref()?;
        let key = key()?;
        let mut shapes = self.shapes.take()?;
        let r = shapes
            .outline(key, bounds, describe, path)
            .map(|(segments, bounds)| {
                let outline = paths::Kept {
                    segments: shapes.segments(segments),
                    bounds,
                };
                paint(self, &outline)
            });
        self.shapes = Some(shapes);
        r
    }

    /// An outline in one paint.
    fn paint_outline<O: Outline + ?Sized>(
        &mut self,
        serial: u32,
        outline: &O,
        rule: FillRule,
        fill: Fill<'_, C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        if !outline.complete() {
            return Err(DrawError::Incomplete);
        }
        let paint = match fill {
            Fill::Flat(color) => Paint::Flat(color.map(|v| v.min(crate::LIN_MAX))),
            // A gradient of one colour is that flat colour.
            Fill::Gradient(g) => g.flat().map_or(Paint::Gradient(g), Paint::Flat),
        };
        // By the fill rule in both blends: an outline wound several times
        // (or a stroke whose pieces overlap) covers a pixel once. Where the
        // outline is simple, a pixel's winding integral is its share
        // already (but for a unit or two of the edges' floors where it is
        // nearly empty, which the rule takes by magnitude), so shapes
        // sharing an edge add up to the whole (`shapes_render.rs`: a
        // polygon cut along a diagonal, raw bits). Triangles and meshes
        // keep the linear integral (`Coverage::Signed`).
        let coverage = match self.edges {
            Edges::Smooth => Coverage::Rule(rule),
            e => Coverage::Sharpened(rule, e),
        };
        let op = op_of(blend, opacity);
        self.fill_outline(serial, 0, outline, coverage, &paint, op)
    }

    /// Fills a triangle with a linear colour per vertex (Gouraud), or one
    /// colour when all three are equal.
    pub fn fill_triangle(
        &mut self,
        v: [FinePoint; 3],
        colors: [[u16; C]; 3],
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let serial = self.next_serial();
        let op = op_of(blend, opacity);
        let r = self.triangle(serial, 0, v, colors, op);
        r.inspect_err(|&e| self.skip(serial, e))
    }

    /// Fills a mesh: triangles given as index triples into `points`, with
    /// one colour per point (`colors`, Gouraud) or one for all. It is
    /// composed as one shape: its shared edges are seamless in painter's
    /// order (no background shows through them) and opacity applies to the
    /// mesh as a whole.
    pub fn fill_mesh(
        &mut self,
        points: &[FinePoint],
        triangles: &[[u16; 3]],
        colors: MeshColors<'_, C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let serial = self.next_serial();
        let r = self.mesh(serial, points, triangles, colors, blend, opacity);
        r.inspect_err(|&e| self.skip(serial, e))
    }

    fn mesh(
        &mut self,
        serial: u32,
        points: &[FinePoint],
        triangles: &[[u16; 3]],
        colors: MeshColors<'_, C>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let mesh = Mesh { points, triangles };
        mesh.check()?;
        if let MeshColors::PerPoint(c) = colors {
            if c.len() != points.len() {
                return Err(DrawError::ColorCount);
            }
        }
        let flat = match colors {
            MeshColors::Flat(c) => Some(c),
            MeshColors::PerPoint(c) => c.first().copied().filter(|f| c.iter().all(|x| x == f)),
        };
        let flat = flat.map(|c| c.map(|v| v.min(crate::LIN_MAX)));
        let MeshColors::PerPoint(per_point) = colors else {
            // One colour: one walk, one compose.
            let Some(color) = flat else {
                return Ok(());
            };
            let op = op_of(blend, opacity);
            return self.fill_outline(
                serial,
                0,
                &mesh,
                Coverage::Signed(1),
                &Paint::Flat(color),
                op,
            );
        };
        if let Some(color) = flat {
            let op = op_of(blend, opacity);
            return self.fill_outline(
                serial,
                0,
                &mesh,
                Coverage::Signed(1),
                &Paint::Flat(color),
                op,
            );
        }
        // Gouraud: in painter's order, first take the mesh's coverage out
        // of what is under it, then add each triangle's colour; added,
        // triangle by triangle.
        let per_triangle = match blend {
            Blend::Over => {
                let none = Paint::Flat([0; C]);
                self.fill_outline(
                    serial,
                    0,
                    &mesh,
                    Coverage::Signed(1),
                    &none,
                    ComposeOp::Attenuate(opacity),
                )?;
                ComposeOp::Accumulate(opacity)
            }
            Blend::Add => ComposeOp::Add(opacity),
        };
        // Edge indices after the whole mesh's (3 per triangle).
        let base = 3 * triangles.len() as u32;
        for (k, t) in triangles.iter().enumerate() {
            let color = |i: u16| per_point.get(usize::from(i)).copied();
            let (Some(v), Some(c0), Some(c1), Some(c2)) =
                (mesh.triangle(t), color(t[0]), color(t[1]), color(t[2]))
            else {
                continue;
            };
            self.triangle(serial, base + 3 * k as u32, v, [c0, c1, c2], per_triangle)?;
        }
        Ok(())
    }

    /// One Gouraud triangle with the edge indices `first..first + 3` and
    /// plane index `first` of shape `serial`.
    fn triangle(
        &mut self,
        serial: u32,
        first: u32,
        v: [FinePoint; 3],
        colors: [[u16; C]; 3],
        op: ComposeOp,
    ) -> Result<(), DrawError> {
        // Most of a band's triangles miss its rows: that is found first,
        // from the y extent alone, with the range test the box test below
        // would make (every coordinate within `FINE_LIMIT`), so that a
        // vertex out of range is still reported in every band.
        let [p, q, r] = &v;
        let (y_lo, y_hi) = (p.y.min(q.y).min(r.y), p.y.max(q.y).max(r.y));
        if !self.reach.rows(y_lo, y_hi)
            && in_fine_range(y_lo)
            && in_fine_range(y_hi)
            && in_fine_range(p.x)
            && in_fine_range(q.x)
            && in_fine_range(r.x)
        {
            return Ok(());
        }
        // Every vertex is in range when the box's corners are (the range is
        // a box): two tests, and the first vertex out of range looked for
        // only when there is one.
        let b = triangle_box(&v);
        if !(FinePoint::new(b.x0, b.y0).in_range() && FinePoint::new(b.x1, b.y1).in_range()) {
            for p in v {
                if !p.in_range() {
                    return Err(DrawError::FineCoord(p));
                }
            }
        }
        if !self.touches(&b) {
            return Ok(());
        }
        let rows = [b.y0 >> FINE_BITS, b.y1 >> FINE_BITS];
        let oriented = orient(v);
        if let Some(color) = flat_color(&colors) {
            // Oriented, its coverage is linear: triangles sharing an edge
            // add up exactly.
            let paint = Paint::Flat(color);
            self.fill_oriented(serial, first, &oriented, rows, &paint, op);
        } else {
            self.gouraud(serial, first, &v, &oriented, rows, &colors, op);
        }
        Ok(())
    }

    /// Draws a Gouraud triangle in range whose box touches the band (its
    /// first and last pixel rows `rows`); `oriented` is `v` in the order
    /// whose winding integral is its coverage.
    #[allow(clippy::too_many_arguments)]
    fn gouraud(
        &mut self,
        serial: u32,
        first: u32,
        v: &[FinePoint; 3],
        oriented: &[FinePoint; 3],
        rows: [i32; 2],
        colors: &[[u16; C]; 3],
        op: ComposeOp,
    ) {
        // Not in a band of the reach's margin that gets nothing from it:
        // its plane is not looked for there.
        let (y_lo, y_hi) = self.triangle_reach();
        if rows[1] < y_lo || rows[0] >= y_hi {
            return;
        }
        if let Some(plane) = self.plane(serial, first, *v, *colors, rows[1]) {
            self.fill_oriented(serial, first, oriented, rows, &Paint::Plane(&plane), op);
        }
    }

    /// [`fill_box`](Self::fill_box) of an oriented triangle: for the box
    /// pixel models (no margin, no curves whose segments a window leaves
    /// out), its three edges walked without the outline's numbering sink.
    /// Every shape of every band it meets comes through here, so the
    /// per-band cost of a triangle is little more than its walks.
    fn fill_oriented(
        &mut self,
        serial: u32,
        first: u32,
        o: &[FinePoint; 3],
        rows: [i32; 2],
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        let at = self.triangle_band();
        self.fill_oriented_here(&at, serial, first, o, rows, paint, op);
    }

    /// What every triangle drawn into this band needs of it, found once
    /// by a caller that draws many (a list's): the walk, the band's rows
    /// and columns.
    #[inline(always)]
    pub(super) fn triangle_band(&self) -> TriangleBand {
        let band = self.buf.band();
        TriangleBand {
            kind: WalkKind::of(self.style),
            rows: band.row_range(),
            cols: band.column_range(),
        }
    }

    /// [`fill_oriented`](Self::fill_oriented), inlined into a caller that
    /// draws many triangles (a list's flat ones), with the band's part
    /// found once (`at`, [`triangle_band`](Self::triangle_band)).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub(super) fn fill_oriented_here(
        &mut self,
        at: &TriangleBand,
        serial: u32,
        first: u32,
        o: &[FinePoint; 3],
        [y_first, y_last]: [i32; 2],
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        let WalkKind::Box(mode) = at.kind else {
            let b = triangle_box(o);
            self.fill_box(serial, first, o, b, Coverage::Signed(1), paint, op);
            return;
        };
        let rows = y_first.max(at.rows.start)..(y_last + 1).min(at.rows.end);
        if rows.start >= rows.end {
            return;
        }
        let buf = &mut *self.buf;
        let mut cache = self.cache.as_mut();
        // The three walks write the same rows of the scratch (the band's
        // part of the triangle's rows, clipped above).
        let mut out = buf.deltas_within(rows.clone());
        let shape = ShapeBand {
            serial,
            mode,
            cols: at.cols.clone(),
            rows,
        };
        let rows = &shape.rows;
        let [p, q, r] = *o;
        for (k, (p0, p1)) in [(0, (p, q)), (1, (q, r)), (2, (r, p))] {
            let (ylo, yhi) = (p0.y.min(p1.y) >> FINE_BITS, p0.y.max(p1.y) >> FINE_BITS);
            if yhi < rows.start || ylo >= rows.end {
                continue;
            }
            if p0.x == p1.x && mode == AreaMode::Exact {
                // Vertical (`walk_edge` would say so too, after its call;
                // a point gives nothing there either).
                crate::edge::walk_vertical(p0, p1, rows.clone(), &mut out);
                continue;
            }
            let edge = first.wrapping_add(k);
            cache::walk_edge(cache.as_deref_mut(), &shape, edge, (p0, p1), &mut out);
        }
        match (paint, op) {
            (Paint::Flat(color), ComposeOp::Over(a)) if a.is_opaque() => {
                buf.compose_opaque_flat(rows.start, rows.end, color);
            }
            _ => buf.compose(rows.start, rows.end, Coverage::Signed(1), paint, op),
        }
    }

    /// The Gouraud plane of a triangle: fitted once per frame when cached.
    fn plane(
        &mut self,
        serial: u32,
        index: u32,
        v: [FinePoint; 3],
        colors: [[u16; C]; 3],
        last: i32,
    ) -> Option<Plane<C>> {
        let made_of = plane_key(v, &colors);
        if let Some(cache) = self.cache.as_mut() {
            if let Some(p) = cache.plane(serial, index, &made_of) {
                return Some(p);
            }
        }
        let plane = Plane::triangle_fine(v, colors)?;
        let band = self.buf.band();
        let band_end = band.y0 + i32::from(band.rows);
        if last >= band_end {
            if let Some(cache) = self.cache.as_mut() {
                cache.put_plane(serial, index, made_of, band.y0, last, plane);
            }
        }
        Some(plane)
    }

    /// The pixel rows a triangle's first and last must meet for it to
    /// draw in this band (`first <= y_hi - 1`, `last >= y_lo`): the band's
    /// own for the box pixel models, which draw a triangle's rows only
    /// (`fill_oriented` clips to them), the reach's margin beyond them for
    /// the others.
    #[inline(always)]
    fn triangle_reach(&self) -> (i32, i32) {
        match WalkKind::of(self.style) {
            WalkKind::Box(_) => {
                let band = self.buf.band();
                (band.y0, band.y0 + i32::from(band.rows))
            }
            _ => (self.reach.y_lo, self.reach.y_hi),
        }
    }

    /// True when the box can touch the band (pixel models reach up to
    /// 1.5 px beyond a pixel).
    fn touches(&self, b: &FineRect) -> bool {
        let r = &self.reach;
        r.rows(b.y0, b.y1) && (b.x1 >> FINE_BITS) >= r.x_lo && (b.x0 >> FINE_BITS) < r.x_hi
    }

    /// Walks the outline's edges (indices from `first`) into the scratch
    /// and composes it.
    fn fill_outline<O: Outline + ?Sized>(
        &mut self,
        serial: u32,
        first: u32,
        outline: &O,
        coverage: Coverage,
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) -> Result<(), DrawError> {
        let Some(b) = outline.bounds() else {
            return Ok(());
        };
        for (x, y) in [(b.x0, b.y0), (b.x1, b.y1)] {
            let p = FinePoint::new(x, y);
            if !p.in_range() {
                return Err(DrawError::FineCoord(p));
            }
        }
        if !self.touches(&b) {
            return Ok(());
        }
        self.fill_box(serial, first, outline, b, coverage, paint, op);
        Ok(())
    }

    /// [`fill_outline`](Self::fill_outline) of an outline known to be in
    /// range, in the box `b`.
    #[allow(clippy::too_many_arguments)]
    fn fill_box<O: Outline + ?Sized>(
        &mut self,
        serial: u32,
        first: u32,
        outline: &O,
        b: FineRect,
        coverage: Coverage,
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        let band = self.buf.band();
        let kind = WalkKind::of(self.style);
        let margin = if kind == WalkKind::Sampled { 2 } else { 0 };
        let rows: Range<i32> = ((b.y0 >> FINE_BITS) - margin).max(band.y0)
            ..((b.y1 >> FINE_BITS) + 1 + margin).min(band.y0 + i32::from(band.rows));
        if rows.start >= rows.end {
            return;
        }
        let cols = band.column_range();
        let style = self.style;
        let buf = &mut *self.buf;
        let mut cache = self.cache.as_mut();
        // The rows the band needs, widened by the margin, in fine units.
        let window = (
            (rows.start - margin).saturating_mul(1 << FINE_BITS),
            (rows.end + margin)
                .saturating_mul(1 << FINE_BITS)
                .saturating_sub(1),
        );
        // What the exact-area walks of every segment share, made once.
        let shape = ShapeBand {
            serial,
            mode: match kind {
                WalkKind::Box(mode) => mode,
                _ => AreaMode::Exact,
            },
            cols: cols.clone(),
            rows: rows.clone(),
        };
        let mut edges = Numbered::new(first, window, |k, p0: FinePoint, p1: FinePoint| {
            let (ylo, yhi) = (p0.y.min(p1.y) >> FINE_BITS, p0.y.max(p1.y) >> FINE_BITS);
            if yhi + margin < rows.start || ylo - margin >= rows.end {
                return;
            }
            match kind {
                WalkKind::Box(_) => cache::walk_edge(
                    cache.as_deref_mut(),
                    &shape,
                    k,
                    (p0, p1),
                    &mut buf.deltas(rows.clone()),
                ),
                WalkKind::Aliased => {
                    if let Some(w) = cache
                        .as_deref_mut()
                        .and_then(|c| c.aliased(serial, k, p0, p1))
                    {
                        w.walk(rows.clone(), buf);
                    } else if let Some(mut w) = AliasedWalk::new(p0, p1) {
                        match cache.as_deref_mut() {
                            Some(c) if w.rows().end > rows.end => {
                                match c.place_aliased(serial, k, p0, p1, rows.start, w) {
                                    Ok(s) => s.walk(rows.clone(), buf),
                                    Err(mut w) => w.walk(rows.clone(), buf),
                                }
                            }
                            _ => w.walk(rows.clone(), buf),
                        }
                    }
                }
                WalkKind::Sampled => sampled_edge(buf, p0, p1, &style, rows.clone()),
            }
        });
        outline.segments_into(&mut edges);
        buf.compose(rows.start, rows.end, coverage, paint, op);
    }
}

/// An outline's segments numbered in their order, the ones a curve left
/// out counted too (a band's cached walks are found by their number), for
/// the rows `window` (fine units, closed).
struct Numbered<F> {
    next: u32,
    window: (i32, i32),
    f: F,
}

impl<F: FnMut(u32, FinePoint, FinePoint)> Numbered<F> {
    fn new(first: u32, window: (i32, i32), f: F) -> Self {
        Self {
            next: first,
            window,
            f,
        }
    }
}

impl<F: FnMut(u32, FinePoint, FinePoint)> SegmentSink for Numbered<F> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        let k = self.next;
        self.next = k.wrapping_add(1);
        (self.f)(k, from, to);
    }
    fn window(&self) -> Option<(i32, i32)> {
        Some(self.window)
    }
    fn skipped(&mut self, n: u32) {
        self.next = self.next.wrapping_add(n);
    }
}

/// The colours of a mesh.
#[derive(Debug, Clone, Copy)]
pub enum MeshColors<'a, const C: usize> {
    /// One colour for every triangle.
    Flat([u16; C]),
    /// One colour per point (Gouraud).
    PerPoint(&'a [[u16; C]]),
}

/// A mesh's triangles, each walked with positive orientation so that the
/// integral of the winding number is the coverage (and shared edges,
/// walked both ways, cancel).
struct Mesh<'a> {
    points: &'a [FinePoint],
    triangles: &'a [[u16; 3]],
}

impl Mesh<'_> {
    fn check(&self) -> Result<(), DrawError> {
        for t in self.triangles {
            if t.iter().any(|&i| usize::from(i) >= self.points.len()) {
                return Err(DrawError::BadIndex);
            }
        }
        for &p in self.points {
            if !p.in_range() {
                return Err(DrawError::FineCoord(p));
            }
        }
        Ok(())
    }

    fn triangle(&self, t: &[u16; 3]) -> Option<[FinePoint; 3]> {
        Some([
            *self.points.get(usize::from(t[0]))?,
            *self.points.get(usize::from(t[1]))?,
            *self.points.get(usize::from(t[2]))?,
        ])
    }
}

impl Outline for Mesh<'_> {
    fn bounds(&self) -> Option<FineRect> {
        FineRect::around(
            self.triangles
                .iter()
                .flat_map(|t| t.iter())
                .filter_map(|&i| self.points.get(usize::from(i)).copied()),
        )
    }
    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, mut f: F) {
        for t in self.triangles {
            if let Some(v) = self.triangle(t) {
                let [a, b, c] = orient(v);
                f(a, b);
                f(b, c);
                f(c, a);
            }
        }
    }
}

/// A triangle's one colour when its three are equal, clamped to 12 bits
/// (a flat paint); `None` for a Gouraud one.
#[inline]
fn flat_color<const C: usize>(colors: &[[u16; C]; 3]) -> Option<[u16; C]> {
    let [c0, c1, c2] = colors;
    (c0 == c1 && c1 == c2).then(|| c0.map(|x| x.min(crate::LIN_MAX)))
}

/// How a shape drawn with `blend` at `opacity` is composed.
fn op_of(blend: Blend, opacity: Opacity) -> ComposeOp {
    match blend {
        Blend::Over => ComposeOp::Over(opacity),
        Blend::Add => ComposeOp::Add(opacity),
    }
}

/// The triangle in the vertex order whose winding integral is its
/// coverage: counter-clockwise on screen (y down), negative doubled area.
fn orient(v: [FinePoint; 3]) -> [FinePoint; 3] {
    let [a, b, c] = v;
    let cross = (i64::from(b.x) - i64::from(a.x)) * (i64::from(c.y) - i64::from(a.y))
        - (i64::from(b.y) - i64::from(a.y)) * (i64::from(c.x) - i64::from(a.x));
    if cross > 0 {
        [a, c, b]
    } else {
        v
    }
}

/// What a cached plane was made from: the vertices and a hash of the
/// colours.
fn plane_key<const C: usize>(v: [FinePoint; 3], colors: &[[u16; C]; 3]) -> [i32; 6] {
    // FNV-1a over the colours and the last vertex, folded into two words.
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for c in colors.iter().flatten() {
        h = (h ^ u64::from(*c)).wrapping_mul(0x100_0000_01b3);
    }
    h = (h ^ (v[2].x as u32 as u64) ^ (u64::from(v[2].y as u32) << 32))
        .wrapping_mul(0x100_0000_01b3);
    [v[0].x, v[0].y, v[1].x, v[1].y, h as i32, (h >> 32) as i32]
}

/// One edge under a sampled pixel model (bed-of-nails, hexagonal,
/// circular): these sample on the 1/16-px vertex grid, so the edge's end
/// points are rounded to it.
fn sampled_edge<const C: usize>(
    buf: &mut BandBuffer<'_, C>,
    p0: FinePoint,
    p1: FinePoint,
    style: &RenderStyle,
    rows: Range<i32>,
) {
    let sub = |p: FinePoint| {
        const HALF: i32 = 1 << (FINE_BITS - crate::SUB_BITS - 1);
        SubPoint::new(
            p.x.saturating_add(HALF) >> (FINE_BITS - crate::SUB_BITS),
            p.y.saturating_add(HALF) >> (FINE_BITS - crate::SUB_BITS),
        )
    };
    let (a, b) = (sub(p0), sub(p1));
    match style.model {
        PixelModel::BedOfNails4 => walk_bed_of_nails(buf, a, b, 2, rows),
        PixelModel::BedOfNails8 => walk_bed_of_nails(buf, a, b, 4, rows),
        PixelModel::Hex7 => walk_hex7(buf, a, b, rows),
        PixelModel::Hex19 => walk_hex19(buf, a, b, rows),
        PixelModel::Cone => walk_circular(buf, a, b, CircularFilter::Cone, rows),
        PixelModel::Gaussian => walk_circular(buf, a, b, CircularFilter::Gaussian, rows),
        PixelModel::Hamming => walk_circular(buf, a, b, CircularFilter::Hamming, rows),
        _ => {}
    }
}

/// True when the ring of radii `inner <= outer` (quarter fine units; a
/// disc for `inner` 0) about `c` has no area in the pixels of `rows` x
/// `cols`: the pixels lie wholly inside the hole (their farthest corner
/// at most `inner` from `c`) or wholly outside (their nearest point at
/// least `outer` away). Distances below `2^30` quarter units (band
/// columns and rows are below `2^16` px, a centre in range below `2^23`
/// units from the origin), their squares as `u32 x u32` products.
pub(crate) fn ring_misses(
    c: FinePoint,
    outer: u64,
    inner: u64,
    rows: &Range<i32>,
    cols: &Range<i32>,
) -> bool {
    const Q: i64 = 4 << FINE_BITS;
    let (cx, cy) = (i64::from(c.x) * 4, i64::from(c.y) * 4);
    let (x0, x1) = (i64::from(cols.start) * Q, i64::from(cols.end) * Q);
    let (y0, y1) = (i64::from(rows.start) * Q, i64::from(rows.end) * Q);
    if x0 >= x1 || y0 >= y1 {
        return true;
    }
    let sq = |v: i64| {
        let v = v.unsigned_abs().min(u64::from(u32::MAX)) as u32;
        crate::arith::mul_wide(v, v)
    };
    let near = sq((x0 - cx).max(cx - x1).max(0)).saturating_add(sq((y0 - cy).max(cy - y1).max(0)));
    let far = sq((cx - x0).abs().max((cx - x1).abs()))
        .saturating_add(sq((cy - y0).abs().max((cy - y1).abs())));
    let (inner, outer) = (
        inner.min(u64::from(u32::MAX)),
        outer.min(u64::from(u32::MAX)),
    );
    far <= sq(inner as i64) || near >= sq(outer as i64)
}

/// The box of a circle about `c` of radius `outer` (1/4096 px) as its
/// outline's (`paths::shape_bounds`, widened by the curves' margin), when
/// all of it is in range; `None` otherwise (the outline path then reports
/// the shape). Saturating: a centre near the `i32` ends is out of range.
fn circle_box(c: FinePoint, outer: u32) -> Option<FineRect> {
    let reach = i32::try_from(outer.div_ceil(4)).ok()?.saturating_add(16);
    let b = FineRect {
        x0: c.x.saturating_sub(reach),
        y0: c.y.saturating_sub(reach),
        x1: c.x.saturating_add(reach),
        y1: c.y.saturating_add(reach),
    };
    (FinePoint::new(b.x0, b.y0).in_range() && FinePoint::new(b.x1, b.y1).in_range()).then_some(b)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::band::Band;
    use crate::geom::FINE_LIMIT;
    use crate::style::{Blend, Opacity};

    /// The band test a triangle starts with: one missing the band's rows
    /// draws nothing and is no error; one with a coordinate out of range
    /// is the same error (its first vertex out of range) in every band,
    /// whether or not its rows meet the band; one within the margin of
    /// the band's rows is drawn.
    #[test]
    fn triangles_missing_a_band_are_skipped_and_bad_ones_reported_in_every_band() {
        const W: u16 = 32;
        let px = |x: i32, y: i32| FinePoint::new(x * FINE_ONE_PX, y * FINE_ONE_PX);
        let far = FINE_LIMIT + 1;
        for y0 in [0, 16, 48] {
            let (mut acc, mut cover) = (
                [0i32; BandBuffer::<1>::acc_len(W, 16)],
                [0i32; BandBuffer::<1>::cover_len(W, 16)],
            );
            let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(W, y0, 16)).unwrap();
            buf.clear([0]);
            let mut c = Canvas::new(&mut buf, None);
            let mut fill =
                |v: [FinePoint; 3]| c.fill_triangle(v, [[4095]; 3], Blend::Over, Opacity::OPAQUE);
            // Rows far below or above every band tried: nothing.
            assert_eq!(fill([px(1, 200), px(20, 200), px(1, 230)]), Ok(()));
            assert_eq!(fill([px(1, -90), px(20, -90), px(1, -60)]), Ok(()));
            // Out of range in x, rows far from the band: still reported,
            // naming the first vertex out of range.
            let bad = FinePoint::new(far, 200 * FINE_ONE_PX);
            assert_eq!(
                fill([px(1, 200), bad, FinePoint::new(-far, 230 * FINE_ONE_PX)]),
                Err(DrawError::FineCoord(bad))
            );
            let bad_y = FinePoint::new(0, -far);
            assert_eq!(
                fill([bad_y, px(20, 200), px(1, 230)]),
                Err(DrawError::FineCoord(bad_y))
            );
            assert!(
                (0..16).all(|r| (0..i32::from(W)).all(|x| buf.lin12(x, y0 + r) == Some([0]))),
                "band at {y0}: nothing drawn"
            );
        }
        // A triangle whose rows end a pixel above the band still reaches it
        // through the margin test and is walked (its cells there are empty,
        // so the band stays clear), and one across the band is drawn.
        let (mut acc, mut cover) = (
            [0i32; BandBuffer::<1>::acc_len(W, 16)],
            [0i32; BandBuffer::<1>::cover_len(W, 16)],
        );
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(W, 16, 16)).unwrap();
        buf.clear([0]);
        let mut c = Canvas::new(&mut buf, None);
        for v in [
            [px(1, 0), px(20, 0), px(1, 15)],
            [px(1, 10), px(20, 10), px(1, 30)],
        ] {
            c.fill_triangle(v, [[4095]; 3], Blend::Over, Opacity::OPAQUE)
                .unwrap();
        }
        assert_eq!(buf.lin12(2, 20), Some([4095]));
        assert_eq!(buf.lin12(30, 20), Some([0]));
    }

    const FINE_ONE_PX: i32 = 1 << FINE_BITS;
}
