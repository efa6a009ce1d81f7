//! The primitives users draw: triangles, polygons and 1-px lines.
//!
//! Takes vertices in sub-pixel units with linear 12-bit colours (one per
//! vertex, or one for the whole primitive), checks them (range, simplicity),
//! sets up the Gouraud plane ([`shade`](crate::shade)), walks every edge
//! (the `edge` module) and sweeps the spans ([`band`](crate::band)).
//! Gives nothing back but a `Result`: the values land in the band buffer.
//!
//! ## Results for degenerate input (documented, never a panic)
//!
//! - A vertex outside `±COORD_LIMIT_PX` ([`geom`](crate::geom)):
//!   [`DrawError::Coord`], nothing drawn.
//! - Zero area (fewer than 3 vertices, collinear or repeated vertices),
//!   zero-length lines: `Ok`, nothing drawn.
//! - A polygon whose non-adjacent edges touch or cross (after repeated
//!   consecutive vertices are dropped), a bow tie included:
//!   [`DrawError::SelfIntersecting`], nothing drawn (its coverage would not
//!   be an area). A polygon whose vertices all lie on one line: `Ok`,
//!   nothing drawn.
//! - Gouraud intensity is the plane's value at the pixel centre (seed 001's
//!   `I_i` of the edge pixel). Near a vertex a touched pixel's centre may lie
//!   outside the primitive, where the plane is extrapolated by at most one
//!   full scale; the resolve clamps the pixel to `0..=4095`.
//! - Colours above 4095 are clamped to 4095.
//! - Parts outside the frame or the band are clipped.
//!
//! Orientation does not matter: clockwise and counter-clockwise vertex
//! orders give the same pixels.

pub(crate) mod simple;

use crate::band::{BandBuffer, ComposeOp, Coverage, Paint};
use crate::edge::{AliasedWalk, AreaMode, EdgeWalk};
use crate::geom::{area2, FinePoint, SubPoint};
use crate::pixel_model::{walk_bed_of_nails, walk_circular, walk_hex19, walk_hex7, CircularFilter};
use crate::shade::Plane;
use crate::style::Opacity;
use crate::SUB_BITS;

pub use crate::error::DrawError;
pub use crate::units::MAX_POLYGON_VERTICES;

/// What "covered area" means for an edge pixel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum PixelModel {
    /// Square pixel, exact area (within 3/4096 px per edge; see
    /// `AreaMode::Exact`).
    #[default]
    Box,
    /// Square pixel, the single formula of seed 001 (error up to `k/8` of a
    /// pixel for an edge of slope `k <= 1`; see `AreaMode`).
    BoxSeed,
    /// The 4x4 bed-of-nails filter of seed 000 (2x2 samples per pixel, tent
    /// weights on a 2x2-pixel base; [`pixel_model`](crate::pixel_model)).
    BedOfNails4,
    /// The 8x8 bed-of-nails filter of seed 000 (4x4 samples per pixel).
    BedOfNails8,
    /// The hexagonal pixel of seed 003: 7 points, centre weight 2/8, ring
    /// points 1/8, shared with the neighbours.
    Hex7,
    /// The hexagonal pixel of seed 003 with 19 points (1 + 6 + 12) on the
    /// same lattice, weights nearest the seed's cone weights that are equal
    /// energy ([`HEX19_POINTS`](crate::pixel_model::HEX19_POINTS)).
    Hex19,
    /// The cone filter of seed 003's survey, `R` = 1 px, as an equal-energy
    /// splat of 16x16 samples per pixel ([`CircularFilter::Cone`]).
    Cone,
    /// The Gaussian of seed 003's survey, `sigma` = 1/2 px, cut at 1.5 px
    /// ([`CircularFilter::Gaussian`]).
    Gaussian,
    /// The Hamming filter `(cos(pi x/W) cos(pi y/W))^e` of seed 003's
    /// survey, `W` = 2 px, `e` = 2 ([`CircularFilter::Hamming`]).
    Hamming,
}

impl PixelModel {
    /// Every pixel model, in declaration order (for sweeps over them:
    /// tests, fuzzing, galleries).
    pub const ALL: [PixelModel; 9] = [
        PixelModel::Box,
        PixelModel::BoxSeed,
        PixelModel::BedOfNails4,
        PixelModel::BedOfNails8,
        PixelModel::Hex7,
        PixelModel::Hex19,
        PixelModel::Cone,
        PixelModel::Gaussian,
        PixelModel::Hamming,
    ];
}

/// How primitives are drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct RenderStyle {
    /// `false`: aliased, pixel centres sampled with the top-left rule.
    pub antialias: bool,
    /// The pixel model used when `antialias` is on.
    pub model: PixelModel,
}

impl Default for RenderStyle {
    /// Anti-aliased, exact box coverage.
    fn default() -> Self {
        Self {
            antialias: true,
            model: PixelModel::Box,
        }
    }
}

impl RenderStyle {
    /// Aliased drawing (top-left fill rule).
    pub const ALIASED: Self = Self {
        antialias: false,
        model: PixelModel::Box,
    };
}

/// A triangle with a linear 12-bit colour per vertex (Gouraud shading).
///
/// ```
/// use softedge::{Band, BandBuffer, RenderStyle, SubPoint, Triangle};
/// let band = Band::new(8, 0, 8);
/// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// buf.clear([0]);
/// // Half of pixel (0, 0), exactly: the triangle (0,0) (1,0) (0,1) px.
/// let t = Triangle::flat([SubPoint::from_px(0, 0), SubPoint::from_px(1, 0), SubPoint::from_px(0, 1)], [4000]);
/// t.draw(&mut buf, &RenderStyle::default()).unwrap();
/// assert_eq!(buf.lin12(0, 0), Some([2000]));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Triangle<const C: usize> {
    /// Vertices, in either orientation.
    pub vertices: [SubPoint; 3],
    /// Linear 12-bit colour of each vertex.
    pub colors: [[u16; C]; 3],
}

impl<const C: usize> Triangle<C> {
    /// A Gouraud-shaded triangle.
    pub const fn new(vertices: [SubPoint; 3], colors: [[u16; C]; 3]) -> Self {
        Self { vertices, colors }
    }

    /// A flat-coloured triangle.
    pub const fn flat(vertices: [SubPoint; 3], color: [u16; C]) -> Self {
        Self {
            vertices,
            colors: [color; 3],
        }
    }

    /// Accumulates the triangle into the band (seed 000's `I_acc += I * S`,
    /// relative to the band's background).
    pub fn draw(&self, band: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        for v in self.vertices {
            v.check()?;
        }
        let Some(plane) = Plane::triangle(self.vertices, self.colors, [0; C]) else {
            return Ok(());
        };
        let [c0, c1, c2] = self.colors;
        let paint = if c0 == c1 && c1 == c2 {
            Paint::Flat(c0.map(|v| v.min(crate::LIN_MAX)))
        } else {
            Paint::Plane(&plane)
        };
        fill(
            band,
            &self.vertices,
            &paint,
            ComposeOp::Add(Opacity::OPAQUE),
            style,
        );
        Ok(())
    }
}

/// The colours of a [`Polygon`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PolygonColors<'a, const C: usize> {
    /// One colour for the whole polygon.
    Flat([u16; C]),
    /// One colour per vertex (Gouraud; the polygon is split into triangles
    /// along its diagonals, which the accumulation makes seamless).
    PerVertex(&'a [[u16; C]]),
}

/// A simple polygon, convex or concave, of up to [`MAX_POLYGON_VERTICES`]
/// vertices.
///
/// ```
/// use softedge::{Band, BandBuffer, Polygon, PolygonColors, RenderStyle, SubPoint};
/// let band = Band::new(8, 0, 8);
/// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// buf.clear([0]);
/// let l_shape = [(0, 0), (4, 0), (4, 2), (2, 2), (2, 4), (0, 4)].map(|(x, y)| SubPoint::from_px(x, y));
/// Polygon::new(&l_shape, PolygonColors::Flat([4095])).draw(&mut buf, &RenderStyle::default()).unwrap();
/// assert_eq!(buf.lin12(3, 1), Some([4095]));
/// assert_eq!(buf.lin12(3, 3), Some([0]));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Polygon<'a, const C: usize> {
    /// Vertices in order, either orientation; the last joins the first.
    pub vertices: &'a [SubPoint],
    /// Colours.
    pub colors: PolygonColors<'a, C>,
}

impl<'a, const C: usize> Polygon<'a, C> {
    /// A polygon.
    pub const fn new(vertices: &'a [SubPoint], colors: PolygonColors<'a, C>) -> Self {
        Self { vertices, colors }
    }

    /// Accumulates the polygon into the band.
    pub fn draw(&self, band: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        // No depths kept: the polygon path is what small-RAM firmware
        // runs, and every byte of its stack counts there.
        let Some(p) = self.prepare::<0>(None)? else {
            return Ok(());
        };
        let add = ComposeOp::Add(Opacity::OPAQUE);
        if let Some(&first) = p.colors.first() {
            if p.colors.iter().all(|c| *c == first) {
                let paint = Paint::Flat(first.map(|v| v.min(crate::LIN_MAX)));
                fill(band, &p.points, &paint, add, style);
                return Ok(());
            }
        }
        p.triangles(|tri, colors, _| {
            if let Some(plane) = Plane::triangle(tri, colors, [0; C]) {
                fill(band, &tri, &Paint::Plane(&plane), add, style);
            }
        })
    }

    /// Checks the polygon and drops repeated vertices; `None` when nothing
    /// is to be drawn. Keeps up to `D` depths (0: none, all read as 0).
    pub(crate) fn prepare<const D: usize>(
        &self,
        depths: Option<&[u16]>,
    ) -> Result<Option<Prepared<C, D>>, DrawError> {
        let v = self.vertices;
        if v.len() > MAX_POLYGON_VERTICES {
            return Err(DrawError::TooManyVertices);
        }
        if let PolygonColors::PerVertex(c) = self.colors {
            if c.len() != v.len() {
                return Err(DrawError::ColorCount);
            }
        }
        if depths.is_some_and(|d| d.len() != v.len()) {
            return Err(DrawError::ColorCount);
        }
        for p in v {
            p.check()?;
        }
        // Drop repeated consecutive vertices: they only add zero-length edges.
        let mut p = Prepared {
            points: heapless::Vec::new(),
            colors: heapless::Vec::new(),
            depths: heapless::Vec::new(),
        };
        for (k, &pt) in v.iter().enumerate() {
            if p.points.last() != Some(&pt) {
                let c = match self.colors {
                    PolygonColors::Flat(c) => c,
                    PolygonColors::PerVertex(cs) => cs.get(k).copied().unwrap_or([0; C]),
                };
                let z = depths.and_then(|d| d.get(k).copied()).unwrap_or(0);
                // Capacity is MAX_POLYGON_VERTICES, checked above.
                let _ = p.points.push(pt);
                let _ = p.colors.push(c);
                let _ = p.depths.push(z);
            }
        }
        while p.points.len() > 1 && p.points.first() == p.points.last() {
            p.points.pop();
            p.colors.pop();
            p.depths.pop();
        }
        if p.points.len() < 3 || simple::collinear(&p.points) {
            return Ok(None);
        }
        if !simple::is_simple(&p.points) {
            return Err(DrawError::SelfIntersecting);
        }
        Ok(Some(p))
    }
}

/// A checked polygon: distinct consecutive vertices, simple; up to `D`
/// depths (missing ones read as 0).
pub(crate) struct Prepared<const C: usize, const D: usize> {
    points: heapless::Vec<SubPoint, MAX_POLYGON_VERTICES>,
    colors: heapless::Vec<[u16; C], MAX_POLYGON_VERTICES>,
    depths: heapless::Vec<u16, D>,
}

impl<const C: usize, const D: usize> Prepared<C, D> {
    /// Splits the polygon into triangles along its diagonals (ear clipping).
    pub(crate) fn triangles(
        &self,
        mut emit: impl FnMut([SubPoint; 3], [[u16; C]; 3], [u16; 3]),
    ) -> Result<(), DrawError> {
        let ok = simple::ear_clip::<MAX_POLYGON_VERTICES>(&self.points, |idx| {
            let pick = |k: usize| {
                Some((
                    *self.points.get(k)?,
                    *self.colors.get(k)?,
                    self.depths.get(k).copied().unwrap_or(0),
                ))
            };
            let (Some(a), Some(b), Some(c)) = (pick(idx[0]), pick(idx[1]), pick(idx[2])) else {
                return;
            };
            emit([a.0, b.0, c.0], [a.1, b.1, c.1], [a.2, b.2, c.2]);
        });
        if ok {
            Ok(())
        } else {
            Err(DrawError::SelfIntersecting)
        }
    }
}

/// A line 1 px wide, with butt ends, its colour interpolated from `from` to
/// `to`.
///
/// It is drawn as the rectangle of width 1 centred on the segment (corners
/// rounded to 1/16 px; anti-aliased, its intensity is scaled once by the
/// ratio of the ideal to the rounded area), so its summed intensity equals
/// its length times its colour whatever its angle or sub-pixel position.
///
/// ```
/// use softedge::{Band, BandBuffer, Line, RenderStyle, SubPoint};
/// let band = Band::new(8, 0, 4);
/// let (mut acc, mut cover) = ([0i32; 32], [0i32; BandBuffer::<1>::cover_len(8, 4)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// buf.clear([0]);
/// // Horizontal, on the boundary between rows 1 and 2: half in each.
/// Line::new(SubPoint::from_px(1, 2), SubPoint::from_px(7, 2), [[4094], [4094]])
///     .draw(&mut buf, &RenderStyle::default())
///     .unwrap();
/// assert_eq!(buf.lin12(3, 1), Some([2047]));
/// assert_eq!(buf.lin12(3, 2), Some([2047]));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Line<const C: usize> {
    /// Start point.
    pub from: SubPoint,
    /// End point.
    pub to: SubPoint,
    /// Linear 12-bit colours at `from` and `to`.
    pub colors: [[u16; C]; 2],
}

impl<const C: usize> Line<C> {
    /// A line.
    pub const fn new(from: SubPoint, to: SubPoint, colors: [[u16; C]; 2]) -> Self {
        Self { from, to, colors }
    }

    /// Accumulates the line into the band.
    pub fn draw(&self, band: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        let Some((quad, ideal, actual)) = self.rectangle()? else {
            return Ok(());
        };
        let [c0, c1] = self.colors;
        let bg = band.background();
        let Some(plane) = Plane::triangle([quad[0], quad[1], quad[2]], [c0, c1, c1], bg) else {
            return Ok(());
        };
        // Rounding the corners to 1/16 px changes the rectangle's area by up
        // to a few per cent, depending on the angle: scale the intensity
        // (relative to the background, what the line adds) once by ideal /
        // actual area so the line's energy is exact.
        // (Aliased lines keep their colour: their energy is a pixel count.)
        let plane = if style.antialias {
            plane.scaled(ideal, actual)
        } else {
            plane
        };
        let absolute = plane.offset(bg);
        let paint = Paint::Plane(&absolute);
        fill(band, &quad, &paint, ComposeOp::Add(Opacity::OPAQUE), style);
        Ok(())
    }

    /// The rectangle of width 1 px centred on the segment, corners rounded
    /// to 1/16 px, with its ideal and its actual area (in the same units),
    /// or `None` for a zero-length line.
    pub(crate) fn rectangle(&self) -> Result<Option<([SubPoint; 4], i64, i64)>, DrawError> {
        self.from.check()?;
        self.to.check()?;
        let (dx, dy) = (
            i64::from(self.to.x) - i64::from(self.from.x),
            i64::from(self.to.y) - i64::from(self.from.y),
        );
        let len = ((dx * dx + dy * dy) as u64).isqrt() as i64;
        if len == 0 {
            return Ok(None);
        }
        // Half the width, 1/2 px, along the normal; rounded to 1/16 px.
        let half = i64::from(crate::SUB_ONE / 2);
        let nx = crate::arith::div_floor(-dy * half * 2 + len, 2 * len) as i32;
        let ny = crate::arith::div_floor(dx * half * 2 + len, 2 * len) as i32;
        let (a, b) = (self.from, self.to);
        let quad = [
            SubPoint::new(a.x + nx, a.y + ny),
            SubPoint::new(b.x + nx, b.y + ny),
            SubPoint::new(b.x - nx, b.y - ny),
            SubPoint::new(a.x - nx, a.y - ny),
        ];
        let len_256 = (((dx * dx + dy * dy) as u64) << 16).isqrt() as i64;
        let ideal = i64::from(crate::SUB_ONE) * len_256;
        let actual = 2 * (dx * i64::from(ny) - dy * i64::from(nx)).abs() * 256;
        Ok(Some((quad, ideal, actual)))
    }
}

/// Walks every edge of a simple closed outline into the band's scratch,
/// then composes it once with `paint`. Its coverage is the winding integral
/// times the outline's orientation, so either orientation gives the same
/// pixels, and outlines sharing an edge add up exactly.
#[inline(never)] // kept out of line so profiles can name it
pub(crate) fn fill<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    v: &[SubPoint],
    paint: &Paint<'_, C>,
    op: ComposeOp,
    style: &RenderStyle,
) {
    if let Some(rows) = walk_outline(band, v, style) {
        // A clockwise outline (positive area, y down) has its inside left
        // of its downward edges: its winding integral is -coverage.
        let orientation = if area2(v) > 0 { -1 } else { 1 };
        band.compose(
            rows.start,
            rows.end,
            Coverage::Signed(orientation),
            paint,
            op,
        );
    }
}

/// Walks every edge of a closed outline into the band's scratch (the
/// winding integral per pixel, under the style's pixel model) and returns
/// the frame rows the sweep must visit, or `None` when the outline cannot
/// touch the band.
pub(crate) fn walk_outline<const C: usize>(
    band: &mut BandBuffer<'_, C>,
    v: &[SubPoint],
    style: &RenderStyle,
) -> Option<core::ops::Range<i32>> {
    let info = band.band();
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    for p in v {
        x_min = x_min.min(p.x);
        x_max = x_max.max(p.x);
        y_min = y_min.min(p.y);
        y_max = y_max.max(p.y);
    }
    let band_end = info.y0 + i32::from(info.rows);
    // Bed-of-nails filters reach half a pixel beyond the pixel.
    let samples = match style.model {
        PixelModel::BedOfNails4 if style.antialias => 2,
        PixelModel::BedOfNails8 if style.antialias => 4,
        _ => 0,
    };
    let hex = style.antialias && matches!(style.model, PixelModel::Hex7 | PixelModel::Hex19);
    let circular = match style.model {
        _ if !style.antialias => None,
        PixelModel::Cone => Some(CircularFilter::Cone),
        PixelModel::Gaussian => Some(CircularFilter::Gaussian),
        PixelModel::Hamming => Some(CircularFilter::Hamming),
        _ => None,
    };
    // Circular footprints reach up to 1.5 px from the pixel centre.
    let margin = if circular.is_some() {
        2 * crate::SUB_ONE
    } else if samples > 0 || hex {
        crate::SUB_ONE
    } else {
        0
    };
    let (x_min, x_max) = (x_min.saturating_sub(margin), x_max.saturating_add(margin));
    let (y_min, y_max) = (y_min.saturating_sub(margin), y_max.saturating_add(margin));
    let rows = (y_min >> SUB_BITS).max(info.y0)..((y_max >> SUB_BITS) + 1).min(band_end);
    // Wholly above, below, right or left of the band: nothing to add (left
    // of it, the edges' covers would cancel at its first column).
    let cols = info.column_range();
    if rows.start >= rows.end || (x_min >> SUB_BITS) >= cols.end || (x_max >> SUB_BITS) < cols.start
    {
        return None;
    }
    let mode = match style.model {
        PixelModel::BoxSeed => AreaMode::SeedFormula,
        _ => AreaMode::Exact,
    };
    let n = v.len();
    for k in 0..n {
        let (Some(&p0), Some(&p1)) = (v.get(k), v.get((k + 1) % n)) else {
            continue;
        };
        if !style.antialias {
            if let Some(mut w) = AliasedWalk::new(FinePoint::from(p0), FinePoint::from(p1)) {
                w.walk(rows.clone(), band);
            }
        } else if samples > 0 {
            walk_bed_of_nails(band, p0, p1, samples, rows.clone());
        } else if let Some(filter) = circular {
            walk_circular(band, p0, p1, filter, rows.clone());
        } else if hex && style.model == PixelModel::Hex19 {
            walk_hex19(band, p0, p1, rows.clone());
        } else if hex {
            walk_hex7(band, p0, p1, rows.clone());
        } else if let Some(mut w) =
            EdgeWalk::new(FinePoint::from(p0), FinePoint::from(p1), mode, cols.clone())
        {
            w.walk_band(rows.clone(), band);
        }
    }
    Some(rows)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;

    use super::*;
    use crate::band::Band;

    #[test]
    fn every_pixel_model_is_listed_once_in_declaration_order() {
        // The match has no wildcard: a new model does not compile here
        // until it has its place in `ALL`.
        let place = |m: PixelModel| match m {
            PixelModel::Box => 0,
            PixelModel::BoxSeed => 1,
            PixelModel::BedOfNails4 => 2,
            PixelModel::BedOfNails8 => 3,
            PixelModel::Hex7 => 4,
            PixelModel::Hex19 => 5,
            PixelModel::Cone => 6,
            PixelModel::Gaussian => 7,
            PixelModel::Hamming => 8,
        };
        for (i, &m) in PixelModel::ALL.iter().enumerate() {
            assert_eq!(place(m), i, "{m:?}");
        }
    }

    /// Sum of the raw accumulation (lin12 * 65536) over an 80x80 frame.
    fn energy(draw: impl Fn(&mut BandBuffer<'_, 1>) -> Result<(), DrawError>) -> i64 {
        let band = Band::new(80, 0, 80);
        let mut acc = vec![0i32; BandBuffer::<1>::acc_len(80, 80)];
        let mut cover = vec![0i32; BandBuffer::<1>::cover_len(80, 80)];
        let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
        buf.clear([0]);
        draw(&mut buf).unwrap();
        (0..80)
            .flat_map(|y| (0..80).map(move |x| (x, y)))
            .map(|(x, y)| i64::from(buf.raw(x, y).unwrap()[0]))
            .sum()
    }

    #[test]
    fn line_energy_is_length_times_colour_at_every_angle() {
        for deg in (0..=90).step_by(5) {
            let a = f64::from(deg).to_radians();
            let (dx, dy) = (
                (a.cos() * 40.0 * 16.0) as i32,
                (a.sin() * 40.0 * 16.0) as i32,
            );
            let from = SubPoint::new(20 * 16 + 3, 20 * 16 + 5);
            let to = SubPoint::new(from.x + dx, from.y + dy);
            let e =
                energy(|b| Line::new(from, to, [[4095], [4095]]).draw(b, &RenderStyle::default()));
            let len = f64::from(dx * dx + dy * dy).sqrt() / 16.0;
            let ratio = e as f64 / (4095.0 * 65536.0 * len);
            assert!(
                (ratio - 1.0).abs() < 0.001,
                "{deg} degrees: energy ratio {ratio}"
            );
        }
    }

    #[test]
    fn bow_tie_with_equal_lobes_is_rejected() {
        let v = [(0, 0), (10, 10), (10, 0), (0, 10)].map(|(x, y)| SubPoint::from_px(x, y));
        let e = energy(|b| {
            assert_eq!(
                Polygon::new(&v, PolygonColors::Flat([4095])).draw(b, &RenderStyle::default()),
                Err(DrawError::SelfIntersecting)
            );
            Ok(())
        });
        assert_eq!(e, 0);
    }

    #[test]
    fn repeated_and_collinear_vertices_draw_the_plain_shape() {
        let sq = [(1, 1), (9, 1), (9, 9), (1, 9)].map(|(x, y)| SubPoint::from_px(x, y));
        let rep = [
            (1, 1),
            (1, 1),
            (5, 1),
            (9, 1),
            (9, 9),
            (9, 9),
            (1, 9),
            (1, 1),
        ]
        .map(|(x, y)| SubPoint::from_px(x, y));
        let style = RenderStyle::default();
        let a = energy(|b| Polygon::new(&sq, PolygonColors::Flat([4095])).draw(b, &style));
        let r = energy(|b| Polygon::new(&rep, PolygonColors::Flat([4095])).draw(b, &style));
        assert_eq!(a, r);
        assert_eq!(a, 64 * 4095 * 65536);
        let line = [(1, 1), (5, 5), (9, 9), (3, 3)].map(|(x, y)| SubPoint::from_px(x, y));
        assert_eq!(
            energy(|b| Polygon::new(&line, PolygonColors::Flat([4095])).draw(b, &style)),
            0
        );
    }
}
