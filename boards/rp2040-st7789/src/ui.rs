//! The instrument panel the firmware shows: its layout, how it is drawn,
//! and which pixels a change of its readings can touch.
//!
//! Board-independent (softedge and embedded-graphics only), so the same
//! file can be compiled on a PC to look at a frame or to measure the
//! partial redraws.
//!
//! The panel is a dial (face, rim, 21 ticks, a needle, a hub), an arc
//! gauge inside it (a track and a value arc with round caps), a readout
//! of the needle's value on a translucent panel over the dial's rim, and
//! a rounded button. Everything is drawn anti-aliased, in painter's order,
//! in `Rgb565` colours (sRGB, composed in linear light), the text too:
//! embedded-graphics' `Text` with softedge's `AaTextStyle`, its glyphs
//! rasterized ahead of time (the readout's digits at 24 px,
//! `readout_font.rs`; the label the crate's `text::bundled::SANS_12`).
//!
//! A reading is `0..=FULL_SCALE` over the dial's 270 degrees, clockwise
//! from 135 degrees (bottom left) on screen, as embedded-graphics measures
//! angles. Geometry that moves is placed on softedge's 1/1024-px grid
//! (`FinePoint`), so the needle and the value arc move by fractions of a
//! pixel from one frame to the next.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Rectangle, RoundedRectangle};
use embedded_graphics::text::{Alignment, Baseline, Text, TextStyleBuilder};
use softedge::geom::{FINE_BITS, FINE_ONE};
use softedge::path;
use softedge::prelude::*;
use softedge::scene3d::Angle;
use softedge::text::{bundled::SANS_12, AaTextStyle, RasterFont};

// The readout's digits: the bundled font at 24 px, made by
// `softedge-sim font --size 24 --chars U+0030-U+0039 --name READOUT_FONT`.
include!("readout_font.rs");

/// Steps of a reading over the whole scale. 4096 makes one step
/// `270 / 4096` degree, exactly 12 of `scene3d::Angle`'s 65536 per turn.
pub const FULL_SCALE: i32 = 4096;
/// Where the scale starts, degrees clockwise from +x on screen (bottom
/// left), as embedded-graphics and softedge measure angles.
const START_DEG: i32 = 135;
/// How far the scale runs, degrees.
const SWEEP_DEG: i32 = 270;

/// The dial's centre pixel; odd diameters centre a `Circle` on it, so
/// the continuous centre is the middle of this pixel.
const CENTRE_PX: Point = Point::new(120, 100);
/// The same centre on the fine grid.
const CENTRE: FinePoint = FinePoint::centre_of(CENTRE_PX.x, CENTRE_PX.y);
/// Face diameter, px (radius 84.5).
const FACE_D: u32 = 169;
/// Rim: a 4-px stroke centred on the circle of this diameter (radius
/// 87.5, so the rim covers radii 85.5..89.5: it overlaps the face by one
/// pixel, with no background between them).
const RIM_D: u32 = 175;
const RIM_W: u32 = 4;
/// Ticks: `TICKS + 1` of them, every fifth a major one, from `TICK_OUT`
/// inwards (radii in px).
const TICKS: i32 = 20;
const TICK_OUT: i32 = 80;
const MAJOR_IN: i32 = 66;
const MINOR_IN: i32 = 73;
/// The gauge's radius and width, px.
const GAUGE_R: i32 = 54;
const GAUGE_W: u32 = 9;
/// The gauge's arcs are ring segments (`path::Polygon`s) through fixed
/// points every `ARC_STEP` readings and the exact end, not stroked
/// `Arc`s, for two reasons. An arc's flattened vertices are spread evenly
/// over its sweep, so all of them move when the sweep does, and its edge
/// pixels change by a code value here and there far from the moving
/// end: with fixed vertices, all but the last segment stay bit for bit
/// the same, so redrawing the end alone is exact. And a filled polygon
/// needs no curve set-up: per band, its stroked `Arc` with round caps
/// costs more than the whole ring and its two end discs (measured on
/// the Cortex-M0, boards/README.md).
/// 128 steps over 270 degrees: chords of 2.1 degrees, 2 px long at
/// radius 54, within `58.5 (1 - cos 1.05°)` = 0.01 px of the circle.
const ARC_STEPS: i32 = 128;
const ARC_STEP: i32 = FULL_SCALE / ARC_STEPS;
/// The most vertices: every step below full scale and the end, on both
/// edges.
const RING_POINTS: usize = 2 * (ARC_STEPS as usize + 1);
/// The needle: tip and tail radii and stroke width, px.
const NEEDLE_TIP: i32 = 76;
const NEEDLE_TAIL: i32 = 16;
const NEEDLE_W: u32 = 3;
/// The hub over the needle's pivot, diameters, px.
const HUB_D: u32 = 15;
const PIVOT_D: u32 = 5;
/// The readout's translucent panel (it covers the bottom of the rim) and
/// the button, px.
const READOUT: Rectangle = Rectangle::new(Point::new(60, 160), Size::new(120, 36));
const READOUT_CORNER: u32 = 8;
const BUTTON: Rectangle = Rectangle::new(Point::new(72, 204), Size::new(96, 30));
const BUTTON_CORNER: u32 = 10;
const BUTTON_EDGE_W: u32 = 2;

/// An 8-bit sRGB colour (what colour pickers give) as the display's
/// type, rounded to Rgb565's 5 and 6 bits as embedded-graphics'
/// `Rgb888 -> Rgb565` conversion does (`(v * max + 127) / 255`; its
/// `From` cannot be called in a `const`).
const fn srgb(r: u8, g: u8, b: u8) -> Rgb565 {
    let (r, g, b) = (r as u32, g as u32, b as u32);
    Rgb565::new(
        ((r * 31 + 127) / 255) as u8,
        ((g * 63 + 127) / 255) as u8,
        ((b * 31 + 127) / 255) as u8,
    )
}

/// The panel's background (what the renderer clears each band to).
pub const BACKGROUND: Rgb565 = srgb(0x0b, 0x10, 0x22);
const FACE: Rgb565 = srgb(0x1c, 0x22, 0x30);
const RIM: Rgb565 = srgb(0xb8, 0xc0, 0xcc);
const MAJOR_TICK: Rgb565 = srgb(0xf0, 0xf0, 0xf0);
const MINOR_TICK: Rgb565 = srgb(0x80, 0x88, 0x98);
const TRACK: Rgb565 = srgb(0x38, 0x40, 0x50);
const VALUE: Rgb565 = srgb(0x20, 0xc0, 0xf0);
const NEEDLE: Rgb565 = srgb(0xff, 0x40, 0x30);
const HUB: Rgb565 = srgb(0xd0, 0xd4, 0xdc);
const PIVOT: Rgb565 = srgb(0x20, 0x20, 0x20);
const PANEL: Rgb565 = srgb(0x00, 0x00, 0x00);
/// The readout panel lets 3/8 of what is under it through.
const PANEL_OPACITY: Opacity = Opacity::from_4096ths(2560); // 5/8
const BUTTON_FILL: Rgb565 = srgb(0x10, 0x60, 0x58);
const BUTTON_EDGE: Rgb565 = srgb(0x60, 0xd0, 0xc0);
const TEXT: Rgb565 = Rgb565::WHITE;

/// One swing of the needle every `NEEDLE_PERIOD` frames, of the gauge
/// every `GAUGE_PERIOD` (out of step: the pattern repeats after 9 000).
const NEEDLE_PERIOD: u32 = 360;
const GAUGE_PERIOD: u32 = 1000;
/// Amplitude of each swing about mid-scale, reading steps.
const NEEDLE_SWING: i32 = 1900;
const GAUGE_SWING: i32 = 2000;

/// The panel's state: everything a frame depends on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Panel {
    /// The needle's reading, `0..=FULL_SCALE`.
    pub needle: i32,
    /// The gauge's reading, `0..=FULL_SCALE`.
    pub gauge: i32,
}

/// `mid + swing * sin(2 pi * frame / period)`, clamped to the scale.
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

/// The point at `radius_fine` from the dial's centre in the direction of
/// `reading`.
fn at_reading(reading: i32, radius_fine: i32) -> FinePoint {
    // START_DEG + SWEEP_DEG * reading / FULL_SCALE, in units of 1/65536
    // turn; below 2^17 * 2^12 = 2^29 before the division.
    let units = (START_DEG as u32 * Angle::TURN / 360)
        + (SWEEP_DEG as u32 * Angle::TURN / 360) * reading.clamp(0, FULL_SCALE) as u32
            / FULL_SCALE as u32;
    let a = Angle((units % Angle::TURN) as u16);
    // radius < 2^17 fine units, |cos| <= 2^16: i64 for the product.
    let dx = (i64::from(radius_fine) * i64::from(a.cos_q16())) >> 16;
    let dy = (i64::from(radius_fine) * i64::from(a.sin_q16())) >> 16;
    FinePoint::new(CENTRE.x + dx as i32, CENTRE.y + dy as i32)
}

/// The ring segment of the gauge from the scale's start to `reading`:
/// the outer edge forwards, then the inner edge back, through the
/// readings `k * ARC_STEP` below `reading` and `reading` itself. Returns
/// how many of `out` were written.
fn ring_segment(reading: i32, out: &mut [FinePoint; RING_POINTS]) -> usize {
    let reading = reading.clamp(0, FULL_SCALE);
    let half = GAUGE_W as i32 * FINE_ONE / 2;
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
        *o = at_reading(at, outer);
        *i = at_reading(at, inner);
    }
    2 * n
}

/// The readout: the needle's value in percent, three digits.
fn percent_digits(reading: i32) -> [u8; 3] {
    let p = (reading.clamp(0, FULL_SCALE) * 100 + FULL_SCALE / 2) / FULL_SCALE;
    let digit = |d: i32| b'0' + (d % 10) as u8;
    [digit(p / 100), digit(p / 10), digit(p)]
}

/// Centred text style (horizontally, and vertically on its middle).
fn centred() -> embedded_graphics::text::TextStyle {
    TextStyleBuilder::new()
        .alignment(Alignment::Center)
        .baseline(Baseline::Middle)
        .build()
}

/// Where the readout's digits go.
fn readout_text(digits: &[u8; 3]) -> Text<'_, AaTextStyle<&'static RasterFont<'static>, Rgb565>> {
    // ASCII digits are always UTF-8.
    let s = core::str::from_utf8(digits).unwrap_or("000");
    Text::with_text_style(
        s,
        READOUT.center(),
        AaTextStyle::new(&READOUT_FONT, TEXT),
        centred(),
    )
}

impl Panel {
    /// The state at `frame`.
    pub fn at(frame: u32) -> Self {
        Self {
            needle: swing(frame, NEEDLE_PERIOD, NEEDLE_SWING),
            gauge: swing(frame, GAUGE_PERIOD, GAUGE_SWING),
        }
    }

    /// Draws the panel into one band's canvas (called once per band, and
    /// per band of each redrawn window: it must draw the same every time).
    pub fn draw(&self, canvas: &mut Canvas<'_, '_, 3, Rgb565>) -> Result<(), DrawError> {
        // The dial.
        Circle::with_center(CENTRE_PX, FACE_D)
            .into_styled(AaStyle::with_fill(FACE))
            .draw(canvas)?;
        Circle::with_center(CENTRE_PX, RIM_D)
            .into_styled(AaStyle::with_stroke(RIM, RIM_W))
            .draw(canvas)?;
        let major = AaStyle::with_stroke(MAJOR_TICK, 3);
        let minor = AaStyle::with_stroke(MINOR_TICK, 1);
        for k in 0..=TICKS {
            let reading = (k * FULL_SCALE + TICKS / 2) / TICKS;
            let (inner, style) = if k % 5 == 0 {
                (MAJOR_IN, major)
            } else {
                (MINOR_IN, minor)
            };
            path::Line::new(
                at_reading(reading, px(inner)),
                at_reading(reading, px(TICK_OUT)),
            )
            .into_styled(style)
            .draw(canvas)?;
        }

        // The arc gauge: the whole track, the value over it, each a ring
        // segment with a disc at either end for round caps.
        for (reading, color) in [(FULL_SCALE, TRACK), (self.gauge, VALUE)] {
            let mut ring = [CENTRE; RING_POINTS];
            let n = ring_segment(reading, &mut ring);
            path::Polygon::new(ring.get(..n).unwrap_or(&[]))
                .into_styled(AaStyle::with_fill(color))
                .draw(canvas)?;
            for end in [0, reading] {
                path::Circle::new(at_reading(end, px(GAUGE_R)), GAUGE_W * FINE_ONE as u32 / 2)
                    .into_styled(AaStyle::with_fill(color))
                    .draw(canvas)?;
            }
        }

        // The needle, then the hub over its pivot.
        self.needle_line()
            .into_styled(AaStyle::with_stroke(NEEDLE, NEEDLE_W).cap(LineCap::Round))
            .draw(canvas)?;
        Circle::with_center(CENTRE_PX, HUB_D)
            .into_styled(AaStyle::with_fill(HUB))
            .draw(canvas)?;
        Circle::with_center(CENTRE_PX, PIVOT_D)
            .into_styled(AaStyle::with_fill(PIVOT))
            .draw(canvas)?;

        // The readout on a translucent panel: the rim shows through it.
        RoundedRectangle::with_equal_corners(READOUT, Size::new_equal(READOUT_CORNER))
            .into_styled(AaStyle::with_fill(PANEL).opacity(PANEL_OPACITY))
            .draw(canvas)?;
        let digits = percent_digits(self.needle);
        readout_text(&digits).draw(canvas)?;

        // The button.
        RoundedRectangle::with_equal_corners(BUTTON, Size::new_equal(BUTTON_CORNER))
            .into_styled(
                AaStyle::with_fill(BUTTON_FILL)
                    .stroke_color(BUTTON_EDGE)
                    .stroke_width(BUTTON_EDGE_W),
            )
            .draw(canvas)?;
        let label = AaTextStyle::new(&SANS_12, TEXT);
        Text::with_text_style("MODE", BUTTON.center(), label, centred()).draw(canvas)?;
        Ok(())
    }

    /// The needle, tail to tip, through the centre: the tail points
    /// opposite the tip.
    fn needle_line(&self) -> path::Line {
        let back = at_reading(self.needle, px(NEEDLE_TAIL));
        path::Line::new(
            FinePoint::new(2 * CENTRE.x - back.x, 2 * CENTRE.y - back.y),
            at_reading(self.needle, px(NEEDLE_TIP)),
        )
    }

    /// The pixels whose colour can differ between `self` and `next`: at
    /// most three rectangles (needle, gauge, readout), overlapping ones
    /// merged. What a partial redraw sends.
    pub fn dirty(&self, next: &Panel) -> Dirty {
        let mut d = Dirty::default();
        if self.needle != next.needle {
            let (a, b) = (self.needle_line(), next.needle_line());
            d.add(fine_box(
                [a.start, a.end, b.start, b.end],
                NEEDLE_W as i32 * FINE_ONE / 2,
            ));
            if percent_digits(self.needle) != percent_digits(next.needle) {
                d.add(readout_text(&percent_digits(next.needle)).bounding_box());
            }
        }
        if self.gauge != next.gauge {
            d.add(gauge_change(self.gauge, next.gauge));
        }
        d
    }
}

/// The pixels a change of the gauge from reading `a` to `b` can touch:
/// the ring from the last fixed vertex both value segments share (one
/// step before the nearer end, to be safe) to the farther end, its
/// axis-extreme points included, widened by half the ring's width, which
/// also holds each end's disc.
fn gauge_change(a: i32, b: i32) -> Rectangle {
    let lo = ((a.min(b) / ARC_STEP - 1) * ARC_STEP).max(0);
    let hi = a.max(b);
    let r = px(GAUGE_R);
    let (p_lo, p_hi) = (at_reading(lo, r), at_reading(hi, r));
    // Unused slots repeat an end point.
    let mut pts = [p_lo, p_hi, p_lo, p_lo, p_lo];
    // The left, top and right extremes of the circle, where the arc
    // passes them: reading = (deg - START_DEG) * FULL_SCALE / SWEEP_DEG.
    let extremes = [
        (180, FinePoint::new(CENTRE.x - r, CENTRE.y)),
        (270, FinePoint::new(CENTRE.x, CENTRE.y - r)),
        (360, FinePoint::new(CENTRE.x + r, CENTRE.y)),
    ];
    for (slot, (deg, p)) in pts.iter_mut().skip(2).zip(extremes) {
        let at = (deg - START_DEG) * FULL_SCALE;
        if lo * SWEEP_DEG <= at && at <= hi * SWEEP_DEG {
            *slot = p;
        }
    }
    fine_box(pts, GAUGE_W as i32 * FINE_ONE / 2)
}

/// The whole pixels within `reach` fine units (plus one pixel of
/// anti-aliased fringe) of the box around `pts`.
fn fine_box<const N: usize>(pts: [FinePoint; N], reach: i32) -> Rectangle {
    let pad = reach + FINE_ONE;
    let (mut x0, mut y0, mut x1, mut y1) = (i32::MAX, i32::MAX, i32::MIN, i32::MIN);
    for p in pts {
        x0 = x0.min(p.x - pad);
        y0 = y0.min(p.y - pad);
        x1 = x1.max(p.x + pad);
        y1 = y1.max(p.y + pad);
    }
    // Floor the corner, ceil the far side (arithmetic shifts floor).
    let (px0, py0) = (x0 >> FINE_BITS, y0 >> FINE_BITS);
    let (px1, py1) = (
        (x1 + FINE_ONE - 1) >> FINE_BITS,
        (y1 + FINE_ONE - 1) >> FINE_BITS,
    );
    Rectangle::with_corners(Point::new(px0, py0), Point::new(px1 - 1, py1 - 1))
}

/// Rectangles to redraw, overlapping ones merged.
#[derive(Debug, Default, Clone, Copy)]
pub struct Dirty {
    rects: [Option<Rectangle>; 3],
}

impl Dirty {
    /// Adds `r`, merged with every rectangle it overlaps (their bounding
    /// box; merging can make it overlap another, so repeat).
    fn add(&mut self, r: Rectangle) {
        let mut r = r;
        loop {
            let hit = self.rects.iter_mut().find(|s| {
                s.as_ref()
                    .is_some_and(|s| !s.intersection(&r).is_zero_sized())
            });
            match hit {
                Some(slot) => {
                    if let Some(s) = slot.take() {
                        r = union(&s, &r);
                    }
                }
                None => break,
            }
        }
        if let Some(free) = self.rects.iter_mut().find(|s| s.is_none()) {
            *free = Some(r);
        } else if let Some(last) = self.rects.last_mut() {
            // Never reached with three adds; merge rather than lose it.
            *last = last.map(|s| union(&s, &r));
        }
    }

    /// The rectangles.
    pub fn rects(&self) -> impl Iterator<Item = Rectangle> + '_ {
        self.rects.iter().flatten().copied()
    }
}

/// The bounding box of two rectangles.
fn union(a: &Rectangle, b: &Rectangle) -> Rectangle {
    let (Some(a1), Some(b1)) = (a.bottom_right(), b.bottom_right()) else {
        return if a.is_zero_sized() { *b } else { *a };
    };
    Rectangle::with_corners(
        Point::new(
            a.top_left.x.min(b.top_left.x),
            a.top_left.y.min(b.top_left.y),
        ),
        Point::new(a1.x.max(b1.x), a1.y.max(b1.y)),
    )
}
