//! Issue #34: softedge as a drop-in for embedded-graphics users. A shape
//! the canvas rejects does not blank the frame, whatever the closure does
//! with `?`; errors say pixels and name the shape; bad input is a typed
//! error.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, Rectangle, RoundedRectangle};
use softedge::prelude::*;
use softedge::style::{Gradient, Offset, Stop};
use softedge::ShapeKind;

use softedge_tests::screen::Screen;

const W: u16 = 64;
const H: u16 = 48;
const ROWS: u16 = 8;

/// The frame `draw` gives, with its report (or the render's error).
fn frame<F>(draw: F) -> (Vec<Option<Rgb565>>, Result<FrameReport, String>)
where
    F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError>,
{
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut slots = [WalkSlot::<3>::EMPTY; 4];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, ROWS).unwrap();
    let mut screen = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    let format = Rgb565Format::new(Curve::Srgb);
    let report = r
        .render(&mut screen, &format, Rgb565::BLACK, draw)
        .map_err(|e| e.to_string());
    (screen.px, report)
}

/// Four shapes of the README's kind in order; with `bad = Some(k)`, a
/// shape far out of range (x = 5000, the circle) is drawn before
/// the `k`-th, every call followed by `?`.
fn scene(c: &mut Canvas<'_, '_, 3, Rgb565>, bad: Option<usize>) -> Result<(), DrawError> {
    let g = Gradient::linear(
        FinePoint::from_px(0, 0),
        FinePoint::from_px(0, 48),
        &[
            Stop::new(Offset::ZERO, Rgb565::RED),
            Stop::new(Offset::ONE, Rgb565::BLUE),
        ],
    )
    .unwrap();
    for k in 0..5 {
        if bad == Some(k) {
            match k {
                0 => Circle::new(Point::new(5000, 10), 30)
                    .into_styled(AaStyle::with_fill(Rgb565::WHITE))
                    .draw(c)?,
                1 => Line::new(Point::new(0, 0), Point::new(0, -9000))
                    .into_styled(AaStyle::with_stroke(Rgb565::WHITE, 2))
                    .draw(c)?,
                2 => Rectangle::new(Point::new(-4000, 0), Size::new(10, 10))
                    .into_styled(AaGradient::fill(&g))
                    .draw(c)?,
                _ => RoundedRectangle::with_equal_corners(
                    Rectangle::new(Point::new(3000, 3000), Size::new(10, 10)),
                    Size::new(2, 2),
                )
                .into_styled(AaStyle::with_stroke(Rgb565::WHITE, 1))
                .draw(c)?,
            }
        }
        match k {
            0 => Circle::new(Point::new(4, 4), 36)
                .into_styled(AaStyle::with_fill(Rgb565::BLUE))
                .draw(c)?,
            1 => RoundedRectangle::with_equal_corners(
                Rectangle::new(Point::new(8, 26), Size::new(48, 18)),
                Size::new(6, 6),
            )
            .into_styled(AaStyle::with_fill(Rgb565::RED).opacity(Opacity::from_percent(50)))
            .draw(c)?,
            2 => Rectangle::new(Point::new(40, 2), Size::new(20, 20))
                .into_styled(AaGradient::fill(&g))
                .draw(c)?,
            3 => Line::new(Point::new(2, 45), Point::new(61, 2))
                .into_styled(AaStyle::with_stroke(Rgb565::WHITE, 3).cap(LineCap::Round))
                .draw(c)?,
            _ => {}
        }
    }
    Ok(())
}

/// Issue #34, item 1: one circle at x = 5000 made `render` return
/// `Err(RenderError::Draw)` and every shape after it was skipped in
/// every band (a frame of background), the report lost. Now, for a bad
/// shape at every place in the order, of every kind tried: the frame is
/// the frame without it, bit for bit, `render` is `Ok`, and the report
/// names it (its place, its kind, the point in px).
#[test]
fn a_rejected_shape_leaves_every_other_shape_drawn_whatever_the_closure_does_with_the_question_mark(
) {
    let (clean, report) = frame(|c| scene(c, None));
    let report = report.unwrap();
    assert_eq!(report.skipped.count, 0);
    // Something of every shape is there.
    assert!(clean.iter().filter(|p| **p != Some(Rgb565::BLACK)).count() > 1000);
    // The kind, and a point of the box of what it draws (a stroke's box
    // is widened by its miter reach), near where the shape was put.
    let names = [
        (ShapeKind::Circle, "circle", (5000.0, 10.0)),
        (ShapeKind::Line, "line", (0.0, -9000.0)),
        (ShapeKind::Rectangle, "rectangle", (-4000.0, 0.0)),
        (
            ShapeKind::RoundedRectangle,
            "rounded rectangle",
            (3000.0, 3000.0),
        ),
    ];
    for (k, (kind, name, near)) in names.iter().enumerate() {
        let (px, report) = frame(|c| scene(c, Some(k)));
        let report = report.unwrap_or_else(|e| panic!("bad shape {k}: render failed: {e}"));
        assert_eq!(
            px, clean,
            "bad shape before shape {k}: the other shapes differ"
        );
        assert_eq!(report.skipped.count, 1);
        let (at, why) = report.skipped.first.unwrap();
        // Each of the k shapes before it is one (a fill or a stroke).
        assert_eq!(at, k as u32, "its place in the drawing order");
        match why {
            DrawError::OutOfRange { shape, .. } => assert_eq!(shape, *kind),
            e => panic!("{e:?}"),
        }
        let message = why.to_string();
        let point = message
            .strip_prefix(&format!("{name} reaches ("))
            .and_then(|m| m.strip_suffix(") px, outside ±2048 px"))
            .unwrap_or_else(|| panic!("{message}"));
        let (x, y) = point.split_once(", ").unwrap();
        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        assert!(
            (x - near.0).abs() <= 10.0 && (y - near.1).abs() <= 10.0,
            "{message}"
        );
    }
}
