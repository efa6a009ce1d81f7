//! Edge level: the walker of seed 001 (SPEC §1-3) against the exact
//! reference.
//!
//! Sign convention (checked by every area test below, and pinned by
//! `edge_area_sign_convention`): with `orientation = +1`, an edge whose end
//! point `p1` is lower on the screen than `p0` (it runs down) reports `+` the
//! area right of it, an edge running up reports `-` that area; with
//! `orientation = -1` both flip. So the reported area is
//! `orientation * dir * A_right`, `dir = +1` for downward edges.

use std::cell::Cell as StdCell;
use std::ops::Range;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::edge::{walk_edge, AreaMode, Plane};
use softedge::SubPoint;
use softedge_tests::exact::{edge_right_area, gouraud_at_centre, q, to_f64, Q};
use softedge_tests::frame::Recorder;

/// The plane triangle (sub-pixels): contains every edge drawn below
/// (`[-4800, 9600]²`), so every plane value lies between vertex colours.
const PLANE_TRI: [(i64, i64); 3] = [(-6000, -6000), (30000, -6000), (-6000, 30000)];

#[derive(Debug, Clone)]
struct EdgeCase {
    p0: (i64, i64),
    p1: (i64, i64),
    orientation: i32,
    colors: [[u16; 3]; 3],
    bg: [u16; 3],
}

/// Random edges in all 8 octants, sub-pixel end points, 0..300 px long
/// (short ones on purpose too), with random Gouraud planes.
fn edge_case() -> impl Strategy<Value = EdgeCase> {
    let delta = prop_oneof![
        (-4800i64..=4800, -4800i64..=4800),
        (-48i64..=48, -48i64..=48),
        // Exactly 45° and near it, where the seed formula is worst.
        (-300i64..=300, prop::bool::ANY, -2i64..=2)
            .prop_map(|(d, flip, j)| (d, if flip { -d + j } else { d + j })),
    ];
    (
        (0i64..=4800, 0i64..=4800),
        delta,
        prop::bool::ANY,
        prop::array::uniform3(prop::array::uniform3(0u16..=4095)),
        prop::array::uniform3(0u16..=4095),
    )
        .prop_map(|(p0, (dx, dy), o, colors, bg)| EdgeCase {
            p0,
            p1: (p0.0 + dx, p0.1 + dy),
            orientation: if o { 1 } else { -1 },
            colors,
            bg,
        })
}

fn sp(p: (i64, i64)) -> SubPoint {
    SubPoint::new(p.0 as i32, p.1 as i32)
}

fn plane_of(c: &EdgeCase) -> Plane<3> {
    Plane::triangle(PLANE_TRI.map(sp), c.colors, c.bg).expect("plane triangle")
}

fn rows_of(c: &EdgeCase) -> Range<i32> {
    let ylo = c.p0.1.min(c.p1.1).div_euclid(16) as i32;
    let yhi = c.p0.1.max(c.p1.1).div_euclid(16) as i32;
    ylo - 1..yhi + 2
}

fn walk(c: &EdgeCase, mode: AreaMode, rows: Range<i32>) -> Recorder<3> {
    let mut rec = Recorder::default();
    walk_edge(
        sp(c.p0),
        sp(c.p1),
        c.orientation,
        &plane_of(c),
        mode,
        rows,
        &mut rec,
    );
    rec
}

/// `floor(x_edge(y) / 16)` for the edge `a -> b` (`a.1 < b.1`).
fn column_at(a: (i64, i64), b: (i64, i64), y: i64) -> i64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    (a.0 * dy + (y - a.1) * dx).div_euclid(16 * dy)
}

/// Largest `|walker area - exact area|` over every pixel of the edge's rows
/// (1/4096 px), and the pixel where it happens. Checks the rows outside the
/// edge's y-range report nothing.
fn max_area_error(c: &EdgeCase, rec: &Recorder<3>) -> (Q, (i32, i32)) {
    let (a, b) = if c.p0.1 <= c.p1.1 {
        (c.p0, c.p1)
    } else {
        (c.p1, c.p0)
    };
    let dir = if c.p0.1 < c.p1.1 { 1 } else { -1 };
    let sign = i64::from(c.orientation) * dir;
    let x_lo = (a.0.min(b.0).div_euclid(16) - 2) as i32;
    let x_hi = (a.0.max(b.0).div_euclid(16) + 2) as i32;
    let areas = rec.areas(x_lo, x_hi);
    let mut worst = (q(0), (0, 0));
    for y in rows_of(c) {
        let got = areas.get(&y);
        let (ylo, yhi) = (
            (i64::from(y) * 16).max(a.1),
            (i64::from(y) * 16 + 16).min(b.1),
        );
        if ylo >= yhi || a.1 == b.1 {
            if let Some(row) = got {
                assert!(
                    row.iter().all(|&v| v == 0),
                    "row {y} outside the edge: {row:?}"
                );
            }
            continue;
        }
        let row = got.unwrap_or_else(|| panic!("row {y} of the edge reported nothing"));
        let (ca, cb) = (column_at(a, b, ylo), column_at(a, b, yhi));
        let (c_min, c_max) = (ca.min(cb), ca.max(cb));
        let full = (yhi - ylo) * 256;
        for x in x_lo..=x_hi {
            let xi = i64::from(x);
            let exact = if xi < c_min {
                q(0)
            } else if xi > c_max {
                q(full)
            } else {
                edge_right_area(a, b, xi, i64::from(y))
            };
            let err = (q(row[(x - x_lo) as usize]) - q(sign) * exact).abs();
            if err > worst.0 {
                worst = (err, (x, y));
            }
        }
    }
    worst
}

#[test]
fn edge_area_sign_convention() {
    // A vertical edge at x = 4.5 px over rows 0..2, walked down then up.
    let plane = Plane::flat([4095], [0]);
    for (p0, p1, orientation, sign) in [
        ((72, 0), (72, 32), 1, 1),
        ((72, 32), (72, 0), 1, -1),
        ((72, 0), (72, 32), -1, -1),
        ((72, 32), (72, 0), -1, 1),
    ] {
        let mut rec = Recorder::<1>::default();
        walk_edge(
            sp(p0),
            sp(p1),
            orientation,
            &plane,
            AreaMode::Exact,
            0..2,
            &mut rec,
        );
        let areas = rec.areas(0, 9);
        for y in 0..2 {
            let row = &areas[&y];
            assert_eq!(row[3], 0);
            assert_eq!(row[4], sign * 2048, "half of pixel 4");
            assert_eq!(row[5], sign * 4096);
        }
    }
}

#[test]
fn exact_edge_area_within_1_256() {
    let max = StdCell::new(0.0f64);
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    });
    runner
        .run(&edge_case(), |c| {
            let rec = walk(&c, AreaMode::Exact, rows_of(&c));
            let (err, at) = max_area_error(&c, &rec);
            max.set(max.get().max(to_f64(&err)));
            // SPEC §2: within 1/256 px = 16 units of 1/4096 px; the
            // documented per-edge bound is tighter: below 3 units.
            prop_assert!(err <= q(16), "error {} at {:?} for {:?}", err, at, c);
            prop_assert!(err < q(3), "error {} at {:?} for {:?}", err, at, c);
            Ok(())
        })
        .unwrap();
    eprintln!("exact mode: max edge-area error {} / 4096 px", max.get());
}

/// The documented per-edge bound of `AreaMode::Exact` (`core/src/edge/mod.rs`):
/// below 3 units of 1/4096 px — the floor of the main term (< 1) plus the
/// spill's (< 1/2 from truncating `e`, < 1/1000 from its reciprocal, < 1
/// from the floor). The first version of the docs claimed 1 unit; these two
/// edges (found by search: 2.09 and 2.14 units off) showed it was wrong.
#[test]
fn exact_edge_area_within_documented_three_units() {
    for (p0, p1) in [((39, 20), (55, -2)), ((10, 26), (32, 64))] {
        let c = EdgeCase {
            p0,
            p1,
            orientation: 1,
            colors: [[0; 3]; 3],
            bg: [0; 3],
        };
        let (err, at) = max_area_error(&c, &walk(&c, AreaMode::Exact, rows_of(&c)));
        assert!(
            err > q(2) && err < q(3),
            "edge {p0:?} -> {p1:?}: error {err} / 4096 px at {at:?}"
        );
    }
}

#[test]
fn seed_formula_edge_area_within_k_over_8() {
    let max_ratio = StdCell::new(0.0f64);
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    });
    runner
        .run(&edge_case(), |c| {
            let rec = walk(&c, AreaMode::SeedFormula, rows_of(&c));
            let (err, at) = max_area_error(&c, &rec);
            let (dx, dy) = ((c.p1.0 - c.p0.0).abs(), (c.p1.1 - c.p0.1).abs());
            let (minor, major) = (dx.min(dy), dx.max(dy));
            if major == 0 {
                return Ok(());
            }
            // k/8 px + 2/4096 px, in 1/4096 px: 512 k + 2.
            let bound = q(512) * Q::new(minor.into(), major.into()) + q(2);
            if minor > 0 {
                let r = to_f64(&(err / (q(512) * Q::new(minor.into(), major.into()))));
                max_ratio.set(max_ratio.get().max(r));
            }
            prop_assert!(
                err <= bound,
                "error {} > {} at {:?} for {:?}",
                err,
                bound,
                at,
                c
            );
            Ok(())
        })
        .unwrap();
    eprintln!("seed mode: max error / (k/8 px) = {:.3}", max_ratio.get());
}

#[test]
fn seed_formula_error_bound_is_reached_at_45_degrees() {
    // A 45° edge half a pixel below the corners, y = x + 1/2: it crosses a
    // row boundary at every column centre, e = k/2 = 1/2, and the seed
    // formula gives the spill triangle e²/(2k) = 1/8 px to the wrong pixel.
    let c = EdgeCase {
        p0: (0, 8),
        p1: (320, 328),
        orientation: 1,
        colors: [[4095; 3]; 3],
        bg: [0; 3],
    };
    let (seed_err, _) = max_area_error(&c, &walk(&c, AreaMode::SeedFormula, rows_of(&c)));
    let (exact_err, _) = max_area_error(&c, &walk(&c, AreaMode::Exact, rows_of(&c)));
    eprintln!(
        "45° edge: seed error {} / 4096 px, exact error {} / 4096 px",
        seed_err, exact_err
    );
    assert!(
        seed_err > q(256),
        "seed error {seed_err} is not above 1/16 px"
    );
    assert!(seed_err <= q(512 + 2));
    assert!(exact_err <= q(2));
}

/// The walker's cell values: `value = I * coverage` with `I` the plane at
/// the cell's pixel.
///
/// Bound: against `(plane.at(x, y) * coverage) >> 16`, 1 unit (the floor of
/// a negative product may sit one lower); against the exact Gouraud value at
/// the pixel centre, also the plane's own rounding (at0, gx, gy each within
/// 1/2 of 1/65536 level), so `2 + |cov| (1 + |di| + |dj|) / 2^17` units
/// (`di, dj` the distance from the plane's reference pixel) — far inside the
/// 1/256 of full scale (65520 units) of SPEC §3.
fn check_values(c: &EdgeCase, mode: AreaMode) -> Result<f64, TestCaseError> {
    let plane = plane_of(c);
    let rec = walk(c, mode, rows_of(c));
    let mut worst = 0.0f64;
    let cols = c.colors;
    for cell in &rec.cells {
        let fine = plane.at(cell.x, cell.y);
        let cov = i64::from(cell.coverage);
        for ch in 0..3 {
            let direct = (fine[ch] * cov) >> 16;
            prop_assert!(
                (i64::from(cell.value[ch]) - direct).abs() <= 1,
                "cell {:?} ch {} direct {} for {:?}",
                cell,
                ch,
                direct,
                c
            );
            let exact = gouraud_at_centre(
                PLANE_TRI,
                [0, 1, 2].map(|k| i64::from(cols[k][ch])),
                i64::from(cell.x),
                i64::from(cell.y),
            )
            .expect("plane")
                - q(i64::from(c.bg[ch]));
            let err = (q(i64::from(cell.value[ch])) - exact * q(cov)).abs();
            let dist = i64::from((cell.x - plane.i0).abs() + (cell.y - plane.j0).abs());
            let bound = q(2) + Q::new((cov.abs() * (1 + dist)).into(), (1i64 << 17).into());
            prop_assert!(
                err <= bound,
                "cell {:?} ch {}: error {} > {} for {:?}",
                cell,
                ch,
                err,
                bound,
                c
            );
            worst = worst.max(to_f64(&err));
        }
    }
    Ok(worst)
}

#[test]
fn incremental_evaluator_equals_direct_formula() {
    let max = StdCell::new(0.0f64);
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    });
    runner
        .run(&edge_case(), |c| {
            let a = check_values(&c, AreaMode::Exact)?;
            let b = check_values(&c, AreaMode::SeedFormula)?;
            max.set(max.get().max(a).max(b));
            Ok(())
        })
        .unwrap();
    eprintln!("evaluator: max |I*S - exact| = {} acc units", max.get());
}

#[test]
fn walk_restricted_to_rows_equals_full_walk_in_those_rows() {
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    });
    runner
        .run(&(edge_case(), 0u32..1000, 1i32..20), |(c, start, len)| {
            let full = rows_of(&c);
            let span = (full.end - full.start) as u32;
            let y0 = full.start + (start % span) as i32;
            let rows = y0..(y0 + len).min(full.end);
            let whole = walk(&c, AreaMode::Exact, full);
            let part = walk(&c, AreaMode::Exact, rows.clone());
            let (x_lo, x_hi) = (
                (c.p0.0.min(c.p1.0) / 16 - 3) as i32,
                (c.p0.0.max(c.p1.0) / 16 + 3) as i32,
            );
            let (aw, ap) = (whole.areas(x_lo, x_hi), part.areas(x_lo, x_hi));
            for y in rows.clone() {
                let zero = vec![0; (x_hi - x_lo + 1) as usize];
                prop_assert_eq!(aw.get(&y).unwrap_or(&zero), ap.get(&y).unwrap_or(&zero));
            }
            prop_assert!(part.cells.iter().all(|k| rows.contains(&k.y)));
            prop_assert!(part.covers.iter().all(|k| rows.contains(&k.1)));
            // The values too, summed per pixel.
            let sum = |r: &Recorder<3>, x: i32, y: i32| {
                r.cells
                    .iter()
                    .filter(|k| k.x == x && k.y == y)
                    .fold([0i64; 3], |mut s, k| {
                        for (a, v) in s.iter_mut().zip(k.value) {
                            *a += i64::from(v);
                        }
                        s
                    })
            };
            for k in &part.cells {
                prop_assert_eq!(sum(&whole, k.x, k.y), sum(&part, k.x, k.y));
            }
            Ok(())
        })
        .unwrap();
}

#[test]
fn every_octant_is_exact_and_evaluated() {
    // One edge per octant (and the axes), sub-pixel end points, both
    // orientations, a Gouraud plane: area and value checks as above.
    let dirs = [
        (97, 13),
        (13, 97),
        (-13, 97),
        (-97, 13),
        (-97, -13),
        (-13, -97),
        (13, -97),
        (97, -13),
        (100, 0),
        (0, 100),
        (-100, 0),
        (0, -100),
        (77, 77),
        (-77, 77),
    ];
    for (dx, dy) in dirs {
        for scale in [1i64, 5, 40] {
            for orientation in [1, -1] {
                let p0 = (2403, 1999);
                let c = EdgeCase {
                    p0,
                    p1: (p0.0 + dx * scale / 3, p0.1 + dy * scale / 3),
                    orientation,
                    colors: [[0, 4095, 1000], [4095, 0, 3000], [2000, 2000, 0]],
                    bg: [100, 0, 4095],
                };
                for mode in [AreaMode::Exact, AreaMode::SeedFormula] {
                    let (err, at) = max_area_error(&c, &walk(&c, mode, rows_of(&c)));
                    let bound = if mode == AreaMode::Exact { 16 } else { 512 + 2 };
                    assert!(err <= q(bound), "{mode:?} error {err} at {at:?} for {c:?}");
                    check_values(&c, mode).unwrap();
                }
            }
        }
    }
}
