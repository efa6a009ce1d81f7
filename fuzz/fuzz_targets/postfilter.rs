//! Seed 002's lightness filter on any frame: no panic, outputs within
//! 0..=4095, and the band-by-band filter (halo rows) gives the frame
//! filter's result for any band height.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::postfilter::LightnessFilter;
use softedge_fuzz::Input;

/// The one use of the filter API: frame rows `y0..y0 + rows` of `frame`
/// filtered band-wise into `out` (the band's input is its rows and one
/// halo row above and below, as a firmware band renders them).
fn filter_band<const C: usize>(
    filter: &LightnessFilter,
    frame: &[[u16; C]],
    w: usize,
    y0: i32,
    rows: u16,
    out: &mut [[u16; C]],
) where
    [u16; C]: softedge::postfilter::LightnessPixel,
{
    let h = frame.len() / w;
    let mut input = vec![[0u16; C]; w * (usize::from(rows) + 2)];
    for (r, row) in input.chunks_exact_mut(w).enumerate() {
        let y = y0 - 1 + r as i32;
        if (0..h as i32).contains(&y) {
            row.copy_from_slice(&frame[y as usize * w..(y as usize + 1) * w]);
        } else {
            // Rows outside the frame are never read: fill them with junk.
            row.fill([4095; C]);
        }
    }
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w as u16)];
    let mut out_row = vec![[0u16; C]; w];
    filter
        .filter_band(y0, rows, &input, &mut scratch, &mut out_row, |y, row| {
            out[y as usize * w..(y as usize + 1) * w].copy_from_slice(row);
        })
        .expect("buffers are large enough");
}

fn check<const C: usize>(inp: &mut Input)
where
    [u16; C]: softedge::postfilter::LightnessPixel,
{
    let (w, h) = (inp.side(48), inp.side(32));
    let rows = inp.side(h);
    let Ok(filter) = LightnessFilter::new(w, h) else {
        return;
    };
    let (wu, hu) = (usize::from(w), usize::from(h));
    let flat = inp.bool();
    let frame: Vec<[u16; C]> = (0..wu * hu)
        .map(|_| {
            if flat {
                [inp.u16() % 4096; C]
            } else {
                inp.color()
            }
        })
        .collect();
    let mut whole = vec![[0u16; C]; wu * hu];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w)];
    filter
        .filter_frame(&frame, &mut whole, &mut scratch)
        .expect("buffers are large enough");
    assert!(whole.iter().flatten().all(|&v| v <= 4095));
    let mut banded = vec![[0u16; C]; wu * hu];
    let mut y0 = 0;
    while y0 < i32::from(h) {
        filter_band(&filter, &frame, wu, y0, rows, &mut banded);
        y0 += i32::from(rows);
    }
    assert!(
        whole == banded,
        "band height {rows} differs from the frame filter"
    );
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    if inp.bool() {
        check::<1>(&mut inp);
    } else {
        check::<3>(&mut inp);
    }
});
