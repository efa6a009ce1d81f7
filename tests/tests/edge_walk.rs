//! Edge level: the walker of seed 001 (SPEC §1-3) against the exact
//! reference.
//!
//! Sign convention (checked by every area test below, and pinned by
//! `edge_area_sign_convention`): an edge whose end point `p1` is lower on
//! the screen than `p0` (it runs down) reports `+` the area right of it, an
//! edge running up reports `-` that area. The cases' `orientation = -1`
//! walks the edge reversed, so the reported area is `orientation * dir *
//! A_right`, `dir = +1` for downward edges. Areas are in coverage units,
//! 1/65536 px.

use std::cell::Cell as StdCell;
use std::ops::Range;

use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use softedge::edge::{AreaMode, EdgeWalk};
use softedge::geom::FinePoint;
use softedge::SubPoint;
use softedge_tests::exact::{edge_right_area, q, to_f64, Q};
use softedge_tests::frame::Recorder;

#[derive(Debug, Clone)]
struct EdgeCase {
    p0: (i64, i64),
    p1: (i64, i64),
    orientation: i32,
}

/// Random edges in all 8 octants, sub-pixel end points, 0..300 px long
/// (short ones on purpose too).
fn edge_case() -> impl Strategy<Value = EdgeCase> {
    let delta = prop_oneof![
        (-4800i64..=4800, -4800i64..=4800),
        (-48i64..=48, -48i64..=48),
        // Exactly 45° and near it, where the seed formula is worst.
        (-300i64..=300, prop::bool::ANY, -2i64..=2)
            .prop_map(|(d, flip, j)| (d, if flip { -d + j } else { d + j })),
    ];
    ((0i64..=4800, 0i64..=4800), delta, prop::bool::ANY).prop_map(|(p0, (dx, dy), o)| EdgeCase {
        p0,
        p1: (p0.0 + dx, p0.1 + dy),
        orientation: if o { 1 } else { -1 },
    })
}

fn fp(p: (i64, i64)) -> FinePoint {
    FinePoint::from(SubPoint::new(p.0 as i32, p.1 as i32))
}

fn rows_of(c: &EdgeCase) -> Range<i32> {
    let ylo = c.p0.1.min(c.p1.1).div_euclid(16) as i32;
    let yhi = c.p0.1.max(c.p1.1).div_euclid(16) as i32;
    ylo - 1..yhi + 2
}

/// The set-up walk of the case, for a sink keeping `columns`.
fn walker(c: &EdgeCase, mode: AreaMode, columns: Range<i32>) -> Option<EdgeWalk> {
    let (a, b) = if c.orientation > 0 {
        (c.p0, c.p1)
    } else {
        (c.p1, c.p0)
    };
    EdgeWalk::new(fp(a), fp(b), mode, columns)
}

fn walk(c: &EdgeCase, mode: AreaMode, rows: Range<i32>) -> Recorder {
    let mut rec = Recorder::default();
    if let Some(mut w) = walker(c, mode, -10_000..10_000) {
        w.walk(rows, &mut rec);
    }
    rec
}

/// `floor(x_edge(y) / 16)` for the edge `a -> b` (`a.1 < b.1`).
fn column_at(a: (i64, i64), b: (i64, i64), y: i64) -> i64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    (a.0 * dy + (y - a.1) * dx).div_euclid(16 * dy)
}

/// Largest `|walker area - exact area|` over every pixel of the edge's rows
/// (1/65536 px), and the pixel where it happens. Checks the rows outside the
/// edge's y-range report nothing.
fn max_area_error(c: &EdgeCase, rec: &Recorder) -> (Q, (i32, i32)) {
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
        let full = (yhi - ylo) * 4096;
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
    let half = 1 << 15;
    for (p0, p1, sign) in [((72, 0), (72, 32), 1), ((72, 32), (72, 0), -1)] {
        let mut rec = Recorder::default();
        EdgeWalk::new(fp(p0), fp(p1), AreaMode::Exact, 0..10)
            .unwrap()
            .walk(0..2, &mut rec);
        let areas = rec.areas(0, 9);
        for y in 0..2 {
            let row = &areas[&y];
            assert_eq!(row[3], 0);
            assert_eq!(row[4], sign * half, "half of pixel 4");
            assert_eq!(row[5], sign * 2 * half);
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
            // SPEC §2: within 1/256 px = 256 units of 1/65536 px; the
            // documented per-edge bound is tighter: below 2 units (the
            // floors of the main term and of the spill).
            prop_assert!(err <= q(256), "error {} at {:?} for {:?}", err, at, c);
            prop_assert!(err < q(2), "error {} at {:?} for {:?}", err, at, c);
            Ok(())
        })
        .unwrap();
    eprintln!("exact mode: max edge-area error {} / 65536 px", max.get());
}

/// Edges the old walker's approximate spill (`e² * (du/dv)` by a rounded
/// reciprocal) got 2.09 and 2.14 of 4096 units wrong: the spill tracked by
/// differences is exact, so only the two floors remain.
#[test]
fn exact_edge_area_within_documented_two_units() {
    for (p0, p1) in [((39, 20), (55, -2)), ((10, 26), (32, 64))] {
        let c = EdgeCase {
            p0,
            p1,
            orientation: 1,
        };
        let (err, at) = max_area_error(&c, &walk(&c, AreaMode::Exact, rows_of(&c)));
        assert!(
            err < q(2),
            "edge {p0:?} -> {p1:?}: error {err} / 65536 px at {at:?}"
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
            // k/8 px + 2/65536 px, in 1/65536 px: 8192 k + 2.
            let bound = q(8192) * Q::new(minor.into(), major.into()) + q(2);
            if minor > 0 {
                let r = to_f64(&(err / (q(8192) * Q::new(minor.into(), major.into()))));
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
    };
    let (seed_err, _) = max_area_error(&c, &walk(&c, AreaMode::SeedFormula, rows_of(&c)));
    let (exact_err, _) = max_area_error(&c, &walk(&c, AreaMode::Exact, rows_of(&c)));
    eprintln!(
        "45° edge: seed error {} / 65536 px, exact error {} / 65536 px",
        seed_err, exact_err
    );
    assert!(
        seed_err > q(4096),
        "seed error {seed_err} is not above 1/16 px"
    );
    assert!(seed_err <= q(8192 + 2));
    assert!(exact_err < q(2));
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
            prop_assert!(part.covers.iter().all(|k| rows.contains(&k.1)));
            Ok(())
        })
        .unwrap();
}

#[test]
fn every_octant_is_exact() {
    // One edge per octant (and the axes), sub-pixel end points, both
    // orientations: the area check as above.
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
                };
                for mode in [AreaMode::Exact, AreaMode::SeedFormula] {
                    let (err, at) = max_area_error(&c, &walk(&c, mode, rows_of(&c)));
                    let bound = if mode == AreaMode::Exact { 2 } else { 8192 + 2 };
                    assert!(err <= q(bound), "{mode:?} error {err} at {at:?} for {c:?}");
                }
            }
        }
    }
}

/// Walking the bands of a frame in order resumes each edge where the band
/// above stopped; starting every band afresh, or walking the whole edge at
/// once, must give the same reports in every row — and so must a sink
/// that keeps only some columns, within them.
#[test]
fn resumed_walk_equals_fresh_walks_and_the_whole_walk() {
    let mut runner = TestRunner::new(Config {
        failure_persistence: None,
        ..Config::with_cases(256)
    });
    runner
        .run(
            &(edge_case(), 1i32..9, -40i32..40, 1i32..60),
            |(c, band, col0, cols)| {
                let full = rows_of(&c);
                let columns =
                    col0 + c.p0.0.min(c.p1.0) as i32 / 16..col0 + cols + c.p0.0 as i32 / 16;
                for mode in [AreaMode::Exact, AreaMode::SeedFormula] {
                    let Some(base) = walker(&c, mode, columns.clone()) else {
                        continue;
                    };
                    let mut whole = Recorder::default();
                    { base }.walk(full.clone(), &mut whole);
                    let mut resumed = Recorder::default();
                    let mut fresh = Recorder::default();
                    let mut w = base;
                    let mut y = full.start;
                    while y < full.end {
                        let rows = y..(y + band).min(full.end);
                        w.walk(rows.clone(), &mut resumed);
                        // A fresh copy of the set-up walk: started over.
                        { base }.walk(rows, &mut fresh);
                        y += band;
                    }
                    let (lo, hi) = (columns.start, columns.end - 1);
                    let aw = whole.areas(lo, hi);
                    prop_assert_eq!(&aw, &resumed.areas(lo, hi), "resumed, {:?}", mode);
                    prop_assert_eq!(&aw, &fresh.areas(lo, hi), "fresh, {:?}", mode);
                    // Within the kept columns, the same as an unclipped walk.
                    let free = walk(&c, mode, full.clone());
                    let af = free.areas(lo, hi);
                    for y in full.clone() {
                        let zero = vec![0; (hi - lo + 1) as usize];
                        prop_assert_eq!(
                            aw.get(&y).unwrap_or(&zero),
                            af.get(&y).unwrap_or(&zero),
                            "row {} clipped to {:?}, {:?}",
                            y,
                            columns,
                            mode
                        );
                    }
                }
                Ok(())
            },
        )
        .unwrap();
}
