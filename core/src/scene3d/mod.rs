//! 3D scenes: fixed-point transforms, per-vertex lighting, projection and
//! canonical objects (seed 000, "modelling"; DESIGN.md step 1, "Geometry
//! in").
//!
//! Takes meshes (the canonical objects of [`Shape`], or any closed mesh in a
//! [`MeshRef`]), each part with its own [`Transform`] and colour, a
//! [`Camera`] and a [`Light`]; gives screen-space [`ScreenTriangle`]s, each
//! with sub-pixel vertices, a linear 12-bit colour and a `u16` depth per
//! vertex, ready for [`Triangle::draw`](crate::Triangle::draw). Everything
//! here is per-vertex or per-triangle setup: integer multiplies and divides
//! in `i64`, no floating point anywhere (a Cortex-M0 has no FPU).
//!
//! ## The stages of [`project`], per vertex then per triangle
//!
//! 1. Model to world: `p' = M p + t` ([`Transform`], Q16.16), normals by the
//!    cofactor matrix of `M` (right under non-uniform scale), renormalised.
//! 2. Lighting, per channel: `c = base * (ambient + diffuse * max(0, n.l))`
//!    with `ambient` and `diffuse` in Q12 (`4096 = 1`), clamped to 4095
//!    ([`Light`]). With `ambient = 4096` and `diffuse = 0` every vertex
//!    has exactly its part's colour.
//! 3. World to camera space ([`View`]).
//! 4. Near-plane clipping in camera space: a triangle crossing `d = near` is
//!    cut into one or two triangles, positions and colours interpolated
//!    along the cut edges (always from the vertex in front, so an edge shared
//!    by two triangles is cut at the very same point for both).
//! 5. Projection to 1/16 px and depth ([`camera`](self::Camera)).
//! 6. Back-face culling: the meshes wind counter-clockwise seen from
//!    outside, so a triangle facing the camera runs counter-clockwise as
//!    seen on the screen (negative twice-area in y-down coordinates);
//!    the others, and edge-on ones, are skipped. This is hidden-surface removal for one convex
//!    object only.
//!
//! ## Results for bad or awkward input (documented, never a panic)
//!
//! - Invalid shapes, transforms, cameras, lights, scratch too small, an
//!   index beyond the vertex list, a vertex leaving the world range: a
//!   [`SceneError`], and nothing emitted (every vertex is transformed, lit
//!   and checked before the first triangle is emitted).
//! - Triangles wholly behind the near plane (objects behind the camera) or
//!   beyond `far`: skipped, counted in [`ProjectStats::clipped`].
//! - Triangles with a vertex projected outside `±COORD_LIMIT_PX`: skipped,
//!   counted in [`ProjectStats::off_range`] (no screen-space clipping yet).
//!
//! ```
//! use fixed::types::I16F16;
//! use softedge::scene3d::{project, Angle, Camera, Light, Mesh, Part, Shape, Transform, Vec3, ViewVertex};
//! use softedge::{Band, BandBuffer, RenderStyle};
//!
//! let ball = Mesh::<114, 224>::new(&Shape::Sphere { radius: I16F16::from_num(1), segments: 16 }).unwrap();
//! let parts = [Part { mesh: ball.as_ref(), transform: Transform::IDENTITY, color: [4095] }];
//! let cam = Camera::perspective(Vec3::from_int(0, 0, 5), Vec3::ZERO, Vec3::from_int(0, 1, 0), Angle::from_degrees(40));
//! let view = cam.view(32, 32).unwrap();
//! let light = Light::new(Vec3::from_int(1, 1, 1), [410], [3686]);
//! let mut scratch = [ViewVertex::<1>::EMPTY; 114];
//!
//! let (mut acc, mut cover) = ([0i32; 32 * 32], [0i32; BandBuffer::<1>::cover_len(32, 32)]);
//! let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(32, 0, 32)).unwrap();
//! buf.clear([0]);
//! let stats = project(&parts, &Transform::IDENTITY, &view, &light, &mut scratch, |t| {
//!     // Emitted triangles are inside the coordinate range: drawing cannot fail.
//!     let _ = t.draw(&mut buf, &RenderStyle::default());
//! })
//! .unwrap();
//! assert!(stats.emitted > 0 && stats.back_facing > 0);
//! assert!(buf.lin12(16, 16).unwrap()[0] > 0);
//! ```

mod camera;
mod errors;
mod math;
mod mesh;
mod trig;

pub use camera::{Camera, Projection, View, MAX_FOCAL_PX, MAX_PX_PER_UNIT, MIN_UP_SIN_SHIFT};
/// The Q16.16 number type of positions and sizes, re-exported from `fixed`.
pub use fixed::types::I16F16;
pub use math::{Transform, Vec3, MATRIX_LIMIT, WORLD_LIMIT};
pub use mesh::{Mesh, MeshRef, Shape, Vertex, MAX_MESH_VERTICES, MAX_SEGMENTS, MIN_SEGMENTS};
pub use trig::{sin_q16, Angle};

use crate::geom::{area2, SubPoint};
use crate::shade::LIN_MAX;
use math::{normalize, NormalMatrix};

/// Why a scene could not be set up or projected.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum SceneError {
    /// A coordinate, size, scale or matrix entry outside its documented
    /// range (or a torus tube not thinner than its ring).
    OutOfRange,
    /// A size, scale or distance that must be positive is not.
    NonPositive,
    /// A segment count outside `MIN_SEGMENTS..=MAX_SEGMENTS`, or one giving
    /// more than `MAX_MESH_VERTICES` vertices.
    Segments,
    /// The storage is too small: the counts it needs.
    Capacity {
        /// Vertices needed.
        vertices: usize,
        /// Triangles needed.
        triangles: usize,
    },
    /// The scratch slice of [`project`] is too small: the vertices needed.
    Scratch {
        /// Vertices needed (all parts together).
        needed: usize,
    },
    /// A triangle refers to a vertex beyond its mesh's vertex list.
    BadIndex,
    /// The eye is at the target: no view direction.
    EyeAtTarget,
    /// `up` is zero or (nearly) parallel to the view direction.
    UpParallel,
    /// The field of view is not in `(0, 180)` degrees, or so narrow the
    /// focal length exceeds `MAX_FOCAL_PX`.
    FieldOfView,
    /// The light direction is zero while some diffuse factor is not.
    ZeroDirection,
}

/// One directional light plus ambient light, per channel.
///
/// Factors are Q12: `4096` is 1. A vertex of colour `base` and unit normal
/// `n` gets `base * (ambient + diffuse * max(0, n . l))` per channel, `l`
/// the unit vector towards the light, rounded and clamped to 4095.
///
/// ```
/// use softedge::scene3d::{Light, Vec3};
/// let flat = Light::<3>::FLAT; // ambient 1, diffuse 0
/// assert_eq!(flat.ambient, [4096; 3]);
/// let sun = Light::new(Vec3::from_int(0, 1, 0), [410; 3], [3686; 3]);
/// assert_eq!(sun.diffuse[2], 3686);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Light<const C: usize> {
    /// Direction towards the light (any length, not zero when some diffuse
    /// factor is not zero).
    pub to_light: Vec3,
    /// Ambient factor per channel, Q12.
    pub ambient: [u16; C],
    /// Diffuse factor per channel, Q12.
    pub diffuse: [u16; C],
}

impl<const C: usize> Light<C> {
    /// Ambient 1, diffuse 0: every vertex gets its part's colour.
    pub const FLAT: Self = Self {
        to_light: Vec3::ZERO,
        ambient: [1 << 12; C],
        diffuse: [0; C],
    };

    /// A light towards `to_light` with Q12 factors.
    pub const fn new(to_light: Vec3, ambient: [u16; C], diffuse: [u16; C]) -> Self {
        Self {
            to_light,
            ambient,
            diffuse,
        }
    }

    /// The colour of a vertex of colour `base` with the unit normal `n`
    /// (Q30), given the unit light direction `l` (Q30).
    fn shade(&self, base: [u16; C], n: Option<[i64; 3]>, l: Option<[i64; 3]>) -> [u16; C] {
        // n . l in Q16, clamped at 0 (|n|, |l| <= 2^30: sum below 2^62).
        let ndotl = match (n, l) {
            (Some(n), Some(l)) => {
                let dot: i64 = n.iter().zip(l).map(|(a, b)| a * b).sum();
                ((dot + (1 << 43)) >> 44).clamp(0, 1 << 16)
            }
            _ => 0,
        };
        let mut out = [0u16; C];
        for k in 0..C {
            // Q28 intensity below 2^33, times base <= 4095: below 2^45.
            let i = (i64::from(self.ambient[k]) << 16) + i64::from(self.diffuse[k]) * ndotl;
            let b = i64::from(base[k].min(LIN_MAX));
            out[k] = ((b * i + (1 << 27)) >> 28).min(i64::from(LIN_MAX)) as u16;
        }
        out
    }
}

/// One part of an object: a mesh, where it goes, and its colour.
#[derive(Debug, Clone, Copy)]
pub struct Part<'a, const C: usize> {
    /// The mesh, in model units.
    pub mesh: MeshRef<'a>,
    /// Model to object transform (the object's own transform follows it).
    pub transform: Transform,
    /// Linear 12-bit colour (values above 4095 are clamped).
    pub color: [u16; C],
}

/// A lit vertex in camera space: scratch storage of [`project`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ViewVertex<const C: usize> {
    /// `(x, y, d)`, Q16.16 bits.
    cam: [i32; 3],
    /// Lit colour, linear 12-bit.
    color: [u16; C],
}

impl<const C: usize> ViewVertex<C> {
    /// An unused slot (for initialising scratch arrays).
    pub const EMPTY: Self = Self {
        cam: [0; 3],
        color: [0; C],
    };
}

/// A triangle ready to draw: sub-pixel vertices (counter-clockwise as seen
/// on screen, inside the coordinate range), colours and depths (larger is
/// nearer, seed 004): the [`DepthTriangle`](crate::hsr::DepthTriangle) of
/// hidden-surface removal.
pub type ScreenTriangle<const C: usize> = crate::hsr::DepthTriangle<C>;

/// What [`project`] did with the triangles it was given.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ProjectStats {
    /// Triangles handed to `emit` (a near-clipped triangle may give two).
    pub emitted: usize,
    /// Triangles (after clipping) facing away or edge-on, skipped.
    pub back_facing: usize,
    /// Triangles wholly behind the near plane or beyond `far`, skipped.
    pub clipped: usize,
    /// Triangles with a vertex projected outside `±COORD_LIMIT_PX`, skipped.
    pub off_range: usize,
}

/// Projects the parts of one object, placed in the world by `object`, and
/// hands every visible screen triangle to `emit`.
///
/// `scratch` must hold the vertices of all parts together
/// ([`SceneError::Scratch`] otherwise). All vertices are transformed, lit and
/// checked first: on an error nothing has been emitted.
pub fn project<const C: usize>(
    parts: &[Part<'_, C>],
    object: &Transform,
    view: &View,
    light: &Light<C>,
    scratch: &mut [ViewVertex<C>],
    emit: impl FnMut(ScreenTriangle<C>),
) -> Result<ProjectStats, SceneError> {
    project_faces(parts, object, view, light, scratch, Faces::Front, emit)
}

/// Which faces [`project_faces`] emits.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Faces {
    /// Front faces only (back-face culling): all a closed mesh shows.
    Front,
    /// Front and back faces (section mode cuts through both), each emitted
    /// counter-clockwise as seen on screen.
    Both,
}

/// [`project`], choosing whether back faces are culled.
pub fn project_faces<const C: usize>(
    parts: &[Part<'_, C>],
    object: &Transform,
    view: &View,
    light: &Light<C>,
    scratch: &mut [ViewVertex<C>],
    faces: Faces,
    mut emit: impl FnMut(ScreenTriangle<C>),
) -> Result<ProjectStats, SceneError> {
    let needed: usize = parts.iter().map(|p| p.mesh.vertices.len()).sum();
    if scratch.len() < needed {
        return Err(SceneError::Scratch { needed });
    }
    let to_light = normalize(light.to_light.wide(), 30);
    if to_light.is_none() && light.diffuse.iter().any(|&d| d != 0) {
        return Err(SceneError::ZeroDirection);
    }
    // Per vertex: transform, light, to camera space.
    let mut base = 0;
    for part in parts {
        let n = part.mesh.vertices.len();
        if part
            .mesh
            .triangles
            .iter()
            .flatten()
            .any(|&i| usize::from(i) >= n)
        {
            return Err(SceneError::BadIndex);
        }
        let model = part.transform.then(object)?;
        let normals: Option<NormalMatrix> = model.normal_matrix();
        let out = scratch.get_mut(base..base + n).unwrap_or(&mut []);
        for (slot, v) in out.iter_mut().zip(part.mesh.vertices) {
            let world = model.apply(v.position)?;
            let nw = normals.and_then(|m| m.apply(v.normal.wide()));
            slot.color = light.shade(part.color, nw, to_light);
            slot.cam = view.camera_coords(world.wide());
        }
        base += n;
    }
    // Per triangle: clip, project, cull, emit.
    let mut stats = ProjectStats::default();
    let mut base = 0;
    for part in parts {
        let verts = scratch
            .get(base..base + part.mesh.vertices.len())
            .unwrap_or(&[]);
        for tri in part.mesh.triangles {
            let corners = tri.map(|i| verts.get(usize::from(i)).copied());
            let [Some(a), Some(b), Some(c)] = corners else {
                continue;
            };
            emit_triangle([a, b, c], view, faces, &mut stats, &mut emit);
        }
        base += part.mesh.vertices.len();
    }
    Ok(stats)
}

/// [`project`] for a single mesh with its transform and colour.
pub fn project_mesh<const C: usize>(
    mesh: MeshRef<'_>,
    transform: &Transform,
    color: [u16; C],
    view: &View,
    light: &Light<C>,
    scratch: &mut [ViewVertex<C>],
    emit: impl FnMut(ScreenTriangle<C>),
) -> Result<ProjectStats, SceneError> {
    let part = Part {
        mesh,
        transform: *transform,
        color,
    };
    project(&[part], &Transform::IDENTITY, view, light, scratch, emit)
}

/// A camera-space vertex during clipping: `(x, y, d)` Q16 and colour.
#[derive(Clone, Copy)]
struct ClipVertex<const C: usize> {
    p: [i64; 3],
    color: [u16; C],
}

/// The point where the edge from `inside` (`d >= near`) to `outside`
/// (`d < near`) crosses `d = near`. Differences are below `2^31`, so each
/// product is below `2^62`.
fn cut<const C: usize>(inside: ClipVertex<C>, outside: ClipVertex<C>, near: i64) -> ClipVertex<C> {
    let num = inside.p[2] - near; // >= 0
    let den = inside.p[2] - outside.p[2]; // > num
    let lerp = |a: i64, b: i64| a + math::div_round((b - a) * num, den);
    let mut color = inside.color;
    for k in 0..C {
        color[k] = lerp(i64::from(inside.color[k]), i64::from(outside.color[k])) as u16;
    }
    ClipVertex {
        p: [
            lerp(inside.p[0], outside.p[0]),
            lerp(inside.p[1], outside.p[1]),
            near,
        ],
        color,
    }
}

fn emit_triangle<const C: usize>(
    tri: [ViewVertex<C>; 3],
    view: &View,
    faces: Faces,
    stats: &mut ProjectStats,
    emit: &mut impl FnMut(ScreenTriangle<C>),
) {
    let near = view.near();
    let v = tri.map(|t| ClipVertex {
        p: t.cam.map(i64::from),
        color: t.color,
    });
    if v.iter().all(|c| c.p[2] < near) || v.iter().all(|c| c.p[2] > view.far()) {
        stats.clipped += 1;
        return;
    }
    // Sutherland-Hodgman against d >= near: at most 4 vertices.
    let mut poly = [v[0]; 4];
    let mut len = 0;
    for k in 0..3 {
        let (a, b) = (v[k], v[(k + 1) % 3]);
        let (a_in, b_in) = (a.p[2] >= near, b.p[2] >= near);
        // At most 4 vertices come out (one per edge plus one cut); `get_mut`
        // keeps that bound without a panic path.
        if a_in {
            if let Some(slot) = poly.get_mut(len) {
                *slot = a;
            }
            len += 1;
        }
        if a_in != b_in {
            if let Some(slot) = poly.get_mut(len) {
                *slot = if a_in {
                    cut(a, b, near)
                } else {
                    cut(b, a, near)
                };
            }
            len += 1;
        }
    }
    let len = len.min(poly.len());
    let mut screen = [(SubPoint::default(), 0u16); 4];
    for (slot, c) in screen.iter_mut().zip(&poly).take(len) {
        match view.project_camera(c.p) {
            Some(s) => *slot = s,
            None => {
                stats.off_range += 1;
                return;
            }
        }
    }
    for k in 1..len.saturating_sub(1) {
        // k + 1 < len <= 4: in range; `min` lets the compiler see it.
        let mut idx = [0, k, k + 1].map(|i| i.min(3));
        // Counter-clockwise seen from outside stays counter-clockwise as
        // seen on screen, which in y-down coordinates is a negative area2.
        let a = area2(&idx.map(|i| screen[i].0));
        if a == 0 || (a > 0 && faces == Faces::Front) {
            stats.back_facing += 1;
            continue;
        }
        if a > 0 {
            // A back face, kept: turned to run counter-clockwise on screen.
            idx.swap(1, 2);
        }
        let vertices = idx.map(|i| screen[i].0);
        stats.emitted += 1;
        emit(ScreenTriangle {
            vertices,
            colors: idx.map(|i| poly[i].color),
            depth: idx.map(|i| screen[i].1),
        });
    }
}
