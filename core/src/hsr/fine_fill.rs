//! Polygons with vertices on the fine grid ([`FinePoint`], 1/1024 px),
//! accumulated with a Gouraud plane: how Weiler–Atherton's visible pieces,
//! whose cut vertices lie between the 1/16-px vertices of their triangles,
//! are drawn.
//!
//! The edge walker takes fine vertices: every edge is walked in exact mode
//! (each edge pixel within 2/65536 px of its exact area) into the band's
//! scratch, and the polygon is composed once by seed 000's addition, its
//! coverage the winding integral times its orientation. An edge's cells
//! depend on the edge alone (walked top to bottom), so two pieces sharing
//! an edge cancel it exactly: their coverages sum to the union's, no seam;
//! a polygon whose vertices all lie on the 1/16-px grid gets exactly the
//! bits of [`fill`](crate::raster) (the same edges, walked the same way).
//! Per pixel: the walker's and the sweep's additions and compares only.

use super::super::band::{BandBuffer, ComposeOp, Coverage, Paint};
use crate::edge::{AreaMode, EdgeWalk};
use crate::geom::{FinePoint, FINE_BITS, FINE_LIMIT};
use crate::shade::Plane;
use crate::style::Opacity;

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

/// Accumulates the simple polygon `v` (fine vertices; either orientation)
/// with the Gouraud plane `plane` of absolute intensity (fitted over a zero
/// background), exact box coverage. Vertices outside the coordinate range
/// are clamped into it.
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
    let cols = info.column_range();
    // Nothing to add above, below, right or left of the band (left of it
    // the covers cancel at its first column).
    if rows.start >= rows.end
        || (x_min >> FINE_BITS) >= cols.end
        || (x_max >> FINE_BITS) < cols.start
    {
        return;
    }
    // A clockwise outline (positive area, y down) has its inside left of
    // its downward edges: its winding integral is -coverage.
    let orientation = match area2_fine(v).signum() {
        0 => return,
        s => -s as i32,
    };
    let n = v.len();
    for k in 0..n {
        let (p0, p1) = (clamp(&v[k]), clamp(&v[(k + 1) % n]));
        if let Some(mut w) = EdgeWalk::new(p0, p1, AreaMode::Exact, cols.clone()) {
            w.walk(rows.clone(), band);
        }
    }
    band.compose(
        rows.start,
        rows.end,
        Coverage::Signed(orientation),
        &Paint::Plane(plane),
        ComposeOp::Add(Opacity::OPAQUE),
    );
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
        let mut acc = vec![0i32; BandBuffer::<1>::acc_len(24, 24)];
        let mut cover = vec![0i32; BandBuffer::<1>::cover_len(24, 24)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(24, 0, 24)).unwrap();
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
            Plane::triangle([sub[0], sub[1], sub[2]], [[4000], [1000], [2500]], [0]).unwrap();
        let add = ComposeOp::Add(Opacity::OPAQUE);
        let a = frame(|b| fill(b, &sub, &Paint::Plane(&plane), add, &RenderStyle::default()));
        let f = frame(|b| fill_fine(b, &fine, &plane));
        assert_eq!(a, f);
    }

    #[test]
    fn a_triangle_split_on_a_fine_point_covers_like_the_whole() {
        // Coverage only (flat colour 4095 over 0): the two halves of a
        // quadrilateral cut along a diagonal through a point between the
        // 1/16 grid points sum to the whole, pixel for pixel.
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
