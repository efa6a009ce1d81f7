//! Tone pipeline (seed 000, SPEC §7): γ tables, log codes, formats,
//! dithering, bit depths. References are written here in `f64`, never taken
//! from the code under test.

use proptest::prelude::*;
use softedge::tone::format::{
    code_row, Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat,
};
use softedge::tone::*;

const CURVES: [Curve; 3] = [Curve::GAMMA_2_2, Curve::GAMMA_2_4, Curve::Srgb];

/// The seed's display: K = 100, and m = 255 gradations in an 8-bit code.
/// Tables are `const fn`s, so the tests build them once, at compile time.
const K100: LogScale = match LogScale::new(100, 255) {
    Ok(s) => s,
    Err(_) => panic!("K = 100, m = 255 is a valid scale"),
};
static GAUSS: GaussLog = match GaussLog::new(K100) {
    Ok(g) => g,
    Err(_) => panic!("the K = 100, m = 255 Gaussian-log table closes"),
};
static POT: PotentiationLut = PotentiationLut::new(K100);
static LUT_SRGB: GammaLut = GammaLut::new(Curve::Srgb);
static LUT_24: GammaLut = GammaLut::new(Curve::GAMMA_2_4);
static OUT_SRGB: LogOutputLut = LogOutputLut::new(K100, Curve::Srgb);
static OUT_24: LogOutputLut = LogOutputLut::new(K100, Curve::GAMMA_2_4);
static RGB565: Rgb565Format = Rgb565Format::new(Curve::Srgb);

/// The ideal code value for linear light `x`: the inverse of the display curve.
fn encode(curve: Curve, x: f64) -> f64 {
    match curve {
        Curve::Power(g) => {
            let (n, d) = g.ratio();
            x.powf(f64::from(d) / f64::from(n))
        }
        Curve::Srgb if x <= 0.0031308 => 12.92 * x,
        Curve::Srgb => 1.055 * x.powf(1.0 / 2.4) - 0.055,
    }
}

// ---------------------------------------------------------------- eqs. 9, 10, m

#[test]
fn seed_eq9_linear_levels_are_1980_to_4950_at_k100() {
    assert_eq!(levels(100.0, 0.05, 2.4).unwrap().n_i.round(), 1980.0);
    assert_eq!(levels(100.0, 0.02, 2.4).unwrap().n_i.round(), 4950.0);
}

#[test]
fn seed_eq10_dac_levels_are_165_to_413_at_k100_gamma_2_4() {
    let lo = levels(100.0, 0.05, 2.4).unwrap().n_u;
    let hi = levels(100.0, 0.02, 2.4).unwrap().n_u;
    assert!((lo - 165.0).abs() < 0.5, "{lo}");
    assert!((hi - 413.0).abs() < 0.5, "{hi}");
    // Independent check of the formula itself.
    let f = |d: f64| 99f64.powf(1.0 / 2.4) / d * 1.4f64.powf(1.0 - 1.0 / 2.4);
    assert!((lo - f(0.05)).abs() < 1e-9 && (hi - f(0.02)).abs() < 1e-9);
}

#[test]
fn gradations_m_are_94_4_to_232_6_at_k100() {
    // We reproduce m = ln 100 / ln 1.05 = 94.4 and ln 100 / ln 1.02 = 232.6.
    // The seed prints 94..236; 236 does not follow from its own formula with
    // δ = 0.02 (it would need δ = 1.97 %), so we keep the formula's 232.6.
    let lo = levels(100.0, 0.05, 2.4).unwrap().m;
    let hi = levels(100.0, 0.02, 2.4).unwrap().m;
    assert!((lo - 100f64.ln() / 1.05f64.ln()).abs() < 1e-9, "{lo}");
    assert!((hi - 100f64.ln() / 1.02f64.ln()).abs() < 1e-9, "{hi}");
    assert_eq!((lo * 10.0).round(), 944.0);
    assert_eq!((hi * 10.0).round(), 2326.0);
}

#[test]
fn eight_bit_linear_code_allows_only_k_6_to_13() {
    // Eq. 9 solved for K with N_I = 255 levels: K = 1 + 255 δ.
    for (delta, k) in [(0.02, 6.1), (0.05, 13.75)] {
        let n = levels(k, delta, 2.4).unwrap().n_i;
        assert!((n - 255.0).abs() < 1e-9, "{n}");
    }
}

// ---------------------------------------------------------------- γ table

#[test]
fn gamma_lut_is_monotone_with_exact_endpoints_and_within_one_code_of_f64() {
    for curve in CURVES {
        for bits in 1..=8u8 {
            let lut = GammaLut::with_bits(curve, bits);
            let max = f64::from(lut.max_code());
            assert_eq!(lut.code(0), 0);
            assert_eq!(lut.code(4095), lut.max_code());
            assert!(
                lut.codes().windows(2).all(|w| w[0] <= w[1]),
                "{curve:?} {bits}"
            );
            let mut exact = 0;
            for i in 0..=4095u16 {
                let want = (max * encode(curve, f64::from(i) / 4095.0)).round();
                let got = f64::from(lut.code(i));
                assert!((got - want).abs() <= 1.0, "{curve:?} {bits} bits, I = {i}");
                exact += usize::from(got == want);
            }
            // In fact the table is the correctly rounded formula everywhere.
            assert_eq!(exact, 4096, "{curve:?} {bits}");
        }
    }
}

#[test]
fn intensities_above_4095_are_clamped() {
    let lut = GammaLut::new(Curve::GAMMA_2_4);
    for i in [4096, 5000, u16::MAX] {
        assert_eq!(lut.code(i), 255);
    }
}

/// Brightness of an object of intensity `obj` split over two pixels with
/// coverages `s1` and `1 - s1` (in 1/4096), relative to the object alone,
/// on a simulated display `B = (code / 255)^2.4`.
fn split_brightness(obj: u16, s1: u32, to_code: impl Fn(u16) -> u8) -> f64 {
    let part = |s: u32| ((u32::from(obj) * s + 2048) >> 12) as u16;
    let b = |i: u16| (f64::from(to_code(i)) / 255.0).powf(2.4);
    (b(part(s1)) + b(part(4096 - s1))) / b(obj)
}

#[test]
fn uncorrected_split_object_loses_62_percent_at_gamma_2_4() {
    // Linear codes sent straight to the display: code8 = round(255 I).
    let linear = |i: u16| ((u32::from(i) * 255 + 2047) / 4095) as u8;
    let rel = split_brightness(4095, 2048, linear);
    // Seed: B = 2 (1/2)^2.4 = 0.379, -62 % (128/255 instead of 1/2: 0.383).
    assert!((rel - 2.0 * 0.5f64.powf(2.4)).abs() < 0.005, "{rel}");
    assert!((rel - 1.0 + 0.62).abs() < 0.01, "{rel}");
}

#[test]
fn gamma_lut_keeps_split_object_brightness_within_1_percent() {
    let lut = GammaLut::new(Curve::GAMMA_2_4);
    let rel = split_brightness(4095, 2048, |i| lut.code(i));
    assert!((rel - 1.0).abs() < 0.01, "{rel}");
    // Over every split position of a full-intensity object, too.
    let mut worst: f64 = 0.0;
    for s1 in 0..=4096 {
        worst = worst.max((split_brightness(4095, s1, |i| lut.code(i)) - 1.0).abs());
    }
    assert!(worst < 0.01, "worst {worst}");
}

// ---------------------------------------------------------------- log codes

#[test]
fn log_code_steps_are_at_most_2_percent_at_k100_m255() {
    // m = 255: K^(1/m) - 1 = 1.82 % per code, every code, black to white.
    let s = LogScale::new(100, 255).unwrap();
    for i in 0..255u8 {
        let r = f64::from(s.brightness(i + 1)) / f64::from(s.brightness(i)) - 1.0;
        assert!(
            r <= 0.02 && (r - (100f64.powf(1.0 / 255.0) - 1.0)).abs() < 1e-4,
            "{i}: {r}"
        );
    }
    assert_eq!(s.brightness(0), 1 << 16);
    assert_eq!(s.brightness(255), 100 << 16);
}

#[test]
fn potentiation_is_within_half_a_linear_level_of_f64() {
    let s = LogScale::new(100, 255).unwrap();
    let pot = PotentiationLut::new(s);
    let x = |i: u8| (100f64.powf(f64::from(i) / 255.0) - 1.0) / 99.0;
    for i in 0..=255u8 {
        let want = 4095.0 * x(i);
        assert!((f64::from(pot.lin12(i)) - want).abs() <= 0.5 + 1e-9, "{i}");
    }
    // One linear level is (K - 1) / 4095 = 2.4 % of the black level B_min:
    // 12 bits are just short of eq. 9's N_I = 4950 for δ = 2 % at K = 100,
    // so near black fig. 7a is coarser than the log code it potentiates.
    assert!(99.0 / 4095.0 > 0.02 && levels(100.0, 0.02, 2.4).unwrap().n_i > 4095.0);
}

#[test]
fn eq15_output_table_is_within_one_code_of_f64() {
    for (k, m) in [(100u16, 255u8), (30, 172), (1000, 255)] {
        for curve in CURVES {
            let s = LogScale::new(k, m).unwrap();
            let out = LogOutputLut::new(s, curve);
            let kf = f64::from(k);
            let mut prev = 0;
            for t in 0..=(i32::from(m) * 8) {
                let x = (kf.powf(f64::from(t) / (8.0 * f64::from(m))) - 1.0) / (kf - 1.0);
                let want = (255.0 * encode(curve, x)).round();
                let got = out.code(LogValue::from_fine(t));
                assert!(
                    (f64::from(got) - want).abs() <= 1.0,
                    "{k} {m} {curve:?} t = {t}"
                );
                assert!(got >= prev);
                prev = got;
            }
            assert_eq!(out.code(LogValue::from_code(m)), 255);
            assert_eq!(out.code(LogValue::from_fine(-5)), 0);
            assert_eq!(out.code(LogValue::from_fine(i32::MAX)), 255);
        }
    }
}

/// Fig. 7a: potentiate, multiply-accumulate in linear light, γ table.
fn fig7a(pot: &PotentiationLut, lut: &GammaLut, codes: &[u8], covers: &[u16]) -> u8 {
    let acc: u32 = codes
        .iter()
        .zip(covers)
        .map(|(&c, &s)| u32::from(pot.lin12(c)) * u32::from(s))
        .sum();
    lut.code(((acc + 2048) >> 12) as u16)
}

/// Fig. 7b: log arithmetic throughout, eq. 15 table.
fn fig7b(s: LogScale, g: &GaussLog, out: &LogOutputLut, codes: &[u8], covers: &[u16]) -> u8 {
    let v = g.filter(
        codes
            .iter()
            .zip(covers)
            .map(|(&c, &w)| (LogValue::from_code(c), s.log_weight(w))),
    );
    out.code(v)
}

/// 2..=4 log codes with coverages (1/4096) that sum to one pixel.
fn filter_inputs() -> impl Strategy<Value = (Vec<u8>, Vec<u16>)> {
    (2usize..=4).prop_flat_map(|n| {
        (
            prop::collection::vec(any::<u8>(), n),
            prop::collection::vec(0u16..=4096, n - 1),
        )
            .prop_map(|(codes, mut cuts)| {
                cuts.push(0);
                cuts.push(4096);
                cuts.sort_unstable();
                let covers = cuts.windows(2).map(|w| w[1] - w[0]).collect();
                (codes, covers)
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20_000))]

    #[test]
    fn fig7a_and_fig7b_agree_within_one_display_code_srgb((codes, covers) in filter_inputs()) {
        let a = fig7a(&POT, &LUT_SRGB, &codes, &covers);
        let b = fig7b(K100, &GAUSS, &OUT_SRGB, &codes, &covers);
        prop_assert!(a.abs_diff(b) <= 1, "{} vs {}", a, b);
    }

    /// With a pure power γ = 2.4 the display code is infinitely steep at
    /// black, where fig. 7a's 12-bit linear code is coarser than the log
    /// code (eq. 9: K = 100 wants 4950 linear levels for δ = 2 %, 12 bits
    /// give 4095). There the two may differ by more than one code (measured
    /// once, 200 000 random inputs: 14 differ, by 2 to 5 codes, all at codes
    /// <= 13, i.e. under 0.1 % of white in light). The test then checks the
    /// difference is just that quantization: fig. 7b is within one code
    /// of the exact f64 result (or, nearer black than its own first step,
    /// the code of a log value within one fine unit of the exact one), and
    /// fig. 7a is the code of a linear level within one level of the exact
    /// linear value.
    #[test]
    fn fig7a_and_fig7b_agree_within_one_display_code_gamma_2_4_or_7a_is_12_bit_quantized(
        (codes, covers) in filter_inputs()
    ) {
        let a = fig7a(&POT, &LUT_24, &codes, &covers);
        let b = fig7b(K100, &GAUSS, &OUT_24, &codes, &covers);
        if a.abs_diff(b) > 1 {
            let x: f64 = codes
                .iter()
                .zip(&covers)
                .map(|(&c, &w)| f64::from(w) / 4096.0 * (100f64.powf(f64::from(c) / 255.0) - 1.0) / 99.0)
                .sum();
            let exact = (255.0 * x.powf(1.0 / 2.4)).round();
            // Fig. 7b keeps the light as a log value in fine units of
            // 1 / (8 m) of the scale: one unit above black is x =
            // (K^(1/2040) - 1) / 99 = 2.3e-5 of white, display code 3 under
            // γ = 2.4. So near black it may be off the exact code by more
            // than one too (found by this test: codes [0, 9], covers
            // [4092, 4], x = 1.7e-6, exact code 1, 7b 3): the difference is
            // then its own quantization, the code of a log value within
            // one fine unit of the exact one.
            let fine = 8.0 * 255.0 * (1.0 + 99.0 * x).ln() / 100f64.ln();
            let within = (fine.floor() as i32 - 1..=fine.ceil() as i32 + 1)
                .filter(|&f| (f64::from(f) - fine).abs() <= 1.0)
                .any(|f| OUT_24.code(LogValue::from_fine(f.max(0))) == b);
            prop_assert!(
                (f64::from(b) - exact).abs() <= 1.0 || within,
                "7b {} vs exact {} (log {} fine units)",
                b,
                exact,
                fine
            );
            let lin = 4095.0 * x;
            let explained = (0..=4095u16)
                .filter(|&l| (f64::from(l) - lin).abs() <= 1.0)
                .any(|l| LUT_24.code(l) == a);
            prop_assert!(explained, "7a {} not a code of lin12 {} ± 1", a, lin);
            prop_assert!(a.max(b) <= 16, "{} vs {} away from black", a, b);
        }
    }

    #[test]
    fn gaussian_log_sum_is_within_one_fine_unit_of_f64(a in 0i32..=2040, b in -24_000i32..=2040) {
        let got = GAUSS.add(LogValue::from_fine(a), LogValue::from_fine(b)).fine();
        let unit = 8.0 * 255.0;
        let lin = |v: i32| 100f64.powf(f64::from(v) / unit);
        let want = unit * (lin(a) + lin(b)).ln() / 100f64.ln();
        prop_assert!((f64::from(got) - want).abs() <= 1.0, "{} vs {}", got, want);
    }

    #[test]
    fn log_weight_is_within_half_a_fine_unit_of_f64(cover in 1u16..=4096) {
        let want = 8.0 * 255.0 * (f64::from(cover) / 4096.0).ln() / 100f64.ln();
        let got = f64::from(K100.log_weight(cover).fine());
        prop_assert!((got - want).abs() <= 0.5 + 1e-6, "{} vs {}", got, want);
    }

    #[test]
    fn no_tone_function_panics_on_any_input(i in any::<u16>(), c in any::<u8>(), f in any::<i32>(),
                                            x in any::<i32>(), y in any::<i32>(), w in any::<u16>()) {
        let s = K100;
        let _ = LUT_SRGB.code(i);
        let _ = POT.lin12(c);
        let _ = OUT_24.code(LogValue::from_fine(f));
        let _ = GAUSS.add(LogValue::from_fine(f), LogValue::from_fine(x));
        let _ = LogValue::from_fine(f).mul(LogValue::from_fine(y));
        let _ = s.log_weight(w);
        let _ = s.brightness(c);
        let _ = Bayer8::new().is_on(i, x, y);
        let _ = RGB565.code([i, w, i]);
        let mut err = [i16::MAX, i16::MIN, 0];
        let mut fs = FloydSteinberg::new(&mut err);
        let mut out = [false; 3];
        fs.row(&[[i], [w], [u16::MAX]], &mut out);
    }
}

// ---------------------------------------------------------------- formats

#[test]
fn formats_match_the_f64_formula_within_one_code() {
    let curve = Curve::GAMMA_2_2;
    let g8 = Gray8Format::new(curve);
    let g4 = Gray4Format::new(curve);
    let rgb8 = Rgb888Format::new(curve);
    let rgb5 = Rgb565Format::new(curve);
    let want = |i: u16, max: f64| (max * encode(curve, f64::from(i) / 4095.0)).round();
    for i in (0..=4095u16).step_by(7) {
        let j = 4095 - i;
        assert!((f64::from(g8.code([i])) - want(i, 255.0)).abs() <= 1.0);
        assert!((f64::from(g4.code([i])) - want(i, 15.0)).abs() <= 1.0);
        assert_eq!(
            rgb8.code([i, j, i]),
            [g8.code([i]), g8.code([j]), g8.code([i])]
        );
        let p = rgb5.code([i, j, i]);
        let (r, g, b) = (p >> 11, (p >> 5) & 63, p & 31);
        assert!((f64::from(r) - want(i, 31.0)).abs() <= 1.0);
        assert!((f64::from(g) - want(j, 63.0)).abs() <= 1.0);
        assert_eq!(r, b);
    }
    let mut out = [0u8; 4];
    assert_eq!(code_row(&g4, &[[0], [4095], [7000]], &mut out), 3);
    assert_eq!(&out[..3], &[0, 15, 15]);
}

// ---------------------------------------------------------------- dithering

#[test]
fn bayer8_flat_area_mean_equals_linear_intensity_within_1_64() {
    let bayer = Bayer8::new();
    for i in 0..=4095u16 {
        // Any 8x8-aligned or not: a 16x16 area at an odd offset.
        let mut on = 0u32;
        let mut row = [false; 16];
        for y in 3..19 {
            bayer.row(&[[i]; 16], 5, y, &mut row);
            on += row.iter().map(|&b| u32::from(b)).sum::<u32>();
        }
        let mean = f64::from(on) / 256.0;
        let want = f64::from(i) / 4095.0;
        assert!(
            (mean - want).abs() <= 1.0 / 64.0,
            "I = {i}: {mean} vs {want}"
        );
    }
}

/// Fraction of on-pixels of a `w x h` flat area of intensity `i`, dithered by
/// Floyd–Steinberg in bands of `band` rows over one error row.
fn fs_mean(i: u16, w: usize, h: usize, band: usize) -> (f64, Vec<bool>) {
    let mut err = vec![0i16; w];
    let mut fs = FloydSteinberg::new(&mut err);
    let row = vec![[i]; w];
    let mut all = Vec::with_capacity(w * h);
    let mut out = vec![false; w];
    for y0 in (0..h).step_by(band) {
        for _ in y0..(y0 + band).min(h) {
            fs.row(&row, &mut out);
            all.extend_from_slice(&out);
        }
    }
    let on = all.iter().filter(|&&b| b).count();
    (on as f64 / (w * h) as f64, all)
}

#[test]
fn floyd_steinberg_flat_area_mean_equals_linear_intensity_within_1_percent() {
    for i in (0..=4095u16).step_by(13).chain([1, 4094, 4095]) {
        let (mean, _) = fs_mean(i, 128, 128, 128);
        let want = f64::from(i) / 4095.0;
        assert!((mean - want).abs() < 0.01, "I = {i}: {mean} vs {want}");
    }
}

#[test]
fn floyd_steinberg_in_bands_equals_whole_frame_when_the_error_row_is_carried() {
    for i in [100u16, 1500, 2900] {
        let (_, whole) = fs_mean(i, 96, 64, 64);
        let (_, banded) = fs_mean(i, 96, 64, 8);
        assert_eq!(whole, banded);
    }
}
