//! softedge on a Raspberry Pi Pico (RP2040) with an ST7789 240x240 SPI TFT.
//!
//! Shows an animated instrument panel (`ui.rs`): a dial with ticks and a
//! moving needle, an arc gauge, a readout on a translucent panel and a
//! rounded button, anti-aliased in painter's order. `softedge`'s
//! [`Renderer`] draws it band by band (40 rows) into static buffers, tones
//! each band through the sRGB tables of [`Rgb565Format`] and sends it to
//! the `mipidsi` driver in one `fill_contiguous`: the firmware has no band
//! loop and no frame buffer.
//!
//! The first frame is sent whole; after it, only the rectangles the
//! needle, the gauge and the readout can have changed
//! ([`Panel::dirty`](ui::Panel::dirty)), each with
//! [`Renderer::render_window`].
//!
//! Logs over defmt (RTT), one `info` line per frame: the rectangles sent,
//! their pixels, the bytes that went over SPI (pixels and each band's
//! window set-up) against a whole frame's, and the time; `debug` adds the
//! walk cache's hits and misses.
//!
//! ## Wiring (Pico pin numbers are GPIO numbers)
//!
//! | ST7789 module | Pico         | notes                                      |
//! | ------------- | ------------ | ------------------------------------------ |
//! | GND           | GND          |                                            |
//! | VCC           | 3V3(OUT)     | 3.3 V only                                 |
//! | SCL / SCK     | GP18         | SPI0 SCK                                   |
//! | SDA / MOSI    | GP19         | SPI0 TX                                    |
//! | CS            | GP17         | driven as a GPIO (modules without CS: leave unconnected) |
//! | DC / RS       | GP16         | data/command                               |
//! | RES / RST     | GP20         | hardware reset                             |
//! | BLK / BL      | GP21         | backlight, driven high                     |
//!
//! SPI mode 3 (works for modules with and without a CS pin) at 62.5 MHz
//! (clk_peri / 2); lower `SPI_HZ` for long jumper wires.

#![no_std]
#![no_main]

mod ui;

use defmt_rtt as _;
use panic_probe as _;

use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use embedded_hal::digital::OutputPin;
use embedded_hal_bus::spi::ExclusiveDevice;
use mipidsi::interface::SpiInterface;
use mipidsi::models::ST7789;
use mipidsi::options::ColorInversion;
use rp2040_hal as hal;

use hal::clocks::Clock;
use hal::fugit::RateExtU32;
use hal::gpio::FunctionSpi;
use hal::pac;

use softedge::canvas::ShapeEntry;
use softedge::path::Segment;
use softedge::prelude::*;

use ui::Panel;

/// The second-stage bootloader for the Pico's W25Q080 flash, at the start of
/// flash (see `memory.x`).
#[link_section = ".boot2"]
#[used]
pub static BOOT2: [u8; 256] = rp2040_boot2::BOOT_LOADER_W25Q080;

/// The Pico's crystal.
const XTAL_FREQ_HZ: u32 = 12_000_000;
/// SPI clock to the panel.
const SPI_HZ: u32 = 62_500_000;

/// Panel size.
const W: u16 = 240;
const H: u16 = 240;
/// Rows per band. Per band, every shape that reaches it is described
/// again (its curves' vertices computed where they meet the band) and its
/// edges there set up or resumed, and on the Cortex-M0 that, more than
/// the pixels, is what a frame costs: without the shape cache (below)
/// this panel costs 27.1 M instructions a whole frame in 16-row bands and
/// 20.2 M in 40-row ones, a partial redraw 8.6 M and 6.3 M; with it 16.4 M
/// and 14.4 M, 5.7 M and 4.9 M (`bench-m0`, boards/README.md). 40 rows
/// divide the panel into 6 bands; their buffers take 154 240 bytes, 58 %
/// of the RP2040's 264 KiB (the shape cache 36 864 more).
const BAND_ROWS: u16 = 40;
/// `i32`s of the accumulation buffer: 240 x 40 pixels x 3 channels.
const ACC_LEN: usize = BandBuffer::<3>::acc_len(W, BAND_ROWS);
/// `i32`s of the coverage scratch: (240 + 4) x 40.
const COVER_LEN: usize = BandBuffer::<3>::cover_len(W, BAND_ROWS);
/// Walk-cache slots: an edge that goes on below a band can keep its walk
/// in one, so that the next band resumes it instead of setting it up
/// again. This panel's edges are short (flattened curves): a whole frame
/// has 44 that cross a band boundary, and on the Cortex-M0 16 slots
/// changed a frame by under 0.2 % (a little slower, the look-ups cost
/// what the saved set-ups did), so it runs without; each slot is
/// `WalkSlot::<3>::SIZE` = 368 bytes. Scenes of long edges (large
/// triangles, Gouraud meshes, whose planes are cached too) gain more.
const SLOTS: usize = 0;

/// The shape cache (`Renderer::with_shape_cache`): the panel's circles,
/// ticks, needle and rounded rectangles are described once into it and
/// filled from it in every later band and frame (the gauge's ring polygons
/// and the text are drawn directly). Their outlines hold 2 132 segments in
/// 32 entries (`boards/bench-m0`: `panel_shape_cache`), and each new
/// needle takes the room of an old one; 16 bytes a segment (36 KiB),
/// `ShapeEntry::SIZE` (about 100) an entry. On the Cortex-M0 it takes a
/// whole frame in 40-row bands from 20.24 M to 14.44 M instructions and a
/// partial redraw from 6.33 M to 4.94 M on average.
const CACHE_SEGMENTS: usize = 2304;
const CACHE_ENTRIES: usize = 40;

/// Bytes mipidsi sends to open each window (each band of a rectangle):
/// CASET and RASET (a command byte and four parameter bytes each) and
/// RAMWR (a command byte).
const WINDOW_SETUP_BYTES: u32 = (1 + 4) + (1 + 4) + 1;

/// Linear 12-bit → Rgb565 through the sRGB transfer curve; the 5- and 6-bit
/// tables are computed at compile time and live in flash.
static TONE: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// What went over SPI in one frame.
#[derive(Debug, Default, Clone, Copy)]
struct Sent {
    rects: u32,
    pixels: u32,
    bytes: u32,
}

impl Sent {
    /// Counts `area` (clipped to the panel, as the renderer clips it) sent
    /// in `bands` bands.
    fn add(&mut self, area: Rectangle, bands: u32) {
        let frame = Rectangle::new(Point::zero(), Size::new(W.into(), H.into()));
        let a = area.intersection(&frame).size;
        let pixels = a.width * a.height;
        self.rects += 1;
        self.pixels += pixels;
        // Rgb565: two bytes a pixel.
        self.bytes += 2 * pixels + bands * WINDOW_SETUP_BYTES;
    }
}

/// Logs a frame's failure (the SPI error's type has no defmt formatting:
/// only that it happened is logged). Returns the report of a frame that
/// was drawn and sent whole.
fn check<T>(
    frame: u32,
    result: Result<FrameReport, RenderError<T, DrawError>>,
) -> Option<FrameReport> {
    match result {
        Ok(report) => {
            if report.skipped.count > 0 {
                defmt::warn!("frame {}: shapes skipped: {}", frame, report.skipped);
            }
            return Some(report);
        }
        Err(RenderError::Target(_)) => defmt::error!("frame {}: SPI write failed", frame),
        Err(RenderError::Draw { band_y0, error }) => {
            defmt::error!("frame {}: band at row {}: {}", frame, band_y0, error)
        }
        Err(RenderError::Band(e)) => defmt::error!("frame {}: {}", frame, e),
        Err(RenderError::Size {
            frame: f,
            display: d,
        }) => {
            defmt::error!("frame {}: frame {} larger than panel {}", frame, f, d)
        }
        Err(_) => defmt::error!("frame {}: not rendered", frame),
    }
    None
}

#[hal::entry]
fn main() -> ! {
    // The band buffers, in .bss: cortex-m-rt hands each `static mut` at
    // the top of the entry function to it as a `&'static mut`, safely
    // (the entry function runs once).
    static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
    static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];
    // All zero bits: in .bss too.
    static mut SEGMENTS: [Segment; CACHE_SEGMENTS] = [Segment::ZERO; CACHE_SEGMENTS];

    let Some(mut pac) = pac::Peripherals::take() else {
        defmt::panic!("peripherals taken twice");
    };
    let mut watchdog = hal::Watchdog::new(pac.WATCHDOG);
    let Ok(clocks) = hal::clocks::init_clocks_and_plls(
        XTAL_FREQ_HZ,
        pac.XOSC,
        pac.CLOCKS,
        pac.PLL_SYS,
        pac.PLL_USB,
        &mut pac.RESETS,
        &mut watchdog,
    ) else {
        defmt::panic!("clock setup failed");
    };
    let mut timer = hal::Timer::new(pac.TIMER, &mut pac.RESETS, &clocks);
    let sio = hal::Sio::new(pac.SIO);
    let pins = hal::gpio::Pins::new(
        pac.IO_BANK0,
        pac.PADS_BANK0,
        sio.gpio_bank0,
        &mut pac.RESETS,
    );

    // SPI0 on GP18 (SCK) / GP19 (MOSI); CS, DC, RST, BL as plain outputs.
    let sck = pins.gpio18.into_function::<FunctionSpi>();
    let mosi = pins.gpio19.into_function::<FunctionSpi>();
    let spi_bus = hal::Spi::<_, _, _, 8>::new(pac.SPI0, (mosi, sck)).init(
        &mut pac.RESETS,
        clocks.peripheral_clock.freq(),
        SPI_HZ.Hz(),
        embedded_hal::spi::MODE_3,
    );
    let cs = pins.gpio17.into_push_pull_output();
    let dc = pins.gpio16.into_push_pull_output();
    let rst = pins.gpio20.into_push_pull_output();
    let mut backlight = pins.gpio21.into_push_pull_output();

    // Setting an RP2040 GPIO cannot fail: the error type is `Infallible`.
    let Ok(spi) = ExclusiveDevice::new_no_delay(spi_bus, cs);
    // mipidsi gathers pixels into this buffer before each SPI write.
    let mut spi_buf = [0u8; 512];
    let di = SpiInterface::new(spi, dc, &mut spi_buf);
    // Most 240x240 ST7789 modules need colour inversion on to show true colours.
    let Ok(mut display) = mipidsi::Builder::new(ST7789, di)
        .display_size(W, H)
        .invert_colors(ColorInversion::Inverted)
        .reset_pin(rst)
        .init(&mut timer)
    else {
        defmt::panic!("display init failed");
    };
    let _ = backlight.set_high();

    // Walk-cache slots on the stack (`WalkSlot::EMPTY` is not all zero
    // bits: as a static they would be copied from flash at start-up).
    let mut slots = [WalkSlot::<3>::EMPTY; SLOTS];
    defmt::info!(
        "softedge rp2040-st7789: {}x{}, bands of {} rows: band buffers {} bytes, walk cache {} bytes",
        W,
        H,
        BAND_ROWS,
        4 * (ACC_LEN + COVER_LEN),
        SLOTS * WalkSlot::<3>::SIZE
    );
    // The shape cache's entries on the stack (`ShapeEntry::EMPTY` is not
    // all zero bits either).
    let mut entries = [ShapeEntry::EMPTY; CACHE_ENTRIES];
    defmt::info!(
        "shape cache {} bytes",
        CACHE_SEGMENTS * core::mem::size_of::<Segment>() + CACHE_ENTRIES * ShapeEntry::SIZE
    );
    let mut renderer = match Renderer::new(ACC, COVER, &mut slots, W, H, BAND_ROWS) {
        Ok(r) => r.with_shape_cache(SEGMENTS, &mut entries),
        Err(e) => defmt::panic!("band buffers too small: {}", e),
    };
    let whole = Rectangle::new(Point::zero(), Size::new(W.into(), H.into()));

    // What the panel shows; `None` until a frame has been sent whole (and
    // again after any failure, so that the next frame repairs it).
    let mut shown: Option<Panel> = None;
    let mut frame: u32 = 0;
    loop {
        let panel = Panel::at(frame);
        let t0 = timer.get_counter();
        let mut sent = Sent::default();
        let mut ok = true;
        match shown {
            None => {
                let r = renderer.render(&mut display, &TONE, ui::BACKGROUND, |c| panel.draw(c));
                match check(frame, r) {
                    Some(report) => sent.add(whole, report.bands),
                    None => ok = false,
                }
            }
            Some(before) => {
                for area in before.dirty(&panel).rects() {
                    let r =
                        renderer.render_window(&mut display, &TONE, ui::BACKGROUND, area, |c| {
                            panel.draw(c)
                        });
                    match check(frame, r) {
                        Some(report) => sent.add(area, report.bands),
                        None => ok = false,
                    }
                }
            }
        }
        let us = (timer.get_counter() - t0).to_micros();
        shown = ok.then_some(panel);
        // A whole frame: every pixel, and one window per band.
        let whole_bytes =
            2 * u32::from(W) * u32::from(H) + u32::from(H.div_ceil(BAND_ROWS)) * WINDOW_SETUP_BYTES;
        defmt::info!(
            "frame {}: {} rects, {} px, {} of {} bytes over SPI, {} us",
            frame,
            sent.rects,
            sent.pixels,
            sent.bytes,
            whole_bytes,
            us
        );
        let (hits, misses) = renderer.cache_stats();
        defmt::debug!("walk cache: {} hits, {} without a slot", hits, misses);
        frame = frame.wrapping_add(1);
    }
}
