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
//! A partial pixel's product `v * k / 2^16` is two 32-bit multiplies (the
//! operand split at bit 14, see [`mul_share`]), within one unit, 1/65536 of
//! a level, of the exact `acc (1 - k) + I k`. The sweep clears what it
//! reads, for the next shape.

use super::{take_row, BandBuffer};
use crate::shade::{Plane, PLANE_FRAC};
use crate::style::{FillRule, Opacity};
use crate::{COVER_BITS, COVER_ONE};

// A plane's fine intensity is exactly an accumulator value: lin12 * 2^16.
const _: () = assert!(PLANE_FRAC == COVER_BITS);

/// Bits of an [`Opacity`].
const ALPHA_BITS: u32 = 12;
/// Where [`mul_share`] splits its operand.
const LO_BITS: u32 = 14;
/// Largest operand of [`mul_share`]: `|v| * 2^16 >> 14` stays below 2^31.
const V_LIMIT: i32 = (1 << 29) - 1;

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
    /// `acc += I s α`: the second half.
    Accumulate(Opacity),
}

/// How a pixel's winding integral becomes its share of a shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Coverage {
    /// A simple outline of known orientation (`+1` or `-1`, the sign of
    /// its area): the integral times it, unclamped, so that shapes sharing
    /// an edge add up exactly (what `Blend::Add` needs); over clamps it to
    /// `0..=1` px.
    Signed(i32),
    /// Any outline, by a fill rule.
    Rule(FillRule),
}

/// The share of a pixel covered, from its winding integral `c` (coverage
/// units).
#[inline]
fn share(c: i32, coverage: Coverage) -> i32 {
    match coverage {
        Coverage::Signed(o) => c.wrapping_mul(o),
        Coverage::Rule(FillRule::NonZero) => {
            let a = c.unsigned_abs();
            if a >= COVER_ONE as u32 {
                COVER_ONE
            } else {
                a as i32
            }
        }
        Coverage::Rule(FillRule::EvenOdd) => {
            let m = c & (2 * COVER_ONE - 1);
            if m > COVER_ONE {
                2 * COVER_ONE - m
            } else {
                m
            }
        }
    }
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
        rule: Coverage,
        paint: &Paint<'_, C>,
        op: ComposeOp,
    ) {
        // One sweep per kind of span, chosen once per shape.
        let bg = self.background;
        match (op, paint) {
            (ComposeOp::Over(a), Paint::Flat(color)) => {
                let f = color.map(|v| i32::from(v) << COVER_BITS);
                self.sweep(y_lo, y_hi, rule, a, true, |px, k, whole, _, _| {
                    if whole {
                        for p in pixels::<C>(px) {
                            *p = f;
                        }
                    } else {
                        for p in pixels::<C>(px) {
                            for ch in 0..C {
                                p[ch] += mul_share(f[ch] - p[ch], k);
                            }
                        }
                    }
                });
            }
            (ComposeOp::Over(a), Paint::Plane(plane)) => {
                self.sweep(y_lo, y_hi, rule, a, true, |px, k, whole, x, y| {
                    let mut v = plane_at(plane, x, y);
                    for p in pixels::<C>(px) {
                        for ch in 0..C {
                            if whole {
                                p[ch] = v[ch];
                            } else {
                                p[ch] += mul_share(v[ch] - p[ch], k);
                            }
                            v[ch] = v[ch].saturating_add(plane.gx[ch]);
                        }
                    }
                });
            }
            (ComposeOp::Add(a) | ComposeOp::Accumulate(a), Paint::Flat(color)) => {
                let base = if matches!(op, ComposeOp::Add(_)) {
                    bg
                } else {
                    [0; C]
                };
                let diff: [i32; C] =
                    core::array::from_fn(|ch| i32::from(color[ch]) - i32::from(base[ch]));
                self.sweep(y_lo, y_hi, rule, a, false, |px, k, _, _, _| {
                    // (I - bg) k exactly: below 2^12 * 2^16, one product per
                    // run.
                    let add: [i32; C] = core::array::from_fn(|ch| diff[ch] * k);
                    for p in pixels::<C>(px) {
                        for ch in 0..C {
                            p[ch] = p[ch].saturating_add(add[ch]);
                        }
                    }
                });
            }
            (ComposeOp::Add(a) | ComposeOp::Accumulate(a), Paint::Plane(plane)) => {
                let base = if matches!(op, ComposeOp::Add(_)) {
                    bg
                } else {
                    [0; C]
                };
                let bgf = base.map(|b| i32::from(b) << COVER_BITS);
                self.sweep(y_lo, y_hi, rule, a, false, |px, k, whole, x, y| {
                    let mut v = plane_at(plane, x, y);
                    for p in pixels::<C>(px) {
                        for ch in 0..C {
                            let rel = v[ch] - bgf[ch];
                            let add = if whole { rel } else { mul_share(rel, k) };
                            p[ch] = p[ch].saturating_add(add);
                            v[ch] = v[ch].saturating_add(plane.gx[ch]);
                        }
                    }
                });
            }
            (ComposeOp::Attenuate(a), _) => {
                self.sweep(y_lo, y_hi, rule, a, true, |px, k, whole, _, _| {
                    for p in pixels::<C>(px) {
                        for ch in 0..C {
                            p[ch] = if whole {
                                0
                            } else {
                                p[ch] - mul_share(p[ch], k)
                            };
                        }
                    }
                });
            }
        }
    }

    /// The sweep of rows `y_lo..y_hi`: per row, the running sum of the
    /// scratch's changes (clearing them) splits the row into runs of one
    /// coverage; each run with a share is handed to `span` with the
    /// composite's factor `k` (the share times the opacity, in coverage
    /// units), whether it is a whole opaque pixel, and the frame pixel of
    /// its first pixel. `convex`: the share is clamped to `0..=1` px first
    /// (over, attenuate).
    #[inline(always)]
    fn sweep<F: FnMut(&mut [i32], i32, bool, i32, i32)>(
        &mut self,
        y_lo: i32,
        y_hi: i32,
        rule: Coverage,
        alpha: Opacity,
        convex: bool,
        mut span: F,
    ) {
        let w = usize::from(self.band.width);
        let x0 = self.band.x0;
        let opaque = alpha.is_opaque();
        let a4096 = i32::from(alpha.to_4096ths());
        for y in self.rows_in_band(y_lo, y_hi) {
            let r = (y - self.band.y0) as usize;
            let Some(mut row) = take_row(self.cover, r, w) else {
                continue;
            };
            let (lo, hi) = (row.lo, row.hi);
            let Some(changes) = row.deltas.get_mut(..=hi) else {
                continue;
            };
            let Some(row_acc) = self.acc.get_mut(r * w * C..(r + 1) * w * C) else {
                changes.iter_mut().for_each(|d| *d = 0);
                continue;
            };
            let mut c: i32 = 0;
            let mut x = lo;
            let mut drawn = (usize::MAX, 0);
            loop {
                if let Some(d) = changes.get_mut(x) {
                    c = c.wrapping_add(core::mem::take(d));
                }
                // The run lasts to the next change, or to the band's end if
                // coverage remains after the last one.
                let next = match changes
                    .get(x + 1..)
                    .and_then(|t| t.iter().position(|&d| d != 0))
                {
                    Some(k) => x + 1 + k,
                    None => hi + 1,
                };
                let end = if next > hi && c != 0 { w } else { next };
                let s = share(c, rule);
                if s != 0 {
                    if let Some(px) = row_acc.get_mut(x * C..end * C) {
                        drawn = (drawn.0.min(x), drawn.1.max(end));
                        // A convex combination needs a share within the pixel.
                        let s = if convex { s.clamp(0, COVER_ONE) } else { s };
                        let k = if opaque {
                            s
                        } else if s.unsigned_abs() < 1 << (31 - ALPHA_BITS) {
                            (s * a4096) >> ALPHA_BITS
                        } else {
                            ((i64::from(s) * i64::from(a4096)) >> ALPHA_BITS) as i32
                        };
                        if k != 0 {
                            let fx = x0.saturating_add(x as i32);
                            span(px, k, opaque && s == COVER_ONE, fx, y);
                        }
                    }
                }
                if next > hi {
                    break;
                }
                x = next;
            }
            row.mark(drawn.0, drawn.1);
        }
    }
}

/// The pixels of a run, `C` values each. (`chunks_exact` would divide the
/// run's length by `C`: a library call on the Cortex-M0.)
#[inline]
fn pixels<const C: usize>(px: &mut [i32]) -> Pixels<'_, C> {
    Pixels(px)
}

struct Pixels<'p, const C: usize>(&'p mut [i32]);

impl<'p, const C: usize> Iterator for Pixels<'p, C> {
    type Item = &'p mut [i32; C];
    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        let (p, rest) = core::mem::take(&mut self.0).split_first_chunk_mut::<C>()?;
        self.0 = rest;
        Some(p)
    }
}

/// `floor(v * k / 2^16)` exactly, for a share `|k| <= 2^16`, in 32-bit
/// multiplies:
/// `v` is split at bit 14, so each product stays below `2^31` (`v` is
/// limited to `±2^29` first, two full scales beyond any intensity).
#[inline]
fn mul_share(v: i32, k: i32) -> i32 {
    if k == COVER_ONE {
        return v;
    }
    let v = v.clamp(-V_LIMIT, V_LIMIT);
    let (hi, lo) = (v >> LO_BITS, v & ((1 << LO_BITS) - 1));
    // v k / 2^16 = (hi k) / 2^2 + (lo k) / 2^16: carry hi k's low bits
    // into the second quotient so the result is the floor of the whole.
    let (a, b) = (hi * k, lo * k);
    const UP: u32 = COVER_BITS - LO_BITS;
    (a >> UP) + ((((a & ((1 << UP) - 1)) << LO_BITS) + b) >> COVER_BITS)
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
        let (nz, eo) = (
            Coverage::Rule(FillRule::NonZero),
            Coverage::Rule(FillRule::EvenOdd),
        );
        assert_eq!(share(one / 2, nz), one / 2);
        assert_eq!(share(-one / 2, nz), one / 2);
        assert_eq!(share(2 * one, nz), one);
        assert_eq!(share(2 * one, eo), 0);
        assert_eq!(share(3 * one / 2, eo), one / 2);
        assert_eq!(share(-one, eo), one);
        assert_eq!(share(-one / 4, eo), one / 4);
        // Signed: linear, so that a seam's two sides add up exactly.
        assert_eq!(share(-3, Coverage::Signed(1)), -3);
        assert_eq!(share(-one - 3, Coverage::Signed(-1)), one + 3);
    }

    #[test]
    fn over_at_half_coverage_is_the_linear_midpoint() {
        let (mut acc, mut cover) = ([0i32; 4], [0i32; 12]);
        let band = crate::band::Band::new(2, 0, 2);
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([1000]);
        buf.add_area(0, 0, COVER_ONE / 2);
        buf.compose(
            0,
            1,
            Coverage::Rule(FillRule::NonZero),
            &Paint::Flat([3000]),
            ComposeOp::Over(Opacity::OPAQUE),
        );
        assert_eq!(buf.lin12(0, 0), Some([2000]));
        assert_eq!(buf.lin12(1, 0), Some([1000]));
    }

    #[test]
    fn share_products_are_floors_of_the_exact_product() {
        for v in [
            -(1 << 29) + 1,
            -123_456_789,
            -1,
            0,
            1,
            77_777,
            (1 << 29) - 1,
        ] {
            for k in [1, 2, 4095, 32768, 65535, -65535, -3] {
                let exact = (i64::from(v) * i64::from(k)).div_euclid(1 << 16);
                assert_eq!(i64::from(mul_share(v, k)), exact, "{v} * {k}");
            }
        }
    }
}
