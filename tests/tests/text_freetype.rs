//! Text against FreeType's unhinted rasterizer: `tests/data/freetype_ref.txt`
//! holds FreeType 2.13's rendering (no hinting, 8-bit coverage) of glyphs
//! of the bundled font at 8, 12, 24 and 48 px, at origins on the 1/8-px
//! grid, rendered 8 times larger and summed over 8x8 blocks (FreeType's
//! own flattening error divided by 8); `tests/data/make_freetype_ref.py`
//! regenerates it. Each pixel softedge draws must be within 1/32 of
//! FreeType's, and each glyph's summed intensity within 0.5 %.

use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::style::{Blend, FillRule, Opacity};
use softedge::text::{Font, GlyphRun, Scale, TextSize};
use softedge::{Band, BandBuffer};

const DATA: &str = include_str!("../data/freetype_ref.txt");
/// A pixel's sum when FreeType covers it fully: 64 samples of 255.
const FULL: f64 = 64.0 * 255.0;

struct Case {
    size: u16,
    ch: char,
    origin: FinePoint,
    x0: i32,
    y0: i32,
    w: i32,
    h: i32,
    cov: Vec<f64>,
}

fn cases() -> Vec<Case> {
    DATA.lines()
        .filter(|l| !l.starts_with('#') && !l.is_empty())
        .map(|l| {
            let f: Vec<&str> = l.split_whitespace().collect();
            let n = |i: usize| f[i].parse::<i32>().unwrap();
            let (w, h) = (n(6), n(7));
            let hex = f.get(8).copied().unwrap_or("");
            let cov = (0..(w * h) as usize)
                .map(|k| f64::from(u16::from_str_radix(&hex[4 * k..4 * k + 4], 16).unwrap()) / FULL)
                .collect();
            Case {
                size: n(0) as u16,
                ch: char::from_u32(n(1) as u32).unwrap(),
                origin: FinePoint::new(n(2), n(3)),
                x0: n(4),
                y0: n(5),
                w,
                h,
                cov,
            }
        })
        .collect()
}

#[test]
fn glyphs_agree_with_freetype_within_a_32nd_per_pixel() {
    let font = Font::bundled().unwrap();
    let cases = cases();
    assert_eq!(cases.len(), 53);
    let mut worst = [0.0f64; 4];
    let mut worst_sum = [0.0f64; 4];
    for c in &cases {
        let (w, h) = (c.size * 3 + 16, c.size * 3 + 16);
        let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
        let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(w, 0, h)).unwrap();
        buf.clear([0]);
        let mut canvas = Canvas::new(&mut buf, None);
        let mut s = [0u8; 4];
        let scale = Scale::new(TextSize::px(c.size), font.units_per_em());
        let run = GlyphRun::new(&font, c.ch.encode_utf8(&mut s), c.origin, scale);
        canvas
            .fill(
                &run,
                [4095],
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        let k = match c.size {
            8 => 0,
            12 => 1,
            24 => 2,
            _ => 3,
        };
        let (mut ours_sum, mut ft_sum) = (0.0, 0.0);
        for y in 0..i32::from(h) {
            for x in 0..i32::from(w) {
                let ours = f64::from(canvas.buffer().lin12(x, y).unwrap()[0]) / 4095.0;
                let (i, j) = (x - c.x0, y - c.y0);
                let ft = if (0..c.w).contains(&i) && (0..c.h).contains(&j) {
                    c.cov[(j * c.w + i) as usize]
                } else {
                    0.0
                };
                let e = (ours - ft).abs();
                assert!(
                    e <= 1.0 / 32.0,
                    "{:?} at {} px, pixel ({x}, {y}): {ours} vs FreeType {ft}",
                    c.ch,
                    c.size
                );
                worst[k] = worst[k].max(e);
                ours_sum += ours;
                ft_sum += ft;
            }
        }
        let rel = (ours_sum / ft_sum - 1.0).abs();
        assert!(
            rel < 0.005,
            "{:?} at {} px: {ours_sum} vs {ft_sum}",
            c.ch,
            c.size
        );
        worst_sum[k] = worst_sum[k].max(rel);
    }
    for (k, size) in [8, 12, 24, 48].iter().enumerate() {
        println!(
            "{size} px: worst pixel difference from FreeType {:.4}, worst glyph sum {:.3} %",
            worst[k],
            worst_sum[k] * 100.0
        );
    }
}
