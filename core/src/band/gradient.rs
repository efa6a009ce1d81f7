//! Gradient paint along a run of the span sweep: the colour of a linear
//! or radial [`Gradient`] at every pixel of a run, stepped with additions
//! and composed by the run's operation (over, add, accumulate).
//!
//! Takes a run (its first frame pixel, its share, its pixels) and the
//! gradient's set-up (done once, when the gradient was made:
//! [`style::gradient`](crate::style::gradient)); gives the run's pixels
//! the same compose as a flat colour or a Gouraud plane (`sweep.rs`), with
//! the colour varying along the run.
//!
//! ## Linear: exact segments, a plane per segment
//!
//! Along a row the projection `M` of a pixel centre on the gradient's axis
//! changes by a constant, so which segment (pair of stops, or pad) a pixel
//! is in is decided exactly, by `i64` compares at the run's first pixel:
//! the number of pixels left in the segment is one division (per segment
//! a run crosses; 32-bit when the numbers fit). Inside a segment the colour
//! is the segment's plane `r0 + b x + g y`: set up from `x` and `y` (two
//! multiplies per channel), then one addition per pixel and channel.
//!
//! ## Radial: the distance tracked by an integer square root
//!
//! The distance `d` of a pixel centre from the centre is tracked as
//! `D = floor(128 d)`, exactly, with `E = D2 - D²` (`0 <= E <= 2D`,
//! `D2 = 128² d²`, an integer: the centre lies on the 1/128-px grid) —
//! the midpoint circle's idea. One pixel right adds `F = 2 · 128 u + 128²`
//! to `D2` (`u` the pixel's x offset from the centre, 1/128 px), and `F`
//! itself grows by `2 · 128²`. `D` is predicted to move by its last jump
//! `j`: `E -= Q`, `D += j`, `Q += J2` with `Q = 2Dj + j²` and `J2 = 2j²`
//! kept up to date; when the prediction misses (`E` out of `0..=2D`), `D`
//! and `j` are corrected by steps of `±2^k`, each of which updates `E`,
//! `Q`, `J2` with shifts and additions (greedy, from `2^8` down): one step
//! for the usual jitter of a floor, at most `2 · 9 + 1` near the centre,
//! where `D` turns. The colour is a function of `D` (the segment's colour
//! at the middle of the quantum): `col += j m` with `m` the colour per
//! unit of `D` (and `j m` kept like `Q`). Segments are cut into pieces of
//! 4096 units of `D` (32 px), each anchored at its start with the slope's
//! 16 extra fraction bits, so the slope's rounding adds at most 1/32
//! level. Leaving a piece re-sets-up the colour from `D` (a multiply per
//! channel).
//!
//! Per pixel and channel, in the loop: additions, compares and the
//! compose; multiplies only when a run starts, a segment or piece is
//! entered, and in the compose of partly covered pixels. The quantum,
//! 1/128 px, is the trade of precision for speed on the Cortex-M0: the
//! jump `j` of `D` swings through `2 · 128` over a row that passes the
//! centre and jitters by one at about half the pixels, and each change is
//! a correction (measured on thumbv6m, a 240x240 frame filled with a
//! radial gradient: about 120 instructions per pixel more than a flat
//! fill at 1/128 px, 95 at 1/64 px, 176 at 1/256 px).
//!
//! ## Every pixel, whatever the run
//!
//! Each run is set up from its own first pixel with exact integers (the
//! linear `M`; the radial `D` by an integer square root), and the colour
//! is a function of the pixel alone: the plane's value, exact modulo 2^32,
//! or the piece's value at `D`. So bands of any height and any cut of a
//! shape give a pixel the same colour.
//!
//! ## Whole levels for add
//!
//! `Blend::Add` and accumulate compose the colour rounded to a whole
//! level: `(I - bg) k` is then exact (the way a flat colour's is), so two
//! shapes sharing an edge add up to the bits of one. Over keeps the
//! fraction (the resolve rounds once).
//!
//! ## Ranges
//!
//! For any pixel a band holds against any centre in the coordinate range
//! (offsets below 8192 px: `|u|, |v| < 2^20` in 1/128 px), `D < 2^20.5`,
//! `F < 2^28.1`, `|Q| < 2^28.6`, `|J2| < 2^15.1`, and the greedy trials
//! `E ∓ 2D 2^k - 4^k` (`k <= 8`) stay within `±2^29.6`: all in `i32`.
//! Arithmetic that could leave its range for pixels beyond it wraps (no
//! panic; such pixels hold no shape).

use super::sweep::{mul_share, ComposeOp};
use crate::geom::FINE_BITS;
use crate::style::gradient::{LinearRamp, RadialRamp, Ramp, MAX_STOPS, RADIAL_BITS, T_BITS};
use crate::style::Gradient;
use crate::COVER_BITS;

/// Half a level, added before a colour is cut to whole levels.
const HALF_LEVEL: i32 = 1 << (COVER_BITS - 1);

/// Composes a run of pixels `px` (`C` values each) whose first pixel is
/// frame pixel `(x, y)`, painted with `g`: `k` is the share times the
/// opacity (coverage units), `whole` whether it covers the pixels fully
/// and opaquely. Attenuate ignores colour and is the sweep's own.
#[allow(clippy::too_many_arguments)]
pub(super) fn compose<const C: usize>(
    px: &mut [i32],
    k: i32,
    whole: bool,
    x: i32,
    y: i32,
    g: &Gradient<C>,
    op: ComposeOp,
    bg: [u16; C],
) {
    match op {
        ComposeOp::Over(_) if whole => paint(px, x, y, g, &Store),
        ComposeOp::Over(_) => paint(px, x, y, g, &OverPart(k)),
        ComposeOp::Add(_) | ComposeOp::Accumulate(_) => {
            let base = if matches!(op, ComposeOp::Add(_)) {
                bg
            } else {
                [0; C]
            };
            let bgf = base.map(|b| i32::from(b) << COVER_BITS);
            if whole {
                paint(px, x, y, g, &AddWhole(bgf));
            } else {
                paint(px, x, y, g, &AddPart(bgf, k));
            }
        }
        ComposeOp::Attenuate(_) => {}
    }
}

/// How one pixel takes the paint's value `v` (accumulator units, plus
/// [`BIAS`](Apply::BIAS)).
trait Apply<const C: usize> {
    /// Added to the colour at set-up: half a level for the operations that
    /// round the colour to whole levels by cutting its fraction.
    const BIAS: i32;
    fn apply(&self, p: &mut [i32; C], v: &[i32; C]);
}

/// Over, the pixel fully covered and the shape opaque: the colour.
struct Store;

impl<const C: usize> Apply<C> for Store {
    const BIAS: i32 = 0;
    #[inline(always)]
    fn apply(&self, p: &mut [i32; C], v: &[i32; C]) {
        *p = *v;
    }
}

/// Over by the share `k`: `p + (v - p) k`.
struct OverPart(i32);

impl<const C: usize> Apply<C> for OverPart {
    const BIAS: i32 = 0;
    #[inline(always)]
    fn apply(&self, p: &mut [i32; C], v: &[i32; C]) {
        for ch in 0..C {
            p[ch] = p[ch].wrapping_add(mul_share(v[ch].wrapping_sub(p[ch]), self.0));
        }
    }
}

/// The colour's whole level, in accumulator units (`v` carries the half
/// level of [`HALF_LEVEL`]: this rounds to nearest).
#[inline(always)]
fn level(v: i32) -> i32 {
    (v >> COVER_BITS) << COVER_BITS
}

/// Add (or accumulate, over a zero background), whole pixel:
/// `p + (I - bg)`.
struct AddWhole<const C: usize>([i32; C]);

impl<const C: usize> Apply<C> for AddWhole<C> {
    const BIAS: i32 = HALF_LEVEL;
    #[inline(always)]
    fn apply(&self, p: &mut [i32; C], v: &[i32; C]) {
        for ch in 0..C {
            p[ch] = p[ch].saturating_add(level(v[ch]).wrapping_sub(self.0[ch]));
        }
    }
}

/// Add by the share `k`: `p + (I - bg) k`, exact for whole levels.
struct AddPart<const C: usize>([i32; C], i32);

impl<const C: usize> Apply<C> for AddPart<C> {
    const BIAS: i32 = HALF_LEVEL;
    #[inline(always)]
    fn apply(&self, p: &mut [i32; C], v: &[i32; C]) {
        for ch in 0..C {
            let rel = level(v[ch]).wrapping_sub(self.0[ch]);
            p[ch] = p[ch].saturating_add(mul_share(rel, self.1));
        }
    }
}

#[inline(always)]
fn paint<const C: usize, A: Apply<C>>(px: &mut [i32], x: i32, y: i32, g: &Gradient<C>, a: &A) {
    match &g.ramp {
        Ramp::Flat(c) => {
            let v = c.map(|c| (i32::from(c) << COVER_BITS) + A::BIAS);
            for p in pixels::<C>(px) {
                a.apply(p, &v);
            }
        }
        Ramp::Linear(l) => linear(px, x, y, l, a),
        Ramp::Radial(r) => radial(px, x, y, r, a),
    }
}

// ---------------------------------------------------------------- linear

impl<const C: usize> LinearRamp<C> {
    /// The exact projection `M` of pixel `(x, y)`'s centre (per-run set-up:
    /// two 64-bit multiplies).
    #[inline]
    fn m_at(&self, x: i32, y: i32) -> i64 {
        self.mc
            .wrapping_add(self.mx.wrapping_mul(i64::from(x)))
            .wrapping_add(self.my.wrapping_mul(i64::from(y)))
    }

    /// The region of `M`: how many stops lie at or before it.
    #[inline]
    fn region(&self, m: i64) -> usize {
        let th = self.th.get(..self.n).unwrap_or(&[]);
        th.iter().filter(|&&t| t <= m).count()
    }

    /// How many pixels from the one of `M` on (to the right) stay in
    /// region `r`, at least 1; `u32::MAX` when the region does not end.
    fn count(&self, m: i64, r: usize) -> u32 {
        // |mx| = |dx| 2^22: divide by 2^22 first (a shift; nested floors
        // and ceilings of positive quotients compose), then by |dx|.
        const SH: u32 = FINE_BITS + T_BITS;
        let n = if self.mx > 0 {
            // The next stop, at the first pixel with M >= th[r].
            let Some(&t) = self.th.get(r).filter(|_| r < self.n) else {
                return u32::MAX;
            };
            let dist = (t.wrapping_sub(m) as u64).saturating_add((1 << SH) - 1) >> SH;
            let (q, rem) = crate::arith::udivmod(dist, self.dx_abs);
            q + u64::from(rem != 0)
        } else if self.mx < 0 {
            // The previous stop, at the first pixel with M < th[r - 1].
            let Some(&t) = r.checked_sub(1).and_then(|i| self.th.get(i)) else {
                return u32::MAX;
            };
            let dist = (m.wrapping_sub(t) as u64) >> SH;
            crate::arith::udivmod(dist, self.dx_abs).0 + 1
        } else {
            return u32::MAX;
        };
        n.clamp(1, u64::from(u32::MAX)) as u32
    }
}

/// A run painted with a linear gradient: per segment crossed, a set-up,
/// then one addition per pixel and channel.
#[inline(never)]
fn linear<const C: usize, A: Apply<C>>(px: &mut [i32], x: i32, y: i32, l: &LinearRamp<C>, a: &A) {
    let mut x = x;
    let mut rest = px;
    loop {
        let m = l.m_at(x, y);
        let r = l.region(m);
        let n = l.count(m, r);
        let Some(planes) = l.planes.get(r) else {
            return;
        };
        let mut v = [0i32; C];
        let mut b = [0i32; C];
        for ch in 0..C {
            let p = planes[ch];
            v[ch] =
                p.r0.wrapping_add(p.b.wrapping_mul(x))
                    .wrapping_add(p.g.wrapping_mul(y))
                    .wrapping_add(A::BIAS);
            b[ch] = p.b;
        }
        // A run is at most a band wide: no overflow, no 64-bit product.
        let take = (n.min(u32::from(super::MAX_WIDTH)) as usize * C).min(rest.len());
        let (now, later) = core::mem::take(&mut rest).split_at_mut(take);
        for p in pixels::<C>(now) {
            a.apply(p, &v);
            for ch in 0..C {
                v[ch] = v[ch].wrapping_add(b[ch]);
            }
        }
        if later.is_empty() {
            return;
        }
        rest = later;
        x = x.wrapping_add(n as i32);
    }
}

// ---------------------------------------------------------------- radial

/// One unit of the tracked distance is 1/S px.
const S: i32 = 1 << RADIAL_BITS;
/// The growth of `F` per pixel: `2 S²`.
const FF: i32 = 2 * S * S;
/// The largest correction step is `2^K`: corrections are below `2S + 2`,
/// which the steps `2^K .. 1` cover.
const K: u32 = RADIAL_BITS + 1;
/// The pieces a segment is cut into, in units of `D`.
const PIECE: i32 = 1 << 12;

/// The radial stepper's state along a row (see the module docs).
struct Tracker<const C: usize> {
    /// `floor(S d)`.
    d: i32,
    /// `D2 - d²`, in `0..=2d` between pixels.
    e: i32,
    /// What `D2` grows by to the next pixel.
    f: i32,
    /// The last jump of `d`, the next one's prediction.
    j: i32,
    /// `2 d j + j²`.
    q: i32,
    /// `2 j²`.
    j2: i32,
    /// The current piece: `d` in `lo .. lo + span`.
    lo: i32,
    span: u32,
    /// The colour at `d` (accumulator units plus the bias).
    col: [i32; C],
    /// The colour per unit of `d`.
    m: [i32; C],
    /// `j m`.
    jm: [i32; C],
}

/// `floor(sqrt(n))` (in 32 bits when `n` fits).
fn isqrt(n: u64) -> u32 {
    match u32::try_from(n) {
        Ok(n) => n.isqrt(),
        Err(_) => n.isqrt() as u32,
    }
}

impl<const C: usize> Tracker<C> {
    /// The state at pixel `(x, y)`, from scratch (per-run set-up: an
    /// integer square root).
    fn start(ramp: &RadialRamp<C>, x: i32, y: i32, bias: i32) -> Self {
        let u = x
            .wrapping_shl(RADIAL_BITS)
            .wrapping_add(S / 2)
            .wrapping_sub(ramp.cx);
        let v = y
            .wrapping_shl(RADIAL_BITS)
            .wrapping_add(S / 2)
            .wrapping_sub(ramp.cy);
        let (ua, va) = (u64::from(u.unsigned_abs()), u64::from(v.unsigned_abs()));
        let d2 = ua * ua + va * va;
        let d = isqrt(d2);
        let e = d2.wrapping_sub(u64::from(d) * u64::from(d)) as i32;
        let mut t = Self {
            d: d as i32,
            e,
            f: u.wrapping_shl(RADIAL_BITS + 1).wrapping_add(S * S),
            j: 0,
            q: 0,
            j2: 0,
            lo: 0,
            span: 0,
            col: [0; C],
            m: [0; C],
            jm: [0; C],
        };
        t.enter(ramp, bias);
        t
    }

    /// One pixel right.
    #[inline(always)]
    fn advance(&mut self, ramp: &RadialRamp<C>, bias: i32) {
        self.e = self.e.wrapping_add(self.f);
        self.f = self.f.wrapping_add(FF);
        self.e = self.e.wrapping_sub(self.q);
        self.d = self.d.wrapping_add(self.j);
        self.q = self.q.wrapping_add(self.j2);
        for ch in 0..C {
            self.col[ch] = self.col[ch].wrapping_add(self.jm[ch]);
        }
        // Signed: a prediction below 0 fails one of the two.
        if self.e < 0 || self.e > self.d.wrapping_shl(1) {
            self.correct();
        }
        if self.d.wrapping_sub(self.lo) as u32 >= self.span {
            self.enter(ramp, bias);
        }
    }

    /// `d` and `j` up by `2^k`.
    #[inline(always)]
    fn up(&mut self, k: u32) {
        let (d2k, j4k, a2) = (
            self.d.wrapping_shl(k + 1),
            self.j.wrapping_shl(k + 2),
            1i32 << (2 * k),
        );
        // E = D2 - (d + a)², Q = 2 (d + a)(j + a) + (j + a)², J2 = 2 (j + a)².
        self.e = self.e.wrapping_sub(d2k).wrapping_sub(a2);
        self.q = self
            .q
            .wrapping_add(d2k)
            .wrapping_add(j4k)
            .wrapping_add(3 * a2);
        self.j2 = self.j2.wrapping_add(j4k).wrapping_add(2 * a2);
        self.d = self.d.wrapping_add(1 << k);
        self.j = self.j.wrapping_add(1 << k);
        for ch in 0..C {
            let mk = self.m[ch].wrapping_shl(k);
            self.col[ch] = self.col[ch].wrapping_add(mk);
            self.jm[ch] = self.jm[ch].wrapping_add(mk);
        }
    }

    /// `d` and `j` down by `2^k`.
    #[inline(always)]
    fn down(&mut self, k: u32) {
        let (d2k, j4k, a2) = (
            self.d.wrapping_shl(k + 1),
            self.j.wrapping_shl(k + 2),
            1i32 << (2 * k),
        );
        self.e = self.e.wrapping_add(d2k).wrapping_sub(a2);
        self.q = self
            .q
            .wrapping_sub(d2k)
            .wrapping_sub(j4k)
            .wrapping_add(3 * a2);
        self.j2 = self.j2.wrapping_sub(j4k).wrapping_add(2 * a2);
        self.d = self.d.wrapping_sub(1 << k);
        self.j = self.j.wrapping_sub(1 << k);
        for ch in 0..C {
            let mk = self.m[ch].wrapping_shl(k);
            self.col[ch] = self.col[ch].wrapping_sub(mk);
            self.jm[ch] = self.jm[ch].wrapping_sub(mk);
        }
    }

    /// Brings `d` back to `floor(sqrt(D2))` after a missed prediction:
    /// greedy steps of `2^K .. 1` (at most `K + 2` of them).
    #[cold]
    #[inline(never)]
    fn correct(&mut self) {
        if self.d < 0 {
            // Overshot the centre: up to 0 first (|d| <= S here).
            for k in (0..=K).rev() {
                if self.d.wrapping_add(1 << k) <= 0 {
                    self.up(k);
                }
            }
        }
        if self.e < 0 {
            // (d - 1)² <= D2 is the usual case.
            if self.e.wrapping_add(self.d.wrapping_shl(1)) > 0 {
                self.down(0);
                return;
            }
            // The largest b with (d - b)² > D2, then one more.
            for k in (0..=K).rev() {
                let trial = self
                    .e
                    .wrapping_add(self.d.wrapping_shl(k + 1))
                    .wrapping_sub(1 << (2 * k));
                if (1 << k) <= self.d && trial < 0 {
                    self.down(k);
                }
            }
            self.down(0);
        } else if self.e > self.d.wrapping_shl(1) {
            // (d + 1)² <= D2 < (d + 2)² is the usual case.
            if self.e.wrapping_sub(self.d.wrapping_shl(1)).wrapping_sub(1)
                <= self.d.wrapping_add(1).wrapping_shl(1)
            {
                self.up(0);
                return;
            }
            // The largest a with (d + a)² <= D2.
            for k in (0..=K).rev() {
                let trial = self
                    .e
                    .wrapping_sub(self.d.wrapping_shl(k + 1))
                    .wrapping_sub(1 << (2 * k));
                if trial >= 0 {
                    self.up(k);
                }
            }
        }
    }

    /// Sets up the colour of the region and piece `d` is in (at a run's
    /// start and whenever `d` leaves its piece): multiplies per channel.
    #[cold]
    #[inline(never)]
    fn enter(&mut self, ramp: &RadialRamp<C>, bias: i32) {
        let n = ramp.n.min(MAX_STOPS);
        let th = ramp.th.get(..n).unwrap_or(&[]);
        let d = self.d;
        let r = th.iter().filter(|&&t| t <= d).count();
        let Some(piece) = ramp.pieces.get(r) else {
            return;
        };
        let start = r.checked_sub(1).and_then(|i| th.get(i)).copied();
        let end = th.get(r).copied().unwrap_or(i32::MAX);
        match start {
            // A segment between two stops: the piece of 4096 units of D
            // holding d, anchored at its first D.
            Some(s) if r < n => {
                let lo = s.max(d & !(PIECE - 1));
                let hi = end.min((d & !(PIECE - 1)).wrapping_add(PIECE));
                self.lo = lo;
                self.span = hi.wrapping_sub(lo) as u32;
                for ch in 0..C {
                    let p = piece[ch];
                    let rise = p
                        .mhp
                        .wrapping_mul(i64::from(lo.wrapping_sub(s)))
                        .wrapping_add(1 << (COVER_BITS - 1))
                        >> COVER_BITS;
                    self.col[ch] =
                        p.a.wrapping_add(rise as i32)
                            .wrapping_add(p.m.wrapping_mul(d.wrapping_sub(lo)))
                            .wrapping_add(bias);
                    self.m[ch] = p.m;
                    self.jm[ch] = p.m.wrapping_mul(self.j);
                }
            }
            // A pad: one colour out to the region's end.
            _ => {
                self.lo = start.unwrap_or(i32::MIN);
                self.span = end.wrapping_sub(self.lo) as u32;
                for ch in 0..C {
                    self.col[ch] = piece[ch].a.wrapping_add(bias);
                    self.m[ch] = 0;
                    self.jm[ch] = 0;
                }
            }
        }
    }
}

/// A run painted with a radial gradient: the distance tracked pixel by
/// pixel, the colour stepped with it.
#[inline(never)]
fn radial<const C: usize, A: Apply<C>>(
    px: &mut [i32],
    x: i32,
    y: i32,
    ramp: &RadialRamp<C>,
    a: &A,
) {
    let mut t = Tracker::start(ramp, x, y, A::BIAS);
    let mut rest = px;
    loop {
        let Some((p, more)) = core::mem::take(&mut rest).split_first_chunk_mut::<C>() else {
            return;
        };
        a.apply(p, &t.col);
        if more.is_empty() {
            return;
        }
        rest = more;
        t.advance(ramp, A::BIAS);
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::FinePoint;
    use crate::style::{Offset, Stop};

    #[test]
    fn isqrt_is_the_floor_of_the_root() {
        for n in [
            0u64,
            1,
            2,
            3,
            4,
            15,
            16,
            17,
            99,
            1 << 32,
            (1 << 32) - 1,
            1 << 41,
            u64::MAX,
        ] {
            let r = u64::from(isqrt(n));
            assert!(r * r <= n, "{n}");
            assert!((r + 1).checked_mul(r + 1).is_none_or(|s| s > n), "{n}");
        }
    }

    /// A run's pixels, stepped, against each pixel set up on its own
    /// (a fresh integer square root): across the centre and far from it,
    /// from many starts. The ramp is steep enough in `D` (over 1000 units
    /// of 1/65536 level per unit) that any error of the tracked distance
    /// shows in the colour.
    #[test]
    fn tracked_distance_is_the_exact_integer_root() {
        let stops = [Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])];
        let mut seed = 0x1234_5678_9abc_def0u64;
        let mut rnd = |m: u64| {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (seed >> 33) % m
        };
        for _ in 0..300 {
            let c = FinePoint::new(
                rnd(200 * 1024) as i32 - 50 * 1024,
                rnd(200 * 1024) as i32 - 50 * 1024,
            );
            let g = Gradient::radial(c, (600 + rnd(300) as i32) * 1024, &stops).unwrap();
            let Ramp::Radial(ramp) = g.ramp else {
                panic!("radial")
            };
            // Every other row through the centre's pixel or next to it,
            // where D turns within a pixel.
            let y = if rnd(2) == 0 {
                (c.y >> 10) + rnd(3) as i32 - 1
            } else {
                rnd(300) as i32 - 100
            };
            let x0 = (c.x >> 10) - rnd(150) as i32;
            let mut run = [0i32; 300];
            radial::<1, _>(&mut run, x0, y, &ramp, &Store);
            for (x, &v) in (x0..).zip(&run) {
                let mut one = [0i32; 1];
                radial::<1, _>(&mut one, x, y, &ramp, &Store);
                assert_eq!(v, one[0], "x {x} y {y} centre {c:?}");
            }
        }
    }

    #[test]
    fn far_corners_of_the_range_do_not_overflow() {
        let stops = [Stop::lin(Offset::ZERO, [0]), Stop::lin(Offset::ONE, [4095])];
        let lim = crate::geom::FINE_LIMIT;
        let g = Gradient::radial(FinePoint::new(-lim, -lim), i32::MAX, &stops).unwrap();
        let Ramp::Radial(ramp) = g.ramp else {
            panic!("radial")
        };
        let mut run = [0i32; 200];
        radial::<1, _>(&mut run, 2048, 2048, &ramp, &Store);
        for (x, v) in (2048..).zip(run.chunks(1)) {
            let mut one = [0i32; 1];
            radial::<1, _>(&mut one, x, 2048, &ramp, &Store);
            assert_eq!(v, one);
        }
    }
}
