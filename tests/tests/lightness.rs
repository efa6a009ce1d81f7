//! The CIELAB lightness filter of seed 002 against an independent `f64`
//! reference of the seed's formulas (eqs. 3-1 to 3-3, table 4.1), written
//! here from the formulas and the IEC 61966-2-1 matrix.

use softedge::postfilter::{FilterError, Lab, LightnessFilter, LightnessPixel, K_TWENTIETHS};
use softedge::{Band, BandBuffer, Bands, RenderStyle, SubPoint, Triangle};

// ---------------------------------------------------------------- reference

/// IEC 61966-2-1 sRGB -> XYZ (D65); the white is the row sums.
const M: [[f64; 3]; 3] = [
    [0.4124, 0.3576, 0.1805],
    [0.2126, 0.7152, 0.0722],
    [0.0193, 0.1192, 0.9505],
];

fn white() -> [f64; 3] {
    M.map(|r| r.iter().sum())
}

fn f(t: f64) -> f64 {
    let d: f64 = 6.0 / 29.0;
    if t > d * d * d {
        t.cbrt()
    } else {
        t / (3.0 * d * d) + 4.0 / 29.0
    }
}

fn f_inv(u: f64) -> f64 {
    let d: f64 = 6.0 / 29.0;
    if u > d {
        u * u * u
    } else {
        3.0 * d * d * (u - 4.0 / 29.0)
    }
}

/// `(L*, a*, b*)` of linear 12-bit RGB.
fn lab(rgb: [u16; 3]) -> [f64; 3] {
    let c = rgb.map(|v| f64::from(v) / 4095.0);
    let w = white();
    let t: Vec<f64> = (0..3)
        .map(|r| (0..3).map(|k| M[r][k] * c[k]).sum::<f64>() / w[r])
        .collect();
    let (fx, fy, fz) = (f(t[0]), f(t[1]), f(t[2]));
    [116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)]
}

fn lstar_gray(v: u16) -> f64 {
    116.0 * f(f64::from(v) / 4095.0) - 16.0
}

/// Linear RGB in 12-bit units (unclamped) of `(L*, a*, b*)`.
fn rgb_of_lab(l: f64, a: f64, b: f64) -> [f64; 3] {
    let fy = (l + 16.0) / 116.0;
    let w = white();
    let xyz = [
        f_inv(fy + a / 500.0) * w[0],
        f_inv(fy) * w[1],
        f_inv(fy - b / 200.0) * w[2],
    ];
    // Invert M by Cramer's rule.
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(M);
    let mut out = [0.0; 3];
    for (c, o) in out.iter_mut().enumerate() {
        let mut m = M;
        for r in 0..3 {
            m[r][c] = xyz[r];
        }
        *o = det(m) / d * 4095.0;
    }
    out
}

/// Table 4.1 of seed 002, as printed.
fn k_table(l: i32) -> f64 {
    match l {
        0..=54 => 0.0,
        55..=62 => 0.05,
        63..=72 => 0.10,
        73..=81 => 0.15,
        82..=89 => 0.20,
        90..=93 => 0.15,
        94..=96 => 0.10,
        97..=100 => 0.0,
        _ => f64::NAN,
    }
}

/// The `k` values a pixel of lightness `l` may get: one, or both
/// neighbours' when `l` lies within 0.01 of a half (fixed point may round
/// either way there).
fn k_candidates(l: f64) -> Vec<f64> {
    let mut ks = vec![k_table(l.round() as i32)];
    for e in [-0.01, 0.01] {
        let k = k_table((l + e).round() as i32);
        if !ks.contains(&k) {
            ks.push(k);
        }
    }
    ks
}

/// Eq. 3-2: the 4-neighbour Laplacian, edge pixels repeated.
fn laplacian(l: &[f64], w: usize, h: usize, x: usize, y: usize) -> f64 {
    let at = |x: usize, y: usize| l[y * w + x];
    at(x.saturating_sub(1), y)
        + at((x + 1).min(w - 1), y)
        + at(x, y.saturating_sub(1))
        + at(x, (y + 1).min(h - 1))
        - 4.0 * at(x, y)
}

/// Reference outputs per pixel: the candidate new `L*` values (eq. 3-3).
fn reference_lstar(l: &[f64], w: usize, h: usize) -> Vec<Vec<f64>> {
    let mut out = Vec::with_capacity(l.len());
    for y in 0..h {
        for x in 0..w {
            let lap = laplacian(l, w, h, x, y);
            let c = l[y * w + x];
            out.push(k_candidates(c).iter().map(|k| c + k * lap).collect());
        }
    }
    out
}

// ---------------------------------------------------------------- images

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn lin12(&mut self) -> u16 {
        (self.next() % 4096) as u16
    }
}

/// Random pixels, or (every other image) random blobs: a smooth image with
/// edges, like a rendered one.
fn random_rgb(rng: &mut Rng, w: usize, h: usize, smooth: bool) -> Vec<[u16; 3]> {
    if !smooth {
        return (0..w * h)
            .map(|_| [rng.lin12(), rng.lin12(), rng.lin12()])
            .collect();
    }
    let cell = 3;
    let grid: Vec<[u16; 3]> = (0..(w / cell + 2) * (h / cell + 2))
        .map(|_| [rng.lin12(), rng.lin12(), rng.lin12()])
        .collect();
    let gw = w / cell + 2;
    (0..w * h)
        .map(|i| {
            let (x, y) = (i % w, i / w);
            let g = grid[(y / cell) * gw + x / cell];
            let n = grid[(y / cell) * gw + x / cell + 1];
            let t = (x % cell) as u32;
            [0, 1, 2].map(|c| {
                ((u32::from(g[c]) * (cell as u32 - t) + u32::from(n[c]) * t) / cell as u32) as u16
            })
        })
        .collect()
}

fn filter_frame<P: LightnessPixel + Default>(
    img: &[P],
    w: usize,
    h: usize,
) -> (Vec<P>, softedge::postfilter::FilterStats) {
    let filter = LightnessFilter::new(w as u16, h as u16).unwrap();
    let mut out = vec![P::default(); w * h];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w as u16)];
    let stats = filter.filter_frame(img, &mut out, &mut scratch).unwrap();
    (out, stats)
}

fn dist(a: &[f64], b: f64) -> f64 {
    a.iter()
        .map(|x| (x - b).abs())
        .fold(f64::INFINITY, f64::min)
}

// ---------------------------------------------------------------- tests

#[test]
fn k_of_lstar_reproduces_table_4_1_at_every_integer_lstar() {
    for l in 0..=100 {
        assert_eq!(
            f64::from(K_TWENTIETHS[l as usize]) / 20.0,
            k_table(l),
            "L* = {l}"
        );
    }
    // And the pipeline looks k up by the pixel's own L*, rounded: every gray
    // level's rounded L* is the reference's (away from the halves).
    let mut seen = [false; 101];
    for v in 0..=4095u16 {
        let l = lstar_gray(v);
        if (l - l.floor() - 0.5).abs() < 1e-3 {
            continue;
        }
        let got = Lab::from_gray(v).l_star_rounded();
        assert_eq!(i32::from(got), l.round() as i32, "v = {v}, L* = {l}");
        seen[usize::from(got)] = true;
    }
    assert!(seen.iter().all(|&s| s), "every integer L* is reached");
}

#[test]
fn gray_filter_equals_f64_reference_within_half_an_lstar() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let mut worst: f64 = 0.0;
    let mut changed = 0;
    for img in 0..40 {
        let (w, h) = (23, 17);
        let rgb = random_rgb(&mut rng, w, h, img % 2 == 1);
        let gray: Vec<[u16; 1]> = rgb.iter().map(|p| [p[1]]).collect();
        let (out, stats) = filter_frame(&gray, w, h);
        changed += stats.changed;
        assert_eq!(stats.clamped, 0, "L* stays in [0, 100]: no clamping");
        let l: Vec<f64> = gray.iter().map(|p| lstar_gray(p[0])).collect();
        let want = reference_lstar(&l, w, h);
        for (o, cands) in out.iter().zip(&want) {
            let e = dist(cands, lstar_gray(o[0]));
            worst = worst.max(e);
        }
    }
    println!("gray: {changed} pixels changed, max |L* - reference| = {worst:.4}");
    assert!(worst <= 0.5, "{worst}");
}

#[test]
fn rgb_filter_equals_f64_reference_within_half_an_lstar_inside_the_gamut() {
    let mut rng = Rng(0x0123_4567_89AB_CDEF);
    let mut worst: f64 = 0.0;
    let (mut n, mut skipped) = (0, 0);
    for img in 0..40 {
        let (w, h) = (23, 17);
        let rgb = random_rgb(&mut rng, w, h, img % 2 == 1);
        let (out, _) = filter_frame(&rgb, w, h);
        let labs: Vec<[f64; 3]> = rgb.iter().map(|&p| lab(p)).collect();
        let l: Vec<f64> = labs.iter().map(|c| c[0]).collect();
        let want = reference_lstar(&l, w, h);
        for ((o, cands), c) in out.iter().zip(&want).zip(&labs) {
            if cands
                .iter()
                .any(|&g| out_of_gamut(rgb_of_lab(g, c[1], c[2])))
            {
                skipped += 1;
                continue;
            }
            n += 1;
            worst = worst.max(dist(cands, lab(*o)[0]));
        }
    }
    println!(
        "rgb: {n} pixels in gamut, max |L* - reference| = {worst:.4}; {skipped} left the gamut"
    );
    assert!(worst <= 0.5, "{worst}");
}

fn out_of_gamut(rgb: [f64; 3]) -> bool {
    rgb.iter().any(|&v| !(-0.5..=4095.5).contains(&v))
}

#[test]
fn pixels_whose_own_lstar_has_k_zero_come_out_unchanged_bit_for_bit() {
    let mut rng = Rng(42);
    let mut checked = 0;
    for img in 0..20 {
        let (w, h) = (19, 13);
        let rgb = random_rgb(&mut rng, w, h, img % 2 == 0);
        let (out, _) = filter_frame(&rgb, w, h);
        for (i, o) in rgb.iter().zip(&out) {
            let l = lab(*i)[0];
            if k_candidates(l).iter().all(|&k| k == 0.0) {
                assert_eq!(i, o);
                checked += 1;
            }
        }
        let gray: Vec<[u16; 1]> = rgb.iter().map(|p| [p[0]]).collect();
        let (out, _) = filter_frame(&gray, w, h);
        for (i, o) in gray.iter().zip(&out) {
            if k_candidates(lstar_gray(i[0])).iter().all(|&k| k == 0.0) {
                assert_eq!(i, o);
                checked += 1;
            }
        }
    }
    println!("{checked} pixels with k = 0, all unchanged");
    assert!(checked > 1000);
}

#[test]
fn flat_images_come_out_unchanged() {
    let mut rng = Rng(7);
    for v in (0..=4095).step_by(13) {
        let img = vec![[v]; 6 * 5];
        assert_eq!(filter_frame(&img, 6, 5).0, img);
        let c = [v, rng.lin12(), rng.lin12()];
        let img = vec![c; 6 * 5];
        assert_eq!(filter_frame(&img, 6, 5).0, img);
    }
}

/// `(max |Δa*|, max |Δb*|)` over pixels, split into unclamped and clamped.
#[test]
fn colour_filter_keeps_a_and_b_within_one_unit_while_rgb_blur_shifts_them() {
    let mut rng = Rng(0xC0FF_EE00_1234_5678);
    let (mut max_in, mut max_clamped, mut clamped, mut changed) = (0.0f64, 0.0f64, 0u32, 0u32);
    let mut stats_clamped = 0;
    let mut max_blur: f64 = 0.0;
    for img in 0..40 {
        let (w, h) = (23, 17);
        let rgb = random_rgb(&mut rng, w, h, img % 2 == 1);
        let (out, stats) = filter_frame(&rgb, w, h);
        stats_clamped += stats.clamped;
        let labs: Vec<[f64; 3]> = rgb.iter().map(|&p| lab(p)).collect();
        let l: Vec<f64> = labs.iter().map(|c| c[0]).collect();
        let want = reference_lstar(&l, w, h);
        for ((o, i), (c, cands)) in out.iter().zip(&rgb).zip(labs.iter().zip(&want)) {
            if o == i {
                continue;
            }
            changed += 1;
            let d = lab(*o);
            let shift = (d[1] - c[1]).abs().max((d[2] - c[2]).abs());
            if cands
                .iter()
                .any(|&g| out_of_gamut(rgb_of_lab(g, c[1], c[2])))
            {
                clamped += 1;
                max_clamped = max_clamped.max(shift);
            } else {
                max_in = max_in.max(shift);
            }
        }
        // A plain RGB 3x3 box blur, edge pixels repeated.
        for y in 0..h {
            for x in 0..w {
                let mut s = [0u32; 3];
                for dy in -1i32..=1 {
                    for dx in -1i32..=1 {
                        let xx = (x as i32 + dx).clamp(0, w as i32 - 1) as usize;
                        let yy = (y as i32 + dy).clamp(0, h as i32 - 1) as usize;
                        for c in 0..3 {
                            s[c] += u32::from(rgb[yy * w + xx][c]);
                        }
                    }
                }
                let b = lab(s.map(|v| ((v + 4) / 9) as u16));
                let c = labs[y * w + x];
                max_blur = max_blur.max((b[1] - c[1]).abs().max((b[2] - c[2]).abs()));
            }
        }
    }
    println!(
        "filter: {changed} pixels changed; in gamut max |Δa*|,|Δb*| = {max_in:.3}; \
         {clamped} clamped to the gamut (filter counted {stats_clamped}), their max shift = {max_clamped:.2}"
    );
    println!("plain RGB 3x3 box blur: max |Δa*|,|Δb*| = {max_blur:.2}");
    assert!(max_in <= 1.0, "{max_in}");
    assert!(max_blur > 20.0 * max_in.max(1.0), "{max_blur}");
}

#[test]
fn rgb_to_lab_to_rgb_round_trip_is_within_one_level() {
    let mut worst = 0;
    let mut n = 0u64;
    let check = |rgb: [u16; 3], worst: &mut u16| {
        let (back, clamped) = Lab::from_rgb(rgb).to_rgb();
        assert!(!clamped, "{rgb:?}");
        for (b, v) in back.iter().zip(rgb) {
            *worst = (*worst).max(b.abs_diff(v));
        }
        assert!(*worst <= 1, "{rgb:?} -> {back:?}");
    };
    let levels: Vec<u16> = (0..=4095).step_by(17).chain([4095]).collect();
    for &r in &levels {
        for &g in &levels {
            for &b in &levels {
                check([r, g, b], &mut worst);
                n += 1;
            }
        }
    }
    let mut rng = Rng(99);
    for _ in 0..1_000_000 {
        check([rng.lin12(), rng.lin12(), rng.lin12()], &mut worst);
        n += 1;
    }
    for v in 0..=4095 {
        assert_eq!(Lab::from_gray(v).to_gray(), (v, false));
    }
    println!("{n} colours: max round-trip error {worst} level(s)");
}

/// Splits a frame into bands of `rows` with halos (rows outside the frame
/// filled with junk, which must not be read) and filters each band.
fn filter_in_bands<P: LightnessPixel + Default>(
    img: &[P],
    w: usize,
    h: usize,
    rows: usize,
    junk: impl Fn(usize) -> P,
) -> Vec<P> {
    let filter = LightnessFilter::new(w as u16, h as u16).unwrap();
    let mut out = vec![P::default(); w * h];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(w as u16)];
    let mut out_row = vec![P::default(); w];
    for band in Bands::new(w as u16, h as u16, rows as u16) {
        let mut input = Vec::new();
        for y in band.y0 - 1..=band.y0 + i32::from(band.rows) {
            if (0..h as i32).contains(&y) {
                input.extend_from_slice(&img[y as usize * w..(y as usize + 1) * w]);
            } else {
                input.extend((0..w).map(&junk));
            }
        }
        filter
            .filter_band(
                band.y0,
                band.rows,
                &input,
                &mut scratch,
                &mut out_row,
                |y, row| {
                    out[y as usize * w..(y as usize + 1) * w].copy_from_slice(row);
                },
            )
            .unwrap();
    }
    out
}

#[test]
fn bands_of_1_7_16_and_full_height_equal_the_full_frame_filter() {
    let mut rng = Rng(1234);
    let (w, h) = (37, 45);
    let rgb = random_rgb(&mut rng, w, h, true);
    let gray: Vec<[u16; 1]> = rgb.iter().map(|p| [p[1]]).collect();
    let (full_rgb, s) = filter_frame(&rgb, w, h);
    let (full_gray, _) = filter_frame(&gray, w, h);
    assert!(s.changed > 100);
    for rows in [1, 7, 16, h] {
        let junk3 = |x: usize| [(x * 997 % 4096) as u16, 4095, 0];
        let junk1 = |x: usize| [(x * 997 % 4096) as u16];
        assert_eq!(
            filter_in_bands(&rgb, w, h, rows, junk3),
            full_rgb,
            "rgb, rows {rows}"
        );
        assert_eq!(
            filter_in_bands(&gray, w, h, rows, junk1),
            full_gray,
            "gray, rows {rows}"
        );
    }
}

/// A rendered RGB scene: each band is rendered one row taller at each end
/// (the halo rows are rendered twice) and filtered; the frame equals the
/// whole frame rendered at once and filtered.
#[test]
fn rendered_scene_filtered_in_bands_with_halo_equals_the_full_frame() {
    let (w, h) = (48u16, 40u16);
    let tris = [
        Triangle::new(
            [
                SubPoint::new(3, 5),
                SubPoint::new(46 * 16 + 7, 9 * 16 + 3),
                SubPoint::new(20 * 16 + 9, 39 * 16 + 1),
            ],
            [[4095, 3000, 500], [1000, 4000, 2000], [3500, 3500, 3800]],
        ),
        Triangle::flat(
            [
                SubPoint::new(30 * 16, 2 * 16 + 5),
                SubPoint::new(47 * 16 + 3, 35 * 16),
                SubPoint::new(10 * 16 + 1, 30 * 16 + 11),
            ],
            [600, 2500, 4095],
        ),
    ];
    let render = |band: Band, out: &mut Vec<[u16; 3]>| {
        let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, band.rows)];
        let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, band.rows)];
        let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([2600, 2700, 2500]);
        for t in &tris {
            t.draw(&mut buf, &RenderStyle::default()).unwrap();
        }
        for r in 0..band.rows {
            let mut row = vec![[0u16; 3]; usize::from(w)];
            buf.resolve_row(band.y0 + i32::from(r), &mut row);
            out.extend(row);
        }
    };
    let mut frame = Vec::new();
    render(Band::new(w, 0, h), &mut frame);
    let (full, stats) = filter_frame(&frame, usize::from(w), usize::from(h));
    println!(
        "rendered scene: {} pixels changed, {} clamped",
        stats.changed, stats.clamped
    );
    assert!(stats.changed > 50);
    let filter = LightnessFilter::new(w, h).unwrap();
    for rows in [1u16, 7, 16, h] {
        let mut got = vec![[0u16; 3]; usize::from(w) * usize::from(h)];
        let mut scratch = vec![0u16; LightnessFilter::scratch_len(w)];
        let mut out_row = vec![[0u16; 3]; usize::from(w)];
        for band in Bands::new(w, h, rows) {
            let mut input = Vec::new();
            render(Band::new(w, band.y0 - 1, band.rows + 2), &mut input);
            filter
                .filter_band(
                    band.y0,
                    band.rows,
                    &input,
                    &mut scratch,
                    &mut out_row,
                    |y, row| {
                        let k = y as usize * usize::from(w);
                        got[k..k + row.len()].copy_from_slice(row);
                    },
                )
                .unwrap();
        }
        assert_eq!(got, full, "rows {rows}");
    }
}

#[test]
fn short_buffers_are_errors_and_odd_bands_do_not_panic() {
    assert_eq!(LightnessFilter::new(0, 1), Err(FilterError::BadSize));
    assert_eq!(LightnessFilter::new(1, 0), Err(FilterError::BadSize));
    let f = LightnessFilter::new(4, 3).unwrap();
    let img = [[2000u16]; 12];
    let mut out = [[0u16]; 12];
    let mut scratch = [0u16; 12];
    assert_eq!(
        f.filter_frame(&img[..11], &mut out, &mut scratch),
        Err(FilterError::InputTooShort)
    );
    assert_eq!(
        f.filter_frame(&img, &mut out[..11], &mut scratch),
        Err(FilterError::OutputTooSmall)
    );
    assert_eq!(
        f.filter_frame(&img, &mut out, &mut scratch[..11]),
        Err(FilterError::ScratchTooSmall)
    );
    let mut row = [[0u16]; 4];
    let mut n = 0;
    assert_eq!(
        f.filter_band(0, 1, &img, &mut scratch, &mut row, |_, _| n += 1),
        Ok(Default::default())
    );
    assert_eq!(
        f.filter_band(0, 3, &img, &mut scratch, &mut row, |_, _| n += 1),
        Err(FilterError::InputTooShort)
    );
    assert_eq!(
        f.filter_band(0, 1, &img, &mut scratch, &mut row[..3], |_, _| n += 1),
        Err(FilterError::OutputTooSmall)
    );
    // Bands partly or wholly outside the frame emit only frame rows.
    let mut ys = Vec::new();
    for y0 in [-5, -1, 2, 3, 100, i32::MIN + 1, i32::MAX - 1] {
        let input = vec![[4095u16]; 4 * 4];
        f.filter_band(y0, 2, &input, &mut scratch, &mut row, |y, _| ys.push(y))
            .unwrap();
    }
    assert_eq!(ys, [0, 2]);
    assert_eq!(n, 1);
    // Any values, including above 4095, in gray and RGB.
    let mut rng = Rng(5);
    let wild: Vec<[u16; 3]> = (0..12)
        .map(|_| [rng.next() as u16, rng.next() as u16, rng.next() as u16])
        .collect();
    let mut out3 = [[0u16; 3]; 12];
    f.filter_frame(&wild, &mut out3, &mut scratch).unwrap();
    assert!(out3.iter().flatten().all(|&v| v <= 4095));
}
