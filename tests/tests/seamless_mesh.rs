//! Accumulation (SPEC §4, seed 000 eq. 3): primitives sharing edges sum to
//! exactly the coverage of their union. An axis-aligned square with
//! sub-pixel corners drawn as one polygon, as 2 triangles, as a
//! 64-triangle fan and as a random triangulation gives the same raw
//! buffer to the last bit, anti-aliased (both box models) and aliased.

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::{PixelModel, Polygon, PolygonColors, RenderStyle, Triangle};
use softedge_tests::frame::{render, sub_points, Frame};
use softedge_tests::shapes::{rectangle_boundary, triangulate};

const W: u16 = 32;
const H: u16 = 32;

#[derive(Debug, Clone)]
struct Scene {
    x0: i64,
    y0: i64,
    x1: i64,
    y1: i64,
    color: u16,
    bg: u16,
    picks: Vec<u64>,
    centre: (u64, u64),
    interior: Vec<(u64, u64)>,
}

fn scene() -> impl Strategy<Value = Scene> {
    (
        (-40i64..200, -40i64..200),
        (64i64..360, 64i64..360),
        0u16..=4095,
        0u16..=4095,
        prop::collection::vec(any::<u64>(), 60..=60),
        (any::<u64>(), any::<u64>()),
        prop::collection::vec((any::<u64>(), any::<u64>()), 0..40),
    )
        .prop_map(
            |((x0, y0), (w, h), color, bg, picks, centre, interior)| Scene {
                x0,
                y0,
                x1: x0 + w,
                y1: y0 + h,
                color,
                bg,
                picks,
                centre,
                interior,
            },
        )
}

/// A point strictly inside the square from two random numbers.
fn inside(s: &Scene, r: (u64, u64)) -> (i64, i64) {
    let (w, h) = ((s.x1 - s.x0 - 1) as u64, (s.y1 - s.y0 - 1) as u64);
    (s.x0 + 1 + (r.0 % w) as i64, s.y0 + 1 + (r.1 % h) as i64)
}

fn draw_tris(s: &Scene, tris: &[[(i64, i64); 3]], style: RenderStyle) -> Frame<1> {
    render(W, H, 8, [s.bg], |buf| {
        for t in tris {
            let v = sub_points(t);
            Triangle::flat([v[0], v[1], v[2]], [s.color])
                .draw(buf, &style)
                .unwrap();
        }
    })
}

fn check(s: &Scene, style: RenderStyle) -> Result<(), TestCaseError> {
    let corners = [(s.x0, s.y0), (s.x1, s.y0), (s.x1, s.y1), (s.x0, s.y1)];
    let whole = render(W, H, 8, [s.bg], |buf| {
        Polygon::new(&sub_points(&corners), PolygonColors::Flat([s.color]))
            .draw(buf, &style)
            .unwrap();
    });
    let two = draw_tris(
        s,
        &[
            [corners[0], corners[1], corners[2]],
            [corners[0], corners[2], corners[3]],
        ],
        style,
    );
    prop_assert!(two == whole, "2 triangles differ from the polygon: {:?}", s);
    // 64 boundary points (the 4 corners and 60 more on the 1/16 grid).
    // The random picks may repeat: add grid points one at a time (each adds
    // at most one point) until there are exactly 64.
    let mut picks = s.picks.clone();
    let mut boundary = rectangle_boundary(s.x0, s.y0, s.x1, s.y1, &picks);
    let mut k = 0u64;
    while boundary.len() < 64 {
        picks.push(k * 13 + 1);
        k += 1;
        boundary = rectangle_boundary(s.x0, s.y0, s.x1, s.y1, &picks);
    }
    prop_assert_eq!(boundary.len(), 64);
    let fan = triangulate(&boundary, inside(s, s.centre), &[]);
    prop_assert_eq!(fan.len(), 64);
    let f = draw_tris(s, &fan, style);
    prop_assert!(
        f == whole,
        "64-triangle fan differs from the polygon: {:?}",
        s
    );
    let interior: Vec<_> = s.interior.iter().map(|&r| inside(s, r)).collect();
    let mesh = triangulate(&boundary, inside(s, s.centre), &interior);
    let m = draw_tris(s, &mesh, style);
    prop_assert!(
        m == whole,
        "random triangulation differs from the polygon: {:?}",
        s
    );
    Ok(())
}

#[test]
fn shared_edge_coverage_sums_to_one() {
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(128)
    })
    .run(&scene(), |s| check(&s, RenderStyle::default()))
    .unwrap();
}

#[test]
fn shared_edge_coverage_sums_to_one_in_seed_mode() {
    let style = RenderStyle {
        antialias: true,
        model: PixelModel::BoxSeed,
    };
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(48)
    })
    .run(&scene(), |s| check(&s, style))
    .unwrap();
}

#[test]
fn shared_edge_claims_each_centre_once_aliased() {
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(128)
    })
    .run(&scene(), |s| check(&s, RenderStyle::ALIASED))
    .unwrap();
}
