//! Strokes against independent `f64` references: areas of straight
//! strokes, the exact union of a polyline's stroke (rectangles, join
//! wedges, caps from the SVG definition), winding numbers (never
//! negative; exactly one where the pieces tile), dashes, alignment and
//! the degenerate cases.

use std::f64::consts::PI;

use softedge::geom::{FinePoint, PathSink};
use softedge::path::svg::parse_path_data;
use softedge::path::{
    Circle, Dash, Degrees, Ellipse, LineCap, LineJoin, MiterLimit, Rectangle, Sector, Shape,
    StrokeAlignment, StrokeError, StrokeStyle, Stroker, MAX_DASH_INTERVALS,
};
use softedge_tests::path_ref::{
    bezier, fine_point, polyline_stroke, union_area, RefCap, RefJoin, Region, Rng, Segments, FINE,
};

fn px(p: FinePoint) -> (f64, f64) {
    (f64::from(p.x) * FINE, f64::from(p.y) * FINE)
}

/// Strokes a polyline (closed: back to its first point with `close`).
fn stroke_polyline(
    pts: &[FinePoint],
    closed: bool,
    style: &StrokeStyle<'_>,
) -> (Segments, Result<(), StrokeError>) {
    let mut s = Segments::new();
    let r = {
        let mut st = Stroker::new(style, &mut s);
        st.move_to(pts[0]);
        for &p in &pts[1..] {
            st.line_to(p);
        }
        if closed {
            st.close();
        }
        st.finish()
    };
    (s, r)
}

fn ref_join(j: LineJoin) -> RefJoin {
    match j {
        LineJoin::Miter => RefJoin::Miter(4.0),
        LineJoin::Round => RefJoin::Round,
        LineJoin::Bevel => RefJoin::Bevel,
    }
}

fn ref_cap(c: LineCap) -> RefCap {
    match c {
        LineCap::Butt => RefCap::Butt,
        LineCap::Round => RefCap::Round,
        LineCap::Square => RefCap::Square,
    }
}

const JOINS: [LineJoin; 3] = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel];
const CAPS: [LineCap; 3] = [LineCap::Butt, LineCap::Round, LineCap::Square];

#[test]
fn a_straight_stroke_is_length_times_width_plus_its_caps() {
    let mut rng = Rng(1);
    for k in 0..120 {
        let (x, y) = (rng.range(50.0, 60.0), rng.range(50.0, 60.0));
        let len = rng.range(0.3, 100.0);
        let ang = rng.range(0.0, 2.0 * PI);
        // Widths from a 1/16-px hairline to 20 px.
        let w = if k % 5 == 0 {
            1.0 / 16.0
        } else {
            rng.range(0.1, 20.0)
        };
        let (a, b) = (
            fine_point(x, y),
            fine_point(x + len * ang.cos(), y + len * ang.sin()),
        );
        let wf = (w * 1024.0_f64).round() as u32;
        let w = f64::from(wf) * FINE;
        let (pa, pb) = (px(a), px(b));
        let l = (pb.0 - pa.0).hypot(pb.1 - pa.1);
        for cap in CAPS {
            let style = StrokeStyle::new(wf).with_cap(cap);
            let (s, r) = stroke_polyline(&[a, b], false, &style);
            r.unwrap();
            assert!(s.is_closed_in_range());
            let want = l * w
                + match cap {
                    LineCap::Butt => 0.0,
                    LineCap::Square => w * w,
                    LineCap::Round => PI * w * w / 4.0,
                };
            // The grid rounding moves each outline point by at most 0.71
            // fine units: allow that along the whole outline.
            let slack = 2.0 * (l + 2.0 * w) * 0.71 * FINE + 1e-3 * want;
            let got = s.shoelace();
            assert!(
                (got - want).abs() <= slack,
                "{cap:?} l {l} w {w}: {got} vs {want}"
            );
            assert_eq!(
                s.winding_extremes(w.min(0.5) / 3.0).0,
                0,
                "negative winding"
            );
        }
    }
}

#[test]
fn polyline_stroke_area_equals_the_exact_union_within_half_a_percent() {
    let mut rng = Rng(2);
    let mut worst = 0f64;
    for k in 0..60 {
        let n = 2 + k % 6;
        let mut pts: Vec<FinePoint> = (0..n)
            .map(|_| fine_point(rng.range(10.0, 60.0), rng.range(10.0, 60.0)))
            .collect();
        if k % 7 == 3 {
            // A repeated point: a zero-length segment.
            pts.insert(1, pts[1]);
        }
        let w = rng.range(0.3, 8.0);
        let wf = (w * 1024.0_f64).round() as u32;
        let h = f64::from(wf) * FINE / 2.0;
        let closed = k % 3 == 0 && n > 2;
        for (j, join) in JOINS.into_iter().enumerate() {
            let cap = CAPS[(k + j) % 3];
            let style = StrokeStyle::new(wf).with_join(join).with_cap(cap);
            let (s, r) = stroke_polyline(&pts, closed, &style);
            r.unwrap();
            assert!(s.is_closed_in_range());
            let ptsf: Vec<(f64, f64)> = pts.iter().map(|&p| px(p)).collect();
            let want = union_area(
                &polyline_stroke(&ptsf, h, ref_join(join), ref_cap(cap), closed),
                64,
            );
            let got = s.nonzero_area(64);
            let rel = got / want - 1.0;
            worst = worst.max(rel.abs());
            assert!(
                rel.abs() < 5e-3,
                "polyline {k} {join:?} {cap:?} closed {closed}: {got} vs {want}"
            );
            assert!(s.winding_extremes(0.173).0 >= 0, "negative winding");
        }
    }
    println!("polyline strokes: worst relative area error {worst:.2e} (limit 5e-3)");
}

#[test]
fn gentle_polylines_tile_their_stroke_exactly_once() {
    // Turns below 60 degrees, segments longer than the width: every inner
    // corner is cut, so the winding number is 0 or 1 and the shoelace sum
    // is the area.
    let mut rng = Rng(3);
    for k in 0..30 {
        let w = rng.range(0.5, 4.0);
        let wf = (w * 1024.0_f64).round() as u32;
        let mut dir = rng.range(0.0, 2.0 * PI);
        let mut p = (rng.range(20.0, 40.0), rng.range(20.0, 40.0));
        let mut pts = vec![fine_point(p.0, p.1)];
        for _ in 0..5 {
            let l = rng.range(3.0 * w, 15.0);
            p = (p.0 + l * dir.cos(), p.1 + l * dir.sin());
            pts.push(fine_point(p.0, p.1));
            dir += rng.range(-1.0, 1.0);
        }
        let join = JOINS[k % 3];
        let (s, _) = stroke_polyline(
            &pts,
            false,
            &StrokeStyle::new(wf)
                .with_join(join)
                .with_cap(LineCap::Round),
        );
        assert_eq!(s.winding_extremes(0.0731), (0, 1), "polyline {k} {join:?}");
        let (a, b) = (s.shoelace(), s.nonzero_area(64));
        assert!((a / b - 1.0).abs() < 1e-3, "{a} vs {b}");
    }
}

#[test]
fn u_turns_and_coincident_points_keep_the_union() {
    let p = |x: f64, y: f64| fine_point(x, y);
    let cases: [&[FinePoint]; 5] = [
        &[p(10.0, 10.0), p(30.0, 10.0), p(10.0, 10.0)], // 180 degrees
        &[
            p(10.0, 10.0),
            p(30.0, 10.0),
            p(30.0, 10.0),
            p(30.0, 10.0),
            p(30.0, 25.0),
        ],
        &[p(10.0, 10.0), p(30.0, 10.0), p(12.0, 10.5)], // almost 180
        &[p(10.0, 10.0), p(10.5, 10.0), p(10.5, 30.0), p(11.0, 30.0)], // segments shorter than the width
        &[p(10.0, 10.0), p(30.0, 30.0), p(30.0, 10.0), p(10.0, 30.0)], // crosses itself
    ];
    for pts in cases {
        for join in JOINS {
            for cap in CAPS {
                let style = StrokeStyle::new(3 * 1024).with_join(join).with_cap(cap);
                let (s, _) = stroke_polyline(pts, false, &style);
                let ptsf: Vec<(f64, f64)> = pts.iter().map(|&q| px(q)).collect();
                let want = union_area(
                    &polyline_stroke(&ptsf, 1.5, ref_join(join), ref_cap(cap), false),
                    64,
                );
                let got = s.nonzero_area(64);
                assert!(
                    (got / want - 1.0).abs() < 5e-3,
                    "{pts:?} {join:?} {cap:?}: {got} vs {want}"
                );
                assert!(s.winding_extremes(0.0913).0 >= 0);
            }
        }
    }
}

#[test]
fn the_stroke_of_a_cubic_with_a_cusp_is_the_union_of_discs_along_it() {
    // Round caps: the stroke is exactly the set of points within h of
    // the curve. Reference: discs along a dense sampling, joined by the
    // rectangles between consecutive samples.
    let c = [(10.0, 10.0), (40.0, 40.0), (10.0, 40.0), (40.0, 10.0)];
    let cf: Vec<FinePoint> = c.iter().map(|&(x, y)| fine_point(x, y)).collect();
    let cp: Vec<(f64, f64)> = cf.iter().map(|&q| px(q)).collect();
    for w in [1.0, 4.0, 12.0] {
        let h = w / 2.0;
        let mut s = Segments::new();
        {
            let style = StrokeStyle::new((w * 1024.0_f64) as u32).with_cap(LineCap::Round);
            let mut st = Stroker::new(&style, &mut s);
            st.move_to(cf[0]);
            st.cubic_to(cf[1], cf[2], cf[3]);
            st.finish().unwrap();
        }
        let samples: Vec<(f64, f64)> = (0..=3000)
            .map(|i| bezier(&cp, f64::from(i) / 3000.0))
            .collect();
        let mut regions: Vec<Region> = samples.iter().map(|&q| Region::Disc(q, h)).collect();
        regions.extend(polyline_stroke(
            &samples,
            h,
            RefJoin::Bevel,
            RefCap::Butt,
            false,
        ));
        let want = union_area(&regions, 32);
        let got = s.nonzero_area(32);
        assert!((got / want - 1.0).abs() < 5e-3, "w {w}: {got} vs {want}");
        assert!(s.winding_extremes(0.113).0 >= 0);
    }
}

#[test]
fn a_circle_stroked_through_the_stroker_is_the_ring() {
    // The general stroker on the circle's cubic outline (closed, smooth):
    // exact offsets along the true normals.
    for (r, w) in [(20.0, 4.0), (5.0, 0.25), (3.0, 5.0), (60.0, 30.0)] {
        let c = Circle::new(fine_point(80.0, 80.0), (r * 1024.0_f64) as u32);
        let mut s = Segments::new();
        {
            let style = StrokeStyle::new((w * 1024.0_f64) as u32);
            let mut st = Stroker::new(&style, &mut s);
            c.describe(&mut st);
            st.finish().unwrap();
        }
        let h = w / 2.0;
        let want = PI * ((r + h).powi(2) - (r - h).max(0.0).powi(2));
        let got = s.nonzero_area(32);
        assert!(
            (got / want - 1.0).abs() < 2e-3,
            "r {r} w {w}: {got} vs {want}"
        );
        if h < r {
            assert_eq!(s.winding(80.0, 80.0), 0);
        }
    }
}

#[test]
fn an_ellipse_stroked_through_the_stroker_is_its_exact_offset() {
    let e = Ellipse::new(fine_point(60.0, 60.0), 40 * 1024, 12 * 1024).rotated(Degrees::new(25));
    let (a, b, rot) = (40.0, 12.0, 25.0_f64.to_radians());
    for w in [2.0, 10.0] {
        let mut s = Segments::new();
        {
            let style = StrokeStyle::new((w * 1024.0_f64) as u32);
            let mut st = Stroker::new(&style, &mut s);
            e.describe(&mut st);
            st.finish().unwrap();
        }
        let samples: Vec<(f64, f64)> = (0..3000)
            .map(|i| {
                let t = 2.0 * PI * f64::from(i) / 3000.0;
                let (u, v) = (a * t.cos(), b * t.sin());
                (
                    60.0 + rot.cos() * u - rot.sin() * v,
                    60.0 + rot.sin() * u + rot.cos() * v,
                )
            })
            .collect();
        let mut regions: Vec<Region> = samples.iter().map(|&q| Region::Disc(q, w / 2.0)).collect();
        regions.extend(polyline_stroke(
            &samples,
            w / 2.0,
            RefJoin::Bevel,
            RefCap::Butt,
            true,
        ));
        let want = union_area(&regions, 32);
        let got = s.nonzero_area(32);
        assert!((got / want - 1.0).abs() < 3e-3, "w {w}: {got} vs {want}");
    }
}

#[test]
fn an_ellipse_stroke_is_the_band_within_its_reach_of_the_ellipse() {
    let (c, a, b, rot) = ((50.0, 40.0), 30.0, 10.0, 20.0_f64);
    let e = Ellipse::new(fine_point(c.0, c.1), 30 * 1024, 10 * 1024).rotated(Degrees::new(20));
    for (w, al) in [
        (2.0, StrokeAlignment::Centre),
        (6.0, StrokeAlignment::Centre),
        (3.0, StrokeAlignment::Inside),
        (3.0, StrokeAlignment::Outside),
    ] {
        let style = StrokeStyle::new((w * 1024.0_f64) as u32).with_alignment(al);
        let mut s = Segments::new();
        e.stroke(&style, &mut s).unwrap();
        assert!(s.is_closed_in_range());
        let (reach_in, reach_out) = match al {
            StrokeAlignment::Inside => (w, 0.0),
            StrokeAlignment::Centre => (w / 2.0, w / 2.0),
            StrokeAlignment::Outside => (0.0, w),
        };
        let mut y = 20.03;
        while y < 60.0 {
            let mut x = 15.07;
            while x < 85.0 {
                let (d, inside) =
                    softedge_tests::path_ref::ellipse_distance((x, y), c, a, b, rot.to_radians());
                let reach = if inside { reach_in } else { reach_out };
                if (d - reach).abs() > 0.01 && d > 0.01 {
                    let got = s.winding(x, y);
                    assert_eq!(got != 0, d < reach, "{al:?} w {w} at ({x}, {y}), d {d}");
                    assert!(got >= 0);
                }
                x += 0.37;
            }
            y += 0.37;
        }
    }
}

#[test]
fn dashes_follow_the_pattern_along_a_line() {
    // 100 px along y = 10.5, 2 px wide, 7 on, 3 off, starting 2 px in.
    let pattern = [7 * 1024, 3 * 1024];
    let style = StrokeStyle::new(2048).with_dash(Dash::new(&pattern, 2 * 1024));
    let (s, r) = stroke_polyline(
        &[fine_point(0.0, 10.5), fine_point(100.0, 10.5)],
        false,
        &style,
    );
    r.unwrap();
    // Dashes at [0, 5), [8, 15), [18, 25), ... [98, 100).
    let mut on = vec![(0.0, 5.0)];
    let mut x = 8.0;
    while x < 100.0 {
        on.push((x, (x + 7.0f64).min(100.0)));
        x += 10.0;
    }
    for &(a, b) in &on {
        let got = s.covered_length(10.3, a - 0.2, b + 0.2, |w| w != 0);
        assert!((got - (b - a)).abs() < 2e-3, "dash [{a}, {b}): {got}");
    }
    let total: f64 = on.iter().map(|(a, b)| b - a).sum();
    assert!((s.shoelace() - 2.0 * total).abs() < 1e-3);
    assert!((s.covered_length(10.3, 0.0, 100.0, |w| w != 0) - total).abs() < 1e-2);
}

#[test]
fn dash_patterns_odd_negative_zero_and_solid() {
    let line = [fine_point(0.0, 5.5), fine_point(60.0, 5.5)];
    let area = |pattern: &[u32], offset: i32, cap: LineCap| {
        let style = StrokeStyle::new(1024)
            .with_cap(cap)
            .with_dash(Dash::new(pattern, offset));
        let (s, r) = stroke_polyline(&line, false, &style);
        r.unwrap();
        assert!(s.winding_extremes(0.0497).0 >= 0);
        s.shoelace()
    };
    // Odd: [5] is 5 on, 5 off: 6 dashes of 5 px, 1 px wide.
    assert!((area(&[5 * 1024], 0, LineCap::Butt) - 30.0).abs() < 1e-3);
    // Negative offset counts back: -2 is 8 px into the 10-px period:
    // [0, 2) then [7, 12) ... [57, 60): 2 + 5 * 5 + 3 = 30.
    assert!((area(&[5 * 1024], -2 * 1024, LineCap::Butt) - 30.0).abs() < 1e-3);
    // All zero: solid. A zero-length gap does not split: solid.
    assert!((area(&[0, 0], 0, LineCap::Butt) - 60.0).abs() < 1e-3);
    assert!((area(&[10 * 1024, 0], 0, LineCap::Round) - (60.0 + PI / 4.0)).abs() < 2e-3);
    // Zero-length dashes with round caps: dots of diameter 1 every 10 px
    // (at 0, 10, ..., 60): 7 discs.
    let dots = area(&[0, 10 * 1024], 0, LineCap::Round);
    assert!((dots - 7.0 * PI / 4.0).abs() < 1e-2, "{dots}");
    // ... and nothing with butt caps.
    assert_eq!(area(&[0, 10 * 1024], 0, LineCap::Butt), 0.0);
}

#[test]
fn a_dash_through_the_start_of_a_closed_contour_is_one_dash() {
    // A 40-px square from (10, 10), clockwise; 30 on, 10 off, starting 15
    // in: the dash covering the start runs from 25 px before the corner
    // (on the left side) to 15 px after it, around the corner with a
    // miter.
    let sq = [
        fine_point(10.0, 10.0),
        fine_point(50.0, 10.0),
        fine_point(50.0, 50.0),
        fine_point(10.0, 50.0),
    ];
    let pattern = [30 * 1024, 10 * 1024];
    let style = StrokeStyle::new(2048).with_dash(Dash::new(&pattern, 15 * 1024));
    let (s, r) = stroke_polyline(&sq, true, &style);
    r.unwrap();
    let h = 1.0;
    let mut regions = Vec::new();
    // Dashes at contour lengths [-15, 15), [25, 55), [65, 95), [105, 135), [145, 160): the
    // last one meets the first at the start.
    let at = |d: f64| -> (f64, f64) {
        let d = d.rem_euclid(160.0);
        match (d / 40.0) as i32 {
            0 => (10.0 + d, 10.0),
            1 => (50.0, 10.0 + d - 40.0),
            2 => (50.0 - (d - 80.0), 50.0),
            _ => (10.0, 50.0 - (d - 120.0)),
        }
    };
    let dash = |a: f64, b: f64| -> Vec<(f64, f64)> {
        let mut v = vec![at(a)];
        for c in [0.0, 40.0, 80.0, 120.0, 160.0] {
            if c > a && c < b {
                v.push(at(c));
            }
        }
        v.push(at(b));
        v
    };
    for (a, b) in [(-15.0, 15.0), (25.0, 55.0), (65.0, 95.0), (105.0, 135.0)] {
        regions.extend(polyline_stroke(
            &dash(a, b),
            h,
            RefJoin::Miter(4.0),
            RefCap::Butt,
            false,
        ));
    }
    let want = union_area(&regions, 64);
    let got = s.nonzero_area(64);
    assert!((got / want - 1.0).abs() < 2e-3, "{got} vs {want}");
    // The corner at the start is mitered: (9, 9) is covered.
    assert_eq!(s.winding(9.05, 9.05), 1);
}

#[test]
fn a_dash_pattern_too_fine_stops_and_reports() {
    let pattern = [1, 1];
    let style = StrokeStyle::new(1024).with_dash(Dash::new(&pattern, 0));
    let (s, r) = stroke_polyline(
        &[fine_point(-1000.0, 0.0), fine_point(1000.0, 0.0)],
        false,
        &style,
    );
    // The stroke's work budget runs out first (issue #36: every interval
    // is charged, every dash its caps and body), before the contour's
    // MAX_DASH_INTERVALS.
    assert_eq!(r, Err(StrokeError::TooComplex));
    // At most one dash per two intervals, four segments each, and no more
    // segments than the budget charged.
    assert!(
        s.len() <= 4 * (MAX_DASH_INTERVALS as usize / 2 + 2)
            && s.len() <= softedge::path::MAX_STROKE_WORK as usize,
        "{}",
        s.len()
    );
    assert!(s.is_closed_in_range());
}

#[test]
fn alignment_puts_the_stroke_inside_centred_or_outside() {
    let r = Rectangle::new(fine_point(10.0, 10.0), 20 * 1024, 10 * 1024);
    for (al, want) in [
        (StrokeAlignment::Inside, 200.0 - 16.0 * 6.0),
        (StrokeAlignment::Centre, 22.0 * 12.0 - 18.0 * 8.0),
        (StrokeAlignment::Outside, 24.0 * 14.0 - 200.0),
    ] {
        let style = StrokeStyle::new(2048).with_alignment(al);
        let mut s = Segments::new();
        r.stroke(&style, &mut s).unwrap();
        assert!((s.shoelace() - want).abs() < 1e-6, "{al:?}");
        // The same through the general stroker on the outline.
        let mut g = Segments::new();
        {
            let mut st = Stroker::new(&style, &mut g);
            r.describe(&mut st);
            st.finish().unwrap();
        }
        assert!(
            (g.nonzero_area(64) - want).abs() < 1e-3,
            "{al:?} stroker: {}",
            g.nonzero_area(64)
        );
    }
    // Round and bevel joins on the rectangle's outer corners.
    let style = StrokeStyle::new(2048)
        .with_join(LineJoin::Round)
        .with_alignment(StrokeAlignment::Outside);
    let mut s = Segments::new();
    r.stroke(&style, &mut s).unwrap();
    assert!((s.shoelace() - (24.0 * 14.0 - 4.0 * 4.0 + 4.0 * PI - 200.0)).abs() < 2e-3);
    let style = StrokeStyle::new(2048)
        .with_join(LineJoin::Bevel)
        .with_alignment(StrokeAlignment::Outside);
    let mut s = Segments::new();
    r.stroke(&style, &mut s).unwrap();
    assert!((s.shoelace() - (24.0 * 14.0 - 4.0 * 2.0 - 200.0)).abs() < 1e-6);
    // A miter limit below sqrt(2) bevels the right angles.
    let style = StrokeStyle::new(2048).with_miter_limit(MiterLimit::from_q16(90_000));
    let mut s = Segments::new();
    r.stroke(&style, &mut s).unwrap();
    assert!((s.shoelace() - (22.0 * 12.0 - 4.0 * 0.5 - 18.0 * 8.0)).abs() < 1e-6);
}

/// Distance from `p` to the boundary of the sector (centre, radius,
/// start and sweep in radians, clockwise), and whether `p` is inside.
fn sector_boundary(p: (f64, f64), c: (f64, f64), r: f64, t0: f64, s: f64) -> (f64, bool) {
    let e1 = (c.0 + r * t0.cos(), c.1 + r * t0.sin());
    let e2 = (c.0 + r * (t0 + s).cos(), c.1 + r * (t0 + s).sin());
    let (dx, dy) = (p.0 - c.0, p.1 - c.1);
    let rho = dx.hypot(dy);
    let a = (dy.atan2(dx) - t0).rem_euclid(2.0 * PI);
    let in_angle = a <= s;
    let arc = if in_angle {
        (r - rho).abs()
    } else {
        f64::INFINITY
    };
    let seg = |q| softedge_tests::path_ref::dist_to_segment(p, c, q);
    let d = seg(e1)
        .min(seg(e2))
        .min(arc)
        .min((p.0 - e1.0).hypot(p.1 - e1.1))
        .min((p.0 - e2.0).hypot(p.1 - e2.1));
    (d, in_angle && rho <= r)
}

#[test]
fn a_sector_stroke_is_the_band_within_its_reach_of_the_outline() {
    // Round joins: the band is exactly the points within the reach of the
    // outline, on the chosen side.
    let cases = [
        (100, 3.0, StrokeAlignment::Inside),
        (30, 2.0, StrokeAlignment::Inside),
        (200, 4.0, StrokeAlignment::Inside),
        (300, 6.0, StrokeAlignment::Inside),
        (180, 5.0, StrokeAlignment::Inside),
        (10, 1.0, StrokeAlignment::Inside),
        (100, 3.0, StrokeAlignment::Outside),
        (45, 4.0, StrokeAlignment::Centre),
        (250, 4.0, StrokeAlignment::Centre),
        (250, 3.0, StrokeAlignment::Outside),
    ];
    for (sweep, w, al) in cases {
        let (c, r) = ((40.0, 40.0), 30.0);
        let sec = Sector::new(
            fine_point(c.0, c.1),
            30 * 1024,
            Degrees::new(-30),
            Degrees::new(sweep),
        );
        let style = StrokeStyle::new((w * 1024.0_f64) as u32)
            .with_alignment(al)
            .with_join(LineJoin::Round);
        let (reach_in, reach_out) = match al {
            StrokeAlignment::Inside => (w, 0.0),
            StrokeAlignment::Centre => (w / 2.0, w / 2.0),
            StrokeAlignment::Outside => (0.0, w),
        };
        let mut s = Segments::new();
        sec.stroke(&style, &mut s).unwrap();
        assert!(s.is_closed_in_range());
        let (t0, sw) = (-30f64.to_radians(), f64::from(sweep).to_radians());
        let mut y = 5.03;
        while y < 75.0 {
            let mut x = 5.07;
            while x < 75.0 {
                let (d, inside) = sector_boundary((x, y), c, r, t0, sw);
                let reach = if inside { reach_in } else { reach_out };
                // Away from the band's edges (the polygons are within 4
                // fine units of the exact curves), covered iff nearer the
                // outline than the reach on that side.
                if (d - reach).abs() > 0.01 && d > 0.01 {
                    let got = s.winding(x, y);
                    assert_eq!(
                        got != 0,
                        d < reach,
                        "{al:?} sweep {sweep} w {w} at ({x}, {y}), d {d}"
                    );
                    assert!(got >= 0);
                }
                x += 0.41;
            }
            y += 0.41;
        }
    }
}

#[test]
fn degenerate_strokes_are_empty_or_dots() {
    let p = fine_point(10.0, 10.0);
    let run = |d: &str, cap: LineCap, width: u32| {
        let mut s = Segments::new();
        {
            let style = StrokeStyle::new(width).with_cap(cap);
            let mut st = Stroker::new(&style, &mut s);
            parse_path_data(d, &mut st).unwrap();
            st.finish().unwrap();
        }
        s
    };
    // A lone move: nothing. Zero width: nothing.
    assert!(run("M 10 10", LineCap::Round, 2048).is_empty());
    assert!(run("M 10 10 L 20 20", LineCap::Round, 0).is_empty());
    // A zero-length subpath is a dot with round or square caps, nothing
    // with butt caps (SVG).
    for d in [
        "M 10 10 Z",
        "M 10 10 L 10 10",
        "M 10 10 C 10 10 10 10 10 10",
    ] {
        assert!(
            (run(d, LineCap::Round, 2048).shoelace() - PI).abs() < 2e-3,
            "{d}"
        );
        assert!(
            (run(d, LineCap::Square, 2048).shoelace() - 4.0).abs() < 1e-9,
            "{d}"
        );
        assert!(run(d, LineCap::Butt, 2048).is_empty(), "{d}");
    }
    let _ = p;
    // Shapes of no size.
    let mut s = Segments::new();
    Circle::new(p, 0)
        .stroke(&StrokeStyle::new(1024), &mut s)
        .unwrap();
    Circle::new(p, 0).fill(&mut s);
    Rectangle::new(p, 0, 500).fill(&mut s);
    Sector::new(p, 1000, Degrees::new(10), Degrees::new(0)).fill(&mut s);
    Ellipse::new(p, 0, 100).fill(&mut s);
    assert!(s.is_empty());
}

#[test]
fn huge_coordinates_give_bounded_closed_output_in_range() {
    let (a, b) = (i32::MIN, i32::MAX);
    for join in JOINS {
        let style = StrokeStyle::new(u32::MAX)
            .with_join(join)
            .with_cap(LineCap::Round);
        let pts = [
            FinePoint::new(a, a),
            FinePoint::new(b, 0),
            FinePoint::new(0, b),
            FinePoint::new(a, 7),
        ];
        let (s, r) = stroke_polyline(&pts, true, &style);
        r.unwrap();
        assert!(s.is_closed_in_range());
        assert!(s.len() < 20_000, "{}", s.len());
        let mut c = Segments::new();
        {
            let mut st = Stroker::new(&style, &mut c);
            st.move_to(FinePoint::new(a, b));
            st.cubic_to(
                FinePoint::new(b, b),
                FinePoint::new(a, a),
                FinePoint::new(b, a),
            );
            st.finish().unwrap();
        }
        assert!(c.is_closed_in_range());
    }
}

#[test]
fn hairlines_keep_their_width() {
    // 1/16 px wide, 100 px long, at an angle: the area is L w to the grid
    // rounding of the offsets (at most a fine unit across the width).
    for ang in [0.0f64, 0.3, 1.0, 2.2] {
        let a = fine_point(20.0, 20.0);
        let b = fine_point(20.0 + 100.0 * ang.cos(), 20.0 + 100.0 * ang.sin());
        let (s, _) = stroke_polyline(&[a, b], false, &StrokeStyle::new(64));
        let (pa, pb) = (px(a), px(b));
        let l = (pb.0 - pa.0).hypot(pb.1 - pa.1);
        let want = l / 16.0;
        assert!(
            (s.shoelace() - want).abs() <= l * 1.5 * FINE,
            "{ang}: {} vs {want}",
            s.shoelace()
        );
        assert_eq!(s.winding_extremes(0.01).0, 0);
    }
}

/// Distance from `p` to the segment `a b` (px).
fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 > 0.0 {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// A wide stroke of a curve keeps its offset edges within the tolerance
/// of the exact offset curve (`B + h N` and `B - h N`, `f64`), where the
/// stroke is narrower than the curve's radius of curvature: every point of
/// the exact offsets lies within `tol + 1` fine units of the outline sent
/// (the chords' error, the grid's rounding of the offset points and of
/// the unit normals). The curves: circular-arc cubics of radius 10 to
/// 1 500 px over a quarter turn and less, stroked up to 1.8 times their
/// radius wide, and an S-curve, whose turning is uneven along it.
#[test]
fn a_wide_curved_stroke_stays_within_the_tolerance_of_its_exact_offset() {
    let tol_px = (3.0 + 1.0) / 1024.0;
    let mut worst: f64 = 0.0;
    let mut cases: Vec<([(f64, f64); 4], f64)> = Vec::new();
    for (r, sweep_deg, h_frac) in [
        (10.0, 90.0, 0.9),
        (40.0, 90.0, 0.5),
        (120.0, 60.0, 0.9),
        (400.0, 90.0, 0.3),
        (1500.0, 45.0, 0.9),
        (1500.0, 90.0, 0.05),
    ] {
        let th: f64 = f64::to_radians(sweep_deg);
        let k = 4.0 / 3.0 * (th / 4.0).tan();
        let c = (-1000.0, -1000.0);
        let (s, e) = ((0.0f64).sin_cos(), th.sin_cos());
        let p0 = (c.0 + r * s.1, c.1 + r * s.0);
        let p3 = (c.0 + r * e.1, c.1 + r * e.0);
        let p1 = (p0.0 - k * r * s.0, p0.1 + k * r * s.1);
        let p2 = (p3.0 + k * r * e.0, p3.1 - k * r * e.1);
        cases.push(([p0, p1, p2, p3], h_frac * r));
    }
    // An S-curve whose radius of curvature stays above about 60 px.
    cases.push((
        [
            (100.0, 300.0),
            (300.0, 100.0),
            (500.0, 500.0),
            (700.0, 300.0),
        ],
        20.0,
    ));
    for (ctrl, h) in cases {
        let cf: Vec<FinePoint> = ctrl.iter().map(|&(x, y)| fine_point(x, y)).collect();
        let cp: Vec<(f64, f64)> = cf.iter().map(|&q| px(q)).collect();
        let mut s = Segments::new();
        {
            let style = StrokeStyle::new((2.0 * h * 1024.0) as u32);
            let mut st = Stroker::new(&style, &mut s);
            st.move_to(cf[0]);
            st.cubic_to(cf[1], cf[2], cf[3]);
            st.finish().unwrap();
        }
        let segs: Vec<((f64, f64), (f64, f64))> =
            s.segs.iter().map(|&(a, b)| (px(a), px(b))).collect();
        let d = |t: f64| {
            let u = 1.0 - t;
            let dx = 3.0
                * (u * u * (cp[1].0 - cp[0].0)
                    + 2.0 * u * t * (cp[2].0 - cp[1].0)
                    + t * t * (cp[3].0 - cp[2].0));
            let dy = 3.0
                * (u * u * (cp[1].1 - cp[0].1)
                    + 2.0 * u * t * (cp[2].1 - cp[1].1)
                    + t * t * (cp[3].1 - cp[2].1));
            let l = (dx * dx + dy * dy).sqrt();
            (-dy / l, dx / l)
        };
        for i in 1..4000 {
            let t = f64::from(i) / 4000.0;
            let (b, n) = (bezier(&cp, t), d(t));
            for side in [-1.0, 1.0] {
                let o = (b.0 + side * h * n.0, b.1 + side * h * n.1);
                let near = segs
                    .iter()
                    .map(|&(a, e)| to_segment(o, a, e))
                    .fold(f64::INFINITY, f64::min);
                worst = worst.max(near);
                assert!(
                    near <= tol_px,
                    "{ctrl:?} h {h}: offset point {o:?} (t {t}) is {:.2} fine units from the outline",
                    near * 1024.0
                );
            }
        }
    }
    println!("worst {:.2} fine units", worst * 1024.0);
}
