//! `oled_gauge` in plain embedded-graphics through `ssd1306`'s buffered
//! mode (a 1 KiB frame buffer, flushed whole): aliased, the translucent
//! track as a 1-px arc, the round caps as discs, e-g's fonts.
//! `cargo run --example oled_gauge_eg`.
mod support;

use embedded_graphics::mono_font::ascii::{FONT_10X20, FONT_6X10};
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle, PrimitiveStyle};
use embedded_graphics::text::{Alignment, Text};
use support::{BufferedOled, I2cOled};

const C: Point = Point::new(64, 40);

pub fn run() -> Result<I2cOled, Box<dyn std::error::Error>> {
    let mut oled = BufferedOled::new(I2cOled::new()); // after ssd1306's init
    oled.clear(BinaryColor::Off)?;
    let arc = |sweep: f32| Arc::with_center(C, 61, 150.0.deg(), sweep.deg());
    let thin = PrimitiveStyle::with_stroke(BinaryColor::On, 1);
    arc(240.0).into_styled(thin).draw(&mut oled)?;
    let thick = PrimitiveStyle::with_stroke(BinaryColor::On, 5);
    arc(150.0).into_styled(thick).draw(&mut oled)?;
    let dot = PrimitiveStyle::with_fill(BinaryColor::On);
    for deg in [150.0f32, 300.0] {
        let (s, c) = deg.to_radians().sin_cos();
        let end = C + Point::new((28.0 * c).round() as i32, (28.0 * s).round() as i32);
        Circle::with_center(end, 5)
            .into_styled(dot)
            .draw(&mut oled)?;
    }
    let big = MonoTextStyle::new(&FONT_10X20, BinaryColor::On);
    let small = MonoTextStyle::new(&FONT_6X10, BinaryColor::On);
    Text::with_alignment("42", Point::new(64, 46), big, Alignment::Center).draw(&mut oled)?;
    Text::with_alignment("km/h", Point::new(64, 60), small, Alignment::Center).draw(&mut oled)?;
    oled.flush().map_err(|e| format!("{e:?}"))?;
    Ok(oled.interface)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let i2c = run()?;
    println!("I2C bytes: {}", i2c.wire_bytes);
    support::show(&i2c.frame(), "oled_gauge_eg")
}
