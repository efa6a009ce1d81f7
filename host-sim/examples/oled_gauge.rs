//! A 128x64 SSD1306 gauge with text, on I2C without a frame buffer: the
//! library's page writer takes the renderer's 2-row bands, packs them
//! into pages and sends each page as it is complete. A translucent
//! track (dithered), a crisp value arc with round caps and crisp text
//! (`Edges::Crisp`). `cargo run --example oled_gauge` (its
//! embedded-graphics twin: `oled_gauge_eg`).
mod support;

use embedded_graphics::pixelcolor::BinaryColor::{self, On};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Arc;
use softedge::prelude::*;
use softedge::render::pages::PageWriter;
use softedge::text::{bundled::SOFTEDGE_SANS, Alignment, Font, FontStyle, Text};
use support::I2cOled;

pub fn run() -> Result<I2cOled, Box<dyn std::error::Error>> {
    let mut oled = PageWriter::ssd1306_128x64(I2cOled::new()); // after ssd1306's init
    let font = Font::new(SOFTEDGE_SANS)?;
    // Bands of 2 rows: bands, dither rows and page buffer in 2.7 KiB.
    let mut acc = [0; BandBuffer::<1>::acc_len(128, 2)];
    let mut cover = [0; BandBuffer::<1>::cover_len(128, 2)];
    let (mut err_row, mut bits) = ([0i16; 128], [false; 128]);
    let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 128, 64, 2)?;
    let mut fs = DiffusionProfile::new(&mut err_row, &mut bits);
    let arc = |sweep: f32| Arc::with_center(Point::new(64, 40), 61, 150.0.deg(), sweep.deg());
    let on = AaStyle::with_stroke(BinaryColor::On, 5);
    let track = on.opacity(Opacity::from_percent(33));
    let value = on.cap(LineCap::Round).edges(Edges::Crisp);
    let (big, unit) = (FontStyle::new(&font, 22, On), FontStyle::new(&font, 10, On));
    renderer.render(&mut oled, &mut fs, BinaryColor::Off, |c| {
        arc(240.0).into_styled(track).draw(c)?;
        c.set_edges(Edges::Crisp);
        Text::with_alignment("42", FinePoint::from_px(64, 47), big, Alignment::Center).draw(c)?;
        Text::with_alignment("km/h", FinePoint::from_px(64, 61), unit, Alignment::Center)
            .draw(c)?;
        arc(150.0).into_styled(value).draw(c)
    })?;
    Ok(oled.release())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let i2c = run()?;
    println!("I2C bytes: {}", i2c.wire_bytes);
    support::show(&i2c.frame(), "oled_gauge")
}
