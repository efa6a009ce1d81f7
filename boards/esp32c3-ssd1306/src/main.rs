//! softedge on an ESP32-C3 with an SSD1306 128x64 I2C OLED (1 bit per pixel).
//!
//! Renders an animated gray scene — a rotating fan of Gouraud triangles, a
//! counter-rotating star of anti-aliased lines, and a linear black-to-white
//! ramp along the bottom — band by band, 8 rows at a time: one band is one
//! SSD1306 page, so there is no frame buffer anywhere, only the band's
//! accumulation buffer and one 128-byte page. Each row of a band is resolved
//! to linear 12-bit intensity and dithered to `BinaryColor` in linear light
//! (`softedge::tone::dither`): Floyd–Steinberg, with one error row that
//! lives across the bands of a frame, or the ordered 8x8 Bayer matrix; the
//! two alternate every 100 frames. The page is sent with the `ssd1306`
//! driver's `set_draw_area` + `draw`.
//!
//! Logs one line per frame over the USB serial/JTAG port (or UART0):
//! frame number, microseconds spent rendering and dithering, microseconds
//! on the I2C bus, and the ditherer.
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

use esp_backtrace as _;

use embedded_graphics_core::pixelcolor::BinaryColor;
use esp_hal::clock::CpuClock;
use esp_hal::i2c::master::{Config as I2cConfig, I2c};
use esp_hal::time::{Instant, Rate};
use esp_println::println;
use ssd1306::prelude::*;
use ssd1306::{I2CDisplayInterface, Ssd1306};

use softedge::scene3d::Angle;
use softedge::tone::{Bayer8, FloydSteinberg};
use softedge::{BandBuffer, Bands, DrawError, Line, RenderStyle, SubPoint, Triangle, SUB_ONE};

// The application descriptor Espressif's second-stage bootloader checks.
esp_bootloader_esp_idf::esp_app_desc!();

/// Panel size.
const W: u16 = 128;
const H: u16 = 64;
/// Rows per band: one SSD1306 page.
const BAND_ROWS: u16 = 8;
const ACC_LEN: usize = BandBuffer::<1>::acc_len(W, BAND_ROWS);
const COVER_LEN: usize = BandBuffer::<1>::cover_len(W, BAND_ROWS);

/// The band buffers (`4 * (ACC_LEN + COVER_LEN)` = 8 256 bytes of .bss).
static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];

/// Ordered-dither thresholds, computed at compile time (flash).
static BAYER: Bayer8 = Bayer8::new();

/// Frames between switches of the ditherer.
const DITHER_PERIOD: u32 = 100;
const FAN: usize = 8;
const RAYS: usize = 6;

#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Dither {
    FloydSteinberg,
    Bayer,
}

/// The scene of one frame, drawn into every band.
struct Scene {
    fan: [Triangle<1>; FAN],
    rays: [Line<1>; RAYS],
    ramp: [Triangle<1>; 2],
}

/// `(cx, cy) + r * (cos a, sin a)` in sub-pixel units (pixels in).
fn polar(cx: i32, cy: i32, a: Angle, r: i32) -> SubPoint {
    // r * 16 < 2^10 and |cos| <= 2^16: the product stays below 2^27.
    let dx = (r * SUB_ONE * a.cos_q16()) >> 16;
    let dy = (r * SUB_ONE * a.sin_q16()) >> 16;
    SubPoint::new(cx * SUB_ONE + dx, cy * SUB_ONE + dy)
}

fn turn(base: Angle, k: usize, n: usize) -> Angle {
    Angle(base.0.wrapping_add(Angle::from_turns(k as u32, n as u32).0))
}

impl Scene {
    fn at(frame: u32) -> Self {
        // 1/1024 of a turn per frame: slow sub-pixel motion, where
        // anti-aliasing (and its dithering) shows best.
        let spin = Angle((frame.wrapping_mul(64) & 0xffff) as u16);
        let back = Angle(0u16.wrapping_sub(spin.0));
        let (fx, fy, fr) = (34, 26, 24);
        let fan = core::array::from_fn(|k| {
            let rim = if k % 2 == 0 { 3200 } else { 700 };
            Triangle::new(
                [
                    polar(fx, fy, spin, 0),
                    polar(fx, fy, turn(spin, k, FAN), fr),
                    polar(fx, fy, turn(spin, k + 1, FAN), fr),
                ],
                [[4095], [rim], [4095 - rim]],
            )
        });
        let (sx, sy) = (96, 26);
        let rays = core::array::from_fn(|k| {
            Line::new(
                polar(sx, sy, turn(back, k, RAYS), 4),
                polar(sx, sy, turn(back, k, RAYS), 24),
                [[4095], [1200]],
            )
        });
        // A linear ramp, black at the left to white at the right, rows 54..64.
        let (tl, tr, bl, br) = (
            SubPoint::from_px(0, 54),
            SubPoint::from_px(128, 54),
            SubPoint::from_px(0, 64),
            SubPoint::from_px(128, 64),
        );
        let ramp = [
            Triangle::new([tl, tr, bl], [[0], [4095], [0]]),
            Triangle::new([tr, br, bl], [[4095], [4095], [0]]),
        ];
        Scene { fan, rays, ramp }
    }

    fn draw(&self, band: &mut BandBuffer<'_, 1>) -> Result<(), DrawError> {
        let style = RenderStyle::default();
        for t in self.fan.iter().chain(&self.ramp) {
            t.draw(band, &style)?;
        }
        for l in &self.rays {
            l.draw(band, &style)?;
        }
        Ok(())
    }
}

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

    // SAFETY: the only references to the two statics are taken here, once;
    // `main` never returns, so they are unique for the program's life.
    let (acc, cover) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(ACC),
            &mut *core::ptr::addr_of_mut!(COVER),
        )
    };
    // Floyd–Steinberg's error row: one `i16` per column, kept across the
    // bands of a frame.
    let mut err_row = [0i16; W as usize];
    println!(
        "softedge esp32c3-ssd1306: {}x{}, bands of {} rows, band buffers {} bytes",
        W,
        H,
        BAND_ROWS,
        4 * (ACC_LEN + COVER_LEN)
    );

    let mut frame: u32 = 0;
    loop {
        let dither = if (frame / DITHER_PERIOD) % 2 == 0 {
            Dither::FloydSteinberg
        } else {
            Dither::Bayer
        };
        let scene = Scene::at(frame);
        let mut fs = FloydSteinberg::new(&mut err_row);
        let (mut render_us, mut bus_us) = (0u64, 0u64);
        let mut failed = false;
        for band in Bands::new(W, H, BAND_ROWS) {
            let t0 = Instant::now();
            let mut buf = match BandBuffer::<1>::new(acc, cover, band) {
                Ok(buf) => buf,
                Err(e) => panic!("band buffer: {:?}", e),
            };
            buf.clear([0]);
            if let Err(e) = scene.draw(&mut buf) {
                println!("frame {}: draw error {:?}", frame, e);
            }
            // One page: byte x holds column x of the band's 8 rows, bit r = row r.
            let mut page = [0u8; W as usize];
            for r in 0..band.rows {
                let y = band.y0 + i32::from(r);
                let mut lin = [[0u16; 1]; W as usize];
                buf.resolve_row(y, &mut lin);
                let mut px = [BinaryColor::Off; W as usize];
                match dither {
                    Dither::FloydSteinberg => fs.row(&lin, &mut px),
                    Dither::Bayer => BAYER.row(&lin, 0, y, &mut px),
                };
                for (byte, p) in page.iter_mut().zip(px) {
                    if p.is_on() {
                        *byte |= 1 << r;
                    }
                }
            }
            let t1 = Instant::now();
            // Band rows fit u8: the frame is 64 rows high.
            let (top, bottom) = (band.y0 as u8, (band.y0 + i32::from(band.rows)) as u8);
            let sent = display
                .set_draw_area((0, top), (W as u8, bottom))
                .and_then(|()| display.draw(&page));
            if sent.is_err() {
                failed = true;
            }
            render_us += (t1 - t0).as_micros();
            bus_us += t1.elapsed().as_micros();
        }
        if failed {
            println!("frame {}: I2C write failed", frame);
        } else {
            println!(
                "frame {} render {} us i2c {} us dither {:?}",
                frame, render_us, bus_us, dither
            );
        }
        frame = frame.wrapping_add(1);
    }
}
