//! Depth triangles of a convex quad whose corners may lie slightly outside
//! the coordinate range: a line's 1-px rectangle at the documented limit.
//!
//! A line may run along or end on `|x| = 2048 px` (or `|y|`): its endpoints
//! are in range, but its rectangle's corners lie up to half a pixel (plus
//! the rounding to 1/16 px) beyond, where [`Line::draw`](crate::Line::draw)
//! still fills them but every hidden-surface method rejects a vertex
//! (issue #18). [`quad_depth_triangles`] clips such a quad to the range
//! instead: Sutherland–Hodgman against the four limit lines, each cut
//! point on its limit line, its other coordinate, colour and depth
//! interpolated along the cut edge and rounded to nearest (halves away
//! from zero). Nothing inside the range moves but the cut points, and they
//! move only along the limit lines, by at most 1/32 px: no frame pixel
//! changes except those touching the limit itself (a frame is at most 2048
//! px wide, so its pixels lie in `[0, 2048)`), and there by at most 1/64 of
//! a pixel per cut edge. A quad inside the range gives its two triangles
//! unchanged, bit for bit.
//!
//! Integer ranges: corners within `2^15 + 2^5` sub-pixels, colours and
//! depths below `2^16`; every product below `2^38` in `i64`.

use super::DepthTriangle;
use crate::geom::{SubPoint, COORD_LIMIT_SUB};

/// A corner with its attributes, in `i64` for the interpolation.
#[derive(Clone, Copy)]
struct Corner<const C: usize> {
    p: [i64; 2],
    color: [i64; C],
    depth: i64,
}

/// Most corners after clipping a quad by four lines.
const MAX_CORNERS: usize = 8;

/// Emits the quad `q` (convex, corners in order) as depth triangles with a
/// colour and a depth per corner: `(q0, q1, q2)` and `(q0, q2, q3)` when
/// every corner is in range; otherwise the quad clipped to the range (see
/// the module doc), as a fan from its first corner.
pub(crate) fn quad_depth_triangles<const C: usize>(
    q: [SubPoint; 4],
    colors: [[u16; C]; 4],
    depths: [u16; 4],
    mut emit: impl FnMut(DepthTriangle<C>),
) {
    if q.iter().all(|p| p.check().is_ok()) {
        let t = |a: usize, b: usize, c: usize| {
            DepthTriangle::new(
                [q[a], q[b], q[c]],
                [colors[a], colors[b], colors[c]],
                [depths[a], depths[b], depths[c]],
            )
        };
        emit(t(0, 1, 2));
        emit(t(0, 2, 3));
        return;
    }
    let mut poly: heapless::Vec<Corner<C>, MAX_CORNERS> = heapless::Vec::new();
    for k in 0..4 {
        let _ = poly.push(Corner {
            p: [i64::from(q[k].x), i64::from(q[k].y)],
            color: colors[k].map(i64::from),
            depth: i64::from(depths[k]),
        });
    }
    let limit = i64::from(COORD_LIMIT_SUB);
    // (axis, sign): keep `sign * p[axis] <= limit`.
    for (axis, sign) in [(0, 1), (0, -1), (1, 1), (1, -1)] {
        poly = clip(&poly, axis, sign, limit);
    }
    let Some(first) = poly.first().copied() else {
        return;
    };
    for pair in poly.get(1..).unwrap_or(&[]).windows(2) {
        let [b, c] = [pair[0], pair[1]];
        let point = |k: &Corner<C>| {
            // Clipped into the range: the conversions cannot fail.
            SubPoint::new(
                i32::try_from(k.p[0]).unwrap_or(0),
                i32::try_from(k.p[1]).unwrap_or(0),
            )
        };
        let color = |k: &Corner<C>| k.color.map(|v| v.clamp(0, i64::from(u16::MAX)) as u16);
        let depth = |k: &Corner<C>| k.depth.clamp(0, i64::from(u16::MAX)) as u16;
        emit(DepthTriangle::new(
            [point(&first), point(&b), point(&c)],
            [color(&first), color(&b), color(&c)],
            [depth(&first), depth(&b), depth(&c)],
        ));
    }
}

/// One Sutherland–Hodgman stage: the part of `poly` with
/// `sign * p[axis] <= limit`.
fn clip<const C: usize>(
    poly: &[Corner<C>],
    axis: usize,
    sign: i64,
    limit: i64,
) -> heapless::Vec<Corner<C>, MAX_CORNERS> {
    let mut out = heapless::Vec::new();
    let n = poly.len();
    let inside = |k: &Corner<C>| sign * k.p[axis] <= limit;
    for i in 0..n {
        let (v, w) = (poly[i], poly[(i + 1) % n]);
        if inside(&v) {
            let _ = out.push(v);
        }
        if inside(&v) != inside(&w) {
            let _ = out.push(cut(&v, &w, axis, sign * limit));
        }
    }
    out
}

/// The point of the edge `v -> w` on the line `p[axis] = at` (the edge
/// crosses it), attributes interpolated there, rounded to nearest.
fn cut<const C: usize>(v: &Corner<C>, w: &Corner<C>, axis: usize, at: i64) -> Corner<C> {
    let (num, den) = (at - v.p[axis], w.p[axis] - v.p[axis]);
    let lerp = |a: i64, b: i64| a + div_round((b - a) * num, den);
    let mut p = [0i64; 2];
    p[axis] = at;
    p[1 - axis] = lerp(v.p[1 - axis], w.p[1 - axis]);
    let mut color = [0i64; C];
    for (c, (a, b)) in color.iter_mut().zip(v.color.iter().zip(&w.color)) {
        *c = lerp(*a, *b);
    }
    Corner {
        p,
        color,
        depth: lerp(v.depth, w.depth),
    }
}

/// `n / d` rounded to nearest, halves away from zero; 0 for `d = 0`.
fn div_round(n: i64, d: i64) -> i64 {
    let (nu, du) = (n.unsigned_abs(), d.unsigned_abs());
    let q = nu
        .checked_add(du / 2)
        .and_then(|x| x.checked_div(du))
        .and_then(|q| i64::try_from(q).ok())
        .unwrap_or(0);
    if (n < 0) != (d < 0) {
        -q
    } else {
        q
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn collect(q: [SubPoint; 4]) -> heapless::Vec<DepthTriangle<1>, 8> {
        let mut v = heapless::Vec::new();
        quad_depth_triangles(q, [[0], [4000], [4000], [0]], [0, 1000, 1000, 0], |t| {
            let _ = v.push(t);
        });
        v
    }

    #[test]
    fn a_quad_in_range_is_its_two_triangles() {
        let q = [(0, 0), (160, 0), (160, 16), (0, 16)].map(|(x, y)| SubPoint::new(x, y));
        let t = collect(q);
        assert_eq!(t.len(), 2);
        assert_eq!(t[0].vertices, [q[0], q[1], q[2]]);
        assert_eq!(t[1].vertices, [q[0], q[2], q[3]]);
    }

    #[test]
    fn a_quad_across_the_limit_is_clipped_to_it() {
        let l = COORD_LIMIT_SUB;
        // The 1-px rectangle of a line along x = 2048 px, from y = 0 to 10 px.
        let q =
            [(l + 8, 0), (l + 8, 160), (l - 8, 160), (l - 8, 0)].map(|(x, y)| SubPoint::new(x, y));
        let t = collect(q);
        assert!(!t.is_empty());
        let mut area2 = 0i64;
        for tri in &t {
            for v in tri.vertices {
                assert!(v.check().is_ok(), "{v:?}");
            }
            area2 += crate::geom::area2(&tri.vertices).abs();
        }
        // The half inside the range: 1/2 px by 10 px, twice, in 1/256 px^2.
        assert_eq!(area2, 2 * 8 * 160);
        // Colour and depth interpolated at the cut (half way across, on the
        // edges running from a colour-0 corner to a colour-4000 one: none
        // here, the cut edges join corners of the same colour).
        assert!(t
            .iter()
            .all(|tri| tri.depth.iter().all(|&z| z == 0 || z == 1000)));
    }
}
