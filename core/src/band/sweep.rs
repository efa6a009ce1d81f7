//! The span sweep: one shape's coverage, summed along each row of the
//! scratch, composed into the band (over, add, or the attenuation that
//! starts a multi-plane shape's over).
//!
//! Per row a running sum of the cover changes (exact integers) gives each
//! pixel the shape's signed coverage; between changes it is constant, so
//! the row is a few runs: the edge pixels, one coverage each, and the
//! interior spans. The fill rule turns the sum into a share `s` of the
//! pixel; a run is composed with its paint set up once (a flat colour, or
//! the Gouraud plane at the run's first pixel: two multiplies per channel)
//! and stepped by one addition per pixel. Per pixel of a run:
//!
//! | op | whole pixel, opaque | part of a pixel |
//! | --- | --- | --- |
//! | over, flat | store | 1 multiply per channel |
//! | over, plane | store | 1 multiply per channel |
//! | add, flat | add | add (the product is per run) |
//! | add, plane | add | 1 multiply per channel |
//! | attenuate | store 0 | 1 multiply per channel |
//!
//! The partial-pixel products use 12.4-bit intensities and 12-bit shares
//! (`|diff| < 2^18`, `k <= 2^12`: inside `i32`), within 1/16 of a level of
//! the exact `acc (1 - k) + I k`. The sweep clears what it reads, for the
//! next shape.

use super::{take_row, BandBuffer};
use crate::shade::{Plane, PLANE_FRAC};
use crate::style::{FillRule, Opacity};
use crate::{COVER_BITS, COVER_ONE};

// A plane's fine intensity is exactly an accumulator value: lin12 * 2^16.
const _: () = assert!(PLANE_FRAC == COVER_BITS);

/// Bits of the 12-bit share `k` used in partial-pixel products.
const K_BITS: u32 = 12;
/// The accumulator's bits below the 12.4 intensity used in products.
const DROP: u32 = COVER_BITS - 4;
/// Bound on a partial-pixel difference, so `diff * k` stays in `i32`.
const DIFF_LIMIT: i32 = 1 << 18;

/// What colour a shape's pixels get.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Paint<'p, const C: usize> {
    /// One linear 12-bit colour.
    Flat([u16; C]),
    /// A Gouraud plane of absolute intensity (built over a zero
    /// background).
    Plane(&'p Plane<C>),
}

/// How a shape's coverage meets the band.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum ComposeOp {
    /// `acc = acc (1 - s α) + I s α`.
    Over(Opacity),
    /// `acc += (I - bg) s α`.
    Add(Opacity),
    /// `acc = acc (1 - s α)`: the first half of an over whose colour is
    /// then added plane by plane (a Gouraud mesh composed as one shape).
    Attenuate(Opacity),
}

/// The share of a pixel covered, by the fill rule, from its winding
/// integral `c` (coverage units).
#[inline]
fn share(c: i32, rule: FillRule) -> i32 {
    match rule {
        FillRule::NonZero => {
            let a = c.unsigned_abs();
            if a >= COVER_ONE as u32 {
                COVER_ONE
            } else {
                a as i32
            }
        }
        FillRule::EvenOdd => {
            let m = c & (2 * COVER_ONE - 1);
            if m > COVER_ONE {
                2 * COVER_ONE - m
            } else {
                m
            }
        }
    }
}

/// `s α` in 1/4096, rounded.
#[inline]
fn share12(s: i32, alpha: Opacity) -> i32 {
    (s * i32::from(alpha.to_4096ths()) + (1 << (COVER_BITS - 1))) >> COVER_BITS
}

impl<const C: usize> BandBuffer<'_, C> {
    /// Composes the shape whose edges were just walked into the scratch over
    /// frame rows `y_lo..y_hi` (clipped to the band), and clears the
    /// scratch there.
    #[inline(never)] // kept out of line so profiles can name it
    pub(crate) fn compose(
        &mut self,
        y_lo: i32,
        y_hi: i32,
        rule: FillRule,
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        let w = usize::from(self.band.width);
        let x0 = self.band.x0;
        let bg = self.background;
        for y in self.rows_in_band(y_lo, y_hi) {
            let r = (y - self.band.y0) as usize;
            let Some((deltas, lo, hi)) = take_row(self.cover, r, w) else {
                continue;
            };
            let Some(row_acc) = self.acc.get_mut(r * w * C..(r + 1) * w * C) else {
                deltas.iter_mut().for_each(|d| *d = 0);
                continue;
            };
            let mut c: i32 = 0;
            let mut x = lo;
            while x <= hi {
                if let Some(d) = deltas.get_mut(x) {
                    c = c.wrapping_add(core::mem::take(d));
                }
                // The run lasts to the next change, or to the band's end if
                // coverage remains after the last one.
                let mut next = x + 1;
                while next <= hi && deltas.get(next) == Some(&0) {
                    next += 1;
                }
                let end = if next > hi && c != 0 { w } else { next };
                let s = share(c, rule);
                if s != 0 {
                    if let Some(px) = row_acc.get_mut(x * C..end * C) {
                        let fx = x0.saturating_add(x as i32);
                        run(px, s, fx, y, paint, op, bg);
                    }
                }
                x = next;
            }
        }
    }
}

/// Composes one run of pixels `px` (`C` values each) of share `s`, whose
/// first pixel is frame pixel `(x, y)`.
#[inline]
fn run<const C: usize>(
    px: &mut [i32],
    s: i32,
    x: i32,
    y: i32,
    paint: &Paint<'_, C>,
    op: ComposeOp,
    bg: [u16; C],
) {
    let alpha = match op {
        ComposeOp::Over(a) | ComposeOp::Add(a) | ComposeOp::Attenuate(a) => a,
    };
    let whole = s == COVER_ONE && alpha.is_opaque();
    let k = share12(s, alpha);
    if k == 0 && !whole {
        return;
    }
    match (op, paint) {
        (ComposeOp::Over(_), Paint::Flat(color)) => {
            if whole {
                let fill = color.map(|v| i32::from(v) << COVER_BITS);
                for p in px.chunks_exact_mut(C) {
                    p.copy_from_slice(&fill);
                }
            } else {
                let f4 = color.map(|v| i32::from(v) << (COVER_BITS - DROP));
                for p in px.chunks_exact_mut(C) {
                    for ch in 0..C {
                        let d = (f4[ch] - (p[ch] >> DROP)).clamp(-DIFF_LIMIT, DIFF_LIMIT);
                        p[ch] += d * k;
                    }
                }
            }
        }
        (ComposeOp::Over(_), Paint::Plane(plane)) => {
            let mut v = plane_at(plane, x, y);
            for p in px.chunks_exact_mut(C) {
                for ch in 0..C {
                    if whole {
                        p[ch] = v[ch];
                    } else {
                        let d = ((v[ch] >> DROP) - (p[ch] >> DROP)).clamp(-DIFF_LIMIT, DIFF_LIMIT);
                        p[ch] += d * k;
                    }
                    v[ch] = v[ch].saturating_add(plane.gx[ch]);
                }
            }
        }
        (ComposeOp::Add(_), Paint::Flat(color)) => {
            let mut add = [0i32; C];
            for ch in 0..C {
                let dl = i32::from(color[ch]) - i32::from(bg[ch]);
                add[ch] = if alpha.is_opaque() {
                    dl * s
                } else {
                    (dl * k) << (COVER_BITS - K_BITS)
                };
            }
            for p in px.chunks_exact_mut(C) {
                for ch in 0..C {
                    p[ch] = p[ch].saturating_add(add[ch]);
                }
            }
        }
        (ComposeOp::Add(_), Paint::Plane(plane)) => {
            let mut v = plane_at(plane, x, y);
            let bgf = bg.map(|b| i32::from(b) << COVER_BITS);
            for p in px.chunks_exact_mut(C) {
                for ch in 0..C {
                    let rel = v[ch].saturating_sub(bgf[ch]);
                    let add = if whole {
                        rel
                    } else {
                        (rel >> DROP).clamp(-DIFF_LIMIT, DIFF_LIMIT) * k
                    };
                    p[ch] = p[ch].saturating_add(add);
                    v[ch] = v[ch].saturating_add(plane.gx[ch]);
                }
            }
        }
        (ComposeOp::Attenuate(_), _) => {
            for p in px.chunks_exact_mut(C) {
                for ch in 0..C {
                    if whole {
                        p[ch] = 0;
                    } else {
                        let d = (p[ch] >> DROP).clamp(-DIFF_LIMIT, DIFF_LIMIT);
                        p[ch] -= d * k;
                    }
                }
            }
        }
    }
}

/// The plane at frame pixel `(x, y)`, in accumulator units (span set-up:
/// two multiplies per channel).
#[inline]
fn plane_at<const C: usize>(plane: &Plane<C>, x: i32, y: i32) -> [i32; C] {
    plane
        .at(x, y)
        .map(|v| v.clamp(i64::from(i32::MIN / 2), i64::from(i32::MAX / 2)) as i32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fill_rules_fold_the_winding_integral() {
        let one = COVER_ONE;
        assert_eq!(share(one / 2, FillRule::NonZero), one / 2);
        assert_eq!(share(-one / 2, FillRule::NonZero), one / 2);
        assert_eq!(share(2 * one, FillRule::NonZero), one);
        assert_eq!(share(2 * one, FillRule::EvenOdd), 0);
        assert_eq!(share(3 * one / 2, FillRule::EvenOdd), one / 2);
        assert_eq!(share(-one, FillRule::EvenOdd), one);
        assert_eq!(share(-one / 4, FillRule::EvenOdd), one / 4);
    }

    #[test]
    fn over_at_half_coverage_is_the_linear_midpoint() {
        let mut px = [1000 << COVER_BITS];
        run(
            &mut px,
            COVER_ONE / 2,
            0,
            0,
            &Paint::Flat([3000]),
            ComposeOp::Over(Opacity::OPAQUE),
            [0],
        );
        assert_eq!(px[0], 2000 << COVER_BITS);
    }
}
