//! Paths and shapes against independent `f64` references: flattening
//! error, areas, per-pixel coverage, winding numbers, embedded-graphics'
//! conventions.

use std::f64::consts::PI;

use softedge::geom::{FinePoint, PathSink};
use softedge::path::svg::parse_path_data;
use softedge::path::{
    Arc, Circle, CornerRadii, Degrees, Ellipse, Flattener, Rectangle, RoundedRectangle, Sector,
    Shape, StrokeStyle, Tolerance,
};
use softedge_tests::path_ref::{
    bezier, disc_box_area, dist_to_segment, fine_point, polygon_winding, BezierIndex, Rng,
    Segments, FINE,
};

/// `sqrt(2)/2` fine units: the grid rounding of a vertex.
const ROUNDING: f64 = std::f64::consts::FRAC_1_SQRT_2;

fn fine_px(p: FinePoint) -> (f64, f64) {
    (f64::from(p.x) * FINE, f64::from(p.y) * FINE)
}

/// The polyline a flattener emits for one open curve from `c[0]`: all
/// segments but the closing one (the flattener emits them in order).
fn flatten_curve(c: &[FinePoint], tol: Tolerance) -> Segments {
    let mut s = Segments::new();
    {
        let mut f = Flattener::with_tolerance(&mut s, tol);
        f.move_to(c[0]);
        match c.len() {
            3 => f.quad_to(c[1], c[2]),
            _ => f.cubic_to(c[1], c[2], c[3]),
        }
        f.finish();
    }
    // Drop the closing segment back to the start.
    if s.segs.last().is_some_and(|&(_, b)| b == c[0]) && c.last() != Some(&c[0]) {
        s.segs.pop();
    }
    s
}

fn check_curve_bound(c: &[FinePoint], tol: Tolerance) -> f64 {
    let cf: Vec<(f64, f64)> = c.iter().map(|&p| fine_px(p)).collect();
    let s = flatten_curve(c, tol);
    let bound = (f64::from(tol.fine()) + ROUNDING) * FINE + 1e-9;
    let mut worst = 0f64;
    let curve = BezierIndex::new(&cf);
    // Every vertex and every chord midpoint near the curve.
    for ((ax, ay), (bx, by)) in s.px() {
        for p in [(ax, ay), ((ax + bx) / 2.0, (ay + by) / 2.0)] {
            worst = worst.max(curve.distance(p));
        }
    }
    // Every point of the curve near the polygon.
    for i in 0..=400 {
        let q = bezier(&cf, f64::from(i) / 400.0);
        let d = s
            .px()
            .map(|(a, b)| dist_to_segment(q, a, b))
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(d);
    }
    assert!(
        worst <= bound,
        "{c:?} tol {}: {} > {}",
        tol.fine(),
        worst / FINE,
        bound / FINE
    );
    worst / FINE
}

#[test]
fn flattened_cubics_stay_within_tolerance_plus_rounding() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut worst = 0f64;
    for tol in [1u16, 3, 16, 256] {
        for _ in 0..20 {
            let c: Vec<FinePoint> = (0..4)
                .map(|_| fine_point(rng.range(0.0, 200.0), rng.range(0.0, 200.0)))
                .collect();
            worst = worst.max(check_curve_bound(&c, Tolerance::new(tol)) - f64::from(tol));
        }
    }
    println!("cubics: worst distance beyond tol {worst:.3} fine units (bound {ROUNDING})");
}

#[test]
fn flattened_quadratics_stay_within_tolerance_plus_rounding() {
    let mut rng = Rng(0x0fed_cba9_8765_4321);
    for tol in [1u16, 3, 40] {
        for _ in 0..25 {
            let c: Vec<FinePoint> = (0..3)
                .map(|_| fine_point(rng.range(-50.0, 150.0), rng.range(0.0, 100.0)))
                .collect();
            check_curve_bound(&c, Tolerance::new(tol));
        }
    }
}

#[test]
fn cusps_and_degenerate_cubics_stay_within_the_bound() {
    let p = |x: f64, y: f64| fine_point(x, y);
    let cases = [
        vec![p(0.0, 0.0), p(30.0, 30.0), p(0.0, 30.0), p(30.0, 0.0)], // cusp
        vec![p(0.0, 0.0), p(40.0, 40.0), p(-10.0, 40.0), p(30.0, 0.0)], // loop
        vec![p(5.0, 5.0), p(5.0, 5.0), p(5.0, 5.0), p(25.0, 5.0)],
        vec![p(0.0, 0.0), p(10.0, 0.0), p(20.0, 0.0), p(30.0, 0.0)], // straight
        vec![p(0.0, 0.0), p(30.0, 0.0), p(-10.0, 0.0), p(20.0, 0.0)], // folds back on a line
    ];
    for c in cases {
        check_curve_bound(&c, Tolerance::DEFAULT);
    }
}

#[test]
fn huge_and_degenerate_curves_give_bounded_closed_output_in_range() {
    let (a, b) = (i32::MIN, i32::MAX);
    let mut s = Segments::new();
    {
        let mut f = Flattener::new(&mut s);
        f.move_to(FinePoint::new(a, 0));
        f.cubic_to(
            FinePoint::new(b, b),
            FinePoint::new(a, a),
            FinePoint::new(b, 0),
        );
        f.quad_to(FinePoint::new(0, b), FinePoint::new(a, a));
        let q = FinePoint::new(7, 7);
        f.move_to(q);
        f.cubic_to(q, q, q);
        f.line_to(q);
        f.close();
    }
    assert!(s.is_closed_in_range());
    assert!(s.len() <= 5 * (2 * 1024 + 2), "{}", s.len());
}

fn random_centre(rng: &mut Rng) -> FinePoint {
    fine_point(rng.range(120.0, 130.0), rng.range(120.0, 130.0))
}

#[test]
fn disc_area_is_within_0_2_percent_of_pi_r_squared_for_radii_half_to_100_px() {
    let mut rng = Rng(42);
    let mut radii = vec![
        0.5, 0.55, 0.6, 0.75, 1.0, 1.3, 2.0, 3.7, 5.0, 8.0, 13.3, 21.0, 34.0, 55.0, 89.0, 100.0,
    ];
    radii.extend((0..200).map(|_| 0.5 + 99.5 * rng.f().powi(3)));
    let mut worst: f64 = 0.0;
    for &r in &radii {
        let r_fine = (r * 1024.0).round() as u32;
        let c = Circle::new(random_centre(&mut rng), r_fine);
        let mut s = Segments::new();
        c.fill(&mut s);
        assert!(s.is_closed_in_range());
        let rr = f64::from(r_fine) * FINE;
        let rel = s.shoelace() / (PI * rr * rr) - 1.0;
        worst = worst.max(rel.abs());
        assert!(rel.abs() < 0.002, "r = {r}: {rel:e}");
    }
    println!("disc area: worst relative error {worst:.2e} (limit 2e-3)");
}

#[test]
fn disc_pixel_coverage_is_within_1_64_of_the_exact_disc() {
    let mut rng = Rng(7);
    let mut worst: f64 = 0.0;
    for r in [0.5, 0.8, 1.5, 4.2, 17.0, 100.0] {
        let r_fine = (r * 1024.0_f64).round() as u32;
        let centre = random_centre(&mut rng);
        let c = Circle::new(centre, r_fine);
        let mut s = Segments::new();
        c.fill(&mut s);
        let (cx, cy) = fine_px(centre);
        let rr = f64::from(r_fine) * FINE;
        let (i0, i1) = ((cx - rr).floor() as i32 - 1, (cx + rr).ceil() as i32 + 1);
        for row in (cy - rr).floor() as i32 - 1..=(cy + rr).ceil() as i32 {
            let cov = s.row_coverage(row, i0, i1, 64, |w| w != 0);
            for (k, got) in cov.iter().enumerate() {
                let x = f64::from(i0) + k as f64;
                let y = f64::from(row);
                let want = disc_box_area(cx, cy, rr, x, y, x + 1.0, y + 1.0);
                worst = worst.max((got - want).abs());
            }
        }
    }
    println!("disc pixel coverage: worst error {worst:.5} (limit 1/64 = 0.0156)");
    assert!(worst < 1.0 / 64.0, "{worst}");
}

/// Distance from `p` to the ellipse `(c, a, b, rot)` (f64, by dense
/// parameter sampling and refinement).
fn dist_to_ellipse(p: (f64, f64), c: (f64, f64), a: f64, b: f64, rot: f64) -> f64 {
    let (cs, sn) = (rot.cos(), rot.sin());
    let at = |t: f64| {
        let (u, v) = (a * t.cos(), b * t.sin());
        (c.0 + cs * u - sn * v, c.1 + sn * u + cs * v)
    };
    let d = |t: f64| {
        let q = at(t);
        ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt()
    };
    let n = 4000;
    let mut best = (0.0, f64::INFINITY);
    for i in 0..n {
        let t = 2.0 * PI * f64::from(i) / f64::from(n);
        let v = d(t);
        if v < best.1 {
            best = (t, v);
        }
    }
    let (mut lo, mut hi) = (
        best.0 - 2.0 * PI / f64::from(n),
        best.0 + 2.0 * PI / f64::from(n),
    );
    for _ in 0..60 {
        let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
        if d(m1) < d(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    d((lo + hi) / 2.0).min(best.1)
}

#[test]
fn circle_and_ellipse_polygons_stay_within_tolerance_plus_rounding_and_keep_their_area() {
    let mut rng = Rng(99);
    let bound = (f64::from(Tolerance::DEFAULT.fine()) + ROUNDING) * FINE;
    for k in 0..40 {
        let a = rng.range(0.5, 120.0);
        let b = if k % 4 == 0 { a } else { rng.range(0.5, 120.0) };
        let rot_deg = if k % 3 == 0 {
            0.0
        } else {
            rng.range(-360.0, 360.0)
        };
        let rot_bits = (rot_deg * 65536.0_f64).round() as i32;
        let centre = random_centre(&mut rng);
        let (af, bf) = (
            (a * 1024.0_f64).round() as u32,
            (b * 1024.0_f64).round() as u32,
        );
        let e = Ellipse::new(centre, af, bf).rotated(Degrees::from_bits(rot_bits));
        let mut s = Segments::new();
        e.fill(&mut s);
        let (a, b) = (f64::from(af) * FINE, f64::from(bf) * FINE);
        let rot = f64::from(rot_bits) / 65536.0 * PI / 180.0;
        let c = fine_px(centre);
        for ((ax, ay), (bx, by)) in s.px() {
            for p in [(ax, ay), ((ax + bx) / 2.0, (ay + by) / 2.0)] {
                let d = dist_to_ellipse(p, c, a, b, rot);
                assert!(d <= bound, "ellipse {a} {b} {rot}: {} fine units", d / FINE);
            }
        }
        let rel = s.shoelace() / (PI * a * b) - 1.0;
        assert!(rel.abs() < 2e-3, "{a} {b}: {rel:e}");
    }
}

#[test]
fn rounded_rectangle_area_matches_the_formula_with_css_clamping() {
    let px = |v: f64| (v * 1024.0).round() as u32;
    type Case = (f64, f64, [(f64, f64); 4]);
    let cases: [Case; 5] = [
        (40.0, 30.0, [(5.0, 5.0); 4]),
        (
            40.0,
            30.0,
            [(10.0, 4.0), (0.0, 0.0), (3.0, 12.0), (7.5, 7.5)],
        ),
        (50.0, 60.0, [(40.0, 40.0); 4]), // clamped by 50/80
        (
            20.0,
            100.0,
            [(15.0, 60.0), (15.0, 60.0), (2.0, 2.0), (2.0, 2.0)],
        ),
        (3.3, 2.2, [(1.0, 0.7), (0.5, 0.5), (1.6, 1.1), (0.0, 3.0)]), // a zero radius: square
    ];
    for (w, h, radii) in cases {
        let (wf, hf) = (px(w), px(h));
        let rf = radii.map(|(x, y)| (px(x), px(y)));
        let rr = RoundedRectangle::new(
            Rectangle::new(fine_point(10.25, 20.5), wf, hf),
            CornerRadii {
                top_left: rf[0],
                top_right: rf[1],
                bottom_right: rf[2],
                bottom_left: rf[3],
            },
        );
        // The reference clamp (CSS Backgrounds 3): f = min(1, side / sum).
        let r: Vec<(f64, f64)> = rf
            .iter()
            .map(|&(x, y)| {
                if x == 0 || y == 0 {
                    (0.0, 0.0)
                } else {
                    (f64::from(x), f64::from(y))
                }
            })
            .collect();
        let (w, h) = (f64::from(wf), f64::from(hf));
        let f = [
            w / (r[0].0 + r[1].0),
            h / (r[1].1 + r[2].1),
            w / (r[2].0 + r[3].0),
            h / (r[3].1 + r[0].1),
        ]
        .into_iter()
        .filter(|v| v.is_finite())
        .fold(1.0f64, f64::min);
        let corners: f64 = r
            .iter()
            .map(|&(x, y)| (x * f).floor() * (y * f).floor())
            .sum();
        let want = (w * h - (1.0 - PI / 4.0) * corners) * FINE * FINE;
        let mut s = Segments::new();
        rr.fill(&mut s);
        assert!(s.is_closed_in_range());
        let rel = s.shoelace() / want - 1.0;
        assert!(rel.abs() < 5e-4, "{w} {h}: {rel:e}");
        // Straight sides: the bounding box is the rectangle's, exactly.
        let (x0, y0, x1, y1) = s.bbox().unwrap_or_default();
        assert_eq!(
            (x0, y0, x1 - x0, y1 - y0),
            (10.25, 20.5, w * FINE, h * FINE)
        );
    }
}

#[test]
fn sector_area_is_half_sweep_times_r_squared() {
    let mut rng = Rng(5);
    for _ in 0..50 {
        let r = rng.range(0.5, 80.0);
        let start = rng.range(-720.0, 720.0);
        let sweep = rng.range(-400.0, 400.0);
        let rf = (r * 1024.0_f64).round() as u32;
        let sw_bits = (sweep * 65536.0_f64).round() as i32;
        let sec = Sector::new(
            random_centre(&mut rng),
            rf,
            Degrees::from_bits((start * 65536.0_f64) as i32),
            Degrees::from_bits(sw_bits),
        );
        let mut s = Segments::new();
        sec.fill(&mut s);
        let rr = f64::from(rf) * FINE;
        let sweep = (f64::from(sw_bits) / 65536.0).abs().min(360.0) * PI / 180.0;
        let want = sweep / 2.0 * rr * rr;
        assert!(s.is_closed_in_range());
        let got = s.shoelace();
        assert!(
            (got - want).abs() <= 2e-3 * want + 1e-4,
            "r {r} sweep {sweep}: {got} vs {want}"
        );
        assert!(s.nonzero_area(32) <= got * 1.001 + 1e-3);
    }
}

#[test]
fn arc_stroke_with_butt_caps_is_the_annular_sector() {
    let mut rng = Rng(11);
    for _ in 0..30 {
        let r = rng.range(2.0, 60.0);
        let w = rng.range(0.1, 2.0 * r);
        let sweep = rng.range(-300.0, 300.0);
        let rf = (r * 1024.0_f64).round() as u32;
        let wf = (w * 1024.0_f64).round() as u32;
        let sw = (sweep * 65536.0_f64).round() as i32;
        let arc = Arc::new(
            random_centre(&mut rng),
            rf,
            Degrees::new(30),
            Degrees::from_bits(sw),
        );
        let mut s = Segments::new();
        arc.stroke(&StrokeStyle::new(wf), &mut s).unwrap();
        let (rr, h) = (f64::from(rf) * FINE, f64::from(wf) * FINE / 2.0);
        let ri = (rr - h).max(0.0);
        let want =
            (f64::from(sw) / 65536.0).abs() * PI / 180.0 / 2.0 * ((rr + h).powi(2) - ri * ri);
        let got = s.shoelace();
        assert!(
            (got / want - 1.0).abs() < 2e-3,
            "{r} {w} {sweep}: {got} vs {want}"
        );
        let (lo, hi) = s.winding_extremes(0.37);
        assert!(lo >= 0 && hi <= 1);
    }
}

#[test]
fn a_ring_is_two_contours_whose_areas_subtract() {
    let c = Circle::new(fine_point(50.0, 50.0), 20 * 1024);
    let mut s = Segments::new();
    c.stroke(&StrokeStyle::new(4 * 1024), &mut s).unwrap();
    assert!(s.is_closed_in_range());
    let want = PI * (22.0f64.powi(2) - 18.0f64.powi(2));
    assert!((s.shoelace() / want - 1.0).abs() < 1e-3);
    assert!((s.nonzero_area(16) / want - 1.0).abs() < 1e-3);
    assert_eq!(s.winding(50.0, 50.0), 0); // the hole
    assert_eq!(s.winding(70.0, 50.0), 1); // the ring
    assert_eq!(s.winding(50.0, 29.0), 1);
    assert_eq!(s.winding(80.0, 50.0), 0); // outside
                                          // The hole runs counter-clockwise: its own shoelace is negative.
    let (outer, inner): (Vec<_>, Vec<_>) = s.segs.iter().partition(|(a, _)| {
        let (x, y) = fine_px(*a);
        (x - 50.0).hypot(y - 50.0) > 20.0
    });
    let sl = |v: &[&(FinePoint, FinePoint)]| {
        Segments {
            segs: v.iter().map(|&&p| p).collect(),
        }
        .shoelace()
    };
    assert!(sl(&outer) > 0.0 && sl(&inner) < 0.0);
}

/// The test path: a pentagram (self-intersecting: winding 2 in the
/// middle), a square with a square inside running the same way (winding
/// 2) and one inside it running the other way (back to 1), a curved
/// contour. Returns the exact contours (curves sampled densely).
fn winding_test_path<P: PathSink>(sink: &mut P) -> Vec<Vec<(f64, f64)>> {
    let mut contours = Vec::new();
    let star: Vec<(f64, f64)> = (0..5)
        .map(|k| {
            let t = -PI / 2.0 + f64::from(k * 2) * 2.0 * PI / 5.0;
            (30.0 + 25.0 * t.cos(), 30.0 + 25.0 * t.sin())
        })
        .collect();
    let stf: Vec<FinePoint> = star.iter().map(|&(x, y)| fine_point(x, y)).collect();
    sink.move_to(stf[0]);
    for p in &stf[1..] {
        sink.line_to(*p);
    }
    sink.close();
    contours.push(stf.iter().map(|&p| fine_px(p)).collect());
    let sq = |x0: f64, y0: f64, s: f64, cw: bool| -> Vec<(f64, f64)> {
        let v = vec![(x0, y0), (x0 + s, y0), (x0 + s, y0 + s), (x0, y0 + s)];
        if cw {
            v
        } else {
            v.into_iter().rev().collect()
        }
    };
    for q in [
        sq(70.0, 5.0, 50.0, true),
        sq(80.0, 15.0, 30.0, true),
        sq(88.0, 23.0, 14.0, false),
    ] {
        sink.move_to(fine_point(q[0].0, q[0].1));
        for p in &q[1..] {
            sink.line_to(fine_point(p.0, p.1));
        }
        // Left open: the flattener closes it on the next move_to.
        contours.push(q);
    }
    let c = [(10.0, 70.0), (60.0, 60.0), (40.0, 110.0), (10.0, 100.0)];
    let cf: Vec<FinePoint> = c.iter().map(|&(x, y)| fine_point(x, y)).collect();
    sink.move_to(cf[0]);
    sink.cubic_to(cf[1], cf[2], cf[3]);
    sink.quad_to(fine_point(-10.0, 85.0), cf[0]);
    let cp: Vec<(f64, f64)> = cf.iter().map(|&p| fine_px(p)).collect();
    let mut curve: Vec<(f64, f64)> = (0..2000)
        .map(|i| bezier(&cp, f64::from(i) / 2000.0))
        .collect();
    let q = [cp[3], fine_px(fine_point(-10.0, 85.0)), cp[0]];
    curve.extend((0..2000).map(|i| bezier(&q, f64::from(i) / 2000.0)));
    contours.push(curve);
    contours
}

#[test]
fn pentagram_and_nested_contours_wind_like_the_path_for_nonzero_and_even_odd() {
    let mut s = Segments::new();
    let contours = {
        let mut f = Flattener::new(&mut s);
        let c = winding_test_path(&mut f);
        f.finish();
        c
    };
    assert!(s.is_closed_in_range());
    let mut checked = 0;
    let mut y = 0.25;
    while y < 120.0 {
        let mut x = 0.13;
        while x < 125.0 {
            // Skip points within 0.01 px of any edge (the flattening moves
            // curved edges by up to 0.004 px).
            let near = s.px().any(|(a, b)| dist_to_segment((x, y), a, b) < 0.01);
            if !near {
                let want: i32 = contours.iter().map(|c| polygon_winding(c, x, y)).sum();
                let got = s.winding(x, y);
                assert_eq!(got, want, "winding at ({x}, {y})");
                assert_eq!(got != 0, want != 0, "nonzero at ({x}, {y})");
                assert_eq!(got % 2 != 0, want % 2 != 0, "even-odd at ({x}, {y})");
                checked += 1;
            }
            x += 0.7;
        }
        y += 0.7;
    }
    assert!(checked > 25_000);
    // The star's centre winds twice: nonzero fills it, even-odd does not.
    assert_eq!(s.winding(30.0, 31.0), 2);
    assert_eq!(s.winding(95.0, 30.0), 1);
    assert_eq!(s.winding(85.0, 30.0), 2);
}

#[test]
fn svg_path_data_gives_the_same_pentagram() {
    let d = "M30,5 L44.69,50.23 6.22,22.27 H53.78 L15.31,50.23 Z";
    let mut s = Segments::new();
    {
        let mut f = Flattener::new(&mut s);
        parse_path_data(d, &mut f).unwrap();
    }
    let star = [
        (30.0, 5.0),
        (44.69, 50.23),
        (6.22, 22.27),
        (53.78, 22.27),
        (15.31, 50.23),
    ];
    for (x, y) in [
        (30.0, 30.0),
        (30.0, 15.0),
        (20.0, 40.0),
        (50.0, 10.0),
        (30.0, 48.0),
    ] {
        assert_eq!(s.winding(x, y), polygon_winding(&star, x, y), "({x}, {y})");
    }
    assert_eq!(s.winding(30.0, 30.0), 2);
}

mod embedded_graphics_conventions {
    use super::*;
    use embedded_graphics::geometry::{AngleUnit, Point, Size};
    use embedded_graphics::prelude::{Dimensions, Transform};
    use embedded_graphics::primitives as eg;

    /// The bounding box of a shape's fill, px.
    fn fill_bbox<S: Shape>(s: &S) -> (f64, f64, f64, f64) {
        let mut seg = Segments::new();
        s.fill(&mut seg);
        seg.bbox().unwrap_or_default()
    }

    fn eg_box(r: eg::Rectangle) -> (f64, f64, f64, f64) {
        let (x, y) = (f64::from(r.top_left.x), f64::from(r.top_left.y));
        (
            x,
            y,
            x + f64::from(r.size.width),
            y + f64::from(r.size.height),
        )
    }

    fn close(a: (f64, f64, f64, f64), b: (f64, f64, f64, f64), tol: f64) -> bool {
        (a.0 - b.0).abs() <= tol
            && (a.1 - b.1).abs() <= tol
            && (a.2 - b.2).abs() <= tol
            && (a.3 - b.3).abs() <= tol
    }

    #[test]
    fn rectangles_cover_their_bounding_box_exactly() {
        let r = eg::Rectangle::new(Point::new(-3, 7), Size::new(10, 4));
        assert_eq!(fill_bbox(&Rectangle::from(r)), eg_box(r.bounding_box()));
        let rr = eg::RoundedRectangle::with_equal_corners(r, Size::new(3, 2));
        assert_eq!(
            fill_bbox(&RoundedRectangle::from(rr)),
            eg_box(rr.bounding_box())
        );
    }

    #[test]
    fn circles_and_ellipses_are_inscribed_in_their_bounding_box() {
        // The area-preserving vertices stand out by at most 0.35 r (pi/n)^2
        // plus the rounding: a few fine units.
        let tol = 4.0 * FINE;
        for d in [1u32, 2, 7, 30] {
            let c = eg::Circle::new(Point::new(5, -2), d);
            let b = fill_bbox(&Circle::from(c));
            assert!(close(b, eg_box(c.bounding_box()), tol), "{d}: {b:?}");
        }
        let e = eg::Ellipse::new(Point::new(1, 2), Size::new(9, 4));
        assert!(close(
            fill_bbox(&Ellipse::from(e)),
            eg_box(e.bounding_box()),
            tol
        ));
    }

    #[test]
    fn arcs_and_sectors_run_clockwise_from_3_o_clock() {
        // 0 to +90 degrees: the bottom-right quarter (y grows downwards).
        let s = eg::Sector::new(Point::new(0, 0), 20, 0.0.deg(), 90.0.deg());
        let b = fill_bbox(&Sector::from(s));
        assert!(close(b, (10.0, 10.0, 20.0, 20.0), 4.0 * FINE), "{b:?}");
        // 180 degrees back by -90: the bottom-left quarter (as
        // embedded-graphics' own quadrant test has it).
        let s = eg::Sector::new(Point::new(0, 0), 20, 180.0.deg(), (-90.0).deg());
        let b = fill_bbox(&Sector::from(s));
        assert!(close(b, (0.0, 10.0, 10.0, 20.0), 4.0 * FINE), "{b:?}");
        // 270 plus 90: the top-right quarter.
        let s = eg::Sector::new(Point::new(0, 0), 20, 270.0.deg(), 90.0.deg());
        let b = fill_bbox(&Sector::from(s));
        assert!(close(b, (10.0, 0.0, 20.0, 10.0), 4.0 * FINE), "{b:?}");
        let a = eg::Arc::new(Point::new(0, 0), 20, 90.0.deg(), 90.0.deg());
        let mut seg = Segments::new();
        Arc::from(a)
            .stroke(&StrokeStyle::new(2048), &mut seg)
            .unwrap();
        let b = seg.bbox().unwrap_or_default();
        // Bottom-left quarter of the ring of radii 9 and 11 about (10, 10).
        assert!(close(b, (-1.0, 10.0, 10.0, 21.0), 4.0 * FINE), "{b:?}");
    }

    #[test]
    fn lines_and_polylines_run_between_pixel_centres() {
        let l = eg::Line::new(Point::new(2, 3), Point::new(12, 3));
        let mut seg = Segments::new();
        softedge::path::Line::from(l)
            .stroke(&StrokeStyle::new(1024), &mut seg)
            .unwrap();
        assert_eq!(seg.bbox(), Some((2.5, 3.0, 12.5, 4.0)));
        let pts = [Point::new(0, 0), Point::new(10, 0), Point::new(10, 10)];
        let p = eg::Polyline::new(&pts).translate(Point::new(5, 5));
        let mut seg = Segments::new();
        let style = StrokeStyle::new(2048);
        softedge::path::Polyline::from(p)
            .stroke(&style, &mut seg)
            .unwrap();
        // Miter join at (15.5, 5.5): the outer corner at (16.5, 4.5).
        assert_eq!(seg.bbox(), Some((5.5, 4.5, 16.5, 15.5)));
    }

    #[test]
    fn primitive_style_alignment_moves_the_stroke_of_closed_shapes() {
        use embedded_graphics::pixelcolor::BinaryColor;
        let c = eg::Circle::new(Point::new(0, 0), 20);
        for (al, ro, ri) in [
            (eg::StrokeAlignment::Inside, 10.0, 7.0),
            (eg::StrokeAlignment::Center, 11.5, 8.5),
            (eg::StrokeAlignment::Outside, 13.0, 10.0),
        ] {
            let style = eg::PrimitiveStyleBuilder::new()
                .stroke_color(BinaryColor::On)
                .stroke_width(3)
                .stroke_alignment(al)
                .build();
            let st = StrokeStyle::from_primitive_style(&style).unwrap();
            let mut seg = Segments::new();
            Circle::from(c).stroke(&st, &mut seg).unwrap();
            let want = PI * (ro * ro - ri * ri);
            assert!((seg.shoelace() / want - 1.0).abs() < 1e-3, "{al:?}");
        }
    }
}

/// Radii beyond `MAX_RADIUS` (the documented limit) are limited to it,
/// centre and arc together: a rounded rectangle with larger radii is the
/// one with `MAX_RADIUS` corners, segment for segment, filled and
/// stroked; and a stroke whose outer corners grow past the limit stays
/// a ring of non-negative area. (The fuzzer found a stroked rounded
/// rectangle far beyond the coordinate range whose arcs had been limited
/// but not their centres: its contours crossed, and their area came out
/// at -5 million px².)
#[test]
fn rounded_corners_beyond_the_radius_limit_are_limited_to_it() {
    use softedge::path::MAX_RADIUS;
    let m = MAX_RADIUS;
    // The top-left corner at the range's (its cut reaches 0.29 r into
    // it, so the range sees the corners), the others far outside.
    let l = softedge::geom::FINE_LIMIT;
    let rect = Rectangle::new(FinePoint::new(-l, -l), 6 * m, 7 * m);
    let big = RoundedRectangle::new(rect, CornerRadii::uniform(2 * m + 12_345));
    let limited = RoundedRectangle::new(rect, CornerRadii::uniform(m));
    let style = StrokeStyle::new(40 * 1024);
    for stroke in [false, true] {
        let (mut a, mut b) = (Segments::new(), Segments::new());
        if stroke {
            big.stroke(&style, &mut a).unwrap();
            limited.stroke(&style, &mut b).unwrap();
        } else {
            big.fill(&mut a);
            limited.fill(&mut b);
        }
        assert!(a.is_closed_in_range() && !a.is_empty());
        assert_eq!(a.segs, b.segs, "stroke: {stroke}");
        assert!(a.shoelace() >= 0.0);
    }
    // The fuzzer's case: corners of every kind, far out of range.
    let rr = RoundedRectangle::new(
        Rectangle::new(
            FinePoint::new(-2_098_599, 5237),
            2_264_817_684,
            1_448_498_822,
        ),
        CornerRadii {
            top_left: (511, 5_765_839),
            top_right: (1536, 1_611_924_223),
            bottom_right: (14_726_534, 0),
            bottom_left: (28_766, 0),
        },
    );
    let mut s = Segments::new();
    rr.stroke(&StrokeStyle::new(14_790), &mut s).unwrap();
    assert!(s.is_closed_in_range());
    // Within a square pixel of slack for the grid rounding of cuts.
    assert!(s.shoelace() > -1.0, "{}", s.shoelace());
}
