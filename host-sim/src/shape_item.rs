//! Shapes, strokes and meshes in a host scene (scene files' `[[circle]]`,
//! `[[ellipse]]`, `[[arc]]`, `[[sector]]`, `[[rect]]`, `[[polyline]]`,
//! `[[path]]` and `[[mesh]]`), owned, and drawn into a band through the
//! canvas (`softedge::canvas`): each one shape in its compositing.
//!
//! Also the scene's older primitives (triangles, polygons, lines) drawn
//! through the canvas, for painter's order and opacity ([`triangle`],
//! [`polygon`], [`line`]).

use softedge::canvas::{Canvas, Contour, MeshColors};
use softedge::geom::FinePoint;
use softedge::path::{
    self, svg::SvgPath, Dash, LineCap, LineJoin, MiterLimit, StrokeAlignment, StrokeStyle,
};
use softedge::style::{Blend, FillRule, Gradient, Opacity};
use softedge::{DrawError, Line, Polygon, PolygonColors, SubPoint, Triangle};

/// The outline of a [`ShapeItem`], owned.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Geometry {
    /// A circle.
    Circle(path::Circle),
    /// An ellipse, rotated or not.
    Ellipse(path::Ellipse),
    /// An arc (its fill is the region between the arc and its chord).
    Arc(path::Arc),
    /// A sector (pie).
    Sector(path::Sector),
    /// A rectangle.
    Rect(path::Rectangle),
    /// A rounded rectangle.
    RoundedRect(path::RoundedRectangle),
    /// An open polyline (its fill is the polygon it closes).
    Polyline(Vec<FinePoint>),
    /// SVG path data, checked to parse when the item was made.
    Path(String),
}

/// Runs `$body` with `$s` bound to the geometry as a `path::Shape`.
macro_rules! with_shape {
    ($geometry:expr, $s:ident => $body:expr) => {
        match $geometry {
            Geometry::Circle($s) => $body,
            Geometry::Ellipse($s) => $body,
            Geometry::Arc($s) => $body,
            Geometry::Sector($s) => $body,
            Geometry::Rect($s) => $body,
            Geometry::RoundedRect($s) => $body,
            Geometry::Polyline(v) => {
                let $s = &path::Polyline::new(v);
                $body
            }
            Geometry::Path(d) => match SvgPath::new(d) {
                Ok(p) => {
                    let $s = &p;
                    $body
                }
                Err(_) => Ok(()),
            },
        }
    };
}

/// A stroke: width and style in fine units, dash pattern owned.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Stroke<const C: usize> {
    /// Linear colour.
    pub color: [u16; C],
    /// Width, 1/1024 px.
    pub width: u32,
    /// Joins.
    pub join: LineJoin,
    /// Miter limit.
    pub miter_limit: MiterLimit,
    /// Caps.
    pub cap: LineCap,
    /// Dash intervals, 1/1024 px (empty: solid).
    pub dash: Vec<u32>,
    /// Dash offset, 1/1024 px.
    pub dash_offset: i32,
    /// Which side of a closed outline.
    pub alignment: StrokeAlignment,
}

impl<const C: usize> Stroke<C> {
    /// A solid centred stroke of `width` fine units, miter joins, butt caps.
    pub fn new(color: [u16; C], width: u32) -> Self {
        Self {
            color,
            width,
            join: LineJoin::Miter,
            miter_limit: MiterLimit::DEFAULT,
            cap: LineCap::Butt,
            dash: Vec::new(),
            dash_offset: 0,
            alignment: StrokeAlignment::Centre,
        }
    }

    fn style(&self) -> StrokeStyle<'_> {
        let s = StrokeStyle::new(self.width)
            .with_join(self.join)
            .with_miter_limit(self.miter_limit)
            .with_cap(self.cap)
            .with_alignment(self.alignment);
        if self.dash.is_empty() {
            s
        } else {
            s.with_dash(Dash::new(&self.dash, self.dash_offset))
        }
    }
}

/// One shape of a scene: its outline, fill and stroke.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShapeItem<const C: usize> {
    /// The outline.
    pub geometry: Geometry,
    /// The fill's linear colour, if filled with one.
    pub fill: Option<[u16; C]>,
    /// The fill's gradient, if filled with one.
    pub gradient: Option<Gradient<C>>,
    /// The fill rule.
    pub rule: FillRule,
    /// The stroke, if stroked (drawn after the fill).
    pub stroke: Option<Stroke<C>>,
    /// Opacity of fill and stroke.
    pub opacity: Opacity,
}

impl<const C: usize> ShapeItem<C> {
    /// Draws the fill, then the stroke; the first error is returned
    /// (both are tried).
    pub fn draw<Col>(
        &self,
        canvas: &mut Canvas<'_, '_, C, Col>,
        blend: Blend,
    ) -> Result<(), DrawError> {
        let op = self.opacity;
        let fill = match (self.fill, &self.gradient) {
            (Some(c), _) => {
                with_shape!(&self.geometry, s => canvas.fill_shape(s, c, self.rule, blend, op))
            }
            (None, Some(g)) => with_shape!(&self.geometry, s => {
                canvas.fill_shape_gradient(s, g, self.rule, blend, op)
            }),
            (None, None) => Ok(()),
        };
        let stroke = match &self.stroke {
            Some(st) if st.width > 0 => {
                let style = st.style();
                with_shape!(&self.geometry, s => canvas.stroke_shape(s, &style, st.color, blend, op))
            }
            _ => Ok(()),
        };
        fill.and(stroke)
    }
}

/// A mesh of triangles over shared points (scene files' `[[mesh]]`): one
/// shape, its shared edges seamless in painter's order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MeshItem<const C: usize> {
    /// The points, 1/16 px.
    pub points: Vec<SubPoint>,
    /// Index triples into `points`.
    pub triangles: Vec<[u16; 3]>,
    /// One colour, or one per point.
    pub colors: crate::scene::PolyColors<C>,
    /// Opacity of the whole mesh.
    pub opacity: Opacity,
}

impl<const C: usize> MeshItem<C> {
    /// Draws the mesh as one shape.
    pub fn draw<Col>(
        &self,
        canvas: &mut Canvas<'_, '_, C, Col>,
        blend: Blend,
    ) -> Result<(), DrawError> {
        let pts: Vec<FinePoint> = self.points.iter().map(|&p| p.into()).collect();
        let colors = match &self.colors {
            crate::scene::PolyColors::Flat(c) => MeshColors::Flat(*c),
            crate::scene::PolyColors::PerVertex(cs) => MeshColors::PerPoint(cs),
        };
        canvas.fill_mesh(&pts, &self.triangles, colors, blend, self.opacity)
    }

    /// The mesh's triangles, for seed 000's accumulation one by one.
    pub fn triangles(&self) -> impl Iterator<Item = Triangle<C>> + '_ {
        self.triangles.iter().filter_map(|t| {
            let p = |k: u16| self.points.get(usize::from(k)).copied();
            let c = |k: u16| match &self.colors {
                crate::scene::PolyColors::Flat(c) => Some(*c),
                crate::scene::PolyColors::PerVertex(cs) => cs.get(usize::from(k)).copied(),
            };
            Some(Triangle::new(
                [p(t[0])?, p(t[1])?, p(t[2])?],
                [c(t[0])?, c(t[1])?, c(t[2])?],
            ))
        })
    }
}

/// A triangle through the canvas.
pub fn triangle<const C: usize, Col>(
    canvas: &mut Canvas<'_, '_, C, Col>,
    t: &Triangle<C>,
    blend: Blend,
    opacity: Opacity,
) -> Result<(), DrawError> {
    canvas.fill_triangle(t.vertices.map(FinePoint::from), t.colors, blend, opacity)
}

/// A polygon through the canvas: a flat one as its outline (nonzero), a
/// Gouraud one as the mesh of its triangulation (one shape).
pub fn polygon<const C: usize, Col>(
    canvas: &mut Canvas<'_, '_, C, Col>,
    p: &Polygon<'_, C>,
    blend: Blend,
    opacity: Opacity,
) -> Result<(), DrawError> {
    if let PolygonColors::Flat(c) = p.colors {
        // Checked as the seed-000 polygon is (simple, at most 64 vertices).
        let zeros = vec![0u16; p.vertices.len()];
        p.depth_triangles(&zeros, |_| {})?;
        let pts: Vec<FinePoint> = p.vertices.iter().map(|&v| v.into()).collect();
        return canvas.fill(&Contour(&pts), c, FillRule::NonZero, blend, opacity);
    }
    let zeros = vec![0u16; p.vertices.len()];
    let (mut pts, mut colors, mut tris) = (Vec::new(), Vec::new(), Vec::new());
    p.depth_triangles(&zeros, |t| {
        let k = pts.len() as u16;
        for (v, c) in t.vertices.iter().zip(t.colors) {
            pts.push(FinePoint::from(*v));
            colors.push(c);
        }
        tris.push([k, k + 1, k + 2]);
    })?;
    canvas.fill_mesh(&pts, &tris, MeshColors::PerPoint(&colors), blend, opacity)
}

/// A seed-000 line through the canvas: one colour, the 1-px stroke with
/// butt ends it stands for (exact on the fine grid); two colours, the
/// Gouraud mesh of its rectangle (corners on the 1/16-px grid).
pub fn line<const C: usize, Col>(
    canvas: &mut Canvas<'_, '_, C, Col>,
    l: &Line<C>,
    blend: Blend,
    opacity: Opacity,
) -> Result<(), DrawError> {
    let [c0, c1] = l.colors;
    if c0 == c1 {
        let shape = path::Line::new(l.from.into(), l.to.into());
        let style = StrokeStyle::new(softedge::geom::FINE_ONE as u32);
        return canvas.stroke_shape(&shape, &style, c0, blend, opacity);
    }
    let (mut pts, mut colors, mut tris) = (Vec::new(), Vec::new(), Vec::new());
    l.depth_triangles([0; 2], |t| {
        let k = pts.len() as u16;
        for (v, c) in t.vertices.iter().zip(t.colors) {
            pts.push(FinePoint::from(*v));
            colors.push(c);
        }
        tris.push([k, k + 1, k + 2]);
    })?;
    canvas.fill_mesh(&pts, &tris, MeshColors::PerPoint(&colors), blend, opacity)
}
