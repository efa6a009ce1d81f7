//! Gouraud shading (SPEC §3): the interior of a triangle shows the exact
//! plane through its vertex colours; channels are independent.

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::{RenderStyle, SubPoint, Triangle};
use softedge_tests::exact::{gouraud_at_centre, q, CoverageMap};
use softedge_tests::frame::{render, Frame};
use softedge_tests::shapes::cross;

const W: u16 = 48;
const H: u16 = 40;

#[derive(Debug, Clone)]
struct Case {
    v: [(i64, i64); 3],
    colors: [[u16; 3]; 3],
    bg: [u16; 3],
}

fn case() -> impl Strategy<Value = Case> {
    (
        prop::array::uniform3((-64i64..(W as i64 * 16 + 64), -64i64..(H as i64 * 16 + 64))),
        prop::array::uniform3(prop::array::uniform3(0u16..=4095)),
        prop::array::uniform3(0u16..=4095),
    )
        // Big enough to have interior pixels and gradients under the
        // clamp of one full scale per pixel.
        .prop_filter("area", |(v, _, _)| {
            cross(v[0], v[1], v[2]).abs() > 2 * 256 * 16
        })
        .prop_map(|(v, colors, bg)| Case { v, colors, bg })
}

fn draw<const C: usize>(c: &Case, colors: [[u16; C]; 3], bg: [u16; C]) -> Frame<C> {
    let v = c.v.map(|(x, y)| SubPoint::new(x as i32, y as i32));
    render(W, H, 8, bg, |buf| {
        Triangle::new(v, colors)
            .draw(buf, &RenderStyle::default())
            .unwrap();
    })
}

#[test]
fn interior_pixels_equal_exact_plane_within_one_step() {
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(192)
    })
    .run(&case(), |c| {
        let f = draw::<3>(&c, c.colors, c.bg);
        let cover = CoverageMap::new(&c.v, i32::from(W), i32::from(H));
        let mut interior = 0;
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                if *cover.at(x, y) != q(65536) {
                    continue;
                }
                interior += 1;
                for ch in 0..3 {
                    let col = [0, 1, 2].map(|k| i64::from(c.colors[k][ch]));
                    let exact = gouraud_at_centre(c.v, col, i64::from(x), i64::from(y)).unwrap();
                    let got = f.lin_at(x, y)[ch];
                    let err = (q(i64::from(got)) - exact).abs();
                    prop_assert!(
                        err <= q(1),
                        "pixel {},{} ch {}: {} vs exact {} for {:?}",
                        x,
                        y,
                        ch,
                        got,
                        exact,
                        c
                    );
                }
            }
        }
        prop_assert!(interior >= 0);
        Ok(())
    })
    .unwrap();
}

#[test]
fn rgb_triangle_equals_three_gray_triangles() {
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(128)
    })
    .run(&case(), |c| {
        let rgb = draw::<3>(&c, c.colors, c.bg);
        for ch in 0..3 {
            let gray = draw::<1>(&c, c.colors.map(|k| [k[ch]]), [c.bg[ch]]);
            for (k, (a, b)) in rgb.raw.iter().zip(&gray.raw).enumerate() {
                prop_assert_eq!(a[ch], b[0], "pixel {} channel {} for {:?}", k, ch, c);
            }
            for (a, b) in rgb.lin12.iter().zip(&gray.lin12) {
                prop_assert_eq!(a[ch], b[0]);
            }
        }
        Ok(())
    })
    .unwrap();
}
