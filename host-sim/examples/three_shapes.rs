//! The README's first program: a disc, a half-transparent button and a
//! 3-px line with round caps on a 64x64 Rgb565 display, anti-aliased.
//! `cargo run --example three_shapes` (its embedded-graphics twin:
//! `three_shapes_eg`).
mod support;

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, Rectangle, RoundedRectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use softedge::prelude::*;

pub fn run() -> Result<SimulatorDisplay<Rgb565>, Box<dyn std::error::Error>> {
    let mut display = SimulatorDisplay::<Rgb565>::new(Size::new(64, 64));
    let mut acc = [0; BandBuffer::<3>::acc_len(64, 8)];
    let mut cover = [0; BandBuffer::<3>::cover_len(64, 8)];
    let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 64, 64, 8)?;
    let rect = Rectangle::new(Point::new(8, 36), Size::new(48, 20));
    let half_red = AaStyle::with_fill(Rgb565::RED).opacity(Opacity::from_percent(50));
    let rgb565 = Rgb565Format::new(Curve::Srgb);
    renderer.render(&mut display, &rgb565, Rgb565::BLACK, |canvas| {
        Circle::new(Point::new(4, 4), 40)
            .into_styled(AaStyle::with_fill(Rgb565::BLUE))
            .draw(canvas)?;
        let button = RoundedRectangle::with_equal_corners(rect, Size::new(6, 6));
        button.into_styled(half_red).draw(canvas)?;
        let line = Line::new(Point::new(2, 61), Point::new(61, 2));
        line.into_styled(AaStyle::with_stroke(Rgb565::WHITE, 3).cap(LineCap::Round))
            .draw(canvas)
    })?;
    Ok(display)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    support::show(&run()?, "three_shapes")
}
