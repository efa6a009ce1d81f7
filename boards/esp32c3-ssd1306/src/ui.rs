//! The panel the firmware shows on the 128x64 OLED: a small dial with a
//! needle on the left, an arc gauge with its value in text on the right,
//! and the name of the ditherer in use.
//!
//! Board-independent (softedge and embedded-graphics only). Everything is
//! drawn anti-aliased in painter's order; white is `BinaryColor::On`, the
//! gauge's track a linear gray (`[1024]`: a quarter of full intensity, so
//! a quarter of its pixels light up once dithered); the text is
//! embedded-graphics' `Text` with softedge's `AaTextStyle`: the bundled
//! font at 10 px rasterized ahead of time with its x-height on the pixel
//! grid (`label_font.rs`), glyphs on whole pixels and the text's own
//! contrast gain of 4, what keeps 10-12 px text legible once dithered
//! (`tests/tests/text_one_bit.rs`).
//!
//! A reading is `0..=FULL_SCALE` over 270 degrees, clockwise from 135
//! degrees (bottom left) on screen, as embedded-graphics measures angles;
//! moving geometry is placed on softedge's 1/1024-px grid, so it moves by
//! fractions of a pixel, which the dithering shows as shifting patterns
//! along the edges.

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Circle;
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use softedge::geom::FINE_ONE;
use softedge::path;
use softedge::prelude::*;
use softedge::scene3d::Angle;
use softedge::text::AaTextStyle;

// The value's and the label's characters: the bundled font at 10 px, made
// by `softedge-sim font --size 10 --grid --chars U+0030-U+0039 --text
// " %F-SBAYER" --name LABEL_FONT`.
include!("label_font.rs");

/// Steps of a reading over the whole scale: one step is `270 / 4096`
/// degree, exactly 12 of `scene3d::Angle`'s 65536 per turn.
pub const FULL_SCALE: i32 = 4096;
/// Where the scale starts, degrees clockwise from +x on screen.
const START_DEG: i32 = 135;
/// How far it runs, degrees.
const SWEEP_DEG: i32 = 270;

/// The dial: centre pixel (odd diameters centre a `Circle` on it), rim
/// (a 2-px stroke on the circle of radius 30.5: radii 29.5..31.5, the
/// display's full height), ticks, needle and hub, px.
const DIAL_PX: Point = Point::new(31, 31);
const DIAL: FinePoint = FinePoint::centre_of(DIAL_PX.x, DIAL_PX.y);
const RIM_D: u32 = 61;
const RIM_W: u32 = 2;
const TICKS: i32 = 10;
const TICK_OUT: i32 = 26;
const MAJOR_IN: i32 = 20;
const MINOR_IN: i32 = 23;
const NEEDLE_TIP: i32 = 24;
const NEEDLE_TAIL: i32 = 6;
const NEEDLE_W: u32 = 2;
const HUB_D: u32 = 7;
const PIVOT_D: u32 = 3;

/// The gauge: centre, radius and width, px.
const GAUGE: FinePoint = FinePoint::centre_of(96, 26);
const GAUGE_R: i32 = 19;
const GAUGE_W: i32 = 6;
/// The gauge's arcs are ring segments (`path::Polygon`s) through fixed
/// points every `ARC_STEP` readings and the exact end, with a disc at
/// each end for round caps: a filled polygon needs no curve set-up per
/// band, unlike a stroked `Arc` with round caps. 64 steps over 270
/// degrees: chords of 4.2 degrees, within `22 (1 - cos 2.1°)` = 0.015 px
/// of the circle.
const ARC_STEPS: i32 = 64;
const ARC_STEP: i32 = FULL_SCALE / ARC_STEPS;
/// The most vertices: every step below full scale and the end, on both
/// edges.
const RING_POINTS: usize = 2 * (ARC_STEPS as usize + 1);
/// The gauge's value under it, and the ditherer's name at the bottom.
const VALUE_AT: Point = Point::new(96, 47);
const LABEL_AT: Point = Point::new(96, 58);

/// White, and the track's gray in linear light.
const WHITE: BinaryColor = BinaryColor::On;
const BLACK: BinaryColor = BinaryColor::Off;
const TRACK: [u16; 1] = [1024];

/// One swing of the needle every `NEEDLE_PERIOD` frames, of the gauge
/// every `GAUGE_PERIOD`, each `SWING` reading steps about mid-scale.
const NEEDLE_PERIOD: u32 = 300;
const GAUGE_PERIOD: u32 = 700;
const SWING: i32 = 1900;

/// What a frame shows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Panel {
    /// The needle's reading, `0..=FULL_SCALE`.
    pub needle: i32,
    /// The gauge's reading, `0..=FULL_SCALE`.
    pub gauge: i32,
    /// The ditherer's name.
    pub label: &'static str,
}

/// `mid + amplitude * sin(2 pi * frame / period)`, clamped to the scale.
fn swing(frame: u32, period: u32, amplitude: i32) -> i32 {
    let phase = Angle::from_turns(frame % period, period);
    // |amplitude| < 2^11 and |sin| <= 2^16: the product fits i32.
    let r = FULL_SCALE / 2 + ((amplitude * phase.sin_q16()) >> 16);
    r.clamp(0, FULL_SCALE)
}

/// `n` pixels in fine units.
const fn px(n: i32) -> i32 {
    n * FINE_ONE
}

/// The point `radius_fine` from `centre` in the direction of `reading`.
fn at_reading(centre: FinePoint, reading: i32, radius_fine: i32) -> FinePoint {
    // START_DEG + SWEEP_DEG * reading / FULL_SCALE in 1/65536 turn;
    // below 2^17 * 2^12 = 2^29 before the division.
    let units = (START_DEG as u32 * Angle::TURN / 360)
        + (SWEEP_DEG as u32 * Angle::TURN / 360) * reading.clamp(0, FULL_SCALE) as u32
            / FULL_SCALE as u32;
    let a = Angle((units % Angle::TURN) as u16);
    // |radius| < 2^15 fine units here, |cos| <= 2^16: i64 for safety.
    let dx = (i64::from(radius_fine) * i64::from(a.cos_q16())) >> 16;
    let dy = (i64::from(radius_fine) * i64::from(a.sin_q16())) >> 16;
    FinePoint::new(centre.x + dx as i32, centre.y + dy as i32)
}

/// The gauge's ring segment from the scale's start to `reading`: the
/// outer edge forwards, the inner edge back, through the readings
/// `k * ARC_STEP` below `reading` and `reading` itself. Returns how many
/// of `out` were written.
fn ring_segment(reading: i32, out: &mut [FinePoint; RING_POINTS]) -> usize {
    let reading = reading.clamp(0, FULL_SCALE);
    let half = GAUGE_W * FINE_ONE / 2;
    let (outer, inner) = (px(GAUGE_R) + half, px(GAUGE_R) - half);
    // Steps k with k * ARC_STEP < reading, then the end.
    let n = ((reading + ARC_STEP - 1) / ARC_STEP) as usize + 1;
    let n = n.min(RING_POINTS / 2);
    let (fwd, back) = out.split_at_mut(n);
    for (k, (o, i)) in (0..).zip(fwd.iter_mut().zip(back.iter_mut().take(n).rev())) {
        let at = if k + 1 == n {
            reading
        } else {
            k as i32 * ARC_STEP
        };
        *o = at_reading(GAUGE, at, outer);
        *i = at_reading(GAUGE, at, inner);
    }
    2 * n
}

/// Centred text (horizontally, and vertically on its middle).
fn centred() -> embedded_graphics::text::TextStyle {
    TextStyleBuilder::new()
        .alignment(Alignment::Center)
        .baseline(Baseline::Middle)
        .build()
}

/// A reading in percent, `"  0%"` to `"100%"`.
fn percent(reading: i32) -> [u8; 4] {
    let p = (reading.clamp(0, FULL_SCALE) * 100 + FULL_SCALE / 2) / FULL_SCALE;
    let digit = |d: i32, lead: bool| if lead { b' ' } else { b'0' + (d % 10) as u8 };
    [
        digit(p / 100, p < 100),
        digit(p / 10, p < 10),
        digit(p, false),
        b'%',
    ]
}

impl Panel {
    /// The readings at `frame`.
    pub fn at(frame: u32, label: &'static str) -> Self {
        Self {
            needle: swing(frame, NEEDLE_PERIOD, SWING),
            gauge: swing(frame, GAUGE_PERIOD, SWING),
            label,
        }
    }

    /// Draws the panel into one band's canvas (called once per band: it
    /// must draw the same every time).
    pub fn draw(&self, canvas: &mut Canvas<'_, '_, 1, BinaryColor>) -> Result<(), DrawError> {
        // The dial: rim, ticks, needle, hub.
        Circle::with_center(DIAL_PX, RIM_D)
            .into_styled(AaStyle::with_stroke(WHITE, RIM_W))
            .draw(canvas)?;
        for k in 0..=TICKS {
            let reading = (k * FULL_SCALE + TICKS / 2) / TICKS;
            let (inner, width) = if k % 5 == 0 {
                (MAJOR_IN, 2)
            } else {
                (MINOR_IN, 1)
            };
            path::Line::new(
                at_reading(DIAL, reading, px(inner)),
                at_reading(DIAL, reading, px(TICK_OUT)),
            )
            .into_styled(AaStyle::with_stroke(WHITE, width))
            .draw(canvas)?;
        }
        // The tail points opposite the tip.
        let back = at_reading(DIAL, self.needle, px(NEEDLE_TAIL));
        path::Line::new(
            FinePoint::new(2 * DIAL.x - back.x, 2 * DIAL.y - back.y),
            at_reading(DIAL, self.needle, px(NEEDLE_TIP)),
        )
        .into_styled(AaStyle::with_stroke(WHITE, NEEDLE_W).cap(LineCap::Round))
        .draw(canvas)?;
        Circle::with_center(DIAL_PX, HUB_D)
            .into_styled(AaStyle::with_fill(WHITE))
            .draw(canvas)?;
        Circle::with_center(DIAL_PX, PIVOT_D)
            .into_styled(AaStyle::with_fill(BLACK))
            .draw(canvas)?;

        // The gauge: the whole track in gray, the value in white over it,
        // each a ring segment with a disc at either end.
        let cap = |reading| {
            path::Circle::new(
                at_reading(GAUGE, reading, px(GAUGE_R)),
                (GAUGE_W * FINE_ONE / 2) as u32,
            )
        };
        let mut ring = [GAUGE; RING_POINTS];
        let n = ring_segment(FULL_SCALE, &mut ring);
        let track = AaStyle::with_fill(TRACK);
        path::Polygon::new(ring.get(..n).unwrap_or(&[]))
            .into_styled(track)
            .draw(canvas)?;
        cap(0).into_styled(track).draw(canvas)?;
        cap(FULL_SCALE).into_styled(track).draw(canvas)?;
        let n = ring_segment(self.gauge, &mut ring);
        let value = AaStyle::with_fill(WHITE);
        path::Polygon::new(ring.get(..n).unwrap_or(&[]))
            .into_styled(value)
            .draw(canvas)?;
        cap(0).into_styled(value).draw(canvas)?;
        cap(self.gauge).into_styled(value).draw(canvas)?;

        let font = AaTextStyle::new(&LABEL_FONT, WHITE).grid(true).contrast(2);
        let digits = percent(self.gauge);
        // ASCII is always UTF-8.
        let value_text = core::str::from_utf8(&digits).unwrap_or("---");
        Text::with_text_style(value_text, VALUE_AT, font, centred()).draw(canvas)?;
        Text::with_text_style(self.label, LABEL_AT, font, centred()).draw(canvas)?;
        Ok(())
    }
}
