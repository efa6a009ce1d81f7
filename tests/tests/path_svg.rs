//! SVG path data: every command against hand-computed calls, numbers
//! against `f64` rounding, arcs against the SVG 2 endpoint-to-centre
//! conversion written in `f64`, errors, and arbitrary input.

use std::f64::consts::PI;

use proptest::prelude::*;
use softedge::geom::{FinePoint, PathSink};
use softedge::path::svg::{parse_path_data, SvgErrorKind, SvgPath};
use softedge::path::{Flattener, Shape};
use softedge_tests::path_ref::{Segments, FINE};

#[derive(Debug, Clone, Copy, PartialEq)]
enum Call {
    M(f64, f64),
    L(f64, f64),
    Q(f64, f64, f64, f64),
    C(f64, f64, f64, f64, f64, f64),
    Z,
}

#[derive(Default)]
struct Rec(Vec<Call>);

fn px(p: FinePoint) -> (f64, f64) {
    (f64::from(p.x) * FINE, f64::from(p.y) * FINE)
}

impl PathSink for Rec {
    fn move_to(&mut self, p: FinePoint) {
        let p = px(p);
        self.0.push(Call::M(p.0, p.1));
    }
    fn line_to(&mut self, p: FinePoint) {
        let p = px(p);
        self.0.push(Call::L(p.0, p.1));
    }
    fn quad_to(&mut self, c: FinePoint, p: FinePoint) {
        let (c, p) = (px(c), px(p));
        self.0.push(Call::Q(c.0, c.1, p.0, p.1));
    }
    fn cubic_to(&mut self, c1: FinePoint, c2: FinePoint, p: FinePoint) {
        let (a, b, p) = (px(c1), px(c2), px(p));
        self.0.push(Call::C(a.0, a.1, b.0, b.1, p.0, p.1));
    }
    fn close(&mut self) {
        self.0.push(Call::Z);
    }
}

fn calls(d: &str) -> Vec<Call> {
    let mut r = Rec::default();
    parse_path_data(d, &mut r).unwrap_or_else(|e| panic!("{d}: {e}"));
    r.0
}

use Call::{C, L, M, Q, Z};

#[test]
fn every_command_absolute_and_relative_gives_its_calls() {
    assert_eq!(calls("M 1 2 L 3 4"), [M(1.0, 2.0), L(3.0, 4.0)]);
    assert_eq!(calls("m 1 2 l 3 4"), [M(1.0, 2.0), L(4.0, 6.0)]);
    assert_eq!(
        calls("M1 2H5V7h-1v-2"),
        [
            M(1.0, 2.0),
            L(5.0, 2.0),
            L(5.0, 7.0),
            L(4.0, 7.0),
            L(4.0, 5.0)
        ]
    );
    assert_eq!(
        calls("M0 0 Q1 2 3 4 q1 1 2 0"),
        [M(0.0, 0.0), Q(1.0, 2.0, 3.0, 4.0), Q(4.0, 5.0, 5.0, 4.0)]
    );
    assert_eq!(
        calls("M0 0 C1 2 3 4 5 6 c1 0 1 1 0 1"),
        [
            M(0.0, 0.0),
            C(1.0, 2.0, 3.0, 4.0, 5.0, 6.0),
            C(6.0, 6.0, 6.0, 7.0, 5.0, 7.0)
        ]
    );
    assert_eq!(calls("M0 0 L 1 1 Z"), [M(0.0, 0.0), L(1.0, 1.0), Z]);
}

#[test]
fn implicit_repetition_continues_the_command_and_moves_become_lines() {
    assert_eq!(
        calls("M 1 1 2 2 3 3"),
        [M(1.0, 1.0), L(2.0, 2.0), L(3.0, 3.0)]
    );
    assert_eq!(
        calls("m 1 1 2 2 3 3"),
        [M(1.0, 1.0), L(3.0, 3.0), L(6.0, 6.0)]
    );
    assert_eq!(
        calls("M0 0 h1 2 3"),
        [M(0.0, 0.0), L(1.0, 0.0), L(3.0, 0.0), L(6.0, 0.0)]
    );
    assert_eq!(
        calls("M0 0 Q 1 1 2 0 3 -1 4 0"),
        [M(0.0, 0.0), Q(1.0, 1.0, 2.0, 0.0), Q(3.0, -1.0, 4.0, 0.0)]
    );
}

#[test]
fn smooth_curves_reflect_the_previous_control_point() {
    assert_eq!(
        calls("M0 0 C 1 2 3 2 4 0 S 7 -2 8 0"),
        [
            M(0.0, 0.0),
            C(1.0, 2.0, 3.0, 2.0, 4.0, 0.0),
            C(5.0, -2.0, 7.0, -2.0, 8.0, 0.0)
        ]
    );
    // S after a non-cubic: the first control point is the current point.
    assert_eq!(
        calls("M0 0 L 2 0 S 3 1 4 0"),
        [M(0.0, 0.0), L(2.0, 0.0), C(2.0, 0.0, 3.0, 1.0, 4.0, 0.0)]
    );
    assert_eq!(
        calls("M0 0 Q 1 1 2 0 T 4 0 t 2 0"),
        [
            M(0.0, 0.0),
            Q(1.0, 1.0, 2.0, 0.0),
            Q(3.0, -1.0, 4.0, 0.0),
            Q(5.0, 1.0, 6.0, 0.0)
        ]
    );
    assert_eq!(calls("M0 0 T 2 2"), [M(0.0, 0.0), Q(0.0, 0.0, 2.0, 2.0)]);
}

#[test]
fn after_close_the_next_subpath_starts_at_the_closed_ones_start() {
    assert_eq!(
        calls("M 1 1 L 5 1 L 5 5 Z l 1 0 z"),
        [
            M(1.0, 1.0),
            L(5.0, 1.0),
            L(5.0, 5.0),
            Z,
            M(1.0, 1.0),
            L(2.0, 1.0),
            Z
        ]
    );
}

#[test]
fn numbers_take_every_form_svg_allows() {
    assert_eq!(calls("M-1.5-2.5"), [M(-1.5, -2.5)]);
    assert_eq!(calls("M.5.5"), [M(0.5, 0.5)]);
    assert_eq!(calls("M+1e1,2E-1"), [M(10.0, 0.2001953125)]); // 0.2 * 1024 = 204.8 -> 205
    assert_eq!(calls("M 1,2,3,4"), [M(1.0, 2.0), L(3.0, 4.0)]);
    assert_eq!(calls(" \t\nM\r1\x0c2 "), [M(1.0, 2.0)]);
    // Flags packed without separators.
    let c = calls("M0 0 a1 1 0 0110 0");
    assert_eq!(c.last().map(|c| matches!(c, C(..))), Some(true));
}

proptest! {
    #[test]
    fn numbers_round_to_the_nearest_fine_unit(v in -2000.0f64..2000.0, digits in 0usize..9, exp in prop::bool::ANY) {
        let text = if exp { format!("{:.*e}", digits, v) } else { format!("{:.*}", digits, v) };
        // The value the text denotes (f64 parses decimal text correctly
        // rounded; ties of the fine grid are out of reach at these digits
        // except exactly representable ones, rounded away from zero).
        let exact: f64 = text.parse().unwrap_or(0.0);
        let want = (exact * 1024.0).round();
        let c = calls(&format!("M {text} 0"));
        prop_assert_eq!(c, vec![M(want / 1024.0, 0.0)], "{}", text);
    }

    #[test]
    fn arbitrary_input_never_panics_and_stays_bounded(d in "[MmLlHhVvCcSsQqTtAaZz0-9 ,.eE+-]{0,80}") {
        let mut s = Segments::new();
        {
            let mut f = Flattener::new(&mut s);
            let _ = parse_path_data(&d, &mut f);
        }
        prop_assert!(s.is_closed_in_range());
        prop_assert!(s.len() < 80 * 5 * 1100);
    }
}

#[test]
fn errors_report_the_position_and_what_was_wrong() {
    let e = |d: &str| parse_path_data(d, &mut Rec::default()).unwrap_err();
    assert_eq!(
        (e("L 1 1").position, e("L 1 1").kind),
        (0, SvgErrorKind::MissingMoveTo)
    );
    assert_eq!(
        (e("M 1 1 L 2").position, e("M 1 1 L 2").kind),
        (9, SvgErrorKind::ExpectedNumber)
    );
    assert_eq!(e("M 1 1 Q 1 1 e").kind, SvgErrorKind::ExpectedNumber);
    assert_eq!(e("M 1 1 # 2").kind, SvgErrorKind::ExpectedCommand);
    assert_eq!(e("M 1 1 A 1 1 0 3 1 2 2").kind, SvgErrorKind::ExpectedFlag);
    assert_eq!(e("M 1e9 1").kind, SvgErrorKind::NumberOutOfRange);
    assert_eq!(
        e("M 0 0 l 2000 0 l 100 0").kind,
        SvgErrorKind::PointOutOfRange
    );
    assert_eq!(e("M 0 0 L 1 1 1").position, 13);
    let text = format!("{}", e("M 1 1 L 2"));
    assert!(text.contains("byte 9") && text.contains("number"), "{text}");
    // The calls before the error have been made.
    let mut r = Rec::default();
    assert!(parse_path_data("M 1 1 L 2 2 L x", &mut r).is_err());
    assert_eq!(r.0, [M(1.0, 1.0), L(2.0, 2.0)]);
    assert!(SvgPath::new("M 0 0 L 9 9 Z").is_ok());
}

/// SVG 2 appendix B.2.4 in `f64`: the centre, radii, start angle and sweep
/// of the arc from `p1` to `p2`.
fn centre_form(
    p1: (f64, f64),
    p2: (f64, f64),
    rx: f64,
    ry: f64,
    phi_deg: f64,
    fa: bool,
    fs: bool,
) -> ((f64, f64), f64, f64, f64, f64, f64) {
    let phi = phi_deg.to_radians();
    let (c, s) = (phi.cos(), phi.sin());
    let (dx, dy) = ((p1.0 - p2.0) / 2.0, (p1.1 - p2.1) / 2.0);
    let (x1, y1) = (c * dx + s * dy, -s * dx + c * dy);
    let (mut rx, mut ry) = (rx.abs(), ry.abs());
    let lambda = x1 * x1 / (rx * rx) + y1 * y1 / (ry * ry);
    if lambda > 1.0 {
        rx *= lambda.sqrt();
        ry *= lambda.sqrt();
    }
    let num = rx * rx * ry * ry - rx * rx * y1 * y1 - ry * ry * x1 * x1;
    let den = rx * rx * y1 * y1 + ry * ry * x1 * x1;
    let mut k = (num / den).max(0.0).sqrt();
    if fa == fs {
        k = -k;
    }
    let (cx1, cy1) = (k * rx * y1 / ry, -k * ry * x1 / rx);
    let centre = (
        c * cx1 - s * cy1 + (p1.0 + p2.0) / 2.0,
        s * cx1 + c * cy1 + (p1.1 + p2.1) / 2.0,
    );
    let ang = |ux: f64, uy: f64| uy.atan2(ux);
    let t1 = ang((x1 - cx1) / rx, (y1 - cy1) / ry);
    let mut dt = ang((-x1 - cx1) / rx, (-y1 - cy1) / ry) - t1;
    dt = dt.rem_euclid(2.0 * PI);
    if !fs {
        dt -= 2.0 * PI;
    }
    (centre, rx, ry, phi, t1, dt)
}

#[test]
fn arcs_follow_the_endpoint_to_centre_conversion() {
    let cases = [
        ((10.0, 10.0), (50.0, 30.0), 30.0, 20.0, 0.0, false, true),
        ((10.0, 10.0), (50.0, 30.0), 30.0, 20.0, 0.0, true, true),
        ((10.0, 10.0), (50.0, 30.0), 30.0, 20.0, 0.0, false, false),
        ((10.0, 10.0), (50.0, 30.0), 30.0, 20.0, 0.0, true, false),
        ((100.0, 50.0), (20.0, 80.0), 45.0, 25.0, 30.0, true, true),
        ((0.0, 0.0), (100.0, 0.0), 10.0, 10.0, 0.0, false, true), // radii too small: scaled up
        ((5.0, 5.0), (5.5, 5.25), 300.0, 200.0, -70.0, false, true), // huge radii, short chord
    ];
    for (p1, p2, rx, ry, phi, fa, fs) in cases {
        let d = format!(
            "M {} {} A {rx} {ry} {phi} {} {} {} {}",
            p1.0,
            p1.1,
            u8::from(fa),
            u8::from(fs),
            p2.0,
            p2.1
        );
        let mut s = Segments::new();
        {
            let mut f = Flattener::new(&mut s);
            parse_path_data(&d, &mut f).unwrap();
        }
        let (c, rx, ry, phi, t1, dt) = centre_form(p1, p2, rx, ry, phi, fa, fs);
        // Every vertex of the flattened arc lies on the ellipse, at a
        // parameter inside the swept range. The closing chord back to p1
        // is the flattener's: skip it.
        let pts: Vec<(f64, f64)> = s.px().map(|(a, _)| a).collect();
        for (k, &(x, y)) in pts.iter().enumerate() {
            let (u, v) = (
                (x - c.0) * phi.cos() + (y - c.1) * phi.sin(),
                -(x - c.0) * phi.sin() + (y - c.1) * phi.cos(),
            );
            let level = (u / rx).hypot(v / ry);
            // Within 6 fine units of the curve (tolerance, the cubics'
            // bulge, two roundings), relative to the radius.
            assert!(
                (level - 1.0).abs() * rx.min(ry) < 6.0 * FINE,
                "{d}: vertex {k} off by {}",
                level - 1.0
            );
            // The vertex's parameter, relative to the start, in (-pi, pi]
            // around the middle of the sweep.
            let t = (v / ry).atan2(u / rx);
            let rel = (t - t1 - dt / 2.0 + PI).rem_euclid(2.0 * PI) - PI + dt / 2.0;
            let inside = dt.min(0.0) - 1e-3 <= rel && rel <= dt.max(0.0) + 1e-3;
            assert!(
                inside,
                "{d}: vertex {k} at parameter {rel} outside the sweep {dt}"
            );
        }
        // The path ends exactly at p2.
        let last = s.segs.iter().rev().nth(1).map(|&(_, b)| b);
        assert_eq!(last.map(px), Some(p2), "{d}");
    }
}

#[test]
fn degenerate_arcs_are_lines_or_nothing() {
    assert_eq!(calls("M 1 1 A 0 5 0 0 1 4 4"), [M(1.0, 1.0), L(4.0, 4.0)]);
    assert_eq!(calls("M 1 1 A 5 5 0 0 1 1 1"), [M(1.0, 1.0)]);
    assert_eq!(calls("M 1 1 a -5 -5 0 0 1 4 0").len(), 1 + 2); // negative radii taken absolute: a half circle in two cubics
}

#[test]
fn svg_path_describes_itself_again_and_again() {
    let p = SvgPath::new("M 10 10 h 20 v 20 h -20 z").unwrap();
    for _ in 0..3 {
        let mut s = Segments::new();
        p.fill(&mut s);
        assert!((s.shoelace() - 400.0).abs() < 1e-9);
    }
}
