//! A 240x240 instrument screen on an ST7789 through a `mipidsi`-style
//! `DrawTarget` (one window per `fill_contiguous`): a gradient dial, an
//! arc gauge with round caps, a needle and text, then a partial redraw
//! of the read-out. `cargo run --example instrument` (its
//! embedded-graphics twin: `instrument_eg`).
mod support;

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, Line, Rectangle};
use softedge::prelude::*;
use softedge::style::{Gradient, Offset, Stop};
use softedge::text::{bundled::SOFTEDGE_SANS, Alignment, Font, FontStyle, Text};
use support::Spi240;

const C: Point = Point::new(120, 120);

pub fn run() -> Result<Spi240, Box<dyn std::error::Error>> {
    let mut display = Spi240::new();
    let font = Font::new(SOFTEDGE_SANS)?;
    let (top, rim) = (Rgb565::new(6, 14, 10), Rgb565::new(1, 3, 2));
    let stops = [Stop::new(Offset::ZERO, top), Stop::new(Offset::ONE, rim)];
    let face = Gradient::radial(FinePoint::from_px(120, 80), 140 * 1024, &stops)?;
    let sweep = 270.0 * 5200.0 / 8000.0; // 5 200 rpm of 8 000
    let a = f32::to_radians(135.0 + sweep);
    let tip = C + Point::new((70.0 * a.cos()) as i32, (70.0 * a.sin()) as i32);
    let arc = |sweep: f32| Arc::with_center(C, 181, 135.0.deg(), sweep.deg());
    let track = AaStyle::with_stroke(Rgb565::new(6, 12, 6), 12);
    let value = AaStyle::with_stroke(Rgb565::GREEN, 12).cap(LineCap::Round);
    let needle = AaStyle::with_stroke(Rgb565::RED, 4).cap(LineCap::Round);
    let (dial, white) = (AaGradient::fill(&face), AaStyle::with_fill(Rgb565::WHITE));
    let scene = |c: &mut Canvas<'_, '_, 3, Rgb565>, readout| {
        Circle::with_center(C, 221).into_styled(dial).draw(c)?;
        arc(270.0).into_styled(track).draw(c)?;
        arc(sweep).into_styled(value).draw(c)?;
        Line::new(C, tip).into_styled(needle).draw(c)?;
        Circle::with_center(C, 15).into_styled(white).draw(c)?;
        let (at, big) = (
            FinePoint::from_px(120, 190),
            FontStyle::new(&font, 28, Rgb565::WHITE),
        );
        Text::with_alignment(readout, at, big, Alignment::Center).draw(c)?;
        Ok::<_, DrawError>(())
    };
    let mut acc = [0; BandBuffer::<3>::acc_len(240, 8)];
    let mut cover = [0; BandBuffer::<3>::cover_len(240, 8)];
    let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 240, 240, 8)?;
    let (p, bg) = (Rgb565Format::new(Curve::Srgb), Rgb565::BLACK);
    renderer.render(&mut display, &p, bg, |c| scene(c, "23.5 °C"))?;
    let area = Rectangle::new(Point::new(60, 160), Size::new(120, 40));
    renderer.render_window(&mut display, &p, bg, area, |c| scene(c, "23.6 °C"))?;
    Ok(display)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let display = run()?;
    println!("SPI bytes: {}", display.wire_bytes);
    support::show(&display.frame, "instrument")
}
