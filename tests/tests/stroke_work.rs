//! Issue #36, G3: the work a dashed stroke costs in one band. Dash pieces
//! that cannot meet the band are stepped over by their bounds, not built;
//! and a stroke's dashes are charged against a budget that does not
//! depend on the band, beyond which it stops with
//! `StrokeError::TooComplex` (the same place in every band).
//!
//! Work is measured deterministically: the segments a stroke sends its
//! sink (every segment built, in the band or not) for a sink whose
//! window is one pixel row, as a band's canvas gives. The callgrind
//! figures for the same inputs are in the commit message.

use softedge::geom::FinePoint;
use softedge::path::svg::SvgPath;
use softedge::path::{
    Circle, Dash, LineCap, MiterLimit, SegmentSink, Shape, StrokeError, StrokeStyle, Tolerance,
};

/// Counts segments sent and keeps those meeting `window` (rows, fine
/// units) with their numbers (segments left out count, as a band's walk
/// cache numbers them).
struct Band {
    window: Option<(i32, i32)>,
    sent: u64,
    next: u64,
    kept: Vec<(u64, FinePoint, FinePoint)>,
}

impl SegmentSink for Band {
    fn segment(&mut self, a: FinePoint, b: FinePoint) {
        self.sent += 1;
        let (lo, hi) = self.window.unwrap_or((i32::MIN, i32::MAX));
        if a.y.max(b.y) >= lo && a.y.min(b.y) <= hi {
            self.kept.push((self.next, a, b));
        }
        self.next += 1;
    }
    fn window(&self) -> Option<(i32, i32)> {
        self.window
    }
    fn skipped(&mut self, n: u32) {
        self.next += u64::from(n);
    }
}

fn stroke<S: Shape>(
    shape: &S,
    style: &StrokeStyle<'_>,
    window: Option<(i32, i32)>,
) -> (Band, Result<(), StrokeError>) {
    let mut b = Band {
        window,
        sent: 0,
        next: 0,
        kept: Vec::new(),
    };
    let r = shape.stroke_with(style, Tolerance::DEFAULT, &mut b);
    (b, r)
}

/// The most segments a stroke may send one band's sink.
const BAND_SEGMENTS: u64 = 1 << 17;

/// For each 1-row band of a frame `rows` high: the segments sent are at
/// most [`BAND_SEGMENTS`], those meeting the band are exactly those the
/// whole stroke (no window) has there, in the same order with the same
/// numbers, and the result is the same. Returns the most sent in a band and the result.
fn check_bands<S: Shape>(
    name: &str,
    shape: &S,
    style: &StrokeStyle<'_>,
    rows: i32,
) -> (u64, Result<(), StrokeError>) {
    check_bands_numbered(name, shape, style, rows, true)
}

/// [`check_bands`]; without `whole_numbers` (a polyline stroked only
/// where it meets the band: `path::stroke::windowed`), the segments
/// meeting the band are those of the whole stroke in some order, and
/// their numbers rise (a band's walks are found by them; that they are the
/// same from band to band is `a_windowed_stroke_sends_the_window_the_whole_strokes_segments`
/// in the library).
fn check_bands_numbered<S: Shape>(
    name: &str,
    shape: &S,
    style: &StrokeStyle<'_>,
    rows: i32,
    whole_numbers: bool,
) -> (u64, Result<(), StrokeError>) {
    let (whole, whole_r) = stroke(shape, style, None);
    let mut most = 0;
    for y in 0..rows {
        let w = (y * 1024, y * 1024 + 1023);
        let (band, r) = stroke(shape, style, Some(w));
        assert_eq!(r, whole_r, "{name}: band {y}: another result");
        let want: Vec<_> = whole
            .kept
            .iter()
            .filter(|(_, a, b)| a.y.max(b.y) >= w.0 && a.y.min(b.y) <= w.1)
            .copied()
            .collect();
        if whole_numbers {
            assert_eq!(
                band.kept, want,
                "{name}: band {y}: other segments in the band"
            );
            assert_eq!(band.next, whole.next, "{name}: band {y}: other numbers");
        } else {
            let sorted = |v: &[(u64, FinePoint, FinePoint)]| {
                let mut s: Vec<_> = v.iter().map(|&(_, a, b)| (a.x, a.y, b.x, b.y)).collect();
                s.sort();
                s
            };
            assert_eq!(
                sorted(&band.kept),
                sorted(&want),
                "{name}: band {y}: other segments in the band"
            );
            assert!(
                band.kept.windows(2).all(|p| p[0].0 < p[1].0),
                "{name}: band {y}: numbers do not rise"
            );
        }
        assert!(
            band.sent <= BAND_SEGMENTS,
            "{name}: band {y}: {} segments sent",
            band.sent
        );
        most = most.max(band.sent);
    }
    eprintln!(
        "{name}: at most {most} segments per band, whole {} ({whole_r:?})",
        whole.sent
    );
    (most, whole_r)
}

/// The first input: a 50-byte path 21.8 px wide with round caps
/// and a 3/1024-px dash, in the 1-row bands of a 4x15 frame (6.4 s).
#[test]
fn a_fine_dash_on_a_wide_round_capped_path_is_bounded() {
    let d = SvgPath::new("M 2 2 C 900 -900 -900 900 2 13 S 2000 -40 1 8 Z").unwrap();
    assert!(d.data().len() <= 50);
    let pattern = [3];
    let style = StrokeStyle::new(22323)
        .with_cap(LineCap::Round)
        .with_dash(Dash::new(&pattern, 0));
    let (_, r) = check_bands("fine dash", &d, &style, 15);
    assert_eq!(r, Err(StrokeError::TooComplex));
}

/// The second: a circle of diameter 45 px stroked 785 px wide with the
/// pattern [144, 0, 0] (172 ms per band).
#[test]
fn a_very_wide_circle_with_dots_is_bounded() {
    let c = Circle::new(FinePoint::new(8 * 1024, 8 * 1024), 45 * 512);
    let pattern = [144, 0, 0];
    for cap in [LineCap::Butt, LineCap::Round, LineCap::Square] {
        let style = StrokeStyle::new(785 * 1024)
            .with_cap(cap)
            .with_dash(Dash::new(&pattern, 0));
        let (_, r) = check_bands("wide circle", &c, &style, 16);
        // Round caps 785 px wide: about 1 000 segments a dash, so the
        // budget runs out; butt caps cost 6 a dash, and the 1 000 dashes
        // are drawn.
        match cap {
            LineCap::Round => assert_eq!(r, Err(StrokeError::TooComplex)),
            LineCap::Butt => assert_eq!(r, Ok(())),
            _ => {}
        }
    }
}

/// The third: a 2048-px curve 16 px wide dashed [64] (1/16 px: 16 384
/// dashes) in the 1-row bands of a 16x16 frame (1.9 s per band): past the
/// budget, the same in every band.
#[test]
fn a_long_finely_dashed_curve_is_bounded() {
    let d = SvgPath::new("M -1000 8 C -300 -1500 300 1500 1000 8").unwrap();
    let pattern = [64];
    let style = StrokeStyle::new(16 * 1024).with_dash(Dash::new(&pattern, 0));
    let (_, r) = check_bands("long curve", &d, &style, 16);
    assert_eq!(r, Err(StrokeError::TooComplex));
}

/// Dashes of 1 px along the same curve (1 000 dashes, within the
/// budget): drawn, and a band builds only those near it, a small part of
/// the whole.
#[test]
fn a_long_dashed_curve_builds_only_the_dashes_near_the_band() {
    let d = SvgPath::new("M -1000 8 C -300 -1500 300 1500 1000 8").unwrap();
    let pattern = [1024];
    let style = StrokeStyle::new(16 * 1024).with_dash(Dash::new(&pattern, 0));
    let (most, r) = check_bands("long curve, 1-px dashes", &d, &style, 16);
    assert_eq!(r, Ok(()));
    let (whole, _) = stroke(&d, &style, None);
    assert!(most * 8 < whole.sent, "{most} of {}", whole.sent);
}

/// The budget is charged the same whatever the window: a stroke just
/// within it is drawn in every band, and every band of one just past it
/// stops at the same dash (the band checks above compare each band's
/// segments with the whole stroke's).
#[test]
fn the_budget_is_charged_by_the_stated_rule() {
    // Butt caps: a dash is charged 2 + 4 and each of its two intervals 1:
    // 8 units a period. A straight 1-px-wide line of n periods of 2/1024
    // px costs 8 n (plus the first dash, 6).
    let pattern = [1];
    let style = StrokeStyle::new(1024).with_dash(Dash::new(&pattern, 0));
    let line = |periods: i32| {
        let x = periods * 2;
        let p = [FinePoint::new(0, 4096), FinePoint::new(x, 4096)];
        softedge::path::Polyline::new(&p).stroke_with(
            &style,
            Tolerance::DEFAULT,
            &mut Band {
                window: Some((0, 1023)),
                sent: 0,
                next: 0,
                kept: Vec::new(),
            },
        )
    };
    let max = softedge::path::MAX_STROKE_WORK as i32;
    let fits = (max - 6) / 8 - 1;
    assert_eq!(line(fits), Ok(()));
    assert_eq!(line(fits + 3), Err(StrokeError::TooComplex));
}

/// Solid strokes too: a piece of the path (and the joins and caps at its
/// ends) that misses the band, within the range square, is quiet. An
/// ellipse of 1000 x 900 px stroked 300 px wide (its offset curve needs
/// thousands of pieces with round joins between them): a band builds the
/// pieces near it, with the same segments and numbers there as the whole
/// stroke.
#[test]
fn a_wide_solid_curve_builds_only_the_pieces_near_the_band() {
    let e = softedge::path::Ellipse::new(FinePoint::new(0, 0), 1000 * 1024, 900 * 1024);
    let style = StrokeStyle::new(300 * 1024).with_join(softedge::path::LineJoin::Round);
    let (most, r) = check_bands("wide ellipse", &e, &style, 16);
    assert_eq!(r, Ok(()));
    let (whole, _) = stroke(&e, &style, None);
    assert!(most * 2 < whole.sent, "{most} of {}", whole.sent);
    // And a polyline with round joins and caps, crossing the band.
    let v = [
        FinePoint::new(-400 * 1024, -300 * 1024),
        FinePoint::new(8 * 1024, 8 * 1024),
        FinePoint::new(300 * 1024, -200 * 1024),
        FinePoint::new(-100 * 1024, 500 * 1024),
    ];
    let style = StrokeStyle::new(40 * 1024)
        .with_join(softedge::path::LineJoin::Round)
        .with_cap(LineCap::Round);
    let (_, r) = check_bands("polyline", &softedge::path::Polyline::new(&v), &style, 16);
    assert_eq!(r, Ok(()));
}

/// Miter joins of quiet pieces are counted, not built (no tip computed):
/// a zigzag whose turns are within the miter limit and beyond it (bevel),
/// both ways, and a chart's line, give every band the whole stroke's
/// segments there (stroked only near the band: their numbers are their
/// own, see `check_bands_numbered`).
#[test]
fn quiet_miter_joins_keep_their_numbers() {
    let zig: Vec<FinePoint> = (0..40)
        .map(|i| {
            let x = (i % 2) * (3 + i % 7) * 1024 + (i % 3) * 300;
            FinePoint::new(x, i * 700 - 2000)
        })
        .collect();
    let chart: Vec<FinePoint> = (0..60)
        .map(|i| FinePoint::new(i * 4 * 1024, ((i * 37) % 23) * 1024 + 512))
        .collect();
    for (name, pts) in [("zigzag", &zig), ("chart", &chart)] {
        for width in [1024, 3 * 1024, 7 * 1024 + 300] {
            for limit in [MiterLimit::DEFAULT, MiterLimit::from_q16(3 << 15)] {
                let style = StrokeStyle::new(width).with_miter_limit(limit);
                let line = softedge::path::Polyline::new(pts);
                let (_, r) = check_bands_numbered(name, &line, &style, 28, false);
                assert_eq!(r, Ok(()), "{name}");
            }
        }
    }
}

/// Issue #36's bound for solid strokes: the widest descriptions of at most
/// 1 KiB found (a 2000-px ellipse stroked 4 096 px wide; 250 points of
/// zigzag with round joins; 28 curves across the range; 512 `h1v1`
/// commands with round joins and caps; tiny loops stroked 1 000 px wide),
/// built at the tolerance fitted to the budget (`path::stroke::budget`):
/// drawn whole, the same segments with the same numbers in every band,
/// and at most the stroker's limit for 512 drawing commands,
/// `2 * MAX_STROKE_WORK + 16 * 512` units, sent to a band. (They sent
/// 20 892 to 1 387 580 segments a band before; callgrind per band in
/// `tests/examples/stroke_work.rs`, cases `i` to `m`.)
#[test]
fn the_widest_solid_strokes_are_fitted_within_the_limit() {
    use softedge::path::{LineJoin, MAX_STROKE_WORK};
    let limit = u64::from(2 * MAX_STROKE_WORK + 16 * 512);
    let wide = StrokeStyle::new(4096 * 1024);
    let round = wide.with_join(LineJoin::Round);
    let ellipse = softedge::path::Ellipse::new(FinePoint::new(0, 0), 2000 * 1024, 1900 * 1024);
    let (most, r) = check_bands("ellipse", &ellipse, &wide, 16);
    assert_eq!(r, Ok(()));
    assert!(most <= limit, "{most}");
    let zig: Vec<FinePoint> = (0..250)
        .map(|i| FinePoint::new((i % 2) * 9 * 1024, i * 8 * 1024))
        .collect();
    let (most, r) = check_bands("zigzag", &softedge::path::Polyline::new(&zig), &round, 16);
    assert_eq!(r, Ok(()));
    assert!(most <= limit, "{most}");
    let mut curves = String::from("M -2000 -2000");
    for k in 0.. {
        let s = if k % 2 == 0 { 1 } else { -1 };
        let c = format!(
            " C {} -1900 {} 1900 {} {}",
            2000 * s,
            -2000 * s,
            1990 * s,
            1990 - k * 90
        );
        if curves.len() + c.len() > 1024 {
            break;
        }
        curves += &c;
    }
    let mut stairs = String::from("M8 8");
    while stairs.len() + 4 <= 1024 {
        stairs += "h1v1";
    }
    let mut loops = String::from("M8 8");
    while loops.len() + 16 <= 1024 {
        loops += "c1 -1 -1 -1 0 1";
    }
    let capped = round.with_cap(LineCap::Round);
    let thick = StrokeStyle::new(1000 * 1024).with_join(LineJoin::Round);
    for (name, d, style) in [
        ("curves", &curves, &round),
        ("stairs", &stairs, &capped),
        ("loops", &loops, &thick),
    ] {
        assert!(d.len() <= 1024);
        let path = SvgPath::new(d).unwrap();
        let (most, r) = check_bands(name, &path, style, 16);
        assert_eq!(r, Ok(()), "{name}");
        assert!(most <= limit, "{name}: {most}");
    }
}
