//! Canonical objects triangulated into caller storage (seed 000, section
//! "modelling": automatic triangulation of sphere, torus, cone, cylinder).
//!
//! A [`Shape`] is a canonical object with its level of detail; it writes its
//! vertices (position and unit outward normal, Q16.16) and triangles
//! (`[u16; 3]` vertex indices) into slices ([`Shape::write`]) or into a
//! const-generic [`Mesh`]. Storage too small is a
//! [`SceneError::Capacity`] naming what is needed, before anything is
//! written.
//!
//! ## Conventions
//!
//! Every object is centred at its origin. Cylinder and cone have their axis
//! along y (the cone's apex at `+height/2`, its base at `-height/2`); the
//! torus lies in the x-y plane around the z axis; the sphere's poles are on
//! the y axis. Triangles wind counter-clockwise seen from outside
//! (`(b - a) x (c - a)` points out). Every mesh is closed: once vertices at
//! equal positions are welded (the cylinder, cone and box repeat rim and edge
//! positions with a second normal, so the shading has its creases), each
//! directed edge appears exactly once and its reverse exactly once.
//!
//! ## Counts (`n` = `segments`, `m` as noted)
//!
//! | shape | vertices | triangles |
//! |---|---|---|
//! | sphere, `m = max(2, n / 2)` latitude bands | `n (m - 1) + 2` | `2 n (m - 1)` |
//! | torus, `m = tube_segments` | `n m` | `2 n m` |
//! | cylinder | `4 n + 2` | `4 n` |
//! | cone | `3 n + 1` | `2 n` |
//! | box, `n` divisions per edge | `6 (n + 1)^2` | `12 n^2` |
//!
//! [`Shape::counts`] computes them. `segments` must lie in
//! `MIN_SEGMENTS..=MAX_SEGMENTS` (the box: `1..=MAX_SEGMENTS`) and the vertex
//! count must fit the `u16` indices (at most 65536 vertices).
//!
//! ## Sizes
//!
//! Radii, heights and box sizes must be positive ([`SceneError::NonPositive`]);
//! the object must fit in `±WORLD_LIMIT` ([`SceneError::OutOfRange`]); the
//! torus needs `minor < major` (a thicker tube would pass through its own
//! axis).

use fixed::types::I16F16;

use super::math::{normalize, Vec3, WORLD_LIMIT_BITS};
use super::trig::Angle;
use super::SceneError;

/// Fewest segments around an axis.
pub const MIN_SEGMENTS: u16 = 3;
/// Most segments around an axis (or box divisions).
pub const MAX_SEGMENTS: u16 = 1024;
/// Most vertices a mesh may have: its indices are `u16`.
pub const MAX_MESH_VERTICES: usize = 1 << 16;

/// A mesh vertex: position and unit outward normal, Q16.16.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Vertex {
    /// Position in model units.
    pub position: Vec3,
    /// Unit outward normal (length 1 within `2^-15`).
    pub normal: Vec3,
}

/// A canonical object and its level of detail.
///
/// ```
/// use softedge::scene3d::{Shape, Vertex};
/// use fixed::types::I16F16;
/// let s = Shape::Sphere { radius: I16F16::from_num(2), segments: 8 };
/// assert_eq!(s.counts(), Ok((26, 48)));
/// let mut v = [Vertex::default(); 26];
/// let mut t = [[0u16; 3]; 48];
/// assert_eq!(s.write(&mut v, &mut t), Ok((26, 48)));
/// assert_eq!(v[0].position.y, I16F16::from_num(2)); // the north pole
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A UV sphere: `segments` meridians, `max(2, segments / 2)` latitude
    /// bands, poles on the y axis.
    Sphere {
        /// Radius.
        radius: I16F16,
        /// Segments around the y axis.
        segments: u16,
    },
    /// A ring torus in the x-y plane around the z axis.
    Torus {
        /// Distance from the z axis to the tube's centre line.
        major: I16F16,
        /// Radius of the tube (`< major`).
        minor: I16F16,
        /// Segments around the z axis.
        segments: u16,
        /// Segments around the tube.
        tube_segments: u16,
    },
    /// A closed cylinder with its axis along y, flat caps.
    Cylinder {
        /// Radius.
        radius: I16F16,
        /// Height along y (from `-height/2` to `height/2`).
        height: I16F16,
        /// Segments around the y axis.
        segments: u16,
    },
    /// A closed cone with its axis along y: base at `-height/2`, apex at
    /// `+height/2`.
    Cone {
        /// Radius of the base.
        radius: I16F16,
        /// Height along y.
        height: I16F16,
        /// Segments around the y axis.
        segments: u16,
    },
    /// A box with edges along the axes, each face divided into
    /// `segments x segments` squares.
    Box {
        /// Edge lengths along x, y and z.
        size: Vec3,
        /// Divisions of each edge (at least 1).
        segments: u16,
    },
}

impl Shape {
    /// `(vertices, triangles)` by the formulas of the module docs, after
    /// checking the parameters.
    pub fn counts(&self) -> Result<(usize, usize), SceneError> {
        self.check()?;
        let (v, t) = match *self {
            Shape::Sphere { segments, .. } => {
                let (n, m) = sphere_nm(segments);
                (n * (m - 1) + 2, 2 * n * (m - 1))
            }
            Shape::Torus {
                segments,
                tube_segments,
                ..
            } => {
                let (n, m) = (usize::from(segments), usize::from(tube_segments));
                (n * m, 2 * n * m)
            }
            Shape::Cylinder { segments, .. } => {
                let n = usize::from(segments);
                (4 * n + 2, 4 * n)
            }
            Shape::Cone { segments, .. } => {
                let n = usize::from(segments);
                (3 * n + 1, 2 * n)
            }
            Shape::Box { segments, .. } => {
                let k = usize::from(segments);
                (6 * (k + 1) * (k + 1), 12 * k * k)
            }
        };
        if v > MAX_MESH_VERTICES {
            return Err(SceneError::Segments);
        }
        Ok((v, t))
    }

    fn check(&self) -> Result<(), SceneError> {
        let seg_ok = |s: u16, min: u16| (min..=MAX_SEGMENTS).contains(&s);
        let positive = |v: &[I16F16]| v.iter().all(|x| *x > 0);
        // Largest extent from the origin along any axis, Q16 bits.
        let (sizes_ok, segs_ok, extent): (bool, bool, i64) = match *self {
            Shape::Sphere { radius, segments } => (
                positive(&[radius]),
                seg_ok(segments, MIN_SEGMENTS),
                i64::from(radius.to_bits()),
            ),
            Shape::Torus {
                major,
                minor,
                segments,
                tube_segments,
            } => (
                positive(&[major, minor]),
                seg_ok(segments, MIN_SEGMENTS) && seg_ok(tube_segments, MIN_SEGMENTS),
                i64::from(major.to_bits()) + i64::from(minor.to_bits()),
            ),
            Shape::Cylinder {
                radius,
                height,
                segments,
            }
            | Shape::Cone {
                radius,
                height,
                segments,
            } => (
                positive(&[radius, height]),
                seg_ok(segments, MIN_SEGMENTS),
                i64::from(radius.to_bits()).max(i64::from(height.to_bits()) / 2),
            ),
            Shape::Box { size, segments } => (
                positive(&[size.x, size.y, size.z]),
                seg_ok(segments, 1),
                size.wide().iter().fold(0, |m, &c| m.max(c / 2)),
            ),
        };
        if !sizes_ok {
            return Err(SceneError::NonPositive);
        }
        if !segs_ok {
            return Err(SceneError::Segments);
        }
        if extent > WORLD_LIMIT_BITS {
            return Err(SceneError::OutOfRange);
        }
        if let Shape::Torus { major, minor, .. } = *self {
            if minor >= major {
                return Err(SceneError::OutOfRange);
            }
        }
        Ok(())
    }

    /// Writes the mesh into `vertices` and `triangles` (longer slices are
    /// fine); returns how many of each were written. On error nothing is
    /// written.
    pub fn write(
        &self,
        vertices: &mut [Vertex],
        triangles: &mut [[u16; 3]],
    ) -> Result<(usize, usize), SceneError> {
        let (nv, nt) = self.counts()?;
        if vertices.len() < nv || triangles.len() < nt {
            return Err(SceneError::Capacity {
                vertices: nv,
                triangles: nt,
            });
        }
        let mut w = Writer {
            v: vertices,
            t: triangles,
            nv: 0,
            nt: 0,
        };
        match *self {
            Shape::Sphere { radius, segments } => sphere(&mut w, radius, segments),
            Shape::Torus {
                major,
                minor,
                segments,
                tube_segments,
            } => torus(&mut w, major, minor, segments, tube_segments),
            Shape::Cylinder {
                radius,
                height,
                segments,
            } => cylinder(&mut w, radius, height, segments),
            Shape::Cone {
                radius,
                height,
                segments,
            } => cone(&mut w, radius, height, segments),
            Shape::Box { size, segments } => cuboid(&mut w, size, segments),
        }
        Ok((w.nv, w.nt))
    }
}

fn sphere_nm(segments: u16) -> (usize, usize) {
    let n = usize::from(segments);
    (n, (n / 2).max(2))
}

/// Appends vertices and triangles; capacity was checked by the caller, and
/// a write past the end is dropped rather than panicking.
struct Writer<'a> {
    v: &'a mut [Vertex],
    t: &'a mut [[u16; 3]],
    nv: usize,
    nt: usize,
}

impl Writer<'_> {
    /// Adds a vertex at `p` (Q16 bits) with the normal along `n` (any
    /// length), and returns its index.
    fn vertex(&mut self, p: [i64; 3], n: [i64; 3]) -> usize {
        let n = normalize(n, 16).unwrap_or([0; 3]);
        if let Some(slot) = self.v.get_mut(self.nv) {
            *slot = Vertex {
                position: Vec3::from_bits(p.map(|c| c as i32)),
                normal: Vec3::from_bits(n.map(|c| c as i32)),
            };
        }
        self.nv += 1;
        self.nv - 1
    }

    fn tri(&mut self, a: usize, b: usize, c: usize) {
        if let Some(slot) = self.t.get_mut(self.nt) {
            *slot = [a as u16, b as u16, c as u16];
        }
        self.nt += 1;
    }

    /// Two rings of `n` vertices starting at `top` and `bottom`, where
    /// "right" (index + 1) crossed with "down" (top to bottom) points out.
    fn band(&mut self, top: usize, bottom: usize, n: usize) {
        for j in 0..n {
            let j1 = (j + 1) % n;
            self.tri(top + j, top + j1, bottom + j);
            self.tri(top + j1, bottom + j1, bottom + j);
        }
    }

    /// A fan from `pole` above a ring (`pole_step` 1: one pole vertex per
    /// segment, as the cone's apex copies).
    fn fan_down(&mut self, pole: usize, pole_step: usize, ring: usize, n: usize) {
        for j in 0..n {
            self.tri(pole + j * pole_step, ring + (j + 1) % n, ring + j);
        }
    }

    /// A fan from a ring down to `pole`.
    fn fan_up(&mut self, ring: usize, pole: usize, n: usize) {
        for j in 0..n {
            self.tri(ring + j, ring + (j + 1) % n, pole);
        }
    }
}

/// `r * c / 2^16` for Q16 `r` and a Q16 sine or cosine, rounded.
fn mul16(r: i64, c: i32) -> i64 {
    super::math::round16(r * i64::from(c))
}

fn cos_sin(k: usize, n: usize) -> (i32, i32) {
    let a = Angle::from_turns(k as u32, n as u32);
    (a.cos_q16(), a.sin_q16())
}

fn sphere(w: &mut Writer<'_>, radius: I16F16, segments: u16) {
    let (n, m) = sphere_nm(segments);
    let r = i64::from(radius.to_bits());
    w.vertex([0, r, 0], [0, 1, 0]);
    for i in 1..m {
        let (cp, sp) = cos_sin(i, 2 * m);
        for j in 0..n {
            let (ct, st) = cos_sin(j, n);
            // Direction in Q32, position r * dir rounded to Q16.
            let d = [
                i64::from(sp) * i64::from(ct),
                i64::from(cp) << 16,
                i64::from(sp) * i64::from(st),
            ];
            w.vertex(d.map(|c| (r * c + (1 << 31)) >> 32), d);
        }
    }
    w.vertex([0, -r, 0], [0, -1, 0]);
    w.fan_down(0, 0, 1, n);
    for i in 0..m - 2 {
        w.band(1 + i * n, 1 + (i + 1) * n, n);
    }
    w.fan_up(1 + (m - 2) * n, 1 + (m - 1) * n, n);
}

fn torus(w: &mut Writer<'_>, major: I16F16, minor: I16F16, segments: u16, tube: u16) {
    let (n, m) = (usize::from(segments), usize::from(tube));
    let (big, small) = (i64::from(major.to_bits()), i64::from(minor.to_bits()));
    // Rows by increasing tube angle phi: "right" is +theta (x towards y),
    // "down" is +phi, and right x down points out of the tube.
    for i in 0..m {
        let (cp, sp) = cos_sin(i, m);
        let ring = big + mul16(small, cp);
        for j in 0..n {
            let (ct, st) = cos_sin(j, n);
            let p = [mul16(ring, ct), mul16(ring, st), mul16(small, sp)];
            let d = [
                i64::from(cp) * i64::from(ct),
                i64::from(cp) * i64::from(st),
                i64::from(sp) << 16,
            ];
            w.vertex(p, d);
        }
    }
    for i in 0..m {
        w.band(i * n, ((i + 1) % m) * n, n);
    }
}

/// A ring of `n` vertices of radius `r` at height `y`, with normals
/// `(cos * nr, ny, sin * nr)` (Q16 `nr`, `ny`).
fn ring(w: &mut Writer<'_>, r: i64, y: i64, n: usize, nr: i64, ny: i64) -> usize {
    let start = w.nv;
    for j in 0..n {
        let (ct, st) = cos_sin(j, n);
        let d = [nr * i64::from(ct), ny << 16, nr * i64::from(st)];
        w.vertex([mul16(r, ct), y, mul16(r, st)], d);
    }
    start
}

fn cylinder(w: &mut Writer<'_>, radius: I16F16, height: I16F16, segments: u16) {
    let n = usize::from(segments);
    let r = i64::from(radius.to_bits());
    let h = i64::from(height.to_bits()) / 2;
    // Top cap: centre, then rim ("down" runs outwards, +x at theta = 0).
    let top = w.vertex([0, h, 0], [0, 1, 0]);
    let top_rim = ring(w, r, h, n, 0, 1);
    // Side, top ring then bottom ring ("down" is -y).
    let side_top = ring(w, r, h, n, 1, 0);
    let side_bottom = ring(w, r, -h, n, 1, 0);
    // Bottom cap: rim, then centre.
    let bottom_rim = ring(w, r, -h, n, 0, -1);
    let bottom = w.vertex([0, -h, 0], [0, -1, 0]);
    w.fan_down(top, 0, top_rim, n);
    w.band(side_top, side_bottom, n);
    w.fan_up(bottom_rim, bottom, n);
}

fn cone(w: &mut Writer<'_>, radius: I16F16, height: I16F16, segments: u16) {
    let n = usize::from(segments);
    let r = i64::from(radius.to_bits());
    let height = i64::from(height.to_bits());
    let h = height / 2;
    // The side's normal leans up by the slope: (height * cos, radius,
    // height * sin) up to length. One apex copy per segment, its normal at
    // the segment's middle angle.
    let apex = w.nv;
    for j in 0..n {
        let a = Angle::from_turns(2 * j as u32 + 1, 2 * n as u32);
        let d = [
            height * i64::from(a.cos_q16()),
            r << 16,
            height * i64::from(a.sin_q16()),
        ];
        w.vertex([0, h, 0], d);
    }
    let side = ring(w, r, -h, n, height, r);
    let rim = ring(w, r, -h, n, 0, -1);
    let centre = w.vertex([0, -h, 0], [0, -1, 0]);
    w.fan_down(apex, 1, side, n);
    w.fan_up(rim, centre, n);
}

/// `p[axis] = value` for an axis index from a table (no panic path).
fn set(p: &mut [i64; 3], axis: usize, value: i64) {
    if let Some(c) = p.get_mut(axis) {
        *c = value;
    }
}

fn cuboid(w: &mut Writer<'_>, size: Vec3, segments: u16) {
    let k = i64::from(segments);
    let half = size.wide().map(|c| c / 2);
    // Lattice coordinate t in 0..=k of axis a, the same expression on every
    // face so shared edges get identical positions.
    let h = |a: usize| half.get(a).copied().unwrap_or(0);
    let coord = |a: usize, t: i64| -h(a) + (2 * h(a) * t).checked_div(k).unwrap_or(0);
    // (normal axis, sign, u axis, v axis) with u x v pointing out.
    let faces: [(usize, i64, usize, usize); 6] = [
        (0, 1, 1, 2),
        (0, -1, 2, 1),
        (1, 1, 2, 0),
        (1, -1, 0, 2),
        (2, 1, 0, 1),
        (2, -1, 1, 0),
    ];
    for (axis, sign, u, v) in faces {
        let start = w.nv;
        let mut normal = [0i64; 3];
        set(&mut normal, axis, sign);
        for j in 0..=k {
            for i in 0..=k {
                let mut p = [0i64; 3];
                set(&mut p, axis, if sign > 0 { h(axis) } else { -h(axis) });
                set(&mut p, u, coord(u, i));
                set(&mut p, v, coord(v, j));
                w.vertex(p, normal);
            }
        }
        let row = (k + 1) as usize;
        for j in 0..k as usize {
            for i in 0..k as usize {
                let a = start + j * row + i;
                // (i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1): counter-
                // clockwise in (u, v).
                w.tri(a, a + 1, a + row + 1);
                w.tri(a, a + row + 1, a + row);
            }
        }
    }
}

/// A mesh in caller-visible storage: vertices and index triples.
///
/// ```
/// use softedge::scene3d::{MeshRef, Vertex};
/// let v = [Vertex::default(); 3];
/// let t = [[0u16, 1, 2]];
/// let mesh = MeshRef { vertices: &v, triangles: &t };
/// assert_eq!(mesh.triangles.len(), 1);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct MeshRef<'a> {
    /// Vertices.
    pub vertices: &'a [Vertex],
    /// Triangles, counter-clockwise seen from outside.
    pub triangles: &'a [[u16; 3]],
}

/// A mesh in const-generic storage: at most `V` vertices and `T` triangles.
///
/// ```
/// use softedge::scene3d::{Mesh, SceneError, Shape};
/// use fixed::types::I16F16;
/// let torus = Shape::Torus { major: I16F16::from_num(3), minor: I16F16::ONE, segments: 12, tube_segments: 6 };
/// let mesh = Mesh::<72, 144>::new(&torus).unwrap();
/// assert_eq!(mesh.as_ref().triangles.len(), 144);
/// assert_eq!(Mesh::<71, 144>::new(&torus).err(), Some(SceneError::Capacity { vertices: 72, triangles: 144 }));
/// ```
#[derive(Debug, Clone)]
pub struct Mesh<const V: usize, const T: usize> {
    vertices: [Vertex; V],
    triangles: [[u16; 3]; T],
    nv: usize,
    nt: usize,
}

impl<const V: usize, const T: usize> Mesh<V, T> {
    /// Triangulates `shape`.
    pub fn new(shape: &Shape) -> Result<Self, SceneError> {
        let mut mesh = Self {
            vertices: [Vertex::default(); V],
            triangles: [[0; 3]; T],
            nv: 0,
            nt: 0,
        };
        let (nv, nt) = shape.write(&mut mesh.vertices, &mut mesh.triangles)?;
        mesh.nv = nv;
        mesh.nt = nt;
        Ok(mesh)
    }

    /// The filled part of the storage.
    pub fn as_ref(&self) -> MeshRef<'_> {
        MeshRef {
            vertices: self.vertices.get(..self.nv).unwrap_or(&[]),
            triangles: self.triangles.get(..self.nt).unwrap_or(&[]),
        }
    }
}
