//! `three_shapes` in plain embedded-graphics: aliased, and what e-g
//! lacks done by hand (the half-transparent button's colours mixed, the
//! line's round caps as discs). `cargo run --example three_shapes_eg`.
mod support;

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, PrimitiveStyle, Rectangle, RoundedRectangle};
use embedded_graphics_simulator::SimulatorDisplay;

pub fn run() -> Result<SimulatorDisplay<Rgb565>, Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(64, 64));
    display.clear(Rgb565::BLACK)?;
    let disc = Circle::new(Point::new(4, 4), 40);
    disc.into_styled(PrimitiveStyle::with_fill(Rgb565::BLUE))
        .draw(&mut display)?;
    let rect = Rectangle::new(Point::new(8, 36), Size::new(48, 20));
    let button = RoundedRectangle::with_equal_corners(rect, Size::new(6, 6));
    // Half red over black, and over blue where the disc is: mixed by hand.
    button
        .into_styled(PrimitiveStyle::with_fill(Rgb565::new(23, 0, 0)))
        .draw(&mut display)?;
    let over_disc = PrimitiveStyle::with_fill(Rgb565::new(23, 0, 23));
    disc.into_styled(over_disc)
        .draw(&mut display.clipped(&rect))?;
    let line = Line::new(Point::new(2, 61), Point::new(61, 2));
    line.into_styled(PrimitiveStyle::with_stroke(Rgb565::WHITE, 3))
        .draw(&mut display)?;
    let white = PrimitiveStyle::with_fill(Rgb565::WHITE);
    for end in [line.start, line.end] {
        Circle::with_center(end, 3)
            .into_styled(white)
            .draw(&mut display)?;
    }
    Ok(display)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    support::show(&run()?, "three_shapes_eg")
}
