//! Independent reference for the text tests, in `f64`: a glyph outline read
//! from the font file by `ttf-parser` (the parser, not the code under
//! test), scaled to pixels in `f64`, its curves flattened far finer than
//! softedge does (chords within 1e-4 px), and the exact area of the
//! outline inside each pixel (every contour clipped to the pixel square by
//! Sutherland–Hodgman, signed areas summed: the winding-weighted area,
//! which for a glyph's non-overlapping contours is its coverage).

use ttf_parser::{Face, GlyphId, OutlineBuilder};

/// Closed contours in px, y down.
#[derive(Debug, Default, Clone)]
pub struct RefOutline {
    /// Each contour's vertices (the last joins the first).
    pub contours: Vec<Vec<(f64, f64)>>,
}

struct Collect<'a> {
    out: &'a mut RefOutline,
    ox: f64,
    oy: f64,
    k: f64,
    cur: Vec<(f64, f64)>,
    last: (f64, f64),
}

impl Collect<'_> {
    fn pt(&self, x: f32, y: f32) -> (f64, f64) {
        (
            self.ox + f64::from(x) * self.k,
            self.oy - f64::from(y) * self.k,
        )
    }
    fn flush(&mut self) {
        if self.cur.len() >= 3 {
            self.out.contours.push(std::mem::take(&mut self.cur));
        }
        self.cur.clear();
    }
    /// Chords within 1e-4 px: a Bézier's deviation from n chords is at
    /// most |second difference| / (8 n^2) (quadratic; cubic 3/4 of max).
    fn curve(&mut self, ctrl: &[(f64, f64)], eval: impl Fn(f64) -> (f64, f64)) {
        let mut m: f64 = 0.0;
        for w in ctrl.windows(3) {
            let dx = w[0].0 - 2.0 * w[1].0 + w[2].0;
            let dy = w[0].1 - 2.0 * w[1].1 + w[2].1;
            m = m.max(dx.hypot(dy));
        }
        let n = ((m / (8.0 * 1e-4)).sqrt().ceil() as usize).clamp(1, 100_000);
        for i in 1..=n {
            let p = eval(i as f64 / n as f64);
            self.cur.push(p);
        }
    }
}

impl OutlineBuilder for Collect<'_> {
    fn move_to(&mut self, x: f32, y: f32) {
        self.flush();
        let p = self.pt(x, y);
        self.cur.push(p);
        self.last = p;
    }
    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.pt(x, y);
        self.cur.push(p);
        self.last = p;
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (a, b, c) = (self.last, self.pt(x1, y1), self.pt(x, y));
        self.curve(&[a, b, c], |t| {
            let u = 1.0 - t;
            (
                u * u * a.0 + 2.0 * u * t * b.0 + t * t * c.0,
                u * u * a.1 + 2.0 * u * t * b.1 + t * t * c.1,
            )
        });
        self.last = c;
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (a, b, c, d) = (self.last, self.pt(x1, y1), self.pt(x2, y2), self.pt(x, y));
        self.curve(&[a, b, c, d], |t| {
            let u = 1.0 - t;
            let (w0, w1, w2, w3) = (u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t);
            (
                w0 * a.0 + w1 * b.0 + w2 * c.0 + w3 * d.0,
                w0 * a.1 + w1 * b.1 + w2 * c.1 + w3 * d.1,
            )
        });
        self.last = d;
    }
    fn close(&mut self) {
        self.flush();
    }
}

impl RefOutline {
    /// Glyph `g` of `face` at `size_px` per em, origin (pen on the
    /// baseline) at `(ox, oy)` px.
    pub fn glyph(face: &Face<'_>, g: GlyphId, size_px: f64, ox: f64, oy: f64) -> Self {
        let mut out = RefOutline::default();
        let k = size_px / f64::from(face.units_per_em());
        let mut c = Collect {
            out: &mut out,
            ox,
            oy,
            k,
            cur: Vec::new(),
            last: (0.0, 0.0),
        };
        face.outline_glyph(g, &mut c);
        c.flush();
        out
    }

    /// Adds another outline's contours (a string's glyphs).
    pub fn extend(&mut self, other: RefOutline) {
        self.contours.extend(other.contours);
    }

    /// The box around every vertex, px: `(x0, y0, x1, y1)`.
    pub fn bbox(&self) -> Option<(f64, f64, f64, f64)> {
        let mut it = self.contours.iter().flatten();
        let &(x, y) = it.next()?;
        Some(it.fold((x, y, x, y), |b, &(x, y)| {
            (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y))
        }))
    }

    /// Signed area (clockwise on screen positive), px^2.
    pub fn signed_area(&self) -> f64 {
        self.contours.iter().map(|c| shoelace(c)).sum()
    }

    /// The exact coverage of pixel `(i, j)`: the winding-weighted area
    /// inside it, in absolute value, clamped to 1.
    pub fn pixel_coverage(&self, i: i32, j: i32) -> f64 {
        let (x0, y0) = (f64::from(i), f64::from(j));
        let mut a = 0.0;
        for c in &self.contours {
            a += shoelace(&clip_box(c, x0, y0, x0 + 1.0, y0 + 1.0));
        }
        a.abs().min(1.0)
    }

    /// Coverage of every pixel of `w x h` from `(0, 0)`, row-major: each
    /// contour clipped to the row's strip once, the strip's polygon to each
    /// pixel; pixels outside the outline's box are 0.
    pub fn coverage_image(&self, w: i32, h: i32) -> Vec<f64> {
        let mut out = vec![0.0; (w * h) as usize];
        let Some((bx0, by0, bx1, by1)) = self.bbox() else {
            return out;
        };
        let (i0, i1) = ((bx0.floor() as i32).max(0), (bx1.ceil() as i32 + 1).min(w));
        for j in (by0.floor() as i32).max(0)..(by1.ceil() as i32 + 1).min(h) {
            let (y0, y1) = (f64::from(j), f64::from(j) + 1.0);
            let strips: Vec<Vec<(f64, f64)>> = self
                .contours
                .iter()
                .map(|c| clip_box(c, f64::MIN, y0, f64::MAX, y1))
                .filter(|c| c.len() >= 3)
                .collect();
            for i in i0..i1 {
                let (x0, x1) = (f64::from(i), f64::from(i) + 1.0);
                let a: f64 = strips
                    .iter()
                    .map(|c| shoelace(&clip_box(c, x0, f64::MIN, x1, f64::MAX)))
                    .sum();
                out[(j * w + i) as usize] = a.abs().min(1.0);
            }
        }
        out
    }
}

fn shoelace(c: &[(f64, f64)]) -> f64 {
    let n = c.len();
    let mut s = 0.0;
    for k in 0..n {
        let (a, b) = (c[k], c[(k + 1) % n]);
        s += a.0 * b.1 - b.0 * a.1;
    }
    s / 2.0
}

/// Sutherland–Hodgman against the box: the polygon's part inside, with
/// degenerate edges along the border (which carry no area).
fn clip_box(c: &[(f64, f64)], x0: f64, y0: f64, x1: f64, y1: f64) -> Vec<(f64, f64)> {
    let mut poly = c.to_vec();
    type Side = (fn((f64, f64), f64) -> f64, f64);
    let sides: [Side; 4] = [
        (|p, v| p.0 - v, x0),
        (|p, v| v - p.0, x1),
        (|p, v| p.1 - v, y0),
        (|p, v| v - p.1, y1),
    ];
    for (dist, v) in sides {
        if poly.is_empty() {
            break;
        }
        let mut out = Vec::with_capacity(poly.len() + 4);
        let n = poly.len();
        for k in 0..n {
            let (a, b) = (poly[k], poly[(k + 1) % n]);
            let (da, db) = (dist(a, v), dist(b, v));
            if da >= 0.0 {
                out.push(a);
            }
            if (da >= 0.0) != (db >= 0.0) {
                let t = da / (da - db);
                out.push((a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)));
            }
        }
        poly = out;
    }
    poly
}

/// A string laid out in `f64` from the font's own numbers (advances and
/// kerning as `ttf-parser` reports them: the GPOS `kern` feature's first
/// pair subtable per lookup, or the `kern` table), glyphs' outlines joined.
/// Returns the outline and the pen's end, px.
pub fn string_outline(
    face: &Face<'_>,
    text: &str,
    size_px: f64,
    ox: f64,
    oy: f64,
    kern: &dyn Fn(GlyphId, GlyphId) -> i32,
) -> (RefOutline, f64) {
    let k = size_px / f64::from(face.units_per_em());
    let mut out = RefOutline::default();
    let mut x = ox;
    let mut prev = None;
    for ch in text.chars() {
        let g = face.glyph_index(ch).unwrap_or(GlyphId(0));
        if let Some(p) = prev {
            x += f64::from(kern(p, g)) * k;
        }
        out.extend(RefOutline::glyph(face, g, size_px, x, oy));
        x += f64::from(face.glyph_hor_advance(g).unwrap_or(0)) * k;
        prev = Some(g);
    }
    (out, x)
}
