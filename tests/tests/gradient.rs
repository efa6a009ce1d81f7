//! Gradient fills (issue #16): linear and radial gradients with stops,
//! interpolated in linear light, against references written here — the
//! definition of the gradient in exact integers (which segment a pixel
//! centre is in) and `f64` (the colour there), never the code under test.
//!
//! - every pixel of random gradients (2 to 8 stops, hard stops, random
//!   geometry from sub-pixel to full-range lengths) within the documented
//!   bound of the exact value at its centre: linear 0.57 levels after the
//!   resolve (0.07 before it), radial the same plus the colour's change
//!   over the distance quantum (`(1 + √2) / 256` px);
//! - linear light (black to white is half the light half way), no banding
//!   (a 240-px ramp rises by at most 1 + ceil(4095 / 240) levels per pixel,
//!   never falls), pads, hard stops, degenerate gradients, bad stop lists;
//! - band invariance (heights 1, 3, 16, 240, with and without the walk
//!   cache), a shape cut in two equals the whole (add: every bit; over:
//!   every pixel off the cut), edge pixels composed like a flat colour's,
//!   strokes, and geometry at the limits of the coordinate range.

// Per-channel loops index several arrays at once.
#![allow(clippy::needless_range_loop)]

use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
use softedge::canvas::{Canvas, Contour, WalkCache, WalkSlot};
use softedge::geom::{FinePoint, FINE_LIMIT};
use softedge::path::{
    Circle, CornerRadii, Ellipse, LineJoin, Polyline, Rectangle, RoundedRectangle, StrokeStyle,
};
use softedge::style::{
    Blend, FillRule, Gradient, GradientError, GradientKind, Offset, Opacity, Stop, MAX_STOPS,
};
use softedge::tone::{Curve, GammaLut};
use softedge::{BandBuffer, Bands};

/// One level in accumulator units.
const LEVEL: f64 = 65536.0;
/// How far from the true distance the radial gradient colours a pixel, px:
/// half the 1/128-px quantum plus the centre's rounding to the 1/128-px
/// grid.
const RADIAL_DELTA_PX: f64 = (1.0 + std::f64::consts::SQRT_2) / 256.0;

// ------------------------------------------------------------- harness

/// A seeded generator (64-bit LCG, high bits): reproducible cases.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        self.0 >> 16
    }
    fn below(&mut self, n: u64) -> u64 {
        self.next() % n.max(1)
    }
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
    fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
}

/// A frame read back from its bands: raw accumulator and lin12 values.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Frame<const C: usize> {
    w: i32,
    raw: Vec<[i32; C]>,
    lin: Vec<[u16; C]>,
}

impl<const C: usize> Frame<C> {
    fn raw(&self, x: i32, y: i32) -> [i32; C] {
        self.raw[(y * self.w + x) as usize]
    }
    fn lin(&self, x: i32, y: i32) -> [u16; C] {
        self.lin[(y * self.w + x) as usize]
    }
}

/// Draws a `w x h` frame in bands of `rows` over `bg`, the closure called
/// once per band with a canvas (with a walk cache when `cache`).
fn render<const C: usize>(
    w: u16,
    h: u16,
    rows: u16,
    bg: [u16; C],
    cache: bool,
    mut draw: impl FnMut(&mut Canvas<'_, '_, C>),
) -> Frame<C> {
    let (wu, hu) = (usize::from(w), usize::from(h));
    let mut raw = vec![[0i32; C]; wu * hu];
    let mut lin = vec![[0u16; C]; wu * hu];
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(w, rows)];
    let mut slots = vec![WalkSlot::<C>::EMPTY; 256];
    WalkCache::new(&mut slots).clear();
    for band in Bands::new(w, h, rows) {
        let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear(bg);
        {
            let c = cache.then(|| WalkCache::new(&mut slots));
            let mut canvas = Canvas::new(&mut buf, c);
            draw(&mut canvas);
            assert_eq!(canvas.skipped().count, 0, "{:?}", canvas.skipped());
        }
        for y in band.row_range() {
            for x in 0..i32::from(w) {
                let k = y as usize * wu + x as usize;
                raw[k] = buf.raw(x, y).unwrap();
                lin[k] = buf.lin12(x, y).unwrap();
            }
        }
    }
    Frame {
        w: i32::from(w),
        raw,
        lin,
    }
}

/// The whole frame as one rectangle (every pixel fully covered).
fn cover_all(w: i32, h: i32) -> [FinePoint; 4] {
    let p = FinePoint::from_px;
    [p(0, 0), p(w, 0), p(w, h), p(0, h)]
}

// ----------------------------------------------------------- reference

/// A gradient as the tests define it: geometry in fine units, stops as
/// (offset in 1/4096, linear colour).
#[derive(Debug, Clone)]
struct Spec<const C: usize> {
    kind: Kind,
    stops: Vec<(i64, [u16; C])>,
}

#[derive(Debug, Clone, Copy)]
enum Kind {
    Linear { p0: (i64, i64), p1: (i64, i64) },
    Radial { c: (i64, i64), r: i64 },
}

impl<const C: usize> Spec<C> {
    fn gradient(&self) -> Gradient<C> {
        let stops: Vec<Stop<C>> = self
            .stops
            .iter()
            .map(|&(o, c)| Stop::lin(Offset::from_4096ths(o as u16), c))
            .collect();
        let fp = |(x, y): (i64, i64)| FinePoint::new(x as i32, y as i32);
        match self.kind {
            Kind::Linear { p0, p1 } => Gradient::linear(fp(p0), fp(p1), &stops),
            Kind::Radial { c, r } => Gradient::radial(fp(c), r as i32, &stops),
        }
        .unwrap()
    }

    /// The colour of the segment (or pad) the parameter `t = num / den`
    /// falls in, decided exactly: stop `i` is at or before `t` when
    /// `O_i den <= 4096 num`; the later of equal stops wins.
    fn colour_exact(&self, num: i128, den: i128) -> [f64; C] {
        let s = &self.stops;
        let r = s
            .iter()
            .filter(|(o, _)| i128::from(*o) * den <= 4096 * num)
            .count();
        if r == 0 {
            return s[0].1.map(f64::from);
        }
        if r == s.len() {
            return s[s.len() - 1].1.map(f64::from);
        }
        let ((oa, ca), (ob, cb)) = (s[r - 1], s[r]);
        let u = (4096 * num - i128::from(oa) * den) as f64 / (i128::from(ob - oa) * den) as f64;
        std::array::from_fn(|ch| f64::from(ca[ch]) + (f64::from(cb[ch]) - f64::from(ca[ch])) * u)
    }

    /// The colour at a real parameter `t`.
    fn colour_at(&self, t: f64) -> [f64; C] {
        let s = &self.stops;
        let r = s.iter().filter(|(o, _)| *o as f64 / 4096.0 <= t).count();
        if r == 0 {
            return s[0].1.map(f64::from);
        }
        if r == s.len() {
            return s[s.len() - 1].1.map(f64::from);
        }
        let ((oa, ca), (ob, cb)) = (s[r - 1], s[r]);
        let u = (t - oa as f64 / 4096.0) / ((ob - oa) as f64 / 4096.0);
        std::array::from_fn(|ch| f64::from(ca[ch]) + (f64::from(cb[ch]) - f64::from(ca[ch])) * u)
    }

    /// The least and greatest colour over parameters `t0..=t1`: the
    /// colour is piecewise linear, so they are at the ends or at stops
    /// (every stop colour there, for the two sides of a hard stop).
    fn colour_span(&self, t0: f64, t1: f64) -> ([f64; C], [f64; C]) {
        let mut lo = self.colour_at(t0);
        let mut hi = lo;
        let mut see = |c: [f64; C]| {
            for ch in 0..C {
                lo[ch] = lo[ch].min(c[ch]);
                hi[ch] = hi[ch].max(c[ch]);
            }
        };
        see(self.colour_at(t1));
        for &(o, c) in &self.stops {
            let t = o as f64 / 4096.0;
            if t >= t0 && t <= t1 {
                see(c.map(f64::from));
                see(self.colour_at(t));
            }
        }
        (lo, hi)
    }

    /// The exact parameter of pixel `(x, y)`'s centre: `num / den`
    /// (linear, exactly), or as `f64` (radial).
    fn linear_t(&self, x: i32, y: i32) -> (i128, i128) {
        let Kind::Linear { p0, p1 } = self.kind else {
            unreachable!()
        };
        let (dx, dy) = (i128::from(p1.0 - p0.0), i128::from(p1.1 - p0.1));
        let (cx, cy) = (1024 * i128::from(x) + 512, 1024 * i128::from(y) + 512);
        let num = (cx - i128::from(p0.0)) * dx + (cy - i128::from(p0.1)) * dy;
        (num, dx * dx + dy * dy)
    }

    /// The exact distance (px) of pixel `(x, y)`'s centre from a radial
    /// gradient's centre, and the radius (px).
    fn radial_d(&self, x: i32, y: i32) -> (f64, f64) {
        let Kind::Radial { c, r } = self.kind else {
            unreachable!()
        };
        let (cx, cy) = (1024 * i128::from(x) + 512, 1024 * i128::from(y) + 512);
        let (ux, uy) = (cx - i128::from(c.0), cy - i128::from(c.1));
        (
            ((ux * ux + uy * uy) as f64).sqrt() / 1024.0,
            r as f64 / 1024.0,
        )
    }
}

/// Random stops: 2..=8 of them, offsets sorted (some equal: hard stops,
/// some at 0 and 1), random colours.
fn random_stops<const C: usize>(rng: &mut Rng) -> Vec<(i64, [u16; C])> {
    let n = rng.range(2, MAX_STOPS as i64) as usize;
    let mut offsets: Vec<i64> = (0..n).map(|_| rng.range(0, 4096)).collect();
    offsets.sort_unstable();
    if rng.chance(30) {
        offsets[0] = 0;
        offsets[n - 1] = 4096;
    }
    for i in 1..n {
        if rng.chance(15) {
            offsets[i] = offsets[i - 1];
        }
    }
    offsets
        .into_iter()
        .map(|o| (o, std::array::from_fn(|_| rng.below(4096) as u16)))
        .collect()
}

/// A random fine coordinate around a `w`-px extent: mostly near the
/// frame, sometimes anywhere in the range.
fn random_coord(rng: &mut Rng, w: i64) -> i64 {
    if rng.chance(10) {
        rng.range(-i64::from(FINE_LIMIT), i64::from(FINE_LIMIT))
    } else {
        rng.range(-40 * 1024, (w + 40) * 1024)
    }
}

fn random_linear<const C: usize>(rng: &mut Rng, w: i64, h: i64) -> Spec<C> {
    let p0 = (random_coord(rng, w), random_coord(rng, h));
    let p1 = match rng.below(4) {
        // Short: sub-pixel to a few pixels.
        0 => {
            let mut q = (p0.0 + rng.range(-3000, 3000), p0.1 + rng.range(-3000, 3000));
            if q == p0 {
                q.0 += 1;
            }
            q
        }
        // Axis-aligned (a zero x or y step).
        1 if rng.chance(50) => (p0.0, p0.1 + rng.range(1, 80 * 1024)),
        1 => (p0.0 - rng.range(1, 80 * 1024), p0.1),
        _ => loop {
            let q = (random_coord(rng, w), random_coord(rng, h));
            if q != p0 {
                break q;
            }
        },
    };
    let clamp = |v: i64| v.clamp(-i64::from(FINE_LIMIT), i64::from(FINE_LIMIT));
    Spec {
        kind: Kind::Linear {
            p0,
            p1: (clamp(p1.0), clamp(p1.1)),
        },
        stops: random_stops(rng),
    }
}

fn random_radial<const C: usize>(rng: &mut Rng, w: i64, h: i64) -> Spec<C> {
    let c = (random_coord(rng, w), random_coord(rng, h));
    let r = match rng.below(6) {
        0 => rng.range(1, 2048),
        1 => rng.range(1, i64::from(i32::MAX)),
        _ => rng.range(1024, 200 * 1024),
    };
    Spec {
        kind: Kind::Radial { c, r },
        stops: random_stops(rng),
    }
}

/// The biggest error seen, in levels.
#[derive(Default, Debug)]
struct Worst {
    raw: f64,
    lin: f64,
}

// --------------------------------------------------------------- tests

#[test]
fn linear_gradients_match_the_exact_colour_at_every_pixel_centre() {
    const W: u16 = 40;
    const H: u16 = 32;
    let mut rng = Rng(0x6772_6164_6c69_6e31);
    let mut worst = Worst::default();
    for case in 0..250 {
        let spec: Spec<3> = random_linear(&mut rng, W.into(), H.into());
        let g = spec.gradient();
        let rows = [1, 7, 32][case % 3];
        let bg = [rng.below(4096) as u16; 3];
        let all = cover_all(W.into(), H.into());
        let f = render(W, H, rows, bg, false, |c| {
            c.fill_gradient(
                &Contour(&all),
                &g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let (num, den) = spec.linear_t(x, y);
                let exact = spec.colour_exact(num, den);
                let (raw, lin) = (f.raw(x, y), f.lin(x, y));
                for ch in 0..3 {
                    let e_raw = (f64::from(raw[ch]) / LEVEL - exact[ch]).abs();
                    let e_lin = (f64::from(lin[ch]) - exact[ch]).abs();
                    worst.raw = worst.raw.max(e_raw);
                    worst.lin = worst.lin.max(e_lin);
                    assert!(
                        e_raw <= 0.07 && e_lin <= 0.57,
                        "case {case} pixel ({x}, {y}) ch {ch}: raw {} lin {} exact {} ({spec:?})",
                        f64::from(raw[ch]) / LEVEL,
                        lin[ch],
                        exact[ch]
                    );
                }
            }
        }
    }
    eprintln!("linear, worst error in levels: {worst:?}");
}

#[test]
fn radial_gradients_match_the_exact_colour_within_the_distance_quantum() {
    const W: u16 = 40;
    const H: u16 = 32;
    let mut rng = Rng(0x6772_6164_7261_6431);
    let mut worst = Worst::default();
    // The error against the exact value, beyond what the quantum allows.
    let mut worst_plain = 0.0f64;
    for case in 0..250 {
        let spec: Spec<3> = random_radial(&mut rng, W.into(), H.into());
        let g = spec.gradient();
        let rows = [1, 5, 32][case % 3];
        let all = cover_all(W.into(), H.into());
        let f = render(W, H, rows, [0; 3], false, |c| {
            c.fill_gradient(
                &Contour(&all),
                &g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let (d, r) = spec.radial_d(x, y);
                let (t0, t1) = ((d - RADIAL_DELTA_PX) / r, (d + RADIAL_DELTA_PX) / r);
                let (lo, hi) = spec.colour_span(t0, t1);
                let exact = spec.colour_at(d / r);
                let (raw, lin) = (f.raw(x, y), f.lin(x, y));
                for ch in 0..3 {
                    let v = f64::from(raw[ch]) / LEVEL;
                    let l = f64::from(lin[ch]);
                    let out = |v: f64| (lo[ch] - v).max(v - hi[ch]).max(0.0);
                    worst.raw = worst.raw.max(out(v));
                    worst.lin = worst.lin.max(out(l));
                    worst_plain = worst_plain.max((l - exact[ch]).abs() - (hi[ch] - lo[ch]));
                    assert!(
                        out(v) <= 0.05 && out(l) <= 0.55,
                        "case {case} pixel ({x}, {y}) ch {ch}: raw {v} lin {l} in {}..{} ({spec:?})",
                        lo[ch],
                        hi[ch]
                    );
                }
            }
        }
    }
    eprintln!(
        "radial, worst distance beyond the quantum's colour range: {worst:?}; \
         worst |lin - exact| minus that range: {worst_plain}"
    );
}

/// Smooth radial gradients (no segment steeper than 45 levels per px of
/// radius: black to white over 91 px or more): every pixel within one
/// level of the exact value (0.55 + 45 × 0.0095 = 0.98).
#[test]
fn smooth_radial_gradients_are_within_a_level() {
    const W: u16 = 48;
    const H: u16 = 48;
    let mut rng = Rng(0x736d_6f6f_7468);
    let mut worst = 0.0f64;
    let mut checked = 0;
    for _ in 0..60 {
        let r = rng.range(91 * 1024, 300 * 1024);
        let c = (
            rng.range(-20 * 1024, 68 * 1024),
            rng.range(-20 * 1024, 68 * 1024),
        );
        let mut spec: Spec<3> = Spec {
            kind: Kind::Radial { c, r },
            stops: vec![(0, [0; 3]), (4096, [4095; 3])],
        };
        if rng.chance(50) {
            let mid = rng.range(1024, 3072);
            spec.stops.insert(1, (mid, [rng.below(4096) as u16; 3]));
        }
        let slope = spec
            .stops
            .windows(2)
            .map(|p| {
                let dc = (f64::from(p[1].1[0]) - f64::from(p[0].1[0])).abs();
                dc / ((p[1].0 - p[0].0) as f64 / 4096.0 * r as f64 / 1024.0)
            })
            .fold(0.0, f64::max);
        if slope > 45.0 {
            continue;
        }
        checked += 1;
        let g = spec.gradient();
        let all = cover_all(W.into(), H.into());
        let f = render(W, H, 16, [0; 3], false, |cv| {
            cv.fill_gradient(
                &Contour(&all),
                &g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let (d, rr) = spec.radial_d(x, y);
                let exact = spec.colour_at(d / rr);
                let e = (f64::from(f.lin(x, y)[0]) - exact[0]).abs();
                worst = worst.max(e);
                assert!(e <= 1.0, "({x}, {y}): {} vs {}", f.lin(x, y)[0], exact[0]);
            }
        }
    }
    assert!(checked >= 30, "{checked}");
    eprintln!("smooth radial, {checked} gradients, worst |lin12 - exact|: {worst}");
}

#[test]
fn black_to_white_is_half_the_light_half_way() {
    // From the centre of pixel 0 to the centre of pixel 240: pixel 120's
    // centre is half way.
    let g = Gradient::linear(
        FinePoint::centre_of(0, 0),
        FinePoint::centre_of(240, 0),
        &[Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])],
    )
    .unwrap();
    let all = cover_all(241, 2);
    let f = render(241, 2, 2, [0], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    let [mid] = f.lin(120, 1);
    assert!((2047..=2049).contains(&mid), "{mid}");
    // On an sRGB display that is code 187 or 188 (linear light), not 128.
    let code = GammaLut::new(Curve::Srgb).code(mid);
    assert!((186..=188).contains(&code), "{code}");
    assert_eq!(f.lin(0, 0), [0]);
    assert_eq!(f.lin(240, 0), [4095]);

    // Radial: half the radius, half the light.
    let c = FinePoint::centre_of(20, 20);
    let g = Gradient::radial(
        c,
        16 * 1024,
        &[Stop::lin(Offset::ZERO, [4095]), Stop::lin(Offset::ONE, [0])],
    )
    .unwrap();
    let all = cover_all(41, 41);
    let f = render(41, 41, 8, [0], false, |cv| {
        cv.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    for (x, y) in [(28, 20), (12, 20), (20, 28), (20, 12)] {
        let [v] = f.lin(x, y);
        assert!((2046..=2049).contains(&v), "({x}, {y}): {v}");
    }
}

#[test]
fn a_ramp_over_240_pixels_has_no_bands() {
    let stops = [
        Stop::lin(Offset::ZERO, [0; 3]),
        Stop::lin(Offset::ONE, [4095; 3]),
    ];
    let step = 1 + 4095u16.div_ceil(240);
    for (from, to) in [
        (FinePoint::from_px(0, 0), FinePoint::from_px(240, 0)),
        (FinePoint::new(333, 0), FinePoint::new(240 * 1024 - 77, 100)),
    ] {
        let g = Gradient::linear(from, to, &stops).unwrap();
        let all = cover_all(240, 3);
        let f = render(240, 3, 3, [0; 3], false, |c| {
            c.fill_gradient(
                &Contour(&all),
                &g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        for y in 0..3 {
            for x in 1..240 {
                let (a, b) = (f.lin(x - 1, y)[0], f.lin(x, y)[0]);
                assert!(b >= a && b - a <= step, "({x}, {y}): {a} then {b}");
            }
        }
    }
    // Radial, along a ray from the centre.
    let g = Gradient::radial(FinePoint::from_px(0, 0), 240 * 1024, &stops).unwrap();
    let all = cover_all(240, 1);
    let f = render(240, 1, 1, [0; 3], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    for x in 1..240 {
        let (a, b) = (f.lin(x - 1, 0)[0], f.lin(x, 0)[0]);
        assert!(b >= a && b - a <= step, "({x}, 0): {a} then {b}");
    }
}

#[test]
fn pads_extend_the_end_colours() {
    let stops = [
        Stop::lin(Offset::from_percent(25), [1000, 2000, 3000]),
        Stop::lin(Offset::from_percent(75), [3000, 100, 7]),
    ];
    // Linear, 8 px to 40 px: t < 1/4 left of x = 16 px, t > 3/4 right of 32.
    let g = Gradient::linear(FinePoint::from_px(8, 0), FinePoint::from_px(40, 0), &stops).unwrap();
    let all = cover_all(48, 4);
    let f = render(48, 4, 4, [0; 3], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    let lvl = |c: [u16; 3]| c.map(|v| i32::from(v) << 16);
    for y in 0..4 {
        for x in 0..16 {
            assert_eq!(f.raw(x, y), lvl([1000, 2000, 3000]), "({x}, {y})");
        }
        for x in 32..48 {
            assert_eq!(f.raw(x, y), lvl([3000, 100, 7]), "({x}, {y})");
        }
        assert_ne!(f.raw(16, y), lvl([1000, 2000, 3000]));
    }
    // Radial: inside a quarter of the radius the first colour, beyond
    // three quarters the last.
    let c = FinePoint::from_px(20, 20);
    let g = Gradient::radial(c, 16 * 1024, &stops).unwrap();
    let all = cover_all(40, 40);
    let f = render(40, 40, 7, [0; 3], false, |cv| {
        cv.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    for y in 0..40 {
        for x in 0..40 {
            let d = (f64::from(x) + 0.5 - 20.0).hypot(f64::from(y) + 0.5 - 20.0);
            if d < 4.0 - 0.01 {
                assert_eq!(f.raw(x, y), lvl([1000, 2000, 3000]), "({x}, {y})");
            } else if d > 12.0 + 0.01 {
                assert_eq!(f.raw(x, y), lvl([3000, 100, 7]), "({x}, {y})");
            }
        }
    }
}

#[test]
fn hard_stops_switch_colour_at_their_offset() {
    // Two stops at 1/2: the first colour ramps up to it, the later stop's
    // colour starts there (at a pixel centre exactly on it, too).
    let stops = [
        Stop::lin(Offset::ZERO, [0]),
        Stop::lin(Offset::HALF, [1000]),
        Stop::lin(Offset::HALF, [3000]),
        Stop::lin(Offset::ONE, [4000]),
    ];
    // Pixel 10's centre (10.5 px) is the half-way point of 0.5 .. 20.5 px.
    let g = Gradient::linear(
        FinePoint::centre_of(0, 0),
        FinePoint::centre_of(20, 0),
        &stops,
    )
    .unwrap();
    let all = cover_all(21, 1);
    let f = render(21, 1, 1, [0], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    assert_eq!(f.lin(10, 0), [3000]);
    assert_eq!(f.lin(9, 0), [900]);
    assert_eq!(f.lin(11, 0), [3100]);
    assert_eq!(f.lin(20, 0), [4000]);
    // Radial: the ring at 8 px switches from 1000 to 3000 between the
    // pixel centres at 7.5 and 8.5 px.
    let g = Gradient::radial(FinePoint::from_px(0, 0), 16 * 1024, &stops).unwrap();
    let all = cover_all(17, 1);
    let f = render(17, 1, 1, [0], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    // 7.5 px along 16: t = 0.46875 of the ramp to 1/2: 937.5 of 1000.
    let d = |x: i32| (f64::from(x) + 0.5).hypot(0.5);
    assert!((f64::from(f.lin(7, 0)[0]) - d(7) / 8.0 * 1000.0).abs() <= 1.0);
    assert!((f64::from(f.lin(8, 0)[0]) - (3000.0 + (d(8) / 16.0 - 0.5) * 2000.0)).abs() <= 1.0);
}

#[test]
fn degenerate_gradients_paint_the_last_stop() {
    let stops = [
        Stop::lin(Offset::ZERO, [100]),
        Stop::lin(Offset::ONE, [2500]),
    ];
    let p = FinePoint::centre_of(3, 3);
    let all = cover_all(8, 8);
    for g in [
        Gradient::linear(p, p, &stops).unwrap(),
        Gradient::radial(p, 0, &stops).unwrap(),
        Gradient::linear(p, FinePoint::from_px(9, 9), &stops[..1]).unwrap(),
    ] {
        let want = if g.stops().len() == 1 { 100 } else { 2500 };
        let f = render(8, 8, 3, [0], false, |c| {
            c.fill_gradient(
                &Contour(&all),
                &g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        assert!(f.lin.iter().all(|&v| v == [want]), "{g:?}");
    }
    // A gradient one fine unit long: a step at its point, pads either side.
    let g = Gradient::linear(FinePoint::new(4096, 0), FinePoint::new(4097, 0), &stops).unwrap();
    let all = cover_all(8, 1);
    let f = render(8, 1, 1, [0], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    assert_eq!(f.lin(3, 0), [100]);
    assert_eq!(f.lin(4, 0), [2500]);
}

#[test]
fn bad_stop_lists_and_geometry_are_errors() {
    let p = FinePoint::from_px(0, 0);
    let q = FinePoint::from_px(10, 10);
    let s = |o: u16| Stop::lin(Offset::from_4096ths(o), [0u16; 3]);
    assert_eq!(
        Gradient::<3>::linear(p, q, &[]).err(),
        Some(GradientError::NoStops)
    );
    assert_eq!(
        Gradient::<3>::radial(p, 5, &[]).err(),
        Some(GradientError::NoStops)
    );
    assert_eq!(
        Gradient::linear(p, q, &[s(0); MAX_STOPS + 1]).err(),
        Some(GradientError::TooManyStops {
            given: MAX_STOPS + 1
        })
    );
    assert!(Gradient::linear(p, q, &[s(0); MAX_STOPS]).is_ok());
    assert_eq!(
        Gradient::linear(p, q, &[s(0), s(2000), s(1999)]).err(),
        Some(GradientError::Unsorted { index: 2 })
    );
    assert_eq!(
        Gradient::radial(p, 9, &[s(10), s(9)]).err(),
        Some(GradientError::Unsorted { index: 1 })
    );
    let out = FinePoint::new(FINE_LIMIT + 1, 0);
    assert_eq!(
        Gradient::linear(out, q, &[s(0)]).err(),
        Some(GradientError::Coord(out))
    );
    assert_eq!(
        Gradient::radial(out, 5, &[s(0)]).err(),
        Some(GradientError::Coord(out))
    );
    assert_eq!(
        Gradient::radial(p, -5, &[s(0)]).err(),
        Some(GradientError::Radius { radius: -5 })
    );
    // Errors print.
    let e = GradientError::Unsorted { index: 2 }.to_string();
    assert!(e.contains('2'), "{e}");
    // Equal offsets are fine (a hard edge), colours are clamped.
    let g = Gradient::linear(p, q, &[Stop::lin(Offset::HALF, [9000, 1, 2]), s(2048)]).unwrap();
    assert_eq!(g.stops()[0].color, [4095, 1, 2]);
    assert_eq!(g.kind(), GradientKind::Linear { from: p, to: q });
}

/// Gradient shapes of every kind: the frame a band test draws.
fn scene<Col>(c: &mut Canvas<'_, '_, 3, Col>, gs: &[Gradient<3>; 4]) {
    let p = FinePoint::new;
    c.fill_shape_gradient(
        &Circle::new(p(30 * 1024 + 300, 60 * 1024 + 77), 28 * 1024),
        &gs[0],
        FillRule::NonZero,
        Blend::Over,
        Opacity::OPAQUE,
    )
    .unwrap();
    c.fill_shape_gradient(
        &Ellipse::new(p(50 * 1024, 150 * 1024 + 512), 35 * 1024, 70 * 1024),
        &gs[1],
        FillRule::NonZero,
        Blend::Over,
        Opacity::from_u8(170),
    )
    .unwrap();
    let rr = RoundedRectangle::new(
        Rectangle::new(p(-10 * 1024, 180 * 1024 + 300), 100 * 1024, 50 * 1024),
        CornerRadii::uniform(12 * 1024),
    );
    c.fill_shape_gradient(
        &rr,
        &gs[2],
        FillRule::NonZero,
        Blend::Add,
        Opacity::from_u8(200),
    )
    .unwrap();
    let pts = [
        p(3 * 1024, 5 * 1024),
        p(70 * 1024 + 333, 40 * 1024),
        p(10 * 1024, 120 * 1024 + 900),
        p(75 * 1024, 230 * 1024),
    ];
    let style = StrokeStyle::new(5 * 1024 + 200).with_join(LineJoin::Round);
    c.stroke_shape_gradient(
        &Polyline::new(&pts),
        &style,
        &gs[3],
        Blend::Over,
        Opacity::OPAQUE,
    )
    .unwrap();
}

fn scene_gradients() -> [Gradient<3>; 4] {
    let stops = [
        Stop::lin(Offset::ZERO, [4095, 0, 0]),
        Stop::lin(Offset::from_percent(30), [0, 4095, 300]),
        Stop::lin(Offset::from_percent(30), [100, 200, 4095]),
        Stop::lin(Offset::ONE, [2000, 2000, 0]),
    ];
    let p = FinePoint::new;
    [
        Gradient::radial(p(25 * 1024 + 11, 55 * 1024 + 999), 30 * 1024, &stops).unwrap(),
        Gradient::linear(
            p(10 * 1024, 90 * 1024),
            p(90 * 1024 + 5, 210 * 1024),
            &stops,
        )
        .unwrap(),
        Gradient::radial(p(40 * 1024, 205 * 1024), 60 * 1024 + 123, &stops[1..]).unwrap(),
        Gradient::linear(p(0, 0), p(10 * 1024, 240 * 1024), &stops).unwrap(),
    ]
}

#[test]
fn band_height_does_not_change_a_single_bit() {
    let gs = scene_gradients();
    let reference = render(80, 240, 240, [300, 600, 900], false, |c| scene(c, &gs));
    for rows in [1, 3, 16, 240] {
        for cache in [false, true] {
            let f = render(80, 240, rows, [300, 600, 900], cache, |c| scene(c, &gs));
            assert!(f == reference, "band rows {rows}, cache {cache}");
        }
    }
    // And through the renderer, as a display sees it.
    let screen = |rows| {
        use embedded_graphics_core::pixelcolor::Rgb888;
        use embedded_graphics_core::prelude::*;
        struct Screen(Vec<Rgb888>);
        impl OriginDimensions for Screen {
            fn size(&self) -> Size {
                Size::new(80, 240)
            }
        }
        impl DrawTarget for Screen {
            type Color = Rgb888;
            type Error = core::convert::Infallible;
            fn draw_iter<I: IntoIterator<Item = Pixel<Rgb888>>>(
                &mut self,
                px: I,
            ) -> Result<(), Self::Error> {
                for Pixel(p, c) in px {
                    self.0[(p.y * 80 + p.x) as usize] = c;
                }
                Ok(())
            }
        }
        let mut acc = vec![0i32; BandBuffer::<3>::acc_len(80, rows)];
        let mut cover = vec![0i32; BandBuffer::<3>::cover_len(80, rows)];
        let mut slots = vec![WalkSlot::<3>::EMPTY; 64];
        let mut s = Screen(vec![Rgb888::BLACK; 80 * 240]);
        let mut r =
            softedge::render::Renderer::new(&mut acc, &mut cover, &mut slots, 80, 240, rows)
                .unwrap();
        static RGB: softedge::tone::format::Rgb888Format =
            softedge::tone::format::Rgb888Format::new(Curve::Srgb);
        r.render(&mut s, &RGB, [300, 600, 900], |c| {
            scene(c, &gs);
            Ok::<(), ()>(())
        })
        .unwrap();
        s.0
    };
    let one = screen(240);
    for rows in [1, 3, 16] {
        assert!(screen(rows) == one, "renderer, band rows {rows}");
    }
}

/// A box, and its two halves cut by the segment between two random points
/// on its left and right sides. Corners on the 1/16-px grid: there the
/// edge walker's areas of a shared edge cancel exactly (on the 1/1024-px
/// grid they are rounded, and two flat halves added can differ from the
/// whole by a unit of coverage).
fn cut_rect(rng: &mut Rng) -> ([FinePoint; 4], [FinePoint; 4], [FinePoint; 4]) {
    let sub = |v: i64| (v as i32) & !63;
    let x0 = sub(rng.range(-8 * 1024, 10 * 1024));
    let y0 = sub(rng.range(-8 * 1024, 10 * 1024));
    let x1 = x0 + sub(rng.range(8 * 1024, 50 * 1024));
    let y1 = y0 + sub(rng.range(8 * 1024, 50 * 1024));
    let yl = sub(rng.range(i64::from(y0) + 64, i64::from(y1) - 64));
    let yr = sub(rng.range(i64::from(y0) + 64, i64::from(y1) - 64));
    let p = FinePoint::new;
    (
        [p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1)],
        [p(x0, y0), p(x1, y0), p(x1, yr), p(x0, yl)],
        [p(x0, yl), p(x1, yr), p(x1, y1), p(x0, y1)],
    )
}

#[test]
fn a_shape_cut_in_two_adds_up_to_the_whole() {
    let mut rng = Rng(0x7365_616d);
    for case in 0..120 {
        let spec: Spec<3> = if case % 2 == 0 {
            random_linear(&mut rng, 40, 40)
        } else {
            random_radial(&mut rng, 40, 40)
        };
        let g = spec.gradient();
        let (whole, top, bottom) = cut_rect(&mut rng);
        let bg = [rng.below(4096) as u16, 0, 4095];
        let rows = [1, 6, 40][case % 3];
        let nz = FillRule::NonZero;
        for blend in [Blend::Add, Blend::Over] {
            let one = render(40, 40, rows, bg, false, |c| {
                c.fill_gradient(&Contour(&whole), &g, nz, blend, Opacity::OPAQUE)
                    .unwrap();
            });
            let two = render(40, 40, rows, bg, case % 4 < 2, |c| {
                c.fill_gradient(&Contour(&top), &g, nz, blend, Opacity::OPAQUE)
                    .unwrap();
                c.fill_gradient(&Contour(&bottom), &g, nz, blend, Opacity::OPAQUE)
                    .unwrap();
            });
            // The rows the cut passes through (over composes its pixels
            // twice: conflation, as for any two shapes).
            let [_, _, r, l] = top;
            let cut = (l.y.min(r.y) >> 10)..=(l.y.max(r.y) >> 10);
            for y in 0..40 {
                for x in 0..40 {
                    if blend == Blend::Over && cut.contains(&y) {
                        continue;
                    }
                    assert_eq!(
                        one.raw(x, y),
                        two.raw(x, y),
                        "case {case} {blend:?} ({x}, {y}) {spec:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn edge_pixels_compose_like_flat_colours() {
    let mut rng = Rng(0x6564_6765);
    for case in 0..40 {
        let spec: Spec<3> = if case % 2 == 0 {
            random_linear(&mut rng, 32, 32)
        } else {
            random_radial(&mut rng, 32, 32)
        };
        let g = spec.gradient();
        let disc = Circle::new(
            FinePoint::new(
                rng.range(10_000, 22_000) as i32,
                rng.range(10_000, 22_000) as i32,
            ),
            rng.range(2048, 14 * 1024) as u32,
        );
        let alpha = Opacity::from_4096ths(rng.range(1, 4096) as u16);
        let bg = [rng.below(4096) as u16, rng.below(4096) as u16, 0];
        let nz = FillRule::NonZero;
        let all = cover_all(32, 32);
        // The gradient's colour at every pixel, and the disc's share k of
        // every pixel (4095 k from a flat white disc over black).
        let colour = render(32, 32, 8, [0; 3], false, |c| {
            c.fill_gradient(&Contour(&all), &g, nz, Blend::Over, Opacity::OPAQUE)
                .unwrap();
        });
        let share = render(32, 32, 8, [0; 3], false, |c| {
            c.fill_shape(&disc, [4095; 3], nz, Blend::Over, alpha)
                .unwrap();
        });
        for blend in [Blend::Over, Blend::Add] {
            let f = render(32, 32, 8, bg, false, |c| {
                c.fill_shape_gradient(&disc, &g, nz, blend, alpha).unwrap();
            });
            for y in 0..32 {
                for x in 0..32 {
                    let k = i64::from(share.raw(x, y)[0]);
                    assert_eq!(k % 4095, 0);
                    let k = k / 4095;
                    for ch in 0..3 {
                        let acc = i64::from(bg[ch]) << 16;
                        let i = i64::from(colour.raw(x, y)[ch]);
                        let want = match blend {
                            // acc (1 - k) + I k, floored once.
                            Blend::Over => acc + ((i - acc) * k).div_euclid(65536),
                            // (I - bg) k with I at its whole level: exact.
                            Blend::Add => {
                                let level = ((i >> 15) + 1) >> 1;
                                acc + (level - i64::from(bg[ch])) * k
                            }
                        };
                        let got = i64::from(f.raw(x, y)[ch]);
                        assert!(
                            (got - want).abs() <= 1,
                            "case {case} {blend:?} ({x}, {y}) ch {ch}: {got} vs {want}, k {k}"
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn strokes_and_shapes_take_the_gradient_of_the_frame() {
    // A fully covered pixel of any shape has the gradient's colour there,
    // bit for bit: the colour does not depend on the shape.
    let gs = scene_gradients();
    let all = cover_all(80, 240);
    for (i, g) in gs.iter().enumerate() {
        let full = render(80, 240, 16, [0; 3], false, |c| {
            c.fill_gradient(
                &Contour(&all),
                g,
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        let pts = [
            FinePoint::new(3 * 1024, 5 * 1024),
            FinePoint::new(70 * 1024 + 333, 40 * 1024),
            FinePoint::new(10 * 1024, 120 * 1024 + 900),
        ];
        let style = StrokeStyle::new(9 * 1024).with_join(LineJoin::Round);
        let stroke = render(80, 240, 16, [0; 3], false, |c| {
            c.stroke_shape_gradient(
                &Polyline::new(&pts),
                &style,
                g,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        let flat = render(80, 240, 16, [0; 3], false, |c| {
            c.stroke_shape(
                &Polyline::new(&pts),
                &style,
                [4095; 3],
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        });
        let mut inside = 0;
        for y in 0..240 {
            for x in 0..80 {
                if flat.raw(x, y) == [4095 << 16; 3] {
                    inside += 1;
                    assert_eq!(stroke.raw(x, y), full.raw(x, y), "gradient {i} ({x}, {y})");
                }
            }
        }
        assert!(inside > 500, "{inside}");
    }
}

#[test]
fn geometry_at_the_limits_of_the_range_is_safe() {
    let lim = FINE_LIMIT;
    let stops = [
        Stop::lin(Offset::ZERO, [0, 4095, 0]),
        Stop::lin(Offset::from_percent(40), [4095, 0, 0]),
        Stop::lin(Offset::ONE, [0, 0, 4095]),
    ];
    let p = FinePoint::new;
    let gradients = [
        Gradient::linear(p(-lim, -lim), p(lim, lim), &stops).unwrap(),
        Gradient::linear(p(lim, -lim), p(-lim, lim), &stops).unwrap(),
        Gradient::linear(p(lim, lim), p(lim, lim - 1), &stops).unwrap(),
        Gradient::radial(p(-lim, -lim), i32::MAX, &stops).unwrap(),
        Gradient::radial(p(lim, lim), 1, &stops).unwrap(),
        Gradient::radial(p(-lim, lim), 4096 * 1024, &stops).unwrap(),
    ];
    // Windows at the corners and the middle of the range.
    for (x0, y0) in [(-2048, -2048), (2000, 2000), (-2048, 2016), (-20, -20)] {
        for g in &gradients {
            let mut acc = vec![0i32; BandBuffer::<3>::acc_len(48, 8)];
            let mut cover = vec![0i32; BandBuffer::<3>::cover_len(48, 8)];
            for band in Bands::window(x0, y0, 48, 32, 8) {
                let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).unwrap();
                buf.clear([0; 3]);
                let mut c: Canvas<'_, '_, 3> = Canvas::new(&mut buf, None);
                let r = Rectangle::new(FinePoint::from_px(x0, y0), 48 * 1024, 32 * 1024);
                c.fill_shape_gradient(&r, g, FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
                    .unwrap();
                let disc = Circle::new(FinePoint::from_px(x0 + 20, y0 + 16), 15 * 1024 + 77);
                c.fill_shape_gradient(
                    &disc,
                    g,
                    FillRule::EvenOdd,
                    Blend::Add,
                    Opacity::from_u8(99),
                )
                .unwrap();
                assert_eq!(c.skipped().count, 0);
            }
        }
    }
    // The radial gradient of radius 1 fine unit at the corner: its last
    // colour everywhere in a window away from it.
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(8, 8)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(8, 8)];
    let band = softedge::Band {
        width: 8,
        y0: 2030,
        rows: 8,
        x0: 2030,
    };
    let mut buf = BandBuffer::<3>::new(&mut acc, &mut cover, band).unwrap();
    buf.clear([0; 3]);
    let mut c: Canvas<'_, '_, 3> = Canvas::new(&mut buf, None);
    let r = Rectangle::new(FinePoint::from_px(2030, 2030), 8 * 1024, 8 * 1024);
    c.fill_shape_gradient(
        &r,
        &gradients[4],
        FillRule::NonZero,
        Blend::Over,
        Opacity::OPAQUE,
    )
    .unwrap();
    assert_eq!(c.buffer().lin12(2033, 2033), Some([0, 0, 4095]));
}

#[test]
fn stops_take_embedded_graphics_colours_as_srgb() {
    let stops = [
        Stop::new(Offset::ZERO, Rgb565::RED),
        Stop::new(Offset::ONE, Rgb565::BLUE),
    ];
    assert_eq!(stops[0].color, [4095, 0, 0]);
    let g = Gradient::linear(
        FinePoint::centre_of(0, 0),
        FinePoint::centre_of(10, 0),
        &stops,
    )
    .unwrap();
    let all = cover_all(11, 1);
    let f = render(11, 1, 1, [0; 3], false, |c| {
        c.fill_gradient(
            &Contour(&all),
            &g,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    // Half way: half the red light and half the blue, in linear light.
    let [r, gr, b] = f.lin(5, 0);
    assert!(
        r.abs_diff(2048) <= 1 && b.abs_diff(2048) <= 1 && gr == 0,
        "{r} {gr} {b}"
    );
    // The same colours on a one-channel display: their luminance.
    let grey = [
        Stop::<1>::new(Offset::ZERO, Rgb565::RED),
        Stop::new(Offset::ONE, Rgb565::BLUE),
    ];
    assert!(grey[0].color[0] > grey[1].color[0]);
}

/// The constructors are `const fn`: a gradient can be a `static` (in
/// flash on a microcontroller), made at compile time.
static GLOW: Gradient<3> = match Gradient::radial(
    FinePoint::centre_of(16, 16),
    12 * 1024,
    &[
        Stop::lin(Offset::ZERO, [4095, 4095, 3000]),
        Stop::lin(Offset::from_percent(70), [4095, 1200, 0]),
        Stop::lin(Offset::ONE, [0, 0, 0]),
    ],
) {
    Ok(g) => g,
    Err(_) => panic!("bad gradient"),
};

#[test]
fn a_gradient_can_be_made_at_compile_time() {
    let disc = Circle::new(FinePoint::centre_of(16, 16), 12 * 1024);
    let f = render(33, 33, 11, [0; 3], false, |c| {
        c.fill_shape_gradient(
            &disc,
            &GLOW,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    let [r, g, b] = f.lin(16, 16);
    assert!(r == 4095 && g >= 4090 && b >= 2995, "{r} {g} {b}");
    assert_eq!(GLOW.stops().len(), 3);
}
