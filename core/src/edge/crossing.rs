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
//! crossing moves by `N du / dv` columns' worth: `xi += delta`
//! (`delta = N (du mod dv)`) and, when that passes `N dv`, `xi -= N dv`
//! (one column more). So `xi` takes one of two steps, `d1 = delta` or
//! `d2 = delta - N dv`, and
//!
//! ```text
//!   L' = (xi + d)² / D = L + 2 xi d / D + d² / D
//! ```
//!
//! needs `2 xi d1 / D = J` and `2 xi d2 / D = J - M` with `M = 2 xi N dv / D`,
//! themselves linear in `xi`: every increment is one of a handful of
//! constants, all exact rationals over the one denominator `D`, kept as
//! quotient and remainder ([`Qr`]). The right spill is `R = C_R - M + L`
//! with `C_R = (N dv)² / D`. The state at any crossing is therefore the
//! exact floor of the true spill, equal to a direct evaluation: bands and
//! partial redraws that start the walk anywhere get the same bits.
//!
//! ## Ranges
//!
//! Fine coordinates are within `±2^21`, so `du, dv <= 2^22`, `N dv <= 2^32`,
//! `D <= 2^49`: remainders and their sums of three stay below `2^51` in
//! `i64`. The quotients are areas below one pixel, `L, R <= C_R <= N² / Z`
//! (`2^15`), and the trackers `J, M <= 2 C_R`. Set-up divides in `u64`
//! with numerators below `2^64` (stated at each); stepping adds.

use crate::geom::FINE_BITS;
use crate::COVER_BITS as AREA_BITS;

/// `log2(Z)`, `Z = 2 N² / AREA_ONE`: the spill's denominator is `Z du dv`.
const Z_BITS: u32 = 2 * FINE_BITS + 1 - AREA_BITS;
const _: () = assert!(2 * FINE_BITS + 1 > AREA_BITS);

/// An exact rational `q + r / d` over a denominator `d` kept elsewhere,
/// with `0 <= r < d`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub(crate) struct Qr {
    pub q: i64,
    pub r: i64,
}

impl Qr {
    /// `num / den` for `num >= 0`, `den > 0`, the remainder scaled by
    /// `scale` so that it counts `1 / (den * scale)` (set-up only).
    fn of(num: u64, den: u64, scale: u64) -> Self {
        let (q, r) = crate::arith::udivmod(num, den);
        Self {
            q: q as i64,
            r: r.saturating_mul(scale) as i64,
        }
    }

    #[inline]
    fn add(self, o: Self, d: i64) -> Self {
        let (mut q, mut r) = (self.q + o.q, self.r + o.r);
        if r >= d {
            r -= d;
            q += 1;
        }
        Self { q, r }
    }

    #[inline]
    fn sub(self, o: Self, d: i64) -> Self {
        let (mut q, mut r) = (self.q - o.q, self.r - o.r);
        if r < 0 {
            r += d;
            q -= 1;
        }
        Self { q, r }
    }

    fn double(self, d: i64) -> Self {
        self.add(self, d)
    }
}

/// The per-edge constants of the crossing walk (set-up: one per edge).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossings {
    /// `D = Z du dv`.
    d: i64,
    /// `N dv`: the range of `xi`.
    ndv: i64,
    /// `xi`'s step without wrap, `N (du mod dv)`.
    delta: i64,
    /// The crossing's column step without wrap, `floor(du / dv)`.
    cols: i32,
    /// `d1² / D`, `2 d1 N dv / D`, `(N dv)² / D`, and what follows from
    /// them: `j1 = 2 c1`, `j2 = j1 - m1`, `c2 = c1 - m1 + cr`,
    /// `m2 = m1 - 2 cr`.
    c1: Qr,
    c2: Qr,
    j1: Qr,
    j2: Qr,
    m1: Qr,
    m2: Qr,
    cr: Qr,
    /// Canonical geometry the direct evaluation needs.
    u0: i64,
    v0: i64,
    du: i64,
    dv: i64,
}

/// The next crossing of a walk: boundary `v = m N` at canonical column
/// `col`, with its exact spill state.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Crossing {
    /// Boundary index: the crossing of `v = m N`.
    pub m: i32,
    /// Canonical major column holding it.
    pub col: i32,
    xi: i64,
    l: Qr,
    j: Qr,
    mm: Qr,
}

impl Crossings {
    /// Constants for the canonical edge `(u0, v0)` with extents `du >= dv
    /// > 0` (fine units); `None` when `dv == 0` (no crossings).
    pub(crate) fn new(u0: i64, v0: i64, du: i64, dv: i64) -> Option<Self> {
        if dv <= 0 || du < dv {
            return None;
        }
        let n = 1i64 << FINE_BITS;
        let (udu, udv) = (du as u64, dv as u64);
        let (cols, rho) = crate::arith::divmod_floor(du, dv);
        let d = (du * dv) << Z_BITS;
        // c1 = d1² / D = N² rho² / (Z du dv): numerator < 2^(20 + 44 - 5).
        let n2_over_z = 1u64 << (2 * FINE_BITS - Z_BITS);
        let z = 1u64 << Z_BITS;
        let c1 = Qr::of(n2_over_z * (rho as u64) * (rho as u64), udu * udv, z);
        // m1 = 2 d1 N dv / D = 2 N² rho / (Z du): numerator < 2^(21 + 22 - 5).
        let m1 = Qr::of(2 * n2_over_z * rho as u64, udu, z * udv);
        // cr = (N dv)² / D = N² dv / (Z du).
        let cr = Qr::of(n2_over_z * udv, udu, z * udv);
        let j1 = c1.double(d);
        Some(Self {
            d,
            ndv: n * dv,
            delta: n * rho,
            cols: cols as i32,
            c1,
            c2: c1.sub(m1, d).add(cr, d),
            j1,
            j2: j1.sub(m1, d),
            m1,
            m2: m1.sub(cr.double(d), d),
            cr,
            u0,
            v0,
            du,
            dv,
        })
    }

    /// The crossing of boundary `v = m N`, evaluated directly (set-up: a
    /// few divisions).
    pub(crate) fn at(&self, m: i32) -> Crossing {
        let n = 1i64 << FINE_BITS;
        // u* dv = u0 dv + (m N - v0) du: below 2^45 in magnitude.
        let t = self.u0 * self.dv + (i64::from(m) * n - self.v0) * self.du;
        let (col, xi) = crate::arith::divmod_floor(t, self.ndv);
        let (uxi, udu, udv) = (xi as u64, self.du as u64, self.dv as u64);
        let z = 1u64 << Z_BITS;
        let rho = (self.delta >> FINE_BITS) as u64;
        // L = xi² / D: xi < 2^32, so xi² < 2^64 (u64).
        let l = Qr::of(uxi * uxi, self.d as u64, 1);
        // J = 2 xi d1 / D = 2 N xi rho / (Z du dv): numerator < 2^(11 + 32 + 22 - 5).
        let two_n_over_z = 1u64 << (FINE_BITS + 1 - Z_BITS);
        let j = Qr::of(two_n_over_z * uxi * rho, udu * udv, z);
        // M = 2 xi N dv / D = 2 N xi / (Z du).
        let mm = Qr::of(two_n_over_z * uxi, udu, z * udv);
        Crossing {
            m,
            col: col as i32,
            xi,
            l,
            j,
            mm,
        }
    }
}

impl Crossing {
    /// True when the crossing lies in the left half of its column (or on
    /// its centre): the centre is past it, the spill is the left triangle.
    #[inline]
    pub(crate) fn is_left(&self, k: &Crossings) -> bool {
        2 * self.xi <= k.ndv
    }

    /// The spill, in area units: the floor of the exact triangle.
    #[inline]
    pub(crate) fn spill(&self, k: &Crossings) -> i32 {
        if self.is_left(k) {
            self.l.q as i32
        } else {
            k.cr.sub(self.mm, k.d).add(self.l, k.d).q as i32
        }
    }

    /// On to the next boundary, `m + 1`: additions and compares.
    #[inline]
    pub(crate) fn advance(&mut self, k: &Crossings) {
        self.xi += k.delta;
        self.col += k.cols;
        self.m += 1;
        if self.xi >= k.ndv {
            self.xi -= k.ndv;
            self.col += 1;
            self.l = self.l.add(self.j, k.d).sub(self.mm, k.d).add(k.c2, k.d);
            self.j = self.j.add(k.j2, k.d);
            self.mm = self.mm.add(k.m2, k.d);
        } else {
            self.l = self.l.add(self.j, k.d).add(k.c1, k.d);
            self.j = self.j.add(k.j1, k.d);
            self.mm = self.mm.add(k.m1, k.d);
        }
    }
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;

    /// The exact spill of boundary `m`, from the definition, in `i128`.
    fn exact(u0: i64, v0: i64, du: i64, dv: i64, m: i32) -> (i64, i64, bool) {
        let n = 1i128 << FINE_BITS;
        let t =
            i128::from(u0) * i128::from(dv) + (i128::from(m) * n - i128::from(v0)) * i128::from(du);
        let ndv = n * i128::from(dv);
        let col = t.div_euclid(ndv);
        let xi = t - col * ndv;
        let d = (i128::from(du) * i128::from(dv)) << Z_BITS;
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
            (1, 1, 4_194_304, 4_194_303),
            (-2_097_152, 2_097_151, 4_194_304, 1_000_003),
            (0, 1000, 2_000_000, 3_000),
        ];
        for (u0, v0, du, dv) in cases {
            let k = Crossings::new(u0, v0, du, dv).unwrap();
            let n = 1i64 << FINE_BITS;
            let first = (v0.div_euclid(n) + 1) as i32;
            let last = ((v0 + dv - 1).div_euclid(n)) as i32;
            let mut c = k.at(first);
            for m in first..=last.min(first + 5000) {
                let (spill, col, left) = exact(u0, v0, du, dv, m);
                assert_eq!(c.m, m);
                assert_eq!(i64::from(c.col), col, "column of crossing {m}");
                assert_eq!(c.is_left(&k), left);
                assert_eq!(i64::from(c.spill(&k)), spill, "spill of crossing {m}");
                // A direct start anywhere agrees with the stepped state.
                let d = k.at(m);
                assert_eq!((d.xi, d.l, d.j, d.mm), (c.xi, c.l, c.j, c.mm));
                c.advance(&k);
            }
        }
    }

    #[test]
    fn the_spill_never_exceeds_half_a_column_at_45_degrees() {
        let k = Crossings::new(0, 512, 1 << 20, 1 << 20).unwrap();
        let c = k.at(1);
        // At 45° through (0, 1/2 px) every crossing is on a column centre:
        // k x² / 2 = 1/8 px.
        assert_eq!(c.spill(&k), 1 << (AREA_BITS - 3));
    }
}
