//! Set-up: the canonical (first-octant) frame of an edge, by the rule of
//! duality of seed 001. No per-pixel work here.

use crate::arith::{div_floor, limit};
use crate::geom::{FinePoint, FINE_ONE};

/// An edge in its canonical frame: `u` the major axis, `v` the minor axis,
/// `u0 < u1`, `v0 <= v1`, `dv <= du`, all in fine units (1/1024 px). With
/// fine coordinates within `±2^21`, extents are at most `2^22`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Canon {
    /// `u` is `y` (the edge is steeper than 45°).
    pub transposed: bool,
    /// The `x` axis is negated (the edge runs to the left going down).
    pub mirrored: bool,
    pub u0: i64,
    pub v0: i64,
    pub u1: i64,
    pub v1: i64,
    pub du: i64,
    pub dv: i64,
    /// `+1` if the edge runs down in the caller's order, `-1` if up.
    pub dir: i32,
}

/// One pixel in fine units, as `i64`.
pub(crate) const N: i64 = FINE_ONE as i64;

impl Canon {
    /// The canonical frame of the edge `p0 -> p1`; `None` for a horizontal
    /// edge (it cuts off no area in the row-wise model).
    pub fn new(p0: FinePoint, p1: FinePoint) -> Option<Self> {
        let (a, b, dir) = match p0.y.cmp(&p1.y) {
            core::cmp::Ordering::Less => (p0, p1, 1),
            core::cmp::Ordering::Greater => (p1, p0, -1),
            core::cmp::Ordering::Equal => return None,
        };
        let (ax, ay, bx, by) = (
            i64::from(a.x),
            i64::from(a.y),
            i64::from(b.x),
            i64::from(b.y),
        );
        let mirrored = bx < ax;
        let sx = if mirrored { -1 } else { 1 };
        let transposed = (bx - ax).abs() < by - ay;
        let (u0, v0, u1, v1) = if transposed {
            (ay, sx * ax, by, sx * bx)
        } else {
            (sx * ax, ay, sx * bx, by)
        };
        Some(Self {
            transposed,
            mirrored,
            u0,
            v0,
            u1,
            v1,
            du: u1 - u0,
            dv: v1 - v0,
            dir,
        })
    }

    /// Frame pixel of canonical cell `(a, b)` (`a` major, `b` minor).
    pub fn pixel(&self, a: i32, b: i32) -> (i32, i32) {
        let (x, y) = if self.transposed { (b, a) } else { (a, b) };
        (if self.mirrored { -1 - x } else { x }, y)
    }

    /// Frame column where cover starts, for a canonical boundary `beta`.
    pub fn cover_column(&self, beta: i32) -> i32 {
        if self.mirrored {
            beta.saturating_neg()
        } else {
            beta
        }
    }

    /// `+1` when the area right of the edge is the canonical low-`v` area,
    /// `-1` when it is its complement.
    pub fn sign(&self) -> i32 {
        if self.transposed == self.mirrored {
            1
        } else {
            -1
        }
    }

    /// First and last major columns the edge touches.
    pub fn columns(&self) -> (i64, i64) {
        (div_floor(self.u0, N), div_floor(self.u1 + N - 1, N) - 1)
    }

    /// First and last minor rows the edge touches.
    pub fn rows(&self) -> (i64, i64) {
        (div_floor(self.v0, N), div_floor(self.v1 + N - 1, N) - 1)
    }

    /// `v * du` at `u`, with `u` clamped into the edge (the line extended
    /// flat beyond its end points).
    pub fn v_num_clamped(&self, u: i64) -> i64 {
        let u = limit(u, self.u0, self.u1);
        self.v0 * self.du + (u - self.u0) * self.dv
    }

    /// The minor cell holding the (clamped) line at major position `u`.
    pub fn cell_at(&self, u: i64) -> i64 {
        div_floor(self.v_num_clamped(u), N * self.du)
    }
}
