//! The depth buffer of one band: a depth, a coverage count and a sample
//! mask per pixel, and the passes that compose depth fragments into it
//! (seed 004's z-buffer; the method is described in [`hsr`](crate::hsr)).

use super::{Band, BandError, MAX_WIDTH};
use crate::geom::SubPoint;
use crate::SUB_ONE;

/// Depth and coverage of one band's pixels, over caller-provided storage.
///
/// - `depth`: 16 bits per pixel, larger is nearer (seed 004); cleared to 0,
///   the farthest depth. Sixteen bits give 65 536 depth steps: for a scene
///   4 units deep, 1/16384 unit, far below one pixel for the displays this
///   library serves (a 240 px view across 4 units is 60 px per unit), so
///   two surfaces are ordered wrongly only where they are closer in depth
///   than that; 32-bit depth would double the RAM for no visible change.
/// - `covered`: two `u16`s per pixel ([`covered_len`](Self::covered_len)):
///   how much of the pixel surfaces already claim, in 1/32768 px (16 bits
///   used), what lets anti-aliased edges meet the
///   z-buffer (see [`hsr`](crate::hsr)); and which of the pixel's 4 x 4
///   sample points they cover ([`SAMPLES`]), so that a fragment lying
///   wholly under what is claimed is known to be hidden (a count alone
///   cannot tell it from one in the uncovered rest).
///
/// For 240x240 and 16-row bands that is `3 * 2 * 240 * 16` = 23 040 bytes
/// next to the band's accumulator.
#[derive(Debug)]
pub struct DepthBuffer<'a> {
    depth: &'a mut [u16],
    covered: &'a mut [u16],
    band: Band,
}

impl<'a> DepthBuffer<'a> {
    /// `u16`s needed for `depth`: one per pixel.
    pub const fn len(width: u16, rows: u16) -> usize {
        width as usize * rows as usize
    }

    /// `u16`s needed for `covered`: two per pixel (the claimed coverage
    /// and the claimed sample mask).
    pub const fn covered_len(width: u16, rows: u16) -> usize {
        2 * Self::len(width, rows)
    }

    /// A depth buffer for `band` (longer slices are fine). Cleared.
    pub fn new(
        depth: &'a mut [u16],
        covered: &'a mut [u16],
        band: Band,
    ) -> Result<Self, BandError> {
        let y_ok = band.y0.unsigned_abs() <= crate::geom::COORD_LIMIT_PX as u32;
        if band.width == 0 || band.rows == 0 || band.width > MAX_WIDTH || !y_ok {
            return Err(BandError::BadBand);
        }
        let n = Self::len(band.width, band.rows);
        if depth.len() < n || covered.len() < Self::covered_len(band.width, band.rows) {
            return Err(BandError::DepthTooSmall);
        }
        let mut buf = Self {
            depth,
            covered,
            band,
        };
        buf.clear();
        Ok(buf)
    }

    /// The band this buffer holds.
    pub fn band(&self) -> Band {
        self.band
    }

    /// Every pixel empty and at the farthest depth (0).
    pub fn clear(&mut self) {
        let n = Self::len(self.band.width, self.band.rows);
        if let Some(d) = self.depth.get_mut(..n) {
            d.iter_mut().for_each(|z| *z = 0);
        }
        if let Some(c) = self.covered.get_mut(..2 * n) {
            c.iter_mut().for_each(|c| *c = 0);
        }
    }

    /// Ends the [`ZPass::Centres`](super::ZPass::Centres) pass: each
    /// pixel's depth is now its threshold (the nearest fragment touching it
    /// less that fragment's depth slope across a pixel), and its coverage
    /// and samples are emptied for the drawing passes.
    pub fn finish_centres(&mut self) {
        let n = Self::len(self.band.width, self.band.rows);
        if let Some(c) = self.covered.get_mut(..2 * n) {
            c.iter_mut().for_each(|k| *k = 0);
        }
    }

    /// The depth at frame pixel `(x, y)`, or `None` outside the band: the
    /// nearest depth drawn (single pass) or the threshold of the drawing
    /// passes (three passes).
    pub fn depth(&self, x: i32, y: i32) -> Option<u16> {
        self.depth.get(self.index(x, y)?).copied()
    }

    /// How much of frame pixel `(x, y)` is covered, in 1/4096 px, or `None`
    /// outside the band.
    pub fn covered(&self, x: i32, y: i32) -> Option<u16> {
        self.covered.get(self.index(x, y)?).copied()
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let r = y.checked_sub(self.band.y0)?;
        if x < 0 || x >= i32::from(self.band.width) || r < 0 || r >= i32::from(self.band.rows) {
            return None;
        }
        Some(r as usize * usize::from(self.band.width) + x as usize)
    }

    /// The claimed sample mask of frame pixel `(x, y)` ([`SAMPLES`]), or
    /// `None` outside the band.
    pub fn samples(&self, x: i32, y: i32) -> Option<u16> {
        let n = Self::len(self.band.width, self.band.rows);
        self.covered.get(n + self.index(x, y)?).copied()
    }

    /// Row `r` of the band: (depths, coverage counts, sample masks).
    pub(crate) fn row_mut(&mut self, r: usize) -> Option<ZRow<'_>> {
        let w = usize::from(self.band.width);
        let n = Self::len(self.band.width, self.band.rows);
        let d = self.depth.get_mut(r * w..(r + 1) * w)?;
        let (counts, masks) = self.covered.get_mut(..2 * n)?.split_at_mut_checked(n)?;
        let c = counts.get_mut(r * w..(r + 1) * w)?;
        let m = masks.get_mut(r * w..(r + 1) * w)?;
        Some((d, c, m))
    }
}

/// One row of a [`DepthBuffer`]: depths, coverage counts, sample masks.
pub(crate) type ZRow<'r> = (&'r mut [u16], &'r mut [u16], &'r mut [u16]);

/// The sample points of a pixel's mask: a 4 x 4 grid at 0, 5/16, 11/16
/// and 1 px from its top-left corner in x and y (the corners included);
/// bit `4 j + i` is column `i` of row `j`. A pixel wholly covered has every
/// bit.
pub const SAMPLES: u32 = 16;

/// Every sample of a pixel.
pub(crate) const ALL_SAMPLES: u16 = u16::MAX;

/// The sample rows and columns, in 1/16 px from the pixel's top-left
/// corner: on both borders and between (spacing 5, 6, 5). With the corners
/// among them a triangle that holds every sample holds the whole pixel, so
/// "every sample claimed" means the pixel is (nearly) full.
const SAMPLE_AT: [i64; 4] = [0, 5, 11, SUB_ONE as i64];

/// Half the widest sample spacing, 3/16 px: every point of a pixel lies
/// this close (in x and in y) to one of its samples.
const SAMPLE_REACH: i64 = 3;

/// Full coverage as stored in [`DepthBuffer`]: 1/32768 px (the band's
/// coverage, 1/65536 px, with its last bit dropped, so that a whole pixel
/// fits a `u16`).
pub(crate) const FULL: u16 = 1 << FULL_BITS;
/// `log2(FULL)`.
pub(crate) const FULL_BITS: u32 = 15;

/// Which of a pixel's 4 x 4 sample points ([`SAMPLES`](crate::hsr::SAMPLES))
/// a triangle covers: its three edge functions `E = a x + b y + c` (x, y
/// in 1/16 px, positive inside), stepped by one addition per pixel, plus
/// each edge's `a ox` and `b oy` at the four sample columns and rows
/// (setup; about 170 bytes in all). A sample
/// on an edge belongs to the triangle on the side the edge's normal points
/// to when it runs right or down (`a > 0`, or `a = 0` and `b > 0`): two
/// triangles sharing an edge never both have it, so a mesh's fragments
/// claim disjoint samples.
///
/// Ranges: `|a|, |b| <= 2^16`, coordinates `<= 2^15 + 2^12` sub-pixels in a
/// band: `|E| < 2^34` in `i64`.
pub(crate) struct SampleEdges {
    /// `(a, b, c)` per edge, inside positive.
    edges: [(i64, i64, i64); 3],
    /// `a ox` at the sample columns and `b oy` at the sample rows, per
    /// edge (`|a ox| <= 2^20`).
    columns: [[i32; 4]; 3],
    rows: [[i32; 4]; 3],
    /// Whether a sample exactly on the edge is inside.
    ties: [bool; 3],
    /// `3 (|a| + |b|)`: the edge moved out by 3/16 px in x and y.
    grow: [i64; 3],
    /// The triangle's box grown by 3/16 px, `[x0, y0, x1, y1]` in 1/16 px
    /// (the grown edges alone reach further at sharp corners).
    reach: [i64; 4],
}

impl SampleEdges {
    /// The edges of the triangle `v` (either orientation); `None` for zero
    /// area.
    pub(crate) fn new(v: &[SubPoint; 3]) -> Option<Self> {
        let area2 = crate::geom::area2(v);
        if area2 == 0 {
            return None;
        }
        let sign = area2.signum();
        let mut edges = [(0i64, 0i64, 0i64); 3];
        let mut columns = [[0i32; 4]; 3];
        let mut rows = [[0i32; 4]; 3];
        let mut ties = [false; 3];
        let mut grow = [0i64; 3];
        for k in 0..3 {
            let (p, q) = (v[k], v[(k + 1) % 3]);
            // cross(q - p, s - p), times the orientation: inside positive.
            let (dx, dy) = (i64::from(q.x - p.x), i64::from(q.y - p.y));
            let (a, b) = (-dy * sign, dx * sign);
            let c = -(a * i64::from(p.x) + b * i64::from(p.y));
            edges[k] = (a, b, c);
            ties[k] = a > 0 || (a == 0 && b > 0);
            grow[k] = SAMPLE_REACH * (a.abs() + b.abs());
            for (i, &at) in SAMPLE_AT.iter().enumerate() {
                columns[k][i] = (a * at) as i32;
                rows[k][i] = (b * at) as i32;
            }
        }
        let (mut lo, mut hi) = ([i64::MAX; 2], [i64::MIN; 2]);
        for p in v {
            let c = [i64::from(p.x), i64::from(p.y)];
            for d in 0..2 {
                lo[d] = lo[d].min(c[d]);
                hi[d] = hi[d].max(c[d]);
            }
        }
        let reach = [
            lo[0] - SAMPLE_REACH,
            lo[1] - SAMPLE_REACH,
            hi[0] + SAMPLE_REACH,
            hi[1] + SAMPLE_REACH,
        ];
        Some(Self {
            edges,
            columns,
            rows,
            ties,
            grow,
            reach,
        })
    }

    /// The edge values at the top-left corner of pixel `(x, y)`.
    pub(crate) fn at(&self, x: i32, y: i32) -> [i64; 3] {
        let (px, py) = (
            i64::from(x) * i64::from(SUB_ONE),
            i64::from(y) * i64::from(SUB_ONE),
        );
        self.edges.map(|(a, b, c)| a * px + b * py + c)
    }

    /// The masks of the pixel whose corner values are `e`: the samples
    /// inside the triangle (what it claims), and the samples to test it by
    /// — the same, or, when there are none (a sliver between them), the
    /// samples within 3/16 px of it in x and y (inside the triangle's edges
    /// moved out by that much and its box grown by that much; every point
    /// of a pixel is that close to one of its samples, so a fragment is
    /// never tested by an empty mask). `(x, y)` is the pixel.
    pub(crate) fn masks(&self, e: &[i64; 3], x: i32, y: i32) -> (u16, u16) {
        let inside = self.samples_inside(e, [0; 3]);
        if inside != 0 {
            return (inside, inside);
        }
        // The samples in the grown box.
        let (px, py) = (
            i64::from(x) * i64::from(SUB_ONE),
            i64::from(y) * i64::from(SUB_ONE),
        );
        let mut boxed = 0u16;
        let mut bit = 0;
        for oy in SAMPLE_AT {
            for ox in SAMPLE_AT {
                let (sx, sy) = (px + ox, py + oy);
                let inside = sx >= self.reach[0]
                    && sx <= self.reach[2]
                    && sy >= self.reach[1]
                    && sy <= self.reach[3];
                boxed |= u16::from(inside) << bit;
                bit += 1;
            }
        }
        (0, self.samples_inside(e, self.grow) & boxed)
    }

    fn samples_inside(&self, e: &[i64; 3], grow: [i64; 3]) -> u16 {
        // Edge by edge: 16 compares each, the bits assembled without
        // branches; stop when nothing is left.
        let mut m = ALL_SAMPLES;
        for (k, &ek) in e.iter().enumerate() {
            let (Some(cols), Some(rows), Some(&g), Some(&tie)) = (
                self.columns.get(k),
                self.rows.get(k),
                grow.get(k),
                self.ties.get(k),
            ) else {
                return 0;
            };
            // The samples include the pixel's corners and the edge is
            // straight: with all four corners strictly inside every sample
            // is, with all four strictly outside none is.
            let corners = [
                ek + g,
                ek + g + i64::from(cols[3]),
                ek + g + i64::from(rows[3]),
                ek + g + i64::from(cols[3]) + i64::from(rows[3]),
            ];
            if corners.iter().all(|&v| v > 0) {
                continue;
            }
            if corners.iter().all(|&v| v < 0) {
                return 0;
            }
            let mut edge = 0u16;
            let mut bit = 0;
            for &r in rows {
                let base = ek + g + i64::from(r);
                for &c in cols {
                    let v = base + i64::from(c);
                    edge |= u16::from(v > 0 || (tie && v == 0)) << bit;
                    bit += 1;
                }
            }
            m &= edge;
            if m == 0 {
                break;
            }
        }
        m
    }

    /// Steps the corner values one pixel to the right.
    pub(crate) fn step(&self, e: &mut [i64; 3]) {
        for (v, (a, _, _)) in e.iter_mut().zip(&self.edges) {
            *v += a * i64::from(SUB_ONE);
        }
    }
}

/// Which pass of the z-buffer a [`DepthTriangle::draw_z`](crate::hsr::DepthTriangle::draw_z) call makes (see
/// the module documentation; [`draw_zbuffer`](crate::hsr::draw_zbuffer) runs them in order).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ZPass {
    /// One pass: replace a pixel where a whole fragment is nearer than all
    /// of it, else composite under it. Exact for aliased drawing.
    Single,
    /// First of three: the nearest fragment touching each pixel sets its
    /// threshold (nothing drawn). Call [`DepthBuffer::finish_centres`]
    /// after it.
    Centres,
    /// Second of three: the fragments at or in front of the threshold.
    Front,
    /// Third of three: the fragments behind it.
    Back,
}
