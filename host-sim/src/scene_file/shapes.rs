//! Shapes, strokes and meshes in scene files: `[[circle]]`, `[[ellipse]]`,
//! `[[arc]]`, `[[sector]]`, `[[rect]]`, `[[polyline]]`, `[[path]]` and
//! `[[mesh]]`, checked and turned into the scene's
//! [`ShapeItem`]s and [`MeshItem`]s.
//!
//! Lengths are pixels, rounded to the engine's 1/1024-px grid (curves are
//! approximations anyway: no warning); mesh points, like the other
//! polygons', to 1/16 px with a warning when they are off it. Angles are
//! degrees, clockwise on screen from +x (embedded-graphics' convention):
//! any finite start, a sweep within ±360. Paint and stroke keys, shared by
//! every shape (SVG's names where SVG has them):
//!
//! | key | meaning | default |
//! | --- | --- | --- |
//! | `color` | the fill's colour | no fill |
//! | `gradient` | the fill's gradient instead: `{ kind = "linear", from = [x, y], to = [x, y], stops = [...] }` or `{ kind = "radial", centre = [x, y], radius = r, stops = [...] }`, each stop `{ offset = 0..1, color = ... }` (at most 8), interpolated in linear light | none |
//! | `fill_rule` | `"nonzero"` or `"evenodd"` | `"nonzero"` |
//! | `stroke_color` | the stroke's colour | no stroke |
//! | `stroke_width` | px, down to hairlines | 1 |
//! | `join` | `"miter"`, `"round"`, `"bevel"` | `"miter"` |
//! | `miter_limit` | ratio, at least 1 | 4 |
//! | `cap` | `"butt"`, `"round"`, `"square"` | `"butt"` |
//! | `dash` | px, on and off lengths | solid |
//! | `dash_offset` | px | 0 |
//! | `stroke_alignment` | `"inside"`, `"centre"`, `"outside"` (closed shapes) | `"centre"` |
//! | `opacity` | `0..=1`, of fill and stroke | 1 |

use softedge::fixed::types::I16F16;
use softedge::geom::FinePoint;
use softedge::path::{
    self, svg::SvgPath, CornerRadii, Degrees, LineCap, LineJoin, MiterLimit, StrokeAlignment,
    MAX_DASH_INTERVALS,
};
use softedge::style::{FillRule, Gradient, Offset, Opacity, Stop, MAX_STOPS};
use softedge::COORD_LIMIT_PX;
use toml::Spanned;

use super::{raw, Checked, Checker, Origin};
use crate::scene::{PolyColors, Primitive};
use crate::shape_item::{Geometry, MeshItem, ShapeItem, Stroke};

/// Longest side of a shape, px (the coordinate range's width).
const MAX_SIZE: f64 = 2.0 * COORD_LIMIT_PX as f64;
/// Widest stroke, px.
const MAX_STROKE_PX: f64 = 512.0;
/// Largest angle written, degrees.
const MAX_DEGREES: f64 = 1e6;
/// Most triangles of one mesh.
pub(super) const MAX_MESH_TRIANGLES: usize = 65_536;

/// Pixels to fine units (range checked by the caller).
fn fine(v: f64) -> i32 {
    (v * 1024.0).round() as i32
}

impl Checker<'_> {
    /// A point in pixels to the fine grid.
    fn fine_point(&self, v: &raw::Nums, field: &str) -> Checked<FinePoint> {
        let lim = f64::from(COORD_LIMIT_PX);
        let [x, y] = self.nums::<2>(v, field, -lim, lim)?;
        Ok(FinePoint::new(fine(x), fine(y)))
    }

    /// A length in pixels, `0..=max`, to fine units.
    fn length(&self, v: &raw::Num, field: &str, max: f64) -> Checked<u32> {
        Ok(fine(self.num(v, field, 0.0, max)?) as u32)
    }

    /// Degrees (`start`: any finite angle, taken modulo a turn; `sweep`:
    /// within ±360).
    fn degrees(&self, v: &raw::Num, field: &str, sweep: bool) -> Checked<Degrees> {
        let lim = if sweep { 360.0 } else { MAX_DEGREES };
        let d = self.num(v, field, -lim, lim)?;
        let d = if sweep { d } else { d.rem_euclid(360.0) };
        Ok(Degrees::from_fixed(I16F16::from_num(d)))
    }

    pub(super) fn opacity(&self, v: Option<&raw::Num>, field: &str) -> Checked<Opacity> {
        match v {
            None => Ok(Opacity::OPAQUE),
            Some(v) => {
                let a = self.num(v, field, 0.0, 1.0)?;
                Ok(Opacity::from_4096ths((a * 4096.0).round() as u16))
            }
        }
    }

    fn choice<T: Copy>(
        &self,
        v: Option<&Spanned<String>>,
        field: &str,
        options: &[(&str, T)],
        default: T,
    ) -> Checked<T> {
        let Some(v) = v else {
            return Ok(default);
        };
        match options.iter().find(|(name, _)| name == v.get_ref()) {
            Some((_, t)) => Ok(*t),
            None => {
                let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
                self.err(
                    v.span(),
                    field,
                    format!(
                        "unknown value `{}`; one of {}",
                        v.get_ref(),
                        names.join(", ")
                    ),
                )
            }
        }
    }

    /// The paint keys of a shape: fill, stroke, rule, opacity.
    fn paint<const C: usize>(
        &self,
        p: raw::Paint<'_>,
        field: &str,
        span: std::ops::Range<usize>,
        geometry: Geometry,
    ) -> Checked<ShapeItem<C>> {
        let fill = match p.color {
            Some(c) => Some(self.color::<C>(c, &format!("{field}.color"))?),
            None => None,
        };
        let gradient = match (p.gradient, fill) {
            (Some(g), Some(_)) => {
                return self.err(
                    g.span(),
                    &format!("{field}.gradient"),
                    "give either `color` or `gradient` for the fill, not both",
                )
            }
            (Some(g), None) => Some(self.gradient::<C>(g, &format!("{field}.gradient"))?),
            (None, _) => None,
        };
        let rule = self.choice(
            p.fill_rule,
            &format!("{field}.fill_rule"),
            &[
                ("nonzero", FillRule::NonZero),
                ("evenodd", FillRule::EvenOdd),
            ],
            FillRule::NonZero,
        )?;
        let stroke = match p.stroke_color {
            None => {
                if let Some(w) = p.stroke_width {
                    return self.err(
                        w.span(),
                        &format!("{field}.stroke_width"),
                        "a stroke width without `stroke_color`",
                    );
                }
                None
            }
            Some(c) => {
                let color = self.color::<C>(c, &format!("{field}.stroke_color"))?;
                let width = match p.stroke_width {
                    Some(w) => self.length(w, &format!("{field}.stroke_width"), MAX_STROKE_PX)?,
                    None => 1024,
                };
                let mut s = Stroke::new(color, width);
                s.join = self.choice(
                    p.join,
                    &format!("{field}.join"),
                    &[
                        ("miter", LineJoin::Miter),
                        ("round", LineJoin::Round),
                        ("bevel", LineJoin::Bevel),
                    ],
                    LineJoin::Miter,
                )?;
                s.cap = self.choice(
                    p.cap,
                    &format!("{field}.cap"),
                    &[
                        ("butt", LineCap::Butt),
                        ("round", LineCap::Round),
                        ("square", LineCap::Square),
                    ],
                    LineCap::Butt,
                )?;
                s.alignment = self.choice(
                    p.stroke_alignment,
                    &format!("{field}.stroke_alignment"),
                    &[
                        ("inside", StrokeAlignment::Inside),
                        ("centre", StrokeAlignment::Centre),
                        ("center", StrokeAlignment::Centre),
                        ("outside", StrokeAlignment::Outside),
                    ],
                    StrokeAlignment::Centre,
                )?;
                if let Some(m) = p.miter_limit {
                    let m = self.num(m, &format!("{field}.miter_limit"), 1.0, 1000.0)?;
                    s.miter_limit = MiterLimit::from_q16((m * 65536.0).round() as u32);
                }
                if let Some(d) = p.dash {
                    let list = d.get_ref();
                    if list.len() > MAX_DASH_INTERVALS as usize {
                        return self.err(
                            d.span(),
                            &format!("{field}.dash"),
                            format!("at most {MAX_DASH_INTERVALS} lengths"),
                        );
                    }
                    s.dash = list
                        .iter()
                        .enumerate()
                        .map(|(k, v)| self.length(v, &format!("{field}.dash[{k}]"), MAX_SIZE))
                        .collect::<Checked<_>>()?;
                }
                if let Some(o) = p.dash_offset {
                    s.dash_offset =
                        fine(self.num(o, &format!("{field}.dash_offset"), -MAX_SIZE, MAX_SIZE)?);
                }
                Some(s)
            }
        };
        if fill.is_none() && gradient.is_none() && stroke.is_none() {
            return self.err(
                span,
                field,
                "draws nothing: give `color` or `gradient` (the fill), `stroke_color`, or both",
            );
        }
        Ok(ShapeItem {
            geometry,
            fill,
            gradient,
            rule,
            stroke,
            opacity: self.opacity(p.opacity, &format!("{field}.opacity"))?,
        })
    }

    /// `gradient = { kind, from, to | centre, radius, stops }`: stops'
    /// offsets in `0..=1`, never decreasing, their colours as everywhere.
    fn gradient<const C: usize>(
        &self,
        g: &Spanned<raw::Gradient>,
        field: &str,
    ) -> Checked<Gradient<C>> {
        let r = g.get_ref();
        let list = r.stops.get_ref();
        if list.is_empty() || list.len() > MAX_STOPS {
            return self.err(
                r.stops.span(),
                &format!("{field}.stops"),
                format!("a gradient has 1..={MAX_STOPS} stops, not {}", list.len()),
            );
        }
        let mut stops = Vec::with_capacity(list.len());
        for (k, st) in list.iter().enumerate() {
            let f = format!("{field}.stops[{k}]");
            let o = self.num(&st.get_ref().offset, &format!("{f}.offset"), 0.0, 1.0)?;
            let c = self.color::<C>(&st.get_ref().color, &format!("{f}.color"))?;
            stops.push(Stop::lin(
                Offset::from_4096ths((o * 4096.0).round() as u16),
                c,
            ));
        }
        let need = |v: Option<&raw::Nums>, key: &str| match v {
            Some(v) => self.fine_point(v, &format!("{field}.{key}")),
            None => self.err(
                g.span(),
                field,
                format!("this kind of gradient needs `{key}`"),
            ),
        };
        let made = match r.kind.get_ref().as_str() {
            "linear" => Gradient::linear(
                need(r.from.as_ref(), "from")?,
                need(r.to.as_ref(), "to")?,
                &stops,
            ),
            "radial" => {
                let centre = need(r.centre.as_ref(), "centre")?;
                let radius = match &r.radius {
                    Some(v) => self.length(v, &format!("{field}.radius"), MAX_SIZE)?,
                    None => return self.err(g.span(), field, "a radial gradient needs `radius`"),
                };
                Gradient::radial(centre, radius as i32, &stops)
            }
            other => {
                return self.err(
                    r.kind.span(),
                    &format!("{field}.kind"),
                    format!("unknown gradient `{other}`; one of linear, radial"),
                )
            }
        };
        made.or_else(|e| self.err(r.stops.span(), &format!("{field}.stops"), e.to_string()))
    }

    /// A circle's or an arc's centre and radius.
    fn round(
        &self,
        centre: &raw::Nums,
        radius: &raw::Num,
        field: &str,
    ) -> Checked<(FinePoint, u32)> {
        Ok((
            self.fine_point(centre, &format!("{field}.centre"))?,
            self.length(radius, &format!("{field}.radius"), MAX_SIZE)?,
        ))
    }

    /// `[rect] radius`: one radius, or four (top left, top right, bottom
    /// right, bottom left).
    fn corner_radii(&self, r: Option<&raw::Radius>, field: &str) -> Checked<Option<CornerRadii>> {
        let Some(r) = r else {
            return Ok(None);
        };
        let f = format!("{field}.radius");
        Ok(Some(match r.get_ref() {
            raw::RadiusValue::One(v) => {
                let v = fine(self.num(&Spanned::new(r.span(), *v), &f, 0.0, MAX_SIZE)?) as u32;
                CornerRadii::uniform(v)
            }
            raw::RadiusValue::Four(list) => {
                if list.len() != 4 {
                    return self.err(
                        r.span(),
                        &f,
                        format!("one radius, or four (top left, top right, bottom right, bottom left), not {}", list.len()),
                    );
                }
                let mut v = [0u32; 4];
                for (k, (o, x)) in v.iter_mut().zip(list).enumerate() {
                    *o = self.length(x, &format!("{f}[{k}]"), MAX_SIZE)?;
                }
                CornerRadii {
                    top_left: (v[0], v[0]),
                    top_right: (v[1], v[1]),
                    bottom_right: (v[2], v[2]),
                    bottom_left: (v[3], v[3]),
                }
            }
        }))
    }
}

/// One table entry: its field name, span and primitive.
type Item<const C: usize> = (Origin, Vec<Primitive<C>>);

fn item<const C: usize>(field: String, span: std::ops::Range<usize>, p: Primitive<C>) -> Item<C> {
    (Origin { field, span }, vec![p])
}

/// Every shape and mesh of the file, each at its table's place.
pub(super) fn shapes<const C: usize>(
    ck: &mut Checker<'_>,
    file: &raw::File,
) -> Checked<Vec<Item<C>>> {
    let mut out = Vec::new();
    let shape = |ck: &Checker<'_>,
                 p: raw::Paint<'_>,
                 field: String,
                 span: std::ops::Range<usize>,
                 g: Geometry|
     -> Checked<Item<C>> {
        let s = ck.paint::<C>(p, &field, span.clone(), g)?;
        Ok(item(field, span, Primitive::Shape(Box::new(s))))
    };
    for (k, t) in file.circle.iter().enumerate() {
        let (field, c) = (format!("circle[{k}]"), t.get_ref());
        let (centre, r) = ck.round(&c.centre, &c.radius, &field)?;
        let g = Geometry::Circle(path::Circle::new(centre, r));
        out.push(shape(ck, c.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.ellipse.iter().enumerate() {
        let (field, e) = (format!("ellipse[{k}]"), t.get_ref());
        let centre = ck.fine_point(&e.centre, &format!("{field}.centre"))?;
        let [rx, ry] = ck.nums::<2>(&e.radii, &format!("{field}.radii"), 0.0, MAX_SIZE)?;
        let rot = match &e.rotation {
            Some(r) => ck.degrees(r, &format!("{field}.rotation"), false)?,
            None => Degrees::ZERO,
        };
        let g = Geometry::Ellipse(
            path::Ellipse::new(centre, fine(rx) as u32, fine(ry) as u32).rotated(rot),
        );
        out.push(shape(ck, e.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.arc.iter().enumerate() {
        let (field, a) = (format!("arc[{k}]"), t.get_ref());
        let (centre, r) = ck.round(&a.centre, &a.radius, &field)?;
        let start = ck.degrees(&a.start, &format!("{field}.start"), false)?;
        let sweep = ck.degrees(&a.sweep, &format!("{field}.sweep"), true)?;
        let g = Geometry::Arc(path::Arc::new(centre, r, start, sweep));
        out.push(shape(ck, a.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.sector.iter().enumerate() {
        let (field, a) = (format!("sector[{k}]"), t.get_ref());
        let (centre, r) = ck.round(&a.centre, &a.radius, &field)?;
        let start = ck.degrees(&a.start, &format!("{field}.start"), false)?;
        let sweep = ck.degrees(&a.sweep, &format!("{field}.sweep"), true)?;
        let g = Geometry::Sector(path::Sector::new(centre, r, start, sweep));
        out.push(shape(ck, a.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.rect.iter().enumerate() {
        let (field, r) = (format!("rect[{k}]"), t.get_ref());
        let tl = ck.fine_point(&r.position, &format!("{field}.position"))?;
        let [w, h] = ck.nums::<2>(&r.size, &format!("{field}.size"), 0.0, MAX_SIZE)?;
        let rect = path::Rectangle::new(tl, fine(w) as u32, fine(h) as u32);
        let g = match ck.corner_radii(r.radius.as_ref(), &field)? {
            None => Geometry::Rect(rect),
            Some(radii) => Geometry::RoundedRect(path::RoundedRectangle::new(rect, radii)),
        };
        out.push(shape(ck, r.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.polyline.iter().enumerate() {
        let (field, p) = (format!("polyline[{k}]"), t.get_ref());
        let pts = p
            .points
            .get_ref()
            .iter()
            .enumerate()
            .map(|(j, v)| ck.fine_point(v, &format!("{field}.points[{j}]")))
            .collect::<Checked<Vec<_>>>()?;
        if pts.len() < 2 {
            return ck.err(
                p.points.span(),
                &format!("{field}.points"),
                format!("a polyline has at least 2 points, not {}", pts.len()),
            );
        }
        out.push(shape(
            ck,
            p.paint(),
            field,
            t.span(),
            Geometry::Polyline(pts),
        )?);
    }
    for (k, t) in file.path.iter().enumerate() {
        let (field, p) = (format!("path[{k}]"), t.get_ref());
        if let Err(e) = SvgPath::new(p.d.get_ref()) {
            return ck.err(p.d.span(), &format!("{field}.d"), e.to_string());
        }
        let g = Geometry::Path(p.d.get_ref().clone());
        out.push(shape(ck, p.paint(), field, t.span(), g)?);
    }
    for (k, t) in file.mesh.iter().enumerate() {
        let (field, m) = (format!("mesh[{k}]"), t.get_ref());
        let points = ck.points(&m.points, &format!("{field}.points"))?;
        let tris = m.triangles.get_ref();
        if tris.len() > MAX_MESH_TRIANGLES {
            return ck.err(
                m.triangles.span(),
                &format!("{field}.triangles"),
                format!("at most {MAX_MESH_TRIANGLES} triangles, not {}", tris.len()),
            );
        }
        let mut triangles = Vec::with_capacity(tris.len());
        for (j, tri) in tris.iter().enumerate() {
            let f = format!("{field}.triangles[{j}]");
            let [a, b, c] = &tri.get_ref()[..] else {
                return ck.err(
                    tri.span(),
                    &f,
                    format!("a triangle is 3 point indices, not {}", tri.get_ref().len()),
                );
            };
            if points.is_empty() {
                return ck.err(
                    m.points.span(),
                    &format!("{field}.points"),
                    "a mesh with triangles needs points",
                );
            }
            let top = (points.len() as i64 - 1).min(i64::from(u16::MAX));
            let mut idx = [0u16; 3];
            for (o, i) in idx.iter_mut().zip([a, b, c]) {
                *o = ck.int(i, &f, 0, top)? as u16;
            }
            triangles.push(idx);
        }
        let colors = ck.vertex_colors::<C>(
            m.colors.as_ref(),
            m.color.as_ref(),
            points.len(),
            &field,
            t.span(),
        )?;
        let mesh = MeshItem {
            points,
            triangles,
            colors: match colors {
                PolyColors::Flat(c) => PolyColors::Flat(c),
                PolyColors::PerVertex(cs) => PolyColors::PerVertex(cs),
            },
            opacity: ck.opacity(m.opacity.as_ref(), &format!("{field}.opacity"))?,
        };
        out.push(item(field, t.span(), Primitive::Mesh(Box::new(mesh))));
    }
    Ok(out)
}
