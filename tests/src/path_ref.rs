//! Independent reference for the path tests, in `f64`: winding numbers and
//! areas of what a `SegmentSink` received (shoelace, and exact scanline
//! lengths integrated over y), exact disc-in-box areas, distances to
//! curves, and the exact union of convex polygons and discs (the stroke
//! outline written from its definition: segment rectangles, join wedges,
//! caps). Nothing here calls the code under test except to collect its
//! output.

use softedge::geom::FinePoint;
use softedge::path::SegmentSink;

/// One fine unit in px.
pub const FINE: f64 = 1.0 / 1024.0;

/// Collects segments; coordinates kept in fine units.
#[derive(Debug, Default, Clone)]
pub struct Segments {
    /// Every segment received, `(from, to)`.
    pub segs: Vec<(FinePoint, FinePoint)>,
}

impl SegmentSink for Segments {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        self.segs.push((from, to));
    }
}

fn px(p: FinePoint) -> (f64, f64) {
    (f64::from(p.x) * FINE, f64::from(p.y) * FINE)
}

impl Segments {
    /// An empty collector.
    pub fn new() -> Self {
        Self::default()
    }

    /// Number of segments.
    pub fn len(&self) -> usize {
        self.segs.len()
    }

    /// True when nothing was received.
    pub fn is_empty(&self) -> bool {
        self.segs.is_empty()
    }

    /// The segments in px.
    pub fn px(&self) -> impl Iterator<Item = ((f64, f64), (f64, f64))> + '_ {
        self.segs.iter().map(|&(a, b)| (px(a), px(b)))
    }

    /// Signed area in px^2 by the shoelace formula (clockwise on screen
    /// positive), exact in `i128` before the conversion.
    pub fn shoelace(&self) -> f64 {
        let s: i128 = self
            .segs
            .iter()
            .map(|(a, b)| i128::from(a.x) * i128::from(b.y) - i128::from(b.x) * i128::from(a.y))
            .sum();
        s as f64 / 2.0 * FINE * FINE
    }

    /// True when every point starts as many segments as it ends (closed
    /// contours), no segment has zero length and all lie in range.
    pub fn is_closed_in_range(&self) -> bool {
        let mut balance = std::collections::HashMap::<(i32, i32), i64>::new();
        for (a, b) in &self.segs {
            if a == b || !a.in_range() || !b.in_range() {
                return false;
            }
            *balance.entry((a.x, a.y)).or_default() += 1;
            *balance.entry((b.x, b.y)).or_default() -= 1;
        }
        balance.values().all(|&v| v == 0)
    }

    /// Crossings of the horizontal line at `y` (px): `(x, +1)` where a
    /// segment runs down across it, `(x, -1)` up; half-open in y.
    pub fn crossings(&self, y: f64) -> Vec<(f64, i32)> {
        let mut out = Vec::new();
        for ((ax, ay), (bx, by)) in self.px() {
            let (dir, lo, hi) = if ay < by { (1, ay, by) } else { (-1, by, ay) };
            if ay == by || y < lo || y >= hi {
                continue;
            }
            let t = (y - ay) / (by - ay);
            out.push((ax + t * (bx - ax), dir));
        }
        out.sort_by(|a, b| a.0.total_cmp(&b.0));
        out
    }

    /// The winding number at `(x, y)` px: clockwise contours count +1.
    pub fn winding(&self, x: f64, y: f64) -> i32 {
        self.crossings(y)
            .iter()
            .filter(|c| c.0 > x)
            .map(|c| c.1)
            .sum::<i32>()
    }

    /// Length of the line at `y` inside `[x0, x1]` where `rule(winding)`.
    pub fn covered_length(&self, y: f64, x0: f64, x1: f64, rule: impl Fn(i32) -> bool) -> f64 {
        let cr = self.crossings(y);
        // Winding left of everything is 0; walking right, each crossing
        // changes the winding by -dir (a crossing to the right of a point
        // adds dir to its winding).
        let total: i32 = cr.iter().map(|c| c.1).sum();
        let mut w = total;
        let mut prev = f64::NEG_INFINITY;
        let mut len = 0.0;
        for &(x, dir) in &cr {
            if rule(w) {
                len += (x.min(x1) - prev.max(x0)).max(0.0);
            }
            w -= dir;
            prev = x;
        }
        if rule(w) {
            len += (x1 - prev.max(x0)).max(0.0);
        }
        len
    }

    /// The area (px^2) where `rule(winding)` holds, by exact scanline
    /// lengths at `lines_per_px` lines per pixel (midpoint rule: the
    /// length is piecewise linear in y, so the error is confined to the
    /// lines nearest vertices).
    pub fn area_where(&self, lines_per_px: u32, rule: impl Fn(i32) -> bool + Copy) -> f64 {
        let Some((x0, y0, x1, y1)) = self.bbox() else {
            return 0.0;
        };
        let h = 1.0 / f64::from(lines_per_px);
        let n = ((y1 - y0) / h).ceil() as usize + 1;
        (0..n)
            .map(|i| self.covered_length(y0 + (i as f64 + 0.5) * h, x0 - 1.0, x1 + 1.0, rule) * h)
            .sum()
    }

    /// The nonzero area, px^2.
    pub fn nonzero_area(&self, lines_per_px: u32) -> f64 {
        self.area_where(lines_per_px, |w| w != 0)
    }

    /// The covered area (rule) of the box `[x0, x1) x [y0, y1)`, px^2.
    pub fn box_area(
        &self,
        x0: f64,
        y0: f64,
        x1: f64,
        y1: f64,
        lines: u32,
        rule: impl Fn(i32) -> bool + Copy,
    ) -> f64 {
        let h = (y1 - y0) / f64::from(lines);
        (0..lines)
            .map(|i| self.covered_length(y0 + (f64::from(i) + 0.5) * h, x0, x1, rule) * h)
            .sum()
    }

    /// The covered area (rule) of each pixel `(i, row)` for `i` in
    /// `i0..i1`, from `lines` scanlines through the row (crossings found
    /// once per line).
    pub fn row_coverage(
        &self,
        row: i32,
        i0: i32,
        i1: i32,
        lines: u32,
        rule: impl Fn(i32) -> bool + Copy,
    ) -> Vec<f64> {
        let h = 1.0 / f64::from(lines);
        let mut cov = vec![0.0; (i1 - i0).max(0) as usize];
        for l in 0..lines {
            let y = f64::from(row) + (f64::from(l) + 0.5) * h;
            let cr = self.crossings(y);
            // Covered intervals of this line.
            let total: i32 = cr.iter().map(|c| c.1).sum();
            let mut w = total;
            let mut prev = f64::NEG_INFINITY;
            let mut spans = Vec::new();
            for &(x, dir) in &cr {
                if rule(w) {
                    spans.push((prev, x));
                }
                w -= dir;
                prev = x;
            }
            if rule(w) {
                spans.push((prev, f64::INFINITY));
            }
            for (k, c) in cov.iter_mut().enumerate() {
                let (x0, x1) = (f64::from(i0) + k as f64, f64::from(i0) + k as f64 + 1.0);
                let len: f64 = spans
                    .iter()
                    .map(|&(a, b)| (b.min(x1) - a.max(x0)).max(0.0))
                    .sum();
                *c += len * h;
            }
        }
        cov
    }

    /// `(x0, y0, x1, y1)` px of all endpoints.
    pub fn bbox(&self) -> Option<(f64, f64, f64, f64)> {
        let mut it = self.px().flat_map(|(a, b)| [a, b]);
        let (x, y) = it.next()?;
        Some(it.fold((x, y, x, y), |(a, b, c, d), (x, y)| {
            (a.min(x), b.min(y), c.max(x), d.max(y))
        }))
    }

    /// The largest winding number at the centres of a grid of `step` px
    /// over the bounding box (and the smallest).
    pub fn winding_extremes(&self, step: f64) -> (i32, i32) {
        let Some((x0, y0, x1, y1)) = self.bbox() else {
            return (0, 0);
        };
        let (mut lo, mut hi) = (0, 0);
        let mut y = y0 + step * 0.5137;
        while y < y1 {
            let cr = self.crossings(y);
            let mut x = x0 + step * 0.4871;
            while x < x1 {
                let w: i32 = cr.iter().filter(|c| c.0 > x).map(|c| c.1).sum();
                lo = lo.min(w);
                hi = hi.max(w);
                x += step;
            }
            y += step;
        }
        (lo, hi)
    }
}

/// Distance from `p` to the segment `a b`.
pub fn dist_to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let l2 = dx * dx + dy * dy;
    let t = if l2 == 0.0 {
        0.0
    } else {
        (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / l2).clamp(0.0, 1.0)
    };
    ((p.0 - a.0 - t * dx).powi(2) + (p.1 - a.1 - t * dy).powi(2)).sqrt()
}

/// A point of the cubic (or quadratic, with `c[3]` unused when `quad`).
pub fn bezier(c: &[(f64, f64)], t: f64) -> (f64, f64) {
    let u = 1.0 - t;
    match c.len() {
        3 => (
            u * u * c[0].0 + 2.0 * u * t * c[1].0 + t * t * c[2].0,
            u * u * c[0].1 + 2.0 * u * t * c[1].1 + t * t * c[2].1,
        ),
        _ => (
            u * u * u * c[0].0
                + 3.0 * u * u * t * c[1].0
                + 3.0 * u * t * t * c[2].0
                + t * t * t * c[3].0,
            u * u * u * c[0].1
                + 3.0 * u * u * t * c[1].1
                + 3.0 * u * t * t * c[2].1
                + t * t * t * c[3].1,
        ),
    }
}

/// Distance from `p` to a Bézier curve: dense sampling, then golden-section
/// refinement around the best sample.
pub fn dist_to_bezier(p: (f64, f64), c: &[(f64, f64)]) -> f64 {
    let d = |t: f64| {
        let q = bezier(c, t);
        ((q.0 - p.0).powi(2) + (q.1 - p.1).powi(2)).sqrt()
    };
    let n = 2000;
    let mut best = (0.0, d(0.0));
    for i in 1..=n {
        let t = f64::from(i) / f64::from(n);
        let v = d(t);
        if v < best.1 {
            best = (t, v);
        }
    }
    let (mut lo, mut hi) = (
        (best.0 - 1.0 / f64::from(n)).max(0.0),
        (best.0 + 1.0 / f64::from(n)).min(1.0),
    );
    for _ in 0..60 {
        let m1 = lo + (hi - lo) * 0.382;
        let m2 = lo + (hi - lo) * 0.618;
        if d(m1) < d(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    d((lo + hi) / 2.0).min(best.1)
}

/// Distances to a Bézier curve for many query points: the curve sampled
/// at 20 001 parameters, binned in 1-px cells; a query refines, by
/// golden-section search between neighbouring samples, the nearest sample
/// of every stretch of the curve that passes through its 3 x 3 cells (so
/// a curve that comes back near itself is measured on every branch), or
/// of all samples if those cells are empty.
pub struct BezierIndex {
    ctrl: Vec<(f64, f64)>,
    samples: Vec<(f64, f64)>,
    cells: std::collections::HashMap<(i64, i64), Vec<usize>>,
}

impl BezierIndex {
    /// Samples the curve with control points `ctrl` (3 or 4, px).
    pub fn new(ctrl: &[(f64, f64)]) -> Self {
        let n = 20_000;
        let samples: Vec<(f64, f64)> = (0..=n)
            .map(|i| bezier(ctrl, f64::from(i) / f64::from(n)))
            .collect();
        let mut cells = std::collections::HashMap::<(i64, i64), Vec<usize>>::new();
        for (i, p) in samples.iter().enumerate() {
            cells
                .entry((p.0.floor() as i64, p.1.floor() as i64))
                .or_default()
                .push(i);
        }
        Self {
            ctrl: ctrl.to_vec(),
            samples,
            cells,
        }
    }

    /// The distance from `p` to the curve.
    pub fn distance(&self, p: (f64, f64)) -> f64 {
        let d2 = |q: (f64, f64)| (q.0 - p.0).powi(2) + (q.1 - p.1).powi(2);
        let (cx, cy) = (p.0.floor() as i64, p.1.floor() as i64);
        let mut near: Vec<usize> = (-1..=1)
            .flat_map(|dy| (-1..=1).map(move |dx| (cx + dx, cy + dy)))
            .filter_map(|c| self.cells.get(&c))
            .flatten()
            .copied()
            .collect();
        if near.is_empty() {
            near = (0..self.samples.len()).collect();
        }
        near.sort_unstable();
        // The nearest sample of each run of consecutive indices.
        let mut starts = Vec::new();
        let mut run: Option<(usize, f64)> = None;
        for (k, &i) in near.iter().enumerate() {
            if k > 0 && near[k - 1] + 1 != i {
                starts.extend(run.take());
            }
            let v = d2(self.samples[i]);
            if run.is_none_or(|(_, b)| v < b) {
                run = Some((i, v));
            }
        }
        starts.extend(run);
        let n = (self.samples.len() - 1) as f64;
        let f = |t: f64| d2(bezier(&self.ctrl, t));
        let refine = |i: usize| {
            let (mut lo, mut hi) = (
                ((i as f64) - 1.0).max(0.0) / n,
                ((i as f64) + 1.0).min(n) / n,
            );
            for _ in 0..50 {
                let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
                if f(m1) < f(m2) {
                    hi = m2;
                } else {
                    lo = m1;
                }
            }
            f((lo + hi) / 2.0).min(d2(self.samples[i]))
        };
        starts
            .iter()
            .map(|&(i, _)| refine(i))
            .fold(f64::INFINITY, f64::min)
            .sqrt()
    }
}

/// Distance from `p` to the ellipse about `c` with semi-axes `a`, `b`
/// rotated by `rot` radians, and whether `p` is inside: dense parameter
/// sampling, then golden-section refinement.
pub fn ellipse_distance(p: (f64, f64), c: (f64, f64), a: f64, b: f64, rot: f64) -> (f64, bool) {
    use std::f64::consts::PI;
    let (cs, sn) = (rot.cos(), rot.sin());
    let (u, v) = (
        (p.0 - c.0) * cs + (p.1 - c.1) * sn,
        -(p.0 - c.0) * sn + (p.1 - c.1) * cs,
    );
    let d = |t: f64| (a * t.cos() - u).hypot(b * t.sin() - v);
    let n = 2000;
    let (mut bt, mut bd) = (0.0, f64::INFINITY);
    for i in 0..n {
        let t = 2.0 * PI * f64::from(i) / f64::from(n);
        if d(t) < bd {
            (bt, bd) = (t, d(t));
        }
    }
    let (mut lo, mut hi) = (bt - 2.0 * PI / f64::from(n), bt + 2.0 * PI / f64::from(n));
    for _ in 0..60 {
        let (m1, m2) = (lo + (hi - lo) * 0.382, lo + (hi - lo) * 0.618);
        if d(m1) < d(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    (
        d((lo + hi) / 2.0).min(bd),
        (u / a).powi(2) + (v / b).powi(2) < 1.0,
    )
}

/// The area of the disc `(cx, cy, r)` inside the box, exactly (closed form
/// of the integral of the chord length).
pub fn disc_box_area(cx: f64, cy: f64, r: f64, x0: f64, y0: f64, x1: f64, y1: f64) -> f64 {
    let q = |x: f64, y: f64| quadrant_area(r, x - cx, y - cy);
    q(x1, y1) - q(x0, y1) - q(x1, y0) + q(x0, y0)
}

/// Area of the disc of radius `r` about the origin with `X <= x, Y <= y`.
fn quadrant_area(r: f64, x: f64, y: f64) -> f64 {
    // Integral of s(t) = sqrt(r^2 - t^2): G(t) = (t s + r^2 asin(t/r)) / 2.
    let g = |t: f64| {
        let t = t.clamp(-r, r);
        (t * (r * r - t * t).max(0.0).sqrt() + r * r * (t / r).asin()) / 2.0
    };
    let x = x.clamp(-r, r);
    if y >= r {
        return 2.0 * (g(x) - g(-r));
    }
    if y <= -r {
        return 0.0;
    }
    let w = (r * r - y * y).sqrt();
    // Where |t| <= w the chord reaches past y: length y + s(t).
    let (a, b) = (-w, x.min(w));
    let mid = if b > a {
        y * (b - a) + g(b) - g(a)
    } else {
        0.0
    };
    // Where |t| > w the whole chord is below y (y > 0) or above (y < 0).
    let outer = if y > 0.0 {
        let left = 2.0 * (g(x.min(-w)) - g(-r));
        let right = if x > w { 2.0 * (g(x) - g(w)) } else { 0.0 };
        left + right
    } else {
        0.0
    };
    mid + outer
}

/// A convex region for the union reference.
#[derive(Debug, Clone)]
pub enum Region {
    /// A convex polygon (either orientation).
    Polygon(Vec<(f64, f64)>),
    /// A disc: centre and radius.
    Disc((f64, f64), f64),
}

impl Region {
    /// The interval of the line at `y` inside the region.
    pub fn interval(&self, y: f64) -> Option<(f64, f64)> {
        match self {
            Region::Disc(c, r) => {
                let d = r * r - (y - c.1).powi(2);
                (d > 0.0).then(|| (c.0 - d.sqrt(), c.0 + d.sqrt()))
            }
            Region::Polygon(p) => {
                let mut lo = f64::INFINITY;
                let mut hi = f64::NEG_INFINITY;
                for k in 0..p.len() {
                    let (a, b) = (p[k], p[(k + 1) % p.len()]);
                    if (a.1 <= y && y < b.1) || (b.1 <= y && y < a.1) {
                        let x = a.0 + (y - a.1) / (b.1 - a.1) * (b.0 - a.0);
                        lo = lo.min(x);
                        hi = hi.max(x);
                    }
                }
                (hi > lo).then_some((lo, hi))
            }
        }
    }

    fn y_range(&self) -> (f64, f64) {
        match self {
            Region::Disc(c, r) => (c.1 - r, c.1 + r),
            Region::Polygon(p) => p
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), q| {
                    (a.min(q.1), b.max(q.1))
                }),
        }
    }
}

/// The length of the union of the regions on the line at `y`.
pub fn union_length(regions: &[Region], y: f64) -> f64 {
    let mut iv: Vec<(f64, f64)> = regions.iter().filter_map(|r| r.interval(y)).collect();
    iv.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut len = 0.0;
    let mut cur: Option<(f64, f64)> = None;
    for (a, b) in iv {
        match cur {
            Some((c0, c1)) if a <= c1 => cur = Some((c0, c1.max(b))),
            Some((c0, c1)) => {
                len += c1 - c0;
                cur = Some((a, b));
            }
            None => cur = Some((a, b)),
        }
    }
    if let Some((c0, c1)) = cur {
        len += c1 - c0;
    }
    len
}

/// The area of the union of the regions, px^2, by scanlines at
/// `lines_per_px` (midpoint rule).
pub fn union_area(regions: &[Region], lines_per_px: u32) -> f64 {
    let (y0, y1) = regions
        .iter()
        .map(Region::y_range)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), (c, d)| {
            (a.min(c), b.max(d))
        });
    if y1 <= y0 {
        return 0.0;
    }
    let h = 1.0 / f64::from(lines_per_px);
    let n = ((y1 - y0) / h).ceil() as usize;
    (0..n)
        .map(|i| union_length(regions, y0 + (i as f64 + 0.5) * h) * h)
        .sum()
}

/// How a reference stroke joins and caps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RefJoin {
    /// Miter with this limit (ratio of miter length to width).
    Miter(f64),
    /// Round.
    Round,
    /// Bevel.
    Bevel,
}

/// Reference caps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RefCap {
    /// Flat at the end.
    Butt,
    /// Half disc.
    Round,
    /// Half square.
    Square,
}

/// The stroke of a polyline (px) as regions, from the definition (SVG):
/// a rectangle per segment, a join region at every inner vertex (and every
/// vertex of a closed one), caps at the ends of an open one.
pub fn polyline_stroke(
    points: &[(f64, f64)],
    h: f64,
    join: RefJoin,
    cap: RefCap,
    closed: bool,
) -> Vec<Region> {
    let mut pts: Vec<(f64, f64)> = Vec::new();
    for &p in points {
        if pts.last() != Some(&p) {
            pts.push(p);
        }
    }
    if closed && pts.len() > 1 && pts.first() == pts.last() {
        pts.pop();
    }
    let n = pts.len();
    let mut out = Vec::new();
    let nseg = if closed { n } else { n.saturating_sub(1) };
    let seg = |k: usize| (pts[k % n], pts[(k + 1) % n]);
    let normal = |(a, b): ((f64, f64), (f64, f64))| {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let l = (dx * dx + dy * dy).sqrt();
        ((-dy / l, dx / l), (dx / l, dy / l))
    };
    for k in 0..nseg {
        let (a, b) = seg(k);
        let ((nx, ny), _) = normal((a, b));
        out.push(Region::Polygon(vec![
            (a.0 + h * nx, a.1 + h * ny),
            (b.0 + h * nx, b.1 + h * ny),
            (b.0 - h * nx, b.1 - h * ny),
            (a.0 - h * nx, a.1 - h * ny),
        ]));
    }
    let joins: Vec<usize> = if closed {
        (0..n).collect()
    } else {
        (1..n.saturating_sub(1)).collect()
    };
    for &k in &joins {
        let v = pts[k];
        let (na, da) = normal(seg((k + n - 1) % n));
        let (nb, db) = normal(seg(k));
        let cross = da.0 * db.1 - da.1 * db.0;
        let s = if cross > 0.0 { -1.0 } else { 1.0 }; // outer side: -n for right turns
        let oa = (v.0 + s * h * na.0, v.1 + s * h * na.1);
        let ob = (v.0 + s * h * nb.0, v.1 + s * h * nb.1);
        match join {
            RefJoin::Round => {
                // SVG: the sector between the two outer corners, on the
                // outer side (through the direction of travel at a U-turn).
                let (a0, a1) = (
                    (oa.1 - v.1).atan2(oa.0 - v.0),
                    (ob.1 - v.1).atan2(ob.0 - v.0),
                );
                let mut d = (a1 - a0).rem_euclid(2.0 * std::f64::consts::PI);
                if d > std::f64::consts::PI {
                    d -= 2.0 * std::f64::consts::PI;
                }
                let mid = a0 + d / 2.0;
                if (mid.cos() * da.0 + mid.sin() * da.1) < 0.0 {
                    d = if d > 0.0 {
                        d - 2.0 * std::f64::consts::PI
                    } else {
                        d + 2.0 * std::f64::consts::PI
                    };
                }
                let mut poly = vec![v];
                for i in 0..=256 {
                    let a = a0 + d * f64::from(i) / 256.0;
                    poly.push((v.0 + h * a.cos(), v.1 + h * a.sin()));
                }
                out.push(Region::Polygon(poly));
            }
            RefJoin::Bevel => out.push(Region::Polygon(vec![v, oa, ob])),
            RefJoin::Miter(limit) => {
                let cos = na.0 * nb.0 + na.1 * nb.1;
                let half = ((1.0 + cos) / 2.0).sqrt(); // cos(turn/2)
                if half > 0.0 && 1.0 / half <= limit {
                    let m = (s * (na.0 + nb.0), s * (na.1 + nb.1));
                    let k = h / (1.0 + cos);
                    out.push(Region::Polygon(vec![
                        v,
                        oa,
                        (v.0 + k * m.0, v.1 + k * m.1),
                        ob,
                    ]));
                } else {
                    out.push(Region::Polygon(vec![v, oa, ob]));
                }
            }
        }
    }
    if !closed && n >= 2 {
        for (end, other) in [(pts[0], pts[1]), (pts[n - 1], pts[n - 2])] {
            match cap {
                RefCap::Butt => {}
                RefCap::Round => out.push(Region::Disc(end, h)),
                RefCap::Square => {
                    let (_, d) = normal((other, end));
                    let (nx, ny) = (-d.1, d.0);
                    out.push(Region::Polygon(vec![
                        (end.0 + h * nx, end.1 + h * ny),
                        (end.0 + h * nx + h * d.0, end.1 + h * ny + h * d.1),
                        (end.0 - h * nx + h * d.0, end.1 - h * ny + h * d.1),
                        (end.0 - h * nx, end.1 - h * ny),
                    ]));
                }
            }
        }
    }
    if n == 1 {
        match cap {
            RefCap::Round => out.push(Region::Disc(pts[0], h)),
            RefCap::Square => {
                let c = pts[0];
                out.push(Region::Polygon(vec![
                    (c.0 - h, c.1 - h),
                    (c.0 + h, c.1 - h),
                    (c.0 + h, c.1 + h),
                    (c.0 - h, c.1 + h),
                ]));
            }
            RefCap::Butt => {}
        }
    }
    out
}

/// The winding number of `(x, y)` about a closed polygon (px), from the
/// vertices: clockwise on screen counts +1.
pub fn polygon_winding(poly: &[(f64, f64)], x: f64, y: f64) -> i32 {
    let mut w = 0;
    for k in 0..poly.len() {
        let (a, b) = (poly[k], poly[(k + 1) % poly.len()]);
        if a.1 <= y && y < b.1 || b.1 <= y && y < a.1 {
            let xc = a.0 + (y - a.1) / (b.1 - a.1) * (b.0 - a.0);
            if xc > x {
                w += if b.1 > a.1 { 1 } else { -1 };
            }
        }
    }
    w
}

/// A small deterministic generator (xorshift), so that the tests need no
/// seed files.
#[derive(Debug, Clone)]
pub struct Rng(pub u64);

impl Rng {
    /// The next number in `[0, 1)`.
    pub fn f(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A number in `[lo, hi)`.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
}

/// A point in px rounded to the fine grid.
pub fn fine_point(x: f64, y: f64) -> FinePoint {
    FinePoint::new((x * 1024.0).round() as i32, (y * 1024.0).round() as i32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn disc_box_area_sums_to_the_disc() {
        let (cx, cy, r) = (3.3, 4.7, 2.2);
        let mut sum = 0.0;
        for j in 0..10 {
            for i in 0..10 {
                sum += disc_box_area(
                    cx,
                    cy,
                    r,
                    f64::from(i),
                    f64::from(j),
                    f64::from(i + 1),
                    f64::from(j + 1),
                );
            }
        }
        assert!((sum - std::f64::consts::PI * r * r).abs() < 1e-9);
        // A quarter of the disc.
        let q = disc_box_area(0.0, 0.0, 1.0, 0.0, 0.0, 5.0, 5.0);
        assert!((q - std::f64::consts::PI / 4.0).abs() < 1e-12);
    }

    #[test]
    fn union_of_overlapping_squares() {
        let sq = |x: f64| Region::Polygon(vec![(x, 0.0), (x + 2.0, 0.0), (x + 2.0, 2.0), (x, 2.0)]);
        let a = union_area(&[sq(0.0), sq(1.0)], 64);
        assert!((a - 6.0).abs() < 1e-9);
    }
}
