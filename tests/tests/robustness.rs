//! Issue #36: robustness of the drawing surface. Inputs an outside fuzzing
//! campaign found: each a frame that must draw the same in debug and
//! release, without a panic, or be refused with a typed error.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, Ellipse, Rectangle, RoundedRectangle, Sector};
use softedge::prelude::*;

use softedge_tests::screen::Screen;

/// The `w` x `h` frame `draw` gives in bands of `rows`, with its report.
fn frame<F>(w: u16, h: u16, rows: u16, draw: F) -> (Vec<Option<Rgb565>>, FrameReport)
where
    F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
{
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
    let mut slots = [WalkSlot::<3>::EMPTY; 4];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, w, h, rows).unwrap();
    let mut screen = Screen::<Rgb565>::new(u32::from(w), u32::from(h));
    let format = Rgb565Format::new(Curve::Srgb);
    let report = r
        .render(&mut screen, &format, Rgb565::BLACK, draw)
        .unwrap_or_else(|e| panic!("render: {e}"));
    (screen.px, report)
}

/// A 60x40 button at (2, 4) with every corner `radius` px, filled and
/// stroked 3 px centred.
fn button(radius: u32) -> (Vec<Option<Rgb565>>, FrameReport) {
    frame(64, 48, 8, |c| {
        let r = RoundedRectangle::with_equal_corners(
            Rectangle::new(Point::new(2, 4), Size::new(60, 40)),
            Size::new(radius, radius),
        );
        r.into_styled(AaStyle::with_fill(Rgb565::RED)).draw(c)?;
        r.into_styled(AaStyle::with_stroke(Rgb565::WHITE, 3))
            .draw(c)?;
        Ok(())
    })
}

/// G1: corner radii of 2·10^8 px overflowed embedded-graphics'
/// `confine_radii` (u32 sums and products): a panic in debug builds, 9-px
/// corners in release (384 pixels off). The radii are confined as
/// embedded-graphics would with exact arithmetic: 2·10^8 · 40 / 4·10^8 =
/// 20 px, so the frame is the frame with radii of 20 px, in both builds.
#[test]
fn huge_corner_radii_draw_the_confined_corners_in_debug_and_release() {
    let (want, report) = button(20);
    assert_eq!(report.skipped.count, 0);
    for radius in [200_000_000, u32::MAX / 2, u32::MAX - 1, u32::MAX] {
        let (px, report) = button(radius);
        assert_eq!(report.skipped.count, 0, "radius {radius}");
        let off = px.iter().zip(&want).filter(|(a, b)| a != b).count();
        assert_eq!(
            off, 0,
            "radius {radius}: {off} pixels differ from radius 20"
        );
    }
}

/// Unequal huge radii on every corner: confined by the side that overlaps
/// most, as embedded-graphics does, computed here in f64 (exact at these
/// sizes: every product is below 2^53), then drawn at those radii.
#[test]
fn unequal_huge_radii_are_confined_by_the_most_overlapping_side() {
    let corners = [
        Size::new(3_000_000_000, 1_000_000_000),
        Size::new(4_000_000_000, 2_000_000_000),
        Size::new(1_500_000_000, 3_500_000_000),
        Size::new(2_500_000_000, 4_000_000_000),
    ];
    let (w, h) = (60u32, 40u32);
    let [tl, tr, br, bl] = corners;
    let sides = [
        (tl.width as f64 + tr.width as f64, w),
        (tr.height as f64 + br.height as f64, h),
        (bl.width as f64 + br.width as f64, w),
        (tl.height as f64 + bl.height as f64, h),
    ];
    // The largest overlap, the first of equals.
    let mut best = (0.0, 0u32, 0.0);
    for (sum, size) in sides {
        let o = sum - size as f64;
        if o > best.0 {
            best = (o, size, sum);
        }
    }
    // In fine units (1/1024 px), for softedge's own rounded rectangle
    // (which then applies CSS's rule, as the e-g conversion does).
    let scale = |z: Size| {
        let f = |v: u32| ((v as f64) * best.1 as f64 / best.2).floor() as u32 * 1024;
        (f(z.width), f(z.height))
    };
    let rect = Rectangle::new(Point::new(2, 4), Size::new(w, h));
    let (want, _) = frame(64, 48, 8, |cv| {
        let [tl, tr, br, bl] = corners.map(scale);
        let r = softedge::path::RoundedRectangle::new(
            softedge::path::Rectangle::new(FinePoint::from_px(2, 4), w * 1024, h * 1024),
            softedge::path::CornerRadii {
                top_left: tl,
                top_right: tr,
                bottom_right: br,
                bottom_left: bl,
            },
        );
        r.into_styled(AaStyle::with_fill(Rgb565::RED)).draw(cv)
    });
    let (got, _) = frame(64, 48, 8, |cv| {
        let r = RoundedRectangle::new(
            rect,
            embedded_graphics::primitives::CornerRadii {
                top_left: corners[0],
                top_right: corners[1],
                bottom_right: corners[2],
                bottom_left: corners[3],
            },
        );
        r.into_styled(AaStyle::with_fill(Rgb565::RED)).draw(cv)
    });
    assert!(want.iter().filter(|p| **p != Some(Rgb565::BLACK)).count() > 1500);
    assert_eq!(got, want);
}

/// The other conversions at their extremes: diameters and sizes near
/// u32::MAX, corners at i32's ends, NaN and infinite angles. Each is drawn
/// or refused with a typed error; none panics, and the shapes after them
/// are drawn as without them.
#[test]
fn extreme_embedded_graphics_geometry_is_drawn_or_refused_never_a_panic() {
    use embedded_graphics::geometry::AngleUnit;
    let marker = |c: &mut Canvas<'_, '_, 3, Rgb565>| {
        Circle::new(Point::new(10, 10), 20)
            .into_styled(AaStyle::with_fill(Rgb565::GREEN))
            .draw(c)
    };
    let (want, _) = frame(48, 40, 4, marker);
    let tops = [
        Point::new(0, 0),
        Point::new(i32::MIN, i32::MIN),
        Point::new(i32::MAX, -5),
    ];
    let sizes = [0, 1, u32::MAX / 1024, u32::MAX / 2, u32::MAX - 1, u32::MAX];
    let angles = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::MAX,
        -f32::MAX,
        1e-40,
        0.0,
    ];
    for top in tops {
        for d in sizes {
            for a in angles {
                for b in angles {
                    let (px, _) = frame(48, 40, 4, |c| {
                        let fill = AaStyle::with_fill(Rgb565::WHITE);
                        let stroke = AaStyle::with_stroke(Rgb565::WHITE, 3);
                        let _ = Circle::new(top, d).into_styled(fill).draw(c);
                        let _ = Circle::new(top, d).into_styled(stroke).draw(c);
                        let e = Ellipse::new(top, Size::new(d, d / 3 + 1));
                        let _ = e.into_styled(stroke).draw(c);
                        let arc = Arc::new(top, d, a.rad(), b.rad());
                        let _ = arc.into_styled(stroke).draw(c);
                        let sec = Sector::new(top, d, a.deg(), b.deg());
                        let _ = sec.into_styled(fill).draw(c);
                        let _ = sec.into_styled(stroke).draw(c);
                        let r = RoundedRectangle::with_equal_corners(
                            Rectangle::new(top, Size::new(d, d)),
                            Size::new(d, u32::MAX - d),
                        );
                        let _ = r.into_styled(fill).draw(c);
                        let _ = r.into_styled(stroke).draw(c);
                        // Cover whatever they drew, then the marker.
                        Rectangle::new(Point::zero(), Size::new(48, 40))
                            .into_styled(AaStyle::with_fill(Rgb565::BLACK))
                            .draw(c)?;
                        marker(c)
                    });
                    assert_eq!(px, want, "top {top:?} size {d} angles {a} {b}");
                }
            }
        }
    }
}

/// The SVG path: an arc whose end points are in range but whose
/// curve (radius 6582 px, rotated) reaches ~7750 px out.
const G2_PATH: &str = "M 0 20.648 a 6582 7.831 322 1 1 0 7.831";

/// Draws `d` filled and stroked on a 16 x 16 frame; the report.
fn draw_svg(d: softedge::path::svg::SvgPath<'_>) -> FrameReport {
    frame(16, 16, 4, |c| {
        d.into_styled(AaStyle::with_fill(Rgb565::RED)).draw(c)?;
        d.into_styled(AaStyle::with_stroke(Rgb565::WHITE, 1))
            .draw(c)
    })
    .1
}

/// G2: `SvgPath::new` accepted a path that no band could draw. Now the
/// check sees every point the arc is described with, and refuses it with
/// a typed error naming the arc (at the arc command's byte).
#[test]
fn an_svg_arc_reaching_out_of_range_is_refused_when_checked() {
    use softedge::path::svg::{SvgErrorKind, SvgPath};
    let e = SvgPath::new(G2_PATH).unwrap_err();
    assert_eq!((e.position, e.kind), (11, SvgErrorKind::ArcOutOfRange));
    assert_eq!(
        e.to_string(),
        "path data, byte 11: arc reaching beyond the coordinate range of +-2048 px"
    );
}

/// The documented promise, over a pseudo-random sweep of arcs (radii up
/// to 8192 px, any rotation and flags, ends in range, some near the
/// limit): a path `SvgPath::new` accepts draws with no shape rejected.
/// The reference is the renderer's own report of rejections, which the
/// check must predict; both outcomes occur in the sweep.
#[test]
fn every_checked_svg_path_draws_without_rejection() {
    use softedge::path::svg::{SvgErrorKind, SvgPath};
    let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
    let mut next = |m: u64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed % m
    };
    let (mut ok, mut refused) = (0, 0);
    for _ in 0..600 {
        let mut coord = || next(4096) as i64 - 2048;
        let (x0, y0, x1, y1) = (coord(), coord(), coord(), coord());
        let rx = next(8192);
        let ry = next(8192);
        let rot = next(720);
        let d = format!(
            "M {x0} {y0} A {rx} {ry} {rot} {} {} {x1} {y1} Z",
            next(2),
            next(2)
        );
        match SvgPath::new(&d) {
            Ok(p) => {
                ok += 1;
                assert_eq!(draw_svg(p).skipped.count, 0, "{d}");
            }
            Err(e) => {
                refused += 1;
                assert_eq!(e.kind, SvgErrorKind::ArcOutOfRange, "{d}");
            }
        }
    }
    assert!(ok > 50 && refused > 50, "{ok} accepted, {refused} refused");
}
