//! softedge on an ESP32-C3 with an SSD1306 128x64 I2C OLED (1 bit per pixel).
//!
//! Shows an animated panel (`ui.rs`): a dial with a moving needle, an arc
//! gauge with its value in text, and the ditherer's name. `softedge`'s
//! [`Renderer`] draws it in bands of 8 rows, one SSD1306 page each,
//! dithers every band to 1 bit in linear light — Floyd–Steinberg
//! ([`DiffusionProfile`], its error row carried from band to band) and the
//! 8x8 Bayer matrix ([`Bayer8`]) alternate every 100 frames — and sends
//! each band with one `fill_contiguous` to the library's
//! [`PageWriter`](softedge::render::pages::PageWriter), which packs the
//! bands into its one 128-byte page buffer and sends each page over I2C
//! when its last row arrives. No band loop here, no frame buffer anywhere.
//!
//! Logs one line per frame over the USB serial/JTAG port (or UART0):
//! frame number, microseconds for the frame (drawing, dithering and the
//! I2C writes, which the renderer interleaves band by band), ditherer.
//!
//! ## Wiring
//!
//! | SSD1306 module | ESP32-C3 | notes                                  |
//! | -------------- | -------- | -------------------------------------- |
//! | GND            | GND      |                                        |
//! | VCC            | 3V3      |                                        |
//! | SDA            | GPIO5    | I2C0 SDA (any free GPIO works: change `peripherals.GPIO5`) |
//! | SCL            | GPIO6    | I2C0 SCL                               |
//!
//! I2C at 400 kHz, address 0x3C (modules strapped to 0x3D: use
//! `I2CDisplayInterface::new_alternate_address`). Most modules carry the
//! pull-up resistors; bare panels need 4.7 kΩ to 3V3 on SDA and SCL.

#![no_std]
#![no_main]

mod ui;

use esp_backtrace as _;

use embedded_graphics::pixelcolor::BinaryColor;
use esp_hal::clock::CpuClock;
use esp_hal::i2c::master::{Config as I2cConfig, I2c};
use esp_hal::time::{Instant, Rate};
use esp_println::println;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306};
use static_cell::ConstStaticCell;

use softedge::prelude::*;
use softedge::render::pages::PageWriter;

use ui::Panel;

// The application descriptor Espressif's second-stage bootloader checks.
esp_bootloader_esp_idf::esp_app_desc!();

/// Panel size.
const W: u16 = 128;
const H: u16 = 64;
/// Rows per band: 2. The page writer gathers 4 bands into a page; the
/// band buffers are a quarter of 8-row bands' (2 080 bytes, not 8 256).
const BAND_ROWS: u16 = 2;
const ACC_LEN: usize = BandBuffer::<1>::acc_len(W, BAND_ROWS);
const COVER_LEN: usize = BandBuffer::<1>::cover_len(W, BAND_ROWS);
/// Walk-cache slots: none. This panel's edges are short (flattened
/// curves), so few go on from one band to the next; see the RP2040
/// firmware, where 16 slots changed a frame by under 0.2 %. Each slot is
/// `WalkSlot::<1>::SIZE` bytes.
const SLOTS: usize = 0;

/// The band buffers (`4 * (ACC_LEN + COVER_LEN)` = 2 080 bytes), and
/// Floyd–Steinberg's rows (an `i16` error and a result per column, 384
/// bytes): all zeros, in .bss, each handed out once.
static ACC: ConstStaticCell<[i32; ACC_LEN]> = ConstStaticCell::new([0; ACC_LEN]);
static COVER: ConstStaticCell<[i32; COVER_LEN]> = ConstStaticCell::new([0; COVER_LEN]);
static ERR_ROW: ConstStaticCell<[i16; W as usize]> = ConstStaticCell::new([0; W as usize]);
static BITS: ConstStaticCell<[bool; W as usize]> = ConstStaticCell::new([false; W as usize]);

/// Frames between switches of the ditherer.
const DITHER_PERIOD: u32 = 100;

#[esp_hal::main]
fn main() -> ! {
    let peripherals = esp_hal::init(esp_hal::Config::default().with_cpu_clock(CpuClock::max()));

    let i2c = match I2c::new(
        peripherals.I2C0,
        I2cConfig::default().with_frequency(Rate::from_khz(400)),
    ) {
        Ok(i2c) => i2c.with_sda(peripherals.GPIO5).with_scl(peripherals.GPIO6),
        Err(e) => panic!("I2C config: {:?}", e),
    };
    let interface = I2CDisplayInterface::new(i2c);
    let mut display = Ssd1306::new(interface, DisplaySize128x64, DisplayRotation::Rotate0);
    if let Err(e) = display.init() {
        panic!("SSD1306 init (wiring? address?): {:?}", e);
    }
    // The driver has powered and set up the panel; its interface goes to
    // the page writer (SSD1306 commands: column and page ranges).
    let mut oled = PageWriter::ssd1306_128x64(display.release());

    let (Some(acc), Some(cover), Some(err_row), Some(bits)) = (
        ACC.try_take(),
        COVER.try_take(),
        ERR_ROW.try_take(),
        BITS.try_take(),
    ) else {
        panic!("buffers taken twice");
    };
    let mut slots = [WalkSlot::<1>::EMPTY; SLOTS];
    let mut renderer = match Renderer::new(acc, cover, &mut slots, W, H, BAND_ROWS) {
        Ok(r) => r,
        Err(e) => panic!("band buffers too small: {}", e),
    };
    let mut diffusion = DiffusionProfile::new(err_row, bits);
    let mut bayer = Bayer8::new();
    println!(
        "softedge esp32c3-ssd1306: {}x{}, bands of {} rows, band buffers {} bytes",
        W,
        H,
        BAND_ROWS,
        4 * (ACC_LEN + COVER_LEN)
    );

    let mut frame: u32 = 0;
    loop {
        let floyd_steinberg = (frame / DITHER_PERIOD).is_multiple_of(2);
        let label = if floyd_steinberg { "F-S" } else { "BAYER" };
        let panel = Panel::at(frame, label);
        let t0 = Instant::now();
        let result = if floyd_steinberg {
            renderer.render(&mut oled, &mut diffusion, BinaryColor::Off, |c| {
                panel.draw(c)
            })
        } else {
            renderer.render(&mut oled, &mut bayer, BinaryColor::Off, |c| panel.draw(c))
        };
        let us = t0.elapsed().as_micros();
        match result {
            Ok(report) if report.skipped.count > 0 => {
                println!("frame {}: shapes skipped: {:?}", frame, report.skipped)
            }
            Ok(_) => println!("frame {} in {} us, {}", frame, us, label),
            Err(e) => println!("frame {}: {}", frame, e),
        }
        frame = frame.wrapping_add(1);
    }
}
