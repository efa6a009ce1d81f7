//! softedge on a Raspberry Pi Pico (RP2040) with an ST7789 240x240 SPI TFT.
//!
//! Renders an animated scene — a rotating fan of six Gouraud triangles
//! (shared edges, so any seam would show) inside a counter-rotating ring of
//! anti-aliased lines — band by band, 16 rows at a time, into two static band
//! buffers, tone-maps each band through the sRGB γ tables of
//! `softedge::tone::format::Rgb565Format`, and sends it to the panel with one
//! `fill_contiguous` per band (`softedge::eg::Renderer` over the `mipidsi`
//! ST7789 driver). Every 128 frames the style switches between anti-aliased
//! and aliased, so the difference can be seen side by side in time.
//!
//! Logs over defmt (RTT): one `info` line per frame (frame number, render
//! time, the `RenderStyle` in use), and with `DEFMT_LOG=debug` one line per
//! band (the `Band` and the microseconds spent accumulating it).
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

use defmt_rtt as _;
use panic_probe as _;

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

use softedge::eg::Renderer;
use softedge::scene3d::Angle;
use softedge::tone::format::{Rgb565Format, ToneFormat};
use softedge::tone::Curve;
use softedge::{BandBuffer, DrawError, Line, RenderStyle, SubPoint, Triangle, SUB_ONE};

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
/// Rows per band.
const BAND_ROWS: u16 = 16;
/// `i32`s of the accumulation buffer: 240 x 16 pixels x 3 channels.
const ACC_LEN: usize = BandBuffer::<3>::acc_len(W, BAND_ROWS);
/// `i32`s of the coverage scratch: (240 + 2) x 16.
const COVER_LEN: usize = BandBuffer::<3>::cover_len(W, BAND_ROWS);

/// The band buffers (`4 * (ACC_LEN + COVER_LEN)` = 61 568 bytes of .bss).
static mut ACC: [i32; ACC_LEN] = [0; ACC_LEN];
static mut COVER: [i32; COVER_LEN] = [0; COVER_LEN];

/// Linear 12-bit → Rgb565 through the sRGB transfer curve; the 5- and 6-bit
/// tables are computed at compile time and live in flash.
static TONE: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// Background, linear 12-bit RGB: a dark blue.
const BACKGROUND: [u16; 3] = [40, 60, 260];
/// Triangles of the fan and lines of the ring.
const FAN: usize = 6;
const RAYS: usize = 24;
/// Frames between style switches.
const STYLE_PERIOD: u32 = 128;

/// The scene of one frame, computed once per frame, drawn into every band.
struct Scene {
    fan: [Triangle<3>; FAN],
    rays: [Line<3>; RAYS],
    style: RenderStyle,
}

/// `centre + r * (cos a, sin a)` in sub-pixel units (`r` in pixels).
fn polar(a: Angle, r: i32) -> SubPoint {
    let c = i32::from(W / 2) * SUB_ONE;
    // r * 16 <= 1920 and |cos| <= 2^16: the product stays below 2^27.
    let dx = (r * SUB_ONE * a.cos_q16()) >> 16;
    let dy = (r * SUB_ONE * a.sin_q16()) >> 16;
    SubPoint::new(c + dx, c + dy)
}

/// Saturated hues around the fan, linear 12-bit.
const HUES: [[u16; 3]; FAN] = [
    [4095, 0, 0],
    [4095, 4095, 0],
    [0, 4095, 0],
    [0, 4095, 4095],
    [0, 0, 4095],
    [4095, 0, 4095],
];

impl Scene {
    fn at(frame: u32) -> Self {
        // 1/512 of a turn per frame for the fan, the ring the other way.
        let spin = Angle((frame.wrapping_mul(128) & 0xffff) as u16);
        let centre = polar(Angle(0), 0);
        let fan = core::array::from_fn(|k| {
            let a0 = Angle(
                spin.0
                    .wrapping_add(Angle::from_turns(k as u32, FAN as u32).0),
            );
            let a1 = Angle(
                spin.0
                    .wrapping_add(Angle::from_turns(k as u32 + 1, FAN as u32).0),
            );
            Triangle::new(
                [centre, polar(a0, 92), polar(a1, 92)],
                [[4095, 4095, 4095], HUES[k], HUES[(k + 1) % FAN]],
            )
        });
        let rays = core::array::from_fn(|k| {
            let a = Angle(
                Angle::from_turns(k as u32, RAYS as u32)
                    .0
                    .wrapping_sub(spin.0 / 2),
            );
            Line::new(
                polar(a, 100),
                polar(a, 118),
                [[4095, 4095, 4095], [4095, 2600, 300]],
            )
        });
        let style = if (frame / STYLE_PERIOD) % 2 == 0 {
            RenderStyle::default()
        } else {
            RenderStyle::ALIASED
        };
        Scene { fan, rays, style }
    }

    fn draw(&self, band: &mut BandBuffer<'_, 3>) -> Result<(), DrawError> {
        for t in &self.fan {
            t.draw(band, &self.style)?;
        }
        for l in &self.rays {
            l.draw(band, &self.style)?;
        }
        Ok(())
    }
}

#[hal::entry]
fn main() -> ! {
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

    // SAFETY: the only references to the two statics are taken here, once;
    // `main` never returns, so they are unique for the program's life.
    let (acc, cover) = unsafe {
        (
            &mut *core::ptr::addr_of_mut!(ACC),
            &mut *core::ptr::addr_of_mut!(COVER),
        )
    };
    defmt::info!(
        "softedge rp2040-st7789: {}x{}, bands of {} rows, band buffers {} bytes",
        W,
        H,
        BAND_ROWS,
        4 * (ACC_LEN + COVER_LEN)
    );
    let mut renderer = Renderer::<3>::new(acc, cover, W, H, BAND_ROWS);

    let mut frame: u32 = 0;
    loop {
        let scene = Scene::at(frame);
        let t0 = timer.get_counter();
        let result = renderer.render(
            &mut display,
            BACKGROUND,
            |band| {
                let b0 = timer.get_counter();
                let r = scene.draw(band);
                let us = (timer.get_counter() - b0).to_micros();
                defmt::debug!("band {} accumulated in {} us", band.band(), us);
                r
            },
            |px| TONE.color(px),
        );
        let us = (timer.get_counter() - t0).to_micros();
        match result {
            Ok(()) => defmt::info!("frame {} in {} us, style {}", frame, us, scene.style),
            Err(softedge::eg::RenderError::Draw(e)) => defmt::error!("frame {}: {}", frame, e),
            Err(softedge::eg::RenderError::Band(e)) => defmt::error!("frame {}: {}", frame, e),
            Err(softedge::eg::RenderError::Target(_)) => {
                defmt::error!("frame {}: SPI write failed", frame)
            }
        }
        frame = frame.wrapping_add(1);
    }
}
