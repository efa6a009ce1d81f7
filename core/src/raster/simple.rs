//! Setup checks and splitting of polygons: simplicity (no two non-adjacent
//! edges meet) and ear-clipping triangulation, both in exact integer
//! arithmetic, O(n^2) and O(n^3) per polygon, never per pixel.

use crate::geom::SubPoint;

/// `(b - a) x (c - a)`: positive when `a, b, c` turn clockwise on screen.
pub(crate) fn cross(a: SubPoint, b: SubPoint, c: SubPoint) -> i64 {
    let (abx, aby) = (
        i64::from(b.x) - i64::from(a.x),
        i64::from(b.y) - i64::from(a.y),
    );
    let (acx, acy) = (
        i64::from(c.x) - i64::from(a.x),
        i64::from(c.y) - i64::from(a.y),
    );
    abx * acy - aby * acx
}

/// `p` lies on the closed segment `a b` (given that the three are collinear).
fn within(a: SubPoint, b: SubPoint, p: SubPoint) -> bool {
    p.x >= a.x.min(b.x) && p.x <= a.x.max(b.x) && p.y >= a.y.min(b.y) && p.y <= a.y.max(b.y)
}

/// The closed segments `a b` and `c d` have a point in common.
pub(crate) fn segments_meet(a: SubPoint, b: SubPoint, c: SubPoint, d: SubPoint) -> bool {
    let (d1, d2) = (cross(c, d, a).signum(), cross(c, d, b).signum());
    let (d3, d4) = (cross(a, b, c).signum(), cross(a, b, d).signum());
    if d1 * d2 < 0 && d3 * d4 < 0 {
        return true;
    }
    (d1 == 0 && within(c, d, a))
        || (d2 == 0 && within(c, d, b))
        || (d3 == 0 && within(a, b, c))
        || (d4 == 0 && within(a, b, d))
}

/// True when every vertex lies on one line (zero area, nothing to draw).
pub(crate) fn collinear(v: &[SubPoint]) -> bool {
    let Some(&a) = v.first() else {
        return true;
    };
    let Some(&b) = v.iter().find(|&&p| p != a) else {
        return true;
    };
    v.iter().all(|&p| cross(a, b, p) == 0)
}

/// True when no two non-adjacent edges of the closed polygon meet.
pub(crate) fn is_simple(v: &[SubPoint]) -> bool {
    let n = v.len();
    let edge = |k: usize| (v.get(k).copied(), v.get((k + 1) % n.max(1)).copied());
    for i in 0..n {
        for j in i + 1..n {
            let adjacent = j == i + 1 || (i == 0 && j == n - 1);
            if adjacent {
                continue;
            }
            if let ((Some(a), Some(b)), (Some(c), Some(d))) = (edge(i), edge(j)) {
                if segments_meet(a, b, c, d) {
                    return false;
                }
            }
        }
    }
    true
}

/// `p` inside or on the triangle `a b c` of orientation `sign`.
fn in_triangle(a: SubPoint, b: SubPoint, c: SubPoint, p: SubPoint, sign: i64) -> bool {
    cross(a, b, p) * sign >= 0 && cross(b, c, p) * sign >= 0 && cross(c, a, p) * sign >= 0
}

/// Splits a simple polygon into triangles by ear clipping, calling `emit`
/// with the three vertex indices of each (zero-area ears included, so the
/// triangles tile the polygon exactly). Returns `false` if no ear is found
/// (only possible for a polygon that is not simple).
pub(crate) fn ear_clip<const N: usize>(v: &[SubPoint], mut emit: impl FnMut([usize; 3])) -> bool {
    // The remaining outline: vertex indices with their points.
    let mut ring: heapless::Vec<(usize, SubPoint), N> = heapless::Vec::new();
    for (k, &p) in v.iter().enumerate() {
        if ring.push((k, p)).is_err() {
            return false;
        }
    }
    let sign = crate::geom::area2(v).signum();
    // Scanning resumes where the last ear was cut, so a convex run costs
    // one test per ear instead of a rescan from the start.
    let mut k = 0;
    while ring.len() > 3 {
        let m = ring.len();
        let mut clipped = false;
        for step in 0..m {
            let at = (k + step) % m;
            let (Some(&(ia, a)), Some(&(ib, b)), Some(&(ic, c))) = (
                ring.get((at + m - 1) % m),
                ring.get(at),
                ring.get((at + 1) % m),
            ) else {
                return false;
            };
            let turn = cross(a, b, c) * sign;
            if turn < 0 {
                continue;
            }
            let blocked = turn > 0
                && ring.iter().any(|&(o, p)| {
                    o != ia
                        && o != ib
                        && o != ic
                        && p != a
                        && p != b
                        && p != c
                        && in_triangle(a, b, c, p, sign)
                });
            if blocked {
                continue;
            }
            emit([ia, ib, ic]);
            ring.remove(at);
            k = at.saturating_sub(1);
            clipped = true;
            break;
        }
        if !clipped {
            return false;
        }
    }
    if let [(a, _), (b, _), (c, _)] = ring[..] {
        emit([a, b, c]);
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: i32, y: i32) -> SubPoint {
        SubPoint::new(x, y)
    }

    #[test]
    fn collinear_points_are_detected() {
        assert!(collinear(&[p(0, 0), p(0, 0), p(5, 5), p(10, 10)]));
        assert!(!collinear(&[p(0, 0), p(5, 5), p(10, 11)]));
    }

    #[test]
    fn bow_tie_is_not_simple_square_is() {
        assert!(!is_simple(&[p(0, 0), p(10, 10), p(10, 0), p(0, 10)]));
        assert!(is_simple(&[p(0, 0), p(10, 0), p(10, 10), p(0, 10)]));
    }

    #[test]
    fn ear_clipping_tiles_a_concave_polygon() {
        let v = [p(0, 0), p(40, 0), p(40, 40), p(20, 10), p(0, 40)];
        let mut area = 0i64;
        let mut n = 0;
        assert!(ear_clip::<8>(&v, |t| {
            area += cross(v[t[0]], v[t[1]], v[t[2]]).abs();
            n += 1;
        }));
        assert_eq!(n, 3);
        assert_eq!(area, crate::geom::area2(&v).abs());
    }
}
