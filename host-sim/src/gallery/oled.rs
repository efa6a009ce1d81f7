//! A 128x64 1-bit OLED (SSD1306): anti-aliased Gouraud shapes dithered to
//! on/off pixels, as the firmware does it.
//!
//! The frame is drawn band by band, 8 rows per band (one SSD1306 page);
//! each resolved row goes straight to the ditherers of `softedge::tone`:
//!
//! - [`Bayer8`]: ordered, stateless;
//! - [`FloydSteinberg`]: error diffusion over one error row that lives for
//!   the whole frame, so the error of a page's last row flows into the next
//!   page (a new error row per page would leave a seam every 8 rows).
//!
//! Both dither linear light, so the fraction of lit pixels is the
//! anti-aliased intensity. Beside them: the same shapes drawn aliased, a
//! pixel lit wherever a shape covers its centre (what a plain 1-bit
//! renderer shows), and the anti-aliased linear frame in gray for
//! reference.

use std::f64::consts::PI;

use softedge::tone::{Bayer8, FloydSteinberg};
use softedge::{BandBuffer, Bands, DrawError, Line, RenderStyle, Triangle, LIN_MAX};

use super::{lin, sp};
use crate::image::{Channels, Image8, LinImage};

/// SSD1306 geometry.
pub(super) const WIDTH: u16 = 128;
pub(super) const HEIGHT: u16 = 64;
/// Rows per band: one SSD1306 page.
pub(super) const PAGE_ROWS: u16 = 8;

/// The shapes: Gouraud triangles and 1-px lines, no text.
#[derive(Debug, Clone, Default)]
pub(super) struct Shapes {
    triangles: Vec<Triangle<1>>,
    lines: Vec<Line<1>>,
}

impl Shapes {
    fn draw(&self, buf: &mut BandBuffer<'_, 1>, style: &RenderStyle) -> Result<(), DrawError> {
        for t in &self.triangles {
            t.draw(buf, style)?;
        }
        for l in &self.lines {
            l.draw(buf, style)?;
        }
        Ok(())
    }
}

/// The scene: a shaded triangle, a shaded disc (fan of 32 around a white
/// centre), a starburst of lines, a ramp bar and thin slivers.
pub(super) fn shapes() -> Shapes {
    let mut s = Shapes::default();
    s.triangles.push(Triangle::new(
        [sp(3.3, 3.6), sp(44.7, 8.2), sp(12.4, 46.9)],
        [[LIN_MAX], [lin(0.35)], [lin(0.08)]],
    ));
    let (cx, cy, r) = (66.4, 26.3, 21.0);
    let n = 32;
    for k in 0..n {
        let a0 = f64::from(k) * 2.0 * PI / f64::from(n);
        let a1 = f64::from(k + 1) * 2.0 * PI / f64::from(n);
        // Lit from the upper left: the rim is brighter on that side.
        let rim = |a: f64| [lin(0.12 + 0.5 * (1.0 - (a + PI / 4.0).cos()) / 2.0)];
        s.triangles.push(Triangle::new(
            [
                sp(cx - 6.0, cy - 6.0),
                sp(cx + r * a0.cos(), cy + r * a0.sin()),
                sp(cx + r * a1.cos(), cy + r * a1.sin()),
            ],
            [[LIN_MAX], rim(a0), rim(a1)],
        ));
    }
    let (lx, ly) = (108.3, 24.2);
    for k in 0..12 {
        let a = f64::from(k) * PI / 12.0 + 0.1;
        s.lines.push(Line::new(
            sp(lx + 4.0 * a.cos(), ly + 4.0 * a.sin()),
            sp(lx + 18.0 * a.cos(), ly + 18.0 * a.sin()),
            [[LIN_MAX], [lin(0.3)]],
        ));
    }
    // A ramp bar across the bottom, two triangles.
    let (x0, x1, y0, y1) = (3.0, 125.0, 52.0, 61.0);
    let (dark, light) = ([0], [LIN_MAX]);
    s.triangles.push(Triangle::new(
        [sp(x0, y0), sp(x1, y0), sp(x1, y1)],
        [dark, light, light],
    ));
    s.triangles.push(Triangle::new(
        [sp(x0, y0), sp(x1, y1), sp(x0, y1)],
        [dark, light, dark],
    ));
    // Slivers, 1/2 and 1 px at the wide end.
    for (k, t) in [0.5, 1.0].into_iter().enumerate() {
        let y = 44.0 + 3.5 * k as f64;
        s.triangles.push(Triangle::flat(
            [sp(46.0, y + t / 2.0), sp(125.0, y), sp(125.0, y + t)],
            [LIN_MAX],
        ));
    }
    s
}

/// The four renderings of the frame.
pub(super) struct Oled {
    /// Anti-aliased, linear (the reference the 1-bit pictures approximate).
    pub linear: LinImage<1>,
    /// Aliased, lit where a shape covers the pixel centre.
    pub aliased: Vec<bool>,
    /// Anti-aliased, Bayer 8x8.
    pub bayer: Vec<bool>,
    /// Anti-aliased, Floyd–Steinberg with the error row carried across
    /// pages.
    pub floyd: Vec<bool>,
}

/// Renders the frame page by page into all four.
pub(super) fn render(shapes: &Shapes) -> Result<Oled, DrawError> {
    let (w, h) = (WIDTH, HEIGHT);
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, PAGE_ROWS)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, PAGE_ROWS)];
    let mut row = vec![[0u16; 1]; usize::from(w)];
    let n = usize::from(w) * usize::from(h);
    let mut out = Oled {
        linear: LinImage::new(u32::from(w), u32::from(h)),
        aliased: vec![false; n],
        bayer: vec![false; n],
        floyd: vec![false; n],
    };
    let bayer = Bayer8::new();
    // One error row for the whole frame, outliving every page.
    let mut err = vec![0i16; usize::from(w)];
    let mut fs = FloydSteinberg::new(&mut err);
    for (style, aa) in [
        (RenderStyle::ALIASED, false),
        (RenderStyle::default(), true),
    ] {
        for band in Bands::new(w, h, PAGE_ROWS) {
            // Buffers sized for these bands: `new` cannot fail.
            let Ok(mut buf) = BandBuffer::<1>::new(&mut acc, &mut cover, band) else {
                continue;
            };
            buf.clear([0]);
            shapes.draw(&mut buf, &style)?;
            for y in band.y0..band.y0 + i32::from(band.rows) {
                let k = buf.resolve_row(y, &mut row);
                let at = y as usize * usize::from(w);
                let bits = at..at + k;
                if aa {
                    out.linear.set_row(y as u32, &row[..k]);
                    bayer.row(&row[..k], 0, y, &mut out.bayer[bits.clone()]);
                    fs.row(&row[..k], &mut out.floyd[bits]);
                } else {
                    for (o, [v]) in out.aliased[bits].iter_mut().zip(&row[..k]) {
                        // The background is 0: anything drawn lights it.
                        *o = *v > 0;
                    }
                }
            }
        }
    }
    Ok(out)
}

/// Lit OLED pixel colour (a white SSD1306) and an unlit one.
const LIT: [u8; 3] = [235, 245, 255];
const DARK: [u8; 3] = [8, 8, 10];

/// 1-bit pixels as an RGB image.
pub(super) fn show(bits: &[bool]) -> Image8 {
    let data = bits
        .iter()
        .flat_map(|&on| if on { LIT } else { DARK })
        .collect();
    Image8::from_raw(u32::from(WIDTH), u32::from(HEIGHT), Channels::Rgb, data)
        .unwrap_or_else(|| Image8::new(1, 1, Channels::Rgb, &DARK))
}

/// Fraction of pixels lit.
pub(super) fn lit_fraction(bits: &[bool]) -> f64 {
    bits.iter().filter(|&&b| b).count() as f64 / bits.len().max(1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dithered_pictures_keep_the_linear_light() {
        let o = render(&shapes()).unwrap();
        let mean = o.linear.sum() as f64 / f64::from(LIN_MAX) / o.bayer.len() as f64;
        for (name, bits) in [("bayer", &o.bayer), ("floyd", &o.floyd)] {
            let f = lit_fraction(bits);
            // Bayer 8x8 has 65 levels: a flat area is within 1/128 of its
            // intensity; error diffusion keeps the light to the frame's edge.
            assert!((f - mean).abs() < 1.0 / 128.0, "{name}: {f} vs {mean}");
        }
        assert_ne!(o.bayer, o.aliased);
        assert_ne!(o.floyd, o.bayer);
    }

    #[test]
    fn error_row_crosses_pages() {
        // The same frame dithered row by row in one go: identical, so the
        // page loop carried the error exactly as one frame-long pass does.
        let o = render(&shapes()).unwrap();
        let mut err = vec![0i16; usize::from(WIDTH)];
        let mut fs = FloydSteinberg::new(&mut err);
        let mut bits = vec![false; o.floyd.len()];
        let mut row = vec![[0u16; 1]; usize::from(WIDTH)];
        for y in 0..u32::from(HEIGHT) {
            for (x, px) in row.iter_mut().enumerate() {
                *px = *o.linear.get(x as u32, y);
            }
            let at = y as usize * usize::from(WIDTH);
            fs.row(&row, &mut bits[at..at + usize::from(WIDTH)]);
        }
        assert_eq!(bits, o.floyd);
    }
}
