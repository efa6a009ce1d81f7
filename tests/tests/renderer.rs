//! The frame loop: whole frames on any `DrawTarget`, rejected shapes
//! reported with the rest of the frame drawn, closure errors after a
//! whole frame, partial redraws equal to the full frame inside their
//! window, and the README's first example's kind of scene.

use embedded_graphics::pixelcolor::{Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, Rectangle, RoundedRectangle};
use softedge::geom::FinePoint;
use softedge::path;
use softedge::prelude::*;

use softedge_tests::screen::Screen;

const W: u16 = 48;
const H: u16 = 40;
const ROWS: u16 = 6;

/// Renders with fresh buffers.
fn render<F, E>(
    screen: &mut Screen<Rgb565>,
    draw: F,
) -> Result<FrameReport, RenderError<core::convert::Infallible, E>>
where
    F: FnMut(&mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), E>,
{
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut slots = [WalkSlot::<3>::EMPTY; 6];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, ROWS).unwrap();
    let format = Rgb565Format::new(Curve::Srgb);
    r.render(screen, &format, [0; 3], draw)
}

fn scene(c: &mut Canvas<'_, '_, 3, Rgb565>, bad_at: Option<usize>) -> Result<(), DrawError> {
    let shapes = [
        Circle::new(Point::new(2, 2), 20),
        Circle::new(Point::new(26, 4), 18),
        Circle::new(Point::new(10, 20), 18),
    ];
    for (k, s) in shapes.iter().enumerate() {
        if Some(k) == bad_at {
            // Far beyond the coordinate range: rejected.
            let far = path::Circle::new(FinePoint::new(i32::MAX - 5, 0), 4096);
            let _ = far.into_styled(AaStyle::with_fill(Rgb565::WHITE)).draw(c);
        }
        let _ = s.into_styled(AaStyle::with_fill(Rgb565::GREEN)).draw(c);
    }
    Ok(())
}

#[test]
fn a_rejected_shape_is_reported_and_the_rest_of_the_frame_is_drawn() {
    let mut clean = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    let report = render(&mut clean, |c| scene(c, None)).unwrap();
    assert_eq!(report.skipped.count, 0);
    let mut with_bad = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    let report = render(&mut with_bad, |c| scene(c, Some(1))).unwrap();
    assert_eq!(report.skipped.count, 1);
    let (at, why) = report.skipped.first.unwrap();
    assert_eq!(at, 1, "the second shape drawn");
    assert!(
        matches!(
            why,
            DrawError::OutOfRange {
                shape: softedge::ShapeKind::Circle,
                ..
            }
        ),
        "{why:?}"
    );
    // Everything else is there, every pixel sent once per frame.
    assert_eq!(clean.px, with_bad.px);
    assert!(with_bad.px.iter().all(Option::is_some));
    assert_eq!(report.bands, u32::from(H.div_ceil(ROWS)));
}

#[test]
fn a_closure_error_is_reported_after_the_whole_frame() {
    let mut screen = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    let r = render(&mut screen, |c| {
        Circle::new(Point::new(0, 0), 40)
            .into_styled(AaStyle::with_fill(Rgb565::BLUE))
            .draw(c)
            .map_err(|_| "draw")?;
        if c.band().y0 == 12 {
            return Err("band at row 12");
        }
        Ok(())
    });
    assert!(
        matches!(
            r,
            Err(RenderError::Draw {
                band_y0: 12,
                error: "band at row 12"
            })
        ),
        "{r:?}"
    );
    // The frame was sent whole: every band (its drawn columns and the
    // background beside them), every pixel.
    let bands: std::collections::BTreeSet<i32> =
        screen.windows.iter().map(|w| w.top_left.y).collect();
    assert_eq!(bands.len(), usize::from(H.div_ceil(ROWS)));
    assert!(screen.px.iter().all(Option::is_some));
    // The circle is in the bands after the failing one too.
    assert_eq!(screen.at(20, 30), Some(Rgb565::BLUE));
}

#[test]
fn a_window_redraw_equals_the_full_frame_inside_it() {
    let draw = |c: &mut Canvas<'_, '_, 3, Rgb565>| -> Result<(), DrawError> {
        RoundedRectangle::with_equal_corners(
            Rectangle::new(Point::new(3, 5), Size::new(40, 30)),
            Size::new(7, 7),
        )
        .into_styled(AaStyle::with_fill(Rgb565::RED).opacity(Opacity::from_ratio(2, 3).unwrap()))
        .draw(c)?;
        Line::new(Point::new(0, 39), Point::new(47, 0))
            .into_styled(AaStyle::with_stroke(Rgb565::WHITE, 3).cap(LineCap::Round))
            .draw(c)
    };
    let mut full = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    render(&mut full, draw).unwrap();
    let window = Rectangle::new(Point::new(17, 9), Size::new(20, 20));
    let mut part = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut slots = [WalkSlot::<3>::EMPTY; 6];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, ROWS).unwrap();
    let format = Rgb565Format::new(Curve::Srgb);
    r.render_window(&mut part, &format, Rgb565::BLACK, window, draw)
        .unwrap();
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            if window.contains(Point::new(x, y)) {
                assert_eq!(part.at(x, y), full.at(x, y), "({x}, {y})");
            } else {
                assert_eq!(
                    part.at(x, y),
                    None,
                    "({x}, {y}) outside the window was sent"
                );
            }
        }
    }
    // One window per band of the window's rows.
    assert_eq!(part.windows.len(), 20usize.div_ceil(usize::from(ROWS)));
    assert!(part.windows.iter().all(|w| w.size.width == 20));
}

#[test]
fn a_frame_larger_than_the_display_is_refused() {
    let mut small = Screen::<Rgb565>::new(u32::from(W) - 1, u32::from(H));
    let r = render(&mut small, |c| scene(c, None));
    assert!(matches!(r, Err(RenderError::Size { .. })), "{r:?}");
    assert!(small.px.iter().all(Option::is_none));
}

/// The README's kind of scene: anti-aliased, overlapping, half
/// transparent, through embedded-graphics' idioms, on an Rgb565 display;
/// and "#808080" comes out as code 128 of each channel's range.
#[test]
fn an_rgb565_scene_through_the_prelude() {
    let mut screen = Screen::<Rgb565>::new(u32::from(W), u32::from(H));
    render(&mut screen, |c| {
        Rectangle::new(Point::new(0, 0), Size::new(48, 40))
            .into_styled(AaStyle::with_fill(Rgb565::from(Rgb888::new(128, 128, 128))))
            .draw(c)?;
        Circle::new(Point::new(4, 4), 30)
            .into_styled(AaStyle::with_fill(Rgb565::BLUE).opacity(Opacity::from_percent(50)))
            .draw(c)
    })
    .unwrap();
    // Grey 128 in Rgb565 is (16, 32, 16): back out exactly.
    assert_eq!(screen.at(47, 39), Some(Rgb565::new(16, 32, 16)));
    let mid = screen.at(19, 19).unwrap();
    // Half blue over that grey, in linear light: brighter blue than the
    // sRGB average (about 23 of 31), dimmer red and green.
    assert!(mid.b() > 21 && mid.r() < 16 && mid.g() < 32, "{mid:?}");
}
