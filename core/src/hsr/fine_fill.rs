//! Exact box coverage of polygons with vertices on the fine grid
//! ([`FinePoint`], 1/1024 px): how Weiler–Atherton's visible pieces, whose
//! cut vertices lie between the 1/16-px vertices the edge walker takes,
//! are accumulated.
//!
//! ## The idea
//!
//! As in the edge walker (see [`edge`](crate::edge)), a polygon's coverage
//! of a pixel is the sum over its edges of the signed area each edge cuts
//! off to its right, inside its own y-range in the pixel's row. For one
//! edge inside one row strip `[ya, yb]`, with `X(y)` its x at height `y`,
//!
//! ```text
//!   F(t) = ∫ max(t - X(y), 0) dy      (area right of the edge, left of x = t)
//!   cell x  gets  F(x + 1) - F(x)      (the pixel [x, x+1) of the strip)
//! ```
//!
//! `F` is exact in integers: `X` is linear over the strip, so `F` is
//! `(t - mean X) h` where the strip lies wholly left of `t`, and
//! `(t - X_min)^2 h / (2 |X_b - X_a|)` where `t` cuts it. Every column right
//! of the edge gets the strip height `h`: one cover change for the band's
//! span sweep, after the edge's last pixel. Each cell's area is rounded
//! once, to nearest (1/4096 px, the band's coverage unit), from the edge
//! alone (walked top to bottom, its winding applied after rounding), so two
//! pieces sharing an edge get exactly opposite values there: their
//! coverages sum to the union's, no seam. An edge whose two ends lie on
//! the 1/16-px grid is handed to the edge walker instead
//! ([`walk_edge`](crate::edge::walk_edge), exact mode): a polygon with only
//! such vertices gets [`fill`](crate::raster)'s bits, and every piece that
//! shares such an edge walks it the same way.
//!
//! Error: at most half a coverage unit (1/8192 px) per edge and cell,
//! against the exact area of the polygon with these vertices (the walker's
//! edges: 3/4096 px, see [`edge`](crate::edge)).
//!
//! ## Ranges
//!
//! Fine coordinates within `±2^21` (the coordinate range), so an edge has
//! `|dx|, dy <= 2^22`; a row strip is `h <= 2^10` high. With
//! `N = X dy` (`|N| < 2^45`) and `D = 2 dy |N_b - N_a|` (`< 2^55`), the
//! scaled areas `F D` stay below `2^103` in `i128`.
//!
//! ## Cost
//!
//! Per edge cell two `i128` evaluations of `F` with a division: this is
//! setup-grade work done per pixel, against the rule the edge walker keeps
//! (add and compare per pixel). It serves until the edge walker takes
//! fine vertices itself; then [`fill_fine`] becomes a call of it.

use super::super::band::BandBuffer;
use crate::edge::{walk_edge, AreaMode};
use crate::geom::{FinePoint, SubPoint, FINE_BITS, FINE_LIMIT, SUB_BITS};
use crate::shade::{Plane, PLANE_FRAC};
use crate::COVER_BITS;

/// One pixel in fine units.
const ONE: i128 = 1 << FINE_BITS;
/// Fine units squared per coverage unit: `1024^2 / 4096`.
const FINE2_PER_COVER: i128 = 1 << (2 * FINE_BITS - COVER_BITS);
/// Coverage units per fine unit of height: `4096 / 1024`.
const COVER_PER_FINE: i128 = 1 << (COVER_BITS - FINE_BITS);

/// Twice the signed area of a closed fine polygon (fine units squared;
/// positive when clockwise on screen, y down).
pub(crate) fn area2_fine(v: &[FinePoint]) -> i128 {
    let n = v.len();
    let mut sum = 0i128;
    for k in 0..n {
        let (a, b) = (v[k], v[(k + 1) % n]);
        sum += i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y);
    }
    sum
}

/// Accumulates the simple polygon `v` (fine vertices within the coordinate
/// range; either orientation) with the Gouraud plane `plane`, exact box
/// coverage (module doc). Vertices outside the range are clamped into it.
pub(crate) fn fill_fine<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    v: &[FinePoint],
    plane: &Plane<C>,
) {
    let info = band.band();
    let clamp = |p: &FinePoint| {
        FinePoint::new(
            p.x.clamp(-FINE_LIMIT, FINE_LIMIT),
            p.y.clamp(-FINE_LIMIT, FINE_LIMIT),
        )
    };
    let (mut y_min, mut y_max, mut x_min, mut x_max) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    for p in v.iter().map(clamp) {
        y_min = y_min.min(p.y);
        y_max = y_max.max(p.y);
        x_min = x_min.min(p.x);
        x_max = x_max.max(p.x);
    }
    let band_end = info.y0 + i32::from(info.rows);
    let rows = (y_min >> FINE_BITS).max(info.y0)..((y_max >> FINE_BITS) + 1).min(band_end);
    // Nothing to add above, below, right or left of the band (left of it
    // the covers cancel at column 0).
    if rows.start >= rows.end || (x_min >> FINE_BITS) >= i32::from(info.width) || x_max <= 0 {
        return;
    }
    let orientation = -area2_fine(v).signum();
    if orientation == 0 {
        return;
    }
    let n = v.len();
    for k in 0..n {
        let (p0, p1) = (clamp(&v[k]), clamp(&v[(k + 1) % n]));
        // Walked top to bottom; the winding says which side is inside.
        if let (Some(s0), Some(s1)) = (on_sub_grid(p0), on_sub_grid(p1)) {
            // Both ends on the 1/16-px grid: the edge walker's own edge
            // (the same bits as `fill`, and the same edge for every piece
            // that has it, so shared edges still cancel).
            walk_edge(
                s0,
                s1,
                orientation as i32,
                plane,
                AreaMode::Exact,
                rows.clone(),
                band,
            );
            continue;
        }
        let (top, bottom, dir) = match p0.y.cmp(&p1.y) {
            core::cmp::Ordering::Less => (p0, p1, 1),
            core::cmp::Ordering::Greater => (p1, p0, -1),
            core::cmp::Ordering::Equal => continue,
        };
        walk(band, top, bottom, orientation * dir, plane, rows.clone());
    }
    band.sweep(rows.start, rows.end, plane);
}

/// The point as a [`SubPoint`] when it lies on the 1/16-px grid.
fn on_sub_grid(p: FinePoint) -> Option<SubPoint> {
    const STEP: i32 = 1 << (FINE_BITS - SUB_BITS);
    (p.x % STEP == 0 && p.y % STEP == 0).then(|| SubPoint::new(p.x / STEP, p.y / STEP))
}

/// One edge, `top.y < bottom.y`, with winding `w` (`±1`), over the frame
/// rows `rows`.
fn walk<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    top: FinePoint,
    bottom: FinePoint,
    w: i128,
    plane: &Plane<C>,
    rows: core::ops::Range<i32>,
) {
    let width = i64::from(band.band().width);
    let (x0, y0) = (i128::from(top.x), i128::from(top.y));
    let (dx, dy) = (
        i128::from(bottom.x) - x0,
        i128::from(bottom.y) - i128::from(top.y),
    );
    let first = (top.y >> FINE_BITS).max(rows.start);
    let last = ((bottom.y - 1) >> FINE_BITS).min(rows.end - 1);
    for r in first..=last {
        let ya = (i128::from(r) * ONE).max(y0);
        let yb = (i128::from(r + 1) * ONE).min(i128::from(bottom.y));
        let h = yb - ya;
        if h <= 0 {
            continue;
        }
        // x times dy at the strip's top and bottom.
        let na = x0 * dy + dx * (ya - y0);
        let nb = x0 * dy + dx * (yb - y0);
        let (lo, hi) = (na.min(nb), na.max(nb));
        let strip = Strip {
            dy,
            h,
            na,
            nb,
            lo,
            // A vertical strip has no `|N_b - N_a|`: F D with D = dy then.
            d: if hi > lo { 2 * dy * (hi - lo) } else { dy },
        };
        let col = |n: i128| div_floor(n, ONE * dy);
        let (c_lo, c_hi) = (col(lo) as i64, col(hi) as i64);
        let start = c_lo.max(0);
        let end = c_hi.min(width - 1);
        if start <= end {
            let mut f_left = strip.scaled_area(i128::from(start) * ONE);
            for x in start..=end {
                let f_right = strip.scaled_area(i128::from(x + 1) * ONE);
                let s = div_round(f_right - f_left, FINE2_PER_COVER * strip.d);
                f_left = f_right;
                if s == 0 {
                    continue;
                }
                let i = plane.at(x as i32, r);
                let mut values = [0i32; C];
                for (v, &ic) in values.iter_mut().zip(&i) {
                    // As the edge walker: the product floored, then signed.
                    *v = (w * ((i128::from(ic) * s) >> PLANE_FRAC)) as i32;
                }
                band.add_cell(x as i32, r, &values);
            }
        }
        // Whole height from the column after the edge's last pixel.
        let cover = (w * COVER_PER_FINE * h) as i32;
        band.add_cover(
            (c_hi + 1).clamp(i64::from(i32::MIN), width) as i32,
            r,
            cover,
        );
    }
}

/// One edge inside one row strip: `N = X dy` at its top (`na`) and bottom
/// (`nb`), the smaller `lo`, the strip height `h` and the scale `d` of
/// [`scaled_area`](Self::scaled_area).
struct Strip {
    dy: i128,
    h: i128,
    na: i128,
    nb: i128,
    lo: i128,
    d: i128,
}

impl Strip {
    /// `F(t) * d` (module doc), `t` in fine units: exact.
    fn scaled_area(&self, t: i128) -> i128 {
        let tn = t * self.dy;
        if tn <= self.lo {
            return 0;
        }
        let hi = self.na.max(self.nb);
        if hi == self.lo {
            // Vertical in this strip: (t - X) h, times d = dy.
            return (tn - self.lo) * self.h;
        }
        if tn >= hi {
            // (t - (Xa + Xb) / 2) h, times d = 2 dy |Nb - Na|.
            (2 * tn - self.na - self.nb) * self.h * (hi - self.lo)
        } else {
            // (t - X_min)^2 h / (2 |Xb - Xa|), times d.
            (tn - self.lo) * (tn - self.lo) * self.h
        }
    }
}

/// `floor(n / d)` for `d > 0`.
fn div_floor(n: i128, d: i128) -> i128 {
    let q = n.checked_div(d).unwrap_or(0);
    if n.checked_rem(d).unwrap_or(0) != 0 && ((n < 0) != (d < 0)) {
        q - 1
    } else {
        q
    }
}

/// `n / d` rounded to nearest, halves away from zero, for `n >= 0`, `d > 0`.
fn div_round(n: i128, d: i128) -> i128 {
    (n + d / 2).checked_div(d).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;

    use super::*;
    use crate::band::Band;
    use crate::raster::{fill, RenderStyle};
    use crate::SubPoint;

    fn frame(draw: impl Fn(&mut BandBuffer<'_, 1>)) -> vec::Vec<i32> {
        let band = Band {
            width: 24,
            y0: 0,
            rows: 24,
        };
        let mut acc = vec![0i32; BandBuffer::<1>::acc_len(24, 24)];
        let mut cover = vec![0i32; BandBuffer::<1>::cover_len(24, 24)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([100]);
        draw(&mut buf);
        (0..24)
            .flat_map(|y| (0..24).map(move |x| (x, y)))
            .map(|(x, y)| buf.raw(x, y).unwrap()[0])
            .collect()
    }

    #[test]
    fn grid_rectangles_get_the_edge_walkers_bits() {
        let sub = [(19, 5), (300, 5), (300, 211), (19, 211)].map(|(x, y)| SubPoint::new(x, y));
        let fine = sub.map(FinePoint::from);
        let plane =
            Plane::triangle([sub[0], sub[1], sub[2]], [[4000], [1000], [2500]], [100]).unwrap();
        let a = frame(|b| fill(b, &sub, &plane, &RenderStyle::default()));
        let f = frame(|b| fill_fine(b, &fine, &plane));
        assert_eq!(a, f);
    }

    #[test]
    fn a_triangle_split_on_a_fine_point_covers_like_the_whole() {
        // Coverage only (flat colour 4095 over 0): the two halves of a
        // triangle cut through a point between the 1/16 grid points sum to
        // the whole triangle's coverage, pixel for pixel.
        let p = |x, y| FinePoint::new(x, y);
        let (a, b, c) = (p(1000, 700), p(20000, 3000), p(7000, 21000));
        let m = p(13517, 11999); // on no grid but the fine one (not on bc)
        let plane = Plane::flat([4095], [0]);
        let whole = frame(|bf| fill_fine(bf, &[a, b, m, c], &plane));
        let parts = frame(|bf| {
            fill_fine(bf, &[a, b, m], &plane);
            fill_fine(bf, &[a, m, c], &plane);
        });
        assert_eq!(whole, parts);
    }
}
