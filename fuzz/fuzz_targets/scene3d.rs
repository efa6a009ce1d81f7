//! The 3D stage: canonical meshes, transforms, cameras and lights from any
//! bytes, projected (both face modes): no panic, every emitted triangle in
//! the coordinate range, then drawn through the z-buffer in bands of two
//! heights (same frame).
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::hsr::{draw_zbuffer, sort_front_to_back, DepthBuffer, DepthTriangle, HsrError};
use softedge::scene3d::{
    project_faces, Angle, Camera, Faces, Light, MeshRef, Part, Shape, Transform, Vec3, Vertex,
    ViewVertex, I16F16,
};
use softedge::{Band, BandBuffer, RenderStyle};
use softedge_fuzz::{assert_band_invariant, Input};

/// A Q16.16 length: mostly small, sometimes anything.
fn length(inp: &mut Input) -> I16F16 {
    match inp.u8() % 4 {
        0 => I16F16::from_bits(inp.u32() as i32),
        _ => I16F16::from_bits(inp.range(-(8 << 16), 8 << 16)),
    }
}

fn vec3(inp: &mut Input) -> Vec3 {
    Vec3::new(length(inp), length(inp), length(inp))
}

fn shape(inp: &mut Input) -> Shape {
    let segments = inp.u16() % 48;
    match inp.u8() % 5 {
        0 => Shape::Sphere {
            radius: length(inp),
            segments,
        },
        1 => Shape::Torus {
            major: length(inp),
            minor: length(inp),
            segments,
            tube_segments: inp.u16() % 32,
        },
        2 => Shape::Cylinder {
            radius: length(inp),
            height: length(inp),
            segments,
        },
        3 => Shape::Cone {
            radius: length(inp),
            height: length(inp),
            segments,
        },
        _ => Shape::Box {
            size: vec3(inp),
            segments: segments % 8,
        },
    }
}

/// The one use of the drawing API: the projected triangles into one band.
fn draw(
    band: &mut BandBuffer<'_, 3>,
    info: Band,
    tris: &[DepthTriangle<3>],
) -> Result<(), HsrError> {
    let n = DepthBuffer::len(info.width, info.rows);
    let (mut depth, mut covered) = (vec![0u16; n], vec![0u16; 2 * n]);
    let mut zbuf = DepthBuffer::new(&mut depth, &mut covered, info).expect("valid band");
    draw_zbuffer(tris, band, &mut zbuf, &RenderStyle::default())
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let (w, h) = (inp.side(64), inp.side(48));
    let (rows_a, rows_b) = (inp.side(h), inp.side(h));
    let shape = shape(&mut inp);
    let Ok((nv, nt)) = shape.counts() else { return };
    let mut vertices = vec![Vertex::default(); nv];
    let mut triangles = vec![[0u16; 3]; nt];
    shape
        .write(&mut vertices, &mut triangles)
        .expect("counts() said it fits");
    let angle = |inp: &mut Input| Angle(inp.u16());
    let transform = Transform::rotation_x(angle(&mut inp))
        .then(&Transform::rotation_y(angle(&mut inp)))
        .and_then(|t| Transform::translation(vec3(&mut inp)).and_then(|p| t.then(&p)));
    let Ok(transform) = transform else { return };
    let mut camera = if inp.bool() {
        Camera::orthographic(
            vec3(&mut inp),
            vec3(&mut inp),
            vec3(&mut inp),
            I16F16::from_bits(inp.range(0, 64 << 16)),
        )
    } else {
        Camera::perspective(
            vec3(&mut inp),
            vec3(&mut inp),
            vec3(&mut inp),
            angle(&mut inp),
        )
    };
    if inp.bool() {
        camera.near = length(&mut inp);
        camera.far = length(&mut inp);
    }
    let Ok(view) = camera.view(w, h) else { return };
    let light = Light::new(vec3(&mut inp), inp.color(), inp.color());
    let faces = if inp.bool() {
        Faces::Front
    } else {
        Faces::Both
    };
    let part = Part {
        mesh: MeshRef {
            vertices: &vertices,
            triangles: &triangles,
        },
        transform: Transform::IDENTITY,
        color: inp.color(),
    };
    let mut scratch = vec![ViewVertex::<3>::EMPTY; nv];
    let mut tris = Vec::new();
    if project_faces(
        &[part],
        &transform,
        &view,
        &light,
        &mut scratch,
        faces,
        |t| tris.push(t),
    )
    .is_err()
    {
        assert!(tris.is_empty(), "an error after triangles were emitted");
        return;
    }
    for t in &tris {
        for v in t.vertices {
            assert!(v.check().is_ok(), "projected vertex out of range: {v:?}");
        }
        assert!(t.colors.iter().flatten().all(|&c| c <= 4095));
    }
    sort_front_to_back(&mut tris);
    let _ = assert_band_invariant(w, h, rows_a, rows_b, [0; 3], |band, info| {
        draw(band, info, &tris)
    });
});
