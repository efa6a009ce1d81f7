//! Section mode (seed 004): only where a surface's depth crosses the
//! section depth.
//!
//! Within a triangle the depth is a plane, so the points at one depth form
//! a straight segment between two edges: found once per triangle (setup:
//! one division per cut edge) and drawn as an anti-aliased 1 px
//! [`Line`](crate::Line) in the surface's colour there.

use super::DepthTriangle;
use crate::arith::div_floor;
use crate::geom::SubPoint;
use crate::raster::Line;

/// What a triangle shows in section mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Section<const C: usize> {
    /// The segment where the triangle's depth equals the section depth.
    Segment(Line<C>),
    /// The whole triangle lies at the section depth.
    Face,
}

/// A point and colour on the way from `a` to `b` where the depth is `z`,
/// `za != zb`, `z` between them. The ends are ordered first, so the edge
/// shared by two triangles gives both the same point.
fn cut<const C: usize>(
    a: (SubPoint, [u16; C], u16),
    b: (SubPoint, [u16; C], u16),
    z: u16,
) -> (SubPoint, [u16; C]) {
    let (a, b) = if (a.0.y, a.0.x) <= (b.0.y, b.0.x) {
        (a, b)
    } else {
        (b, a)
    };
    // t = num / den in [0, 1], den > 0 after the sign is moved to num.
    let (mut num, mut den) = (
        i64::from(z) - i64::from(a.2),
        i64::from(b.2) - i64::from(a.2),
    );
    if den < 0 {
        (num, den) = (-num, -den);
    }
    // p + (q - p) t, rounded to nearest (halves up).
    let lerp = |p: i64, q: i64| p + div_floor(2 * (q - p) * num + den, 2 * den);
    let p = SubPoint::new(
        lerp(i64::from(a.0.x), i64::from(b.0.x)) as i32,
        lerp(i64::from(a.0.y), i64::from(b.0.y)) as i32,
    );
    let mut color = a.1;
    for (k, c) in color.iter_mut().enumerate() {
        *c = lerp(i64::from(a.1[k]), i64::from(b.1[k])).clamp(0, 4095) as u16;
    }
    (p, color)
}

impl<const C: usize> DepthTriangle<C> {
    /// Where the triangle crosses depth `z`: a segment, the whole face (all
    /// three vertices at `z`), or `None` (it does not reach `z`, or only
    /// touches it at one vertex).
    ///
    /// ```
    /// use softedge::hsr::{DepthTriangle, Section};
    /// use softedge::SubPoint;
    /// let p = |x, y| SubPoint::from_px(x, y);
    /// let t = DepthTriangle::new([p(0, 0), p(10, 0), p(0, 10)], [[4095]; 3], [0, 1000, 0]);
    /// let Some(Section::Segment(l)) = t.section(500) else { panic!() };
    /// assert_eq!((l.from, l.to), (p(5, 0), p(5, 5)));
    /// ```
    pub fn section(&self, z: u16) -> Option<Section<C>> {
        let vert = |k: usize| (self.vertices[k], self.colors[k], self.depth[k]);
        if self.depth.iter().all(|&d| d == z) {
            return Some(Section::Face);
        }
        let mut pts: [(SubPoint, [u16; C]); 3] = [(SubPoint::default(), [0; C]); 3];
        let mut n = 0;
        let mut push = |p: (SubPoint, [u16; C])| {
            if pts.iter().take(n).all(|q| q.0 != p.0) {
                if let Some(slot) = pts.get_mut(n) {
                    *slot = p;
                    n += 1;
                }
            }
        };
        for k in 0..3 {
            let (a, b) = (vert(k), vert((k + 1) % 3));
            if a.2 == z {
                push((a.0, a.1));
            }
            let (da, db) = (i32::from(a.2) - i32::from(z), i32::from(b.2) - i32::from(z));
            if (da < 0 && db > 0) || (da > 0 && db < 0) {
                push(cut(a, b, z));
            }
        }
        if n != 2 {
            return None;
        }
        let ((p, cp), (q, cq)) = (pts[0], pts[1]);
        Some(Section::Segment(Line::new(p, q, [cp, cq])))
    }
}
