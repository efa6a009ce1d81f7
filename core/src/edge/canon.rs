//! Set-up: the canonical (first-octant) frame of an edge, by the rule of
//! duality of seed 001. No per-pixel work here.
//!
//! Coordinates are `i32`: fine coordinates lie within `±2^21`, so extents
//! are at most `2^22` and every position below (a column or row times `N`,
//! a vertex coordinate) stays within `±2^22`. Products of a position and an
//! extent (up to `2^44`) are formed in `i64`, and the divisions that find a
//! cell are made relative to the nearer end point of the edge, so that
//! near the ends (where set-up asks) the quotient is small and the
//! division short.

use crate::arith::{divmod_floor, imul_wide, mul_wide, udivmod};
use crate::geom::{FinePoint, FINE_BITS, FINE_ONE};
use crate::{COVER_BITS, COVER_ONE};

/// `log2(H)`, `H = COVER_ONE / N`: coverage units per fine unit of height
/// across a whole column.
pub(crate) const H_BITS: u32 = COVER_BITS - FINE_BITS;

/// A point of an edge's line in coverage-height units, exactly: `H v =
/// vi + vr / du`, `0 <= vr < du`. `|H v| < 2^28` for `|v| <= 2^21 + N`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Lv {
    pub vi: i32,
    pub vr: i32,
}

impl Lv {
    /// The minor cell holding the point: `floor(v / N)`.
    #[inline]
    pub fn cell(self) -> i32 {
        self.vi >> COVER_BITS
    }

    /// The first minor boundary at or past the point: `ceil(v / N)`.
    #[inline]
    pub fn boundary_ceil(self) -> i32 {
        if self.vr == 0 {
            (self.vi + COVER_ONE - 1) >> COVER_BITS
        } else {
            (self.vi >> COVER_BITS) + 1
        }
    }

    /// The point `q + r / du` further on.
    #[inline]
    pub fn plus(self, (q, r): (i32, i32), du: i32) -> Self {
        let (mut vi, mut vr) = (self.vi + q, self.vr + r);
        if vr >= du {
            vr -= du;
            vi += 1;
        }
        Self { vi, vr }
    }

    /// The point `q + r / du` back.
    #[inline]
    pub fn minus(self, (q, r): (i32, i32), du: i32) -> Self {
        let (mut vi, mut vr) = (self.vi - q, self.vr - r);
        if vr < 0 {
            vr += du;
            vi -= 1;
        }
        Self { vi, vr }
    }
}

/// An edge in its canonical frame: `u` the major axis, `v` the minor axis,
/// `u0 < u1`, `v0 <= v1`, `dv <= du`, all in fine units (1/1024 px). With
/// fine coordinates within `±2^21`, extents are at most `2^22`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Canon {
    /// `u` is `y` (the edge is steeper than 45°).
    pub transposed: bool,
    /// The `x` axis is negated (the edge runs to the left going down).
    pub mirrored: bool,
    /// `+1` if the edge runs down in the caller's order, `-1` if up.
    pub dir: i8,
    pub u0: i32,
    pub v0: i32,
    pub u1: i32,
    pub v1: i32,
    pub du: i32,
    pub dv: i32,
}

/// One pixel in fine units.
pub(crate) const N: i32 = FINE_ONE;

/// `floor(v / N)`: an arithmetic shift.
#[inline]
pub(crate) fn cell_of(v: i32) -> i32 {
    v >> FINE_BITS
}

impl Canon {
    /// The canonical frame of the edge `p0 -> p1`; `None` for a horizontal
    /// edge (it cuts off no area in the row-wise model). Points within
    /// `±2^21` (the caller checks).
    pub fn new(p0: FinePoint, p1: FinePoint) -> Option<Self> {
        let (a, b, dir) = match p0.y.cmp(&p1.y) {
            core::cmp::Ordering::Less => (p0, p1, 1),
            core::cmp::Ordering::Greater => (p1, p0, -1),
            core::cmp::Ordering::Equal => return None,
        };
        let mirrored = b.x < a.x;
        let (ax, bx) = if mirrored { (-a.x, -b.x) } else { (a.x, b.x) };
        let transposed = bx - ax < b.y - a.y;
        let (u0, v0, u1, v1) = if transposed {
            (a.y, ax, b.y, bx)
        } else {
            (ax, a.y, bx, b.y)
        };
        Some(Self {
            transposed,
            mirrored,
            dir,
            u0,
            v0,
            u1,
            v1,
            du: u1 - u0,
            dv: v1 - v0,
        })
    }

    /// First and last major columns the edge touches.
    pub fn columns(&self) -> (i32, i32) {
        (cell_of(self.u0), cell_of(self.u1 + N - 1) - 1)
    }

    /// First and last minor rows the edge touches.
    pub fn rows(&self) -> (i32, i32) {
        (cell_of(self.v0), cell_of(self.v1 + N - 1) - 1)
    }

    /// The line's `v` at major position `u` (clamped into the edge: the
    /// line is extended flat beyond its end points), as an integer part
    /// and a remainder over `du`: `v = vi + vr / du`, `0 <= vr < du`.
    /// Evaluated from the nearer end point, so the division's quotient is
    /// at most half the edge's `dv`, and at most `dv * t / du` for a
    /// position `t` fine units from an end (set-up near the ends: short).
    pub fn v_at(&self, u: i32) -> (i32, i32) {
        // u0 < u1 always (du > 0): `min`/`max`, not `clamp`, which could
        // panic if they crossed.
        let u = u.min(self.u1).max(self.u0);
        let t = u - self.u0;
        let du = self.du as u64;
        if t == 0 {
            (self.v0, 0)
        } else if t <= self.du / 2 {
            // v = v0 + t dv / du; t dv <= 2^21 * 2^22.
            let (q, r) = udivmod(mul_wide(t as u32, self.dv as u32), du);
            (self.v0 + q as i32, r as i32)
        } else if u == self.u1 {
            (self.v1, 0)
        } else {
            // v = v1 - t' dv / du, t' = u1 - u.
            let (q, r) = udivmod(mul_wide((self.u1 - u) as u32, self.dv as u32), du);
            if r == 0 {
                (self.v1 - q as i32, 0)
            } else {
                (self.v1 - q as i32 - 1, (du - r) as i32)
            }
        }
    }

    /// The minor cell holding the (clamped) line at major position `u`.
    #[inline]
    pub fn cell_at(&self, u: i32) -> i32 {
        cell_of(self.v_at(u).0)
    }

    /// The line (not clamped: extended beyond the end points) at `u`
    /// within `N` of the start (`from_end` false) or of the end point, in
    /// coverage-height units (set-up: a quotient below `2^16`).
    pub fn line_near_end(&self, u: i32, from_end: bool) -> Lv {
        let du = i64::from(self.du);
        if from_end {
            // H v = H v1 - H t' dv / du, t' = u1 - u; |H t' dv| < 2^(6 + 11 + 22).
            let (q, r) = divmod_floor(imul_wide(self.u1 - u, self.dv) << H_BITS, du);
            let vi = (self.v1 << H_BITS) - q as i32;
            if r == 0 {
                Lv { vi, vr: 0 }
            } else {
                Lv {
                    vi: vi - 1,
                    vr: (du - r) as i32,
                }
            }
        } else {
            let (q, r) = divmod_floor(imul_wide(u - self.u0, self.dv) << H_BITS, du);
            Lv {
                vi: (self.v0 << H_BITS) + q as i32,
                vr: r as i32,
            }
        }
    }

    /// The first minor boundary `m` with `m N` at or past the (clamped)
    /// line at `u`: `ceil(v(u) / N)`.
    pub fn boundary_at_or_after(&self, u: i32) -> i32 {
        let (vi, vr) = self.v_at(u);
        if vr == 0 {
            cell_of(vi + N - 1)
        } else {
            cell_of(vi) + 1
        }
    }

    /// The major column holding the crossing of minor boundary `v = m N`
    /// (`v0 < m N <= v1`, `dv > 0`) and its offset in the column times
    /// `dv`: `u* dv = col N dv + xi`, `0 <= xi < N dv` (set-up: one
    /// division, from the edge's start).
    pub fn crossing(&self, m: i32) -> (i32, u64) {
        let (a0, _) = self.columns();
        // (u* - a0 N) dv = (u0 - a0 N) dv + (m N - v0) du >= 0: below
        // 2^10 2^22 + 2^22 2^22 < 2^45.
        let dm = (i64::from(m) * i64::from(N) - i64::from(self.v0)).max(0);
        let t = mul_wide((self.u0 - a0 * N) as u32, self.dv as u32)
            + if dm <= i64::from(u32::MAX) {
                mul_wide(dm as u32, self.du as u32)
            } else {
                dm as u64 * self.du as u64
            };
        let ndv = u64::from(N as u32) * self.dv as u64;
        let (c, xi) = udivmod(t, ndv);
        (a0 + c as i32, xi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `floor(v(u) / N)` and the remainder, straight from the definition.
    fn direct(e: &Canon, u: i32) -> (i32, i32) {
        let u = i64::from(u.clamp(e.u0, e.u1));
        let n = i64::from(e.v0) * i64::from(e.du) + (u - i64::from(e.u0)) * i64::from(e.dv);
        let du = i64::from(e.du);
        (n.div_euclid(du) as i32, n.rem_euclid(du) as i32)
    }

    #[test]
    fn the_line_from_either_end_equals_the_direct_evaluation() {
        let f = FinePoint::new;
        for (p0, p1) in [
            (f(-2_097_152, 5), f(2_097_152, 2_097_151)),
            (f(100, 3), f(5_000, 2_000)),
            (f(7, 7), f(8, 1_000_000)),
            (f(0, 0), f(1 << 22 >> 1, -(1 << 21))),
            (f(-3, 4_000), f(-99_999, -17)),
        ] {
            let e = Canon::new(p0, p1).unwrap();
            for k in 0..=64 {
                let u = e.u0 - 300 + (i64::from(e.du + 600) * k / 64) as i32;
                let (vi, vr) = e.v_at(u);
                assert_eq!((vi, vr), direct(&e, u), "{p0:?} {p1:?} at {u}");
                assert_eq!(e.cell_at(u), vi.div_euclid(N));
                let exact_ceil = if vr == 0 {
                    vi.div_euclid(N) + i32::from(vi.rem_euclid(N) != 0)
                } else {
                    vi.div_euclid(N) + 1
                };
                assert_eq!(e.boundary_at_or_after(u), exact_ceil);
            }
        }
    }
}
