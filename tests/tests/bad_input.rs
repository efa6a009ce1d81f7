//! Bad input never panics and never writes outside the caller's buffers:
//! range limits, degenerate shapes, self-intersection, too many vertices,
//! colour count and range, bands far outside the frame, short buffers.
//!
//! Every drawing here goes into a `BandBuffer` whose slices are the middle of
//! larger arrays; the guard areas on both sides must be untouched after.

use softedge::{
    Band, BandBuffer, BandError, DrawError, Line, Polygon, PolygonColors, RenderStyle, SubPoint,
    Triangle, COORD_LIMIT_PX, MAX_POLYGON_VERTICES,
};
use softedge_tests::exact::{q, CoverageMap};

const GUARD: usize = 64;
const SENTINEL: i32 = 0x5a5a_5a5a;
const W: u16 = 24;
const ROWS: u16 = 16;
const LIMIT: i32 = COORD_LIMIT_PX * 16;

const STYLES: [RenderStyle; 3] = [
    RenderStyle {
        antialias: true,
        model: softedge::PixelModel::Box,
    },
    RenderStyle {
        antialias: true,
        model: softedge::PixelModel::BoxSeed,
    },
    RenderStyle::ALIASED,
];

/// Raw values of a band's pixels after `draw` (row by row, `C` per
/// pixel, as `BandBuffer::raw` reads them), with the guard areas checked.
fn guarded<const C: usize, T>(
    band: Band,
    bg: [u16; C],
    draw: impl FnOnce(&mut BandBuffer<'_, C>) -> T,
) -> (Vec<i32>, T) {
    let n_acc = BandBuffer::<C>::acc_len(band.width, band.rows);
    let n_cov = BandBuffer::<C>::cover_len(band.width, band.rows);
    let mut acc = vec![SENTINEL; n_acc + 2 * GUARD];
    let mut cov = vec![SENTINEL; n_cov + 2 * GUARD];
    let out;
    let mut values = Vec::with_capacity(n_acc);
    {
        let (_, acc_rest) = acc.split_at_mut(GUARD);
        let (acc_mid, _) = acc_rest.split_at_mut(n_acc);
        let (_, cov_rest) = cov.split_at_mut(GUARD);
        let (cov_mid, _) = cov_rest.split_at_mut(n_cov);
        let mut buf = BandBuffer::<C>::new(acc_mid, cov_mid, band).expect("band");
        buf.clear(bg);
        out = draw(&mut buf);
        // Reading the whole band and just outside it must not panic either.
        for y in band.y0 - 1..=band.y0 + i32::from(band.rows) {
            for x in -1..=i32::from(band.width) {
                let inside = y >= band.y0
                    && y < band.y0 + i32::from(band.rows)
                    && x >= 0
                    && x < i32::from(band.width);
                assert_eq!(buf.lin12(x, y).is_some(), inside);
                assert_eq!(buf.raw(x, y).is_some(), inside);
                if let (true, Some(v)) = (inside, buf.raw(x, y)) {
                    values.extend_from_slice(&v);
                }
            }
        }
    }
    for g in [
        &acc[..GUARD],
        &acc[GUARD + n_acc..],
        &cov[..GUARD],
        &cov[GUARD + n_cov..],
    ] {
        assert!(g.iter().all(|&v| v == SENTINEL), "guard area overwritten");
    }
    (values, out)
}

fn band(y0: i32, rows: u16) -> Band {
    Band::new(W, y0, rows)
}

fn p(x: i32, y: i32) -> SubPoint {
    SubPoint::new(x, y)
}

fn blank(b: Band) -> Vec<i32> {
    guarded::<1, _>(b, [77], |_| ()).0
}

#[test]
fn vertices_at_the_coordinate_limit_draw_correctly() {
    let b = band(0, ROWS);
    let huge = [p(-LIMIT, -LIMIT), p(LIMIT, -LIMIT), p(0, LIMIT)];
    for style in STYLES {
        let (acc, r) =
            guarded::<1, _>(b, [0], |buf| Triangle::flat(huge, [4095]).draw(buf, &style));
        assert_eq!(r, Ok(()));
        // The frame lies wholly inside the triangle: full coverage.
        assert!(acc.iter().all(|&v| v == 4095 * 65536), "{style:?}");
    }
    // An edge from the far corner through the band: exact coverage.
    let v = [(-LIMIT, -LIMIT), (LIMIT, LIMIT), (-LIMIT, LIMIT)]
        .map(|(x, y)| (i64::from(x), i64::from(y)));
    let shifted = [(-LIMIT, -LIMIT), (LIMIT, LIMIT - 37), (-LIMIT, LIMIT)];
    for tri in [v, shifted.map(|(x, y)| (i64::from(x), i64::from(y)))] {
        let pts = tri.map(|(x, y)| p(x as i32, y as i32));
        let (acc, r) = guarded::<1, _>(b, [0], |buf| {
            Triangle::flat(pts, [4095]).draw(buf, &RenderStyle::default())
        });
        assert_eq!(r, Ok(()));
        let exact = CoverageMap::new(&tri, i32::from(W), i32::from(ROWS));
        for y in 0..i32::from(ROWS) {
            for x in 0..i32::from(W) {
                let got = acc[(y * i32::from(W) + x) as usize];
                assert_eq!(got % 4095, 0);
                let err = q(i64::from(got / 4095)) - exact.at(x, y);
                assert!(err <= q(16) && err >= q(-16), "pixel {x},{y}: error {err}");
            }
        }
    }
    // Lines and polygons at the limit.
    let (_, r) = guarded::<3, _>(b, [0; 3], |buf| {
        Line::new(p(-LIMIT, -LIMIT), p(LIMIT, LIMIT), [[4095; 3], [0; 3]])
            .draw(buf, &RenderStyle::default())
    });
    assert_eq!(r, Ok(()));
    let quad = [
        p(-LIMIT, -LIMIT),
        p(LIMIT, -LIMIT),
        p(LIMIT, LIMIT),
        p(-LIMIT, LIMIT),
    ];
    for style in STYLES {
        let (acc, r) = guarded::<1, _>(b, [0], |buf| {
            Polygon::new(&quad, PolygonColors::PerVertex(&[[0], [4095], [0], [4095]]))
                .draw(buf, &style)
        });
        assert_eq!(r, Ok(()));
        assert!(
            acc.iter().all(|v| (0..=4095 * 65536 + 65536).contains(v)),
            "{style:?}"
        );
    }
}

#[test]
fn vertices_beyond_the_limit_are_rejected_and_draw_nothing() {
    let b = band(0, ROWS);
    let before = blank(b);
    let ok = [p(0, 0), p(100, 0), p(0, 100)];
    for bad in [
        p(LIMIT + 1, 0),
        p(-LIMIT - 1, 0),
        p(0, LIMIT + 1),
        p(0, -LIMIT - 1),
        p(i32::MAX, i32::MIN),
    ] {
        for k in 0..3 {
            let mut v = ok;
            v[k] = bad;
            for style in STYLES {
                let (acc, r) =
                    guarded::<1, _>(b, [77], |buf| Triangle::flat(v, [4095]).draw(buf, &style));
                assert!(matches!(r, Err(DrawError::Coord(_))), "{v:?}: {r:?}");
                assert_eq!(acc, before);
                let (acc, r) = guarded::<1, _>(b, [77], |buf| {
                    Polygon::new(&[v[0], v[1], v[2], p(50, 50)], PolygonColors::Flat([4095]))
                        .draw(buf, &style)
                });
                assert!(matches!(r, Err(DrawError::Coord(_))), "{v:?}: {r:?}");
                assert_eq!(acc, before);
            }
            let (acc, r) = guarded::<1, _>(b, [77], |buf| {
                Line::new(v[k], p(30, 30), [[4095], [4095]]).draw(buf, &RenderStyle::default())
            });
            assert!(matches!(r, Err(DrawError::Coord(_))), "{r:?}");
            assert_eq!(acc, before);
        }
    }
}

#[test]
fn degenerate_shapes_draw_nothing() {
    let b = band(0, ROWS);
    let before = blank(b);
    let a = p(20, 30);
    let cases: Vec<Vec<SubPoint>> = vec![
        vec![],
        vec![a],
        vec![a, p(100, 100)],
        vec![a, a, a],
        vec![a, a, p(100, 40)],
        vec![p(0, 0), p(50, 50), p(100, 100)],
        vec![p(0, 0), p(50, 50), p(100, 100), p(25, 25)],
        vec![p(0, 0), p(200, 0), p(100, 0)],
        vec![p(7, 9), p(7, 200), p(7, 60)],
    ];
    for v in &cases {
        for style in STYLES {
            let (acc, r) = guarded::<1, _>(b, [77], |buf| {
                Polygon::new(v, PolygonColors::Flat([4095])).draw(buf, &style)
            });
            assert_eq!(r, Ok(()), "{v:?}");
            assert_eq!(acc, before, "{v:?}");
            if v.len() == 3 {
                let (acc, r) = guarded::<1, _>(b, [77], |buf| {
                    Triangle::new([v[0], v[1], v[2]], [[0], [4095], [2000]]).draw(buf, &style)
                });
                assert_eq!(r, Ok(()), "{v:?}");
                assert_eq!(acc, before, "{v:?}");
            }
        }
    }
    // Zero-length line.
    let (acc, r) = guarded::<1, _>(b, [77], |buf| {
        Line::new(a, a, [[4095], [4095]]).draw(buf, &RenderStyle::default())
    });
    assert_eq!(r, Ok(()));
    assert_eq!(acc, before);
}

#[test]
fn repeated_vertex_in_a_polygon_draws_it_or_rejects_it_without_panic() {
    // A square with one corner given twice: not documented either way; it
    // must not panic, and if drawn it is the square.
    let b = band(0, ROWS);
    let sq = [p(10, 10), p(200, 10), p(200, 200), p(10, 200)];
    let dup = [p(10, 10), p(200, 10), p(200, 10), p(200, 200), p(10, 200)];
    let (want, _) = guarded::<1, _>(b, [0], |buf| {
        Polygon::new(&sq, PolygonColors::Flat([4095])).draw(buf, &RenderStyle::default())
    });
    let (got, r) = guarded::<1, _>(b, [0], |buf| {
        Polygon::new(&dup, PolygonColors::Flat([4095])).draw(buf, &RenderStyle::default())
    });
    match r {
        Ok(()) => assert_eq!(got, want),
        Err(e) => assert_eq!(e, DrawError::SelfIntersecting),
    }
}

#[test]
fn self_intersecting_polygons_are_rejected_and_draw_nothing() {
    let b = band(0, ROWS);
    let before = blank(b);
    // A bow tie whose two loops differ in area (non-zero signed area).
    let bow_tie = [p(0, 0), p(200, 150), p(200, 0), p(0, 200)];
    // Non-adjacent edges touching at a point (a vertex on another edge).
    let touching = [
        p(0, 0),
        p(200, 0),
        p(100, 100),
        p(200, 200),
        p(0, 200),
        p(100, 0),
    ];
    for v in [&bow_tie[..], &touching[..]] {
        for style in STYLES {
            for colors in [
                PolygonColors::Flat([4095]),
                PolygonColors::PerVertex(&[[0], [4095], [100], [2000], [3000], [50]][..v.len()]),
            ] {
                let (acc, r) =
                    guarded::<1, _>(b, [77], |buf| Polygon::new(v, colors).draw(buf, &style));
                assert_eq!(r, Err(DrawError::SelfIntersecting), "{v:?}");
                assert_eq!(acc, before);
            }
        }
    }
}

#[test]
fn symmetric_bow_tie_is_rejected_as_self_intersecting() {
    // Its two loops cancel: zero signed area, but it is not degenerate, it
    // is self-intersecting (SPEC brief: bow tie -> Err(SelfIntersecting)).
    let b = band(0, ROWS);
    let before = blank(b);
    let bow_tie = [p(0, 0), p(200, 200), p(200, 0), p(0, 200)];
    for style in STYLES {
        let (acc, r) = guarded::<1, _>(b, [77], |buf| {
            Polygon::new(&bow_tie, PolygonColors::Flat([4095])).draw(buf, &style)
        });
        assert_eq!(acc, before);
        assert_eq!(r, Err(DrawError::SelfIntersecting), "{style:?}");
    }
}

#[test]
fn too_many_vertices_are_rejected() {
    let b = band(0, ROWS);
    let before = blank(b);
    // A convex polygon of n vertices on a circle.
    let ngon = |n: usize| -> Vec<SubPoint> {
        (0..n)
            .map(|k| {
                let a = k as f64 * std::f64::consts::TAU / n as f64;
                p(
                    200 + (180.0 * a.cos()).round() as i32,
                    128 + (120.0 * a.sin()).round() as i32,
                )
            })
            .collect()
    };
    let ok = ngon(MAX_POLYGON_VERTICES);
    let cols = [[1000u16]; MAX_POLYGON_VERTICES + 1];
    let (acc, r) = guarded::<1, _>(b, [0], |buf| {
        Polygon::new(&ok, PolygonColors::Flat([4095])).draw(buf, &RenderStyle::default())
    });
    assert_eq!(r, Ok(()));
    assert!(acc.contains(&(4095 * 65536)), "the 64-gon was drawn");
    let (_, r) = guarded::<1, _>(b, [0], |buf| {
        Polygon::new(&ok, PolygonColors::PerVertex(&cols[..MAX_POLYGON_VERTICES]))
            .draw(buf, &RenderStyle::default())
    });
    assert_eq!(r, Ok(()));
    let many = ngon(MAX_POLYGON_VERTICES + 1);
    for colors in [
        PolygonColors::Flat([4095]),
        PolygonColors::PerVertex(&cols[..]),
    ] {
        let (acc, r) = guarded::<1, _>(b, [77], |buf| {
            Polygon::new(&many, colors).draw(buf, &RenderStyle::default())
        });
        assert_eq!(r, Err(DrawError::TooManyVertices));
        assert_eq!(acc, before);
    }
}

#[test]
fn colour_count_mismatch_is_rejected() {
    let b = band(0, ROWS);
    let before = blank(b);
    let v = [p(0, 0), p(200, 0), p(200, 200), p(0, 200)];
    for n in [0usize, 1, 3, 5] {
        let cols = vec![[4095u16]; n];
        let (acc, r) = guarded::<1, _>(b, [77], |buf| {
            Polygon::new(&v, PolygonColors::PerVertex(&cols)).draw(buf, &RenderStyle::default())
        });
        assert_eq!(r, Err(DrawError::ColorCount), "{n} colours");
        assert_eq!(acc, before);
    }
}

#[test]
fn colours_above_4095_are_clamped() {
    let b = band(0, ROWS);
    let v = [p(3, 5), p(300, 40), p(60, 250)];
    for style in STYLES {
        let draw = |c: [[u16; 3]; 3], bg: [u16; 3]| {
            guarded::<3, _>(b, bg, |buf| {
                Triangle::new(v, c).draw(buf, &style).unwrap();
                Line::new(v[0], v[1], [c[0], c[1]])
                    .draw(buf, &style)
                    .unwrap();
                Polygon::new(&v, PolygonColors::PerVertex(&c))
                    .draw(buf, &style)
                    .unwrap();
            })
            .0
        };
        let big = draw(
            [
                [5000, 4095, u16::MAX],
                [4096, 0, 9999],
                [u16::MAX, 100, 4095],
            ],
            [u16::MAX, 4096, 0],
        );
        let clamped = draw(
            [[4095, 4095, 4095], [4095, 0, 4095], [4095, 100, 4095]],
            [4095, 4095, 0],
        );
        assert_eq!(big, clamped, "{style:?}");
    }
}

#[test]
fn bands_far_outside_the_frame_draw_safely() {
    let tri = [p(-300, -40), p(W as i32 * 16 + 300, 100), p(40, 500)];
    for y0 in [-2000, 2000, -2000 + 7, 1999] {
        for rows in 1..=16u16 {
            let b = band(y0, rows);
            let before = blank(b);
            for style in STYLES {
                let (acc, r) = guarded::<1, _>(b, [77], |buf| {
                    Triangle::new(tri, [[0], [4095], [1000]]).draw(buf, &style)
                });
                assert_eq!(r, Ok(()));
                assert_eq!(
                    acc, before,
                    "nothing of the frame's triangle lands at y0 = {y0}"
                );
                // A triangle that does reach the far band is drawn there.
                let far = [
                    p(-100, (y0 - 3) * 16),
                    p(W as i32 * 16 + 100, (y0 + 1) * 16 + 5),
                    p(-100, (y0 + i32::from(rows) + 3) * 16),
                ];
                let (acc, r) =
                    guarded::<1, _>(b, [0], |buf| Triangle::flat(far, [4095]).draw(buf, &style));
                assert_eq!(r, Ok(()));
                assert!(acc[0] > 0, "y0 = {y0}, rows = {rows}, {style:?}");
                let (acc, r) = guarded::<3, _>(b, [0; 3], |buf| {
                    Line::new(far[0], far[1], [[4095; 3], [0; 3]]).draw(buf, &style)
                });
                assert_eq!(r, Ok(()));
                assert!(acc.iter().all(|&v| v >= 0));
            }
        }
    }
}

#[test]
fn short_buffers_and_bad_bands_are_errors() {
    let b = band(0, ROWS);
    let n_acc = BandBuffer::<3>::acc_len(W, ROWS);
    let n_cov = BandBuffer::<3>::cover_len(W, ROWS);
    let mut acc = vec![SENTINEL; n_acc];
    let mut cov = vec![SENTINEL; n_cov];
    assert_eq!(
        BandBuffer::<3>::new(&mut acc[..n_acc - 1], &mut cov, b).err(),
        Some(BandError::AccTooSmall)
    );
    assert_eq!(
        BandBuffer::<3>::new(&mut acc, &mut cov[..n_cov - 1], b).err(),
        Some(BandError::CoverTooSmall)
    );
    assert_eq!(
        BandBuffer::<3>::new(&mut [], &mut [], b).err(),
        Some(BandError::AccTooSmall)
    );
    assert!(
        acc.iter().chain(&cov).all(|&v| v == SENTINEL),
        "failed new wrote nothing"
    );
    for bad in [
        band(0, 0),
        Band::new(0, 0, 4),
        band(i32::MAX, 1),
        band(i32::MIN, 1),
    ] {
        assert_eq!(
            BandBuffer::<3>::new(&mut acc, &mut cov, bad).err(),
            Some(BandError::BadBand),
            "{bad:?}"
        );
    }
    assert!(BandBuffer::<3>::new(&mut acc, &mut cov, b).is_ok());
}
