//! Colours in (issue #15): the sRGB decoding tables against the IEC
//! 61966-2-1 formula written here in `f64`, the Rec. 709 luminance against
//! its exact weights, and the round trip sRGB code → linear 12-bit → the
//! sRGB display's γ table → the same code, for every code of every width.

use embedded_graphics_core::pixelcolor::{Gray4, Gray8, Rgb565, Rgb888};
use softedge::color::srgb::{luminance, srgb_to_lin12, LUMA_WEIGHTS};
use softedge::color::{
    IntoLinear, LinGray, LinRgb, SRGB2_TO_LIN12, SRGB4_TO_LIN12, SRGB5_TO_LIN12, SRGB6_TO_LIN12,
    SRGB8_TO_LIN12,
};
use softedge::tone::format::{Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat};
use softedge::tone::{Curve, GammaLut};

/// The sRGB decoding function `L(V)` (IEC 61966-2-1), linear light in `[0, 1]`.
fn srgb_decode(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

/// Every table with its width.
fn tables() -> [(u32, &'static [u16]); 5] {
    [
        (8, &SRGB8_TO_LIN12),
        (6, &SRGB6_TO_LIN12),
        (5, &SRGB5_TO_LIN12),
        (4, &SRGB4_TO_LIN12),
        (2, &SRGB2_TO_LIN12),
    ]
}

#[test]
fn every_table_entry_is_within_half_a_step_of_the_srgb_formula() {
    for (bits, table) in tables() {
        let max = (1u32 << bits) - 1;
        assert_eq!(table.len(), max as usize + 1);
        let mut worst = 0.0f64;
        for (c, &lin) in table.iter().enumerate() {
            let exact = 4095.0 * srgb_decode(c as f64 / f64::from(max));
            let err = (f64::from(lin) - exact).abs();
            assert!(err <= 0.5, "{bits}-bit code {c}: {lin} vs {exact}");
            // Correctly rounded (halves up) wherever the formula is not
            // within 1e-6 of a midpoint.
            if (exact.fract() - 0.5).abs() > 1e-6 {
                assert_eq!(
                    f64::from(lin),
                    exact.round(),
                    "{bits}-bit code {c}: {exact}"
                );
            }
            assert_eq!(srgb_to_lin12(c as u32, max), lin);
            worst = worst.max(err);
        }
        println!("{bits}-bit table: largest |entry - 4095 L(c / {max})| = {worst:.4}");
    }
}

#[test]
fn luminance_is_rec_709_within_its_rounding() {
    let w = [0.2126, 0.7152, 0.0722];
    let wq = LUMA_WEIGHTS.map(|x| f64::from(x) / 65536.0);
    let weight_err: f64 = (0..3).map(|k| (wq[k] - w[k]).max(0.0)).sum::<f64>() * 4095.0;
    let mut worst = 0.0f64;
    let step = 63;
    for r in (0..=4095u16).step_by(step).chain([4095]) {
        for g in (0..=4095u16).step_by(step).chain([4095]) {
            for b in (0..=4095u16).step_by(step).chain([4095]) {
                let y = luminance([r, g, b]);
                let exact = w[0] * f64::from(r) + w[1] * f64::from(g) + w[2] * f64::from(b);
                let err = (f64::from(y) - exact).abs();
                assert!(err <= 0.5 + weight_err, "{r} {g} {b}: {y} vs {exact}");
                worst = worst.max(err);
            }
        }
    }
    println!("luminance: largest |Y - exact Rec. 709| = {worst:.4} (bound 0.5 + {weight_err:.4})");
}

#[test]
fn luminance_of_a_gray_is_the_gray() {
    for v in 0..=4095 {
        assert_eq!(luminance([v; 3]), v);
    }
}

#[test]
fn srgb_808080_comes_back_as_code_128() {
    let lut = GammaLut::new(Curve::Srgb);
    let rgb = LinRgb::from_hex("#808080").unwrap();
    assert_eq!(rgb.lin12().map(|v| lut.code(v)), [128; 3]);
    let eg: [u16; 3] = Rgb888::new(128, 128, 128).into_linear();
    assert_eq!(eg, rgb.lin12());
    let [y] = LinGray::from_hex("#808080").unwrap().lin12();
    assert_eq!(lut.code(y), 128);
}

#[test]
fn every_code_of_every_width_survives_the_round_trip_through_lin12() {
    for (bits, table) in tables() {
        let lut = GammaLut::with_bits(Curve::Srgb, bits as u8);
        let failed: Vec<usize> = table
            .iter()
            .enumerate()
            .filter(|&(c, &lin)| usize::from(lut.code(lin)) != c)
            .map(|(c, _)| c)
            .collect();
        assert!(
            failed.is_empty(),
            "{bits}-bit codes not returned: {failed:?}"
        );
    }
}

#[test]
fn every_rgb565_colour_comes_back_from_the_rgb565_format() {
    let f = Rgb565Format::new(Curve::Srgb);
    for raw in 0..=u16::MAX {
        let c = Rgb565::new((raw >> 11) as u8, (raw >> 5) as u8 & 63, raw as u8 & 31);
        assert_eq!(f.color(c.into_linear()), c, "{raw:#06x}");
    }
}

#[test]
fn every_rgb888_gray8_and_gray4_code_comes_back_from_its_format() {
    let rgb = Rgb888Format::new(Curve::Srgb);
    let g8 = Gray8Format::new(Curve::Srgb);
    let g4 = Gray4Format::new(Curve::Srgb);
    for v in 0..=255u8 {
        // Channels are independent: cycle the three through different codes.
        let c = Rgb888::new(v, v.wrapping_mul(7), 255 - v);
        assert_eq!(rgb.color(c.into_linear()), c);
        assert_eq!(g8.color(Gray8::new(v).into_linear()), Gray8::new(v));
    }
    for v in 0..=15u8 {
        assert_eq!(g4.color(Gray4::new(v).into_linear()), Gray4::new(v));
    }
}

#[test]
fn an_rgb_colour_on_a_gray_display_is_its_luminance() {
    let [y] = LinGray::from_hex("#ff0000").unwrap().lin12();
    // 0.2126 * 4095 = 870.6
    assert_eq!(y, 871);
    let from_eg: [u16; 1] = Rgb888::new(255, 0, 0).into_linear();
    assert_eq!(from_eg, [871]);
    let from_565: [u16; 1] = Rgb565::new(31, 0, 0).into_linear();
    assert_eq!(from_565, [871]);
}
