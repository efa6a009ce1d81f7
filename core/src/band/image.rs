//! Image paint along a run of the span sweep: each pixel's filtered texel
//! (premultiplied linear colour and alpha, or a mask's alpha under a tint)
//! composed by the run's operation (over, add, accumulate) with the run's
//! coverage factor.
//!
//! Takes a run (its first frame pixel, its share `k` = coverage times
//! opacity, its pixels) and an image sampler ([`TexelRun`], set up once per
//! band by [`image`](crate::image): the texels it reads, its filter, its
//! transform); gives the run's pixels
//!
//! - over: `acc = acc (1 - k a) + k P` (`P` the premultiplied colour, `a`
//!   the texel's alpha; a mask: `P = T a` for the tint `T`);
//! - add: `acc += k (P - bg a)`; accumulate: `acc += k P`.
//!
//! This is the one place an image touches the accumulator. Per pixel: the
//! sampler's filter (table look-ups, multiplies of the filter weights) and
//! here one store (a whole pixel of an opaque texel) or one or two
//! [`mul_share`] products per channel; no division.
//!
//! ## Ranges
//!
//! A sampler gives `0 <= P <= 4095 * 2^16` per channel (below `2^28`) and
//! `0 <= a <= 2^16`, `P <= a * 4095` (premultiplied); `k` is in
//! `0..=2^16` for over, `-2^16..=2^16` for add. Every operand of
//! [`mul_share`] stays within its `2^29` limit (a difference of two values
//! below `2^28`).

use super::sweep::{mul_share, ComposeOp, RunOp, SKIP, WHOLE};
use crate::{COVER_BITS, COVER_ONE};

/// One filtered sample of an image at a pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Texel<const C: usize> {
    /// Premultiplied linear colour, accumulator units (`lin12 * 2^16` at
    /// full alpha); unused by a mask.
    pub color: [i32; C],
    /// Alpha, coverage units (`0..=COVER_ONE`).
    pub alpha: i32,
}

/// An image sampler stepped along a row (crate-internal; implemented by
/// [`image`](crate::image)'s filters). `start` sets up at a frame pixel
/// (per run: multiplies allowed), `next` gives that pixel's sample and
/// moves one pixel right (per pixel: integer adds, compares, look-ups and
/// the filter's multiplies).
pub(crate) trait TexelRun<const C: usize>: core::fmt::Debug {
    /// Every sample has alpha `COVER_ONE` (its `alpha` is not read).
    const OPAQUE: bool;
    /// A mask: the sample is its alpha only, the colour is [`tint`](Self::tint).
    const MASK: bool;
    /// What a row's stepping carries.
    type Cursor;
    /// The cursor at frame pixel `(x, y)`.
    fn start(&self, x: i32, y: i32) -> Self::Cursor;
    /// The sample at the cursor's pixel; the cursor moves one pixel right.
    fn next(&self, cur: &mut Self::Cursor) -> Texel<C>;
    /// A mask's colour, accumulator units.
    fn tint(&self) -> [i32; C] {
        [0; C]
    }
    /// Stores the samples of the whole pixels `px` (`n` of them, `C`
    /// values a pixel) from frame pixel `(x, y)` rightwards, as an opaque over of them
    /// does (each pixel's value becomes its sample), when the sampler
    /// can do so a row at a time. With `codes` (a three-channel band that
    /// keeps tags) it may store an Rgb565 sampler's codes instead, one in
    /// each pixel's first word (see `band::tags`). Only an opaque sampler
    /// is asked.
    fn store_whole(&self, _px: &mut [i32], _n: usize, _x: i32, _y: i32, _codes: bool) -> Stored {
        Stored::No
    }
}

/// What [`TexelRun::store_whole`] did.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Stored {
    /// Nothing: the run is sampled pixel by pixel.
    No,
    /// Each pixel's value.
    Values,
    /// Each pixel's Rgb565 code (the run is to be tagged `SOURCE`).
    Codes,
}

/// An image paint as the sweep holds it (a trait object: one call per
/// run, the pixels' loop monomorphized on the sampler).
pub(crate) trait ImageRuns<const C: usize>: core::fmt::Debug {
    /// Composes the run `px` (`C` values a pixel) whose first pixel is
    /// frame pixel `(x, y)` with factor `k` ([`WHOLE`], [`SKIP`] or a
    /// share) by `op` over the background `bg`; true when it stored
    /// Rgb565 codes (allowed by `codes`; see [`TexelRun::store_whole`]).
    #[allow(clippy::too_many_arguments)]
    fn compose(
        &self,
        px: &mut [i32],
        k: i32,
        x: i32,
        y: i32,
        op: ComposeOp,
        bg: [u16; C],
        codes: bool,
    ) -> bool;

    /// Every sample opaque, and a colour (not a mask's alpha): an over of
    /// whole pixels replaces them unread.
    fn opaque(&self) -> bool;

    /// [`compose`](Self::compose) of the `n` whole pixels `px` of an
    /// opaque sampler, over: each pixel's value its sample (true when
    /// they were given Rgb565 codes, allowed by `codes`).
    fn cover_whole(&self, px: &mut [i32], n: usize, x: i32, y: i32, codes: bool) -> bool;
}

impl<const C: usize> super::BandBuffer<'_, C> {
    /// Composes `image` over the whole pixels of frame columns `xs` and
    /// rows `ys` (clipped to the band), opaquely: what the sweep does for
    /// an opaque image's rectangle whose sides are on pixel boundaries
    /// (every pixel inside covered wholly, none outside touched), without
    /// its edges walked and swept. Only for a sampler of opaque colours
    /// ([`ImageRuns::opaque`]: a whole pixel is replaced unread); each
    /// row's pixels are tagged `SOURCE` when given Rgb565 codes, else
    /// `MIXED` (see `band::tags`), and drawn. False (nothing done) for
    /// any other sampler.
    pub(crate) fn cover_with_image(
        &mut self,
        image: &dyn ImageRuns<C>,
        xs: core::ops::Range<i32>,
        ys: core::ops::Range<i32>,
    ) -> bool {
        if !image.opaque() {
            return false;
        }
        let band = self.band;
        let w = usize::from(band.width);
        let c0 = (xs.start.saturating_sub(band.x0)).clamp(0, w as i32) as usize;
        let c1 = (xs.end.saturating_sub(band.x0)).clamp(0, w as i32) as usize;
        if c0 >= c1 {
            return true;
        }
        let n = super::tags::row_words(w);
        let dense = self.palette.dense;
        let x = band.x0.wrapping_add(c0 as i32);
        for y in self.rows_in_band(ys.start, ys.end) {
            let r = (y - band.y0) as usize;
            let Some(px) = self.acc.get_mut((r * w + c0) * C..(r * w + c1) * C) else {
                continue;
            };
            let codes = image.cover_whole(px, c1 - c0, x, y, !dense);
            if !dense {
                if let Some(words) = self.tags.get_mut(r * n..r * n + n) {
                    let t = if codes {
                        super::tags::SOURCE
                    } else {
                        super::tags::MIXED
                    };
                    super::tags::fill(words, c0, c1, t);
                }
            }
            if let Some([_, _, dlo, dhi]) = self
                .heads
                .get_mut(r * super::ROW_HEAD..(r + 1) * super::ROW_HEAD)
            {
                super::mark_extent(dlo, dhi, c0, c1);
            }
        }
        true
    }
}

/// How a run's pixels take their samples (chosen per run; one pixel loop
/// per sampler, the choice a branch per pixel: a loop per operation would
/// triple each sampler's code, too much for a Cortex-M0's flash).
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    OverWhole,
    OverPart,
    Add,
}

impl<const C: usize, T: TexelRun<C>> ImageRuns<C> for T {
    fn opaque(&self) -> bool {
        T::OPAQUE && !T::MASK
    }

    fn cover_whole(&self, px: &mut [i32], n: usize, x: i32, y: i32, codes: bool) -> bool {
        if !T::OPAQUE || T::MASK {
            return false;
        }
        match self.store_whole(px, n, x, y, codes) {
            Stored::Codes => true,
            Stored::Values => false,
            Stored::No => {
                run(self, px, x, y, |p, t| over_whole(self, p, t));
                false
            }
        }
    }

    fn compose(
        &self,
        px: &mut [i32],
        k: i32,
        x: i32,
        y: i32,
        op: ComposeOp,
        bg: [u16; C],
        codes: bool,
    ) -> bool {
        if k == SKIP {
            return false;
        }
        let whole = k == WHOLE;
        let k = if whole { COVER_ONE } else { k };
        if T::OPAQUE && whole && matches!(op, ComposeOp::Over(_)) {
            match self.store_whole(px, px.len() / C, x, y, codes) {
                Stored::No => {}
                Stored::Values => return false,
                Stored::Codes => return true,
            }
        }
        let (mode, base) = match op {
            ComposeOp::Over(_) if whole => (Mode::OverWhole, [0; C]),
            ComposeOp::Over(_) => (Mode::OverPart, [0; C]),
            ComposeOp::Add(_) => (Mode::Add, bg.map(|b| i32::from(b) << COVER_BITS)),
            ComposeOp::Accumulate(_) => (Mode::Add, [0; C]),
            ComposeOp::Attenuate(_) => return false,
        };
        run(self, px, x, y, |p, t| match mode {
            Mode::OverWhole => over_whole(self, p, t),
            Mode::OverPart => over_part(self, p, t, k),
            Mode::Add => add(self, p, t, k, &base),
        });
        false
    }
}

/// The sweep's run of an image paint.
pub(super) struct ImageRun<'i, const C: usize> {
    pub image: &'i dyn ImageRuns<C>,
    pub op: ComposeOp,
    pub bg: [u16; C],
}

impl<const C: usize> RunOp<C> for ImageRun<'_, C> {
    #[inline(always)]
    fn run(&self, px: &mut [i32], k: i32, (x, y): (i32, i32), codes: bool) -> bool {
        self.image.compose(px, k, x, y, self.op, self.bg, codes)
    }

    #[inline(always)]
    fn reads(&self, k: i32) -> bool {
        !(k == WHOLE && matches!(self.op, ComposeOp::Over(_)) && self.image.opaque())
    }
}

/// Every pixel of the run with its sample.
#[inline(always)]
fn run<const C: usize, T: TexelRun<C>>(
    t: &T,
    px: &mut [i32],
    x: i32,
    y: i32,
    mut apply: impl FnMut(&mut [i32; C], &Texel<C>),
) {
    let mut cur = t.start(x, y);
    let mut px = px;
    while let Some((p, rest)) = core::mem::take(&mut px).split_first_chunk_mut::<C>() {
        let s = t.next(&mut cur);
        apply(p, &s);
        px = rest;
    }
}

/// Over, the pixel wholly covered by an opaque shape.
#[inline(always)]
fn over_whole<const C: usize, T: TexelRun<C>>(t: &T, p: &mut [i32; C], s: &Texel<C>) {
    if T::MASK {
        let tint = t.tint();
        for ch in 0..C {
            p[ch] = p[ch].wrapping_add(mul_share(tint[ch].wrapping_sub(p[ch]), s.alpha));
        }
    } else if T::OPAQUE || s.alpha >= COVER_ONE {
        *p = s.color;
    } else if s.alpha > 0 {
        for ch in 0..C {
            p[ch] = p[ch]
                .wrapping_sub(mul_share(p[ch], s.alpha))
                .wrapping_add(s.color[ch]);
        }
    }
}

/// Over by the share `k`.
#[inline(always)]
fn over_part<const C: usize, T: TexelRun<C>>(t: &T, p: &mut [i32; C], s: &Texel<C>, k: i32) {
    if T::MASK {
        let tint = t.tint();
        let ka = mul_share(s.alpha, k);
        for ch in 0..C {
            p[ch] = p[ch].wrapping_add(mul_share(tint[ch].wrapping_sub(p[ch]), ka));
        }
    } else if T::OPAQUE {
        for ch in 0..C {
            p[ch] = p[ch].wrapping_add(mul_share(s.color[ch].wrapping_sub(p[ch]), k));
        }
    } else {
        let ka = mul_share(s.alpha, k);
        for ch in 0..C {
            p[ch] = p[ch]
                .wrapping_sub(mul_share(p[ch], ka))
                .wrapping_add(mul_share(s.color[ch], k));
        }
    }
}

/// Add (`base` the background, accumulator units) or accumulate (`base`
/// zero) by the share `k`: `acc += k (P - base a)`.
#[inline(always)]
fn add<const C: usize, T: TexelRun<C>>(
    t: &T,
    p: &mut [i32; C],
    s: &Texel<C>,
    k: i32,
    base: &[i32; C],
) {
    if T::MASK {
        let tint = t.tint();
        let ka = mul_share(s.alpha, k);
        for ch in 0..C {
            p[ch] = p[ch].saturating_add(mul_share(tint[ch].wrapping_sub(base[ch]), ka));
        }
    } else {
        for ch in 0..C {
            let b = if T::OPAQUE {
                base[ch]
            } else {
                mul_share(base[ch], s.alpha)
            };
            p[ch] = p[ch].saturating_add(mul_share(s.color[ch].wrapping_sub(b), k));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::band::{Band, BandBuffer, Coverage, Paint};
    use crate::style::{FillRule, Opacity};

    /// A sampler of one constant texel.
    #[derive(Debug)]
    struct Const<const OPAQUE: bool, const MASK: bool>(Texel<1>, [i32; 1]);

    impl<const OPAQUE: bool, const MASK: bool> TexelRun<1> for Const<OPAQUE, MASK> {
        const OPAQUE: bool = OPAQUE;
        const MASK: bool = MASK;
        type Cursor = ();
        fn start(&self, _: i32, _: i32) {}
        fn next(&self, _: &mut ()) -> Texel<1> {
            self.0
        }
        fn tint(&self) -> [i32; 1] {
            self.1
        }
    }

    fn one<T: TexelRun<1>>(bg: u16, cover: i32, t: &T, op: ComposeOp) -> i32 {
        let (mut acc, mut cover_buf) = ([0i32; 2], [0i32; 12]);
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover_buf, Band::new(2, 0, 1)).unwrap();
        buf.clear([bg]);
        buf.add_area(0, 0, cover);
        buf.compose(
            0,
            1,
            Coverage::Rule(FillRule::NonZero),
            &Paint::Image(t),
            op,
        );
        buf.raw(0, 0).unwrap()[0]
    }

    /// Each operation against its formula in `f64`: within the floors of
    /// the products (2 units of 2^-16 level) and, with alpha, the floor of
    /// `k a` (one unit of 2^-16 times the pixel: at most 2^12 units, 1/16
    /// of a level).
    #[test]
    fn composites_follow_the_premultiplied_formulas() {
        let one16 = f64::from(COVER_ONE);
        const TOL: f64 = 2.0 + 4096.0;
        for (bg, cover, alpha, lin) in [
            (1000u16, COVER_ONE, COVER_ONE, 3000i32),
            (1000, COVER_ONE / 2, COVER_ONE, 3000),
            (1000, COVER_ONE, COVER_ONE / 4, 3000),
            (4095, 12345, 40000, 100),
            (0, 65000, 1, 4095),
            (2222, 3, 65535, 17),
        ] {
            let p = (i64::from(lin) * i64::from(alpha)) as i32; // premultiplied acc units
            let texel = Texel { color: [p], alpha };
            let k = f64::from(cover) / one16;
            let a = f64::from(alpha) / one16;
            let b = f64::from(bg) * one16;
            let pf = f64::from(p);
            let over = one(
                bg,
                cover,
                &Const::<false, false>(texel, [0]),
                ComposeOp::Over(Opacity::OPAQUE),
            );
            let want = b * (1.0 - k * a) + k * pf;
            assert!(
                (f64::from(over) - want).abs() <= TOL,
                "over {bg} {cover} {alpha}: {over} vs {want}"
            );
            let add_v = one(
                bg,
                cover,
                &Const::<false, false>(texel, [0]),
                ComposeOp::Add(Opacity::OPAQUE),
            );
            let want = b + k * (pf - b * a);
            assert!(
                (f64::from(add_v) - want).abs() <= TOL,
                "add {bg} {cover} {alpha}: {add_v} vs {want}"
            );
            // The same alpha as a mask of the tint `lin`.
            let mask = Const::<false, true>(texel, [lin << COVER_BITS]);
            let over = one(bg, cover, &mask, ComposeOp::Over(Opacity::OPAQUE));
            let want = b + k * a * (f64::from(lin) * one16 - b);
            assert!(
                (f64::from(over) - want).abs() <= TOL,
                "mask {bg} {cover} {alpha}: {over} vs {want}"
            );
        }
        // An opaque sampler's whole pixel is its colour.
        let t = Texel {
            color: [777 << COVER_BITS],
            alpha: 0,
        };
        let v = one(
            300,
            COVER_ONE,
            &Const::<true, false>(t, [0]),
            ComposeOp::Over(Opacity::OPAQUE),
        );
        assert_eq!(v, 777 << COVER_BITS);
    }
}
