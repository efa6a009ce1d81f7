//! Image 18: images as a paint (`softedge::image`): a needle sprite with
//! alpha rotated on a dial (bilinear, linear light, its outline by exact
//! area), and a row of 1-bpp icons tinted and scaled 1x to 3x, beside
//! embedded-graphics' own aliased `Image` of the same icons.

use embedded_graphics::image::{Image, ImageRaw};
use embedded_graphics::pixelcolor::{BinaryColor, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Arc, Circle};
use softedge::band::{BandBuffer, Bands};
use softedge::canvas::Canvas;
use softedge::draw::{AaDrawable, AaStyle};
use softedge::geom::FinePoint;
use softedge::image::{format, AaImage, RawImage, Scale};
use softedge::path::{Degrees, LineCap};

use super::{compose, GalleryError, Panel};
use crate::image::{Image8, LinImage};

/// The needle: 8x56 texels of RGBA, a tapered red blade with a soft edge
/// (its alpha falls off over one texel) and a light hub at texel row 44.
fn needle() -> Vec<u8> {
    let (w, h) = (8usize, 56usize);
    let mut d = vec![0u8; w * h * 4];
    for j in 0..h {
        // Half-width of the blade, texels: 0.5 at the tip to 3.5 at the hub.
        let half = 0.5 + 3.0 * (j as f64 / 44.0).min(1.0);
        for i in 0..w {
            let x = (i as f64 + 0.5 - 4.0).abs();
            let (hx, hy) = (i as f64 + 0.5 - 4.0, j as f64 + 0.5 - 44.0);
            let hub = (hx * hx + hy * hy).sqrt();
            let blade = (half - x + 0.5).clamp(0.0, 1.0) * if j < 52 { 1.0 } else { 0.0 };
            let hub_a = (4.0 - hub + 0.5).clamp(0.0, 1.0);
            let a = blade.max(hub_a);
            let k = 4 * (j * w + i);
            let (r, g, b) = if hub_a > 0.5 {
                (230, 230, 220)
            } else {
                (255, 70, 40)
            };
            d[k..k + 4].copy_from_slice(&[r, g, b, (a * 255.0).round() as u8]);
        }
    }
    d
}

/// Four 16x16 1-bpp icons side by side (64x16, 8 bytes a row): a ring, a
/// plus, a bell-like arch, three bars.
fn icons() -> Vec<u8> {
    let mut d = vec![0u8; 8 * 16];
    for j in 0..16i32 {
        for i in 0..64i32 {
            let (k, x) = (i / 16, i % 16);
            let (dx, dy) = (2 * x + 1 - 16, 2 * j + 1 - 16);
            let r2 = dx * dx + dy * dy;
            let on = match k {
                0 => (4 * 4 * 4..=4 * 7 * 7).contains(&r2),
                1 => (dx.abs() <= 3 && dy.abs() <= 13) || (dy.abs() <= 3 && dx.abs() <= 13),
                2 => {
                    ((4..=12).contains(&j) && r2 <= 4 * 6 * 6 && (dy < 0 || (2..=13).contains(&x)))
                        || (j == 13 && (2..=13).contains(&x))
                }
                _ => {
                    let bar = x / 5;
                    x < 15 && x % 5 < 3 && j >= 12 - 4 * bar && j < 15
                }
            };
            if on {
                d[(j * 8 + i / 8) as usize] |= 0x80 >> (i % 8);
            }
        }
    }
    d
}

/// A linear image drawn by `draw` through the canvas, band by band.
fn canvas_image(
    w: u16,
    h: u16,
    bg: [u16; 3],
    mut draw: impl FnMut(&mut Canvas<'_, '_, 3, Rgb888>),
) -> LinImage<3> {
    let rows = 8;
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
    let mut img = LinImage::new(u32::from(w), u32::from(h));
    let mut row = vec![[0u16; 3]; usize::from(w)];
    for band in Bands::new(w, h, rows) {
        let Ok(mut buf) = BandBuffer::<3>::new(&mut acc, &mut cover, band) else {
            continue;
        };
        buf.clear(bg);
        {
            let mut canvas = Canvas::typed(&mut buf, None).with_frame(w, h);
            draw(&mut canvas);
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            let n = buf.resolve_row(y, &mut row);
            img.set_row(y as u32, &row[..n]);
        }
    }
    img
}

/// Image 18.
pub(super) fn images_sheet(scale: u32) -> Result<Image8, GalleryError> {
    let bad = |detail: String| GalleryError::Geometry {
        image: "18-images",
        object: "image",
        detail,
    };
    let needle_px = needle();
    let needle =
        RawImage::<format::Rgba8888>::new(&needle_px, 8, 56).map_err(|e| bad(e.to_string()))?;
    let icon_px = icons();
    let icons =
        RawImage::<format::Alpha1>::new(&icon_px, 64, 16).map_err(|e| bad(e.to_string()))?;
    let bg = softedge::color::IntoLinear::<3>::into_linear(Rgb888::new(0x18, 0x1c, 0x24));
    let face = Rgb888::new(0x24, 0x2c, 0x38);
    let track = Rgb888::new(0x38, 0x44, 0x54);
    // Three dials, the needle at three readings.
    let mut err = None;
    let dials = canvas_image(240, 80, bg, |c| {
        for (k, angle) in [-100i32, -25, 62].into_iter().enumerate() {
            let cx = 40 + 80 * k as i32;
            let r = Circle::with_center(Point::new(cx, 40), 72)
                .into_styled(AaStyle::with_fill(face))
                .draw(c);
            let r = r.and(
                Arc::with_center(Point::new(cx, 40), 60, 135.0.deg(), 270.0.deg())
                    .into_styled(AaStyle::with_stroke(track, 4).cap(LineCap::Round))
                    .draw(c),
            );
            // The needle's hub (texel row 44, centre column) on the dial's
            // centre, turned about it.
            let r = r.and(
                AaImage::new(&needle)
                    .pivot(FinePoint::new(4 * 1024, 44 * 1024 + 512))
                    .position(FinePoint::from_px(cx, 40))
                    .scale(Scale::from_ratio(3, 5))
                    .rotate(Degrees::new(angle))
                    .name("needle")
                    .draw(c),
            );
            if let Err(e) = r {
                err.get_or_insert(e);
            }
        }
    });
    // The icons tinted at 1x, 1.5x, 2x and 3x.
    let tints = [
        Rgb888::new(0x40, 0xd0, 0x90),
        Rgb888::new(0xf0, 0xb0, 0x30),
        Rgb888::new(0x60, 0xa0, 0xff),
        Rgb888::new(0xff, 0x60, 0x60),
    ];
    let row = canvas_image(500, 60, bg, |c| {
        let mut x = 4 * 1024;
        for (k, s) in [(2u32, 2u32), (3, 2), (4, 2), (6, 2)]
            .into_iter()
            .enumerate()
        {
            let sc = Scale::from_ratio(s.0, s.1);
            let w = 64 * sc.bits() as i32 / 64;
            let r = AaImage::new(&icons)
                .position(FinePoint::new(x, 30 * 1024 - 8 * sc.bits() as i32 / 64))
                .scale(sc)
                .tint(tints[k])
                .name("icons")
                .draw(c);
            if let Err(e) = r {
                err.get_or_insert(e);
            }
            x += w + 4 * 1024;
        }
    });
    // embedded-graphics' own Image of the same icons, 1x, aliased.
    let raw = ImageRaw::<BinaryColor>::new(&icon_px, 64);
    let eg = canvas_image(72, 24, bg, |c| {
        let mut on = softedge_eg_target(c);
        let _ = Image::new(&raw, Point::new(4, 4)).draw(&mut on);
    });
    if let Some(e) = err {
        return Err(bad(e.to_string()));
    }
    Ok(compose(
        "IMAGES: A NEEDLE SPRITE WITH ALPHA, ROTATED, AND 1-BPP ICONS TINTED AND SCALED",
        &[
            vec![Panel::new(
                "ROTATED NEEDLE SPRITE (BILINEAR, LINEAR LIGHT)",
                dials.to_srgb8(),
                scale,
            )],
            vec![
                Panel::new("ICONS TINTED: 1X, 1.5X, 2X, 3X", row.to_srgb8(), scale),
                Panel::new("E-G IMAGE, 1X", eg.to_srgb8(), scale),
            ],
        ],
    ))
}

/// The canvas as an embedded-graphics target of `BinaryColor` (on: white,
/// off: nothing drawn), for e-g's `Image` of a 1-bpp `ImageRaw`.
fn softedge_eg_target<'a, 'c, 'b>(c: &'a mut Canvas<'c, 'b, 3, Rgb888>) -> OnOff<'a, 'c, 'b> {
    OnOff(c)
}

struct OnOff<'a, 'c, 'b>(&'a mut Canvas<'c, 'b, 3, Rgb888>);

impl OriginDimensions for OnOff<'_, '_, '_> {
    fn size(&self) -> Size {
        self.0.size()
    }
}

impl DrawTarget for OnOff<'_, '_, '_> {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        pixels: I,
    ) -> Result<(), Self::Error> {
        self.0.draw_iter(
            pixels
                .into_iter()
                .filter(|p| p.1.is_on())
                .map(|Pixel(p, _)| Pixel(p, Rgb888::new(0x40, 0xd0, 0x90))),
        )
    }
}
