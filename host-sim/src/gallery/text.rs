//! Images 13 and 14: text in an outline font (`softedge::text`, the bundled
//! Softedge Sans Subset) next to embedded-graphics' mono bitmap fonts.
//!
//! - 13: 8 to 48 px on an RGB TFT (linear light, shown in sRGB), the
//!   same lines in e-g's `FONT_4X6` .. `FONT_10X20`, drawn by e-g itself
//!   into an RGB image (a `DrawTarget` here), and e-g's `Text` with
//!   softedge's `AaTextStyle` in place of `MonoTextStyle`: the bundled font
//!   rasterized ahead of time at 12 and 16 px, and through a glyph cache
//!   at 20, 24 and 32 px.
//! - 14: four lines of an instrument display on a 128x64 1-bit OLED at 10,
//!   11 and 12 px through the frame loop (8-row pages): the anti-aliased
//!   gray frame, its threshold at 1/2, Bayer 8x8, Floyd–Steinberg, and
//!   Floyd–Steinberg with `Sharpen::GRID` and `ContrastBoost` (gain 4); and
//!   e-g's `FONT_6X10` and `FONT_6X13` on the same display. The
//!   measurements of these panels are `tests/tests/text_one_bit.rs`'.

use embedded_graphics::mono_font::{ascii, MonoFont, MonoTextStyle};
use embedded_graphics::pixelcolor::{BinaryColor, Rgb888, RgbColor};
use embedded_graphics::prelude::{DrawTarget, OriginDimensions, Point, Size};
use embedded_graphics::text::Text as EgText;
use embedded_graphics::{Drawable, Pixel};
use softedge::canvas::{Canvas, WalkSlot};
use softedge::color::IntoLinear;
use softedge::geom::FinePoint;
use softedge::render::Renderer;
use softedge::text::{Baseline, ContrastBoost, Font, FontStyle, Sharpen, Text, TextStyle};
use softedge::tone::profile::{DiffusionProfile, Profile};
use softedge::tone::Bayer8;
use softedge::{BandBuffer, Bands, DrawError};

use super::{compose, GalleryError, Panel};
use crate::image::{Channels, Image8, LinImage};

/// The colour panel's size.
const TFT: (u16, u16) = (330, 300);
/// The OLED.
const OLED: (u16, u16) = (128, 64);
/// Sizes of the colour panel, px.
const SIZES: [u16; 9] = [8, 10, 12, 14, 16, 20, 24, 32, 48];
/// The OLED's lines.
const LINES: &str = "Temp 23.5 °C\nHumidity 45 %\nBattery 3.71 V\nAVAWAY Ty To";

/// Buffers or the frame loop refused (a bug in the gallery).
fn setup_err(e: impl std::fmt::Debug) -> GalleryError {
    GalleryError::Geometry {
        image: "text",
        object: "buffers",
        detail: format!("{e:?}"),
    }
}

fn draw_err(source: DrawError) -> GalleryError {
    GalleryError::Draw {
        image: "text",
        source,
    }
}

/// The colour panel: one line per size, white on a dark blue, band by band.
fn tft(font: &Font<'_>, band_rows: u16) -> Result<LinImage<3>, GalleryError> {
    let (w, h) = TFT;
    let bg = softedge::color::LinRgb::from_srgb8(16, 32, 48).lin12();
    let mut img = LinImage::<3>::new(u32::from(w), u32::from(h));
    let rows = band_rows.max(1);
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
    let mut row = vec![[0u16; 3]; usize::from(w)];
    for band in Bands::new(w, h, rows) {
        let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).map_err(setup_err)?;
        buf.clear(bg);
        let mut canvas = Canvas::new(&mut buf, None);
        let mut y = 4 * 1024;
        for (k, &size) in SIZES.iter().enumerate() {
            let color = [[4095, 4095, 4095], [4095, 3000, 600], [1200, 3600, 4095]][k % 3];
            let line = match size {
                48 => format!("{size} px ±µ°C"),
                32 => format!("{size} px: AVA ±0.5"),
                24 => format!("{size} px: Quick fox 0.5 °C"),
                20 => format!("{size} px: Quick brown fox 0123"),
                16 | 14 => format!("{size} px: The quick brown fox 0123 °C"),
                _ => format!("{size} px: The quick brown fox jumps 0123 °C ±µ"),
            };
            let style = FontStyle::<3>::new(font, size, color);
            let t = Text::with_text_style(
                &line,
                FinePoint::new(4 * 1024, y),
                style,
                TextStyle::with_baseline(Baseline::Top),
            );
            t.draw(&mut canvas).map_err(draw_err)?;
            y += t.line_height() as i32;
        }
        for yy in band.y0..band.y0 + i32::from(band.rows) {
            let n = buf.resolve_row(yy, &mut row);
            img.set_row(yy as u32, &row[..n]);
        }
    }
    Ok(img)
}

/// An RGB image e-g draws into.
struct RgbTarget(Image8);

impl OriginDimensions for RgbTarget {
    fn size(&self) -> Size {
        Size::new(self.0.width(), self.0.height())
    }
}

impl DrawTarget for RgbTarget {
    type Color = Rgb888;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            self.0
                .fill_rect(i64::from(p.x), i64::from(p.y), 1, 1, &[c.r(), c.g(), c.b()]);
        }
        Ok(())
    }
}

/// The same lines in e-g's mono fonts.
fn eg_mono() -> Image8 {
    let (w, h) = TFT;
    let mut t = RgbTarget(Image8::new(
        u32::from(w),
        u32::from(h),
        Channels::Rgb,
        &[16, 32, 48],
    ));
    let fonts: [(&str, &MonoFont<'_>); 7] = [
        ("4x6", &ascii::FONT_4X6),
        ("5x8", &ascii::FONT_5X8),
        ("6x10", &ascii::FONT_6X10),
        ("7x13", &ascii::FONT_7X13),
        ("8x13", &ascii::FONT_8X13),
        ("9x15", &ascii::FONT_9X15),
        ("10x20", &ascii::FONT_10X20),
    ];
    let mut y = 4;
    for (k, (name, f)) in fonts.iter().enumerate() {
        let color = [
            Rgb888::WHITE,
            Rgb888::new(255, 225, 110),
            Rgb888::new(150, 235, 255),
        ][k % 3];
        let style = MonoTextStyle::new(f, color);
        let line = format!("{name}: The quick brown fox 0123");
        let _ = EgText::with_baseline(
            &line,
            Point::new(4, y),
            style,
            embedded_graphics::text::Baseline::Top,
        )
        .draw(&mut t);
        y += f.character_size.height as i32 + 6;
    }
    t.0
}

/// A 1-bit display's pixels.
struct Mono(Vec<bool>);

impl OriginDimensions for Mono {
    fn size(&self) -> Size {
        Size::new(u32::from(OLED.0), u32::from(OLED.1))
    }
}

impl DrawTarget for Mono {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        let (w, h) = (i32::from(OLED.0), i32::from(OLED.1));
        for Pixel(p, c) in px {
            if (0..w).contains(&p.x) && (0..h).contains(&p.y) {
                self.0[(p.y * w + p.x) as usize] = c.is_on();
            }
        }
        Ok(())
    }
}

fn mono_image(m: &Mono) -> Image8 {
    let data = m.0.iter().map(|&on| if on { 255 } else { 0 }).collect();
    Image8::from_raw(u32::from(OLED.0), u32::from(OLED.1), Channels::Gray, data)
        .unwrap_or_else(|| Image8::new(1, 1, Channels::Gray, &[0]))
}

fn oled_text<'f>(
    font: &'f Font<'static>,
    size: u16,
    sharpen: Sharpen,
) -> Text<'static, 'f, 'static, 1> {
    let style = FontStyle::<1>::new(font, size, [4095]).with_sharpen(sharpen);
    Text::with_baseline(
        LINES,
        FinePoint::new(2 * 1024 + 300, 1024 + 200),
        style,
        Baseline::Top,
    )
}

/// The text through the frame loop, 8-row pages, into `profile`.
fn oled<P: Profile<1, Color = BinaryColor>>(
    t: &Text<'_, '_, '_, 1>,
    profile: P,
) -> Result<Image8, GalleryError> {
    let (w, h) = OLED;
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, 8)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, 8)];
    let mut slots = vec![WalkSlot::<1>::EMPTY; 64];
    let mut screen = Mono(vec![false; usize::from(w) * usize::from(h)]);
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, w, h, 8).map_err(setup_err)?;
    r.render(&mut screen, profile, [0], |c| t.draw(c).map(|_| ()))
        .map_err(setup_err)?;
    Ok(mono_image(&screen))
}

/// The gray frame (one band), for the reference panels.
fn oled_gray(t: &Text<'_, '_, '_, 1>) -> Result<LinImage<1>, GalleryError> {
    let (w, h) = OLED;
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, softedge::Band::new(w, 0, h))
        .map_err(setup_err)?;
    buf.clear([0]);
    let mut c = Canvas::new(&mut buf, None);
    t.draw(&mut c).map_err(draw_err)?;
    let mut img = LinImage::<1>::new(u32::from(w), u32::from(h));
    let mut row = vec![[0u16; 1]; usize::from(w)];
    for y in 0..i32::from(h) {
        let n = c.buffer().resolve_row(y, &mut row);
        img.set_row(y as u32, &row[..n]);
    }
    Ok(img)
}

/// The e-g panel's lines again, with embedded-graphics' `Text` and
/// softedge's `AaTextStyle`: the bundled font rasterized ahead of time at
/// 12 and 16 px (`text::bundled::SANS_12`, `SANS_16`), and as an outline
/// font at 20, 24 and 32 px through a glyph cache, band by band.
fn eg_aa(font: &Font<'_>, band_rows: u16) -> Result<LinImage<3>, GalleryError> {
    use embedded_graphics::text::renderer::TextRenderer;
    use embedded_graphics::text::Baseline as EgBaseline;
    use softedge::prelude::DrawAaText;
    use softedge::text::{bundled, AaTextStyle, CachedFont, GlyphCache, TextSize, SLOT_WORDS};
    let (w, h) = TFT;
    let bg = Rgb888::new(16, 32, 48);
    let rows = band_rows.max(1);
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
    let mut img = LinImage::<3>::new(u32::from(w), u32::from(h));
    let mut row = vec![[0u16; 3]; usize::from(w)];
    // One cache a size (a cache serves one size at a time).
    let mut store: Vec<(Vec<u8>, Vec<u32>, Vec<i32>)> = (0..3)
        .map(|_| {
            (
                vec![0u8; 8192],
                vec![0u32; 128 * SLOT_WORDS],
                vec![0i32; 4096],
            )
        })
        .collect();
    let caches: Vec<GlyphCache<'_>> = store
        .iter_mut()
        .map(|(a, b, c)| GlyphCache::new(a, b, c))
        .collect();
    let colors = [
        Rgb888::WHITE,
        Rgb888::new(255, 225, 110),
        Rgb888::new(150, 235, 255),
    ];
    for band in Bands::new(w, h, rows) {
        let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).map_err(setup_err)?;
        buf.clear(bg.into_linear());
        let mut canvas: Canvas<'_, '_, 3, Rgb888> = Canvas::typed(&mut buf, None);
        let mut y = 4;
        for (k, (line, font16)) in [
            ("12 px, flash: Quick brown fox 0123 °C", &bundled::SANS_12),
            ("16 px, flash: Quick fox 0123 °C", &bundled::SANS_16),
        ]
        .into_iter()
        .enumerate()
        {
            let style = AaTextStyle::new(font16, colors[k % 3]);
            EgText::with_baseline(line, Point::new(4, y), style, EgBaseline::Top)
                .draw(&mut canvas)
                .map_err(draw_err)?;
            y += style.line_height() as i32 + 6;
        }
        for (k, ((size, line), cache)) in [
            (20u16, "20 px, cache: Quick fox"),
            (24, "24 px, cache: AVA 0.5"),
            (32, "32 px cache ±0.5"),
        ]
        .into_iter()
        .zip(&caches)
        .enumerate()
        {
            let style = AaTextStyle::new(
                CachedFont::new(font, TextSize::px(size), cache),
                colors[(k + 2) % 3],
            );
            EgText::with_baseline(line, Point::new(4, y), style, EgBaseline::Top)
                .draw(&mut canvas)
                .map_err(draw_err)?;
            y += style.line_height() as i32 + 6;
        }
        for yy in band.y0..band.y0 + i32::from(band.rows) {
            let n = buf.resolve_row(yy, &mut row);
            img.set_row(yy as u32, &row[..n]);
        }
    }
    Ok(img)
}

/// Image 13.
pub(super) fn sizes_sheet(band_rows: u16, scale: u32) -> Result<Image8, GalleryError> {
    let font = Font::bundled().map_err(|e| GalleryError::Geometry {
        image: "text",
        object: "bundled font",
        detail: e.to_string(),
    })?;
    let ours = tft(&font, band_rows)?.to_srgb8();
    let aa = eg_aa(&font, band_rows)?.to_srgb8();
    let s = (scale / 2).max(1);
    Ok(compose(
        "TEXT: SOFTEDGE SANS 8-48 PX (AA, LINEAR LIGHT) VS E-G MONO FONTS",
        &[vec![
            Panel::new("SOFTEDGE OUTLINES 8-48 PX", ours, s),
            Panel::new("E-G MONO FONTS 4X6-10X20", eg_mono(), s),
            Panel::new("E-G TEXT, SOFTEDGE AATEXTSTYLE", aa, s),
        ]],
    ))
}

/// Image 14.
pub(super) fn one_bit_sheet(scale: u32) -> Result<Image8, GalleryError> {
    let font = Font::bundled().map_err(|e| GalleryError::Geometry {
        image: "text",
        object: "bundled font",
        detail: e.to_string(),
    })?;
    let mut rows = Vec::new();
    for size in [10u16, 11, 12] {
        let exact = oled_text(&font, size, Sharpen::NONE);
        let grid = oled_text(&font, size, Sharpen::GRID);
        let gray = oled_gray(&exact)?;
        let threshold: Vec<u8> = gray
            .pixels()
            .map(|[v]| if v >= 2048 { 255 } else { 0 })
            .collect();
        let threshold = Image8::from_raw(
            u32::from(OLED.0),
            u32::from(OLED.1),
            Channels::Gray,
            threshold,
        )
        .unwrap_or_else(|| Image8::new(1, 1, Channels::Gray, &[0]));
        let (mut err, mut bits, mut scratch) = ([0i16; 128], [false; 128], [0i32; 128]);
        let fs = oled(&exact, DiffusionProfile::new(&mut err, &mut bits))?;
        let best = oled(
            &grid,
            ContrastBoost::new(DiffusionProfile::new(&mut err, &mut bits), 2, &mut scratch),
        )?;
        let bayer = oled(&exact, Bayer8::new())?;
        rows.push(vec![
            Panel::new(&format!("{size} PX GRAY (AA)"), gray.to_srgb8(), scale),
            Panel::new("THRESHOLD 1/2", threshold, scale),
            Panel::new("BAYER 8X8", bayer, scale),
            Panel::new("FLOYD-STEINBERG", fs, scale),
            Panel::new("FS + GRID + BOOST X4", best, scale),
        ]);
    }
    let mut eg = Vec::new();
    for (name, f) in [
        ("E-G FONT 6X10", &ascii::FONT_6X10),
        ("E-G FONT 6X13", &ascii::FONT_6X13),
    ] {
        let mut m = Mono(vec![false; usize::from(OLED.0) * usize::from(OLED.1)]);
        let style = MonoTextStyle::new(f, BinaryColor::On);
        let _ = EgText::with_baseline(
            LINES,
            Point::new(2, 1),
            style,
            embedded_graphics::text::Baseline::Top,
        )
        .draw(&mut m);
        eg.push(Panel::new(name, mono_image(&m), scale));
    }
    rows.push(eg);
    Ok(compose("TEXT ON A 128X64 1-BIT OLED: 10, 11, 12 PX", &rows))
}
