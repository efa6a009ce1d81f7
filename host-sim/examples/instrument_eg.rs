//! `instrument` in plain embedded-graphics, through the same
//! `mipidsi`-style target: aliased, the gradient as rings, the round
//! caps as discs, e-g's largest built-in font, and the partial redraw as
//! the whole scene drawn clipped to the read-out.
//! `cargo run --example instrument_eg`.
mod support;

use embedded_graphics::mono_font::{ascii::FONT_10X20, MonoTextStyle};
use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, Line, PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Alignment, Text};
use support::Spi240;

const C: Point = Point::new(120, 120);

fn scene<D: DrawTarget<Color = Rgb565>>(d: &mut D, readout: &str) -> Result<(), D::Error> {
    for k in 0..8 {
        let ring = PrimitiveStyle::with_fill(Rgb565::new(1 + k / 2, 3 + k, 2 + k));
        Circle::with_center(C, 221 - 24 * k as u32)
            .into_styled(ring)
            .draw(d)?;
    }
    let sweep = 270.0 * 5200.0 / 8000.0; // 5 200 rpm of 8 000
    let polar = |r: f32, deg: f32| {
        let a = f32::to_radians(deg);
        C + Point::new((r * a.cos()).round() as i32, (r * a.sin()).round() as i32)
    };
    let arc = |sweep: f32| Arc::with_center(C, 181, 135.0.deg(), sweep.deg());
    let track = PrimitiveStyle::with_stroke(Rgb565::new(6, 12, 6), 12);
    let value = PrimitiveStyle::with_stroke(Rgb565::GREEN, 12);
    let needle = PrimitiveStyle::with_stroke(Rgb565::RED, 4);
    let (green, white) = (
        PrimitiveStyle::with_fill(Rgb565::GREEN),
        PrimitiveStyle::with_fill(Rgb565::WHITE),
    );
    arc(270.0).into_styled(track).draw(d)?;
    arc(sweep).into_styled(value).draw(d)?;
    for end in [135.0, 135.0 + sweep] {
        Circle::with_center(polar(90.0, end), 13)
            .into_styled(green)
            .draw(d)?;
    }
    Line::new(C, polar(70.0, 135.0 + sweep))
        .into_styled(needle)
        .draw(d)?;
    Circle::with_center(C, 15).into_styled(white).draw(d)?;
    let big = MonoTextStyle::new(&FONT_10X20, Rgb565::WHITE);
    Text::with_alignment(readout, Point::new(120, 189), big, Alignment::Center).draw(d)?;
    Ok(())
}

pub fn run() -> Result<Spi240, Box<dyn std::error::Error>> {
    let mut display = Spi240::new();
    display.clear(Rgb565::BLACK)?;
    scene(&mut display, "23.5 C")?;
    let area = Rectangle::new(Point::new(60, 160), Size::new(120, 40));
    scene(&mut display.clipped(&area), "23.6 C")?;
    Ok(display)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let display = run()?;
    println!("SPI bytes: {}", display.wire_bytes);
    support::show(&display.frame, "instrument_eg")
}
