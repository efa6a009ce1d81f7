//! Test shapes from random numbers (all integer, sub-pixel units).

use std::cmp::Ordering;

/// Twice the signed area of triangle `o, a, b` (positive: clockwise on
/// screen, y down).
pub fn cross(o: (i64, i64), a: (i64, i64), b: (i64, i64)) -> i64 {
    (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
}

/// Exact angular order of directions around the origin (starting at the
/// +x axis, turning towards +y).
fn angle_cmp(a: (i64, i64), b: (i64, i64)) -> Ordering {
    let half = |p: (i64, i64)| {
        if p.1 > 0 || (p.1 == 0 && p.0 > 0) {
            0
        } else {
            1
        }
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| 0.cmp(&cross((0, 0), a, b)))
}

/// A star-shaped simple polygon: `points` sorted by angle around `centre`,
/// one point per direction. `None` unless `centre` is strictly inside the
/// kernel (every consecutive pair turns strictly the same way around it),
/// which makes the outline simple.
pub fn star_polygon(centre: (i64, i64), points: &[(i64, i64)]) -> Option<Vec<(i64, i64)>> {
    let mut rel: Vec<(i64, i64)> = points
        .iter()
        .map(|p| (p.0 - centre.0, p.1 - centre.1))
        .filter(|p| *p != (0, 0))
        .collect();
    rel.sort_by(|a, b| angle_cmp(*a, *b));
    rel.dedup_by(|a, b| angle_cmp(*a, *b) == Ordering::Equal);
    if rel.len() < 3 {
        return None;
    }
    let n = rel.len();
    for k in 0..n {
        if cross((0, 0), rel[k], rel[(k + 1) % n]) <= 0 {
            return None;
        }
    }
    Some(
        rel.into_iter()
            .map(|p| (p.0 + centre.0, p.1 + centre.1))
            .collect(),
    )
}

/// Points on the perimeter of the axis-aligned rectangle `[x0, x1] x [y0, y1]`
/// (clockwise on screen from the top-left corner), chosen from `picks`
/// (each taken modulo the perimeter), always including the four corners,
/// without repeats.
pub fn rectangle_boundary(x0: i64, y0: i64, x1: i64, y1: i64, picks: &[u64]) -> Vec<(i64, i64)> {
    let (w, h) = (x1 - x0, y1 - y0);
    let perim = 2 * (w + h);
    let mut ts: Vec<i64> = vec![0, w, w + h, 2 * w + h];
    ts.extend(picks.iter().map(|&p| (p % perim as u64) as i64));
    ts.sort_unstable();
    ts.dedup();
    ts.into_iter()
        .map(|t| {
            if t < w {
                (x0 + t, y0)
            } else if t < w + h {
                (x1, y0 + t - w)
            } else if t < 2 * w + h {
                (x1 - (t - w - h), y1)
            } else {
                (x0, y1 - (t - 2 * w - h))
            }
        })
        .collect()
}

/// A triangulation of the polygon `boundary` (convex, clockwise on screen)
/// that first fans it from `centre` (strictly inside), then inserts each of
/// `interior` that falls strictly inside one triangle by splitting that
/// triangle in three. Every interior edge is shared by exactly two
/// triangles; boundary edges are the boundary's own segments.
pub fn triangulate(
    boundary: &[(i64, i64)],
    centre: (i64, i64),
    interior: &[(i64, i64)],
) -> Vec<[(i64, i64); 3]> {
    let n = boundary.len();
    let mut tris: Vec<[(i64, i64); 3]> = (0..n)
        .map(|k| [centre, boundary[k], boundary[(k + 1) % n]])
        .filter(|t| cross(t[0], t[1], t[2]) != 0)
        .collect();
    for &p in interior {
        let hit = tris.iter().position(|t| {
            let s = cross(t[0], t[1], t[2]).signum();
            (0..3).all(|k| cross(t[k], t[(k + 1) % 3], p).signum() == s)
        });
        if let Some(k) = hit {
            let [a, b, c] = tris.swap_remove(k);
            tris.push([a, b, p]);
            tris.push([b, c, p]);
            tris.push([c, a, p]);
        }
    }
    tris
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn star_of_a_square() {
        let p = star_polygon((0, 0), &[(5, 5), (-5, 5), (5, -5), (-5, -5), (10, 10)]).unwrap();
        assert_eq!(p, vec![(5, 5), (-5, 5), (-5, -5), (5, -5)]);
        assert!(star_polygon((0, 0), &[(1, 0), (2, 1), (3, 1)]).is_none());
    }

    #[test]
    fn triangulation_covers_the_square() {
        let b = rectangle_boundary(0, 0, 32, 16, &[3, 50, 7]);
        assert_eq!(b.len(), 7);
        let t = triangulate(&b, (10, 8), &[(20, 4), (25, 12), (2, 2)]);
        let total: i64 = t.iter().map(|t| cross(t[0], t[1], t[2]).abs()).sum();
        assert_eq!(total, 2 * 32 * 16);
    }
}
