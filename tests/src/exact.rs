//! Exact areas by clipping, in rational arithmetic.
//!
//! Everything here is written from the definitions of the box pixel model,
//! not from `softedge`'s code:
//!
//! - pixel `(i, j)` is the square `[16 i, 16 i + 16] x [16 j, 16 j + 16]` in
//!   sub-pixel units (1/16 px), so one pixel is 256 sub² and an area in sub²
//!   times 16 is an area in 1/65536 px (the unit of `softedge::COVER_ONE`);
//! - the coverage of a pixel by a polygon is the area of their intersection,
//!   found by Sutherland–Hodgman clipping of the polygon against the four
//!   sides of the pixel (each side is a half-plane), with every coordinate an
//!   exact rational ([`Ratio`], checked `i128`: an overflow panics, it never
//!   rounds) so nothing is rounded;
//! - the area an edge "cuts off" in a pixel is the part of the pixel, inside
//!   the edge's own y-range, lying right of the edge's line: the rectangle
//!   clipped by one more half-plane.

pub use crate::ratio::Ratio;

/// An exact number.
pub type Q = Ratio;

/// An exact integer as a [`Q`].
pub fn q(v: i64) -> Q {
    Q::int(i128::from(v))
}

/// A point with exact coordinates, in sub-pixel units.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pt {
    /// x, sub-pixels.
    pub x: Q,
    /// y, sub-pixels (down).
    pub y: Q,
}

impl Pt {
    /// An integer point.
    pub fn int(x: i64, y: i64) -> Self {
        Self { x: q(x), y: q(y) }
    }
}

/// The half-plane `a x + b y + c >= 0` (integer coefficients).
#[derive(Debug, Clone, Copy)]
pub struct HalfPlane {
    /// x coefficient.
    pub a: i64,
    /// y coefficient.
    pub b: i64,
    /// constant.
    pub c: i64,
}

impl HalfPlane {
    fn eval(&self, p: &Pt) -> Q {
        p.x * q(self.a) + p.y * q(self.b) + q(self.c)
    }
}

/// One Sutherland–Hodgman pass: the part of `poly` in the half-plane `h`.
/// The result may hold repeated points; they do not change the area.
pub fn clip(poly: &[Pt], h: HalfPlane) -> Vec<Pt> {
    let n = poly.len();
    let mut out = Vec::with_capacity(n + 2);
    if n == 0 {
        return out;
    }
    let f: Vec<Q> = poly.iter().map(|p| h.eval(p)).collect();
    for k in 0..n {
        let (p, fp) = (&poly[k], &f[k]);
        let (r, fr) = (&poly[(k + 1) % n], &f[(k + 1) % n]);
        let p_in = !fp.is_negative();
        let r_in = !fr.is_negative();
        if p_in {
            out.push(*p);
        }
        if p_in != r_in {
            // fp and fr differ in sign (one may be zero): t in [0, 1].
            let t = fp / (fp - fr);
            out.push(Pt {
                x: p.x + (r.x - p.x) * t,
                y: p.y + (r.y - p.y) * t,
            });
        }
    }
    out
}

/// Absolute area of a polygon (shoelace), in the square of its units.
pub fn area(poly: &[Pt]) -> Q {
    let n = poly.len();
    let mut s = q(0);
    for k in 0..n {
        let (p, r) = (&poly[k], &poly[(k + 1) % n]);
        s += p.x * r.y - r.x * p.y;
    }
    s.abs() / q(2)
}

/// Keeps `x >= x0`.
pub fn x_at_least(x0: i64) -> HalfPlane {
    HalfPlane { a: 1, b: 0, c: -x0 }
}
/// Keeps `x <= x1`.
pub fn x_at_most(x1: i64) -> HalfPlane {
    HalfPlane { a: -1, b: 0, c: x1 }
}
/// Keeps `y >= y0`.
pub fn y_at_least(y0: i64) -> HalfPlane {
    HalfPlane { a: 0, b: 1, c: -y0 }
}
/// Keeps `y <= y1`.
pub fn y_at_most(y1: i64) -> HalfPlane {
    HalfPlane { a: 0, b: -1, c: y1 }
}

/// Converts an area in sub² (1/256 px²) to coverage units, 1/65536 px
/// (exact).
pub fn sub2_to_cover(a: &Q) -> Q {
    a * q(256)
}

/// Exact coverage of every pixel of a frame by a simple polygon (vertices in
/// sub-pixels, either orientation).
#[derive(Debug, Clone)]
pub struct CoverageMap {
    /// Frame width in pixels.
    pub width: i32,
    /// Frame height in pixels.
    pub height: i32,
    /// Row-major areas in 1/65536 px, exact.
    pub cover: Vec<Q>,
}

impl CoverageMap {
    /// Clips `poly` to each row strip, then each strip to each pixel column.
    pub fn new(poly: &[(i64, i64)], width: i32, height: i32) -> Self {
        let pts: Vec<Pt> = poly.iter().map(|&(x, y)| Pt::int(x, y)).collect();
        let mut cover = vec![q(0); (width * height) as usize];
        let (xmin, xmax) = minmax(poly.iter().map(|p| p.0));
        let (ymin, ymax) = minmax(poly.iter().map(|p| p.1));
        let j_lo = (ymin.div_euclid(16) as i32).max(0);
        let j_hi = (ymax.div_euclid(16) as i32).min(height - 1);
        let i_lo = (xmin.div_euclid(16) as i32).max(0);
        let i_hi = (xmax.div_euclid(16) as i32).min(width - 1);
        if i_lo > i_hi {
            // Wholly left or right of the frame.
            return Self {
                width,
                height,
                cover,
            };
        }
        for j in j_lo..=j_hi {
            let top = i64::from(j) * 16;
            let strip = clip(&clip(&pts, y_at_least(top)), y_at_most(top + 16));
            if strip.len() < 3 {
                continue;
            }
            // Columns whose inside no boundary segment of the strip enters
            // are wholly in or out: decided by the centre, no clipping.
            let mut touched = vec![false; (i_hi - i_lo + 1) as usize];
            for k in 0..strip.len() {
                let (a, b) = (strip[k], strip[(k + 1) % strip.len()]);
                let on_rim = |p: &Pt| p.y == q(top) || p.y == q(top + 16);
                if a.y == b.y && on_rim(&a) {
                    continue;
                }
                let lo = a.x.min(b.x).floor().div_euclid(16);
                let hi = a.x.max(b.x).floor().div_euclid(16);
                for i in lo.max(i128::from(i_lo))..=hi.min(i128::from(i_hi)) {
                    touched[(i - i128::from(i_lo)) as usize] = true;
                }
            }
            for i in i_lo..=i_hi {
                let k = (j * width + i) as usize;
                if !touched[(i - i_lo) as usize] {
                    if centre_inside_top_left(poly, i64::from(i), i64::from(j)) {
                        cover[k] = q(65536);
                    }
                    continue;
                }
                let left = i64::from(i) * 16;
                let cell = clip(&clip(&strip, x_at_least(left)), x_at_most(left + 16));
                if cell.len() >= 3 {
                    cover[k] = sub2_to_cover(&area(&cell));
                }
            }
        }
        Self {
            width,
            height,
            cover,
        }
    }

    /// Exact coverage of pixel `(i, j)` in 1/65536 px.
    pub fn at(&self, i: i32, j: i32) -> &Q {
        &self.cover[(j * self.width + i) as usize]
    }
}

fn minmax(it: impl Iterator<Item = i64>) -> (i64, i64) {
    it.fold((i64::MAX, i64::MIN), |(lo, hi), v| (lo.min(v), hi.max(v)))
}

/// The exact area, in 1/65536 px, of the part of pixel `(i, j)` that lies
/// inside the y-range of the edge `p0 -> p1` and right of (larger x than)
/// the edge's line. Horizontal edges cut off nothing.
pub fn edge_right_area(p0: (i64, i64), p1: (i64, i64), i: i64, j: i64) -> Q {
    let (a, b) = if p0.1 <= p1.1 { (p0, p1) } else { (p1, p0) };
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    if dy == 0 {
        return q(0);
    }
    let ylo = (j * 16).max(a.1);
    let yhi = (j * 16 + 16).min(b.1);
    if ylo >= yhi {
        return q(0);
    }
    let rect = [
        Pt::int(i * 16, ylo),
        Pt::int(i * 16 + 16, ylo),
        Pt::int(i * 16 + 16, yhi),
        Pt::int(i * 16, yhi),
    ];
    // (x - ax) dy - (y - ay) dx >= 0 with dy > 0: x >= x_edge(y).
    let right = HalfPlane {
        a: dy,
        b: -dx,
        c: -a.0 * dy + a.1 * dx,
    };
    sub2_to_cover(&area(&clip(&rect, right)))
}

/// The exact Gouraud intensity at the centre of pixel `(i, j)`: the affine
/// function through the three vertices (sub-pixels) and their intensities.
/// `None` for a degenerate triangle.
pub fn gouraud_at_centre(v: [(i64, i64); 3], c: [i64; 3], i: i64, j: i64) -> Option<Q> {
    let (px, py) = (16 * i + 8, 16 * j + 8);
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| {
        (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0)
    };
    let d = cross(v[0], v[1], v[2]);
    if d == 0 {
        return None;
    }
    // Barycentric weights of p: areas of the sub-triangles over the whole.
    let w1 = cross(v[0], (px, py), v[2]);
    let w2 = cross(v[0], v[1], (px, py));
    let num = q(c[0]) * q(d) + q(c[1] - c[0]) * q(w1) + q(c[2] - c[0]) * q(w2);
    Some(num / q(d))
}

/// Is pixel `(i, j)` lit by the aliased (point-sampled) polygon under the
/// top-left rule? (Its centre, [`point_inside_top_left`].)
pub fn centre_inside_top_left(poly: &[(i64, i64)], i: i64, j: i64) -> bool {
    point_inside_top_left(poly, 16 * i + 8, 16 * j + 8)
}

/// Is the point `(cx, cy)` inside the polygon under the top-left rule? The
/// point is nudged by `(ε, ε²)`: a point on a left edge or a top edge is
/// inside, on a right or bottom edge outside. Crossing test with a ray to
/// the right of the nudged point.
pub fn point_inside_top_left(poly: &[(i64, i64)], cx: i64, cy: i64) -> bool {
    let n = poly.len();
    let mut crossings = 0;
    for k in 0..n {
        let (p, r) = (poly[k], poly[(k + 1) % n]);
        let (a, b) = if p.1 <= r.1 { (p, r) } else { (r, p) };
        // The nudged y, cy + ε², lies in [a.y, b.y) iff a.y <= cy < b.y.
        if !(a.1 <= cy && cy < b.1) {
            continue;
        }
        // Edge x at cy, compared with cx + ε: counts iff strictly greater.
        let (dx, dy) = (i128::from(b.0 - a.0), i128::from(b.1 - a.1));
        let xe_num = i128::from(a.0) * dy + i128::from(cy - a.1) * dx;
        if xe_num > i128::from(cx) * dy {
            crossings += 1;
        }
    }
    crossings % 2 == 1
}

/// `v` as the nearest `f64` (for reporting only).
pub fn to_f64(v: &Q) -> f64 {
    v.to_f64()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_pixel_triangle() {
        let m = CoverageMap::new(&[(0, 0), (16, 0), (0, 16)], 2, 2);
        assert_eq!(*m.at(0, 0), q(32768));
        assert_eq!(*m.at(1, 0), q(0));
    }

    #[test]
    fn polygon_area_is_sum_of_edge_areas() {
        // A polygon's coverage of a pixel is the signed sum of its edges'
        // right areas (+ for edges running down on a clockwise outline).
        let poly = [(3, 5), (71, 20), (40, 60), (20, 33)];
        let m = CoverageMap::new(&poly, 6, 6);
        for j in 0..6 {
            for i in 0..6 {
                let mut s = q(0);
                for k in 0..poly.len() {
                    let (p, r) = (poly[k], poly[(k + 1) % poly.len()]);
                    let a = edge_right_area(p, r, i64::from(i), i64::from(j));
                    // Clockwise on screen (y down): inside is right of the
                    // edges that run up, left of those running down.
                    if r.1 > p.1 {
                        s -= a;
                    } else {
                        s += a;
                    }
                }
                assert_eq!(s, *m.at(i, j), "pixel {i},{j}");
            }
        }
    }

    #[test]
    fn shortcut_for_untouched_pixels_equals_clipping_every_pixel() {
        // Concave, with horizontal edges inside rows and on row boundaries.
        let poly = [
            (5, 5),
            (300, 21),
            (300, 64),
            (120, 64),
            (120, 165),
            (250, 165),
            (40, 290),
        ];
        let m = CoverageMap::new(&poly, 22, 22);
        let pts: Vec<Pt> = poly.iter().map(|&(x, y)| Pt::int(x, y)).collect();
        for j in 0..22i64 {
            for i in 0..22i64 {
                let cell = [
                    x_at_least(16 * i),
                    x_at_most(16 * i + 16),
                    y_at_least(16 * j),
                    y_at_most(16 * j + 16),
                ]
                .iter()
                .fold(pts.clone(), |p, h| clip(&p, *h));
                let want = sub2_to_cover(&area(&cell));
                assert_eq!(*m.at(i as i32, j as i32), want, "pixel {i},{j}");
            }
        }
    }

    #[test]
    fn gouraud_hits_vertex_colours_at_centres() {
        let v = [(8, 8), (168, 8), (8, 168)];
        let c = [0, 4000, 2000];
        assert_eq!(gouraud_at_centre(v, c, 0, 0), Some(q(0)));
        assert_eq!(gouraud_at_centre(v, c, 10, 0), Some(q(4000)));
        assert_eq!(gouraud_at_centre(v, c, 0, 10), Some(q(2000)));
        assert_eq!(gouraud_at_centre(v, c, 5, 5), Some(q(3000)));
    }

    #[test]
    fn top_left_rule_on_a_square_of_centres() {
        // Square with corners at pixel centres (0,0) and (2,2): the left and
        // top sides' centres are in, right and bottom out.
        let sq = [(8, 8), (40, 8), (40, 40), (8, 40)];
        assert!(centre_inside_top_left(&sq, 0, 0));
        assert!(centre_inside_top_left(&sq, 1, 1));
        assert!(!centre_inside_top_left(&sq, 2, 0));
        assert!(!centre_inside_top_left(&sq, 0, 2));
    }
}
