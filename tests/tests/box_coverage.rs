//! Exact box mode (SPEC §2): every pixel's coverage of random triangles and
//! simple polygons is within 1/256 px of the exact area (rational
//! Sutherland–Hodgman reference). Flat colour 4095 on background 0, so
//! `raw = 4095 * S` exactly and `raw / 4095` is the coverage in 1/4096 px.

use std::cell::Cell;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::{Polygon, PolygonColors, RenderStyle, Triangle};
use softedge_tests::exact::{q, to_f64, CoverageMap, Q};
use softedge_tests::frame::{render, sub_points, Frame};
use softedge_tests::shapes::{cross, star_polygon};

const W: u16 = 40;
const H: u16 = 40;
/// Vertices range a little outside the frame, so frame clipping is covered.
const LO: i64 = -48;
const HI: i64 = W as i64 * 16 + 48;

fn draw_poly(v: &[(i64, i64)], style: RenderStyle) -> Frame<1> {
    let pts = sub_points(v);
    render(W, H, H, [0], |buf| {
        let r = if pts.len() == 3 {
            Triangle::flat([pts[0], pts[1], pts[2]], [4095]).draw(buf, &style)
        } else {
            Polygon::new(&pts, PolygonColors::Flat([4095])).draw(buf, &style)
        };
        r.expect("simple polygon draws");
    })
}

/// Largest per-pixel `|coverage - exact|` in 1/4096 px.
fn max_coverage_error(v: &[(i64, i64)], f: &Frame<1>) -> Result<(Q, (i32, i32)), TestCaseError> {
    let exact = CoverageMap::new(v, i32::from(W), i32::from(H));
    let mut worst = (q(0), (0, 0));
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            let raw = f.raw_at(x, y)[0];
            prop_assert_eq!(raw % 4095, 0, "flat 4095 accumulates 4095 * S exactly");
            let err = (q(i64::from(raw / 4095)) - exact.at(x, y)).abs();
            if err > worst.0 {
                worst = (err, (x, y));
            }
        }
    }
    Ok(worst)
}

fn triangle() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((LO..HI, LO..HI), 3)
        .prop_filter("non-degenerate", |v| cross(v[0], v[1], v[2]) != 0)
}

/// Star-shaped simple polygons: random points sorted by angle around a
/// centre (concave), or points at one radius (convex when few), 3..=24
/// vertices.
fn star() -> impl Strategy<Value = Vec<(i64, i64)>> {
    let concave = (
        (160i64..480, 160i64..480),
        prop::collection::vec((LO..HI, LO..HI), 3..24),
    )
        .prop_filter_map("kernel", |(c, pts)| star_polygon(c, &pts));
    let convex = (
        (200i64..440, 200i64..440),
        prop::collection::vec(0.0f64..std::f64::consts::TAU, 3..12),
        40.0f64..300.0,
    )
        .prop_filter_map("kernel", |(c, angles, r)| {
            let pts: Vec<(i64, i64)> = angles
                .iter()
                .map(|a| {
                    (
                        c.0 + (r * a.cos()).round() as i64,
                        c.1 + (r * a.sin()).round() as i64,
                    )
                })
                .collect();
            star_polygon(c, &pts)
        });
    prop_oneof![concave, convex]
}

fn run(strategy: impl Strategy<Value = Vec<(i64, i64)>>, cases: u32, what: &str) {
    let max = Cell::new(0.0f64);
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(cases)
    });
    runner
        .run(&strategy, |v| {
            let f = draw_poly(&v, RenderStyle::default());
            let (err, at) = max_coverage_error(&v, &f)?;
            max.set(max.get().max(to_f64(&err)));
            prop_assert!(err <= q(16), "error {} / 4096 at {:?} for {:?}", err, at, v);
            // Orientation does not matter, to the bit.
            let rev: Vec<_> = v.iter().rev().copied().collect();
            prop_assert!(
                draw_poly(&rev, RenderStyle::default()) == f,
                "reversed {:?}",
                v
            );
            Ok(())
        })
        .unwrap();
    eprintln!("{what}: max coverage error {} / 4096 px", max.get());
}

#[test]
fn exact_box_coverage_of_triangles_within_1_256() {
    run(triangle(), 160, "triangles");
}

#[test]
fn exact_box_coverage_of_simple_polygons_within_1_256() {
    run(star(), 128, "star polygons");
}

#[test]
fn exact_box_coverage_of_thin_slivers_and_tiny_triangles_within_1_256() {
    // Triangles smaller than a pixel, and slivers thinner than one, where
    // several edges and vertices share one pixel.
    let tiny = (
        (0i64..600, 0i64..600),
        prop::collection::vec((-20i64..20, -20i64..20), 2),
    )
        .prop_map(|(p, d)| {
            vec![
                p,
                (p.0 + d[0].0, p.1 + d[0].1),
                (p.0 + d[1].0, p.1 + d[1].1),
            ]
        })
        .prop_filter("non-degenerate", |v| cross(v[0], v[1], v[2]) != 0);
    let sliver = (
        (0i64..600, 0i64..600),
        (-400i64..400, -400i64..400),
        (-3i64..3, -3i64..3),
    )
        .prop_map(|(p, d, e)| {
            vec![
                p,
                (p.0 + d.0, p.1 + d.1),
                (p.0 + d.0 + e.0, p.1 + d.1 + e.1),
            ]
        })
        .prop_filter("non-degenerate", |v| cross(v[0], v[1], v[2]) != 0);
    run(prop_oneof![tiny, sliver], 160, "tiny triangles and slivers");
}
