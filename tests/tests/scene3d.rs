//! The 3D geometry stage against independent f64 references: projection,
//! depth, mesh topology, silhouettes, Lambert lighting and bad input.

use std::collections::HashMap;
use std::f64::consts::PI;

use softedge::scene3d::{
    project, project_mesh, Angle, Camera, Light, Mesh, MeshRef, Part, SceneError, ScreenTriangle,
    Shape, Transform, Vec3, Vertex, View, ViewVertex, I16F16, MAX_SEGMENTS,
};
use softedge::{Band, BandBuffer, RenderStyle};

// ---------------------------------------------------------------- helpers

/// Deterministic xorshift generator (tests must not depend on a seed file).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    /// Uniform in `[lo, hi)`.
    fn f(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn fx(v: f64) -> I16F16 {
    I16F16::from_num(v)
}
fn v3(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(fx(x), fx(y), fx(z))
}
fn to_f(v: Vec3) -> [f64; 3] {
    v.to_bits().map(|b| f64::from(b) / 65536.0)
}
fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn unit(a: [f64; 3]) -> [f64; 3] {
    let l = dot(a, a).sqrt();
    a.map(|c| c / l)
}
fn rad(a: Angle) -> f64 {
    f64::from(a.0) / 65536.0 * 2.0 * PI
}

/// f64 model of a transform: rotations about x, y, z (in that order), a
/// uniform scale, a translation.
struct RefTransform {
    angles: [Angle; 3],
    scale: I16F16,
    shift: Vec3,
}

impl RefTransform {
    fn fixed(&self) -> Transform {
        Transform::rotation_x(self.angles[0])
            .then(&Transform::rotation_y(self.angles[1]))
            .and_then(|t| t.then(&Transform::rotation_z(self.angles[2])))
            .and_then(|t| t.then(&Transform::scale(self.scale)?))
            .and_then(|t| t.then(&Transform::translation(self.shift)?))
            .unwrap()
    }
    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        let [a, b, c] = self.angles.map(rad);
        let p = [
            p[0],
            p[1] * a.cos() - p[2] * a.sin(),
            p[1] * a.sin() + p[2] * a.cos(),
        ];
        let p = [
            p[0] * b.cos() + p[2] * b.sin(),
            p[1],
            -p[0] * b.sin() + p[2] * b.cos(),
        ];
        let p = [
            p[0] * c.cos() - p[1] * c.sin(),
            p[0] * c.sin() + p[1] * c.cos(),
            p[2],
        ];
        let s = self.scale.to_num::<f64>();
        let t = to_f(self.shift);
        [p[0] * s + t[0], p[1] * s + t[1], p[2] * s + t[2]]
    }
}

/// f64 model of the camera: screen position in px and distance d.
fn ref_project(cam: &Camera, w: u16, h: u16, p: [f64; 3]) -> ([f64; 2], f64) {
    let eye = to_f(cam.eye);
    let f = unit(sub(to_f(cam.target), eye));
    let r = unit(cross(f, to_f(cam.up)));
    let u = cross(r, f);
    let rel = sub(p, eye);
    let (x, y, d) = (dot(r, rel), dot(u, rel), dot(f, rel));
    let (cx, cy) = (f64::from(w) / 2.0, f64::from(h) / 2.0);
    let k = match cam.projection {
        softedge::scene3d::Projection::Orthographic { px_per_unit } => px_per_unit.to_num::<f64>(),
        softedge::scene3d::Projection::Perspective { fov_y } => {
            let half = rad(Angle(fov_y.0 / 2));
            f64::from(h) / 2.0 / half.tan() / d
        }
    };
    ([cx + k * x, cy - k * y], d)
}

fn render<const C: usize>(w: u16, h: u16, tris: &[ScreenTriangle<C>]) -> Vec<[i32; C]> {
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(w, h)];
    let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, Band::new(w, 0, h)).unwrap();
    buf.clear([0; C]);
    for t in tris {
        t.draw(&mut buf, &RenderStyle::default()).unwrap();
    }
    let mut out = Vec::new();
    for y in 0..i32::from(h) {
        for x in 0..i32::from(w) {
            out.push(buf.raw(x, y).unwrap());
        }
    }
    out
}

/// Covered area in px^2 of a white object on black.
fn area_px(pixels: &[[i32; 1]]) -> f64 {
    pixels.iter().map(|p| f64::from(p[0])).sum::<f64>() / (4095.0 * 65536.0)
}

fn mesh_of(shape: &Shape) -> (Vec<Vertex>, Vec<[u16; 3]>) {
    let (nv, nt) = shape.counts().unwrap();
    let mut v = vec![Vertex::default(); nv];
    let mut t = vec![[0u16; 3]; nt];
    assert_eq!(shape.write(&mut v, &mut t), Ok((nv, nt)));
    (v, t)
}

fn emit_all<const C: usize>(
    mesh: MeshRef<'_>,
    transform: &Transform,
    color: [u16; C],
    view: &View,
    light: &Light<C>,
) -> (Vec<ScreenTriangle<C>>, softedge::scene3d::ProjectStats) {
    let mut scratch = vec![ViewVertex::<C>::EMPTY; mesh.vertices.len()];
    let mut tris = Vec::new();
    let stats = project_mesh(mesh, transform, color, view, light, &mut scratch, |t| {
        tris.push(t)
    })
    .unwrap();
    (tris, stats)
}

/// The shapes at a given level of detail, with their centre for the
/// outward tests (`None`: the torus, whose centre is its tube's).
fn shapes(n: u16) -> Vec<Shape> {
    vec![
        Shape::Sphere {
            radius: fx(3.0),
            segments: n,
        },
        Shape::Torus {
            major: fx(5.0),
            minor: fx(1.5),
            segments: n,
            tube_segments: (n / 2).max(3),
        },
        Shape::Torus {
            major: fx(5.0),
            minor: fx(2.0),
            segments: 3,
            tube_segments: n,
        },
        Shape::Cylinder {
            radius: fx(2.0),
            height: fx(7.0),
            segments: n,
        },
        Shape::Cone {
            radius: fx(2.5),
            height: fx(4.0),
            segments: n,
        },
        Shape::Box {
            size: v3(2.0, 3.0, 5.0),
            segments: (n / 4).max(1),
        },
    ]
}

fn formula(shape: &Shape) -> (usize, usize) {
    match *shape {
        Shape::Sphere { segments, .. } => {
            let n = usize::from(segments);
            let m = (n / 2).max(2);
            (n * (m - 1) + 2, 2 * n * (m - 1))
        }
        Shape::Torus {
            segments,
            tube_segments,
            ..
        } => {
            let nm = usize::from(segments) * usize::from(tube_segments);
            (nm, 2 * nm)
        }
        Shape::Cylinder { segments, .. } => {
            (4 * usize::from(segments) + 2, 4 * usize::from(segments))
        }
        Shape::Cone { segments, .. } => (3 * usize::from(segments) + 1, 2 * usize::from(segments)),
        Shape::Box { segments, .. } => {
            let k = usize::from(segments);
            (6 * (k + 1) * (k + 1), 12 * k * k)
        }
    }
}

/// Where outward is measured from, for a vertex or triangle centroid at `p`.
fn centre_of(shape: &Shape, p: [f64; 3]) -> [f64; 3] {
    match *shape {
        Shape::Torus { major, .. } => {
            let t = p[1].atan2(p[0]);
            let r = major.to_num::<f64>();
            [r * t.cos(), r * t.sin(), 0.0]
        }
        _ => [0.0; 3],
    }
}

// ---------------------------------------------------------------- projection

#[test]
fn orthographic_projection_matches_f64_reference_within_a_sixteenth_px() {
    let mut rng = Rng(0x5eed_0001);
    let (w, h) = (1024u16, 1024u16);
    let mut worst = 0.0f64;
    for _ in 0..200 {
        let rt = RefTransform {
            angles: [0; 3].map(|_| Angle(rng.next() as u16)),
            scale: fx(rng.f(0.25, 4.0)),
            shift: v3(rng.f(-20.0, 20.0), rng.f(-20.0, 20.0), rng.f(-20.0, 20.0)),
        };
        let t = rt.fixed();
        let eye = v3(
            rng.f(-300.0, 300.0),
            rng.f(-300.0, 300.0),
            rng.f(-300.0, 300.0),
        );
        let cam = Camera::orthographic(
            eye,
            v3(rng.f(-5.0, 5.0), 0.0, 0.0),
            v3(0.0, 1.0, 0.0),
            fx(rng.f(0.5, 8.0)),
        );
        let Ok(view) = cam.view(w, h) else { continue };
        for _ in 0..20 {
            let p = v3(rng.f(-12.0, 12.0), rng.f(-12.0, 12.0), rng.f(-12.0, 12.0));
            let (want, d) = ref_project(&cam, w, h, rt.apply(to_f(p)));
            if d < 1.0 || want.iter().any(|c| (*c - 512.0).abs() > 512.0) {
                continue; // behind the eye, or off the 1024 px image
            }
            let (got, _) = view.project_point(t.apply(p).unwrap()).unwrap();
            let e = (f64::from(got.x) / 16.0 - want[0])
                .abs()
                .max((f64::from(got.y) / 16.0 - want[1]).abs());
            worst = worst.max(e);
        }
    }
    println!("orthographic worst error {worst:.4} px");
    assert!(worst <= 1.0 / 16.0, "worst error {worst} px");
}

#[test]
fn perspective_projection_matches_f64_reference_within_a_sixteenth_px() {
    let mut rng = Rng(0x5eed_0002);
    let (w, h) = (1024u16, 768u16);
    let mut worst = 0.0f64;
    let mut checked = 0;
    for _ in 0..200 {
        let rt = RefTransform {
            angles: [0; 3].map(|_| Angle(rng.next() as u16)),
            scale: fx(rng.f(0.25, 2.0)),
            shift: v3(rng.f(-5.0, 5.0), rng.f(-5.0, 5.0), rng.f(-5.0, 5.0)),
        };
        let t = rt.fixed();
        let dir = unit([rng.f(-1.0, 1.0), rng.f(-1.0, 1.0), rng.f(-1.0, 1.0)]);
        let dist = rng.f(30.0, 200.0);
        let eye = v3(dir[0] * dist, dir[1] * dist, dir[2] * dist);
        let fov = Angle::from_degrees(rng.f(20.0, 100.0) as i32);
        let cam = Camera::perspective(eye, Vec3::ZERO, v3(0.0, 0.0, 1.0), fov);
        let Ok(view) = cam.view(w, h) else { continue };
        for _ in 0..20 {
            let p = v3(rng.f(-8.0, 8.0), rng.f(-8.0, 8.0), rng.f(-8.0, 8.0));
            let (want, d) = ref_project(&cam, w, h, rt.apply(to_f(p)));
            if d < 1.0 || want[0].abs() > 2000.0 || want[1].abs() > 2000.0 {
                continue;
            }
            let (got, _) = view.project_point(t.apply(p).unwrap()).unwrap();
            let e = (f64::from(got.x) / 16.0 - want[0])
                .abs()
                .max((f64::from(got.y) / 16.0 - want[1]).abs());
            worst = worst.max(e);
            checked += 1;
        }
    }
    println!("perspective worst error {worst:.4} px over {checked} points");
    assert!(checked > 1000);
    assert!(worst <= 1.0 / 16.0, "worst error {worst} px");
}

#[test]
fn depth_is_monotonic_with_distance() {
    let mut rng = Rng(0x5eed_0003);
    for cam in [
        Camera::orthographic(
            v3(3.0, 40.0, 70.0),
            v3(0.0, 0.0, 0.0),
            v3(0.0, 1.0, 0.0),
            fx(2.0),
        ),
        Camera::perspective(
            v3(3.0, 40.0, 70.0),
            v3(0.0, 0.0, 0.0),
            v3(0.0, 1.0, 0.0),
            Angle::from_degrees(60),
        ),
    ] {
        let cam = Camera {
            near: fx(0.5),
            far: fx(400.0),
            ..cam
        };
        let view = cam.view(320, 240).unwrap();
        let mut samples = Vec::new();
        for _ in 0..5000 {
            let p = v3(rng.f(-60.0, 60.0), rng.f(-60.0, 60.0), rng.f(-60.0, 60.0));
            if let Some((_, z)) = view.project_point(p) {
                samples.push((ref_project(&cam, 320, 240, to_f(p)).1, z));
            }
        }
        // Along the axis, nearest first, with the ends of the range.
        let eye = to_f(cam.eye);
        let f = unit(sub([0.0; 3], eye));
        for k in 0..=400 {
            let d = 0.5 + f64::from(k);
            let p = [eye[0] + f[0] * d, eye[1] + f[1] * d, eye[2] + f[2] * d];
            if let Some((_, z)) = view.project_point(v3(p[0], p[1], p[2])) {
                samples.push((d, z));
            }
        }
        samples.sort_by(|a, b| a.0.total_cmp(&b.0));
        assert!(samples.len() > 2000);
        for pair in samples.windows(2) {
            if pair[1].0 - pair[0].0 > 1e-3 {
                assert!(
                    pair[1].1 <= pair[0].1,
                    "depth rises with distance: {pair:?}"
                );
            }
        }
        assert!(samples[0].1 >= 65000, "near end {:?}", samples[0]);
        assert!(
            samples.last().unwrap().1 <= 100,
            "far end {:?}",
            samples.last()
        );
    }
}

// ---------------------------------------------------------------- meshes

#[test]
fn vertex_and_triangle_counts_match_the_documented_formulas() {
    for n in 3..=64 {
        for s in shapes(n) {
            let (v, t) = mesh_of(&s);
            assert_eq!((v.len(), t.len()), formula(&s), "{s:?}");
        }
    }
    // The largest detail that fits the u16 indices, and one beyond.
    // 362 * 180 + 2 = 65162 vertices fit; 364 * 181 + 2 = 65886 do not.
    let big = Shape::Sphere {
        radius: fx(1.0),
        segments: 362,
    };
    assert_eq!(big.counts(), Ok(formula(&big)));
    let bigger = Shape::Sphere {
        radius: fx(1.0),
        segments: 364,
    };
    assert_eq!(bigger.counts(), Err(SceneError::Segments));
    let finest = Shape::Cone {
        radius: fx(1.0),
        height: fx(1.0),
        segments: MAX_SEGMENTS,
    };
    assert_eq!(finest.counts(), Ok(formula(&finest)));
    let torus = Shape::Torus {
        major: fx(2.0),
        minor: fx(1.0),
        segments: 256,
        tube_segments: 257,
    };
    assert_eq!(torus.counts(), Err(SceneError::Segments));
}

#[test]
fn every_canonical_mesh_is_closed_and_consistently_wound() {
    for n in 3..=48 {
        for s in shapes(n) {
            let (v, t) = mesh_of(&s);
            // Weld equal positions.
            let mut ids: HashMap<[i32; 3], usize> = HashMap::new();
            let weld: Vec<usize> = v
                .iter()
                .map(|x| {
                    let k = ids.len();
                    *ids.entry(x.position.to_bits()).or_insert(k)
                })
                .collect();
            let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
            for tri in &t {
                let w = tri.map(|i| weld[usize::from(i)]);
                for k in 0..3 {
                    let e = (w[k], w[(k + 1) % 3]);
                    assert_ne!(e.0, e.1, "degenerate edge in {s:?}");
                    *edges.entry(e).or_default() += 1;
                }
            }
            for (&(a, b), &count) in &edges {
                assert_eq!(count, 1, "directed edge used {count} times in {s:?}");
                assert_eq!(
                    edges.get(&(b, a)),
                    Some(&1),
                    "edge without its reverse in {s:?}"
                );
            }
            // Euler characteristic of a sphere (2) or a torus (0).
            let euler = ids.len() as i64 - edges.len() as i64 / 2 + t.len() as i64;
            let want = if matches!(s, Shape::Torus { .. }) {
                0
            } else {
                2
            };
            assert_eq!(euler, want, "{s:?}");
        }
    }
}

#[test]
fn normals_and_windings_of_every_canonical_mesh_point_outwards() {
    for n in 3..=48 {
        for s in shapes(n) {
            let (v, t) = mesh_of(&s);
            for x in &v {
                let p = to_f(x.position);
                let nrm = to_f(x.normal);
                assert!(
                    (dot(nrm, nrm).sqrt() - 1.0).abs() < 1e-4,
                    "normal length in {s:?}"
                );
                assert!(
                    dot(nrm, sub(p, centre_of(&s, p))) > 0.0,
                    "inward normal at {p:?} in {s:?}"
                );
            }
            for tri in &t {
                let [a, b, c] = tri.map(|i| to_f(v[usize::from(i)].position));
                let out = cross(sub(b, a), sub(c, a));
                // Agrees with its vertices' outward normals ...
                let nsum = tri.iter().fold([0.0; 3], |acc, &i| {
                    let n = to_f(v[usize::from(i)].normal);
                    [acc[0] + n[0], acc[1] + n[1], acc[2] + n[2]]
                });
                assert!(
                    dot(out, nsum) > 0.0,
                    "triangle {tri:?} against its normals in {s:?}"
                );
                // ... and, for the convex shapes, points away from the centre.
                if !matches!(s, Shape::Torus { .. }) {
                    let g = [0, 1, 2].map(|k| (a[k] + b[k] + c[k]) / 3.0);
                    assert!(dot(out, g) > 0.0, "inward triangle {tri:?} in {s:?}");
                }
            }
        }
    }
}

// ---------------------------------------------------------------- silhouettes

fn ngon_area(r: f64, n: usize) -> f64 {
    0.5 * n as f64 * r * r * (2.0 * PI / n as f64).sin()
}

#[test]
fn sphere_covers_between_its_inscribed_polygon_and_its_circle() {
    let (w, h) = (96u16, 96u16);
    let s_px = 10.0;
    let radius = 4.0;
    for n in [3u16, 4, 5, 6, 8, 12, 16, 24, 32, 48, 64] {
        let shape = Shape::Sphere {
            radius: fx(radius),
            segments: n,
        };
        let (v, t) = mesh_of(&shape);
        // Looking down the pole axis: the silhouette is the ring nearest the
        // equator, an n-gon of radius r sin(pi i / m).
        let cam =
            Camera::orthographic(v3(0.0, 50.0, 0.0), Vec3::ZERO, v3(0.0, 0.0, -1.0), fx(s_px));
        let view = cam.view(w, h).unwrap();
        let mesh = MeshRef {
            vertices: &v,
            triangles: &t,
        };
        let (tris, stats) = emit_all(mesh, &Transform::IDENTITY, [4095], &view, &Light::FLAT);
        assert_eq!(stats.off_range + stats.clipped, 0);
        let area = area_px(&render(w, h, &tris));
        let m = (usize::from(n) / 2).max(2);
        let ring = radius * s_px * (PI * (m / 2) as f64 / m as f64).sin();
        let polygon = ngon_area(ring, usize::from(n));
        let circle = PI * (radius * s_px).powi(2);
        // Vertices are rounded to 1/16 px: at most 1/32 px off each way.
        let tol = 2.0 * PI * radius * s_px * (2f64.sqrt() / 32.0);
        println!("sphere n={n}: area {area:.3}, polygon {polygon:.3}, circle {circle:.3}");
        assert!(
            (area - polygon).abs() <= tol,
            "n={n}: {area} vs polygon {polygon}"
        );
        assert!(area <= circle + tol && area >= polygon - tol);
    }
}

#[test]
fn torus_seen_along_its_axis_covers_its_annulus() {
    let (w, h) = (128u16, 128u16);
    let s_px = 6.0;
    let (big, small) = (6.0, 2.5);
    for (n, m) in [(3u16, 3u16), (8, 4), (12, 5), (24, 8), (48, 12), (64, 7)] {
        let shape = Shape::Torus {
            major: fx(big),
            minor: fx(small),
            segments: n,
            tube_segments: m,
        };
        let (v, t) = mesh_of(&shape);
        let cam = Camera::orthographic(v3(0.0, 0.0, 60.0), Vec3::ZERO, v3(0.0, 1.0, 0.0), fx(s_px));
        let view = cam.view(w, h).unwrap();
        let mesh = MeshRef {
            vertices: &v,
            triangles: &t,
        };
        let (tris, _) = emit_all(mesh, &Transform::IDENTITY, [4095], &view, &Light::FLAT);
        let area = area_px(&render(w, h, &tris));
        let (n, m) = (usize::from(n), usize::from(m));
        // Outer outline: the ring at tube angle 0; inner: the ring nearest
        // tube angle pi.
        let inner_cos = (0..m)
            .map(|i| (2.0 * PI * i as f64 / m as f64).cos())
            .fold(1.0, f64::min);
        let outer = (big + small) * s_px;
        let inner = (big + small * inner_cos) * s_px;
        let exact = ngon_area(outer, n) - ngon_area(inner, n);
        let annulus = PI * (outer * outer - (big - small).powi(2) * s_px * s_px);
        let tol = 2.0 * PI * (outer + inner) * (2f64.sqrt() / 32.0);
        println!("torus n={n} m={m}: area {area:.3}, polygonal {exact:.3}, annulus {annulus:.3}");
        assert!((area - exact).abs() <= tol, "{area} vs {exact}");
        assert!(area <= PI * outer * outer - ngon_area(inner, n) + tol);
        // Between the polygons and the circles through their vertices (for
        // odd m the innermost ring lies outside the true hole, radius R - r).
        assert!(area >= ngon_area(outer, n) - PI * inner * inner - tol);
        assert!(inner >= (big - small) * s_px);
    }
}

// ---------------------------------------------------------------- lighting

#[test]
fn flat_light_gives_every_visible_point_the_object_colour() {
    let shape = Shape::Torus {
        major: fx(3.0),
        minor: fx(1.0),
        segments: 24,
        tube_segments: 12,
    };
    let (v, t) = mesh_of(&shape);
    let cam = Camera::perspective(
        v3(4.0, 7.0, 9.0),
        Vec3::ZERO,
        v3(0.0, 1.0, 0.0),
        Angle::from_degrees(50),
    );
    let view = cam.view(64, 64).unwrap();
    let rot = Transform::rotation_x(Angle::from_degrees(33))
        .then(&Transform::scale_xyz(v3(1.0, 2.0, 0.5)).unwrap())
        .unwrap();
    let color = [4095, 1234, 7];
    let (tris, _) = emit_all(
        MeshRef {
            vertices: &v,
            triangles: &t,
        },
        &rot,
        color,
        &view,
        &Light::FLAT,
    );
    assert!(!tris.is_empty());
    assert!(tris.iter().all(|t| t.colors == [color; 3]));
    // And so every fully covered pixel has exactly that colour.
    let px = render(64, 64, &tris);
    let full = px
        .iter()
        .filter(|p| p[0] == 4095 * 65536)
        .collect::<Vec<_>>();
    assert!(full.len() > 100);
    assert!(full
        .iter()
        .all(|p| **p == [4095 * 65536, 1234 * 65536, 7 * 65536]));
}

/// One triangle facing the camera whose three vertices all carry normal `n`.
fn lit_color(
    n: [f64; 3],
    light: &Light<3>,
    base: [u16; 3],
    rot: &RefTransform,
) -> Option<[u16; 3]> {
    let nq = v3(n[0], n[1], n[2]);
    let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]].map(|p| Vertex {
        position: v3(p[0], p[1], p[2]),
        normal: nq,
    });
    let t = [[0u16, 1, 2]];
    // The camera looks at the rotated triangle's front.
    let front = rot.apply([0.0, 0.0, 10.0]);
    let up = sub(rot.apply([0.0, 1.0, 0.0]), rot.apply([0.0; 3]));
    let cam = Camera::orthographic(
        v3(front[0], front[1], front[2]),
        rot.fixed().apply(Vec3::ZERO).unwrap(),
        v3(up[0], up[1], up[2]),
        fx(8.0),
    );
    let view = cam.view(64, 64).unwrap();
    let mut scratch = [ViewVertex::<3>::EMPTY; 3];
    let mut out = None;
    let part = Part {
        mesh: MeshRef {
            vertices: &v,
            triangles: &t,
        },
        transform: rot.fixed(),
        color: base,
    };
    project(
        &[part],
        &Transform::IDENTITY,
        &view,
        light,
        &mut scratch,
        |s| out = Some(s.colors[0]),
    )
    .unwrap();
    out
}

#[test]
fn lambert_intensity_follows_the_cosine_within_one_step() {
    let mut rng = Rng(0x5eed_0004);
    let mut worst = 0.0f64;
    for _ in 0..2000 {
        let rot = RefTransform {
            angles: [0; 3].map(|_| Angle(rng.next() as u16)),
            scale: fx(rng.f(0.5, 3.0)),
            shift: v3(rng.f(-9.0, 9.0), rng.f(-9.0, 9.0), rng.f(-9.0, 9.0)),
        };
        let n = unit([rng.f(-1.0, 1.0), rng.f(-1.0, 1.0), rng.f(-1.0, 1.0)]);
        let l = [rng.f(-5.0, 5.0), rng.f(-5.0, 5.0), rng.f(-5.0, 5.0)];
        let amb = [0; 3].map(|_| (rng.next() % 2048) as u16);
        let dif = [0; 3].map(|_| (rng.next() % 4097) as u16);
        let base = [0; 3].map(|_| (rng.next() % 4096) as u16);
        let light = Light::new(v3(l[0], l[1], l[2]), amb, dif);
        let Some(got) = lit_color(n, &light, base, &rot) else {
            continue;
        };
        // Reference: the normal rotated (uniform scale keeps directions).
        let nw = unit(sub(
            rot.apply(to_f(v3(n[0], n[1], n[2]))),
            rot.apply([0.0; 3]),
        ));
        let cos = dot(nw, unit(to_f(light.to_light))).max(0.0);
        for k in 0..3 {
            let want = f64::from(base[k]) * (f64::from(amb[k]) + f64::from(dif[k]) * cos) / 4096.0;
            let e = (f64::from(got[k]) - want.min(4095.0)).abs();
            worst = worst.max(e);
        }
    }
    println!("Lambert worst error {worst:.4} steps");
    assert!(worst <= 1.0, "{worst}");
}

#[test]
fn lambert_brightest_vertex_faces_the_light() {
    let shape = Shape::Sphere {
        radius: fx(5.0),
        segments: 32,
    };
    let (v, t) = mesh_of(&shape);
    let to_light = [1.0, 2.0, 3.0];
    let light = Light::new(v3(to_light[0], to_light[1], to_light[2]), [0], [4096]);
    // Look from the light's side so the lit hemisphere is visible.
    let eye = to_light.map(|c| c * 20.0);
    let cam = Camera::orthographic(
        v3(eye[0], eye[1], eye[2]),
        Vec3::ZERO,
        v3(0.0, 1.0, 0.0),
        fx(4.0),
    );
    let view = cam.view(64, 64).unwrap();
    let (tris, _) = emit_all(
        MeshRef {
            vertices: &v,
            triangles: &t,
        },
        &Transform::IDENTITY,
        [4000],
        &view,
        &light,
    );
    // Match emitted corners back to front-facing mesh vertices.
    let l = unit(to_light);
    let by_screen: HashMap<_, _> = v
        .iter()
        .filter(|x| dot(to_f(x.normal), l) > 0.05)
        .filter_map(|x| Some((view.project_point(x.position)?.0, dot(to_f(x.normal), l))))
        .collect();
    let (mut best_cos, mut best_color, mut max_color) = (f64::MIN, 0, 0);
    for tri in &tris {
        for k in 0..3 {
            max_color = max_color.max(tri.colors[k][0]);
            if let Some(&c) = by_screen.get(&tri.vertices[k]) {
                if c > best_cos {
                    best_cos = c;
                    best_color = tri.colors[k][0];
                }
            }
        }
    }
    let best = v
        .iter()
        .map(|x| dot(to_f(x.normal), l))
        .fold(f64::MIN, f64::max);
    assert_eq!(best_cos, best, "the vertex nearest the light was emitted");
    assert_eq!(best_color, max_color, "and it is the brightest");
    assert!((f64::from(max_color) - 4000.0 * best).abs() <= 1.0);
}

// ---------------------------------------------------------------- composites, clipping

#[test]
fn composite_object_emits_exactly_its_parts() {
    let body = Mesh::<42, 40>::new(&Shape::Cylinder {
        radius: fx(1.0),
        height: fx(6.0),
        segments: 10,
    })
    .unwrap();
    let tip = Mesh::<31, 20>::new(&Shape::Cone {
        radius: fx(1.0),
        height: fx(2.0),
        segments: 10,
    })
    .unwrap();
    let tip_at = Transform::translation(v3(0.0, 4.0, 0.0)).unwrap();
    let parts = [
        Part {
            mesh: body.as_ref(),
            transform: Transform::IDENTITY,
            color: [3000],
        },
        Part {
            mesh: tip.as_ref(),
            transform: tip_at,
            color: [1000],
        },
    ];
    let object = Transform::rotation_z(Angle::from_degrees(-60))
        .then(&Transform::translation(v3(1.0, 0.0, 0.0)).unwrap())
        .unwrap();
    let cam = Camera::perspective(
        v3(2.0, 3.0, 20.0),
        Vec3::ZERO,
        v3(0.0, 1.0, 0.0),
        Angle::from_degrees(45),
    );
    let view = cam.view(80, 60).unwrap();
    let light = Light::new(v3(-1.0, 1.0, 2.0), [400], [3600]);
    let mut scratch = vec![ViewVertex::<1>::EMPTY; 73];
    let mut whole = Vec::new();
    let stats = project(&parts, &object, &view, &light, &mut scratch, |t| {
        whole.push(t)
    })
    .unwrap();
    assert_eq!(stats.emitted, whole.len());
    assert_eq!(stats.emitted + stats.back_facing, 60);
    let mut separate = Vec::new();
    for p in &parts {
        let t = p.transform.then(&object).unwrap();
        separate.extend(emit_all(p.mesh, &t, p.color, &view, &light).0);
    }
    assert_eq!(whole, separate);
    assert_eq!(
        project(&parts, &object, &view, &light, &mut scratch[..72], |_| {}),
        Err(SceneError::Scratch { needed: 73 })
    );
}

#[test]
fn near_plane_cuts_a_triangle_into_the_part_in_front() {
    // A floor triangle under a camera at the origin looking down -z.
    let cam = Camera {
        near: fx(1.0),
        ..Camera::perspective(
            Vec3::ZERO,
            v3(0.0, 0.0, -1.0),
            v3(0.0, 1.0, 0.0),
            Angle::from_degrees(90),
        )
    };
    let view = cam.view(64, 64).unwrap();
    let n = v3(0.0, 1.0, 0.0);
    let vx = |x: f64, z: f64| Vertex {
        position: v3(x, -1.0, z),
        normal: n,
    };
    let light = Light::<1>::FLAT;
    // One vertex behind the eye: the front part is a quad, two triangles.
    let v = [vx(0.0, 3.0), vx(3.0, -6.0), vx(-3.0, -6.0)];
    let (tris, stats) = emit_all(
        MeshRef {
            vertices: &v,
            triangles: &[[0, 1, 2]],
        },
        &Transform::IDENTITY,
        [4095],
        &view,
        &light,
    );
    assert_eq!((tris.len(), stats.emitted), (2, 2), "{stats:?}");
    let nearest = tris.iter().flat_map(|t| t.depth).max().unwrap();
    assert_eq!(nearest, 65535, "the cut lies on the near plane");
    // Two behind: one triangle; three behind: nothing, counted as clipped.
    let v = [vx(0.0, -6.0), vx(3.0, 3.0), vx(-3.0, 3.0)];
    let (tris, _) = emit_all(
        MeshRef {
            vertices: &v,
            triangles: &[[0, 2, 1]],
        },
        &Transform::IDENTITY,
        [4095],
        &view,
        &light,
    );
    assert_eq!(tris.len(), 1);
    let v = [vx(0.0, 6.0), vx(3.0, 3.0), vx(-3.0, 3.0)];
    let (tris, stats) = emit_all(
        MeshRef {
            vertices: &v,
            triangles: &[[0, 2, 1]],
        },
        &Transform::IDENTITY,
        [4095],
        &view,
        &light,
    );
    assert_eq!((tris.len(), stats.clipped), (0, 1));
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_shapes_are_typed_errors() {
    let neg = fx(-1.0);
    for s in [
        Shape::Sphere {
            radius: I16F16::ZERO,
            segments: 8,
        },
        Shape::Sphere {
            radius: neg,
            segments: 8,
        },
        Shape::Torus {
            major: fx(2.0),
            minor: I16F16::ZERO,
            segments: 8,
            tube_segments: 8,
        },
        Shape::Cylinder {
            radius: fx(1.0),
            height: neg,
            segments: 8,
        },
        Shape::Cone {
            radius: neg,
            height: fx(1.0),
            segments: 8,
        },
        Shape::Box {
            size: v3(1.0, 0.0, 1.0),
            segments: 1,
        },
    ] {
        assert_eq!(s.counts(), Err(SceneError::NonPositive), "{s:?}");
    }
    for s in [
        Shape::Sphere {
            radius: fx(1.0),
            segments: 0,
        },
        Shape::Sphere {
            radius: fx(1.0),
            segments: 2,
        },
        Shape::Cone {
            radius: fx(1.0),
            height: fx(1.0),
            segments: MAX_SEGMENTS + 1,
        },
        Shape::Box {
            size: v3(1.0, 1.0, 1.0),
            segments: 0,
        },
        Shape::Box {
            size: v3(1.0, 1.0, 1.0),
            segments: 200,
        },
    ] {
        assert_eq!(s.counts(), Err(SceneError::Segments), "{s:?}");
    }
    assert_eq!(
        Shape::Sphere {
            radius: fx(5000.0),
            segments: 8
        }
        .counts(),
        Err(SceneError::OutOfRange)
    );
    assert_eq!(
        Shape::Torus {
            major: fx(2.0),
            minor: fx(2.0),
            segments: 8,
            tube_segments: 8
        }
        .counts(),
        Err(SceneError::OutOfRange)
    );
    // Storage one short: the error names what is needed, nothing is written.
    let s = Shape::Cylinder {
        radius: fx(1.0),
        height: fx(1.0),
        segments: 6,
    };
    let mut v = [Vertex::default(); 26];
    let mut t = [[7u16; 3]; 23];
    assert_eq!(
        s.write(&mut v, &mut t),
        Err(SceneError::Capacity {
            vertices: 26,
            triangles: 24
        })
    );
    assert!(t.iter().all(|x| *x == [7; 3]));
    assert!(Mesh::<26, 23>::new(&s).is_err());
}

#[test]
fn bad_cameras_are_typed_errors() {
    let up = v3(0.0, 1.0, 0.0);
    let eye = v3(0.0, 0.0, 5.0);
    let o = |e, t, u| Camera::orthographic(e, t, u, fx(4.0)).view(64, 64).err();
    assert_eq!(o(eye, eye, up), Some(SceneError::EyeAtTarget));
    assert_eq!(
        o(eye, Vec3::ZERO, v3(0.0, 0.0, 3.0)),
        Some(SceneError::UpParallel)
    );
    assert_eq!(
        o(eye, Vec3::ZERO, v3(0.0, 0.0, -1.0)),
        Some(SceneError::UpParallel)
    );
    assert_eq!(o(eye, Vec3::ZERO, Vec3::ZERO), Some(SceneError::UpParallel));
    assert_eq!(
        o(v3(5000.0, 0.0, 0.0), Vec3::ZERO, up),
        Some(SceneError::OutOfRange)
    );
    assert_eq!(
        Camera::orthographic(eye, Vec3::ZERO, up, fx(0.0))
            .view(64, 64)
            .err(),
        Some(SceneError::NonPositive)
    );
    assert_eq!(
        Camera::orthographic(eye, Vec3::ZERO, up, fx(4.0))
            .view(0, 64)
            .err(),
        Some(SceneError::OutOfRange)
    );
    for fov in [
        Angle(0),
        Angle::from_degrees(180),
        Angle::from_degrees(270),
        Angle(1),
    ] {
        assert_eq!(
            Camera::perspective(eye, Vec3::ZERO, up, fov)
                .view(64, 64)
                .err(),
            Some(SceneError::FieldOfView),
            "{fov:?}"
        );
    }
    let c = Camera::perspective(eye, Vec3::ZERO, up, Angle::from_degrees(60));
    assert_eq!(
        Camera { near: fx(0.0), ..c }.view(64, 64).err(),
        Some(SceneError::NonPositive)
    );
    assert_eq!(
        Camera { far: fx(0.01), ..c }.view(64, 64).err(),
        Some(SceneError::NonPositive)
    );
}

#[test]
fn objects_behind_the_camera_or_beyond_range_give_documented_results() {
    let ball = Mesh::<58, 112>::new(&Shape::Sphere {
        radius: fx(1.0),
        segments: 8,
    })
    .unwrap();
    let cam = Camera::perspective(
        v3(0.0, 0.0, 5.0),
        Vec3::ZERO,
        v3(0.0, 1.0, 0.0),
        Angle::from_degrees(60),
    );
    let view = cam.view(64, 64).unwrap();
    let light = Light::new(v3(0.0, 0.0, 1.0), [1000], [3000]);
    let behind = Transform::translation(v3(0.0, 0.0, 20.0)).unwrap();
    let (tris, stats) = emit_all(ball.as_ref(), &behind, [4095], &view, &light);
    assert!(tris.is_empty());
    assert_eq!(stats.clipped, ball.as_ref().triangles.len());
    // Almost touching the eye: projected far outside the coordinate range.
    let at_eye = Transform::scale(fx(0.05))
        .unwrap()
        .then(&Transform::translation(v3(0.3, 0.0, 4.9)).unwrap())
        .unwrap();
    let (tris, stats) = emit_all(ball.as_ref(), &at_eye, [4095], &view, &light);
    assert!(tris
        .iter()
        .all(|t| t.vertices.iter().all(|p| p.check().is_ok())));
    println!("near the eye: {stats:?}");
    // Beyond the world range: an error before anything is emitted.
    let far = Transform::scale(fx(1000.0))
        .unwrap()
        .then(&Transform::translation(v3(4000.0, 0.0, 0.0)).unwrap())
        .unwrap();
    let mut scratch = [ViewVertex::<1>::EMPTY; 58];
    let mut n = 0;
    let r = project_mesh(
        ball.as_ref(),
        &far,
        [4095],
        &view,
        &light,
        &mut scratch,
        |_| n += 1,
    );
    assert_eq!((r, n), (Err(SceneError::OutOfRange), 0));
    // A bad index and a zero light direction.
    let v = [Vertex::default(); 2];
    let r = project_mesh(
        MeshRef {
            vertices: &v,
            triangles: &[[0, 1, 2]],
        },
        &Transform::IDENTITY,
        [1],
        &view,
        &light,
        &mut scratch,
        |_| {},
    );
    assert_eq!(r, Err(SceneError::BadIndex));
    let dark = Light::new(Vec3::ZERO, [0], [1]);
    let r = project_mesh(
        ball.as_ref(),
        &Transform::IDENTITY,
        [1],
        &view,
        &dark,
        &mut scratch,
        |_| {},
    );
    assert_eq!(r, Err(SceneError::ZeroDirection));
}
