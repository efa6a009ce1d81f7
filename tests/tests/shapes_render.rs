//! Shapes and strokes drawn through the engine (canvas, edge walker, span
//! sweep, over) against independent references written here: exact
//! disc-box areas, chord integration of ellipses and rounded rectangles,
//! scanline winding of polygons, the exact union of a stroke's pieces.
//! Plus the engine's own invariants for them: split shapes add up, band
//! height changes nothing, bad shapes are reported, not drawn.

use std::f64::consts::PI;

use softedge::canvas::Contour;
use softedge::geom::FinePoint;
use softedge::path::{
    svg::SvgPath, Arc, Circle, CornerRadii, Dash, Degrees, Ellipse, LineCap, LineJoin, Polygon,
    Polyline, Rectangle, RoundedRectangle, Sector, StrokeAlignment, StrokeStyle,
};
use softedge::prelude::*;
use softedge::COVER_ONE;
use softedge_tests::frame::{render_canvas, Frame};
use softedge_tests::path_ref::{
    disc_box_area, fine_point, polyline_stroke, union_area, RefCap, RefJoin, Rng, Segments, FINE,
};

const FULL: f64 = 4095.0 * COVER_ONE as f64;

/// Each pixel's coverage in a frame drawn at intensity 4095 over 0.
fn coverage(f: &Frame<1>, x: i32, y: i32) -> f64 {
    f64::from(f.raw_at(x, y)[0]) / FULL
}

fn total(f: &Frame<1>) -> f64 {
    f.raw.iter().map(|p| f64::from(p[0])).sum::<f64>() / FULL
}

/// A frame of `w x h` with `shape` filled (nonzero, opaque, over).
fn fill<S: softedge::path::Shape>(w: u16, h: u16, rows: u16, shape: &S) -> Frame<1> {
    render_canvas::<1>(w, h, rows, [0], 4, |c| {
        c.fill_shape(
            shape,
            [4095],
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    })
}

/// Per-pixel coverage of a region given by its chords: `chords(y)` is the
/// inside of the horizontal line at `y` as intervals; integrated over
/// `lines` lines per pixel row (midpoint rule), exact in x.
fn chord_coverage(w: i32, h: i32, lines: u32, chords: impl Fn(f64) -> Vec<(f64, f64)>) -> Vec<f64> {
    let mut cov = vec![0.0; (w * h) as usize];
    let dy = 1.0 / f64::from(lines);
    for j in 0..h {
        for l in 0..lines {
            let y = f64::from(j) + (f64::from(l) + 0.5) * dy;
            for (a, b) in chords(y) {
                let (i0, i1) = (a.floor().max(0.0) as i32, (b.ceil() as i32).min(w));
                for i in i0..i1 {
                    let (x0, x1) = (f64::from(i), f64::from(i) + 1.0);
                    let len = (b.min(x1) - a.max(x0)).max(0.0);
                    cov[(j * w + i) as usize] += len * dy;
                }
            }
        }
    }
    cov
}

/// The chord of the ellipse `(cx, cy, a, b)` rotated by `t` (radians,
/// clockwise on screen) at height `y`.
fn ellipse_chord(cx: f64, cy: f64, a: f64, b: f64, t: f64, y: f64) -> Vec<(f64, f64)> {
    // A point (X, Y) relative to the centre is inside when
    // (X cos + Y sin)^2 / a^2 + (-X sin + Y cos)^2 / b^2 <= 1.
    let (c, s) = (t.cos(), t.sin());
    let yy = y - cy;
    let qa = c * c / (a * a) + s * s / (b * b);
    let qb = 2.0 * yy * s * c * (1.0 / (a * a) - 1.0 / (b * b));
    let qc = yy * yy * (s * s / (a * a) + c * c / (b * b)) - 1.0;
    let d = qb * qb - 4.0 * qa * qc;
    if d <= 0.0 {
        return vec![];
    }
    let r = d.sqrt();
    vec![(cx + (-qb - r) / (2.0 * qa), cx + (-qb + r) / (2.0 * qa))]
}

#[test]
fn filled_discs_match_the_exact_disc_per_pixel_and_in_sum() {
    let mut rng = Rng(11);
    let mut radii = vec![
        0.5, 0.7, 1.0, 1.5, 2.5, 4.0, 7.3, 12.7, 25.0, 50.0, 77.7, 100.0,
    ];
    radii.extend((0..12).map(|_| 0.5 + 99.5 * rng.f().powi(2)));
    let (mut worst_px, mut worst_sum) = (0f64, 0f64);
    for r in radii {
        let rf = (r * 1024.0_f64).round() as u32;
        let side = (2.0 * r).ceil() as u16 + 6;
        let c = fine_point(3.0 + r + rng.f(), 3.0 + r + rng.f());
        let f = fill(side, side, 16, &Circle::new(c, rf));
        let (cx, cy, rr) = (
            f64::from(c.x) * FINE,
            f64::from(c.y) * FINE,
            f64::from(rf) * FINE,
        );
        for y in 0..i32::from(side) {
            for x in 0..i32::from(side) {
                let (fx, fy) = (f64::from(x), f64::from(y));
                let want = disc_box_area(cx, cy, rr, fx, fy, fx + 1.0, fy + 1.0);
                let err = (coverage(&f, x, y) - want).abs();
                worst_px = worst_px.max(err);
                assert!(
                    err <= 1.0 / 32.0,
                    "r {r}: ({x}, {y}) {} vs {want}",
                    coverage(&f, x, y)
                );
            }
        }
        let rel = total(&f) / (PI * rr * rr) - 1.0;
        worst_sum = worst_sum.max(rel.abs());
        assert!(rel.abs() <= 2e-3, "r {r}: sum off by {rel:e}");
    }
    println!(
        "discs: worst pixel {worst_px:.5} px (limit 1/32), worst sum {worst_sum:.2e} (limit 2e-3)"
    );
}

#[test]
fn ellipses_match_chord_integration_per_pixel_and_in_sum() {
    let mut rng = Rng(12);
    let (mut worst_px, mut worst_sum) = (0f64, 0f64);
    for k in 0..16 {
        let (a, b) = (rng.range(0.6, 40.0), rng.range(0.6, 40.0));
        let deg = if k % 4 == 0 {
            0
        } else {
            rng.range(0.0, 180.0) as i32
        };
        let (af, bf) = (
            (a * 1024.0_f64).round() as u32,
            (b * 1024.0_f64).round() as u32,
        );
        let m = a.max(b);
        let side = (2.0 * m).ceil() as u16 + 6;
        let c = fine_point(3.0 + m + rng.f(), 3.0 + m + rng.f());
        let e = Ellipse::new(c, af, bf).rotated(Degrees::new(deg));
        let f = fill(side, side, 8, &e);
        let (cx, cy) = (f64::from(c.x) * FINE, f64::from(c.y) * FINE);
        let (a, b) = (f64::from(af) * FINE, f64::from(bf) * FINE);
        let t = f64::from(deg).to_radians();
        let s = i32::from(side);
        let want = chord_coverage(s, s, 256, |y| ellipse_chord(cx, cy, a, b, t, y));
        for y in 0..s {
            for x in 0..s {
                let err = (coverage(&f, x, y) - want[(y * s + x) as usize]).abs();
                worst_px = worst_px.max(err);
                assert!(err <= 1.0 / 32.0, "ellipse {k}: ({x}, {y}) off by {err}");
            }
        }
        let rel = total(&f) / (PI * a * b) - 1.0;
        worst_sum = worst_sum.max(rel.abs());
        assert!(
            rel.abs() <= 2e-3,
            "ellipse {k} ({a}, {b}, {deg} deg): sum off by {rel:e}"
        );
    }
    println!("ellipses: worst pixel {worst_px:.5} px, worst sum {worst_sum:.2e}");
}

#[test]
fn rounded_rectangles_match_chord_integration_per_pixel_and_in_sum() {
    let mut rng = Rng(13);
    let (mut worst_px, mut worst_sum) = (0f64, 0f64);
    for k in 0..16 {
        let (w, h) = (rng.range(2.0, 60.0), rng.range(2.0, 60.0));
        // Per-corner radii (rx, ry), small enough that no clamping applies.
        let mut radius = || (rng.range(0.0, w / 2.0), rng.range(0.0, h / 2.0));
        let radii = [radius(), radius(), radius(), radius()];
        let q = |v: f64| (v * 1024.0).round() as u32;
        let (x0, y0) = (3.0 + rng.f(), 3.0 + rng.f());
        let tl = fine_point(x0, y0);
        let (wf, hf) = (q(w), q(h));
        let rr = RoundedRectangle::new(
            Rectangle::new(tl, wf, hf),
            CornerRadii {
                top_left: (q(radii[0].0), q(radii[0].1)),
                top_right: (q(radii[1].0), q(radii[1].1)),
                bottom_right: (q(radii[2].0), q(radii[2].1)),
                bottom_left: (q(radii[3].0), q(radii[3].1)),
            },
        );
        let side = (w.max(h) + 8.0).ceil() as u16;
        let f = fill(side, side, 5, &rr);
        // The reference, in px from the quantised values.
        let (x0, y0) = (f64::from(tl.x) * FINE, f64::from(tl.y) * FINE);
        let (w, h) = (f64::from(wf) * FINE, f64::from(hf) * FINE);
        let r: Vec<(f64, f64)> = radii
            .iter()
            .map(|&(a, b)| (f64::from(q(a)) * FINE, f64::from(q(b)) * FINE))
            .collect();
        // How far a corner ellipse (rx, ry) cuts in at distance d from its
        // side's end (d < ry).
        let inset = |(rx, ry): (f64, f64), d: f64| {
            if d >= ry || rx == 0.0 || ry == 0.0 {
                0.0
            } else {
                let u = (ry - d) / ry;
                rx * (1.0 - (1.0 - u * u).max(0.0).sqrt())
            }
        };
        let s = i32::from(side);
        let want = chord_coverage(s, s, 256, |y| {
            if y < y0 || y > y0 + h {
                return vec![];
            }
            let (top, bottom) = (y - y0, y0 + h - y);
            let left = inset(r[0], top).max(inset(r[3], bottom));
            let right = inset(r[1], top).max(inset(r[2], bottom));
            vec![(x0 + left, x0 + w - right)]
        });
        for y in 0..s {
            for x in 0..s {
                let err = (coverage(&f, x, y) - want[(y * s + x) as usize]).abs();
                worst_px = worst_px.max(err);
                assert!(
                    err <= 1.0 / 32.0,
                    "rounded rectangle {k}: ({x}, {y}) off by {err}"
                );
            }
        }
        let area = w * h - (1.0 - PI / 4.0) * r.iter().map(|&(a, b)| a * b).sum::<f64>();
        let rel = total(&f) / area - 1.0;
        worst_sum = worst_sum.max(rel.abs());
        assert!(
            rel.abs() <= 2e-3,
            "rounded rectangle {k}: sum off by {rel:e}"
        );
    }
    println!("rounded rectangles: worst pixel {worst_px:.5} px, worst sum {worst_sum:.2e}");
}

/// Closed polygons as reference segments (not through softedge's
/// flattening).
fn segments(contours: &[Vec<FinePoint>]) -> Segments {
    let mut s = Segments::new();
    for c in contours {
        for k in 0..c.len() {
            s.segs.push((c[k], c[(k + 1) % c.len()]));
        }
    }
    s
}

#[test]
fn fill_rules_on_a_pentagram_and_nested_contours_match_the_winding_numbers() {
    let star: Vec<FinePoint> = (0..5)
        .map(|k| {
            let t = -PI / 2.0 + f64::from(k) * 4.0 * PI / 5.0;
            fine_point(16.3 + 14.0 * t.cos(), 16.1 + 14.0 * t.sin())
        })
        .collect();
    let square = |x0: f64, y0: f64, s: f64, cw: bool| {
        let mut v = vec![
            fine_point(x0, y0),
            fine_point(x0 + s, y0),
            fine_point(x0 + s, y0 + s),
            fine_point(x0, y0 + s),
        ];
        if !cw {
            v.reverse();
        }
        v
    };
    // Three nested squares, all clockwise: winding 1, 2, 3 inward.
    let nested = vec![
        square(2.2, 2.7, 28.0, true),
        square(7.1, 7.3, 18.0, true),
        square(12.6, 12.4, 7.0, true),
    ];
    for (name, contours) in [("pentagram", vec![star.clone()]), ("nested", nested)] {
        let path: String = contours
            .iter()
            .map(|c| {
                let mut d = String::new();
                for (k, p) in c.iter().enumerate() {
                    let cmd = if k == 0 { 'M' } else { 'L' };
                    d += &format!("{cmd} {} {} ", f64::from(p.x) * FINE, f64::from(p.y) * FINE);
                }
                d + "Z "
            })
            .collect();
        let svg = SvgPath::new(&path).unwrap();
        let reference = segments(&contours);
        // Per pixel, the area of each winding number -3..=3.
        let areas: Vec<Vec<[f64; 7]>> = (0..34)
            .map(|y| {
                let mut row = vec![[0.0; 7]; 34];
                for w in -3..=3i32 {
                    let c = reference.row_coverage(y, 0, 34, 1024, move |v| v == w);
                    for x in 0..34 {
                        row[x][(w + 3) as usize] = c[x];
                    }
                }
                row
            })
            .collect();
        for rule in [FillRule::NonZero, FillRule::EvenOdd] {
            let f = render_canvas::<1>(34, 34, 7, [0], 0, |c| {
                c.fill_shape(&svg, [4095], rule, Blend::Over, Opacity::OPAQUE)
                    .unwrap();
            });
            let (mut worst_mean, mut worst_true, mut crossing) = (0f64, 0f64, 0);
            for y in 0..34 {
                for x in 0..34 {
                    let a = &areas[y as usize][x as usize];
                    let got = coverage(&f, x, y);
                    let mean: f64 = (0..7).map(|k| (k as f64 - 3.0) * a[k]).sum();
                    let (semantic, exact) = match rule {
                        FillRule::NonZero => (mean.abs().min(1.0), 1.0 - a[3]),
                        FillRule::EvenOdd => {
                            let m = mean.abs() % 2.0;
                            (if m > 1.0 { 2.0 - m } else { m }, a[0] + a[2] + a[4] + a[6])
                        }
                    };
                    worst_mean = worst_mean.max((got - semantic).abs());
                    let present: Vec<i32> = (0..7)
                        .filter(|&k| a[k] > 1e-9)
                        .map(|k| k as i32 - 3)
                        .collect();
                    let span = present.iter().max().unwrap() - present.iter().min().unwrap();
                    if span <= 1 {
                        worst_true = worst_true.max((got - exact).abs());
                    } else {
                        crossing += 1;
                    }
                }
            }
            // Straight edges: exact area coverage, up to the edges' floors
            // and the reference's scanline sampling.
            assert!(
                worst_mean <= 2e-3,
                "{name} {rule:?}: the mean-winding rule, worst {worst_mean}"
            );
            assert!(
                worst_true <= 2e-3,
                "{name} {rule:?}: pixels of one winding step, worst {worst_true}"
            );
            println!("{name} {rule:?}: worst {worst_true:.1e} where windings differ by one step; {crossing} pixels where the outline crosses itself take the rule on the mean winding (worst {worst_mean:.1e} of that)");
        }
    }
}

#[test]
fn a_ring_is_the_difference_of_two_discs() {
    let c = fine_point(20.37, 19.81);
    let (r0, r1) = (15.3, 7.9);
    let q = |r: f64| (r * 1024.0_f64).round() as u32;
    let d = format!(
        "M {x} {y0} A {r0} {r0} 0 1 1 {x} {y1} A {r0} {r0} 0 1 1 {x} {y0} Z \
         M {x} {z0} A {r1} {r1} 0 1 0 {x} {z1} A {r1} {r1} 0 1 0 {x} {z0} Z",
        x = f64::from(c.x) * FINE,
        y0 = f64::from(c.y) * FINE - r0,
        y1 = f64::from(c.y) * FINE + r0,
        z0 = f64::from(c.y) * FINE - r1,
        z1 = f64::from(c.y) * FINE + r1,
    );
    let ring = SvgPath::new(&d).unwrap();
    let f = render_canvas::<1>(40, 40, 16, [0], 0, |cv| {
        cv.fill_shape(
            &ring,
            [4095],
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    let (cx, cy) = (f64::from(c.x) * FINE, f64::from(c.y) * FINE);
    let (r0, r1) = (f64::from(q(r0)) * FINE, f64::from(q(r1)) * FINE);
    let mut worst = 0f64;
    for y in 0..40 {
        for x in 0..40 {
            let (fx, fy) = (f64::from(x), f64::from(y));
            let want = disc_box_area(cx, cy, r0, fx, fy, fx + 1.0, fy + 1.0)
                - disc_box_area(cx, cy, r1, fx, fy, fx + 1.0, fy + 1.0);
            worst = worst.max((coverage(&f, x, y) - want).abs());
        }
    }
    assert!(worst <= 1.0 / 32.0, "ring: worst pixel {worst}");
    let rel = total(&f) / (PI * (r0 * r0 - r1 * r1)) - 1.0;
    assert!(rel.abs() <= 2e-3, "ring: sum off by {rel:e}");
}

#[test]
fn a_straight_stroke_covers_length_times_width_plus_its_caps() {
    let mut rng = Rng(14);
    for k in 0..40 {
        let (x, y) = (rng.range(30.0, 34.0), rng.range(30.0, 34.0));
        let len = rng.range(0.5, 25.0);
        let t = rng.range(0.0, 2.0 * PI);
        let w = if k % 5 == 0 {
            0.25
        } else {
            rng.range(0.2, 8.0)
        };
        let (a, b) = (
            fine_point(x, y),
            fine_point(x + len * t.cos(), y + len * t.sin()),
        );
        let wf = (w * 1024.0_f64).round() as u32;
        let w = f64::from(wf) * FINE;
        let l = (f64::from(b.x - a.x) * FINE).hypot(f64::from(b.y - a.y) * FINE);
        for (cap, extra) in [
            (LineCap::Butt, 0.0),
            (LineCap::Square, w * w),
            (LineCap::Round, PI * w * w / 4.0),
        ] {
            let style = StrokeStyle::new(wf).with_cap(cap);
            let line = softedge::path::Line::new(a, b);
            let f = render_canvas::<1>(64, 64, 16, [0], 0, |c| {
                c.stroke_shape(&line, &style, [4095], Blend::Over, Opacity::OPAQUE)
                    .unwrap();
            });
            let want = l * w + extra;
            // The outline's grid rounding (0.71 fine units along it) and
            // the flattening of round caps.
            let slack = 2.0 * (l + 2.0 * w) * 0.71 * FINE + 2e-3 * want;
            let got = total(&f);
            assert!(
                (got - want).abs() <= slack,
                "{cap:?} l {l} w {w}: {got} vs {want}"
            );
        }
    }
}

/// The stroke of `pts` drawn through the engine, its summed coverage
/// against the exact union of its pieces (SVG's definition), relative.
fn stroke_area_error(pts: &[FinePoint], wf: u32, join: LineJoin, cap: LineCap) -> f64 {
    stroke_errors(pts, wf, join, cap, None).0
}

/// Each pixel's coverage of the union of `regions` in a `w x h` frame:
/// `lines` horizontal lines per pixel row (midpoint rule), each line's
/// union of intervals exact in x and split among the pixel columns. The
/// midpoint rule is exact where the covered length is linear in y; a
/// pixel holding a vertex, a crossing or a tangent of the outline is off
/// by at most about `1 / (2 lines)` per such feature.
fn union_coverage(
    regions: &[softedge_tests::path_ref::Region],
    w: usize,
    h: usize,
    lines: u32,
) -> Vec<f64> {
    let mut cov = vec![0.0; w * h];
    let dy = 1.0 / f64::from(lines);
    for row in 0..h {
        for i in 0..lines {
            let y = row as f64 + (f64::from(i) + 0.5) * dy;
            let mut iv: Vec<(f64, f64)> = regions.iter().filter_map(|r| r.interval(y)).collect();
            iv.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut merged: Vec<(f64, f64)> = Vec::new();
            for (a, b) in iv {
                match merged.last_mut() {
                    Some(last) if a <= last.1 => last.1 = last.1.max(b),
                    _ => merged.push((a, b)),
                }
            }
            for (a, b) in merged {
                let (a, b) = (a.max(0.0), b.min(w as f64));
                if b <= a {
                    continue;
                }
                for x in (a.floor() as usize)..(b.ceil() as usize).min(w) {
                    let len = b.min(x as f64 + 1.0) - a.max(x as f64);
                    cov[row * w + x] += len.max(0.0) * dy;
                }
            }
        }
    }
    cov
}

/// The stroke of `pts` (64 x 64 frame, 16-row bands) against the exact
/// union of its pieces: the relative error of its summed coverage and,
/// with `lines`, the worst pixel against [`union_coverage`] at that
/// many lines per pixel.
fn stroke_errors(
    pts: &[FinePoint],
    wf: u32,
    join: LineJoin,
    cap: LineCap,
    lines: Option<u32>,
) -> (f64, f64) {
    path_stroke_errors(pts, false, wf, join, cap, lines)
}

/// [`stroke_errors`] of a polyline, or (`closed`) of the polygon through
/// `pts`.
fn path_stroke_errors(
    pts: &[FinePoint],
    closed: bool,
    wf: u32,
    join: LineJoin,
    cap: LineCap,
    lines: Option<u32>,
) -> (f64, f64) {
    let style = StrokeStyle::new(wf).with_join(join).with_cap(cap);
    let f = render_canvas::<1>(64, 64, 16, [0], 0, |c| {
        let r = if closed {
            c.stroke_shape(
                &Polygon::new(pts),
                &style,
                [4095],
                Blend::Over,
                Opacity::OPAQUE,
            )
        } else {
            c.stroke_shape(
                &Polyline::new(pts),
                &style,
                [4095],
                Blend::Over,
                Opacity::OPAQUE,
            )
        };
        r.unwrap();
    });
    // No pixel is covered more than once.
    assert!(f.lin12.iter().all(|p| p[0] <= 4095));
    let ptsf: Vec<(f64, f64)> = pts
        .iter()
        .map(|p| (f64::from(p.x) * FINE, f64::from(p.y) * FINE))
        .collect();
    let rj = match join {
        LineJoin::Miter => RefJoin::Miter(4.0),
        LineJoin::Round => RefJoin::Round,
        LineJoin::Bevel => RefJoin::Bevel,
    };
    let rc = match cap {
        LineCap::Butt => RefCap::Butt,
        LineCap::Round => RefCap::Round,
        LineCap::Square => RefCap::Square,
    };
    let h = f64::from(wf) * FINE / 2.0;
    let regions = polyline_stroke(&ptsf, h, rj, rc, closed);
    let want = union_area(&regions, 128);
    let rel = total(&f) / want - 1.0;
    let worst_px = lines.map_or(0.0, |lines| {
        let cov = union_coverage(&regions, 64, 64, lines);
        let mut worst = 0f64;
        for y in 0..64 {
            for x in 0..64 {
                worst = worst.max((coverage(&f, x, y) - cov[(y * 64 + x) as usize]).abs());
            }
        }
        worst
    });
    (rel, worst_px)
}

const JOINS: [LineJoin; 3] = [LineJoin::Miter, LineJoin::Round, LineJoin::Bevel];
const CAPS: [LineCap; 3] = [LineCap::Butt, LineCap::Round, LineCap::Square];

/// A chart's line: x increasing, any turns, never crossing itself.
#[test]
fn chart_polyline_strokes_cover_their_exact_outline_once() {
    let mut rng = Rng(15);
    let mut worst = 0f64;
    // Fewer in debug builds (the reference is slow there).
    for k in 0..if cfg!(debug_assertions) { 20 } else { 150 } {
        let n = 3 + k % 6;
        let mut x = rng.range(4.0, 8.0);
        let pts: Vec<FinePoint> = (0..n)
            .map(|_| {
                let p = fine_point(x, rng.range(8.0, 56.0));
                x += rng.range(3.0, 10.0);
                p
            })
            .collect();
        let wf = (rng.range(0.5, 4.0) * 1024.0_f64).round() as u32;
        for (j, join) in JOINS.into_iter().enumerate() {
            let cap = CAPS[(k + j) % 3];
            let rel = stroke_area_error(&pts, wf, join, cap);
            worst = worst.max(rel.abs());
            assert!(rel.abs() <= 5e-3, "polyline {k} {join:?} {cap:?}: {rel:e}");
        }
    }
    println!("chart polyline strokes: worst relative area error {worst:.2e} (limit 5e-3)");
}

/// A union test's bar for one pixel against a reference of `lines`
/// lines per pixel: 1/256 (the issue's bar); in debug builds, whose
/// reference is coarser, that reference's own error on top.
fn union_px_limit(lines: u32) -> f64 {
    1.0 / 256.0
        + if lines < 256 {
            0.5 / f64::from(lines)
        } else {
            0.0
        }
}

/// A polyline that crosses itself, folds back on itself (U-turns, segments
/// shorter than the stroke is wide) and overlaps its own caps: the stroke
/// is the union of its pieces however often they overlap (issue #36), in
/// sum against [`union_area`] and in every pixel against
/// [`union_coverage`] at 256 lines per pixel (64 in debug builds), whose
/// own error is about `1 / (2 lines)` per outline feature in a pixel.
/// Before the union treatment (the outline's sum filled by the nonzero
/// rule on each pixel's mean winding) these 100 strokes were off by up
/// to +4.8 % (23 above 0.5 %) and a pixel by up to 0.48.
#[test]
fn self_crossing_polyline_strokes_cover_the_union_of_their_pieces() {
    let mut rng = Rng(17);
    let (mut worst, mut worst_px) = (0f64, 0f64);
    let cases = if cfg!(debug_assertions) { 20 } else { 100 };
    let lines = if cfg!(debug_assertions) { 64 } else { 256 };
    let px_limit = union_px_limit(lines);
    for k in 0..cases {
        let n = 3 + k % 5;
        let pts: Vec<FinePoint> = (0..n)
            .map(|_| fine_point(rng.range(8.0, 56.0), rng.range(8.0, 56.0)))
            .collect();
        let wf = (rng.range(0.5, 6.0) * 1024.0_f64).round() as u32;
        let (rel, px) = stroke_errors(&pts, wf, JOINS[k % 3], LineCap::Round, Some(lines));
        assert!(rel.abs() <= 2e-3, "polyline {k}: {rel:e}");
        assert!(px <= px_limit, "polyline {k}: a pixel off by {px}");
        worst = worst.max(rel.abs());
        worst_px = worst_px.max(px);
    }
    let (issue_worst, issue_px) = (worst, worst_px);
    // Longer polylines (up to the treatment's 16 points), every cap.
    for k in 0..cases / 2 {
        let n = 8 + k % 9;
        let pts: Vec<FinePoint> = (0..n)
            .map(|_| fine_point(rng.range(8.0, 56.0), rng.range(8.0, 56.0)))
            .collect();
        let wf = (rng.range(0.3, 4.0) * 1024.0_f64).round() as u32;
        let (join, cap) = (JOINS[k % 3], CAPS[k / 3 % 3]);
        let (rel, px) = stroke_errors(&pts, wf, join, cap, Some(lines));
        assert!(rel.abs() <= 2e-3, "long polyline {k}: {rel:e}");
        assert!(px <= px_limit, "long polyline {k}: a pixel off by {px}");
        worst = worst.max(rel.abs());
        worst_px = worst_px.max(px);
    }
    println!(
        "self-crossing polyline strokes: worst relative area error {issue_worst:.2e}, worst \
         pixel {issue_px:.5} (issue #36's {cases}); with the longer ones {worst:.2e}, \
         {worst_px:.5} (limits 2e-3, {px_limit:.5})"
    );
}

/// Closed polygons that cross themselves (stars and random points, 3 to
/// 8 of them) stroked centred: the union of their pieces (a body per
/// side, a join at every point), in sum and in every pixel, as for
/// polylines. Before (the outline's sum by the nonzero rule on each
/// pixel's mean winding) they were off as self-crossing polylines were.
/// Longer ones, up to the treatment's 16 points, cross more: where six or
/// more pieces overlap a pixel keeps some of the mean winding's error (a
/// random 10-point one, 5 px wide: 0.0062), and past the work limit the
/// overlaps of two round joins are left (see `path::stroke::union`).
#[test]
fn self_crossing_polygon_strokes_cover_the_union_of_their_pieces() {
    let mut rng = Rng(19);
    let (mut worst, mut worst_px) = (0f64, 0f64);
    let cases = if cfg!(debug_assertions) { 20 } else { 200 };
    let lines = if cfg!(debug_assertions) { 64 } else { 256 };
    let px_limit = union_px_limit(lines);
    for k in 0..cases {
        let n = 3 + k % 6;
        let pts: Vec<FinePoint> = if k % 4 == 0 {
            // A star polygon {m/2} (m odd).
            let c = (32.0, 32.0);
            let r = rng.range(12.0, 24.0);
            let m = n | 1;
            (0..m)
                .map(|i| {
                    let a = std::f64::consts::TAU * (2 * i) as f64 / m as f64 + 0.3;
                    fine_point(c.0 + r * a.cos(), c.1 + r * a.sin())
                })
                .collect()
        } else {
            (0..n)
                .map(|_| fine_point(rng.range(8.0, 56.0), rng.range(8.0, 56.0)))
                .collect()
        };
        let wf = (rng.range(0.3, 5.0) * 1024.0_f64).round() as u32;
        let join = JOINS[k % 3];
        let (rel, px) = path_stroke_errors(&pts, true, wf, join, LineCap::Butt, Some(lines));
        assert!(rel.abs() <= 2e-3, "polygon {k} {join:?}: {rel:e}");
        assert!(px <= px_limit, "polygon {k} {join:?}: a pixel off by {px}");
        worst = worst.max(rel.abs());
        worst_px = worst_px.max(px);
    }
    println!(
        "self-crossing polygon strokes: worst relative area error {worst:.2e}, worst pixel \
         {worst_px:.5} (limits 2e-3, {px_limit:.5})"
    );
}

/// The union's corrections are numbered the same in every band: the
/// strokes of self-crossing polylines give the same bits in bands of any
/// height, with and without the walk cache.
#[test]
fn self_crossing_polyline_strokes_give_the_same_bits_in_every_band() {
    let mut rng = Rng(18);
    for k in 0..12 {
        let n = 3 + k % 10;
        let pts: Vec<FinePoint> = (0..n)
            .map(|_| fine_point(rng.range(4.0, 60.0), rng.range(4.0, 60.0)))
            .collect();
        let wf = (rng.range(0.5, 6.0) * 1024.0_f64).round() as u32;
        let style = StrokeStyle::new(wf)
            .with_join(JOINS[k % 3])
            .with_cap(CAPS[k / 3 % 3]);
        let op = Opacity::from_ratio(3, 4).unwrap();
        let draw = |c: &mut Canvas<'_, '_, 3>| {
            c.stroke_shape(
                &Polyline::new(&pts),
                &style,
                [4095, 2000, 0],
                Blend::Over,
                op,
            )
            .unwrap();
        };
        let reference = render_canvas::<3>(64, 64, 64, [100, 200, 300], 0, draw);
        for rows in [1, 2, 3, 7, 16, 33] {
            for slots in [0, 3, 32] {
                let f = render_canvas::<3>(64, 64, rows, [100, 200, 300], slots, draw);
                assert_eq!(
                    first_diff(&f.raw, &reference.raw),
                    None,
                    "polyline {k}: {rows} rows, {slots} slots"
                );
            }
        }
    }
}

/// A random convex polygon (fine units) around `(cx, cy)`: points on an
/// ellipse, clockwise on screen.
fn convex(rng: &mut Rng, cx: f64, cy: f64, n: usize) -> Vec<FinePoint> {
    let (a, b) = (rng.range(6.0, 14.0), rng.range(6.0, 14.0));
    let mut t: Vec<f64> = (0..n).map(|_| rng.range(0.0, 2.0 * PI)).collect();
    t.sort_by(f64::total_cmp);
    let mut v: Vec<FinePoint> = t
        .iter()
        .map(|&t| fine_point(cx + a * t.cos(), cy + b * t.sin()))
        .collect();
    v.dedup();
    v
}

#[test]
fn a_polygon_cut_along_a_diagonal_equals_the_whole() {
    let mut rng = Rng(16);
    for k in 0..64 {
        let poly = convex(&mut rng, 16.2, 15.7, 5 + k % 6);
        if poly.len() < 4 {
            continue;
        }
        let j = 2 + k % (poly.len() - 2);
        let (a, b): (Vec<_>, Vec<_>) = (
            poly[..=j].to_vec(),
            poly[j..].iter().chain(&poly[..1]).copied().collect(),
        );
        let col = [(k * 61 % 4096) as u16];
        let bg = [(k * 977 % 4096) as u16];
        // Add: the halves drawn one by one.
        let whole = render_canvas::<1>(32, 32, 6, bg, 0, |c| {
            c.fill(
                &Contour(&poly),
                col,
                FillRule::NonZero,
                Blend::Add,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        let halves = render_canvas::<1>(32, 32, 6, bg, 0, |c| {
            c.fill(
                &Contour(&a),
                col,
                FillRule::NonZero,
                Blend::Add,
                Opacity::OPAQUE,
            )
            .unwrap();
            c.fill(
                &Contour(&b),
                col,
                FillRule::NonZero,
                Blend::Add,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        assert_eq!(
            first_diff(&whole.raw, &halves.raw),
            None,
            "polygon {k}, add"
        );
        // Over: the halves as two contours of one path, at any opacity.
        let op = Opacity::from_ratio(k as u32 % 5 + 1, 5).unwrap();
        let whole = render_canvas::<1>(32, 32, 6, bg, 0, |c| {
            c.fill_shape(
                &Polygon::new(&poly),
                col,
                FillRule::NonZero,
                Blend::Over,
                op,
            )
            .unwrap();
        });
        let d = |v: &[FinePoint]| {
            let mut s = String::new();
            for (i, p) in v.iter().enumerate() {
                s += &format!(
                    "{} {} {} ",
                    if i == 0 { 'M' } else { 'L' },
                    f64::from(p.x) * FINE,
                    f64::from(p.y) * FINE
                );
            }
            s + "Z "
        };
        let both = d(&a) + &d(&b);
        let path = SvgPath::new(&both).unwrap();
        let halves = render_canvas::<1>(32, 32, 6, bg, 0, |c| {
            c.fill_shape(&path, col, FillRule::NonZero, Blend::Over, op)
                .unwrap();
        });
        assert_eq!(
            first_diff(&whole.raw, &halves.raw),
            None,
            "polygon {k}, over, one path of two contours"
        );
    }
}

/// The first pixel (index, both values) where two frames differ.
fn first_diff<T: PartialEq + Copy>(a: &[T], b: &[T]) -> Option<(usize, T, T)> {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .enumerate()
        .find(|(_, (x, y))| x != y)
        .map(|(k, (&x, &y))| (k, x, y))
}

/// Every kind of shape and stroke in one frame.
fn scene(c: &mut Canvas<'_, '_, 3>) {
    let p = FinePoint::new;
    let op = Opacity::from_ratio(3, 4).unwrap();
    let over = Blend::Over;
    let nz = FillRule::NonZero;
    c.fill_shape(
        &Circle::new(p(20_000, 18_500), 14_000),
        [4000, 100, 300],
        nz,
        over,
        Opacity::OPAQUE,
    )
    .unwrap();
    let e = Ellipse::new(p(40_300, 30_100), 20_000, 9_000).rotated(Degrees::new(33));
    c.fill_shape(&e, [200, 3000, 900], nz, over, op).unwrap();
    let rr = RoundedRectangle::new(
        Rectangle::new(p(5_300, 35_100), 30_000, 17_000),
        CornerRadii::uniform(6_000),
    );
    c.fill_shape(&rr, [900, 900, 4095], nz, over, op).unwrap();
    let arc = Arc::new(
        p(32_000, 32_000),
        24_000,
        Degrees::new(135),
        Degrees::new(270),
    );
    let gauge = StrokeStyle::new(5_000).with_cap(LineCap::Round);
    c.stroke_shape(&arc, &gauge, [4095, 4095, 0], over, Opacity::OPAQUE)
        .unwrap();
    let pie = Sector::new(
        p(50_000, 12_000),
        9_000,
        Degrees::new(-30),
        Degrees::new(100),
    );
    c.fill_shape(&pie, [0, 4095, 4095], nz, over, op).unwrap();
    let pts = [
        p(3_000, 60_000),
        p(20_000, 45_000),
        p(35_000, 58_000),
        p(60_000, 40_000),
    ];
    let pattern = [6_000, 2_500];
    let dashed = StrokeStyle::new(2_500)
        .with_join(LineJoin::Round)
        .with_dash(Dash::new(&pattern, 1_000));
    c.stroke_shape(&Polyline::new(&pts), &dashed, [4095, 2000, 0], over, op)
        .unwrap();
    let svg = SvgPath::new("M 10 10 Q 30 0 50 10 C 60 20 40 30 50 40 Z").unwrap();
    c.fill_shape(
        &svg,
        [1000, 0, 2000],
        FillRule::EvenOdd,
        over,
        Opacity::from_ratio(1, 2).unwrap(),
    )
    .unwrap();
    let inside = StrokeStyle::new(1_500).with_alignment(StrokeAlignment::Inside);
    c.stroke_shape(&rr, &inside, [4095; 3], over, Opacity::OPAQUE)
        .unwrap();
    c.stroke_shape(&svg, &StrokeStyle::new(300), [0; 3], over, Opacity::OPAQUE)
        .unwrap();
}

#[test]
fn band_height_and_the_walk_cache_change_no_bit_of_shapes_and_strokes() {
    let reference = render_canvas::<3>(64, 64, 64, [100, 200, 300], 0, scene);
    for rows in [1, 2, 3, 7, 16, 33] {
        for slots in [0, 3, 32] {
            let f = render_canvas::<3>(64, 64, rows, [100, 200, 300], slots, scene);
            assert_eq!(
                first_diff(&f.raw, &reference.raw),
                None,
                "{rows} rows, {slots} slots"
            );
        }
    }
    // Something of every shape is there.
    assert!(
        reference
            .lin12
            .iter()
            .filter(|p| **p != [100, 200, 300])
            .count()
            > 2000
    );
}

/// Random curves, many of them larger than the frame: what a band's
/// canvas leaves out of their descriptions (pieces of arcs and ellipses
/// off its rows, Béziers off them) changes no bit, in any band height.
#[test]
fn curves_give_the_same_bits_in_every_band_height() {
    let mut rng = Rng(0x5eed_c0de);
    for case in 0..24 {
        let mut shapes: Vec<(u8, f64, f64, f64, f64, f64, f64)> = Vec::new();
        for _ in 0..6 {
            shapes.push((
                (rng.f() * 6.0) as u8,
                rng.range(-20.0, 84.0),
                rng.range(-20.0, 84.0),
                rng.range(0.3, 90.0),
                rng.range(0.3, 40.0),
                rng.range(-360.0, 360.0),
                rng.range(-400.0, 400.0),
            ));
        }
        let draw = |c: &mut Canvas<'_, '_, 1>| {
            for &(kind, x, y, r, r2, a, s) in &shapes {
                let centre = fine_point(x, y);
                let rf = (r * 1024.0) as u32;
                let (a, s) = (Degrees::new(a as i32), Degrees::new(s as i32));
                let w = (r2 * 300.0) as u32 + 200;
                let col = [((x + 20.0) * 30.0) as u16];
                let op = Opacity::from_ratio(2, 3).unwrap();
                let _ = match kind {
                    0 => c.fill_shape(
                        &Circle::new(centre, rf),
                        col,
                        FillRule::NonZero,
                        Blend::Over,
                        op,
                    ),
                    1 => c.fill_shape(
                        &Ellipse::new(centre, rf, (r2 * 1024.0) as u32).rotated(a),
                        col,
                        FillRule::NonZero,
                        Blend::Over,
                        op,
                    ),
                    2 => c.fill_shape(
                        &Sector::new(centre, rf, a, s),
                        col,
                        FillRule::NonZero,
                        Blend::Over,
                        op,
                    ),
                    3 => {
                        let cap = [LineCap::Butt, LineCap::Round, LineCap::Square][case % 3];
                        let st = StrokeStyle::new(w).with_cap(cap);
                        c.stroke_shape(&Arc::new(centre, rf, a, s), &st, col, Blend::Over, op)
                    }
                    4 => {
                        let st = StrokeStyle::new(w);
                        c.stroke_shape(&Circle::new(centre, rf), &st, col, Blend::Over, op)
                    }
                    _ => {
                        let d = format!(
                            "M {x} {y} Q {} {} {} {} C {} {} {} {} {x} {} Z",
                            x + r,
                            y - r2,
                            x + 2.0 * r,
                            y,
                            x + r,
                            y + 3.0 * r2,
                            x - r,
                            y + r,
                            y + r2
                        );
                        let path = SvgPath::new(&d).unwrap();
                        c.fill_shape(&path, col, FillRule::EvenOdd, Blend::Over, op)
                    }
                };
            }
        };
        let reference = render_canvas::<1>(64, 64, 64, [50], 0, draw);
        for rows in [1, 3, 8, 16] {
            let f = render_canvas::<1>(64, 64, rows, [50], 16, draw);
            assert_eq!(
                first_diff(&f.raw, &reference.raw),
                None,
                "case {case}, {rows} rows"
            );
        }
    }
}

#[test]
fn degenerate_shapes_draw_nothing_and_bad_ones_are_reported() {
    let p = FinePoint::new;
    let f = render_canvas::<1>(16, 16, 4, [7], 0, |c| {
        let none = |r: Result<(), DrawError>| assert_eq!(r, Ok(()));
        let (nz, over, op) = (FillRule::NonZero, Blend::Over, Opacity::OPAQUE);
        none(c.fill_shape(&Circle::new(p(8_000, 8_000), 0), [4095], nz, over, op));
        none(c.fill_shape(
            &Ellipse::new(p(8_000, 8_000), 0, 5_000),
            [4095],
            nz,
            over,
            op,
        ));
        none(c.fill_shape(
            &Rectangle::new(p(1_000, 1_000), 0, 9_000),
            [4095],
            nz,
            over,
            op,
        ));
        let same = [p(3_000, 3_000); 4];
        none(c.fill_shape(&Polygon::new(&same), [4095], nz, over, op));
        none(c.stroke_shape(
            &Polyline::new(&same[..1]),
            &StrokeStyle::new(2_000),
            [4095],
            over,
            op,
        ));
        none(c.fill_shape(&SvgPath::new("").unwrap(), [4095], nz, over, op));
        let arc = Arc::new(p(8_000, 8_000), 5_000, Degrees::new(0), Degrees::new(0));
        none(c.stroke_shape(&arc, &StrokeStyle::new(1_000), [4095], over, op));
        none(c.fill_shape(
            &Circle::new(p(8_000, 8_000), 5_000),
            [4095],
            nz,
            over,
            Opacity::TRANSPARENT,
        ));
        // Beyond the coordinate range: rejected, reported, not drawn.
        let far = c.fill_shape(
            &Circle::new(p(i32::MAX - 10, 8_000), 5_000),
            [4095],
            nz,
            over,
            op,
        );
        assert!(matches!(far, Err(DrawError::FineCoord(_))), "{far:?}");
        assert_eq!(c.skipped().count, 1);
    });
    assert!(f.lin12.iter().all(|&v| v == [7]));
}

/// Eight stacked strips whose top edges zigzag by one fine unit at every
/// fine column: 8 · 2 · 65 536 + 24 = 1 048 600 edges.
struct Zigzags;

const ZIG_W: i32 = 64 * 1024;

impl Zigzags {
    /// The strips' vertices, clockwise on screen (top edge left to right).
    fn contours() -> Vec<Vec<(i64, i64)>> {
        (0..8)
            .map(|j| {
                let (top, bottom) = ((8 + 6 * j) * 1024, (13 + 6 * j) * 1024);
                let mut v = vec![(0i64, top as i64)];
                for x in 0..ZIG_W {
                    let y = top + (x & 1);
                    v.push((i64::from(x + 1), i64::from(y)));
                    v.push((i64::from(x + 1), i64::from(top + ((x + 1) & 1))));
                }
                v.push((i64::from(ZIG_W), i64::from(bottom)));
                v.push((0, i64::from(bottom)));
                v
            })
            .collect()
    }
}

impl softedge::path::Shape for Zigzags {
    fn describe<P: softedge::geom::PathSink + ?Sized>(&self, sink: &mut P) {
        for c in Self::contours() {
            let p = |&(x, y): &(i64, i64)| FinePoint::new(x as i32, y as i32);
            sink.move_to(p(&c[0]));
            for q in &c[1..] {
                sink.line_to(p(q));
            }
            sink.close();
        }
    }
}

/// Issue #16: the number of edges is not limited by an array; a path of
/// a million edges is streamed through the band and filled within the
/// engine's promise: every pixel within 1/256 px of its exact area (a
/// strip's top row loses 512 fine columns x 1 fine unit), the whole
/// within 0.02 % of the shoelace area in exact integers. (Each of the
/// million edges rounds its cells to 1/65536 px: the sum of those
/// roundings is what the total may drift by.)
#[test]
fn a_path_of_a_million_edges_fills_its_area() {
    let contours = Zigzags::contours();
    let edges: usize = contours.iter().map(Vec::len).sum();
    assert!(edges > 1_000_000, "{edges} edges");
    let twice_area: i128 = contours
        .iter()
        .map(|c| {
            (0..c.len())
                .map(|k| {
                    let ((x0, y0), (x1, y1)) = (c[k], c[(k + 1) % c.len()]);
                    i128::from(x0) * i128::from(y1) - i128::from(x1) * i128::from(y0)
                })
                .sum::<i128>()
        })
        .sum();
    let exact = twice_area.unsigned_abs() as f64 / 2.0 / (1024.0 * 1024.0);
    let f = fill(64, 64, 64, &Zigzags);
    let mut worst: f64 = 0.0;
    for y in 0..64i32 {
        let strip = (y - 8).rem_euclid(6);
        let inside = (8..56).contains(&y) && strip < 5;
        let want = match (inside, strip) {
            (false, _) => 0.0,
            (true, 0) => 1.0 - 512.0 / (1024.0 * 1024.0),
            (true, _) => 1.0,
        };
        for x in 0..64 {
            worst = worst.max((coverage(&f, x, y) - want).abs());
        }
    }
    let got = total(&f);
    assert!(
        worst <= 1.0 / 256.0,
        "worst pixel {worst} px ({edges} edges)"
    );
    assert!(
        (got - exact).abs() <= 2e-4 * exact,
        "area {got} px, exact {exact} px ({edges} edges)"
    );
}
