//! The canonical objects of `softedge::scene3d`, lit and anti-aliased, at
//! two levels of detail, and one composite object.
//!
//! Each object is triangulated by [`Shape::write`], placed, lit (ambient
//! plus Lambert from one directional light) and projected by
//! [`project`]; the screen triangles are drawn band by band like any other
//! scene. There is no hidden-surface removal yet, only back-face culling,
//! which is exact for one convex object seen from anywhere: every pixel is
//! covered by one front face at most. The views are chosen so that this
//! holds for the other objects too, and [`overlap`] checks it by drawing
//! the object flat at a quarter of white, where any pixel above a quarter
//! is covered twice:
//!
//! - sphere, cone, cylinder, box: convex, seen obliquely from above;
//! - torus: not convex; seen obliquely, the near half of the tube would
//!   cover front faces of the far inner wall and their light would add.
//!   It is seen along its axis (orthographic), where each line of sight
//!   meets the tube's near surface once;
//! - composite (a cylinder, a cone on top, a torus around its foot): seen
//!   from above along the common axis; the cylinder's top cap, an internal
//!   face of the composite hidden under the cone, is left out of the mesh
//!   (it would add under the cone), and the torus's hole is wider than the
//!   cylinder, so cone, cylinder and ring never cover the same pixel.

use softedge::scene3d::{
    project, Angle, Camera, Light, Part, ProjectStats, SceneError, Shape, Transform, Vec3, Vertex,
    ViewVertex, I16F16,
};
use softedge::{Triangle, LIN_MAX};

use super::{lin, Primitive};
use crate::image::LinImage;
use crate::scene::{render, RenderError, Scene};

/// Panel size in pixels.
pub(super) const PANEL: u16 = 80;
/// Orthographic scale, pixels per world unit.
const PX_PER_UNIT: i32 = 28;

/// Why an object could not be drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum ObjectError {
    /// Meshing, transform or projection.
    Scene(SceneError),
    /// Drawing the projected triangles.
    Render(RenderError),
}

impl From<SceneError> for ObjectError {
    fn from(e: SceneError) -> Self {
        Self::Scene(e)
    }
}

impl From<RenderError> for ObjectError {
    fn from(e: RenderError) -> Self {
        Self::Render(e)
    }
}

/// One part: a shape, where it goes, its colour, and whether its top cap
/// (the triangles whose vertex normals all point straight up) is dropped
/// as an internal face of the composite.
#[derive(Debug, Clone, Copy)]
struct PartSpec {
    shape: Shape,
    transform: Transform,
    color: [u16; 3],
    drop_top_cap: bool,
}

/// How an object is viewed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ViewKind {
    /// From the front, right and above.
    Oblique,
    /// Along +z towards the origin (the torus's axis).
    AlongZ,
    /// From straight above, along -y.
    FromAbove,
}

/// A gallery object: its name and its parts at a level of detail.
pub(super) struct Object {
    /// Label.
    pub name: &'static str,
    /// Level of detail, as a label.
    pub lod: String,
    parts: Vec<PartSpec>,
    view: ViewKind,
}

fn num(v: f64) -> I16F16 {
    I16F16::from_num(v)
}

fn vec3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(num(x), num(y), num(z))
}

fn part(shape: Shape, color: [u16; 3]) -> PartSpec {
    PartSpec {
        shape,
        transform: Transform::IDENTITY,
        color,
        drop_top_cap: false,
    }
}

fn rgb(r: f64, g: f64, b: f64) -> [u16; 3] {
    [lin(r), lin(g), lin(b)]
}

/// The six objects at `segments` around their axes (`coarse` picks the
/// torus tube's and the box's matching detail).
pub(super) fn objects(segments: u16, coarse: bool) -> Result<Vec<Object>, SceneError> {
    let tube = if coarse { 6 } else { 12 };
    let box_div = if coarse { 1 } else { 4 };
    let single = |name, lod: String, shape, color, view| Object {
        name,
        lod,
        parts: vec![part(shape, color)],
        view,
    };
    let mut out = vec![
        single(
            "SPHERE",
            format!("{segments}"),
            Shape::Sphere {
                radius: num(1.2),
                segments,
            },
            rgb(0.85, 0.33, 0.07),
            ViewKind::Oblique,
        ),
        single(
            "TORUS",
            format!("{segments}X{tube}"),
            Shape::Torus {
                major: num(0.95),
                minor: num(0.42),
                segments,
                tube_segments: tube,
            },
            rgb(0.08, 0.6, 0.55),
            ViewKind::AlongZ,
        ),
        single(
            "CONE",
            format!("{segments}"),
            Shape::Cone {
                radius: num(1.0),
                height: num(1.9),
                segments,
            },
            rgb(0.9, 0.72, 0.1),
            ViewKind::Oblique,
        ),
        single(
            "CYLINDER",
            format!("{segments}"),
            Shape::Cylinder {
                radius: num(0.85),
                height: num(1.7),
                segments,
            },
            rgb(0.15, 0.3, 0.95),
            ViewKind::Oblique,
        ),
        single(
            "BOX",
            format!("{box_div}X{box_div}"),
            Shape::Box {
                size: vec3(1.3, 1.3, 1.3),
                segments: box_div,
            },
            rgb(0.8, 0.12, 0.3),
            ViewKind::Oblique,
        ),
    ];
    // Composite: cylinder, cone on top, torus (turned to lie around y)
    // around the foot, its hole wider than the cylinder.
    let (r, h) = (0.7, 0.9);
    let cylinder = PartSpec {
        drop_top_cap: true,
        ..part(
            Shape::Cylinder {
                radius: num(r),
                height: num(h),
                segments,
            },
            rgb(0.55, 0.6, 0.7),
        )
    };
    let cone_h = 1.1;
    let cone = PartSpec {
        transform: Transform::translation(vec3(0.0, h / 2.0 + cone_h / 2.0, 0.0))?,
        ..part(
            Shape::Cone {
                radius: num(r),
                height: num(cone_h),
                segments,
            },
            rgb(0.85, 0.1, 0.08),
        )
    };
    let (major, minor) = (1.05, 0.33);
    let ring = PartSpec {
        transform: Transform::rotation_x(Angle::from_degrees(90))
            .then(&Transform::translation(vec3(0.0, -h / 2.0 + minor, 0.0))?)?,
        ..part(
            Shape::Torus {
                major: num(major),
                minor: num(minor),
                segments,
                tube_segments: tube,
            },
            rgb(0.95, 0.65, 0.15),
        )
    };
    out.push(Object {
        name: "COMPOSITE",
        lod: format!("{segments}"),
        parts: vec![cylinder, cone, ring],
        view: ViewKind::FromAbove,
    });
    Ok(out)
}

/// Light from the upper left, in front: ambient 0.12, diffuse 0.88.
fn light() -> Light<3> {
    let ambient = (0.12 * 4096.0) as u16;
    Light::new(vec3(-2.0, 3.0, 4.0), [ambient; 3], [4096 - ambient; 3])
}

fn camera(view: ViewKind) -> Camera {
    let scale = I16F16::from_num(PX_PER_UNIT);
    match view {
        ViewKind::Oblique => {
            Camera::orthographic(vec3(4.0, 3.5, 6.0), Vec3::ZERO, vec3(0.0, 1.0, 0.0), scale)
        }
        ViewKind::AlongZ => {
            Camera::orthographic(vec3(0.0, 0.0, 8.0), Vec3::ZERO, vec3(0.0, 1.0, 0.0), scale)
        }
        // Looking down; "up" on screen is -z (the far side).
        ViewKind::FromAbove => {
            Camera::orthographic(vec3(0.0, 8.0, 0.0), Vec3::ZERO, vec3(0.0, 0.0, -1.0), scale)
        }
    }
}

/// A mesh in owned storage.
struct OwnedMesh {
    vertices: Vec<Vertex>,
    triangles: Vec<[u16; 3]>,
}

fn mesh(spec: &PartSpec) -> Result<OwnedMesh, SceneError> {
    let (nv, nt) = spec.shape.counts()?;
    let mut vertices = vec![Vertex::default(); nv];
    let mut triangles = vec![[0u16; 3]; nt];
    spec.shape.write(&mut vertices, &mut triangles)?;
    if spec.drop_top_cap {
        let up = |i: u16| {
            vertices
                .get(usize::from(i))
                .is_some_and(|v| v.normal == vec3(0.0, 1.0, 0.0))
        };
        triangles.retain(|t| !t.iter().all(|&i| up(i)));
    }
    Ok(OwnedMesh {
        vertices,
        triangles,
    })
}

/// The object's screen triangles: colours lit by `light`, or, with
/// `flat`, every part in the colour `flat`.
fn triangles(
    obj: &Object,
    flat: Option<u16>,
) -> Result<(Vec<Triangle<3>>, ProjectStats), SceneError> {
    let meshes = obj.parts.iter().map(mesh).collect::<Result<Vec<_>, _>>()?;
    let parts: Vec<Part<'_, 3>> = obj
        .parts
        .iter()
        .zip(&meshes)
        .map(|(spec, m)| Part {
            mesh: softedge::scene3d::MeshRef {
                vertices: &m.vertices,
                triangles: &m.triangles,
            },
            transform: spec.transform,
            color: flat.map_or(spec.color, |v| [v; 3]),
        })
        .collect();
    let view = camera(obj.view).view(PANEL, PANEL)?;
    let light = if flat.is_some() { Light::FLAT } else { light() };
    let needed: usize = meshes.iter().map(|m| m.vertices.len()).sum();
    let mut scratch = vec![ViewVertex::<3>::EMPTY; needed];
    let mut out = Vec::new();
    let stats = project(
        &parts,
        &Transform::IDENTITY,
        &view,
        &light,
        &mut scratch,
        |t| out.push(t.triangle()),
    )?;
    Ok((out, stats))
}

/// Panel background, linear.
pub(super) const BACKGROUND: [u16; 3] = [40, 42, 52];

/// The object lit, anti-aliased, on the dark background.
pub(super) fn render_object(obj: &Object) -> Result<(LinImage<3>, ProjectStats), ObjectError> {
    let (tris, stats) = triangles(obj, None)?;
    let mut scene = Scene::new(PANEL, PANEL, BACKGROUND);
    scene
        .primitives
        .extend(tris.into_iter().map(Primitive::Triangle));
    Ok((render(&scene)?, stats))
}

/// Pixels covered more than once (front faces overlapping), found by
/// drawing the object flat at a quarter of white on black: coverage
/// accumulates, so a pixel above a quarter (plus one step of rounding) is
/// covered by two front faces.
pub(super) fn overlap(obj: &Object) -> Result<usize, ObjectError> {
    let quarter = LIN_MAX.div_ceil(4);
    let (tris, _) = triangles(obj, Some(quarter))?;
    let mut scene = Scene::new(PANEL, PANEL, [0; 3]);
    scene
        .primitives
        .extend(tris.into_iter().map(Primitive::Triangle));
    let img = render(&scene)?;
    Ok(img.pixels().filter(|p| p[0] > quarter + 1).count())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chosen_views_need_no_hidden_surface_removal() {
        for (segments, coarse) in [(8, true), (24, false)] {
            for obj in objects(segments, coarse).unwrap() {
                assert_eq!(overlap(&obj).unwrap(), 0, "{} {segments}", obj.name);
            }
        }
    }

    #[test]
    fn a_tilted_torus_does_overlap() {
        // The check above can fail: seen obliquely, the torus covers some
        // pixels twice.
        let mut objs = objects(24, false).unwrap();
        let mut torus = objs.swap_remove(1);
        assert_eq!(torus.name, "TORUS");
        torus.view = ViewKind::Oblique;
        assert!(overlap(&torus).unwrap() > 0);
    }

    #[test]
    fn objects_are_lit_and_drawn() {
        for obj in objects(8, true).unwrap() {
            let (img, stats) = render_object(&obj).unwrap();
            assert!(stats.emitted > 0 && stats.back_facing > 0, "{}", obj.name);
            let bg = img.pixels().filter(|p| *p == BACKGROUND).count();
            assert!(bg > 0 && bg < img.pixels().count(), "{}", obj.name);
        }
    }

    #[test]
    fn composite_drops_only_the_cylinder_top_cap() {
        let objs = objects(8, true).unwrap();
        let comp = &objs[5];
        let full = comp.parts[0].shape.counts().unwrap().1;
        assert_eq!(mesh(&comp.parts[0]).unwrap().triangles.len(), full - 8);
        assert_eq!(
            mesh(&comp.parts[1]).unwrap().triangles.len(),
            comp.parts[1].shape.counts().unwrap().1
        );
    }
}
