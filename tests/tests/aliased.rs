//! Aliased drawing: a pixel is lit iff its centre is inside, with the
//! top-left rule for centres exactly on an edge (on a left or top edge:
//! inside; on a right or bottom edge: outside). The reference nudges the
//! centre by `(ε, ε²)` and counts crossings; vertices here are mostly put
//! on pixel centres so that centres fall exactly on edges.

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::{Polygon, PolygonColors, RenderStyle, SubPoint, Triangle};
use softedge_tests::exact::centre_inside_top_left;
use softedge_tests::frame::{render, sub_points, Frame};
use softedge_tests::shapes::{cross, star_polygon};

const W: u16 = 24;
const H: u16 = 24;
const FULL: i32 = 4095 * 65536;

/// A vertex: a pixel centre, a pixel corner, or anywhere (sub-pixels).
fn vertex() -> impl Strategy<Value = (i64, i64)> {
    let span = -2i64..(W as i64 + 2);
    prop_oneof![
        3 => (span.clone(), span.clone()).prop_map(|(x, y)| (16 * x + 8, 16 * y + 8)),
        1 => (span.clone(), span.clone()).prop_map(|(x, y)| (16 * x, 16 * y)),
        1 => (-32i64..(W as i64 * 16 + 32), -32i64..(H as i64 * 16 + 32)),
    ]
}

fn draw_shape(v: &[(i64, i64)]) -> Frame<1> {
    let pts = sub_points(v);
    render(W, H, 5, [0], |buf| {
        if pts.len() == 3 {
            Triangle::flat([pts[0], pts[1], pts[2]], [4095])
                .draw(buf, &RenderStyle::ALIASED)
                .unwrap();
        } else {
            Polygon::new(&pts, PolygonColors::Flat([4095]))
                .draw(buf, &RenderStyle::ALIASED)
                .unwrap();
        }
    })
}

fn check_lit(v: &[(i64, i64)], f: &Frame<1>) -> Result<(), TestCaseError> {
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            let want = centre_inside_top_left(v, i64::from(x), i64::from(y));
            let got = f.raw_at(x, y)[0];
            prop_assert!(got == 0 || got == FULL, "pixel {},{} holds {}", x, y, got);
            prop_assert_eq!(got == FULL, want, "pixel {},{} of {:?}", x, y, v);
        }
    }
    Ok(())
}

#[test]
fn aliased_pixel_lit_iff_centre_inside_top_left() {
    let tri =
        prop::collection::vec(vertex(), 3).prop_filter("area", |v| cross(v[0], v[1], v[2]) != 0);
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(512)
    })
    .run(&tri, |v| check_lit(&v, &draw_shape(&v)))
    .unwrap();
}

#[test]
fn aliased_polygon_lit_iff_centre_inside_top_left() {
    let poly = ((8i64..16, 8i64..16), prop::collection::vec(vertex(), 3..20))
        .prop_filter_map("star", |(c, pts)| {
            star_polygon((16 * c.0 + 8, 16 * c.1 + 3), &pts)
        });
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    })
    .run(&poly, |v| check_lit(&v, &draw_shape(&v)))
    .unwrap();
}

#[test]
fn aliased_shared_edge_claims_every_centre_once() {
    // Two triangles a-b-c and a-c-d sharing the diagonal a-c (through pixel
    // centres): every centre inside the quad is lit by exactly one.
    let quad = prop::collection::vec(vertex(), 4).prop_filter("convex quad", |v| {
        let s = cross(v[0], v[1], v[2]).signum();
        s != 0 && (0..4).all(|k| cross(v[k], v[(k + 1) % 4], v[(k + 2) % 4]).signum() == s)
    });
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(512)
    })
    .run(&quad, |v| {
        let t1 = [v[0], v[1], v[2]];
        let t2 = [v[0], v[2], v[3]];
        let (f1, f2) = (draw_shape(&t1), draw_shape(&t2));
        let both = render(W, H, 5, [0], |buf| {
            for t in [t1, t2] {
                let p = t.map(|(x, y)| SubPoint::new(x as i32, y as i32));
                Triangle::flat(p, [4095])
                    .draw(buf, &RenderStyle::ALIASED)
                    .unwrap();
            }
        });
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let (a, b) = (f1.raw_at(x, y)[0] == FULL, f2.raw_at(x, y)[0] == FULL);
                prop_assert!(!(a && b), "pixel {},{} claimed twice: {:?}", x, y, v);
                let inside = centre_inside_top_left(&v, i64::from(x), i64::from(y));
                prop_assert_eq!(a || b, inside, "pixel {},{} of {:?}", x, y, v);
                let want = if inside { FULL } else { 0 };
                prop_assert_eq!(both.raw_at(x, y)[0], want);
            }
        }
        Ok(())
    })
    .unwrap();
}

#[test]
fn aliased_top_left_rule_on_a_square_of_centres() {
    // Corners on centres (2,2) and (6,5): columns 2..6 and rows 2..5 lit.
    let sq = [(40, 40), (104, 40), (104, 88), (40, 88)];
    let f = draw_shape(&sq);
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            let want = (2..6).contains(&x) && (2..5).contains(&y);
            assert_eq!(f.raw_at(x, y)[0] == FULL, want, "pixel {x},{y}");
        }
    }
}
