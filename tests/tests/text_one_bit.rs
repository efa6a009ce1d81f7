//! Text on a 128x64 1-bit OLED (SSD1306) at 10, 11 and 12 px: rendered
//! through the frame loop (8-row pages) and the tone stage's dithering, and
//! measured against the anti-aliased gray frame of the same layout
//! (within 0.0032 of exact coverage per pixel, `text_coverage.rs`) and its
//! threshold at 1/2, the sharpest 1-bit rendering of the outline:
//!
//! - **dropouts**: strokes of the gray frame (maximal runs of coverage
//!   at least 0.3 along a row or a column that peak at 0.45 or more)
//!   without a single lit pixel: lost strokes make letters unreadable;
//! - **edge noise**: pixels that differ from the threshold, per pixel of
//!   the threshold's ink: dithering scatters edge pixels into dots;
//! - **specks**: lit pixels where coverage is below 1/4.
//!
//! The variants: Bayer 8x8, Floyd–Steinberg (exact positions), with
//! `Sharpen::GRID`, and with `ContrastBoost` (gain 4) before the ditherer;
//! and the font rasterized ahead of time (issue #33), grid-fitted, with
//! the contrast gain on the text's own coverage instead of the frame.
//! The printed table is the README's (*Text on a 1-bit OLED*).

use embedded_graphics_core::draw_target::DrawTarget;
use embedded_graphics_core::geometry::{OriginDimensions, Size};
use embedded_graphics_core::pixelcolor::BinaryColor;
use embedded_graphics_core::Pixel;
use softedge::canvas::{Canvas, WalkSlot};
use softedge::geom::FinePoint;
use softedge::render::Renderer;
use softedge::text::{Baseline, ContrastBoost, Font, FontStyle, RasterText, Sharpen, Text};
use softedge::tone::profile::{DiffusionProfile, Profile};
use softedge::tone::Bayer8;
use softedge::DrawError;
use softedge::{Band, BandBuffer};
use softedge_tests::raster_font::Built;

const W: u16 = 128;
const H: u16 = 64;
const PAGE: u16 = 8;
/// Four lines of an instrument display.
pub const LINES: &str = "Temp 23.5 °C\nHumidity 45 %\nBattery 3.71 V\nAVAWAY Ty To";
/// The first line's top, fine units (off the pixel grid on purpose).
const AT: FinePoint = FinePoint::new(2 * 1024 + 300, 1024 + 200);

struct Oled(Vec<bool>);

impl OriginDimensions for Oled {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(H))
    }
}

impl DrawTarget for Oled {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            if (0..i32::from(W)).contains(&p.x) && (0..i32::from(H)).contains(&p.y) {
                self.0[(p.y * i32::from(W) + p.x) as usize] = c.is_on();
            }
        }
        Ok(())
    }
}

fn text<'f>(font: &'f Font<'static>, size: u16, sharpen: Sharpen) -> Text<'static, 'f, 'static, 1> {
    let style = FontStyle::<1>::new(font, size, [4095]).with_sharpen(sharpen);
    Text::with_baseline(LINES, AT, style, Baseline::Top)
}

/// The linear gray frame (fractions of white).
fn gray(t: &Text<'_, '_, '_, 1>) -> Vec<f64> {
    gray_of(|c| t.draw(c).map(|_| ()))
}

/// The linear gray frame of what `draw` draws (fractions of white).
fn gray_of(draw: impl FnOnce(&mut Canvas<'_, '_, 1>) -> Result<(), DrawError>) -> Vec<f64> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, H)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, H)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(W, 0, H)).unwrap();
    buf.clear([0]);
    let mut c = Canvas::new(&mut buf, None);
    draw(&mut c).unwrap();
    let b = c.buffer();
    (0..i32::from(H))
        .flat_map(|y| (0..i32::from(W)).map(move |x| (x, y)))
        .map(|(x, y)| f64::from(b.lin12(x, y).unwrap()[0]) / 4095.0)
        .collect()
}

/// The OLED's pixels through the frame loop and `profile`.
fn oled<P: Profile<1, Color = BinaryColor>>(t: &Text<'_, '_, '_, 1>, profile: P) -> Vec<bool> {
    oled_of(profile, |c| t.draw(c).map(|_| ()))
}

/// The OLED's pixels of what `draw` draws, through the frame loop.
fn oled_of<P: Profile<1, Color = BinaryColor>>(
    profile: P,
    mut draw: impl FnMut(&mut Canvas<'_, '_, 1, BinaryColor>) -> Result<(), DrawError>,
) -> Vec<bool> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, PAGE)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, PAGE)];
    let mut slots = vec![WalkSlot::<1>::EMPTY; 64];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, PAGE).unwrap();
    let mut screen = Oled(vec![false; usize::from(W) * usize::from(H)]);
    r.render(&mut screen, profile, [0], |c| draw(c)).unwrap();
    screen.0
}

/// Dropouts, strokes, edge noise (%), specks.
#[derive(Debug, Clone, Copy)]
pub struct Legibility {
    strokes: usize,
    dropped: usize,
    noise: f64,
    specks: usize,
}

fn measure(g: &[f64], b: &[bool]) -> Legibility {
    let (w, h) = (usize::from(W), usize::from(H));
    let (mut strokes, mut dropped) = (0, 0);
    for pass in 0..2 {
        let (outer, inner) = if pass == 0 { (h, w) } else { (w, h) };
        for o in 0..outer {
            let mut run: Option<(f64, bool)> = None;
            for i in 0..=inner {
                let cell = (i < inner).then(|| {
                    let k = if pass == 0 { o * w + i } else { i * w + o };
                    (g[k], b[k])
                });
                match (cell, &mut run) {
                    (Some((c, on)), Some(r)) if c >= 0.3 => {
                        r.0 = r.0.max(c);
                        r.1 |= on;
                    }
                    (Some((c, on)), None) if c >= 0.3 => run = Some((c, on)),
                    (_, r) => {
                        if let Some((peak, lit)) = r.take() {
                            if peak >= 0.45 {
                                strokes += 1;
                                dropped += usize::from(!lit);
                            }
                        }
                    }
                }
            }
        }
    }
    let ink = g.iter().filter(|&&c| c >= 0.5).count();
    let differ = g.iter().zip(b).filter(|(&c, &on)| (c >= 0.5) != on).count();
    let specks = g.iter().zip(b).filter(|(&c, &on)| on && c < 0.25).count();
    Legibility {
        strokes,
        dropped,
        noise: 100.0 * differ as f64 / ink.max(1) as f64,
        specks,
    }
}

fn variants(font: &Font<'static>, size: u16) -> Vec<(&'static str, Legibility)> {
    let mut out = Vec::new();
    let exact = text(font, size, Sharpen::NONE);
    let grid = text(font, size, Sharpen::GRID);
    let (ge, gg) = (gray(&exact), gray(&grid));
    let threshold: Vec<bool> = ge.iter().map(|&c| c >= 0.5).collect();
    out.push(("threshold at 1/2 (exact)", measure(&ge, &threshold)));
    out.push(("Bayer 8x8", measure(&ge, &oled(&exact, Bayer8::new()))));
    let fs = |t: &Text<'_, '_, '_, 1>, shift: u8| {
        let (mut err, mut bits, mut scratch) = ([0i16; 128], [false; 128], [0i32; 128]);
        let p = DiffusionProfile::new(&mut err, &mut bits);
        oled(t, ContrastBoost::new(p, shift, &mut scratch))
    };
    out.push(("Floyd-Steinberg", measure(&ge, &fs(&exact, 0))));
    out.push(("FS + ContrastBoost x4", measure(&ge, &fs(&exact, 2))));
    out.push(("FS + Sharpen::GRID", measure(&gg, &fs(&grid, 0))));
    out.push(("FS + GRID + boost x4", measure(&gg, &fs(&grid, 2))));
    // Issue #33: the same font rasterized ahead of time, its x-height on
    // the grid (`softedge-sim font --grid`), whole-pixel glyphs, the
    // contrast gain on the text's own coverage (`AaTextStyle::contrast`,
    // the rest of the frame untouched), plain Floyd-Steinberg.
    let style = FontStyle::<1>::new(font, size, [4095]).with_sharpen(Sharpen::GRID);
    let mut chars: Vec<char> = (0x20u8..0x7f).map(char::from).collect();
    chars.push('°');
    let built = Built::with_scale(font, size, style.scale(), &chars, 1);
    let rf = built.font();
    let raster = |shift: u8| {
        RasterText::new(LINES, AT, &rf, [4095])
            .with_baseline(Baseline::Top)
            .with_grid(true)
            .with_contrast(shift)
    };
    let rg = gray_of(|c| raster(0).draw(c).map(|_| ()));
    let fs_raster = |shift: u8| {
        let (mut err, mut bits) = ([0i16; 128], [false; 128]);
        oled_of(DiffusionProfile::new(&mut err, &mut bits), |c| {
            raster(shift).draw(c).map(|_| ())
        })
    };
    out.push(("FS, rasterized ahead, grid", measure(&rg, &fs_raster(0))));
    out.push((
        "FS, rasterized ahead, grid + text contrast x4",
        measure(&rg, &fs_raster(2)),
    ));
    out
}

#[test]
fn one_bit_text_at_10_to_12_px_stays_legible_with_grid_and_boost() {
    let font = Font::bundled().unwrap();
    println!("| size | rendering | strokes dropped | edge noise | specks |");
    println!("| --- | --- | --- | --- | --- |");
    for size in [10u16, 11, 12] {
        let v = variants(&font, size);
        for (name, m) in &v {
            println!(
                "| {size} px | {name} | {} of {} ({:.1} %) | {:.1} % | {} |",
                m.dropped,
                m.strokes,
                100.0 * m.dropped as f64 / m.strokes as f64,
                m.noise,
                m.specks
            );
        }
        let get = |n: &str| v.iter().find(|(k, _)| *k == n).unwrap().1;
        let (plain, best, bayer) = (
            get("Floyd-Steinberg"),
            get("FS + GRID + boost x4"),
            get("Bayer 8x8"),
        );
        let rate = |m: Legibility| m.dropped as f64 / m.strokes as f64;
        // Grid fitting and the boost: a quarter of the edge noise, no more
        // lost strokes than plain error diffusion, no specks.
        assert!(
            best.noise < plain.noise / 4.0,
            "{size}: {best:?} vs {plain:?}"
        );
        assert!(
            rate(best) <= rate(plain) + 0.005,
            "{size}: {best:?} vs {plain:?}"
        );
        assert!(best.specks <= 1);
        // Ordered dithering loses strokes: the worst of all.
        assert!(rate(bayer) > rate(plain));
        // The font rasterized ahead, grid-fitted, with the text's own
        // contrast gain: about as legible as the outline's grid and frame
        // boost (no more lost strokes than plain error diffusion, under a
        // third of its edge noise, no specks).
        let ahead = get("FS, rasterized ahead, grid + text contrast x4");
        assert!(
            ahead.noise < plain.noise / 3.0,
            "{size}: {ahead:?} vs {plain:?}"
        );
        assert!(
            rate(ahead) <= rate(plain) + 0.005,
            "{size}: {ahead:?} vs {plain:?}"
        );
        assert!(ahead.specks <= 1);
    }
}
