//! Seed 000: small moving objects must neither flicker nor pulse.
//!
//! A 1x1 px square and a short 1-px line are moved over all 16x16 sub-pixel
//! offsets (1/16 px steps). The accumulation must keep their summed linear
//! intensity constant (equal energy of the box filter), and after the γ
//! table the brightness a γ = 2.4 display emits must stay constant too;
//! sending linear codes straight to the display must show the seed's large
//! error (an object split over two pixels loses up to 62 %).

use softedge::tone::{Curve, GammaLut};
use softedge::{BandBuffer, Bands, Line, RenderStyle, SubPoint, Triangle};

const W: u16 = 12;
const H: u16 = 12;
const ROWS: u16 = 5;

/// Linear 12-bit frame of one object drawn at sub-pixel offset (dx, dy).
fn frame(draw: &dyn Fn(&mut BandBuffer<'_, 1>)) -> Vec<u16> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, ROWS)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, ROWS)];
    let mut out = vec![0u16; usize::from(W) * usize::from(H)];
    let mut row = vec![[0u16; 1]; usize::from(W)];
    for band in Bands::new(W, H, ROWS) {
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([0]);
        draw(&mut buf);
        for y in band.y0..band.y0 + i32::from(band.rows) {
            buf.resolve_row(y, &mut row);
            let start = y as usize * usize::from(W);
            for (o, v) in out[start..start + usize::from(W)].iter_mut().zip(&row) {
                *o = v[0];
            }
        }
    }
    out
}

/// Brightness a γ = 2.4 display emits for 8-bit codes, summed, in units of
/// one fully lit pixel.
fn emitted(codes: impl Iterator<Item = u8>) -> f64 {
    codes.map(|c| (f64::from(c) / 255.0).powf(2.4)).sum()
}

/// Relative spread (max / min - 1 and min / mean - 1) of a series.
fn spread(v: &[f64]) -> (f64, f64) {
    let mean = v.iter().sum::<f64>() / v.len() as f64;
    let max = v.iter().cloned().fold(f64::MIN, f64::max);
    let min = v.iter().cloned().fold(f64::MAX, f64::min);
    (max / mean - 1.0, min / mean - 1.0)
}

struct Measured {
    linear: Vec<f64>,
    corrected: Vec<f64>,
    uncorrected: Vec<f64>,
}

fn measure(object: impl Fn(i32, i32) -> Box<dyn Fn(&mut BandBuffer<'_, 1>)>) -> Measured {
    static LUT: GammaLut = GammaLut::new(Curve::GAMMA_2_4);
    let mut m = Measured {
        linear: vec![],
        corrected: vec![],
        uncorrected: vec![],
    };
    for dy in 0..16 {
        for dx in 0..16 {
            let f = frame(&*object(dx, dy));
            m.linear
                .push(f.iter().map(|&v| f64::from(v) / 4095.0).sum());
            m.corrected.push(emitted(f.iter().map(|&v| LUT.code(v))));
            m.uncorrected
                .push(emitted(f.iter().map(|&v| (v >> 4) as u8)));
        }
    }
    m
}

fn square(dx: i32, dy: i32) -> Box<dyn Fn(&mut BandBuffer<'_, 1>)> {
    Box::new(move |b| {
        let (x, y) = (5 * 16 + dx, 5 * 16 + dy);
        let p = |u: i32, v: i32| SubPoint::new(x + u, y + v);
        for t in [
            [p(0, 0), p(16, 0), p(16, 16)],
            [p(0, 0), p(16, 16), p(0, 16)],
        ] {
            Triangle::flat(t, [4095])
                .draw(b, &RenderStyle::default())
                .unwrap();
        }
    })
}

fn short_line(dx: i32, dy: i32) -> Box<dyn Fn(&mut BandBuffer<'_, 1>)> {
    Box::new(move |b| {
        let from = SubPoint::new(4 * 16 + dx, 5 * 16 + dy);
        let to = SubPoint::new(from.x + 40, from.y + 24);
        Line::new(from, to, [[4095], [4095]])
            .draw(b, &RenderStyle::default())
            .unwrap();
    })
}

fn check(name: &str, m: &Measured) {
    let lin = spread(&m.linear);
    let cor = spread(&m.corrected);
    let unc = spread(&m.uncorrected);
    println!(
        "{name}: linear sum {:+.3} % / {:+.3} %, γ-corrected emitted {:+.2} % / {:+.2} %, uncorrected {:+.1} % / {:+.1} %",
        lin.0 * 100.0,
        lin.1 * 100.0,
        cor.0 * 100.0,
        cor.1 * 100.0,
        unc.0 * 100.0,
        unc.1 * 100.0
    );
    assert!(
        lin.0 < 0.005 && lin.1 > -0.005,
        "{name}: linear sum flickers: {lin:?}"
    );
    assert!(
        cor.0 < 0.01 && cor.1 > -0.01,
        "{name}: corrected brightness flickers: {cor:?}"
    );
    // Without the table the same frames pulse at least ten times as much
    // (peak to peak): the seed's reason for γ correction.
    assert!(
        unc.0 - unc.1 > 0.15 && unc.0 - unc.1 > 10.0 * (cor.0 - cor.1),
        "{name}: uncorrected display should pulse strongly: {unc:?} vs corrected {cor:?}"
    );
}

#[test]
fn small_square_keeps_its_energy_at_every_sub_pixel_offset() {
    check("1x1 square", &measure(square));
}

#[test]
fn short_line_keeps_its_energy_at_every_sub_pixel_offset() {
    check("short line", &measure(short_line));
}

#[test]
fn square_split_over_two_pixels_loses_62_percent_without_correction() {
    // Offset by half a pixel in x: two pixels at S = 1/2 each.
    let f = frame(&*square(8, 0));
    let lit: Vec<u16> = f.iter().copied().filter(|&v| v > 0).collect();
    assert_eq!(lit, [2048, 2048]);
    let uncorrected = emitted(lit.iter().map(|&v| (v >> 4) as u8));
    assert!(
        (uncorrected - 0.38).abs() < 0.01,
        "B = 2 * (1/2)^2.4 = 0.379, got {uncorrected}"
    );
    static LUT: GammaLut = GammaLut::new(Curve::GAMMA_2_4);
    let corrected = emitted(lit.iter().map(|&v| LUT.code(v)));
    assert!((corrected - 1.0).abs() < 0.01, "corrected: {corrected}");
}
