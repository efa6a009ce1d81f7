//! A frame described as data, and its rendering band by band.
//!
//! [`render`] is the firmware loop on a PC: for each [`Band`] of the frame
//! (top to bottom, `band_rows` rows, the last one possibly shorter) it makes
//! a [`BandBuffer`] over one reused pair of buffers, clears it to the
//! background, draws every primitive in order and resolves the band's rows
//! into the image. Nothing here rounds or converts: the image holds exactly
//! the linear 12-bit values [`BandBuffer::resolve_row`] gave.
//!
//! [`render_lightness_filtered`] adds the post-filter of seed 002
//! ([`LightnessFilter`]) between accumulation and tone, the way firmware
//! runs it: each band is rendered one row taller at each end (the halo rows
//! the filter's 4-neighbour Laplacian needs), resolved into a scratch of
//! `band_rows + 2` rows and filtered into the band's output rows. Every
//! band height gives the frame [`LightnessFilter::filter_frame`] gives for
//! the unfiltered render; the cost is two extra rendered rows per band.

use std::fmt;

use softedge::hsr::{
    draw_warnock, front_to_back, scratch_len, zbuffer_passes, DepthBuffer, DepthTriangle, HsrError,
    Section, VisibleSet, ZPass,
};
use softedge::postfilter::{FilterError, FilterStats, LightnessFilter, LightnessPixel};
use softedge::{
    Band, BandBuffer, BandError, Bands, DrawError, Line, Polygon, PolygonColors, RenderStyle,
    SubPoint, Triangle,
};

use softedge::canvas::Canvas;
use softedge::style::{Blend, Opacity};

use crate::image::LinImage;
use crate::shape_item::{self, MeshItem, ShapeItem};

/// Colours of a [`Primitive::Polygon`], owned.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PolyColors<const C: usize> {
    /// One colour for the whole polygon.
    Flat([u16; C]),
    /// One colour per vertex.
    PerVertex(Vec<[u16; C]>),
}

/// One primitive of a scene, in drawing order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Primitive<const C: usize> {
    /// A Gouraud triangle.
    Triangle(Triangle<C>),
    /// A simple polygon (convex or concave), vertices owned.
    Polygon {
        /// Vertices in order.
        vertices: Vec<SubPoint>,
        /// Colours.
        colors: PolyColors<C>,
    },
    /// A 1-px line.
    Line(Line<C>),
    /// A 1-px line with a depth at each end (scene files' `depths`);
    /// without hidden-surface removal it is drawn as a plain line.
    DepthLine(Line<C>, [u16; 2]),
    /// A triangle with a depth per vertex (3D objects, or 2D primitives
    /// given `depths`); without hidden-surface removal it is drawn as a
    /// plain triangle.
    Depth(DepthTriangle<C>),
    /// A shape with a fill and a stroke (scene files' circles, ellipses,
    /// arcs, sectors, rectangles, polylines, paths); hidden-surface
    /// removal leaves it out.
    Shape(Box<ShapeItem<C>>),
    /// A mesh of triangles sharing points, one shape; hidden-surface
    /// removal takes its triangles at depth 0.
    Mesh(Box<MeshItem<C>>),
    /// A primitive drawn at an opacity below 1 (scene files' `opacity`).
    Faded(Box<Primitive<C>>, Opacity),
    /// Text in an outline font (scene files' `[[text]]`), composed over
    /// what is drawn before it; hidden-surface removal leaves it out.
    Text(Box<crate::text_item::TextItem<C>>),
    /// An image (scene files' `[[image]]`), composed over what is drawn
    /// before it; hidden-surface removal leaves it out.
    Image(Box<crate::image_item::ImageItem<C>>),
}

impl<const C: usize> Primitive<C> {
    /// A flat polygon.
    pub fn flat_polygon(vertices: Vec<SubPoint>, color: [u16; C]) -> Self {
        Self::Polygon {
            vertices,
            colors: PolyColors::Flat(color),
        }
    }

    /// Draws this primitive into one band by seed 000's accumulation
    /// (every band gets every primitive; core clips it to the band).
    pub fn draw(&self, buf: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        match self {
            Self::Triangle(t) => t.draw(buf, style),
            Self::Depth(t) => t.draw(buf, style),
            Self::Line(l) | Self::DepthLine(l, _) => l.draw(buf, style),
            Self::Text(t) => t.draw(buf, style),
            Self::Image(i) => i.draw(buf, style),
            Self::Polygon { vertices, colors } => {
                let colors = match colors {
                    PolyColors::Flat(c) => PolygonColors::Flat(*c),
                    PolyColors::PerVertex(cs) => PolygonColors::PerVertex(cs),
                };
                Polygon::new(vertices, colors).draw(buf, style)
            }
            Self::Mesh(m) if m.opacity == Opacity::OPAQUE => {
                for t in m.triangles() {
                    t.draw(buf, style)?;
                }
                Ok(())
            }
            Self::Shape(_) | Self::Faded(..) | Self::Mesh(_) => {
                let mut canvas = Canvas::new(buf, None);
                canvas.set_style(*style);
                self.compose(&mut canvas, Blend::Add, Opacity::OPAQUE)
            }
        }
    }

    /// Draws this primitive into a band's canvas with `blend`, at
    /// `opacity` (times its own).
    pub fn compose<Col>(
        &self,
        canvas: &mut Canvas<'_, '_, C, Col>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        match self {
            Self::Triangle(t) => shape_item::triangle(canvas, t, blend, opacity),
            Self::Depth(t) => shape_item::triangle(canvas, &t.triangle(), blend, opacity),
            Self::Line(l) | Self::DepthLine(l, _) => shape_item::line(canvas, l, blend, opacity),
            Self::Polygon { vertices, colors } => {
                let colors = match colors {
                    PolyColors::Flat(c) => PolygonColors::Flat(*c),
                    PolyColors::PerVertex(cs) => PolygonColors::PerVertex(cs),
                };
                shape_item::polygon(canvas, &Polygon::new(vertices, colors), blend, opacity)
            }
            Self::Shape(s) => {
                let s = ShapeItem {
                    opacity: times(s.opacity, opacity),
                    ..(**s).clone()
                };
                s.draw(canvas, blend)
            }
            Self::Mesh(m) => {
                let m = MeshItem {
                    opacity: times(m.opacity, opacity),
                    ..(**m).clone()
                };
                m.draw(canvas, blend)
            }
            Self::Faded(p, a) => p.compose(canvas, blend, times(*a, opacity)),
            Self::Text(t) => t.compose(canvas, times(t.opacity, opacity)),
            Self::Image(i) => i.compose(canvas, blend, opacity),
        }
    }

    /// The primitive as depth triangles (2D primitives without depths lie
    /// at depth 0, the farthest; a line is its 1-px rectangle).
    fn depth_triangles(&self, out: &mut Vec<DepthTriangle<C>>) -> Result<(), DrawError> {
        match self {
            Self::Triangle(t) => out.push(DepthTriangle::new(t.vertices, t.colors, [0; 3])),
            Self::Depth(t) => out.push(*t),
            Self::Polygon { vertices, colors } => {
                let colors = match colors {
                    PolyColors::Flat(c) => PolygonColors::Flat(*c),
                    PolyColors::PerVertex(cs) => PolygonColors::PerVertex(cs),
                };
                let zeros = vec![0u16; vertices.len()];
                Polygon::new(vertices, colors).depth_triangles(&zeros, |t| out.push(t))?;
            }
            Self::Line(l) => l.depth_triangles([0; 2], |t| out.push(t))?,
            Self::DepthLine(l, z) => l.depth_triangles(*z, |t| out.push(t))?,
            Self::Mesh(m) => out.extend(
                m.triangles()
                    .map(|t| DepthTriangle::new(t.vertices, t.colors, [0; 3])),
            ),
            Self::Faded(p, _) => p.depth_triangles(out)?,
            Self::Shape(_) => {}
            Self::Text(_) => {}
            Self::Image(_) => {}
        }
        Ok(())
    }
}

/// The product of two opacities.
fn times(a: Opacity, b: Opacity) -> Opacity {
    let p = u32::from(a.to_4096ths()) * u32::from(b.to_4096ths());
    Opacity::from_4096ths(((p + 2048) >> 12) as u16)
}

/// Hidden-surface removal for a frame (`[render] hsr` in scene files).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Hsr {
    /// None: primitives are accumulated in order.
    #[default]
    None,
    /// The z-buffer in bands with anti-aliased edges (`softedge::hsr`).
    ZBuffer,
    /// Warnock's subdivision down to 1/16 px, edges resolved by area
    /// (`softedge::hsr::draw_warnock`), band by band.
    Warnock,
    /// Weiler–Atherton: disjoint visible polygons computed once per frame
    /// (`softedge::hsr::weiler`), then accumulated exactly.
    WeilerAtherton,
}

/// Most visible pieces (and clip lines) the simulator's Weiler–Atherton
/// stores per frame: 4096, about 770 KB on the host (a firmware chooses
/// its own `N`; 164 bytes per piece, 24 per line).
pub const WEILER_CAPACITY: usize = 4096;

/// Most depth triangles the simulator gives Weiler–Atherton per frame: its
/// clipping tests every ordered pair (8192 triangles: 67 M box tests,
/// about a second), so the work is bounded before it starts.
pub const MAX_WEILER_TRIANGLES: usize = 8192;

/// A frame: size, band height, style, background and primitives.
///
/// `C` is the number of colour channels: 1 (gray) or 3 (RGB). Colours are
/// linear 12-bit, `0..=4095`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene<const C: usize> {
    /// Frame width in pixels.
    pub width: u16,
    /// Frame height in pixels.
    pub height: u16,
    /// Rows per band (8 matches an SSD1306 page; the result does not depend
    /// on it).
    pub band_rows: u16,
    /// How every primitive is drawn.
    pub style: RenderStyle,
    /// Background, linear 12-bit.
    pub background: [u16; C],
    /// Primitives, in drawing order.
    pub primitives: Vec<Primitive<C>>,
    /// Hidden-surface removal.
    pub hsr: Hsr,
    /// Section mode: draw only where surfaces cross this depth (seed 004),
    /// as anti-aliased 1 px lines in the surfaces' colours.
    pub section: Option<u16>,
    /// How primitives meet what is drawn before them, without
    /// hidden-surface removal: seed 000's accumulation (`Blend::Add`,
    /// [`Scene::new`]'s default, for disjoint surfaces and meshes drawn
    /// triangle by triangle) or painter's order (`Blend::Over`, scene
    /// files' default). Hidden-surface methods compose their disjoint
    /// visible pieces by addition whatever this says.
    pub blend: Blend,
}

impl<const C: usize> Scene<C> {
    /// An empty scene of `width x height`, bands of 8 rows, default
    /// (anti-aliased, exact box) style.
    pub fn new(width: u16, height: u16, background: [u16; C]) -> Self {
        Self {
            width,
            height,
            band_rows: 8,
            style: RenderStyle::default(),
            background,
            primitives: Vec::new(),
            hsr: Hsr::None,
            section: None,
            blend: Blend::Add,
        }
    }

    /// The same scene drawn with another style.
    pub fn with_style(&self, style: RenderStyle) -> Self {
        Self {
            style,
            ..self.clone()
        }
    }

    /// Draws the primitives into one band's canvas, in order, by
    /// [`Scene::blend`] (without hidden-surface removal); a rejected
    /// primitive stops the band with its index.
    pub fn draw_into<Col>(&self, canvas: &mut Canvas<'_, '_, C, Col>) -> Result<(), RenderError> {
        for (index, p) in self.primitives.iter().enumerate() {
            let legacy = match p {
                Primitive::Shape(_) | Primitive::Faded(..) | Primitive::Image(_) => false,
                Primitive::Mesh(m) => m.opacity == Opacity::OPAQUE,
                _ => true,
            };
            let r = if self.blend == Blend::Add && legacy {
                // Seed 000's accumulation, the frames of before bit for bit.
                p.draw(canvas.buffer(), &self.style)
            } else {
                p.compose(canvas, self.blend, Opacity::OPAQUE)
            };
            r.map_err(|error| RenderError::Draw { index, error })?;
        }
        Ok(())
    }

    /// The same scene drawn in bands of another height.
    pub fn with_band_rows(&self, band_rows: u16) -> Self {
        Self {
            band_rows,
            ..self.clone()
        }
    }
}

/// Why a scene could not be rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RenderError {
    /// The frame or band size was rejected by [`BandBuffer::new`].
    Band {
        /// The band.
        band: Band,
        /// Why.
        error: BandError,
    },
    /// A primitive was rejected.
    Draw {
        /// Its index in [`Scene::primitives`].
        index: usize,
        /// Why.
        error: DrawError,
    },
    /// The post-filter rejected the frame size or its buffers.
    Filter(FilterError),
    /// The frame has more depth triangles than `method` takes
    /// ([`MAX_WEILER_TRIANGLES`], or Warnock's
    /// [`MAX_TRIANGLES`](softedge::hsr::MAX_TRIANGLES)).
    TooManyTriangles {
        /// The method.
        method: Hsr,
        /// The primitive whose triangles passed the limit.
        index: usize,
        /// The frame's triangles.
        count: usize,
        /// The method's limit.
        limit: usize,
    },
    /// A hidden-surface method failed (for capacity: the frame needs more
    /// than the simulator's storage for that method holds).
    Hsr {
        /// The method.
        method: Hsr,
        /// The primitive (index in [`Scene::primitives`]) it failed at,
        /// when the method can tell.
        index: Option<usize>,
        /// Why.
        error: HsrError,
    },
}

impl Hsr {
    /// The name used in scene files (`render.hsr`).
    pub fn name(self) -> &'static str {
        match self {
            Self::None => "none",
            Self::ZBuffer => "zbuffer",
            Self::Warnock => "warnock",
            Self::WeilerAtherton => "weiler-atherton",
        }
    }
}

/// What core's [`DrawError`] means, for a message.
pub fn draw_error_text(error: DrawError) -> String {
    use softedge::{COORD_LIMIT_PX, MAX_POLYGON_VERTICES};
    match error {
        DrawError::Coord(c) => format!(
            "a vertex is outside ±{COORD_LIMIT_PX} px: ({}, {}) px",
            f64::from(c.point.x) / 16.0,
            f64::from(c.point.y) / 16.0
        ),
        DrawError::TooManyVertices => format!("more than {MAX_POLYGON_VERTICES} vertices"),
        DrawError::ColorCount => {
            "per-vertex colours or depths for a different number of vertices".into()
        }
        DrawError::SelfIntersecting => {
            "the polygon intersects itself (two of its edges touch or cross)".into()
        }
        DrawError::FineCoord(p) => format!(
            "a point is outside ±{COORD_LIMIT_PX} px: ({}, {}) px",
            f64::from(p.x) / 1024.0,
            f64::from(p.y) / 1024.0
        ),
        DrawError::BadIndex => "a mesh triangle names a point the mesh does not have".into(),
        other => other.to_string(),
    }
}

/// What a hidden-surface error means, in words, with the limit it hit.
pub fn hsr_error_text(method: Hsr, error: HsrError) -> String {
    use softedge::hsr::{MAX_TRIANGLES as WARNOCK_TRIANGLES, PIECE_VERTICES};
    match (method, error) {
        (_, HsrError::Draw(e)) => draw_error_text(e),
        (_, HsrError::BandMismatch) => {
            "internal: the depth buffer holds another band than the band buffer".into()
        }
        (Hsr::WeilerAtherton, HsrError::Capacity { needed }) if needed == PIECE_VERTICES + 1 => {
            format!(
                "weiler-atherton: a visible piece collected more cut vertices than the {} \
                 a piece may be split into (twice {PIECE_VERTICES}); too many surfaces cut \
                 it: use coarser objects or hsr = \"zbuffer\"",
                2 * PIECE_VERTICES
            )
        }
        (Hsr::WeilerAtherton, HsrError::Capacity { needed }) if needed > usize::from(u16::MAX) => {
            format!(
                "weiler-atherton takes at most {} triangles per frame, this frame has {needed}",
                u16::MAX
            )
        }
        (Hsr::WeilerAtherton, HsrError::Capacity { .. }) => format!(
            "weiler-atherton ran out of storage: the frame needs more than the \
             {WEILER_CAPACITY} visible pieces and {WEILER_CAPACITY} clip lines the \
             simulator keeps per frame ({} KB); use fewer or coarser objects, or \
             hsr = \"zbuffer\"",
            WEILER_CAPACITY * (std::mem::size_of::<softedge::hsr::VisiblePiece>() + 24) / 1000
        ),
        (Hsr::Warnock, HsrError::Capacity { needed }) if needed > WARNOCK_TRIANGLES => format!(
            "warnock takes at most {WARNOCK_TRIANGLES} triangles per frame, this frame \
             has {needed}: use fewer or coarser objects, or hsr = \"zbuffer\""
        ),
        (m, HsrError::Capacity { needed }) => format!(
            "{}: scratch storage too small ({needed} entries needed)",
            m.name()
        ),
    }
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Band { band, error } => write!(
                f,
                "band at row {} ({}x{}) rejected: {error:?}",
                band.y0, band.width, band.rows
            ),
            Self::Draw { index, error } => {
                write!(
                    f,
                    "primitive #{index} rejected: {}",
                    draw_error_text(*error)
                )
            }
            Self::Filter(error) => write!(f, "lightness filter rejected the frame: {error:?}"),
            Self::TooManyTriangles {
                method,
                index,
                count,
                limit,
            } => write!(
                f,
                "primitive #{index}: hsr = {} takes at most {limit} triangles per frame, \
                 this frame has {count}",
                method.name()
            ),
            Self::Hsr {
                method,
                index,
                error,
            } => {
                if let Some(i) = index {
                    write!(f, "primitive #{i}: ")?;
                }
                f.write_str(&hsr_error_text(*method, *error))
            }
        }
    }
}

impl std::error::Error for RenderError {}

/// Renders `scene` band by band into a linear 12-bit image.
///
/// A primitive that [`draw`](Triangle::draw) rejects stops the render with
/// [`RenderError::Draw`] (firmware could skip it; a simulator should say).
/// With [`Scene::hsr`] or [`Scene::section`] the frame's primitives are
/// prepared once (depth triangles sorted front to back, or section lines)
/// and drawn into every band in the same order.
pub fn render<const C: usize>(scene: &Scene<C>) -> Result<LinImage<C>, RenderError> {
    let (w, h) = (scene.width, scene.height);
    let rows = scene.band_rows.max(1);
    let frame = Prepared::new(scene)?;
    let mut img = LinImage::new(u32::from(w), u32::from(h));
    // One set of buffers for the whole frame, as on a microcontroller.
    let mut store = BandStore::<C>::new(w, rows, &frame);
    let mut row = vec![[0u16; C]; usize::from(w)];
    for band in Bands::new(w, h, rows) {
        store.draw(scene, &frame, band, |buf| {
            for y in band.y0..band.y0 + i32::from(band.rows) {
                let n = buf.resolve_row(y, &mut row);
                img.set_row(y as u32, &row[..n]);
            }
        })?;
    }
    Ok(img)
}

/// A frame's primitives as the chosen method draws them, prepared once.
enum Prepared<const C: usize> {
    /// Accumulated in order.
    Plain,
    /// Depth triangles, front to back, through the z-buffer, and the index
    /// of the primitive each came from (kept through the sort).
    ZBuffer(Vec<DepthTriangle<C>>, Vec<usize>),
    /// Section lines and faces, accumulated (with their primitive's index).
    Section(Vec<(Primitive<C>, usize)>),
    /// Weiler–Atherton's visible pieces of the frame's depth triangles.
    Weiler(Vec<DepthTriangle<C>>, Box<VisibleSet<WEILER_CAPACITY>>),
    /// The frame's depth triangles for Warnock's subdivision.
    Warnock(Vec<DepthTriangle<C>>),
}

impl<const C: usize> Prepared<C> {
    fn new(scene: &Scene<C>) -> Result<Self, RenderError> {
        if scene.hsr == Hsr::None && scene.section.is_none() {
            return Ok(Self::Plain);
        }
        let mut tris: Vec<(DepthTriangle<C>, usize)> = Vec::new();
        let mut one = Vec::new();
        for (index, p) in scene.primitives.iter().enumerate() {
            one.clear();
            p.depth_triangles(&mut one)
                .map_err(|error| RenderError::Draw { index, error })?;
            // Checked here, so a bad vertex is reported with its primitive
            // whichever method draws the frame.
            for t in &one {
                for v in t.vertices {
                    v.check().map_err(|e| RenderError::Draw {
                        index,
                        error: DrawError::Coord(e),
                    })?;
                }
            }
            tris.extend(one.iter().map(|&t| (t, index)));
        }
        if let Some(z) = scene.section {
            let mut out = Vec::new();
            for (t, index) in tris {
                match t.section(z) {
                    Some(Section::Segment(l)) => out.push((Primitive::Line(l), index)),
                    Some(Section::Face) => out.push((Primitive::Triangle(t.triangle()), index)),
                    None => {}
                }
            }
            return Ok(Self::Section(out));
        }
        let limit = match scene.hsr {
            Hsr::WeilerAtherton => MAX_WEILER_TRIANGLES,
            Hsr::Warnock => softedge::hsr::MAX_TRIANGLES,
            Hsr::None | Hsr::ZBuffer => usize::MAX,
        };
        if let Some(&(_, index)) = tris.get(limit) {
            return Err(RenderError::TooManyTriangles {
                method: scene.hsr,
                index,
                count: tris.len(),
                limit,
            });
        }
        if scene.hsr == Hsr::Warnock {
            return Ok(Self::Warnock(tris.iter().map(|(t, _)| *t).collect()));
        }
        if scene.hsr == Hsr::WeilerAtherton {
            let sources: Vec<usize> = tris.iter().map(|(_, i)| *i).collect();
            let tris: Vec<DepthTriangle<C>> = tris.iter().map(|(t, _)| *t).collect();
            let mut set = Box::new(VisibleSet::new());
            set.compute(&tris).map_err(|error| RenderError::Hsr {
                method: Hsr::WeilerAtherton,
                index: set.failed_at().and_then(|k| sources.get(k).copied()),
                error,
            })?;
            return Ok(Self::Weiler(tris, set));
        }
        // Sorted front to back once per frame (ties by content: the order
        // does not depend on the file's order of equal-depth triangles),
        // each with its source: n log n, no search afterwards.
        tris.sort_unstable_by(|(a, i), (b, j)| front_to_back(a, b).then(i.cmp(j)));
        let (sorted, sources) = tris.into_iter().unzip();
        Ok(Self::ZBuffer(sorted, sources))
    }
}

/// The buffers of one band, reused for every band of a frame.
struct BandStore<const C: usize> {
    acc: Vec<i32>,
    cover: Vec<i32>,
    depth: Vec<u16>,
    covered: Vec<u16>,
    /// Warnock's candidate lists.
    scratch: Vec<u16>,
}

impl<const C: usize> BandStore<C> {
    fn new(width: u16, rows: u16, frame: &Prepared<C>) -> Self {
        let zlen = match frame {
            Prepared::ZBuffer(..) => DepthBuffer::len(width, rows),
            _ => 0,
        };
        Self {
            acc: vec![0i32; BandBuffer::<C>::acc_len(width, rows)],
            cover: vec![0i32; BandBuffer::<C>::cover_len(width, rows)],
            depth: vec![0u16; zlen],
            covered: vec![0u16; 2 * zlen],
            scratch: Vec::new(),
        }
    }

    /// Clears the band to the background, draws the frame into it and
    /// hands the finished band to `done`.
    fn draw(
        &mut self,
        scene: &Scene<C>,
        frame: &Prepared<C>,
        band: Band,
        done: impl FnOnce(&BandBuffer<'_, C>),
    ) -> Result<(), RenderError> {
        let mut buf = BandBuffer::<C>::new(&mut self.acc, &mut self.cover, band)
            .map_err(|error| RenderError::Band { band, error })?;
        buf.clear(scene.background);
        let style = &scene.style;
        match frame {
            Prepared::Plain => {
                let mut canvas = Canvas::new(&mut buf, None);
                canvas.set_style(*style);
                scene.draw_into(&mut canvas)?;
            }
            Prepared::Section(prims) => {
                for (p, index) in prims {
                    p.draw(&mut buf, style).map_err(|error| RenderError::Draw {
                        index: *index,
                        error,
                    })?;
                }
            }
            Prepared::Weiler(tris, set) => {
                set.draw(tris, &mut buf, style)
                    .map_err(|error| RenderError::Hsr {
                        method: Hsr::WeilerAtherton,
                        index: None,
                        error,
                    })?;
            }
            Prepared::Warnock(tris) => {
                // Warnock resolves edges by area itself: no pixel model.
                if self.scratch.len() < scratch_len(tris.len()) {
                    self.scratch.resize(scratch_len(tris.len()), 0);
                }
                draw_warnock(tris, &mut buf, &mut self.scratch).map_err(|error| {
                    RenderError::Hsr {
                        method: Hsr::Warnock,
                        index: None,
                        error,
                    }
                })?;
            }
            Prepared::ZBuffer(tris, sources) => {
                let mut zbuf = DepthBuffer::new(&mut self.depth, &mut self.covered, band)
                    .map_err(|error| RenderError::Band { band, error })?;
                // `draw_zbuffer`'s passes, spelled out so that an error
                // names the triangle's primitive (vertices were checked when
                // the frame was prepared, so none is expected).
                for &pass in zbuffer_passes(style) {
                    for (t, &index) in tris.iter().zip(sources) {
                        t.draw_z(&mut buf, &mut zbuf, style, pass)
                            .map_err(|error| RenderError::Hsr {
                                method: Hsr::ZBuffer,
                                index: Some(index),
                                error,
                            })?;
                    }
                    if pass == ZPass::Centres {
                        zbuf.finish_centres();
                    }
                }
            }
        }
        done(&buf);
        Ok(())
    }
}

/// Renders `scene` band by band and runs the lightness filter of seed 002
/// on every band ([`LightnessFilter::filter_band`]): the linear 12-bit
/// frame the tone stage receives when the filter is on, and what the
/// filter did (pixels changed, pixels clamped to the RGB gamut).
///
/// Each band of `band_rows` output rows is rendered as a band of
/// `band_rows + 2` rows starting one row higher (the halo); the halo rows
/// are rendered again by the neighbouring bands. The result does not depend
/// on `band_rows`.
///
/// ```
/// use softedge::{RenderStyle, SubPoint, Triangle};
/// use softedge_sim::scene::{render, render_lightness_filtered, Primitive, Scene};
///
/// // A light gray (L* 80, k = 0.15) with a lighter triangle on it.
/// let mut scene = Scene::<1>::new(12, 9, [2300]);
/// scene.primitives.push(Primitive::Triangle(Triangle::flat(
///     [SubPoint::from_px(1, 1), SubPoint::new(170, 30), SubPoint::new(40, 130)],
///     [3400],
/// )));
/// let (filtered, stats) = render_lightness_filtered(&scene).unwrap();
/// assert!(stats.changed > 0);
/// assert_ne!(filtered, render(&scene).unwrap());
/// for rows in [1, 2, 9] {
///     assert_eq!(render_lightness_filtered(&scene.with_band_rows(rows)).unwrap().0, filtered);
/// }
/// ```
pub fn render_lightness_filtered<const C: usize>(
    scene: &Scene<C>,
) -> Result<(LinImage<C>, FilterStats), RenderError>
where
    [u16; C]: LightnessPixel,
{
    let (w, h) = (scene.width, scene.height);
    let rows = scene.band_rows.max(1);
    let halo_rows = rows.saturating_add(2);
    let filter = LightnessFilter::new(w, h).map_err(RenderError::Filter)?;
    let mut img = LinImage::new(u32::from(w), u32::from(h));
    let frame = Prepared::new(scene)?;
    let mut store = BandStore::<C>::new(w, halo_rows, &frame);
    // The band and its halo rows, resolved: the filter's input.
    let mut input = vec![[0u16; C]; usize::from(w) * usize::from(halo_rows)];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w)];
    let mut out_row = vec![[0u16; C]; usize::from(w)];
    let mut stats = FilterStats::default();
    for band in Bands::new(w, h, rows) {
        let halo = Band {
            y0: band.y0 - 1,
            rows: band.rows.saturating_add(2),
            ..band
        };
        let n_in = usize::from(w) * usize::from(halo.rows);
        store.draw(scene, &frame, halo, |buf| {
            for (r, row) in input[..n_in].chunks_exact_mut(usize::from(w)).enumerate() {
                // Rows outside the frame are resolved too; the filter never
                // reads them (it repeats the edge row).
                buf.resolve_row(halo.y0 + r as i32, row);
            }
        })?;
        let s = filter
            .filter_band(
                band.y0,
                band.rows,
                &input[..n_in],
                &mut scratch,
                &mut out_row,
                |y, row| img.set_row(y as u32, row),
            )
            .map_err(RenderError::Filter)?;
        stats.changed += s.changed;
        stats.clamped += s.clamped;
    }
    Ok((img, stats))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sorted_depth_triangles_keep_their_source_primitive() {
        // Issue #18: the sort carries each triangle's primitive index (it
        // was searched for afterwards, quadratic in the triangle count).
        let p = |x, y| SubPoint::from_px(x, y);
        let mut s = Scene::<1>::new(16, 16, [0]);
        for k in 0..40u16 {
            let x = i32::from(k % 8);
            s.primitives.push(Primitive::Depth(DepthTriangle::new(
                [p(x, 0), p(x + 6, 2), p(x, 9)],
                [[k * 100]; 3],
                [(k * 977) % 60_000, (k * 31) % 60_000, 5 + k],
            )));
            // Polygons give several triangles for one primitive.
            s.primitives.push(Primitive::flat_polygon(
                vec![p(x, 10), p(x + 4, 10), p(x + 4, 14), p(x, 14)],
                [k],
            ));
        }
        s.hsr = Hsr::ZBuffer;
        let Prepared::ZBuffer(tris, sources) = Prepared::new(&s).unwrap() else {
            panic!("a z-buffer frame")
        };
        assert_eq!(tris.len(), sources.len());
        assert_eq!(tris.len(), 40 + 40 * 2);
        for (t, &i) in tris.iter().zip(&sources) {
            let mut own = Vec::new();
            s.primitives[i].depth_triangles(&mut own).unwrap();
            assert!(own.contains(t), "triangle {t:?} is not from primitive {i}");
        }
        for pair in tris.windows(2) {
            assert_ne!(
                front_to_back(&pair[0], &pair[1]),
                std::cmp::Ordering::Greater
            );
        }
    }

    fn star_scene() -> Scene<3> {
        let mut s = Scene::new(40, 37, [100, 200, 300]);
        s.primitives.push(Primitive::Triangle(Triangle::new(
            [
                SubPoint::new(3 * 16 + 5, 2 * 16 + 1),
                SubPoint::new(37 * 16 + 9, 9 * 16 + 14),
                SubPoint::new(11 * 16 + 3, 35 * 16 + 7),
            ],
            [[4095, 0, 0], [0, 4095, 0], [0, 0, 4095]],
        )));
        s.primitives.push(Primitive::Line(Line::new(
            SubPoint::new(-40, 600),
            SubPoint::new(700, 3),
            [[4095; 3], [0; 3]],
        )));
        s
    }

    #[test]
    fn band_height_does_not_change_a_bit() {
        let s = star_scene();
        let reference = render(&s.with_band_rows(37)).unwrap();
        for rows in [1, 3, 8, 16, 100] {
            assert_eq!(
                render(&s.with_band_rows(rows)).unwrap(),
                reference,
                "rows {rows}"
            );
        }
    }

    #[test]
    fn rejected_primitive_is_reported_with_its_index() {
        let mut s = star_scene();
        // A bow tie with unequal lobes (a symmetric one has zero signed
        // area and is silently skipped by core as "zero area").
        s.primitives.push(Primitive::flat_polygon(
            vec![
                SubPoint::from_px(0, 0),
                SubPoint::from_px(10, 10),
                SubPoint::from_px(10, 0),
                SubPoint::from_px(0, 20),
            ],
            [1; 3],
        ));
        let Err(err) = render(&s) else {
            panic!("a self-intersecting polygon was drawn");
        };
        assert_eq!(
            err,
            RenderError::Draw {
                index: 2,
                error: DrawError::SelfIntersecting
            }
        );
        assert!(err.to_string().contains("#2"));
    }

    /// With hidden-surface removal a vertex out of range is reported with
    /// its own primitive, by every method.
    #[test]
    fn out_of_range_vertex_is_reported_with_its_index_by_every_method() {
        let mut s = star_scene();
        let far = SubPoint::new(40_000, 0);
        s.primitives.push(Primitive::Depth(DepthTriangle::new(
            [SubPoint::from_px(1, 1), far, SubPoint::from_px(1, 9)],
            [[9; 3]; 3],
            [5; 3],
        )));
        for hsr in [Hsr::ZBuffer, Hsr::Warnock, Hsr::WeilerAtherton] {
            let Err(err) = render(&Scene { hsr, ..s.clone() }) else {
                panic!("{hsr:?}: a vertex out of range was drawn");
            };
            assert!(
                matches!(
                    err,
                    RenderError::Draw {
                        index: 2,
                        error: DrawError::Coord(_)
                    }
                ),
                "{hsr:?}: {err:?}"
            );
        }
    }

    /// Light, thin, colourful shapes: most pixels have `L*` where table
    /// 4.1 gives `k > 0`.
    fn pale_scene() -> Scene<3> {
        let mut s = Scene::new(33, 23, [2600, 2500, 2300]);
        s.primitives.push(Primitive::Triangle(Triangle::new(
            [
                SubPoint::new(2 * 16 + 3, 16 + 9),
                SubPoint::new(31 * 16 + 7, 6 * 16 + 2),
                SubPoint::new(9 * 16 + 11, 21 * 16 + 5),
            ],
            [[4095, 3600, 900], [900, 3900, 3900], [3800, 1500, 3800]],
        )));
        s.primitives.push(Primitive::Line(Line::new(
            SubPoint::new(-30, 22 * 16),
            SubPoint::new(34 * 16, 16 + 3),
            [[4095, 1200, 1200], [1200, 4095, 1200]],
        )));
        s
    }

    #[test]
    fn lightness_filter_bands_equal_the_full_frame_filter() {
        let s = pale_scene();
        let plain = render(&s).unwrap();
        let (w, h) = (s.width, s.height);
        let input: Vec<[u16; 3]> = plain.pixels().collect();
        let mut want = vec![[0u16; 3]; input.len()];
        let mut scratch = vec![0u16; LightnessFilter::scratch_len(w)];
        let want_stats = LightnessFilter::new(w, h)
            .unwrap()
            .filter_frame(&input, &mut want, &mut scratch)
            .unwrap();
        assert!(want_stats.changed > 50, "{want_stats:?}");
        for rows in [1, 2, 7, 16, 22, 23, 100] {
            let (img, stats) = render_lightness_filtered(&s.with_band_rows(rows)).unwrap();
            let got: Vec<[u16; 3]> = img.pixels().collect();
            assert!(got == want, "band rows {rows}");
            assert_eq!(stats, want_stats, "band rows {rows}");
        }
        assert_ne!(plain.pixels().collect::<Vec<_>>(), want);
    }

    #[test]
    fn lightness_filter_on_one_row_and_one_column_frames() {
        for (w, h) in [(1, 1), (1, 9), (9, 1)] {
            let mut s = Scene::<1>::new(w, h, [2400]);
            s.primitives.push(Primitive::Line(Line::new(
                SubPoint::new(0, 8),
                SubPoint::new(i32::from(w) * 16, i32::from(h) * 16 - 8),
                [[4095], [4095]],
            )));
            let (a, _) = render_lightness_filtered(&s.with_band_rows(1)).unwrap();
            let (b, _) = render_lightness_filtered(&s.with_band_rows(h)).unwrap();
            assert_eq!(a, b, "{w}x{h}");
        }
    }

    #[test]
    fn empty_frame_is_background() {
        let img = render(&Scene::<1>::new(5, 3, [77])).unwrap();
        assert!(img.pixels().all(|p| p == [77]));
    }
}
