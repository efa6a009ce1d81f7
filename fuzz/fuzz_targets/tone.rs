//! The tone stage on any rows: every row function against its per-pixel
//! definition (Bayer's row against `is_on`, `code_row` against `code`),
//! Floyd–Steinberg over frames of any width and band split, the log-code
//! tables for any contrast and gradation count: no panic, no disagreement.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::tone::format::{
    code_row, Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat,
};
use softedge::tone::{
    Bayer8, Curve, FloydSteinberg, GaussLog, LogScale, LogValue, PotentiationLut,
};
use softedge_fuzz::Input;

static BAYER: Bayer8 = Bayer8::new();
static GRAY8: Gray8Format = Gray8Format::new(Curve::GAMMA_2_2);
static GRAY4: Gray4Format = Gray4Format::new(Curve::Srgb);
static RGB565: Rgb565Format = Rgb565Format::new(Curve::GAMMA_2_4);
static RGB888: Rgb888Format = Rgb888Format::new(Curve::Srgb);

fn rows_agree<F: ToneFormat<C>, const C: usize>(f: &F, row: &[[u16; C]])
where
    F::Code: PartialEq + core::fmt::Debug + Default,
{
    let mut out = vec![F::Code::default(); row.len()];
    assert_eq!(code_row(f, row, &mut out), row.len());
    for (k, (&px, o)) in row.iter().zip(&out).enumerate() {
        assert_eq!(*o, f.code(px), "pixel {k}");
    }
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let len = usize::from(inp.u16() % 700);
    let gray: Vec<[u16; 1]> = (0..len).map(|_| inp.color()).collect();
    let rgb: Vec<[u16; 3]> = (0..len / 3).map(|_| inp.color()).collect();

    // Bayer: the row against the per-pixel test, from any column.
    let (x0, y) = (inp.u32() as i32, inp.u32() as i32);
    let out_len = if inp.bool() {
        len
    } else {
        usize::from(inp.u16() % 700)
    };
    let mut out = vec![false; out_len];
    let n = BAYER.row(&gray, x0, y, &mut out);
    assert_eq!(n, len.min(out_len));
    for (k, (&[i], &o)) in gray.iter().zip(&out).enumerate() {
        assert_eq!(
            o,
            BAYER.is_on(i, x0.wrapping_add(k as i32), y),
            "Bayer pixel {k}"
        );
    }

    rows_agree(&GRAY8, &gray);
    rows_agree(&GRAY4, &gray);
    rows_agree(&RGB565, &rgb);
    rows_agree(&RGB888, &rgb);

    // Floyd–Steinberg: a frame of `width` columns from the same values, its
    // rows dithered in order; the error row may be shorter or longer.
    let width = 1 + usize::from(inp.u8());
    let mut err = vec![0i16; width + usize::from(inp.u8() % 3) - 1];
    let mut fs = FloydSteinberg::new(&mut err);
    let mut out = vec![0u8; width];
    for row in gray.chunks(width) {
        let n = fs.row(row, &mut out);
        assert!(n <= row.len());
        assert!(out.iter().all(|&b| b <= 1));
    }

    // Log codes: any contrast and gradation count.
    if let Ok(scale) = LogScale::new(inp.u16(), inp.u8()) {
        let pot = PotentiationLut::new(scale);
        for code in [0, inp.u8(), scale.gradations(), u8::MAX] {
            assert!(pot.lin12(code) <= 4095);
        }
        if let Ok(g) = GaussLog::new(scale) {
            let a = LogValue::from_code(inp.u8());
            let b = LogValue::from_fine(inp.u32() as i32);
            let s = g.add(a, b);
            assert!(s >= a.max(b), "log(A + B) below log(max(A, B))");
            let _ = scale.log_weight(inp.u16());
        }
    }
});
