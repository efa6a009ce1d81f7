//! Circular and elliptic arcs: area-preserving polygons for filling, and
//! cubic Béziers for path descriptions.
//!
//! Takes an `EllipseFrame` (centre, semi-axes, rotation) and a start
//! angle and sweep (binary units); gives either the vertices of a polygon
//! on it whose area equals the exact area of the ellipse (or of the
//! sector of the arc), or a chain of cubic Béziers through a
//! [`PathSink`].
//!
//! ## Area-preserving polygons
//!
//! An inscribed polygon loses area, and loses it in the same direction
//! everywhere: a disc drawn with it is too small, however fine the grid.
//! So the vertices are moved out radially by a factor chosen from the
//! count alone:
//!
//! - **Full ellipse**, `n` vertices at the parameters `2 pi k / n`, all
//!   scaled by `f = 1 / sqrt(sinc(2 pi / n))`: the polygon's area
//!   `f^2 n/2 sin(2 pi/n) a b` is exactly `pi a b`. The vertices are
//!   outside by `(f - 1) r`, the chord midpoints inside by
//!   `(1 - f cos(pi/n)) r`; both are below `0.35 r (pi/n)^2` for `n >= 8`
//!   (`r` the major semi-axis; an ellipse is an affine image of the unit
//!   circle, which scales distances by at most `r`). So
//!   `n = 8 ceil(n0 / 8)` with `n0^2 >= 7 r / (2 tol)` keeps the polygon
//!   within `tol` of the ellipse.
//! - **Arc** of sweep `s` in `m` steps `D = s/m`: its two end vertices stay
//!   on the curve (they are shared with the straight edges of sectors,
//!   rounded corners, caps and joins), the `m - 1` inner ones are scaled by
//!   `g`, the positive root of `(m - 2) g^2 + 2 g = q` with
//!   `q = s / sin D = m / sinc(D)`, written `g = q / (1 + sqrt(1 + (m - 2) q))`:
//!   then the fan of triangles from the centre has area
//!   `sin D / 2 ((m - 2) g^2 + 2 g) r^2 = s r^2 / 2`, the sector's exact
//!   area. For `m = 1` there is no inner vertex (a chord, deviation
//!   `r (1 - cos(s/2)) <= r s^2 / 8`). For `m >= 2` and `D <= pi/4` the
//!   deviation is below `0.18 r D^2` (measured over `m = 2 ... 1000`; the
//!   worst case is `m = 2`, `0.1795 r D^2` at `D = pi/4`). So
//!   `m = max(ceil(s / (pi/4)), ceil(s sqrt(9 r / (50 tol))))`.
//!
//! Every vertex is then rounded to the grid (at most 0.71 fine units), so
//! the polygon is within `tol + 0.71` fine units of the curve, and its
//! area differs from the exact one only by the rounding (measured in the
//! tests: within 0.07 % for a disc of radius 1/2 px, 0.001 % at 100 px).
//!
//! Counts are capped at [`MAX_ELLIPSE_SEGMENTS`] = 2048 (full) and
//! [`MAX_ARC_SEGMENTS`] = 2048 (one arc). The bounds hold uncapped for
//! `r <= 2 tol 2048^2 / 7` (3510 px at the default 3 fine units); beyond,
//! the deviation grows as `0.35 r (pi/2048)^2`.
//!
//! ## Cubic Béziers
//!
//! `arc_cubics` approximates an arc by cubics with the classic control
//! length `k = 4/3 tan(phi/4)` per piece of angle `phi`: the curve bulges
//! outward by at most `e(phi) r`, `e(phi) = 2 sin^6(phi/4) / (27 cos^2(phi/4))`
//! (`e(pi/2) = 2.7253e-4`, and `e(phi) / phi^6` grows with `phi`, so
//! `e(pi/(2q)) <= e(pi/2) / q^6`). With `q` pieces per quarter turn, the
//! smallest `q` with `917 q^6 >= r` (`917 < 1 / (4 e(pi/2)) = 917.3`)
//! keeps it within 1/4 fine unit; the control points are then rounded to
//! the grid (moving the curve by at most 0.71 fine units).
//!
//! ## Integer ranges
//!
//! Semi-axes are at most [`MAX_RADIUS`] = `2^23` fine units (8192 px);
//! in Q8 (1/256 fine unit) and scaled by `f, g < 1.12`, they are below
//! `2^31.2`; times a Q30 cosine `< 2^61.2`, and the rotated sums of two
//! such products `< 2^62.2`, in `i64`. The centre is kept in Q8 too (SVG
//! arcs have centres off the grid).

use crate::geom::PathSink;

use super::segment::Vertices;
use super::trig::{cos_sin, round_shift, sinc_q31, Q30, SIN_COARSE_ERR_Q15, TURN};
use super::vector::{div_round_i64, Pt, Unit, UNIT_X};
use super::Tolerance;
use crate::arith::mul_wide;

/// The largest semi-axis or radius, `2^23` fine units (8192 px); larger
/// ones are limited to it.
pub const MAX_RADIUS: u32 = 1 << 23;
/// The most vertices of a full circle or ellipse.
pub const MAX_ELLIPSE_SEGMENTS: u32 = 2048;
/// The most segments of one arc.
pub const MAX_ARC_SEGMENTS: u32 = 2048;

/// Where an ellipse lies: centre (Q8 fine units), semi-axes (fine units,
/// at most [`MAX_RADIUS`]) and rotation (the image of the +x axis).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct EllipseFrame {
    c_q8: Pt,
    a_q8: i64,
    b_q8: i64,
    rot: Unit,
}

impl EllipseFrame {
    /// An ellipse of semi-axes `a`, `b` about `c` (fine units), its `a`
    /// axis along `rot`.
    pub fn new(c: Pt, a: u32, b: u32, rot: Unit) -> Self {
        Self::with_q8(
            Pt::new(c.x << 8, c.y << 8),
            i64::from(a) << 8,
            i64::from(b) << 8,
            rot,
        )
    }

    /// The same with the centre and the semi-axes in 1/256 fine units
    /// (semi-axes limited to `0..=MAX_RADIUS << 8`).
    pub fn with_q8(c_q8: Pt, a_q8: i64, b_q8: i64, rot: Unit) -> Self {
        let max = i64::from(MAX_RADIUS) << 8;
        Self {
            c_q8,
            a_q8: a_q8.clamp(0, max),
            b_q8: b_q8.clamp(0, max),
            rot,
        }
    }

    /// A circle.
    pub fn circle(c: Pt, r: u32) -> Self {
        Self::new(c, r, r, UNIT_X)
    }

    /// The larger semi-axis, in fine units (rounded up).
    pub fn major(&self) -> i64 {
        (self.a_q8.max(self.b_q8) + 255) >> 8
    }

    /// True when either semi-axis is zero (the ellipse has no area).
    pub fn is_flat(&self) -> bool {
        self.a_q8 == 0 || self.b_q8 == 0
    }

    /// The image of the point `(x, y)` of the unit circle's plane, given in
    /// Q30 with `|x|, |y| < 1.12`.
    pub fn map_q30(&self, x: i64, y: i64) -> Pt {
        let p = self.map_q30_q8(x, y);
        // Halves round up (not away from zero): a shape moved by whole
        // fine units then moves every vertex by exactly as much, so its
        // area is the same bits wherever it lies.
        Pt::new((p.x + 128) >> 8, (p.y + 128) >> 8)
    }

    /// [`map_q30`](Self::map_q30) before the rounding to the grid: Q8
    /// fine units.
    fn map_q30_q8(&self, x: i64, y: i64) -> Pt {
        let u = scale_q30(self.a_q8, x); // Q8, below 2^31.2
        let v = scale_q30(self.b_q8, y);
        // Unrotated (circles, most ellipses): `round_shift(u 2^30, 30)` is
        // `u`, so the rotation's four products are skipped (same bits).
        let (dx, dy) = if self.rot == UNIT_X {
            (u, v)
        } else {
            (
                round_shift(u * self.rot.x - v * self.rot.y, 30),
                round_shift(u * self.rot.y + v * self.rot.x, 30),
            )
        };
        Pt::new(self.c_q8.x + dx, self.c_q8.y + dy)
    }

    /// The point at parameter `t` (binary units), radially scaled by
    /// `scale` (Q30).
    pub fn point(&self, t: i64, scale: i64) -> Pt {
        let (c, s) = cos_sin(t as u32);
        self.map_q30(scale_q30(scale, c), scale_q30(scale, s))
    }

    /// The point at parameter `t` on the curve, in Q8 fine units (not
    /// rounded to the grid: the centre of another curve).
    pub fn point_q8(&self, t: i64) -> Pt {
        let (c, s) = cos_sin(t as u32);
        self.map_q30_q8(c, s)
    }
}

/// `(a x) >> 30` (floor) for `0 <= a <= 2^31` (a semi-axis in Q8, or a
/// Q30 scale) and `|x| < 2^31` (a Q30 factor): one 32x32->64 product in
/// halves (no 64-bit multiply on a Cortex-M0); the floor of a negative
/// product as the arithmetic shift gives it. Other values: in 64 bits.
#[inline]
fn scale_q30(a: i64, x: i64) -> i64 {
    match (u32::try_from(a), i32::try_from(x)) {
        (Ok(a), Ok(x)) => {
            let p = mul_wide(a, x.unsigned_abs());
            if x < 0 {
                -(((p + (1 << 30) - 1) >> 30) as i64)
            } else {
                (p >> 30) as i64
            }
        }
        _ => (a * x) >> 30,
    }
}

/// Vertices of a full ellipse within `tol` of the curve: a multiple of 8,
/// `8..=MAX_ELLIPSE_SEGMENTS`.
pub(crate) fn full_count(r: i64, tol: Tolerance) -> u32 {
    let tol = u64::from(tol.fine());
    // `Tolerance` is at least 1; `max` keeps the division's panic out.
    let q = (7 * r.max(0) as u64).div_ceil((2 * tol).max(1));
    let n0 = super::trig::ceil_sqrt_u64(q).max(1);
    let n = n0.div_ceil(8) * 8;
    n.clamp(8, u64::from(MAX_ELLIPSE_SEGMENTS)) as u32
}

/// The area-preserving radial factor of a full `n`-gon, `f = 1/sqrt(sinc(2 pi/n))`
/// in Q30 (`n >= 8`).
pub(crate) fn full_scale(n: u32) -> i64 {
    let step = TURN / i64::from(n.max(8));
    let s = sinc_q31(step).max(1) as u128;
    // f^2 = 1/sinc: f in Q30 = sqrt(2^60 * 2^31 / sinc_q31).
    ((1u128 << 91) / s).isqrt() as i64
}

/// Segments of an arc of sweep `|s|` (binary units) within `tol`:
/// `1..=MAX_ARC_SEGMENTS`, with steps of at most an eighth of a turn.
pub(crate) fn arc_count(r: i64, sweep: i64, tol: Tolerance) -> u32 {
    let s = sweep.unsigned_abs().min(TURN as u64);
    if s == 0 {
        return 1;
    }
    let by_angle = s.div_ceil(1 << 29);
    let (num, den) = deviation(r, s, tol);
    let q = num.div_ceil(den).min(1 << 40) as u64;
    let by_dev = super::trig::ceil_sqrt_u64(q);
    by_angle.max(by_dev).clamp(1, u64::from(MAX_ARC_SEGMENTS)) as u32
}

/// [`arc_count`]'s deviation bound for a sweep of `s` binary units: `m`
/// segments keep within `tol` when `m^2 >= num / den`.
#[inline]
fn deviation(r: i64, s: u64, tol: Tolerance) -> (u128, u128) {
    // m^2 >= 9 s^2 r / (50 tol), s in radians: s_rad = s * 2 pi / 2^32.
    let s_rad_q31 = super::trig::radians_q31(s as i64) as u128; // < 2^34
    let num = s_rad_q31 * s_rad_q31 * 9 * r.max(0) as u128; // < 2^68 * 9 * 2^23
                                                            // `Tolerance` is at least 1; `max` keeps the division's panic out.
    let den = (50 * u128::from(tol.fine().max(1))) << 62;
    (num, den)
}

/// The widest sweep (binary units, at most an eighth of a turn) that
/// [`arc_count`] draws in one segment at radius `r`: `arc_count(r, s)` is
/// 1 for every `|s|` up to it and more above it. Found by halving the
/// interval with the deviation bound's own test (no division), once for
/// a radius: a join then knows from its turn's bound alone that its arc
/// is a single chord, without measuring the turn.
pub(crate) fn one_segment_sweep(r: i64, tol: Tolerance) -> i64 {
    let fits = |s: u64| {
        let (num, den) = deviation(r, s, tol);
        num <= den
    };
    let (mut lo, mut hi) = (0u64, 1u64 << 29);
    if fits(hi) {
        return hi as i64;
    }
    // fits(lo), !fits(hi).
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if fits(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo as i64
}

/// The area-preserving factor `g` (Q30) of the inner vertices of an arc
/// of `m >= 2` steps of `step` binary units each (`0 < step <= 2^29`).
///
/// Every band computes it again for each arc it draws, so it is written
/// in 64-bit pieces (a 128-bit division and square root are library
/// routines of thousands of instructions on a Cortex-M0), with the bits of
/// the plain 128-bit form (kept in the tests): with `s = sinc` in Q31
/// (`0.9 2^31 < s <= 2^31` for a step up to `pi/4`) and `m <= 2^11`,
///
/// - `q = floor(m 2^61 / s) < 2^42` as two long-division steps of 32 bits;
/// - `root = floor(sqrt(2^30 E))`, `E = 2^30 + (m - 2) q < 2^53`: from
///   `r0 = floor(sqrt(2^10 E))` (a 64-bit root), `root = 2^10 r0 + k`
///   with the largest `k < 2^10` whose square fits, found bit by bit on the
///   remainder `2^20 (2^10 E - r0^2)`;
/// - `g = floor(2^30 q / (2^30 + root))` as two long-division steps.
pub(crate) fn arc_scale(m: u32, step: i64) -> i64 {
    let m = u64::from(m.clamp(2, MAX_ARC_SEGMENTS));
    let s = (sinc_q31(step.unsigned_abs().min(1 << 29) as i64).max(1) as u64).min(1 << 31);
    // q = floor(m 2^29 2^32 / s): m 2^29 < 2^41, the remainder below s.
    let hi = m << 29;
    let q = ((hi / s) << 32) + (((hi % s) << 32) / s);
    let e = (1u64 << 30) + (m - 2) * q;
    let r0 = (e << 10).isqrt();
    // (2^10 r0 + k)^2 <= 2^30 E  <=>  2^11 r0 k + k^2 <= 2^20 (2^10 E - r0^2).
    let room = ((e << 10) - r0 * r0) << 20;
    let mut k = 0u64;
    let mut bit = 1u64 << 9;
    while bit > 0 {
        let t = k + bit;
        if (r0 << 11) * t + t * t <= room {
            k = t;
        }
        bit >>= 1;
    }
    let root = (r0 << 10) + k;
    let den = (1u64 << 30) + root;
    // 2^30 q = 2^21 q 2^9: 2^21 q < 2^63.
    let num = q << 21;
    (((num / den) << 9) + (((num % den) << 9) / den)) as i64
}

/// `div_round_i64(step k, d)` for `k = 0, 1, 2, ...` (`d > 0`), by
/// additions and compares: the numerator `|step| k + d/2` is carried as a
/// quotient and a remainder, so the vertices of a curve cost no division
/// each (two per curve, and one for [`skip`](Self::skip)'s constants).
#[derive(Clone)]
struct RoundedMultiples {
    q: i64,
    r: i64,
    dq: i64,
    dr: i64,
    d: i64,
    /// `PIECE - 1` steps at once: `(PIECE - 1) |step|` as `sq d + sr`.
    sq: i64,
    sr: i64,
    negative: bool,
}

impl RoundedMultiples {
    fn new(step: i64, d: i64) -> Self {
        let d = d.max(1);
        let a = step.abs();
        let (dq, dr) = (a / d, a % d);
        // (PIECE - 1) dr < 7 d: a short division for the counts curves
        // have (d <= 2048).
        let k = i64::from(PIECE - 1);
        let kr = k * dr;
        let (cq, cr) = match (u32::try_from(kr), u32::try_from(d)) {
            (Ok(n), Ok(dd)) => (i64::from(n / dd), i64::from(n % dd)),
            _ => (kr / d, kr % d),
        };
        Self {
            q: 0,
            r: d / 2,
            dq,
            dr,
            d,
            sq: k * dq + cq,
            sr: cr,
            negative: step < 0,
        }
    }

    /// The next multiple's rounded quotient.
    fn next(&mut self) -> i64 {
        let v = if self.negative { -self.q } else { self.q };
        self.q += self.dq;
        self.r += self.dr;
        if self.r >= self.d {
            self.r -= self.d;
            self.q += 1;
        }
        v
    }

    /// Moves on as `PIECE - 1` calls of [`next`](Self::next) would: the
    /// remainder grows by `(PIECE - 1) dr = cq d + sr`, so the quotient by
    /// `(PIECE - 1) dq + cq` and one more when `r + sr` passes `d`
    /// (`r, sr < d`).
    fn skip(&mut self) {
        self.q += self.sq;
        self.r += self.sr;
        if self.r >= self.d {
            self.r -= self.d;
            self.q += 1;
        }
    }
}

/// Vertices per piece that a curve skips as a whole when the piece misses
/// the sink's window: only the ends of such a piece are computed (its
/// other vertices cost a few additions each, for their parameters).
const PIECE: u32 = 8;

/// How far (fine units) a vertex between two computed vertices `j` and
/// `j + PIECE` of a curve polygon may lie outside their y-range, for
/// vertices `span` binary units of parameter apart on the ellipse `frame`;
/// `None` when pieces that long are not skipped (more than a quarter turn:
/// small polygons, drawn whole).
///
/// An ellipse is the image of the unit circle under a map that stretches
/// distances by at most its major semi-axis `a`; an arc of angle `D`
/// (radians, `D <= pi/2`) of the unit circle lies within its sagitta
/// `1 - cos(D/2) <= D^2/8` of its chord, and projects onto the chord
/// itself, so the curve between the two vertices' curve points lies within
/// `a D^2 / 8` of their y-range. Each vertex is its curve point scaled
/// radially by `f` or `g` (at most `1 / sinc(d) <= 1 + d^2/5` for a step
/// `d <= pi/4`, so `a D^2 / 320` away) and rounded (under 2 fine units
/// with the Q30 products' floors). The slack `a D^2 pi^2 / 2^64 + 16`
/// (`D` in binary units, `pi^2 < 10`) is `a D_rad^2 / 4 + 16`, above
/// their sum.
///
/// `None` (no piece is jumped) also when a vertex could lie outside the
/// coordinate range: its segments are then clamped to the range and take
/// [`CLAMPED_NUMBERS`](super::segment::CLAMPED_NUMBERS) numbers each, not
/// the one a jump counts. A vertex lies within `a / sinc(d) + 2 <= 9 a / 8
/// + 2` fine units of the centre (`d <= pi/4`).
fn piece_slack(frame: &EllipseFrame, span: i64) -> Option<i32> {
    let span = span.unsigned_abs();
    if span > (TURN / 4) as u64 {
        return None;
    }
    let a = frame.major().clamp(0, i64::from(MAX_RADIUS));
    let reach = a + a / 8 + 4;
    let (cx, cy) = (frame.c_q8.x >> 8, frame.c_q8.y >> 8);
    let limit = i64::from(crate::geom::FINE_LIMIT);
    if cx.abs() + 1 + reach > limit || cy.abs() + 1 + reach > limit {
        return None;
    }
    // (span >> 16) + 1 <= 2^14 + 1; its square times 10 a (a <= 2^23):
    // below 2^55.
    let d = (span >> 16) + 1;
    Some(((d * d * 10 * a as u64) >> 32) as i32 + 16)
}

/// A cheap estimate of a vertex's y on an unrotated ellipse, from the
/// coarse sine: `c_y + g b sin t`, within `err` fine units of the vertex
/// [`EllipseFrame::point`] gives for the scale `g` (its rounding and
/// floors, under 3 fine units, plus `g b` times the coarse sine's error,
/// 5 Q15 units, `1.5e-4 < 2^-12` of `g b`, plus the estimate's own
/// floors).
#[derive(Debug, Clone, Copy)]
struct YEstimate {
    /// The parameter vertex parameters are offset by.
    t0: i64,
    c_q8: i64,
    gb_q8: u32,
    err: i64,
}

impl YEstimate {
    /// For vertices scaled by `scale` (Q30, at most 1.12) on `frame` at
    /// parameters `t0 + t`; `None` for a rotated frame.
    fn new(frame: &EllipseFrame, t0: i64, scale: i64) -> Option<Self> {
        if frame.rot != UNIT_X {
            return None;
        }
        // b below 2^31 in Q8, times a scale below 1.12: below 2^32.
        let gb_q8 = u32::try_from(scale_q30(frame.b_q8, scale)).ok()?;
        Some(Self {
            t0,
            c_q8: frame.c_q8.y,
            gb_q8,
            // g b times the sine's error (Q15, Q8 fine units), plus 8.
            err: ((u64::from(gb_q8) * SIN_COARSE_ERR_Q15 as u64) >> (15 + 8)) as i64 + 8,
        })
    }

    /// The estimate at parameter `t0 + t` (binary units), fine units.
    #[inline]
    fn y(&self, t: i64) -> i64 {
        let s = super::trig::sin_coarse_q15(self.t0.wrapping_add(t) as u32);
        let p = (mul_wide(self.gb_q8, s.unsigned_abs()) >> 15) as i64;
        let dy = if s < 0 { -p } else { p };
        (self.c_q8 + dy + 128) >> 8
    }
}

/// Sends vertices `1..=n` of a curve polygon whose vertex 0, `p0`, the
/// caller has sent: vertex `i` is `point(i, ts.next())`. With a window
/// from `out` and a `slack` ([`piece_slack`]), in pieces of [`PIECE`]
/// vertices: a piece whose end vertices' y-range, widened by the slack,
/// misses the window is jumped over (its segments all lie outside it), so
/// its inner vertices are not computed. With an `estimate` (unrotated
/// ellipses) the ends of the pieces `1..n - 1` are estimated by the
/// coarse sine instead, widened by its error, and a vertex is computed
/// exactly only where a jump ends before a piece that is needed, and at
/// `n`. The vertices sent are the same bits either way.
fn send_vertices<O: Vertices + ?Sized>(
    out: &mut O,
    p0: Pt,
    n: u32,
    mut ts: RoundedMultiples,
    slack: Option<i32>,
    estimate: Option<YEstimate>,
    point: impl Fn(u32, i64) -> Pt,
) {
    let (Some((lo, hi)), Some(slack)) = (out.window(), slack) else {
        for i in 1..=n {
            out.vertex(point(i, ts.next()));
        }
        return;
    };
    let err = estimate.map_or(0, |e| e.err);
    // The window widened by the bulge and the estimate's error.
    let widen = i64::from(slack) + err;
    let (lo, hi) = (i64::from(lo) - widen, i64::from(hi) + widen);
    // Vertex i's parameter and y (exact or estimated), and the segments
    // jumped since the last vertex sent.
    let (mut i, mut ti, mut yi) = (0, 0, p0.y);
    let mut jumped = 0;
    while i < n {
        let j = (i + PIECE).min(n);
        let from = ts.clone();
        if j - i == PIECE {
            ts.skip();
        } else {
            for _ in i + 1..j {
                ts.next();
            }
        }
        let tj = ts.next();
        let (yj, pj) = match estimate {
            Some(e) if j < n => (e.y(tj), None),
            _ => {
                let p = point(j, tj);
                (p.y, Some(p))
            }
        };
        if yi.max(yj) < lo || yi.min(yj) > hi {
            jumped += j - i;
        } else {
            if jumped > 0 {
                out.jump(point(i, ti), jumped);
                jumped = 0;
            }
            let mut t = from;
            for k in i + 1..j {
                out.vertex(point(k, t.next()));
            }
            out.vertex(pj.unwrap_or_else(|| point(j, tj)));
        }
        (i, ti, yi) = (j, tj, yj);
    }
    if jumped > 0 {
        out.jump(point(n, ti), jumped);
    }
}

/// Calls `out` with the `m + 1` vertices of the area-preserving polygon of
/// an arc from `t0` over `sweep` (binary units, `|sweep| <=` one turn),
/// both ends on the curve; only the start for a zero sweep. Pieces that
/// miss `out`'s window are jumped over ([`Vertices::jump`]).
pub(crate) fn arc_points<O: Vertices + ?Sized>(
    frame: &EllipseFrame,
    t0: i64,
    sweep: i64,
    tol: Tolerance,
    out: &mut O,
) {
    let sweep = sweep.clamp(-TURN, TURN);
    let p0 = frame.point(t0, Q30);
    out.vertex(p0);
    if sweep != 0 {
        arc_vertices(frame, t0, sweep, tol, p0, true, out);
    }
}

/// The `m - 1` inner vertices of [`arc_points`]' polygon (none for a
/// single chord): for callers whose arc ends are points they already
/// have (joins and caps of strokes). `p0` is the point the contour stands
/// at, the arc's start or within a few fine units of it (the slack of
/// [`piece_slack`] has room for that); pieces that miss `out`'s window
/// are jumped over.
pub(crate) fn arc_inner_vertices<O: Vertices + ?Sized>(
    frame: &EllipseFrame,
    t0: i64,
    sweep: i64,
    tol: Tolerance,
    p0: Pt,
    out: &mut O,
) {
    let sweep = sweep.clamp(-TURN, TURN);
    if sweep != 0 {
        arc_vertices(frame, t0, sweep, tol, p0, false, out);
    }
}

/// The vertices after `p0` of the area-preserving polygon of an arc from
/// `t0` over `sweep` (non-zero, within a turn): the `m - 1` inner ones,
/// scaled by `g`, and with `end` the last one, on the curve (`ts` gives
/// exactly `sweep` at `m`).
fn arc_vertices<O: Vertices + ?Sized>(
    frame: &EllipseFrame,
    t0: i64,
    sweep: i64,
    tol: Tolerance,
    p0: Pt,
    end: bool,
    out: &mut O,
) {
    let m = arc_count(frame.major(), sweep, tol);
    if m < 2 {
        if end {
            out.vertex(frame.point(t0 + sweep, Q30));
        }
        return;
    }
    let g = arc_scale(m, sweep / i64::from(m));
    let mut ts = RoundedMultiples::new(sweep, i64::from(m));
    ts.next();
    let slack = piece_slack(frame, sweep / i64::from(m) * i64::from(PIECE));
    let estimate = YEstimate::new(frame, t0, g);
    let n = if end { m } else { m - 1 };
    send_vertices(out, p0, n, ts, slack, estimate, |i, t| {
        frame.point(t0 + t, if i == m { Q30 } else { g })
    });
}

/// Calls `out` with the `n` vertices of the area-preserving polygon of the
/// full ellipse, starting at parameter `t0`, clockwise on screen.
/// With `reverse`, counter-clockwise (for holes). Pieces that miss `out`'s
/// window are jumped over ([`Vertices::jump`]).
pub(crate) fn ellipse_points<O: Vertices + ?Sized>(
    frame: &EllipseFrame,
    t0: i64,
    reverse: bool,
    tol: Tolerance,
    out: &mut O,
) {
    let n = full_count(frame.major(), tol);
    let f = full_scale(n);
    let turn = if reverse { -TURN } else { TURN };
    let mut ts = RoundedMultiples::new(turn, i64::from(n));
    let p0 = frame.point(t0 + ts.next(), f);
    out.vertex(p0);
    let slack = piece_slack(frame, turn / i64::from(n) * i64::from(PIECE));
    let estimate = YEstimate::new(frame, t0, f);
    send_vertices(out, p0, n - 1, ts, slack, estimate, |_, t| {
        frame.point(t0 + t, f)
    });
}

/// Describes an elliptic arc into a path as cubic Béziers (within 1/4 fine
/// unit of the arc before the control points are rounded to the grid):
/// the ellipse about `centre` with semi-axes `rx` (along the rotated x
/// axis) and `ry`, rotated by `rotation`, from the parameter angle `start`
/// over `sweep` (clockwise on screen when positive; at most a turn). The
/// arc begins with a `move_to` its first point when `move_first`, else
/// with a `line_to` it (as a canvas `arc` joins the current point).
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::arc::describe_arc;
/// use softedge::path::{Degrees, Flattener, SegmentSink};
/// # struct Count(usize);
/// # impl SegmentSink for Count { fn segment(&mut self, _: FinePoint, _: FinePoint) { self.0 += 1 } }
/// let mut count = Count(0);
/// let mut f = Flattener::new(&mut count);
/// // A half ellipse, closed by its chord.
/// describe_arc(&mut f, FinePoint::new(0, 0), 20 * 1024, 10 * 1024, Degrees::new(0),
///              Degrees::new(0), Degrees::new(180), true);
/// f.finish();
/// assert!(count.0 > 20);
/// ```
#[allow(clippy::too_many_arguments)]
pub fn describe_arc<P: PathSink + ?Sized>(
    sink: &mut P,
    centre: crate::geom::FinePoint,
    rx: u32,
    ry: u32,
    rotation: super::Degrees,
    start: super::Degrees,
    sweep: super::Degrees,
    move_first: bool,
) {
    let frame = EllipseFrame::new(
        centre.into(),
        rx,
        ry,
        Unit::from_angle(rotation.binary() as u32),
    );
    let t0 = start.binary();
    let first = frame.point(t0, Q30).to_fine();
    if move_first {
        sink.move_to(first);
    } else {
        sink.line_to(first);
    }
    if !frame.is_flat() {
        arc_cubics(&frame, t0, sweep.binary(), None, sink);
    }
}

/// Cubic pieces per quarter turn for a radius of `r` fine units.
fn pieces_per_quarter(r: i64) -> i64 {
    // The smallest q >= 1 with 917 q^6 >= r (r <= 2^23: q <= 5).
    let mut q = 1i64;
    while q < 8 && 917 * q.pow(6) < r {
        q += 1;
    }
    q
}

/// Describes the arc from `t0` over `sweep` (binary units, any size; more
/// than a turn is limited to one) as cubic Béziers into `sink`, which must
/// already stand at the arc's start (`frame.point(t0, Q30)`). The last end
/// point is `end` if given (so that a path closes exactly on its own
/// point), else the arc's end.
pub(crate) fn arc_cubics<P: PathSink + ?Sized>(
    frame: &EllipseFrame,
    t0: i64,
    sweep: i64,
    end: Option<Pt>,
    sink: &mut P,
) {
    let sweep = sweep.clamp(-TURN, TURN);
    if sweep == 0 {
        if let Some(e) = end {
            sink.line_to(e.to_fine());
        }
        return;
    }
    let q = pieces_per_quarter(frame.major());
    let quarter = TURN / 4;
    let pieces = ((sweep.unsigned_abs() * q as u64).div_ceil(quarter as u64) as i64).max(1);
    let mut ta = t0;
    let mut pa = unit_at(t0);
    // Each piece from ta to tb; the unit-circle control points are mapped
    // through the frame.
    for i in 1..=pieces {
        let tb = t0 + div_round_i64(sweep * i, pieces);
        let pb = unit_at(tb);
        let phi = tb - ta;
        // k = 4/3 tan(phi/4) in Q30 (|phi| <= a quarter: |k| < 0.56).
        let (c4, s4) = cos_sin((phi / 4) as u32);
        // |s4| <= 2^30, so the quotient never overflows; `checked_div`
        // says so to the compiler (and gives 0 for c4 == 0).
        let k = (s4 << 30).checked_div(c4).unwrap_or(0) * 4 / 3;
        let c1 = (pa.0 - ((k * pa.1) >> 30), pa.1 + ((k * pa.0) >> 30));
        let c2 = (pb.0 + ((k * pb.1) >> 30), pb.1 - ((k * pb.0) >> 30));
        let p_end = if i == pieces {
            end.unwrap_or_else(|| frame.map_q30(pb.0, pb.1))
        } else {
            frame.map_q30(pb.0, pb.1)
        };
        sink.cubic_to(
            frame.map_q30(c1.0, c1.1).to_fine(),
            frame.map_q30(c2.0, c2.1).to_fine(),
            p_end.to_fine(),
        );
        ta = tb;
        pa = pb;
    }
}

/// `(cos t, sin t)` in Q30.
fn unit_at(t: i64) -> (i64, i64) {
    cos_sin(t as u32)
}

#[cfg(test)]
mod tests {
    extern crate std;

    #[test]
    fn scale_q30_is_the_64_bit_floor() {
        let mut rng = Lcg(0x1234_5678_9abc_def1);
        let edges = [0, 1, (1 << 31) - 1, 1 << 31];
        for _ in 0..100_000 {
            let seed = rng.next_u64();
            let a = (seed >> 33) as i64;
            let x = ((seed as u32) as i32) as i64;
            assert_eq!(scale_q30(a, x), (a * x) >> 30, "{a} {x}");
        }
        for a in edges {
            for x in [
                0,
                1,
                -1,
                i64::from(i32::MIN),
                i64::from(i32::MAX),
                1 << 30,
                -(1 << 30),
            ] {
                assert_eq!(scale_q30(a, x), (a * x) >> 30, "{a} {x}");
            }
        }
    }

    /// [`arc_scale`] as first written, in 128 bits.
    fn arc_scale_u128(m: u32, step: i64) -> i64 {
        let m = u128::from(m.max(2));
        let s = sinc_q31(step.unsigned_abs().min(1 << 29) as i64).max(1) as u128;
        let q = (m << 61) / s;
        let d = (1u128 << 60) + (m - 2) * q * (1 << 30);
        let root = d.isqrt();
        ((q << 30) / ((1 << 30) + root)) as i64
    }

    #[test]
    fn arc_scale_in_64_bits_is_the_128_bit_form() {
        let mut rng = Lcg(0x51ed_270b_6f2a_93c5);
        for m in 2..=MAX_ARC_SEGMENTS {
            // The steps arcs give (a sweep up to a turn in m steps of at
            // most an eighth), and random ones.
            for k in 0..12 {
                let seed = rng.next_u64();
                let step = match k {
                    0 => 1 << 29,
                    1 => 1,
                    2 => (TURN / i64::from(m)).min(1 << 29),
                    3 => (TURN / 4 / i64::from(m)).max(1),
                    _ => 1 + (seed >> 35) as i64 % (1 << 29),
                };
                assert_eq!(
                    arc_scale(m, step),
                    arc_scale_u128(m, step),
                    "m {m} step {step}"
                );
                assert_eq!(arc_scale(m, -step), arc_scale_u128(m, -step));
            }
        }
    }

    #[test]
    fn rounded_multiples_are_the_rounded_quotients() {
        let mut rng = Lcg(0x2545_f491_4f6c_dd1d);
        for case in 0..2000 {
            let seed = rng.next_u64();
            let step = match case % 4 {
                0 => TURN,
                1 => -TURN,
                _ => ((seed >> 16) as i64 % (2 * TURN)) - TURN,
            };
            let d = 1 + ((seed >> 40) % 2048) as i64;
            let mut m = RoundedMultiples::new(step, d);
            for k in 0..=d {
                assert_eq!(
                    m.next(),
                    div_round_i64(step * k, d),
                    "step {step} d {d} k {k}"
                );
            }
            // Skipping a piece's inner steps lands where stepping does.
            let mut m = RoundedMultiples::new(step, d);
            let mut k = 0;
            while k + i64::from(PIECE) <= d {
                assert_eq!(m.next(), div_round_i64(step * k, d));
                m.skip();
                k += i64::from(PIECE);
            }
            assert_eq!(
                m.next(),
                div_round_i64(step * k, d),
                "step {step} d {d} k {k}"
            );
        }
    }
    use super::*;

    /// The widest one-segment sweep is `arc_count`'s edge: 1 there, more
    /// one unit beyond (below an eighth of a turn, where the angle alone
    /// asks for a second segment).
    #[test]
    fn the_one_segment_sweep_is_where_arc_count_turns_to_two() {
        let mut rng = crate::path::testing::Lcg(0x0015_e9e1);
        for k in 0..3000 {
            let r = match k % 3 {
                0 => rng.below(64) as i64,
                1 => rng.below(1 << 16) as i64,
                _ => rng.below(1 << 31) as i64,
            };
            let tol = Tolerance::new(1 + rng.below(256) as u16);
            let s = one_segment_sweep(r, tol);
            assert_eq!(arc_count(r, s, tol), 1, "r {r} tol {tol:?} s {s}");
            assert_eq!(arc_count(r, -s, tol), 1, "r {r} tol {tol:?} s {s}");
            assert!(arc_count(r, s + 1, tol) > 1, "r {r} tol {tol:?} s {s}");
        }
    }
    use crate::path::testing::Lcg;

    #[test]
    fn counts_follow_the_stated_rules() {
        let tol = Tolerance::DEFAULT;
        assert_eq!(full_count(0, tol), 8);
        // r = 512 (1/2 px): n0^2 >= 7*512/6 = 597.3, n0 = 25, n = 32.
        assert_eq!(full_count(512, tol), 32);
        // r = 100 px: 7 * 102400 / 6 = 119467, n0 = 346, n = 352.
        assert_eq!(full_count(102_400, tol), 352);
        assert_eq!(full_count(1 << 40, tol), MAX_ELLIPSE_SEGMENTS);
        assert_eq!(arc_count(1000, 0, tol), 1);
        assert_eq!(arc_count(0, TURN, tol), 8);
    }

    #[test]
    fn full_polygon_area_equals_the_circle_before_rounding() {
        for n in [8u32, 16, 24, 352, 2048] {
            let f = full_scale(n) as f64 / Q30 as f64;
            let th = 2.0 * core::f64::consts::PI / f64::from(n);
            let area = f * f * f64::from(n) / 2.0 * th.sin();
            assert!((area / core::f64::consts::PI - 1.0).abs() < 1e-8, "{n}");
        }
    }

    #[test]
    fn arc_fan_area_equals_the_sector_before_rounding() {
        for (m, sweep) in [(2u32, TURN / 4), (3, TURN / 8), (7, TURN / 3), (100, TURN)] {
            let step = sweep / i64::from(m);
            let g = arc_scale(m, step) as f64 / Q30 as f64;
            let d = step as f64 / TURN as f64 * 2.0 * core::f64::consts::PI;
            let fan = d.sin() / 2.0 * (f64::from(m - 2) * g * g + 2.0 * g);
            let want = f64::from(m) * d / 2.0;
            assert!((fan / want - 1.0).abs() < 1e-8, "{m}");
        }
    }

    #[test]
    fn quarter_arc_ends_on_the_axes() {
        let f = EllipseFrame::circle(Pt::new(0, 0), 10240);
        let mut pts = [Pt::default(); 64];
        let mut n = 0;
        arc_points(&f, 0, TURN / 4, Tolerance::DEFAULT, &mut |p| {
            if let Some(s) = pts.get_mut(n) {
                *s = p;
            }
            n += 1;
        });
        assert_eq!(pts[0], Pt::new(10240, 0));
        assert_eq!(pts[n - 1], Pt::new(0, 10240));
    }

    /// Records a contour's segments, numbered, the way a band's canvas
    /// numbers them (jumped segments counted), for a window or none.
    struct Numbering {
        window: Option<(i32, i32)>,
        next: u32,
        last: Option<Pt>,
        segs: std::vec::Vec<(u32, Pt, Pt)>,
    }

    impl Numbering {
        fn new(window: Option<(i32, i32)>) -> Self {
            Self {
                window,
                next: 0,
                last: None,
                segs: std::vec::Vec::new(),
            }
        }

        /// The segments that meet `(lo, hi)`, with their numbers.
        fn meeting(&self, (lo, hi): (i32, i32)) -> std::vec::Vec<(u32, Pt, Pt)> {
            let (lo, hi) = (i64::from(lo), i64::from(hi));
            self.segs
                .iter()
                .copied()
                .filter(|(_, a, b)| a.y.max(b.y) >= lo && a.y.min(b.y) <= hi)
                .collect()
        }
    }

    impl Vertices for Numbering {
        fn vertex(&mut self, p: Pt) {
            if let Some(l) = self.last {
                self.segs.push((self.next, l, p));
                self.next += 1;
            }
            self.last = Some(p);
        }
        fn window(&self) -> Option<(i32, i32)> {
            self.window
        }
        fn jump(&mut self, p: Pt, n: u32) {
            assert!(self.last.is_some(), "a jump never starts a contour");
            self.next += n;
            self.last = Some(p);
        }
    }

    #[test]
    fn the_y_estimate_is_within_its_error_of_the_vertex() {
        let mut rng = Lcg(0x0123_4567_89ab_cdef);
        let mut next = |m: u64| rng.below(m);
        let mut worst = 0f64;
        for case in 0..20_000 {
            let a = (next(u64::from(MAX_RADIUS)) as u32) >> (next(16) as u32);
            let b = (next(u64::from(MAX_RADIUS)) as u32) >> (next(16) as u32);
            let c = Pt::new(
                next(1 << 22) as i64 - (1 << 21),
                next(1 << 22) as i64 - (1 << 21),
            );
            let frame = EllipseFrame::new(c, a, b, UNIT_X);
            // Scales as curves use them: 1, and g or f up to 1.12.
            let scale = Q30 + (next(Q30 as u64 / 8) as i64) * (case % 2);
            let t0 = next(1 << 32) as i64 - (1 << 31);
            let e = YEstimate::new(&frame, t0, scale).unwrap();
            for _ in 0..8 {
                let t = next(1 << 33) as i64 - (1 << 32);
                let d = (frame.point(t0 + t, scale).y - e.y(t)).abs();
                assert!(d <= e.err, "case {case}: {d} > {}", e.err);
                worst = worst.max(d as f64 / e.err as f64);
            }
        }
        // Rotated frames have no estimate.
        let r = EllipseFrame::new(Pt::new(0, 0), 100, 50, Unit::from_angle(1 << 28));
        assert!(YEstimate::new(&r, 0, Q30).is_none());
        assert!(worst > 0.2, "the bound is not loose beyond use: {worst}");
    }

    #[test]
    fn pieces_outside_the_window_leave_out_only_segments_outside_it() {
        // Random ellipses, circles, arcs and windows of 1 to 40 rows near
        // them: the segments that meet the window, and their numbers, are
        // those of the polygon computed whole; so is the count.
        let mut rng = Lcg(0x9e37_79b9_7f4a_7c15);
        let mut next = |m: u64| rng.below(m);
        let mut jumped = 0;
        for case in 0..3000 {
            let r = 256 + next(300 * 1024) as i64;
            let b = if case % 3 == 0 {
                r
            } else {
                256 + next(r as u64) as i64
            };
            let c = Pt::new(next(400 * 1024) as i64, next(400 * 1024) as i64);
            let angle = if case % 2 == 0 {
                0
            } else {
                next(1 << 32) as u32
            };
            let frame = EllipseFrame::new(c, r as u32, b as u32, Unit::from_angle(angle));
            let tol = Tolerance::new(1 + next(12) as u16);
            // Windows anywhere near the shape, or (every other case) a
            // thin one at its top or bottom, where a piece's middle
            // bulges past its ends.
            let th = f64::from(angle) / TURN as f64 * 2.0 * core::f64::consts::PI;
            let half = ((r as f64 * th.sin()).powi(2) + (b as f64 * th.cos()).powi(2)).sqrt();
            let (y0, rows) = if case % 2 == 1 {
                let edge = if next(2) == 0 { -half } else { half };
                let y = c.y + edge as i64 - 96 + next(192) as i64;
                (y - next(2) as i64 * 1023, 1)
            } else {
                (
                    c.y - r - 2048 + next(2 * r as u64 + 4096) as i64,
                    1 + next(40) as i64,
                )
            };
            let w = (y0 as i32, (y0 + rows * 1024 - 1) as i32);
            let t0 = next(1 << 32) as i64 - (1 << 31);
            let sweep = next(2 * TURN as u64 + 1) as i64 - TURN;
            let reverse = case % 5 == 0;
            let (mut whole, mut culled) = (Numbering::new(None), Numbering::new(Some(w)));
            if case % 4 == 0 {
                ellipse_points(&frame, t0, reverse, tol, &mut whole);
                ellipse_points(&frame, t0, reverse, tol, &mut culled);
            } else {
                arc_points(&frame, t0, sweep, tol, &mut whole);
                arc_points(&frame, t0, sweep, tol, &mut culled);
            }
            assert_eq!(whole.next, culled.next, "case {case}: the numbering");
            assert_eq!(whole.meeting(w), culled.meeting(w), "case {case}");
            jumped += whole.segs.len() - culled.segs.len();
        }
        // The test exercised the jumps.
        assert!(jumped > 100_000, "{jumped}");
    }

    #[test]
    fn cubic_pieces_per_quarter() {
        assert_eq!(pieces_per_quarter(917), 1);
        assert_eq!(pieces_per_quarter(918), 2);
        assert_eq!(pieces_per_quarter(1 << 23), 5);
        // 1 / (4 e(pi/2)) with e = 2 sin^6(pi/8) / (27 cos^2(pi/8)).
        let p = core::f64::consts::PI / 8.0;
        let e = 2.0 * p.sin().powi(6) / (27.0 * p.cos().powi(2));
        assert_eq!((0.25 / e).floor(), 917.0);
    }
}
