//! `[camera]`, `[light]` and `[[object]]`: floats of the file to the fixed
//! point of `softedge::scene3d`, then projected (with back-face culling)
//! into screen triangles, once, on the host.
//!
//! Conversions: lengths and positions to Q16.16 (`I16F16`, nearest), angles
//! to binary angles (`2^16` per turn, nearest), light factors to Q12
//! (`4096 = 1`, nearest). An object is rotated about x, then y, then z,
//! then moved to its position.

use softedge::scene3d::{
    project_faces, Angle, Camera, Faces, Light, MeshRef, Part, Projection, SceneError, Shape,
    Transform, Vec3, Vertex, ViewVertex, I16F16, MAX_PX_PER_UNIT, MAX_SEGMENTS, WORLD_LIMIT,
};

use super::{raw, Checked, Checker, Origin};
use crate::scene::Primitive;

/// Degrees accepted for a rotation (any multiple of a turn).
const MAX_DEGREES: f64 = 1e6;

/// What went wrong in core, in words.
fn describe(e: SceneError) -> String {
    match e {
        SceneError::OutOfRange => format!(
            "out of range: positions and sizes must stay within ±{WORLD_LIMIT} units \
             (and a torus needs minor_radius < radius)"
        ),
        SceneError::NonPositive => "sizes and distances must be positive".into(),
        SceneError::Segments => {
            "too many or too few segments for this shape (at most 65536 vertices)".into()
        }
        SceneError::Capacity {
            vertices,
            triangles,
        } => format!("mesh storage too small ({vertices} vertices, {triangles} triangles)"),
        SceneError::Scratch { needed } => format!("scratch too small ({needed} vertices)"),
        SceneError::BadIndex => "a triangle refers to a missing vertex".into(),
        SceneError::EyeAtTarget => "the eye is at the target: no view direction".into(),
        SceneError::UpParallel => "`up` is zero or parallel to the view direction".into(),
        SceneError::FieldOfView => "fov_y must be between 0 and 180 degrees".into(),
        SceneError::ZeroDirection => "the light direction is zero".into(),
    }
}

fn vec3(v: [f64; 3]) -> Vec3 {
    // Checked against WORLD_LIMIT (< 2^15) before: from_num cannot overflow.
    Vec3::new(
        I16F16::from_num(v[0]),
        I16F16::from_num(v[1]),
        I16F16::from_num(v[2]),
    )
}

fn angle(deg: f64) -> Angle {
    let units = (deg / 360.0 * f64::from(Angle::TURN)).round() as i64;
    Angle(units.rem_euclid(i64::from(Angle::TURN)) as u16)
}

/// The objects as screen triangles, each list at its object's place.
pub(super) fn objects<const C: usize>(
    ck: &mut Checker<'_>,
    file: &raw::File,
    width: u16,
    height: u16,
    faces: Faces,
) -> Checked<Vec<(Origin, Vec<Primitive<C>>)>> {
    let mut out = Vec::new();
    if file.object.is_empty() {
        return Ok(out);
    }
    let Some(cam) = &file.camera else {
        let first = &file.object[0];
        return ck.err(
            first.span(),
            "object[0]",
            "objects need a [camera] table to be seen through",
        );
    };
    let world = f64::from(WORLD_LIMIT);
    let c = cam.get_ref();
    let eye = vec3(ck.nums::<3>(&c.eye, "camera.eye", -world, world)?);
    let target = match &c.target {
        Some(t) => vec3(ck.nums::<3>(t, "camera.target", -world, world)?),
        None => Vec3::ZERO,
    };
    let up = match &c.up {
        Some(u) => vec3(ck.nums::<3>(u, "camera.up", -world, world)?),
        None => Vec3::from_int(0, 1, 0),
    };
    let mut camera = match c.projection.get_ref().as_str() {
        "orthographic" => {
            let Some(s) = &c.scale else {
                return ck.err(
                    cam.span(),
                    "camera.scale",
                    "an orthographic camera needs `scale` (pixels per world unit)",
                );
            };
            let s = ck.num(s, "camera.scale", 0.0, f64::from(MAX_PX_PER_UNIT))?;
            Camera::orthographic(eye, target, up, I16F16::from_num(s))
        }
        "perspective" => {
            let Some(f) = &c.fov_y else {
                return ck.err(
                    cam.span(),
                    "camera.fov_y",
                    "a perspective camera needs `fov_y` (degrees)",
                );
            };
            let deg = ck.num(f, "camera.fov_y", 0.0, 180.0)?;
            Camera::perspective(eye, target, up, angle(deg))
        }
        other => {
            return ck.err(
                c.projection.span(),
                "camera.projection",
                format!("unknown projection `{other}`; orthographic or perspective"),
            )
        }
    };
    // Depth range: 16-bit depth spreads over near..far, so the default far
    // is just beyond the scene around the target (twice the eye's
    // distance), and a perspective camera's near plane is an eighth of that
    // distance (perspective depth goes as near / distance).
    let [ex, ey, ez] = ck.nums::<3>(&c.eye, "camera.eye", -world, world)?;
    let [tx, ty, tz] = match &c.target {
        Some(t) => ck.nums::<3>(t, "camera.target", -world, world)?,
        None => [0.0; 3],
    };
    let dist = ((ex - tx).powi(2) + (ey - ty).powi(2) + (ez - tz).powi(2)).sqrt();
    let far_max = Camera::FAR.to_num::<f64>();
    let min = Camera::NEAR.to_num::<f64>();
    let near = match &c.near {
        Some(n) => ck.num(n, "camera.near", min, far_max / 2.0)?,
        None if matches!(camera.projection, Projection::Orthographic { .. }) => min,
        None => (dist / 8.0).clamp(min, far_max / 2.0),
    };
    let far = match &c.far {
        Some(f) => ck.num(f, "camera.far", 0.0, far_max)?,
        None => (2.0 * dist).clamp(2.0 * near, far_max),
    };
    if far <= near {
        let at = c.far.as_ref().map_or(cam.span(), |f| f.span());
        return ck.err(
            at,
            "camera.far",
            format!("far ({far}) must lie beyond near ({near})"),
        );
    }
    camera.near = I16F16::from_num(near);
    camera.far = I16F16::from_num(far);
    let view = camera
        .view(width, height)
        .or_else(|e| ck.err(cam.span(), "camera", describe(e)))?;

    let light = match &file.light {
        None => Light::<C>::FLAT,
        Some(l) => {
            let lr = l.get_ref();
            let dir = vec3(ck.nums::<3>(&lr.direction, "light.direction", -world, world)?);
            let q12 = |v: f64| (v * 4096.0).round() as u16;
            let ambient = match &lr.ambient {
                Some(a) => ck.num(a, "light.ambient", 0.0, 1.0)?,
                None => 0.0,
            };
            let diffuse = match &lr.diffuse {
                Some(d) => ck.num(d, "light.diffuse", 0.0, 1.0)?,
                None => 1.0,
            };
            Light::new(dir, [q12(ambient); C], [q12(diffuse); C])
        }
    };

    // A zero direction is only found when the first face is lit; place
    // the error at the direction itself.
    let light_at = file.light.as_ref().map(|l| l.get_ref().direction.span());
    for (k, o) in file.object.iter().enumerate() {
        let field = format!("object[{k}]");
        if k == super::MAX_OBJECTS {
            return ck.err(
                o.span(),
                &field,
                format!(
                    "more than {} objects in one scene file ({} here)",
                    super::MAX_OBJECTS,
                    file.object.len()
                ),
            );
        }
        let or = o.get_ref();
        let shape = shape(ck, or, &field, o.span())?;
        let color = ck.color::<C>(&or.color, &format!("{field}.color"))?;
        let position = match &or.position {
            Some(p) => vec3(ck.nums::<3>(p, &format!("{field}.position"), -world, world)?),
            None => Vec3::ZERO,
        };
        let [rx, ry, rz] = match &or.rotation {
            Some(r) => ck.nums::<3>(r, &format!("{field}.rotation"), -MAX_DEGREES, MAX_DEGREES)?,
            None => [0.0; 3],
        };
        let transform = Transform::rotation_x(angle(rx))
            .then(&Transform::rotation_y(angle(ry)))
            .and_then(|t| t.then(&Transform::rotation_z(angle(rz))))
            .and_then(|t| Transform::translation(position).and_then(|p| t.then(&p)))
            .or_else(|e| ck.err(o.span(), &field, describe(e)))?;
        let (nv, nt) = shape
            .counts()
            .or_else(|e| ck.err(o.span(), &field, describe(e)))?;
        // Counted before anything is allocated for the mesh.
        ck.count_triangles(nt, o.span(), &field)?;
        let mut vertices = vec![Vertex::default(); nv];
        let mut triangles = vec![[0u16; 3]; nt];
        shape
            .write(&mut vertices, &mut triangles)
            .or_else(|e| ck.err(o.span(), &field, describe(e)))?;
        let mesh = MeshRef {
            vertices: &vertices,
            triangles: &triangles,
        };
        let mut scratch = vec![ViewVertex::<C>::EMPTY; nv];
        let mut prims = Vec::new();
        let part = Part {
            mesh,
            transform,
            color,
        };
        project_faces(
            &[part],
            &Transform::IDENTITY,
            &view,
            &light,
            &mut scratch,
            faces,
            |t| prims.push(Primitive::Depth(t)),
        )
        .or_else(|e| match (e, &light_at) {
            (SceneError::ZeroDirection, Some(at)) => {
                ck.err(at.clone(), "light.direction", describe(e))
            }
            _ => ck.err(o.span(), &field, describe(e)),
        })?;
        out.push((
            Origin {
                field,
                span: o.span(),
            },
            prims,
        ));
    }
    Ok(out)
}

/// The keys each shape uses, besides shape, color, position, rotation and
/// segments.
fn shape_keys(shape: &str) -> Option<&'static [&'static str]> {
    Some(match shape {
        "sphere" => &["radius"],
        "torus" => &["radius", "minor_radius", "tube_segments"],
        "cone" | "cylinder" => &["radius", "height"],
        "box" => &["size"],
        _ => return None,
    })
}

fn shape(
    ck: &mut Checker<'_>,
    o: &raw::Object,
    field: &str,
    span: std::ops::Range<usize>,
) -> Checked<Shape> {
    let name = o.shape.get_ref().as_str();
    let Some(keys) = shape_keys(name) else {
        return ck.err(
            o.shape.span(),
            &format!("{field}.shape"),
            format!("unknown shape `{name}`; one of sphere, torus, cone, cylinder, box"),
        );
    };
    // A key another shape uses is a mistake here, not something to ignore.
    let given: [(&str, Option<std::ops::Range<usize>>); 5] = [
        ("radius", o.radius.as_ref().map(|v| v.span())),
        ("minor_radius", o.minor_radius.as_ref().map(|v| v.span())),
        ("height", o.height.as_ref().map(|v| v.span())),
        ("size", o.size.as_ref().map(|v| v.span())),
        ("tube_segments", o.tube_segments.as_ref().map(|v| v.span())),
    ];
    for (key, at) in given {
        if let Some(at) = at {
            if !keys.contains(&key) {
                return ck.err(
                    at,
                    &format!("{field}.{key}"),
                    format!("a {name} has no `{key}` (it takes {})", keys.join(", ")),
                );
            }
        }
    }
    let world = f64::from(WORLD_LIMIT);
    let need = |ck: &Checker<'_>, v: &Option<raw::Num>, key: &str| -> Checked<I16F16> {
        match v {
            Some(v) => Ok(I16F16::from_num(ck.num(
                v,
                &format!("{field}.{key}"),
                0.0,
                world,
            )?)),
            None => ck.err(
                span.clone(),
                &format!("{field}.{key}"),
                format!("a {name} needs `{key}`"),
            ),
        }
    };
    let max_seg = i64::from(MAX_SEGMENTS);
    let segments = |ck: &Checker<'_>, v: &Option<raw::Int>, key: &str, default: u16| {
        v.as_ref().map_or(Ok(default), |s| {
            ck.int(s, &format!("{field}.{key}"), 1, max_seg)
                .map(|n| n as u16)
        })
    };
    let default_segments = if name == "box" { 1 } else { 24 };
    let n = segments(ck, &o.segments, "segments", default_segments)?;
    Ok(match name {
        "sphere" => Shape::Sphere {
            radius: need(ck, &o.radius, "radius")?,
            segments: n,
        },
        "torus" => Shape::Torus {
            major: need(ck, &o.radius, "radius")?,
            minor: need(ck, &o.minor_radius, "minor_radius")?,
            segments: n,
            tube_segments: segments(ck, &o.tube_segments, "tube_segments", (n / 2).max(3))?,
        },
        "cone" => Shape::Cone {
            radius: need(ck, &o.radius, "radius")?,
            height: need(ck, &o.height, "height")?,
            segments: n,
        },
        "cylinder" => Shape::Cylinder {
            radius: need(ck, &o.radius, "radius")?,
            height: need(ck, &o.height, "height")?,
            segments: n,
        },
        _ => {
            let Some(size) = &o.size else {
                return ck.err(span, &format!("{field}.size"), "a box needs `size`");
            };
            Shape::Box {
                size: vec3(ck.nums::<3>(size, &format!("{field}.size"), 0.0, world)?),
                segments: n,
            }
        }
    })
}
