//! The image's filters as samplers of a band's runs ([`TexelRun`]): copy,
//! bilinear and box (see the module doc of [`image`](super)).
//!
//! Set up once per band ([`paint`]); per run a start at the run's first
//! pixel (`i64` products); per pixel the exact Q32 position stepped by one
//! `i64` addition per axis, the texels read and decoded (table look-ups),
//! and the filter's weights and products (multiplies, no division).
//!
//! ## Bilinear ranges
//!
//! The fractions `fu`, `fv` are 10 bits (the position rounded to 1/1024
//! texel by a bias of 1/2048 folded into the start); the four weights are
//! products in `0..=2^20` summing to `2^20`, so each channel's sum
//! `sum c w <= 4095 * 2^20 < 2^32` (unsigned) and alpha's
//! `sum a w <= 2^30`; the colour is that sum `>> 4` (accumulator units,
//! `lin12 * 2^16`), alpha `>> 14` (coverage units, exactly `2^16` for an
//! opaque texel).

use super::format::{luma, ALPHA_BITS, ALPHA_ONE};
use super::sealed::{Fetch, Lin, Source};
use super::transform::{Filter, Mapping};
use super::ImageFault;
use crate::band::image::{ImageRuns, Stored, Texel, TexelRun};
use crate::{COVER_BITS, COVER_ONE};

/// Q32 of half a texel.
const HALF_Q32: i64 = 1 << 31;
/// Half of the last fraction bit kept (1/2048 texel): rounds the position.
const ROUND_Q32: i64 = 1 << (31 - ALPHA_BITS);

/// Calls `f` with the sampler of `src` under `map` for the pixels
/// `x0..x1` of rows `y0..y1` (their reach in the image is what a
/// sequential source must hold), drawn in `tint` (a mask's colour, or the
/// image's luminance or alpha as a mask).
pub(crate) fn paint<S: Source + ?Sized, const C: usize, R>(
    src: &S,
    map: &Mapping,
    tint: Option<[u16; C]>,
    (x, y): ((i32, i32), (i32, i32)),
    f: impl FnOnce(&dyn ImageRuns<C>) -> R,
) -> Result<R, ImageFault> {
    let rows = map.rows_for(x, y);
    src.with_rows(rows, |fetch| match tint {
        Some(t) => {
            let t = t.map(|v| i32::from(v.min(crate::LIN_MAX)) << COVER_BITS);
            if S::Fetch::MASK {
                by_filter(fetch, map, t, f)
            } else {
                by_filter(&AsMask(fetch), map, t, f)
            }
        }
        None => {
            let white = [i32::from(crate::LIN_MAX) << COVER_BITS; C];
            by_filter(fetch, map, white, f)
        }
    })
}

fn by_filter<F: Fetch, const C: usize, R>(
    fetch: &F,
    map: &Mapping,
    tint: [i32; C],
    f: impl FnOnce(&dyn ImageRuns<C>) -> R,
) -> R {
    let (w, h) = (map.width, map.height);
    match map.filter {
        Filter::Copy { dx, dy } => f(&CopyRun {
            fetch,
            dx,
            dy,
            w,
            h,
            tint,
        }),
        Filter::Bilinear => {
            let bias = ROUND_Q32 - HALF_Q32;
            let mut m = *map;
            m.u[0] = m.u[0].wrapping_add(bias);
            m.v[0] = m.v[0].wrapping_add(bias);
            f(&Bilinear {
                fetch,
                map: m,
                tint,
            })
        }
        Filter::Box { w: bw, h: bh } => f(&BoxRun {
            fetch,
            map: *map,
            half: (bw / 2, bh / 2),
            inv: (inverse_q16(bw), inverse_q16(bh)),
            tint,
        }),
    }
}

/// `2^48 / side` (Q16 of the reciprocal of a Q32 length >= 1 texel).
fn inverse_q16(side: i64) -> i64 {
    if side <= 0 {
        return 0;
    }
    (1i64 << 48) / side
}

/// A source's texels as a mask: the alpha of a source with alpha, the
/// linear luminance of an opaque one.
struct AsMask<'f, F>(&'f F);

impl<F: Fetch> Fetch for AsMask<'_, F> {
    const OPAQUE: bool = false;
    const MASK: bool = true;
    const GRAY: bool = true;
    #[inline(always)]
    fn texel(&self, x: i32, y: i32) -> Lin {
        let t = self.0.texel(x, y);
        let a = if F::OPAQUE {
            // lin12 to 0..=1024: 4095 * 16392 / 2^16 = 1024.25.
            ((luma(t.c) * 16_392) >> 16).min(ALPHA_ONE)
        } else {
            t.a
        };
        Lin { c: [0; 3], a }
    }
}

/// A texel's `C` channels (its luminance on one channel).
#[inline(always)]
fn channels<F: Fetch, const C: usize>(t: &Lin) -> [u32; C] {
    if C == 1 && !F::GRAY {
        [luma(t.c); C]
    } else {
        core::array::from_fn(|ch| t.c[ch.min(2)])
    }
}

/// `v` clamped to `0..=hi` (0 when `hi < 0`; by `min` and `max`, as
/// `Ord::clamp` has a panic path for `hi < 0`).
#[inline(always)]
fn clamp(v: i32, hi: i32) -> i32 {
    v.min(hi).max(0)
}

// ------------------------------------------------------------------ copy

struct CopyRun<'f, F, const C: usize> {
    fetch: &'f F,
    dx: i32,
    dy: i32,
    w: i32,
    h: i32,
    tint: [i32; C],
}

impl<F, const C: usize> core::fmt::Debug for CopyRun<'_, F, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("CopyRun")
    }
}

impl<F: Fetch, const C: usize> TexelRun<C> for CopyRun<'_, F, C> {
    const OPAQUE: bool = F::OPAQUE && !F::MASK;
    const MASK: bool = F::MASK;
    /// The texel's column, row.
    type Cursor = (i32, i32);
    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> (i32, i32) {
        (x.wrapping_sub(self.dx), y.wrapping_sub(self.dy))
    }
    #[inline(always)]
    fn next(&self, cur: &mut (i32, i32)) -> Texel<C> {
        let (i, j) = *cur;
        cur.0 = i.wrapping_add(1);
        let (i, j) = if (i as u32) < self.w as u32 && (j as u32) < self.h as u32 {
            (i, j)
        } else {
            (clamp(i, self.w - 1), clamp(j, self.h - 1))
        };
        let t = self.fetch.texel(i, j);
        let alpha = (t.a << (COVER_BITS - ALPHA_BITS)) as i32;
        if F::MASK {
            return Texel {
                color: [0; C],
                alpha,
            };
        }
        let c = channels::<F, C>(&t);
        Texel {
            color: c.map(|v| (v << COVER_BITS) as i32),
            alpha,
        }
    }
    fn tint(&self) -> [i32; C] {
        self.tint
    }
    /// A run inside the image's columns, on one of its rows: its texels
    /// decoded from the row in order, each stored as it is (an opaque
    /// texel's colour is its pixel's value). A run reaching past the
    /// image's sides takes the clamped texels pixel by pixel.
    ///
    /// With `codes`, a three-channel band and an Rgb565 source: each
    /// pixel's first word its texel's code (see `band::tags`).
    fn store_whole(&self, px: &mut [i32], n: usize, x: i32, y: i32, codes: bool) -> Stored {
        if !Self::OPAQUE {
            return Stored::No;
        }
        let (i, j) = self.start(x, y);
        let inside =
            i >= 0 && (j as u32) < self.h as u32 && i64::from(i) + n as i64 <= i64::from(self.w);
        if !inside {
            return Stored::No;
        }
        if codes && C == 3 && self.fetch.store_rgb565::<C>(i, j, n, px) {
            return Stored::Codes;
        }
        let mut out = px.chunks_exact_mut(C);
        self.fetch.row(i, j, n, |t| {
            if let Some(p) = out.next() {
                let c = channels::<F, C>(&t);
                for (v, c) in p.iter_mut().zip(c) {
                    *v = (c << COVER_BITS) as i32;
                }
            }
        });
        Stored::Values
    }
}

// -------------------------------------------------------------- bilinear

struct Bilinear<'f, F, const C: usize> {
    fetch: &'f F,
    /// The mapping with `-1/2 + 1/2048` texel folded into `u[0]`, `v[0]`.
    map: Mapping,
    tint: [i32; C],
}

impl<F, const C: usize> core::fmt::Debug for Bilinear<'_, F, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("Bilinear")
    }
}

/// The alphas of the last 2x2 texels a mask's run read (texel columns
/// `x`, rows `y`; `-1` before the first), `[a00, a10, a01, a11]`: a
/// magnified mask takes the same four again, or the right column as its
/// left one, for most pixels of a run.
pub(crate) struct Alphas {
    x: (i32, i32),
    y: (i32, i32),
    a: [u32; 4],
}

impl Alphas {
    /// The alphas of columns `x`, rows `y` (inside the image), read only
    /// where the last four do not hold them.
    #[inline(always)]
    fn read<F: Fetch>(&mut self, f: &F, x: (i32, i32), y: (i32, i32)) {
        if self.y == y {
            if self.x == x {
                return;
            }
            if x.0 == self.x.1 {
                self.a = [
                    self.a[1],
                    f.texel(x.1, y.0).a,
                    self.a[3],
                    f.texel(x.1, y.1).a,
                ];
                self.x = x;
                return;
            }
        }
        let (t00, t10) = f.pair(x.0, x.1, y.0);
        let (t01, t11) = f.pair(x.0, x.1, y.1);
        self.a = [t00.a, t10.a, t01.a, t11.a];
        (self.x, self.y) = (x, y);
    }
}

impl<F: Fetch, const C: usize> TexelRun<C> for Bilinear<'_, F, C> {
    const OPAQUE: bool = F::OPAQUE && !F::MASK;
    const MASK: bool = F::MASK;
    /// `u - 1/2`, `v - 1/2` (rounding bias included), Q32 texels; a
    /// mask's last alphas.
    type Cursor = (i64, i64, Alphas);
    #[inline(always)]
    fn start(&self, x: i32, y: i32) -> Self::Cursor {
        let (u, v) = self.map.at(x, y);
        let none = Alphas {
            x: (-1, -1),
            y: (-1, -1),
            a: [0; 4],
        };
        (u, v, none)
    }
    // Out of line: one copy of the filter however many operations the
    // run's loop has (a call a pixel, beside some 300 instructions).
    #[inline(never)]
    fn next(&self, cur: &mut Self::Cursor) -> Texel<C> {
        let (u, v) = (cur.0, cur.1);
        cur.0 = u.wrapping_add(self.map.u[1]);
        cur.1 = v.wrapping_add(self.map.v[1]);
        let (w, h) = (self.map.width, self.map.height);
        let (x, y) = (pair((u >> 32) as i32, w), pair((v >> 32) as i32, h));
        if F::MASK {
            cur.2.read(self.fetch, x, y);
            let [a00, a10, a01, a11] = cur.2.a;
            let alpha = Weights::at(u, v).mix(a00, a10, a01, a11) >> ALPHA_SHIFT;
            return Texel {
                color: [0; C],
                alpha: alpha as i32,
            };
        }
        bilinear::<F, C>(self.fetch, x, y, u, v)
    }
    fn tint(&self) -> [i32; C] {
        self.tint
    }
}

/// The two texel indices around `i + f` (clamped to `0..n`).
#[inline(always)]
fn pair(i: i32, n: i32) -> (i32, i32) {
    if (i as u32) < (n - 1) as u32 {
        (i, i + 1)
    } else {
        (clamp(i, n - 1), clamp(i.saturating_add(1), n - 1))
    }
}

/// A bilinear sum's alpha to coverage units.
const ALPHA_SHIFT: u32 = 2 * ALPHA_BITS - (COVER_BITS - ALPHA_BITS);

/// The four bilinear weights at `(u, v)` (texel-centre coordinates,
/// Q32): products of the 10-bit fractions, in 2^-20, summing to 2^20.
struct Weights([u32; 4]);

impl Weights {
    #[inline(always)]
    fn at(u: i64, v: i64) -> Self {
        let fu = (u as u32) >> (32 - ALPHA_BITS);
        let fv = (v as u32) >> (32 - ALPHA_BITS);
        let w11 = fu * fv;
        let w10 = (fu << ALPHA_BITS) - w11;
        let w01 = (fv << ALPHA_BITS) - w11;
        let w00 = (1u32 << (2 * ALPHA_BITS))
            .wrapping_sub(fu << ALPHA_BITS)
            .wrapping_sub(fv << ALPHA_BITS)
            .wrapping_add(w11);
        Weights([w00, w10, w01, w11])
    }

    /// `a w00 + b w10 + c w01 + d w11`.
    #[inline(always)]
    fn mix(&self, a: u32, b: u32, c: u32, d: u32) -> u32 {
        let [w00, w10, w01, w11] = self.0;
        a.wrapping_mul(w00)
            .wrapping_add(b.wrapping_mul(w10))
            .wrapping_add(c.wrapping_mul(w01))
            .wrapping_add(d.wrapping_mul(w11))
    }
}

/// The bilinear sample at `(u, v)` (texel-centre coordinates, Q32) of
/// the texels in columns `x`, rows `y` around it.
#[inline(always)]
fn bilinear<F: Fetch, const C: usize>(
    f: &F,
    (x0, x1): (i32, i32),
    (y0, y1): (i32, i32),
    u: i64,
    v: i64,
) -> Texel<C> {
    let (t00, t10) = f.pair(x0, x1, y0);
    let (t01, t11) = f.pair(x0, x1, y1);
    let wt = Weights::at(u, v);
    let mix = |a: u32, b: u32, c: u32, d: u32| wt.mix(a, b, c, d);
    let alpha = if F::OPAQUE && !F::MASK {
        COVER_ONE
    } else {
        (mix(t00.a, t10.a, t01.a, t11.a) >> ALPHA_SHIFT) as i32
    };
    if F::MASK {
        return Texel {
            color: [0; C],
            alpha,
        };
    }
    let to_acc = |s: u32| (s >> (2 * ALPHA_BITS - COVER_BITS)) as i32;
    let color = if F::GRAY && C > 1 {
        let g = to_acc(mix(t00.c[0], t10.c[0], t01.c[0], t11.c[0]));
        [g; C]
    } else {
        let (c00, c10, c01, c11) = (
            channels::<F, C>(&t00),
            channels::<F, C>(&t10),
            channels::<F, C>(&t01),
            channels::<F, C>(&t11),
        );
        core::array::from_fn(|ch| to_acc(mix(c00[ch], c10[ch], c01[ch], c11[ch])))
    };
    Texel { color, alpha }
}

// ------------------------------------------------------------------- box

struct BoxRun<'f, F, const C: usize> {
    fetch: &'f F,
    map: Mapping,
    /// Half the box, Q32 texels.
    half: (i64, i64),
    /// The reciprocal of the box's sides, Q16.
    inv: (i64, i64),
    tint: [i32; C],
}

/// The overlaps of `[lo, hi)` (Q32) with texels `i`, each times `inv`
/// (Q16 weights, summing to about 2^16), for `i` from `floor(lo)`; at
/// most `N` of them (a box is at most 16 texels: 17 overlaps).
#[inline(always)]
fn weights(lo: i64, hi: i64, inv: i64, out: &mut [u32; 18]) -> (i32, usize) {
    let first = lo >> 32;
    let mut n = 0;
    let mut i = first;
    while (i << 32) < hi && n < out.len() {
        let a = lo.max(i << 32);
        let b = hi.min((i + 1) << 32);
        let w = (((b - a) >> 16) * inv) >> 16;
        if let Some(o) = out.get_mut(n) {
            *o = w.clamp(0, 1 << 17) as u32;
        }
        n += 1;
        i += 1;
    }
    (
        first.clamp(i64::from(i32::MIN), i64::from(i32::MAX)) as i32,
        n,
    )
}

impl<F, const C: usize> core::fmt::Debug for BoxRun<'_, F, C> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("BoxRun")
    }
}

impl<F: Fetch, const C: usize> TexelRun<C> for BoxRun<'_, F, C> {
    const OPAQUE: bool = F::OPAQUE && !F::MASK;
    const MASK: bool = F::MASK;
    /// `u`, `v` of the pixel centre, Q32 texels.
    type Cursor = (i64, i64);
    fn start(&self, x: i32, y: i32) -> (i64, i64) {
        self.map.at(x, y)
    }
    // Out of line: many texels a pixel, the call is nothing beside them,
    // and the code is not copied into the run's loop.
    #[inline(never)]
    fn next(&self, cur: &mut (i64, i64)) -> Texel<C> {
        let (u, v) = *cur;
        cur.0 = u.wrapping_add(self.map.u[1]);
        cur.1 = v.wrapping_add(self.map.v[1]);
        let (w, h) = (self.map.width, self.map.height);
        let mut wu = [0u32; 18];
        let mut wv = [0u32; 18];
        let (i0, nu) = weights(
            u.saturating_sub(self.half.0),
            u.saturating_add(self.half.0),
            self.inv.0,
            &mut wu,
        );
        let (j0, nv) = weights(
            v.saturating_sub(self.half.1),
            v.saturating_add(self.half.1),
            self.inv.1,
            &mut wv,
        );
        // Sums in u64: each row's sum of up to 17 weights (Q16) times
        // lin12 is below 2^34, then >> 8 and times a row weight.
        let mut sum = [0u64; C];
        let mut sum_a = 0u64;
        for (dj, &rw) in wv.iter().take(nv).enumerate() {
            let j = clamp(j0.saturating_add(dj as i32), h - 1);
            let mut row = [0u64; C];
            let mut row_a = 0u64;
            for (di, &cw) in wu.iter().take(nu).enumerate() {
                let i = clamp(i0.saturating_add(di as i32), w - 1);
                let t = self.fetch.texel(i, j);
                let c = channels::<F, C>(&t);
                for ch in 0..C {
                    row[ch] += u64::from(c[ch]) * u64::from(cw);
                }
                row_a += u64::from(t.a) * u64::from(cw);
            }
            for ch in 0..C {
                sum[ch] += (row[ch] >> 8) * u64::from(rw);
            }
            sum_a += (row_a >> 8) * u64::from(rw);
        }
        // Colour: lin12 2^24 -> 2^16; alpha: 1024 * 2^24 -> 2^16.
        let alpha = if Self::OPAQUE {
            COVER_ONE
        } else {
            ((sum_a >> 18) as i32).min(COVER_ONE)
        };
        let color = core::array::from_fn(|ch| (sum[ch] >> 8).min(1 << 28) as i32);
        Texel {
            color: if F::MASK { [0; C] } else { color },
            alpha,
        }
    }
    fn tint(&self) -> [i32; C] {
        self.tint
    }
}
