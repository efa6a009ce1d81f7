//! Issue #34, item 4: a 128x64 SSD1306 frame through the library's page
//! writer (`softedge::render::pages`) in 2-row bands, into a mock I2C
//! interface that decodes the controller's commands into its display
//! RAM, is bit for bit the same frame rendered into the simulator's
//! display; and the RAM it needs in all is at most 4 KiB.

#[path = "../examples/support/mod.rs"]
mod support;

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle};
use embedded_graphics_simulator::SimulatorDisplay;
use softedge::prelude::*;
use softedge::render::pages::{Controller, PageWriter};
use softedge::text::{bundled::SOFTEDGE_SANS, Alignment, Font, FontStyle, Text};
use softedge::tone::profile::DiffusionProfile as Fs;
use support::I2cOled;

const W: u16 = 128;
const H: u16 = 64;

/// A gauge with text: a dithered track, a crisp arc with round caps, a
/// half-transparent disc, crisp and smooth text.
fn scene(c: &mut Canvas<'_, '_, 1, BinaryColor>, font: &Font) -> Result<(), DrawError> {
    let arc = |sweep: f32| Arc::with_center(Point::new(64, 40), 61, 150.0.deg(), sweep.deg());
    let on = AaStyle::with_stroke(BinaryColor::On, 5);
    arc(240.0)
        .into_styled(on.opacity(Opacity::from_percent(33)))
        .draw(c)?;
    arc(170.0)
        .into_styled(on.cap(LineCap::Round).edges(Edges::Crisp))
        .draw(c)?;
    let disc = AaStyle::with_fill(BinaryColor::On).opacity(Opacity::from_percent(60));
    Circle::new(Point::new(100, 2), 22)
        .into_styled(disc)
        .draw(c)?;
    c.set_edges(Edges::Crisp);
    let big = FontStyle::new(font, 22, BinaryColor::On);
    Text::with_alignment("42", FinePoint::from_px(64, 47), big, Alignment::Center).draw(c)?;
    c.set_edges(Edges::Smooth);
    let small = FontStyle::new(font, 10, BinaryColor::On);
    Text::new("km/h 23.5 °C", FinePoint::from_px(2, 62), small).draw(c)?;
    Ok(())
}

/// The frame rendered into `target` in bands of `rows`, Floyd–Steinberg.
fn render<D>(target: &mut D, rows: u16)
where
    D: DrawTarget<Color = BinaryColor> + OriginDimensions,
    D::Error: core::fmt::Debug,
{
    let font = Font::new(SOFTEDGE_SANS).unwrap();
    let mut acc = vec![0; BandBuffer::<1>::acc_len(W, rows)];
    let mut cover = vec![0; BandBuffer::<1>::cover_len(W, rows)];
    let (mut err_row, mut bits) = ([0i16; W as usize], [false; W as usize]);
    let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], W, H, rows).unwrap();
    let mut fs = Fs::new(&mut err_row, &mut bits);
    let report = renderer
        .render(target, &mut fs, BinaryColor::Off, |c| scene(c, &font))
        .unwrap();
    assert_eq!(report.skipped.count, 0);
}

fn simulator(rows: u16) -> SimulatorDisplay<BinaryColor> {
    let mut d = SimulatorDisplay::new(Size::new(u32::from(W), u32::from(H)));
    render(&mut d, rows);
    d
}

#[test]
fn pages_sent_through_the_writer_decode_to_the_simulators_frame() {
    let reference = simulator(8);
    // Every band height gives the same frame (Floyd–Steinberg's error row
    // is carried from band to band).
    assert!(reference.diff(&simulator(2)).is_none());
    let lit = reference
        .bounding_box()
        .points()
        .filter(|p| reference.get_pixel(*p).is_on())
        .count();
    assert!(lit > 600, "{lit} pixels lit");
    for rows in [1, 2, 3, 8] {
        let mut oled = PageWriter::ssd1306_128x64(I2cOled::new());
        render(&mut oled, rows);
        let i2c = oled.release();
        let diff = reference.diff(&i2c.frame());
        assert!(
            diff.is_none(),
            "bands of {rows} rows: the panel differs from the simulator"
        );
        // 8 pages of 128 bytes, each with its commands: no frame buffer
        // was sent twice, nothing more.
        assert_eq!(i2c.wire_bytes, 3 + 8 * (7 + 129), "bands of {rows} rows");
    }
    // The same through an SH1106's page addressing.
    let mut sh = PageWriter::new(I2cOled::new(), Controller::Sh1106, 128, 64).unwrap();
    render(&mut sh, 2);
    let mut ram = sh.release().ram;
    // The mock decodes SSD1306 RAM: the SH1106's pixels are 2 columns on.
    for page in ram.chunks_mut(128) {
        page.rotate_left(2);
    }
    let mut shifted = I2cOled::new();
    shifted.ram = ram;
    assert!(reference.diff(&shifted.frame()).is_none(), "SH1106");
}

/// The RAM a 128x64 mono frame needs in 2-row bands: band buffers,
/// Floyd–Steinberg's rows, the page writer (its page buffer and state,
/// without the bus), the renderer and the profile. Also with the band
/// the lead is moving to (acc 4 + cover 4 + 1 bytes a pixel and 16 bytes
/// a row).
#[test]
fn a_128x64_mono_frame_needs_at_most_4_kib_in_all() {
    use core::mem::size_of;
    let rows = 2;
    let band = 4 * (BandBuffer::<1>::acc_len(W, rows) + BandBuffer::<1>::cover_len(W, rows));
    let band_next = usize::from(rows) * (usize::from(W) * 9 + 16);
    let dither = usize::from(W) * (size_of::<i16>() + size_of::<bool>());
    let writer = size_of::<PageWriter<()>>();
    let state = size_of::<Renderer<'_, 1>>() + size_of::<Fs<'_>>();
    let total = band + dither + writer + state;
    let total_next = band_next + dither + writer + state;
    println!(
        "128x64 mono, 2-row bands: band buffers {band} B, dither rows {dither} B, page writer {writer} B, \
         renderer + profile {state} B: {total} B in all ({total_next} B with the next band layout, {band_next} B of band)"
    );
    assert!(
        total <= 4096 && total_next <= 4096,
        "{total} / {total_next}"
    );
    // No frame buffer among them (a buffered driver's 1 KiB).
}

/// A small disc in the middle of the panel, ordered dither (black the
/// same everywhere, so a band's background could go beside its drawn
/// columns): the writer still gets whole rows of pages (a 1-bit display
/// packs rows into bytes) and the panel shows the simulator's frame.
#[test]
fn a_small_shape_in_the_middle_still_sends_whole_pages() {
    fn draw<D>(target: &mut D, rows: u16)
    where
        D: DrawTarget<Color = BinaryColor> + OriginDimensions,
        D::Error: core::fmt::Debug,
    {
        let mut acc = vec![0; BandBuffer::<1>::acc_len(W, rows)];
        let mut cover = vec![0; BandBuffer::<1>::cover_len(W, rows)];
        let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], W, H, rows).unwrap();
        let disc = AaStyle::with_fill(BinaryColor::On).opacity(Opacity::from_percent(50));
        renderer
            .render(
                target,
                softedge::tone::Bayer8::new(),
                BinaryColor::Off,
                |c| {
                    Circle::with_center(Point::new(64, 30), 15)
                        .into_styled(disc)
                        .draw(c)
                },
            )
            .unwrap();
    }
    let mut reference = SimulatorDisplay::new(Size::new(u32::from(W), u32::from(H)));
    draw(&mut reference, 8);
    for rows in [2, 8] {
        let mut oled = PageWriter::ssd1306_128x64(I2cOled::new());
        draw(&mut oled, rows);
        let i2c = oled.release();
        assert!(
            reference.diff(&i2c.frame()).is_none(),
            "bands of {rows} rows"
        );
    }
}
