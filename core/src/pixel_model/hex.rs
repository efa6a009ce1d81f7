//! The 7-point hexagonal pixel of seed 003, sampled on its brick lattice.
//!
//! Pixel `(i, j)` with centre `(x, y) = (i + 1/2, j + 1/2)` has the seed's
//! seven points `T7 = (x, y)` (weight 2/8) and `T1..T6 = (x ∓ 1/4, y ± 1/2),
//! (x ± 1/2, y)` (1/8 each; the seed's cone model with `V1 : V7` giving the
//! centre twice a ring point). Neighbours share ring points: `T3` of a pixel
//! is `T6` of the pixel to its right, its `T1`, `T2` are `T5`, `T4` of the
//! pixel below. So the points of all pixels form a lattice of rows half a
//! pixel apart, points half a pixel apart along a row:
//!
//! - row A (`y = j + 1/2`): at `x = i + 1/2` (pixel `i`'s centre, weight 2)
//!   and `x = i + 1` (shared by pixels `i` and `i + 1`, 1 each);
//! - row B (`y = j + 1`): at `x = i + 1/4` and `x = i + 3/4` (shared by the
//!   pixels `(i, j)` and `(i, j + 1)`, 1 each).
//!
//! Every lattice point carries 2/8 in all, and a unit square holds exactly
//! four of them wherever it lies: equal energy, exactly (eq. 4 of seed 000).
//! The points are sampled with the aliased walk (top-left rule, so shared
//! edges stay seamless) on a grid twice as fine, shifted a quarter pixel so
//! its sample centres fall on the lattice: one walk for the A rows, one for
//! the B rows.
//!
//! The 19-point pixel ([`HEX19_POINTS`]) uses the same lattice and walks;
//! its footprint adds ring 2, one lattice step further out: in its own A
//! row the points at `x ± 1`, in the A rows one pixel above and below the
//! points at `x` and `x ± 1/2`, in the B rows those at `x ± 3/4`. Each
//! sample row's cover change is spread over the footprints by
//! `splat_row` (shifts, table look-ups and adds). Why its weights differ
//! from the seed's: see [`pixel_model`](crate::pixel_model).

use super::ModelCover;
use core::ops::Range;

/// The seed-003 evaluation function at the seven points of a pixel, for an
/// edge with increments `(dx, dy)`, as offsets from its value at the centre
/// `T7`: `OF(x, y) = y dx - x dy`, taken at `T1..T6` and scaled by 4 so the
/// quarter-pixel offsets are exact: `[T1, T2, T3, T4, T5, T6, T7]` =
/// `[2dx + dy, 2dx - dy, -2dy, -(2dx + dy), -(2dx - dy), 2dy, 0]` (the
/// seed's `(2Δx ± Δy)/4` and `Δy/2`, times 4). Shifts and adds only;
/// opposite points (`T1`/`T4`, `T2`/`T5`, `T3`/`T6`) have opposite offsets.
/// (SPEC §6 lists `T4` and `T5` the other way round; evaluating `OF` at the
/// points as it places them gives the order here, which the example checks.)
///
/// ```
/// use softedge::pixel_model::hex7_offsets;
/// let (dx, dy) = (5, 3);
/// let of = |x4: i64, y4: i64| y4 * dx - x4 * dy; // 4 * OF at (x4/4, y4/4)
/// let pts = [(-1, 2), (1, 2), (2, 0), (1, -2), (-1, -2), (-2, 0), (0, 0)];
/// let offsets = hex7_offsets(dx, dy);
/// for (k, (x4, y4)) in pts.into_iter().enumerate() {
///     assert_eq!(of(x4, y4), offsets[k]);
/// }
/// ```
pub fn hex7_offsets(dx: i64, dy: i64) -> [i64; 7] {
    let (a, b) = ((dx << 1) + dy, (dx << 1) - dy);
    [a, b, -(dy << 1), -a, -b, dy << 1, 0]
}

use super::splat::{splat_row, suffix_sums, RowFootprint};
use super::walk_samples;
use super::MODEL_ONE as COVER_ONE;
use crate::arith::div_ceil;
use crate::band::BandBuffer;
use crate::edge::CoverSink;
use crate::{SubPoint, SUB_ONE};

/// Sum of a pixel's point weights: 2 + 6 * 1.
const TOTAL: i32 = 8;

/// Walks edge `p0 -> p1` of a primitive for the hexagonal 7-point model,
/// writing coverage changes for pixel `rows` into the band.
pub(crate) fn walk_hex7<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    p0: SubPoint,
    p1: SubPoint,
    rows: Range<i32>,
) {
    let quarter = SUB_ONE / 4;
    // Fine grid: 1/2 px; its sample centres are at f/2 + 1/4. Shifting the
    // geometry up by 1/4 px puts fine row g on y = g/2 + 1/2: even g are A
    // rows (j = g/2), odd g are B rows (between j = (g-1)/2 and j + 1).
    // A rows sample x = f/2 (shift right by 1/4), B rows x = f/2 + 1/4.
    let fine = |p: SubPoint, dx: i32| {
        SubPoint::new(
            p.x.saturating_add(dx).saturating_mul(2),
            p.y.saturating_sub(quarter).saturating_mul(2),
        )
    };
    let fine_rows = rows.start.saturating_mul(2) - 1..rows.end.saturating_mul(2) + 1;
    for row_a in [true, false] {
        let dx = if row_a { quarter } else { 0 };
        let mut sink = HexRows {
            band: &mut *band,
            row_a,
            rows: rows.clone(),
        };
        walk_samples(fine(p0, dx), fine(p1, dx), fine_rows.clone(), &mut sink);
    }
}

/// Turns one row type's cover changes into pixel coverage.
struct HexRows<'a, 'b, const C: usize> {
    band: &'a mut BandBuffer<'b, C>,
    row_a: bool,
    rows: Range<i32>,
}

impl<const C: usize> HexRows<'_, '_, C> {
    /// Cover change `unit * full` from pixel `p_full`, and the cut pixels'
    /// partial weights (`partial[t]` for the pixel whose points start `t`
    /// fine columns left of `c`).
    fn spread(&mut self, j: i32, c: i64, unit: i32, full: i32, partial: &[(i64, i32)]) {
        if !self.rows.contains(&j) {
            return;
        }
        let p_full = div_ceil(c, 2);
        self.band.add_model_cover(p_full as i32, j, unit * full);
        for &(p_off, w) in partial {
            let p = (p_full - p_off) as i32;
            let v = unit * w;
            self.band.add_model_cover(p, j, v);
            self.band.add_model_cover(p + 1, j, -v);
        }
    }
}

impl<const C: usize> CoverSink for HexRows<'_, '_, C> {
    fn cover(&mut self, c: i32, g: i32, delta: i32) {
        let is_a = g.rem_euclid(2) == 0;
        if is_a != self.row_a {
            return;
        }
        let unit = delta.signum() * (COVER_ONE / TOTAL);
        let c = i64::from(c);
        if is_a {
            // Pixel i's A points: fine columns 2i (weight 1), 2i+1 (2),
            // 2i+2 (1). Samples at or right of c are covered.
            let j = g.div_euclid(2);
            let odd = c.rem_euclid(2) == 1;
            // c = 2m: pixels >= m full; pixel m-1 keeps its point 2m (1).
            // c = 2m+1: pixels >= m+1 full; pixel m keeps 2m+1, 2m+2 (3).
            let partial: &[(i64, i32)] = if odd { &[(1, 3)] } else { &[(1, 1)] };
            self.spread(j, c, unit, 4, partial);
        } else {
            // Pixel i's B points in this row: fine columns 2i and 2i+1
            // (1 each), for the pixel rows above and below the B row.
            let j_above = (g - 1).div_euclid(2);
            let odd = c.rem_euclid(2) == 1;
            let partial: &[(i64, i32)] = if odd { &[(1, 1)] } else { &[] };
            for j in [j_above, j_above + 1] {
                self.spread(j, c, unit, 2, partial);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// The 19-point hexagonal pixel.

/// Weight units of a Hex19 pixel: its 19 weights add to `MODEL_ONE`.
const HEX19_TOTAL: i32 = COVER_ONE;
/// Each of the lattice's 4 point classes carries a quarter of it.
const HEX19_CLASS: i32 = HEX19_TOTAL / 4;

/// The seed's cone weights as fractions of the pixel: `V1`, `(V7 - V1)/6`,
/// `(1 - V7)/12` (seed 003; SPEC §6).
const SEED_V1: f64 = 0.123;
const SEED_V7: f64 = 0.492;
const SEED_CENTRE: f64 = SEED_V1 * HEX19_TOTAL as f64;
const SEED_RING1: f64 = (SEED_V7 - SEED_V1) / 6.0 * HEX19_TOTAL as f64;
const SEED_RING2: f64 = (1.0 - SEED_V7) / 12.0 * HEX19_TOTAL as f64;

/// The integer weights of the orbits of a class nearest (least squares)
/// to the seed's: a class holding `k_outer` ring-2 points of one orbit and
/// `k_inner` points of another orbit (target `inner`) must add to
/// [`HEX19_CLASS`]; spreading the difference equally over the class's
/// `k_outer + k_inner` points is the least-squares change. Returns
/// `(inner, outer)`: `outer` rounded to nearest, `inner` takes the rest
/// (exact in integers because `HEX19_CLASS - k_outer * outer` is a multiple
/// of `k_inner` for the classes used).
const fn project(inner: f64, k_inner: i32, k_outer: i32) -> (i32, i32) {
    let sum = inner * k_inner as f64 + SEED_RING2 * k_outer as f64;
    let shift = (HEX19_CLASS as f64 - sum) / (k_inner + k_outer) as f64;
    let outer = (SEED_RING2 + shift + 0.5) as i32;
    ((HEX19_CLASS - k_outer * outer) / k_inner, outer)
}

/// Class `A0` (row A, centres): the centre and the four ring-2 points
/// `(±1, 0)`, `(0, ±1)` (both orbits shifted alike).
const CLASS_A0: (i32, i32) = project(SEED_CENTRE, 1, 4);
/// Class `A½`: the ring-1 points `(±1/2, 0)` and ring-2 `(±1/2, ±1)`.
const CLASS_AH: (i32, i32) = project(SEED_RING1, 2, 4);
/// Each `B` class: two ring-1 points `(±1/4, ±1/2)` and two ring-2 points
/// `(±3/4, ±1/2)`.
const CLASS_B: (i32, i32) = project(SEED_RING1, 2, 2);

/// The 19 points of a Hex19 pixel: `(x4, y4, weight)` with the offset from
/// the pixel's centre in quarter pixels and the weight in units of
/// `1/4096` of the pixel (the 19 weights add to 4096). Centre; ring 1
/// (`(±1/2, 0)`, `(±1/4, ±1/2)`); ring 2 (`(±1, 0)`, `(0, ±1)`,
/// `(±1/2, ±1)`, `(±3/4, ±1/2)`). Derived from the seed's cone weights as
/// the module docs of [`pixel_model`](crate::pixel_model) explain:
/// 468, 224, 295, 139, 139, 144, 217.
///
/// ```
/// use softedge::pixel_model::HEX19_POINTS;
/// assert_eq!(HEX19_POINTS.iter().map(|p| p.2).sum::<i32>(), 4096);
/// // Every point of the lattice carries 1024 in all: the pixels that hold
/// // a point are the translates of the offsets in the same class mod 1 px.
/// for class in [(0, 0), (2, 0), (1, 2), (3, 2)] {
///     let total: i32 = HEX19_POINTS
///         .iter()
///         .filter(|p| (p.0.rem_euclid(4), p.1.rem_euclid(4)) == class)
///         .map(|p| p.2)
///         .sum();
///     assert_eq!(total, 1024);
/// }
/// ```
pub const HEX19_POINTS: [(i32, i32, i32); 19] = {
    let (c, b_ax) = CLASS_A0;
    let (a_row, b_far) = CLASS_AH;
    let (a_diag, b_diag) = CLASS_B;
    [
        (0, 0, c),
        (-2, 0, a_row),
        (2, 0, a_row),
        (-1, -2, a_diag),
        (1, -2, a_diag),
        (-1, 2, a_diag),
        (1, 2, a_diag),
        (-4, 0, b_ax),
        (4, 0, b_ax),
        (0, -4, b_ax),
        (0, 4, b_ax),
        (-2, -4, b_far),
        (2, -4, b_far),
        (-2, 4, b_far),
        (2, 4, b_far),
        (-3, -2, b_diag),
        (3, -2, b_diag),
        (-3, 2, b_diag),
        (3, 2, b_diag),
    ]
};

/// A row (the centre's row): fine columns `2i - 1 ..= 2i + 3` of pixel `i`,
/// offsets `-1, -1/2, 0, 1/2, 1` px.
const HEX19_A0: [u16; 6] =
    suffix_sums([CLASS_A0.1, CLASS_AH.0, CLASS_A0.0, CLASS_AH.0, CLASS_A0.1]);
/// A rows one pixel above and below: fine columns `2i ..= 2i + 2`,
/// offsets `-1/2, 0, 1/2` px.
const HEX19_A1: [u16; 4] = suffix_sums([CLASS_AH.1, CLASS_A0.1, CLASS_AH.1]);
/// B rows half a pixel above and below: fine columns `2i - 1 ..= 2i + 2`,
/// offsets `-3/4, -1/4, 1/4, 3/4` px.
const HEX19_B: [u16; 5] = suffix_sums([CLASS_B.1, CLASS_B.0, CLASS_B.0, CLASS_B.1]);

/// Walks edge `p0 -> p1` of a primitive for the hexagonal 19-point model,
/// writing coverage changes for pixel `rows` into the band. The lattice and
/// the two walks are those of the 7-point model; only the footprint grows.
pub(crate) fn walk_hex19<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    p0: SubPoint,
    p1: SubPoint,
    rows: Range<i32>,
) {
    let quarter = SUB_ONE / 4;
    let fine = |p: SubPoint, dx: i32| {
        SubPoint::new(
            p.x.saturating_add(dx).saturating_mul(2),
            p.y.saturating_sub(quarter).saturating_mul(2),
        )
    };
    // Pixel row j takes fine rows 2j - 2 ..= 2j + 2.
    let fine_rows = rows.start.saturating_mul(2).saturating_sub(2)
        ..rows.end.saturating_mul(2).saturating_add(1);
    for row_a in [true, false] {
        let dx = if row_a { quarter } else { 0 };
        let mut sink = Hex19Rows {
            band: &mut *band,
            row_a,
            rows: rows.clone(),
        };
        walk_samples(fine(p0, dx), fine(p1, dx), fine_rows.clone(), &mut sink);
    }
}

/// Spreads one row type's cover changes over the Hex19 footprints.
struct Hex19Rows<'a, 'b, const C: usize> {
    band: &'a mut BandBuffer<'b, C>,
    row_a: bool,
    rows: Range<i32>,
}

impl<const C: usize> CoverSink for Hex19Rows<'_, '_, C> {
    fn cover(&mut self, c: i32, g: i32, delta: i32) {
        let is_a = g.rem_euclid(2) == 0;
        if is_a != self.row_a {
            return;
        }
        let sign = delta.signum();
        let c = i64::from(c);
        let fp = |o: i64, cum: &'static [u16]| RowFootprint { shift: 1, o, cum };
        if is_a {
            let j = g.div_euclid(2);
            splat_row(self.band, &self.rows, j, c, sign, fp(-1, &HEX19_A0));
            for jj in [j - 1, j + 1] {
                splat_row(self.band, &self.rows, jj, c, sign, fp(0, &HEX19_A1));
            }
        } else {
            let j_above = (g - 1).div_euclid(2);
            for jj in [j_above, j_above + 1] {
                splat_row(self.band, &self.rows, jj, c, sign, fp(-1, &HEX19_B));
            }
        }
    }
}
