//! The RP2040 firmware's panel (`boards/rp2040-st7789/src/ui.rs`, compiled
//! here unchanged) as the firmware sends it: a whole frame, then per frame
//! only the rectangles a change can touch (`render_window`), through a
//! renderer with a shape cache of the firmware's size. Every frame must equal
//! the same state rendered whole without a cache, pixel for pixel: the
//! cache keeps the dial's circles, ticks and rounded rectangles from frame
//! to frame and describes the needle anew whenever it moves.

#[allow(dead_code)]
#[path = "../../boards/rp2040-st7789/src/ui.rs"]
mod ui;

use embedded_graphics::pixelcolor::{IntoStorage, Rgb565};
use embedded_graphics::prelude::*;
use softedge::canvas::ShapeEntry;
use softedge::path::Segment;
use softedge::prelude::*;
use softedge::render::Renderer;
use softedge::tone::Curve;

const W: u16 = 240;
const ROWS: u16 = 40;

struct Screen(Vec<u16>);

impl OriginDimensions for Screen {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(W))
    }
}

impl DrawTarget for Screen {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            if let Some(v) = self.0.get_mut(p.y as usize * usize::from(W) + p.x as usize) {
                *v = c.into_storage();
            }
        }
        Ok(())
    }
}

fn whole(panel: &ui::Panel) -> Vec<u16> {
    let mut acc = vec![0; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut [], W, W, ROWS).unwrap();
    let mut s = Screen(vec![0; usize::from(W) * usize::from(W)]);
    let tone = Rgb565Format::new(Curve::Srgb);
    r.render(&mut s, &tone, ui::BACKGROUND, |c| panel.draw(c))
        .unwrap();
    s.0
}

#[test]
fn partial_redraws_through_a_shape_cache_equal_whole_frames() {
    let mut acc = vec![0; BandBuffer::<3>::acc_len(W, ROWS)];
    let mut cover = vec![0; BandBuffer::<3>::cover_len(W, ROWS)];
    let mut segments = vec![Segment::default(); 2304];
    let mut entries = vec![ShapeEntry::EMPTY; 40];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut [], W, W, ROWS)
        .unwrap()
        .with_shape_cache(&mut segments, &mut entries);
    let tone = Rgb565Format::new(Curve::Srgb);
    let mut s = Screen(vec![0; usize::from(W) * usize::from(W)]);
    let mut shown = ui::Panel::at(0);
    r.render(&mut s, &tone, ui::BACKGROUND, |c| shown.draw(c))
        .unwrap();
    assert!(s.0 == whole(&shown));
    // The first frame describes the shapes with a key that are not walked
    // from their circles' exact areas (27 outlines, the gauge's two ring
    // polygons among them; discs, rings and solid arcs are walked, and
    // are not kept) and draws the rest (text) directly; the firmware's
    // cache holds them all.
    assert_eq!(r.shape_stats().1, 27);
    let mut kept = 0;
    // Every frame for a while, then a stride through the animation.
    for frame in (1..40).chain((40..3000).step_by(97)) {
        let next = ui::Panel::at(frame);
        for area in shown.dirty(&next).rects() {
            r.render_window(&mut s, &tone, ui::BACKGROUND, area, |c| next.draw(c))
                .unwrap();
            kept += r.shape_stats().0;
        }
        shown = next;
        assert!(s.0 == whole(&shown), "frame {frame}");
    }
    assert!(kept > 1000, "{kept}");
}
