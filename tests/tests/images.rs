//! Images as a paint (issue #35), against an independent `f64` reference
//! written here: the transform (forward and inverse, `f64` sines), the
//! filters (bilinear on texel centres at half-integers, clamped to the
//! edge texels; the box average of the edge-extended image over the
//! pixel's footprint), premultiplied alpha, the image's exact coverage
//! (the transformed rectangle clipped to each pixel, shoelace area) and
//! the over composite, all in linear light on the decoded texels (the
//! sRGB tables' values, the definition's input).
//!
//! Measured (printed with `--nocapture`): the worst pixel error of opaque
//! images at random transforms, of images with alpha, of tinted masks, of
//! the box filter, and the worst edge coverage error.

use softedge::band::{BandBuffer, Bands};
use softedge::canvas::Canvas;
use softedge::color::srgb::SRGB8_TO_LIN12;
use softedge::geom::FinePoint;
use softedge::image::{format, AaImage, ImageFault, ImageSource, RawImage, Scale};
use softedge::path::Degrees;
use softedge::style::Opacity;
use softedge::DrawError;
use softedge_tests::lcg::Lcg;

/// The transform in `f64`: pixel centre to image `(u, v)`, and the image's
/// corners on screen.
#[derive(Clone, Copy, Debug)]
struct Xf {
    pos: (f64, f64),
    pivot: (f64, f64),
    s: (f64, f64),
    /// Radians, clockwise on screen.
    a: f64,
}

impl Xf {
    fn of(pos: FinePoint, pivot: FinePoint, sx: Scale, sy: Scale, deg_bits: i32) -> Self {
        Self {
            pos: (f64::from(pos.x) / 1024.0, f64::from(pos.y) / 1024.0),
            pivot: (f64::from(pivot.x) / 1024.0, f64::from(pivot.y) / 1024.0),
            s: (
                f64::from(sx.bits()) / 65536.0,
                f64::from(sy.bits()) / 65536.0,
            ),
            a: f64::from(deg_bits) / 65536.0 * std::f64::consts::PI / 180.0,
        }
    }
    fn inverse(&self, x: f64, y: f64) -> (f64, f64) {
        let (c, s) = (self.a.cos(), self.a.sin());
        let (dx, dy) = (x - self.pos.0, y - self.pos.1);
        (
            self.pivot.0 + (c * dx + s * dy) / self.s.0,
            self.pivot.1 + (-s * dx + c * dy) / self.s.1,
        )
    }
    fn forward(&self, u: f64, v: f64) -> (f64, f64) {
        let (c, s) = (self.a.cos(), self.a.sin());
        let (du, dv) = ((u - self.pivot.0) * self.s.0, (v - self.pivot.1) * self.s.1);
        (self.pos.0 + c * du - s * dv, self.pos.1 + s * du + c * dv)
    }
}

/// A reference image: premultiplied linear colour (lin12 units) and alpha
/// (0..=1) per texel.
struct RefImage {
    w: usize,
    h: usize,
    px: Vec<([f64; 3], f64)>,
}

impl RefImage {
    fn at(&self, i: i64, j: i64) -> ([f64; 3], f64) {
        let i = i.clamp(0, self.w as i64 - 1) as usize;
        let j = j.clamp(0, self.h as i64 - 1) as usize;
        self.px[j * self.w + i]
    }
    /// Bilinear at `(u, v)`: texel centres at half-integers, clamped.
    fn bilinear(&self, u: f64, v: f64) -> ([f64; 3], f64) {
        let (s, t) = (u - 0.5, v - 0.5);
        let (i0, j0) = (s.floor(), t.floor());
        let (fx, fy) = (s - i0, t - j0);
        let (i0, j0) = (i0 as i64, j0 as i64);
        let mut c = [0.0; 3];
        let mut a = 0.0;
        for (di, dj, w) in [
            (0, 0, (1.0 - fx) * (1.0 - fy)),
            (1, 0, fx * (1.0 - fy)),
            (0, 1, (1.0 - fx) * fy),
            (1, 1, fx * fy),
        ] {
            let (tc, ta) = self.at(i0 + di, j0 + dj);
            for ch in 0..3 {
                c[ch] += w * tc[ch];
            }
            a += w * ta;
        }
        (c, a)
    }
    /// The average of the edge-extended, piecewise constant image over the
    /// box `bw x bh` centred at `(u, v)`.
    fn boxed(&self, u: f64, v: f64, bw: f64, bh: f64) -> ([f64; 3], f64) {
        let (u0, u1, v0, v1) = (u - bw / 2.0, u + bw / 2.0, v - bh / 2.0, v + bh / 2.0);
        let mut c = [0.0; 3];
        let mut a = 0.0;
        let mut j = v0.floor();
        while j < v1 {
            let wj = v1.min(j + 1.0) - v0.max(j);
            let mut i = u0.floor();
            while i < u1 {
                let wi = u1.min(i + 1.0) - u0.max(i);
                let (tc, ta) = self.at(i as i64, j as i64);
                for ch in 0..3 {
                    c[ch] += wi * wj * tc[ch];
                }
                a += wi * wj * ta;
                i += 1.0;
            }
            j += 1.0;
        }
        let n = bw * bh;
        (c.map(|v| v / n), a / n)
    }
}

/// The area of the convex polygon `poly` inside pixel `(x, y)`.
fn coverage(poly: &[(f64, f64)], x: f64, y: f64) -> f64 {
    let mut p: Vec<(f64, f64)> = poly.to_vec();
    // Clip by x >= x, x <= x + 1, y >= y, y <= y + 1.
    let planes: [(f64, f64, f64); 4] = [
        (1.0, 0.0, -x),
        (-1.0, 0.0, x + 1.0),
        (0.0, 1.0, -y),
        (0.0, -1.0, y + 1.0),
    ];
    for (a, b, c) in planes {
        let f = |q: (f64, f64)| a * q.0 + b * q.1 + c;
        let mut out = Vec::new();
        for k in 0..p.len() {
            let (s, e) = (p[k], p[(k + 1) % p.len()]);
            let (fs, fe) = (f(s), f(e));
            if fs >= 0.0 {
                out.push(s);
            }
            if (fs >= 0.0) != (fe >= 0.0) {
                let t = fs / (fs - fe);
                out.push((s.0 + t * (e.0 - s.0), s.1 + t * (e.1 - s.1)));
            }
        }
        p = out;
        if p.is_empty() {
            return 0.0;
        }
    }
    let mut area = 0.0;
    for k in 0..p.len() {
        let (a, b) = (p[k], p[(k + 1) % p.len()]);
        area += a.0 * b.1 - a.1 * b.0;
    }
    (area / 2.0).abs()
}

const W: u16 = 96;
const H: u16 = 96;

/// The frame's resolved linear values, drawn in bands of `rows`.
fn render<const C: usize>(
    rows: u16,
    bg: [u16; C],
    mut draw: impl FnMut(&mut Canvas<'_, '_, C>) -> Result<(), DrawError>,
) -> (Vec<[u16; C]>, Option<DrawError>) {
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(W, rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(W, rows)];
    let mut out = vec![[0u16; C]; usize::from(W) * usize::from(H)];
    let mut err = None;
    for band in Bands::new(W, H, rows) {
        let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear(bg);
        let mut canvas = Canvas::new(&mut buf, None);
        if let Err(e) = draw(&mut canvas) {
            err.get_or_insert(e);
        }
        for y in band.row_range() {
            for x in 0..i32::from(W) {
                out[y as usize * usize::from(W) + x as usize] = buf.lin12(x, y).unwrap();
            }
        }
    }
    (out, err)
}

/// A random transform whose image stays inside the frame.
fn random_xf(
    rng: &mut Lcg,
    w: u16,
    h: u16,
    min_scale: u32,
    max_scale: u32,
) -> (FinePoint, FinePoint, Scale, Scale, i32) {
    let sc = |rng: &mut Lcg| {
        Scale::from_bits(min_scale + rng.below(u64::from(max_scale - min_scale)) as u32)
    };
    let (sx, sy) = (sc(rng), sc(rng));
    let deg_bits = rng.below(360 << 16) as i32 - (180 << 16);
    let pivot = FinePoint::new(
        rng.below(u64::from(w) * 1024) as i32,
        rng.below(u64::from(h) * 1024) as i32,
    );
    let pos = FinePoint::new(
        30 * 1024 + rng.below(36 * 1024) as i32,
        30 * 1024 + rng.below(36 * 1024) as i32,
    );
    (pos, pivot, sx, sy, deg_bits)
}

/// The worst error (levels of 4095) over the frame of an image drawn by
/// `xf` against the reference `img` filtered by `filter`, composed over
/// `bg` with exact coverage; and the worst error of pixels wholly inside.
fn compare(
    got: &[[u16; 3]],
    bg: [u16; 3],
    img: &RefImage,
    xf: &Xf,
    filter: &dyn Fn(f64, f64) -> ([f64; 3], f64),
) -> (f64, f64) {
    let corners = [
        xf.forward(0.0, 0.0),
        xf.forward(img.w as f64, 0.0),
        xf.forward(img.w as f64, img.h as f64),
        xf.forward(0.0, img.h as f64),
    ];
    let (mut worst, mut inner) = (0.0f64, 0.0f64);
    for y in 0..usize::from(H) {
        for x in 0..usize::from(W) {
            let k = coverage(&corners, x as f64, y as f64);
            let (u, v) = xf.inverse(x as f64 + 0.5, y as f64 + 0.5);
            let (c, a) = if k > 0.0 {
                filter(u, v)
            } else {
                ([0.0; 3], 0.0)
            };
            for ch in 0..3 {
                let want = f64::from(bg[ch]) * (1.0 - k * a) + k * c[ch];
                let e = (f64::from(got[y * usize::from(W) + x][ch]) - want).abs();
                worst = worst.max(e);
                if k >= 1.0 - 1e-9 {
                    inner = inner.max(e);
                }
            }
        }
    }
    (worst, inner)
}

fn rgb_image(rng: &mut Lcg, w: u16, h: u16, alpha: bool) -> (Vec<u8>, RefImage) {
    let n = usize::from(w) * usize::from(h);
    let mut bytes = Vec::new();
    let mut px = Vec::new();
    for _ in 0..n {
        let c = [
            rng.below(256) as u8,
            rng.below(256) as u8,
            rng.below(256) as u8,
        ];
        // Alpha: often 0 or 255, else anything.
        let a = match rng.below(4) {
            0 => 0u8,
            1 => 255,
            _ => rng.below(256) as u8,
        };
        bytes.extend_from_slice(&c);
        if alpha {
            bytes.push(a);
        }
        let af = if alpha { f64::from(a) / 255.0 } else { 1.0 };
        px.push((
            c.map(|v| f64::from(SRGB8_TO_LIN12[usize::from(v)]) * af),
            af,
        ));
    }
    (
        bytes,
        RefImage {
            w: usize::from(w),
            h: usize::from(h),
            px,
        },
    )
}

fn draw_with<S: ImageSource>(
    src: &S,
    t: (FinePoint, FinePoint, Scale, Scale, i32),
) -> AaImage<'_, S> {
    let (pos, pivot, sx, sy, deg) = t;
    AaImage::new(src)
        .pivot(pivot)
        .position(pos)
        .scale_xy(sx, sy)
        .rotate(Degrees::from_bits(deg))
}

const TOL: f64 = 4095.0 / 256.0;

#[test]
fn bilinear_opaque_images_match_the_f64_filter_within_1_256_at_any_transform() {
    let mut rng = Lcg(0x1a2b_3c4d);
    let (mut worst, mut inner) = (0.0f64, 0.0f64);
    for case in 0..60 {
        let (w, h) = (1 + rng.below(24) as u16, 1 + rng.below(24) as u16);
        let (bytes, img) = rgb_image(&mut rng, w, h, false);
        let src = RawImage::<format::Rgb888>::new(&bytes, w, h).unwrap();
        // Scales 1/2 .. 3: bilinear.
        let t = random_xf(&mut rng, w, h, 32768, 3 << 16);
        let xf = Xf::of(t.0, t.1, t.2, t.3, t.4);
        let bg = [rng.below(4096) as u16, 700, 3000];
        let (got, err) = render::<3>(16, bg, |c| c.draw_image(&draw_with(&src, t)));
        assert_eq!(err, None, "case {case}");
        let (e, i) = compare(&got, bg, &img, &xf, &|u, v| img.bilinear(u, v));
        assert!(e <= TOL, "case {case}: {e} levels ({t:?})");
        worst = worst.max(e);
        inner = inner.max(i);
    }
    println!(
        "bilinear, opaque: worst {worst:.2} levels of 4095, inside {inner:.2} (bound {TOL:.2})"
    );
}

#[test]
fn images_with_alpha_match_within_1_256_and_one_level() {
    let mut rng = Lcg(0x5eed_a1fa);
    let mut worst = 0.0f64;
    for case in 0..60 {
        let (w, h) = (1 + rng.below(20) as u16, 1 + rng.below(20) as u16);
        let (bytes, img) = rgb_image(&mut rng, w, h, true);
        let src = RawImage::<format::Rgba8888>::new(&bytes, w, h).unwrap();
        let t = random_xf(&mut rng, w, h, 32768, 4 << 16);
        let xf = Xf::of(t.0, t.1, t.2, t.3, t.4);
        let bg = [rng.below(4096) as u16, rng.below(4096) as u16, 0];
        let (got, err) = render::<3>(16, bg, |c| c.draw_image(&draw_with(&src, t)));
        assert_eq!(err, None);
        let (e, _) = compare(&got, bg, &img, &xf, &|u, v| img.bilinear(u, v));
        assert!(e <= TOL + 1.0, "case {case}: {e} levels");
        worst = worst.max(e);
    }
    println!(
        "bilinear, alpha: worst {worst:.2} levels of 4095 (bound {:.2})",
        TOL + 1.0
    );
}

#[test]
fn minified_images_match_the_f64_box_average() {
    let mut rng = Lcg(0xb0c5);
    let mut worst = 0.0f64;
    for case in 0..30 {
        let (w, h) = (8 + rng.below(60) as u16, 8 + rng.below(60) as u16);
        let (bytes, img) = rgb_image(&mut rng, w, h, case % 2 == 1);
        // Scales 1/16 .. 1/2 on one axis at least.
        let t0 = random_xf(&mut rng, w, h, 4096, 32768);
        let t = if case % 3 == 0 {
            (t0.0, t0.1, t0.2, Scale::from_int(1), t0.4)
        } else {
            t0
        };
        let xf = Xf::of(t.0, t.1, t.2, t.3, t.4);
        let (bw, bh) = ((1.0 / xf.s.0).max(1.0), (1.0 / xf.s.1).max(1.0));
        let bg = [2000, 100, 4000];
        let (got, err) = if case % 2 == 1 {
            let src = RawImage::<format::Rgba8888>::new(&bytes, w, h).unwrap();
            render::<3>(16, bg, |c| c.draw_image(&draw_with(&src, t)))
        } else {
            let src = RawImage::<format::Rgb888>::new(&bytes, w, h).unwrap();
            render::<3>(16, bg, |c| c.draw_image(&draw_with(&src, t)))
        };
        assert_eq!(err, None);
        let (e, _) = compare(&got, bg, &img, &xf, &|u, v| img.boxed(u, v, bw, bh));
        assert!(e <= TOL + 1.0, "case {case}: {e} levels");
        worst = worst.max(e);
    }
    println!("box, minified: worst {worst:.2} levels of 4095");
}

#[test]
fn tinted_masks_scale_smoothly_against_the_f64_filter() {
    let mut rng = Lcg(0x1c0);
    let mut worst = 0.0f64;
    for case in 0..30 {
        let (w, h) = (24u16, 24u16);
        let stride = 3;
        let bytes: Vec<u8> = (0..stride * usize::from(h))
            .map(|_| rng.below(256) as u8)
            .collect();
        let src = RawImage::<format::Alpha1>::new(&bytes, w, h).unwrap();
        let tint = [4095u16, 1800, 300];
        let px = (0..usize::from(h))
            .flat_map(|j| (0..usize::from(w)).map(move |i| (i, j)))
            .map(|(i, j)| {
                let bit = (bytes[j * stride + i / 8] >> (7 - i % 8)) & 1;
                let a = f64::from(bit);
                (tint.map(|t| f64::from(t) * a), a)
            })
            .collect();
        let img = RefImage { w: 24, h: 24, px };
        let t = random_xf(&mut rng, w, h, 65536, 3 << 16);
        let xf = Xf::of(t.0, t.1, t.2, t.3, t.4);
        let bg = [0, 0, 500];
        let (got, err) = render::<3>(16, bg, |c| c.draw_image(&draw_with(&src, t).tint(tint)));
        assert_eq!(err, None);
        let (e, _) = compare(&got, bg, &img, &xf, &|u, v| img.bilinear(u, v));
        assert!(e <= TOL + 1.0, "case {case}: {e} levels");
        worst = worst.max(e);
    }
    println!("tinted 1-bpp masks: worst {worst:.2} levels of 4095");
}

/// A white opaque image on black: each pixel's value is its coverage.
#[test]
fn edge_coverage_is_within_1_256_of_the_exact_area() {
    let mut rng = Lcg(0xed9e);
    let white = vec![255u8; 40 * 40];
    let mut worst = 0.0f64;
    for _ in 0..40 {
        let (w, h) = (1 + rng.below(40) as u16, 1 + rng.below(40) as u16);
        let src = RawImage::<format::Gray8>::new(&white, w, h).unwrap();
        let t = random_xf(&mut rng, w, h, 16384, 2 << 16);
        let xf = Xf::of(t.0, t.1, t.2, t.3, t.4);
        let corners = [
            xf.forward(0.0, 0.0),
            xf.forward(f64::from(w), 0.0),
            xf.forward(f64::from(w), f64::from(h)),
            xf.forward(0.0, f64::from(h)),
        ];
        let (got, _) = render::<1>(16, [0], |c| c.draw_image(&draw_with(&src, t)));
        for y in 0..usize::from(H) {
            for x in 0..usize::from(W) {
                let k = coverage(&corners, x as f64, y as f64);
                let e = (f64::from(got[y * usize::from(W) + x][0]) / 4095.0 - k).abs();
                worst = worst.max(e);
            }
        }
    }
    assert!(worst <= 1.0 / 256.0, "{worst}");
    println!(
        "edge coverage: worst {worst:.5} of a pixel (bound {:.5})",
        1.0 / 256.0
    );
}

#[test]
fn every_band_height_gives_the_same_pixels() {
    let mut rng = Lcg(0xba9d);
    for case in 0..12 {
        let (w, h) = (4 + rng.below(30) as u16, 4 + rng.below(30) as u16);
        let alpha = case % 2 == 0;
        let (bytes, _) = rgb_image(&mut rng, w, h, alpha);
        let t = random_xf(&mut rng, w, h, 4096, 4 << 16);
        let frame = |rows| {
            if alpha {
                let src = RawImage::<format::Rgba8888>::new(&bytes, w, h).unwrap();
                render::<3>(rows, [100, 200, 300], |c| {
                    c.draw_image(&draw_with(&src, t).opacity(Opacity::from_ratio(2, 3).unwrap()))
                })
                .0
            } else {
                let src = RawImage::<format::Rgb888>::new(&bytes, w, h).unwrap();
                render::<3>(rows, [100, 200, 300], |c| c.draw_image(&draw_with(&src, t))).0
            }
        };
        let whole = frame(H);
        for rows in [1, 3, 7, 16] {
            assert!(frame(rows) == whole, "case {case}: {rows} rows");
        }
    }
}

#[test]
fn unscaled_images_at_whole_pixels_are_copied_texel_for_pixel() {
    // Rgb565 little endian: every texel decodes to the tables' values.
    let mut rng = Lcg(0xc0b1);
    let (w, h) = (17u16, 9u16);
    let bytes: Vec<u8> = (0..2 * usize::from(w) * usize::from(h))
        .map(|_| rng.below(256) as u8)
        .collect();
    let src = RawImage::<format::Rgb565>::new(&bytes, w, h).unwrap();
    let (got, _) = render::<3>(4, [0; 3], |c| {
        c.draw_image(&AaImage::new(&src).position(FinePoint::from_px(5, 7)))
    });
    use softedge::color::srgb::{SRGB5_TO_LIN12, SRGB6_TO_LIN12};
    for j in 0..usize::from(h) {
        for i in 0..usize::from(w) {
            let k = 2 * (j * usize::from(w) + i);
            let v = u16::from(bytes[k]) | u16::from(bytes[k + 1]) << 8;
            let want = [
                SRGB5_TO_LIN12[usize::from(v >> 11)],
                SRGB6_TO_LIN12[usize::from((v >> 5) & 63)],
                SRGB5_TO_LIN12[usize::from(v & 31)],
            ];
            assert_eq!(
                got[(j + 7) * usize::from(W) + i + 5],
                want,
                "texel {i}, {j}"
            );
        }
    }
    assert_eq!(got[6 * usize::from(W) + 5], [0; 3]);
    assert_eq!(got[7 * usize::from(W) + 4], [0; 3]);
}

/// `bytes` as a `w x h` image of format `kind` (Rgb565, Rgb565Be, Rgb888,
/// Gray8) drawn unscaled at `at`.
fn copy_image<const C: usize>(
    c: &mut Canvas<'_, '_, C>,
    kind: u32,
    bytes: &[u8],
    w: u16,
    h: u16,
    at: FinePoint,
) -> Result<(), DrawError> {
    fn one<F: format::TexelFormat, const C: usize>(
        c: &mut Canvas<'_, '_, C>,
        bytes: &[u8],
        w: u16,
        h: u16,
        at: FinePoint,
    ) -> Result<(), DrawError> {
        let src = RawImage::<F>::new(bytes, w, h).expect("a whole image");
        c.draw_image(&AaImage::new(&src).position(at))
    }
    match kind {
        0 => one::<format::Rgb565, C>(c, bytes, w, h, at),
        1 => one::<format::Rgb565Be, C>(c, bytes, w, h, at),
        2 => one::<format::Rgb888, C>(c, bytes, w, h, at),
        _ => one::<format::Gray8, C>(c, bytes, w, h, at),
    }
}

/// Every opaque format of whole bytes, unscaled at whole pixels and
/// partly outside the frame (runs that start and end inside the image's
/// rows, and runs cut by its sides), on three channels and on one: each
/// pixel the texel decoded by the sRGB tables from the bytes (its
/// luminance on one channel), every other pixel the background.
#[test]
fn unscaled_opaque_formats_copy_every_texel_on_every_run() {
    use softedge::color::srgb::{luminance, SRGB5_TO_LIN12, SRGB6_TO_LIN12};
    let t5 = |v: u32| SRGB5_TO_LIN12[(v & 31) as usize];
    let t8 = |v: u32| SRGB8_TO_LIN12[(v & 255) as usize];
    let decode = |kind: u32, b: &[u8]| -> [u16; 3] {
        match kind {
            0 | 1 => {
                let v = if kind == 0 {
                    u32::from(b[0]) | u32::from(b[1]) << 8
                } else {
                    u32::from(b[1]) | u32::from(b[0]) << 8
                };
                [t5(v >> 11), SRGB6_TO_LIN12[((v >> 5) & 63) as usize], t5(v)]
            }
            2 => [t8(b[0].into()), t8(b[1].into()), t8(b[2].into())],
            _ => [t8(b[0].into()); 3],
        }
    };
    let mut rng = Lcg(0x5eed_c0b1);
    for case in 0..48 {
        let kind = case % 4;
        let bpt = [2usize, 2, 3, 1][kind as usize];
        let (w, h) = (1 + rng.below(40) as u16, 1 + rng.below(30) as u16);
        let bytes: Vec<u8> = (0..bpt * usize::from(w) * usize::from(h))
            .map(|_| rng.below(256) as u8)
            .collect();
        let (px, py) = (
            rng.below(u64::from(W) + 40) as i32 - 40,
            rng.below(u64::from(H) + 30) as i32 - 30,
        );
        let rows = [1u16, 3, 16][case as usize % 3];
        let bg = [100u16, 2000, 4095];
        let at = FinePoint::from_px(px, py);
        let (got3, err) = render::<3>(rows, bg, |c| copy_image(c, kind, &bytes, w, h, at));
        assert!(err.is_none(), "case {case}: {err:?}");
        let (got1, err) = render::<1>(rows, [bg[1]], |c| copy_image(c, kind, &bytes, w, h, at));
        assert!(err.is_none(), "case {case}: {err:?}");
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let (i, j) = (x - px, y - py);
                let k = y as usize * usize::from(W) + x as usize;
                let inside = (0..i32::from(w)).contains(&i) && (0..i32::from(h)).contains(&j);
                let (want3, want1) = if inside {
                    let o = bpt * (j as usize * usize::from(w) + i as usize);
                    let c = decode(kind, &bytes[o..o + bpt]);
                    (c, [if kind == 3 { c[0] } else { luminance(c) }])
                } else {
                    (bg, [bg[1]])
                };
                assert_eq!(got3[k], want3, "case {case} ({kind}), pixel {x}, {y}");
                assert_eq!(got1[k], want1, "case {case} ({kind}) gray, pixel {x}, {y}");
            }
        }
    }
}

#[test]
fn bad_images_and_transforms_are_typed_errors_and_draw_nothing() {
    let data = [0u8; 64];
    assert_eq!(
        RawImage::<format::Rgb565>::new(&data, 8, 8).err(),
        Some(ImageFault::Truncated {
            needed: 128,
            have: 64
        })
    );
    assert!(matches!(
        RawImage::<format::Gray8>::new(&data, 0, 8),
        Err(ImageFault::Size { .. })
    ));
    let src = RawImage::<format::Gray8>::new(&data, 8, 8).unwrap();
    let plane = RawImage::<format::PlaneAlpha<format::Gray8>>::new(&data, 8, 8).unwrap();
    assert!(matches!(
        plane.with_alpha_plane(&data[..10]),
        Err(ImageFault::Truncated { .. })
    ));
    let cases: [(AaImage<'_, _>, ImageFault); 3] = [
        (
            AaImage::new(&src).scale(Scale::from_bits(0)),
            ImageFault::Scale { scale: 0 },
        ),
        (
            AaImage::new(&src).scale(Scale::from_ratio(1, 100)),
            ImageFault::Scale { scale: 655 },
        ),
        (
            AaImage::new(&src)
                .position(FinePoint::from_px(2040, 0))
                .scale(Scale::from_int(100)),
            ImageFault::Range,
        ),
    ];
    for (img, fault) in cases {
        let img = img.name("gauge face");
        let (got, err) = render::<1>(16, [1234], |c| c.draw_image(&img));
        match err {
            Some(DrawError::Image(e)) => {
                assert_eq!(e.image, "gauge face");
                assert_eq!(e.fault, fault);
                assert!(e.to_string().starts_with("image `gauge face`: "));
            }
            other => panic!("{other:?}"),
        }
        assert!(got.iter().all(|&p| p == [1234]), "nothing drawn");
    }
}

/// An image drawn inside a clip shape: nothing outside the shape.
#[test]
fn a_clip_shape_bounds_what_is_drawn() {
    let white = vec![255u8; 32 * 32];
    let src = RawImage::<format::Gray8>::new(&white, 32, 32).unwrap();
    let disc = softedge::path::Circle::new(FinePoint::from_px(40, 40), 10 * 1024);
    let (got, _) = render::<1>(8, [0], |c| {
        c.draw_image(
            &AaImage::new(&src)
                .center(FinePoint::from_px(40, 40))
                .clip(&disc),
        )
    });
    for y in 0..usize::from(H) {
        for x in 0..usize::from(W) {
            let (dx, dy) = (x as f64 + 0.5 - 40.0, y as f64 + 0.5 - 40.0);
            let d = (dx * dx + dy * dy).sqrt();
            let v = got[y * usize::from(W) + x][0];
            if d > 11.0 {
                assert_eq!(v, 0, "({x}, {y})");
            }
            if d < 9.0 {
                assert_eq!(v, 4095, "({x}, {y})");
            }
        }
    }
}

/// A QOI file of `rgba` (`w x h`): runs of equal texels and QOI_OP_RGBA
/// for the rest (a valid QOI stream, written here).
fn qoi(rgba: &[u8], w: u32, h: u32) -> Vec<u8> {
    let mut f = b"qoif".to_vec();
    f.extend_from_slice(&w.to_be_bytes());
    f.extend_from_slice(&h.to_be_bytes());
    f.extend_from_slice(&[4, 0]);
    let mut prev = [0u8, 0, 0, 255];
    let mut run = 0u8;
    for p in rgba.chunks_exact(4) {
        if p == prev && run < 62 {
            run += 1;
            continue;
        }
        if run > 0 {
            f.push(0xc0 | (run - 1));
            run = 0;
        }
        if p == prev {
            run = 1;
            continue;
        }
        f.push(0xff);
        f.extend_from_slice(p);
        prev = [p[0], p[1], p[2], p[3]];
    }
    if run > 0 {
        f.push(0xc0 | (run - 1));
    }
    f.extend_from_slice(&[0, 0, 0, 0, 0, 0, 0, 1]);
    f
}

/// A QOI image decoded row by row into a row cache draws the pixels of
/// the same texels in memory, in every band height; a band needing more
/// rows than the cache holds, or rows above its window (the image upside
/// down), is refused with a typed error and draws nothing.
#[test]
fn qoi_images_decode_row_by_row_into_a_row_cache() {
    use softedge::image::QoiImage;
    let mut rng = Lcg(0x9017);
    let (w, h) = (20u16, 30u16);
    // Runs of equal texels, so the stream has runs.
    let mut rgba = Vec::new();
    while rgba.len() < 4 * usize::from(w) * usize::from(h) {
        let p = [
            rng.below(256) as u8,
            rng.below(256) as u8,
            90,
            rng.below(256) as u8,
        ];
        for _ in 0..1 + rng.below(5) {
            rgba.extend_from_slice(&p);
        }
    }
    rgba.truncate(4 * usize::from(w) * usize::from(h));
    let file = qoi(&rgba, u32::from(w), u32::from(h));
    let raw = RawImage::<format::Rgba8888>::new(&rgba, w, h).unwrap();
    let t = (
        FinePoint::from_px(40, 40),
        FinePoint::new(10 * 1024, 15 * 1024),
        Scale::from_ratio(3, 2),
        Scale::from_ratio(3, 2),
        20 << 16,
    );
    for rows in [1, 4, 16] {
        let want = render::<3>(rows, [0, 300, 0], |c| c.draw_image(&draw_with(&raw, t))).0;
        let mut cache = vec![0u8; 4 * usize::from(w) * 24];
        let img = QoiImage::new(&file, &mut cache).unwrap();
        let (got, err) = render::<3>(rows, [0, 300, 0], |c| c.draw_image(&draw_with(&img, t)));
        assert_eq!(err, None, "{rows} rows");
        assert!(got == want, "{rows} rows");
    }
    // Too small a cache for a 16-row band of this image.
    let mut cache = vec![0u8; 4 * usize::from(w) * 4];
    let img = QoiImage::new(&file, &mut cache).unwrap();
    let (got, err) = render::<3>(16, [0, 300, 0], |c| c.draw_image(&draw_with(&img, t)));
    assert!(
        matches!(err, Some(DrawError::Image(e)) if matches!(e.fault, ImageFault::RowCache { .. })),
        "{err:?}"
    );
    // Upside down: each band needs rows above the last band's.
    let mut cache = vec![0u8; 4 * usize::from(w) * 30];
    let img = QoiImage::new(&file, &mut cache).unwrap();
    let flipped = (t.0, t.1, t.2, t.3, 180 << 16);
    let (_, err) = render::<3>(4, [0, 300, 0], |c| c.draw_image(&draw_with(&img, flipped)));
    assert!(
        matches!(err, Some(DrawError::Image(e)) if matches!(e.fault, ImageFault::RandomAccess { .. })),
        "{err:?}"
    );
    let _ = got;
    assert_eq!(
        QoiImage::new(b"qoix", &mut [0u8; 8]).err(),
        Some(ImageFault::Unsupported)
    );
}
