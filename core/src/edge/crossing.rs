//! The spill of a minor-axis crossing, tracked by differences: exact, and
//! with additions and compares only once set up.
//!
//! Where an edge crosses a boundary of the minor axis inside a major
//! column, the main term `S = v(u_c) - b` (seed 001's single formula) gives
//! the wrong pixel a triangle of area `k x² / 2`: `k = dv / du` the slope
//! and `x` the distance, along the major axis, from the crossing to the
//! column's near boundary (its left one when the crossing lies in the
//! column's left half, where the centre is already past it; its right one
//! otherwise). The exact mode moves that triangle to its pixel.
//!
//! ```text
//!      column a
//!   +-----------+ row b - 1
//!   |        __/|          crossing of v = m N at u*, x = u* - a N
//!   +-----*-----+ -- v = m N (boundary m)
//!   |  __/  .   |  row b = m: the centre u_c is past the crossing, so the
//!   |_/     .   |  main term of row m counts -k x²/2 left of u*: the spill
//!   +-----------+  L = k x² / 2 is taken from row m - 1 and given to row m
//! ```
//!
//! Write the crossing's position as `xi = x dv` (an integer: `u* dv` is
//! one, `u* = u0 + (m N - v0) du / dv`), so `0 <= xi < N dv`. In area units
//! (`AREA_ONE` per pixel, `N` fine units per pixel) the left spill is
//! `L = xi² / D` and the right one `R = (N dv - xi)² / D`, with
//! `D = Z du dv`, `Z = 2 N² / AREA_ONE`. From one boundary to the next the
//! crossing moves by `N du / dv` columns' worth: `xi += d1`
//! (`d1 = N (du mod dv)`) and, when that passes `N dv`, `xi -= N dv`
//! (one column more). So `xi` takes one of two steps, `d1` or
//! `d2 = d1 - N dv`, and the next spill is
//!
//! ```text
//!   L' = (xi + d)² / D = L + (2 xi d + d²) / D
//! ```
//!
//! The two possible increments, `A = (2 xi d1 + d1²) / D` and
//! `B = (2 xi d2 + d2²) / D`, are linear in `xi`, so they step by
//! constants too:
//!
//! ```text
//!   no wrap:  L += A;  A += K1;  B += K2      K1 = 2 d1² / D
//!   wrap:     L += B;  A += K2;  B += K3      K2 = 2 d1 d2 / D
//!                                             K3 = 2 d2² / D
//! ```
//!
//! and the right spill is `R = L + B - A + m1` (`m1 = 2 d1 N dv / D`).
//! Every value is an exact rational over the one denominator `D`, kept as
//! quotient and remainder ([`Qr`]), so the state at any crossing is the
//! exact floor of the true spill, equal to a direct evaluation: bands and
//! partial redraws that start the walk anywhere get the same bits.
//!
//! ## Ranges
//!
//! Fine coordinates are within `±2^21`, so `du, dv <= 2^22`, `N dv <= 2^32`,
//! `D <= 2^49`: remainders (`u64`, below `D`) and their sums of two stay
//! below `2^50`. The quotients are areas of at most a pixel or small
//! multiples (`L, R <= (N dv)² / D <= N² / Z = 2^15`, `|A|, |B|, |K| <=
//! 2^18`): `i32`. Set-up divides in `u64` with numerators below `2^64`
//! (stated at each), once per edge (the constants) and once per walk that
//! starts at a crossing without a stepped state (the state); stepping adds.
//!
//! The spill `k x² / 2` depends on the slope alone, so the constants are
//! made for the extents divided by their common power of two (`du / 2^t`,
//! `dv / 2^t`, and `xi / 2^t`, which is a multiple of it): the same
//! floors over a smaller `D`. When `D < 2^31` ([`Tracker::Narrow`]: every
//! edge of up to 8 px on the fine grid, every edge between whole or half
//! pixels (`t >= 9`: `du, dv <= 2^13` after it), and between 1/16-px
//! points those of up to 512 px) the remainders are `u32`, and a step is 32-bit
//! additions and compares only (on the Cortex-M0 about half the
//! instructions of the `u64` ones).
//!
//! A walk that needs fewer crossings (up to the walk's `DIRECT` of them:
//! the rest of a shorter edge, or a band's worth of one that is dropped
//! after its band) takes them one at a time instead ([`Direct`]): `xi`
//! stepped as above (`d1`, one column more past `N dv`), the spill `x² /
//! D` at each a product by `D`'s inverse and one correction
//! ([`div_by_inverse`], where `x² < 2^32` and `D < 2^32`, else a
//! division), no constants set up. The same floors.

use super::canon::{Canon, N};
use crate::arith::{div_by_inverse, divmod_small, inverse, mul_wide, udivmod};
use crate::geom::FINE_BITS;
use crate::COVER_BITS as AREA_BITS;

/// `log2(Z)`, `Z = 2 N² / AREA_ONE`: the spill's denominator is `Z du dv`.
pub(crate) const Z_BITS: u32 = 2 * FINE_BITS + 1 - AREA_BITS;
const _: () = assert!(2 * FINE_BITS + 1 > AREA_BITS);
/// `N² / Z`, `N / Z` and `2 N / Z`, the factors the set-up numerators
/// reduce to.
const N2_OVER_Z: u64 = 1 << (2 * FINE_BITS - Z_BITS);
const N_OVER_Z: u64 = 1 << (FINE_BITS - Z_BITS);
const TWO_N_OVER_Z: u64 = 2 * N_OVER_Z;

/// The integer type of the remainders: `u64` in general, `u32` for the
/// edges whose denominator `D` is below `2^31` (every sum of two
/// remainders below `2^32`), which step in half the instructions on the
/// Cortex-M0 and keep half the bytes.
pub(crate) trait Rem: Copy + PartialOrd + core::fmt::Debug + Default {
    /// `self + o`, wrapping (a sum of two remainders never wraps: both
    /// are below `D` and `2 D` fits; a difference that wrapped comes back).
    fn plus(self, o: Self) -> Self;
    /// `self - o`, wrapping.
    fn minus(self, o: Self) -> Self;
    /// `2 self` (below the type's range by the same bound).
    fn twice(self) -> Self;
    /// `v` in this type (`v` within its range: the caller checks).
    fn of_u64(v: u64) -> Self;
    /// The value as a `u64`.
    fn to_u64(self) -> u64;
}

impl Rem for u64 {
    #[inline(always)]
    fn plus(self, o: Self) -> Self {
        self.wrapping_add(o)
    }
    #[inline(always)]
    fn minus(self, o: Self) -> Self {
        self.wrapping_sub(o)
    }
    #[inline(always)]
    fn twice(self) -> Self {
        2 * self
    }
    #[inline(always)]
    fn of_u64(v: u64) -> Self {
        v
    }
    #[inline(always)]
    fn to_u64(self) -> u64 {
        self
    }
}

impl Rem for u32 {
    #[inline(always)]
    fn plus(self, o: Self) -> Self {
        self.wrapping_add(o)
    }
    #[inline(always)]
    fn minus(self, o: Self) -> Self {
        self.wrapping_sub(o)
    }
    #[inline(always)]
    fn twice(self) -> Self {
        self.wrapping_mul(2)
    }
    #[inline(always)]
    fn of_u64(v: u64) -> Self {
        v as u32
    }
    #[inline(always)]
    fn to_u64(self) -> u64 {
        u64::from(self)
    }
}

/// Below this `D` the tracker's remainders are `u32` (`2 D < 2^32`).
const NARROW_D: u64 = 1 << 31;

/// An exact rational `q + r / d` over a denominator `d` kept elsewhere,
/// with `0 <= r < d`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Qr<R = u64> {
    pub q: i32,
    pub r: R,
}

impl Qr {
    /// `num / den` for `den > 0`, the remainder scaled by `2^shift` so that
    /// it counts `1 / (den 2^shift)` (set-up only).
    fn of(num: u64, den: u64, shift: u32) -> Self {
        let (q, r) = udivmod(num, den);
        Self {
            q: q as i32,
            r: r << shift,
        }
    }

    /// `num / du` for `du > 0`, the remainder scaled by `Z dv`, so that it
    /// counts `1 / D` (set-up only; `du, dv <= 2^22`).
    fn over_du(num: u64, du: u64, dv: u32) -> Self {
        let (q, r) = udivmod(num, du);
        Self {
            q: q as i32,
            r: mul_wide(r as u32, dv) << Z_BITS,
        }
    }

    /// The same value with the remainder in `R` (below `D`, which the
    /// caller has checked fits).
    fn narrow<R: Rem>(self) -> Qr<R> {
        Qr {
            q: self.q,
            r: R::of_u64(self.r),
        }
    }
}

impl<R: Rem> Qr<R> {
    /// The same value with a `u64` remainder.
    fn wide(self) -> Qr {
        Qr {
            q: self.q,
            r: self.r.to_u64(),
        }
    }

    #[inline]
    fn add(self, o: Self, d: R) -> Self {
        let (mut q, mut r) = (self.q.wrapping_add(o.q), self.r.plus(o.r));
        if r >= d {
            r = r.minus(d);
            q = q.wrapping_add(1);
        }
        Self { q, r }
    }

    #[inline]
    fn sub(self, o: Self, d: R) -> Self {
        let (mut q, mut r) = (self.q.wrapping_sub(o.q), self.r.minus(o.r));
        if self.r < o.r {
            r = r.plus(d);
            q = q.wrapping_sub(1);
        }
        Self { q, r }
    }
}

/// The per-edge constants of the crossing walk (set-up: once per edge,
/// when its walk first reaches an interior crossing).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossings<R = u64> {
    /// `log2` of the power of two the extents were divided by: the
    /// constants below are those of `du / 2^t`, `dv / 2^t` (the same
    /// slope, so the same spills, over a smaller denominator), and a
    /// crossing's `xi` is divided by it too.
    t: u32,
    /// `D = Z du dv`.
    d: R,
    /// `N dv`: the range of `xi`.
    ndv: R,
    /// `xi`'s step without wrap, `d1 = N (du mod dv)`.
    d1: R,
    /// The crossing's column step without wrap, `floor(du / dv)`.
    cols: i32,
    k1: Qr<R>,
    k2: Qr<R>,
    k3: Qr<R>,
    /// `m1 = 2 d1 N dv / D` and `cr = (N dv)² / D`, for the right spill and
    /// the direct evaluation.
    m1: Qr<R>,
    cr: Qr<R>,
}

/// The next crossing of a walk: boundary `v = m N` at canonical column
/// `col`, with its exact spill state.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossing<R = u64> {
    xi: R,
    l: Qr<R>,
    a: Qr<R>,
    b: Qr<R>,
    /// Boundary index: the crossing of `v = m N`.
    pub m: i32,
    /// Canonical major column holding it.
    pub col: i32,
}

/// The crossing constants of an edge, in the narrowest remainders that
/// hold them.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Tracker {
    Wide(Crossings),
    /// `D < 2^31` (short edges, and long ones whose extents share a
    /// power of two: see the module's ranges).
    Narrow(Crossings<u32>),
}

impl Tracker {
    /// [`Crossings::new`], narrowed when `D` allows.
    pub(crate) fn new(du: i32, dv: i32) -> Option<Self> {
        let k = Crossings::new(du, dv)?;
        Some(if k.d < NARROW_D {
            Tracker::Narrow(k.narrow())
        } else {
            Tracker::Wide(k)
        })
    }
}

impl Crossings {
    /// The same constants with remainders in `R` (`D < 2^31` when `R` is
    /// `u32`: the caller checks; every value below is below `D` or `N dv
    /// < 2^23`).
    fn narrow<R: Rem>(&self) -> Crossings<R> {
        Crossings {
            t: self.t,
            d: R::of_u64(self.d),
            ndv: R::of_u64(self.ndv),
            d1: R::of_u64(self.d1),
            cols: self.cols,
            k1: self.k1.narrow(),
            k2: self.k2.narrow(),
            k3: self.k3.narrow(),
            m1: self.m1.narrow(),
            cr: self.cr.narrow(),
        }
    }

    /// Constants for a canonical edge with extents `du >= dv > 0` (fine
    /// units); `None` when `dv == 0` (no crossings).
    pub(crate) fn new(du: i32, dv: i32) -> Option<Self> {
        if dv <= 0 || du < dv {
            return None;
        }
        // The spill `x² dv / (Z du)` depends on the slope alone: the
        // common power of two of the extents is taken out (vertices on
        // whole pixels share 2^10), which keeps the divisions below, the
        // direct evaluations and the stepped remainders in fewer bits.
        let t = (du | dv).trailing_zeros();
        let (du, dv) = (du >> t, dv >> t);
        let (udu, udv) = (du as u64, dv as u64);
        let (cols, rho) = divmod_small(du as u32, dv as u32);
        let (cols, rho) = (u64::from(cols), u64::from(rho));
        let dudv = mul_wide(du as u32, dv as u32);
        let d = dudv << Z_BITS;
        // c1 = d1² / D = N² rho² / (Z du dv): numerator < 2^(15 + 44).
        let c1 = Qr::of(N2_OVER_Z * mul_wide(rho as u32, rho as u32), dudv, Z_BITS);
        // m1 = 2 d1 N dv / D = 2 N² rho / (Z du): numerator < 2^(16 + 22).
        let m1 = Qr::over_du(2 * N2_OVER_Z * rho, udu, dv as u32);
        // cr = (N dv)² / D = N² dv / (Z du): numerator < 2^(15 + 22).
        let cr = Qr::over_du(N2_OVER_Z * udv, udu, dv as u32);
        let k1 = c1.add(c1, d);
        let k2 = k1.sub(m1, d);
        let k3 = k2.sub(m1, d).add(cr, d).add(cr, d);
        Some(Self {
            t,
            d,
            ndv: u64::from(N as u32) * udv,
            d1: u64::from(N as u32) * rho,
            cols: cols as i32,
            k1,
            k2,
            k3,
            m1,
            cr,
        })
    }
}

impl<R: Rem> Crossings<R> {
    /// The crossing of boundary `v = m N` of edge `e` (whose extents these
    /// constants are made for), evaluated directly (set-up: four
    /// divisions, in `u64`).
    pub(crate) fn at(&self, e: &Canon, m: i32) -> Crossing<R> {
        let d = self.d.to_u64();
        let d1 = self.d1.to_u64();
        let (col, xi) = e.crossing(m);
        // `xi` is a multiple of 2^t (so are `du`, `dv` and the range
        // `N dv`): the crossing of the reduced extents.
        let xi = xi >> self.t;
        let (udu, udv) = ((e.du >> self.t) as u64, (e.dv >> self.t) as u32);
        let rho = (d1 >> FINE_BITS) as u32;
        // L = xi² / D: xi < 2^32, so xi² < 2^64.
        let l = Qr::of(mul_wide(xi as u32, xi as u32), d, 0);
        // A = d1 (2 xi + d1) / D = N rho (2 xi + N rho) / (Z du dv):
        // numerator 2^5 rho (2 xi + d1) < 2^(5 + 22 + 34).
        let num = 2 * mul_wide(rho, xi as u32) + mul_wide(rho, d1 as u32);
        let a = Qr::of(N_OVER_Z * num, d >> Z_BITS, Z_BITS);
        // M = 2 xi N dv / D = 2 N xi / (Z du): numerator < 2^(6 + 32).
        let mm = Qr::over_du(TWO_N_OVER_Z * xi, udu, udv);
        // B = (2 xi d2 + d2²) / D = A - M - m1 + cr.
        let b = a.sub(mm, d).sub(self.m1.wide(), d).add(self.cr.wide(), d);
        Crossing {
            xi: R::of_u64(xi),
            l: l.narrow(),
            a: a.narrow(),
            b: b.narrow(),
            m,
            col,
        }
    }
}

impl<R: Rem> Crossing<R> {
    /// True when the crossing lies in the left half of its column (or on
    /// its centre): the centre is past it, the spill is the left triangle.
    #[inline]
    pub(crate) fn is_left(&self, k: &Crossings<R>) -> bool {
        self.xi.twice() <= k.ndv
    }

    /// The spill, in area units: the floor of the exact triangle.
    #[inline]
    pub(crate) fn spill(&self, k: &Crossings<R>) -> i32 {
        if self.is_left(k) {
            self.l.q
        } else {
            self.l.add(self.b, k.d).sub(self.a, k.d).add(k.m1, k.d).q
        }
    }

    /// On to the next boundary, `m + 1`: additions and compares.
    #[inline]
    pub(crate) fn advance(&mut self, k: &Crossings<R>) {
        self.xi = self.xi.plus(k.d1);
        self.col += k.cols;
        self.m += 1;
        if self.xi >= k.ndv {
            self.xi = self.xi.minus(k.ndv);
            self.col += 1;
            self.l = self.l.add(self.b, k.d);
            self.a = self.a.add(k.k2, k.d);
            self.b = self.b.add(k.k3, k.d);
        } else {
            self.l = self.l.add(self.a, k.d);
            self.a = self.a.add(k.k1, k.d);
            self.b = self.b.add(k.k2, k.d);
        }
    }
}

/// A walk's crossings one at a time, without the stepping constants of
/// [`Crossings`]: the first found directly (two divisions, and `D`'s
/// inverse), each next one stepped from it (`xi += d1`, one column more
/// when that passes `N dv`); each spill `x² / D` is a product by the
/// inverse and a correction. Cheaper than the tracker's set-up (eight
/// divisions and the `u64` products of its constants) for a walk that
/// needs up to some hundred crossings, about as cheap a crossing; the
/// same floors (both are `x² / D` exactly).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Direct {
    /// Boundary index and the canonical column holding its crossing.
    pub m: i32,
    pub col: i32,
    /// The spill, in area units: the floor of the exact triangle.
    pub spill: i32,
    /// Whether the crossing lies right of the column centre (the line
    /// leaves the row there).
    pub down: bool,
    /// `xi`, `d1 = N (du mod dv)`, `N dv` and `D`, of the extents over
    /// their common power of two (as in [`Crossings`]); the column step
    /// `floor(du / dv)`. `N dv < 2^32` after the reduction (`dv = 2^22`
    /// only when `du = dv`, which reduces to 1), so `xi` and `d1`, below
    /// it, are `u32` too.
    xi: u32,
    d1: u32,
    ndv: u32,
    d: u64,
    cols: i32,
    /// `inverse(D)`, made at the first crossing whose spill takes it (0
    /// before; and for good when `D >= 2^32`, whose spills are divided).
    inv: u32,
}

impl Direct {
    /// The crossing of boundary `v = m N` of `e` (`v0 < m N <= v1`:
    /// `dv > 0`).
    pub(crate) fn at(e: &Canon, m: i32) -> Self {
        let (col, xi) = e.crossing(m);
        let t = (e.du | e.dv).trailing_zeros();
        let (du, dv) = ((e.du >> t) as u32, (e.dv >> t) as u32);
        // du >= dv > 0, both below 2^23: a column step below 3 (slopes
        // over a third) without a division.
        let (cols, rho) = divmod_small(du, dv);
        let mut x = Self {
            m,
            col,
            spill: 0,
            down: false,
            xi: (xi >> t) as u32,
            d1: (N as u32).wrapping_mul(rho),
            ndv: (N as u32).wrapping_mul(dv),
            d: mul_wide(du, dv) << Z_BITS,
            cols: cols as i32,
            inv: 0,
        };
        // The inverse is made here: nine walks in ten step on to a next
        // crossing, which needs it.
        x.evaluate();
        x
    }

    /// `x` for the crossing at `xi`: `xi` or `N dv - xi`, whichever is at
    /// most `N dv / 2`; sets `down` (the second: the crossing lies right
    /// of the column centre).
    #[inline(always)]
    fn near(&mut self) -> u32 {
        let rest = self.ndv - self.xi;
        let left = self.xi <= rest;
        self.down = !left;
        if left {
            self.xi
        } else {
            rest
        }
    }

    /// The spill of the crossing, `x² / D`: where both fit 32 bits
    /// (`x < 2^16`), one 32-bit product and a division by `D`'s inverse
    /// (made at the first crossing that needs it), else the 64-bit product
    /// divided.
    #[inline(always)]
    fn evaluate(&mut self) {
        let x = self.near();
        self.spill = match u32::try_from(self.d) {
            Ok(d) if x < 1 << 16 => {
                if self.inv == 0 {
                    self.inv = inverse(d);
                }
                div_by_inverse(x * x, d, self.inv) as i32
            }
            _ => udivmod(mul_wide(x, x), self.d).0 as i32,
        };
    }

    /// On to boundary `m + 1`: `xi + d1`, past `N dv` into the next column
    /// (compared before adding: the sum may pass `2^32`).
    #[inline]
    pub(crate) fn advance(&mut self) {
        self.m += 1;
        self.col += self.cols;
        let room = self.ndv - self.d1;
        if self.xi >= room {
            self.xi -= room;
            self.col += 1;
        } else {
            self.xi += self.d1;
        }
        self.evaluate();
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::geom::FinePoint;

    /// The exact spill of boundary `m`, from the definition, in `i128`.
    fn exact(e: &Canon, m: i32) -> (i64, i64, bool) {
        let (u0, v0, du, dv) = (
            i128::from(e.u0),
            i128::from(e.v0),
            i128::from(e.du),
            i128::from(e.dv),
        );
        let n = 1i128 << FINE_BITS;
        let t = u0 * dv + (i128::from(m) * n - v0) * du;
        let ndv = n * dv;
        let col = t.div_euclid(ndv);
        let xi = t - col * ndv;
        let d = (du * dv) << Z_BITS;
        let left = 2 * xi <= ndv;
        let x = if left { xi } else { ndv - xi };
        ((x * x).div_euclid(d) as i64, col as i64, left)
    }

    #[test]
    fn stepped_spill_equals_the_direct_floor_at_every_crossing() {
        // A few slopes, from nearly flat to 45°, long and short, odd
        // positions; every crossing of each compared with the definition.
        let cases = [
            (1_234_567, -333_333, 3_000_000, 7),
            (5, 100, 100_000, 99_999),
            (-77_777, 12_345, 65_432, 65_432),
            (-2_097_152, -2_097_151, 4_194_304, 4_194_303),
            (-2_097_152, 1_000_000, 4_194_304, 1_000_003),
            (0, 1000, 2_000_000, 3_000),
            (-2_097_152, -2_097_152, 4_194_304, 4_194_304),
            // Extents with a common power of two (whole pixels, 1/16 px,
            // 2^21), on and off the same grid: the reduced constants.
            (3 * 1024, 5 * 1024 + 512, 75 * 1024, 33 * 1024),
            (64 * 7, -64 * 3, 64 * 1000, 64 * 999),
            (5, 7, 4096, 2048),
            (-1_000_001, 3, 1 << 21, 3 << 19),
            (0, 0, 240 * 1024, 239 * 1024),
            // Short edges on the fine grid (`u32` remainders), the
            // largest `D` that narrows and the smallest that does not.
            (123, 456, 7_777, 5_555),
            (1, 0, 11_585, 5_792),
            (1, 0, 11_587, 5_793),
        ];
        let mut narrowed = 0;
        for (u0, v0, du, dv) in cases {
            let e = Canon::new(FinePoint::new(u0, v0), FinePoint::new(u0 + du, v0 + dv)).unwrap();
            assert!(!e.transposed && !e.mirrored);
            let k = Crossings::new(du, dv).unwrap();
            check_every_crossing(&e, &k);
            // The tracker the walk uses: narrowed exactly when `D` fits.
            match Tracker::new(du, dv).unwrap() {
                Tracker::Narrow(kn) => {
                    assert!(k.d < NARROW_D);
                    check_every_crossing(&e, &kn);
                    narrowed += 1;
                }
                Tracker::Wide(_) => assert!(k.d >= NARROW_D),
            }
        }
        assert_eq!(narrowed, 10, "the cases narrow as planned");
    }

    /// The first and last minor boundaries strictly inside `e` (none when
    /// `first > last`).
    fn inner_boundaries(e: &Canon) -> (i32, i32) {
        let n = 1i32 << FINE_BITS;
        (e.v0.div_euclid(n) + 1, (e.v1 - 1).div_euclid(n))
    }

    fn check_every_crossing<R: Rem + PartialEq>(e: &Canon, k: &Crossings<R>) {
        let (first, last) = inner_boundaries(e);
        let mut c = k.at(e, first);
        // The crossings stepped without the constants, from the first.
        let mut x = Direct::at(e, first);
        for m in first..=last.min(first + 5000) {
            let (spill, col, left) = exact(e, m);
            assert_eq!(c.m, m);
            assert_eq!(i64::from(c.col), col, "column of crossing {m}");
            assert_eq!(c.is_left(k), left);
            assert_eq!(i64::from(c.spill(k)), spill, "spill of crossing {m}");
            // A direct start anywhere agrees with the stepped state.
            let d = k.at(e, m);
            assert!((d.xi, d.l, d.a, d.b) == (c.xi, c.l, c.a, c.b));
            c.advance(k);
            // And so do the crossings stepped one at a time, started
            // anywhere or from the first.
            for y in [&x, &Direct::at(e, m)] {
                assert_eq!((y.m, i64::from(y.col)), (m, col), "direct crossing {m}");
                assert_eq!(
                    (i64::from(y.spill), y.down),
                    (spill, !left),
                    "direct spill {m}"
                );
            }
            x.advance();
        }
    }

    #[test]
    fn direct_crossings_agree_with_the_definition_on_random_edges() {
        // Random x-major edges whose reduced `D` lies on either side of
        // 2^32 and whose `x` reaches either side of 2^16: the spill by the
        // inverse, by the 64-bit division, and the switch between them,
        // each crossing against the definition, stepped from the first.
        let mut rng = crate::path::testing::Lcg(0xd12e_c7ed);
        let (mut fast, mut wide) = (0, 0);
        for _ in 0..3000 {
            let bits = 8 + rng.below(15);
            let du = 1 + rng.below(1 << bits) as i32;
            let dv = 1 + rng.below(du as u64) as i32;
            let u0 = rng.below(1 << 21) as i32 - (1 << 20);
            let v0 = rng.below(1 << 21) as i32 - (1 << 20);
            let Some(e) = Canon::new(FinePoint::new(u0, v0), FinePoint::new(u0 + du, v0 + dv))
            else {
                continue;
            };
            let (first, last) = inner_boundaries(&e);
            if first > last {
                continue;
            }
            let mut x = Direct::at(&e, first);
            for m in first..=last.min(first + 300) {
                let (spill, col, left) = exact(&e, m);
                assert_eq!((x.m, i64::from(x.col)), (m, col), "{e:?} crossing {m}");
                assert_eq!(
                    (i64::from(x.spill), x.down),
                    (spill, !left),
                    "{e:?} spill {m}"
                );
                x.advance();
            }
            if x.inv != 0 {
                fast += 1;
            } else if x.d > u64::from(u32::MAX) {
                wide += 1;
            }
        }
        assert!(
            fast > 200 && wide > 200,
            "{fast} edges by the inverse, {wide} in 64 bits"
        );
    }

    #[test]
    fn the_spill_never_exceeds_half_a_column_at_45_degrees() {
        let e = Canon::new(
            FinePoint::new(0, 512),
            FinePoint::new(1 << 20, 512 + (1 << 20)),
        )
        .unwrap();
        let k = Crossings::new(1 << 20, 1 << 20).unwrap();
        let c = k.at(&e, 1);
        // At 45° through (0, 1/2 px) every crossing is on a column centre:
        // k x² / 2 = 1/8 px.
        assert_eq!(c.spill(&k), 1 << (AREA_BITS - 3));
    }
}
