//! Bands (SPEC §4, seed 004's banded memory): a scene drawn in bands of 1,
//! 7, 16 rows and in one band of the full height gives the same `raw` and
//! `lin12` buffers, for RGB (C = 3) and gray (C = 1), in every style.

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::{
    BandBuffer, Line, PixelModel, Polygon, PolygonColors, RenderStyle, SubPoint, Triangle,
};
use softedge_tests::frame::{render, Frame};
use softedge_tests::shapes::star_polygon;

const W: u16 = 64;
const H: u16 = 48;

#[derive(Debug, Clone)]
enum Prim {
    Tri([(i32, i32); 3], [[u16; 3]; 3]),
    Line((i32, i32), (i32, i32), [[u16; 3]; 2]),
    Poly(Vec<(i64, i64)>, Vec<[u16; 3]>),
}

fn pt() -> impl Strategy<Value = (i32, i32)> {
    (
        -100i32..(W as i32 * 16 + 100),
        -100i32..(H as i32 * 16 + 100),
    )
}

fn rgb() -> impl Strategy<Value = [u16; 3]> {
    prop::array::uniform3(0u16..=4095)
}

fn prim() -> impl Strategy<Value = Prim> {
    prop_oneof![
        (prop::array::uniform3(pt()), prop::array::uniform3(rgb()))
            .prop_map(|(v, c)| Prim::Tri(v, c)),
        (pt(), pt(), prop::array::uniform2(rgb())).prop_map(|(a, b, c)| Prim::Line(a, b, c)),
        (
            (200i64..800, 150i64..600),
            prop::collection::vec((-100i64..1124, -100i64..868), 3..16),
            prop::collection::vec(rgb(), 16),
        )
            .prop_filter_map("star", |(c, pts, cols)| {
                let v = star_polygon(c, &pts)?;
                let n = v.len();
                Some(Prim::Poly(v, cols[..n].to_vec()))
            }),
    ]
}

fn ch<const C: usize>(c: [u16; 3]) -> [u16; C] {
    core::array::from_fn(|k| c[k])
}

fn sp(p: (i32, i32)) -> SubPoint {
    SubPoint::new(p.0, p.1)
}

fn draw<const C: usize>(buf: &mut BandBuffer<'_, C>, scene: &[Prim], style: RenderStyle) {
    for p in scene {
        let r = match p {
            Prim::Tri(v, c) => Triangle::new(v.map(sp), c.map(ch::<C>)).draw(buf, &style),
            Prim::Line(a, b, c) => Line::new(sp(*a), sp(*b), c.map(ch::<C>)).draw(buf, &style),
            Prim::Poly(v, c) => {
                let pts: Vec<SubPoint> = v.iter().map(|&(x, y)| sp((x as i32, y as i32))).collect();
                let cols: Vec<[u16; C]> = c.iter().map(|&c| ch::<C>(c)).collect();
                Polygon::new(&pts, PolygonColors::PerVertex(&cols)).draw(buf, &style)
            }
        };
        r.expect("scene primitives are valid");
    }
}

fn check<const C: usize>(
    scene: &[Prim],
    bg: [u16; 3],
    style: RenderStyle,
) -> Result<(), TestCaseError> {
    let full: Frame<C> = render(W, H, H, ch::<C>(bg), |b| draw(b, scene, style));
    for rows in [1u16, 7, 16] {
        let f: Frame<C> = render(W, H, rows, ch::<C>(bg), |b| draw(b, scene, style));
        prop_assert!(f.raw == full.raw, "raw differs with bands of {} rows", rows);
        prop_assert!(
            f.lin12 == full.lin12,
            "lin12 differs with bands of {} rows",
            rows
        );
    }
    Ok(())
}

const STYLES: [RenderStyle; 3] = [
    RenderStyle {
        antialias: true,
        model: PixelModel::Box,
    },
    RenderStyle {
        antialias: true,
        model: PixelModel::BoxSeed,
    },
    RenderStyle::ALIASED,
];

#[test]
fn band_height_does_not_change_a_single_bit() {
    let strategy = (prop::collection::vec(prim(), 1..8), rgb(), 0usize..3);
    TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(128)
    })
    .run(&strategy, |(scene, bg, s)| {
        check::<3>(&scene, bg, STYLES[s])?;
        check::<1>(&scene, bg, STYLES[s])
    })
    .unwrap();
}

#[test]
fn fixed_scene_is_band_independent_in_every_style() {
    let scene = vec![
        Prim::Tri(
            [(-37, 21), (900, 130), (300, 790)],
            [[4095, 0, 100], [0, 4095, 2000], [1000, 1000, 4095]],
        ),
        Prim::Line((5, 5), (1000, 700), [[4095, 4095, 4095], [0, 0, 0]]),
        Prim::Line(
            (500, -50),
            (510, 900),
            [[100, 2000, 4095], [4095, 2000, 100]],
        ),
        Prim::Poly(
            vec![(100, 100), (400, 120), (250, 250), (420, 400), (90, 380)],
            vec![
                [4095, 0, 0],
                [0, 4095, 0],
                [0, 0, 4095],
                [4095, 4095, 0],
                [0, 4095, 4095],
            ],
        ),
    ];
    for style in STYLES {
        check::<3>(&scene, [30, 60, 90], style).unwrap();
        check::<1>(&scene, [30, 60, 90], style).unwrap();
    }
}
