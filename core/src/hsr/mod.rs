//! Hidden surfaces (seed 004): primitives with a depth per vertex, and the
//! methods that keep only what is nearest.
//!
//! Takes [`DepthTriangle`]s (from 3D objects, [`scene3d`](crate::scene3d),
//! or 2D primitives with depths, [`Polygon::depth_triangles`](crate::Polygon::depth_triangles)); gives the
//! visible surfaces, anti-aliased, in the band's accumulator.
//!
//! **Depth**: `u16` per vertex, **larger is nearer** (seed 004's `z > Z`
//! wins; "reverse Z"); 0 is the farthest depth and the background's. Depth
//! is interpolated over a triangle like intensity, as a plane stepped by
//! one addition per pixel ([`DepthPlane`]).
//!
//! ## The z-buffer in bands, with anti-aliased edges
//!
//! Seed 004's z-buffer keeps per pixel the nearest depth `Z` drawn so far
//! and writes a surface where `z(x, y) > Z(x, y)`. The band of the
//! foundation carries a [`DepthBuffer`] of the same rows, so memory goes
//! down with the band height, to one scanline; each primitive is walked in
//! every band it touches, and every band height gives the same frame bit
//! for bit (each pixel's coverage, intensity and depth are exact integer
//! functions of its address, and the order of primitives is the same in
//! every band).
//!
//! Seed 000 warns that `I_acc += I * S` is exact only for polygons that do
//! not overlap in a pixel. A z-buffer alone would alias every silhouette;
//! accumulation alone would add hidden surfaces in. The method here:
//!
//! 1. Sort the triangles front to back once per frame
//!    ([`sort_front_to_back`], by the sum of the vertex depths).
//! 2. Per pixel keep, besides `Z`, the coverage `K` already claimed.
//! 3. A primitive covering the whole pixel and nearer than everything in it
//!    (`S = 1`, `z > Z`) replaces the pixel: the classic z-buffer, exact in
//!    any drawing order (interpenetrating objects, cyclic overlaps).
//! 4. Any other primitive takes what is left of the pixel:
//!    `s = min(S, 1 - K)`, `I_acc += I * s`, `K += s`: coverage saturates
//!    at a full pixel and later (farther) primitives are rejected by it.
//!
//! Exact cases: a mesh's triangles sharing an edge do not overlap, so their
//! edge pixels add up to the single-polygon value (no seam, no double edge,
//! no background showing through); a silhouette pixel of a nearer surface
//! over a farther one that covers the whole pixel gets exactly
//! `S * I_near + (1 - S) * I_far`. Not exact, with the error bounded by one
//! pixel's value along the curves where it happens: (a) a pixel holding
//! edges of two overlapping surfaces that are both partial (e.g. a
//! silhouette crossing another silhouette): the farther one takes
//! `min(S, 1 - K)`, as if the two did not overlap inside the pixel; (b)
//! where the sort order is wrong (interpenetrating or cyclically overlapping
//! triangles), a partly covering nearer edge pixel drawn after a farther
//! surface gets only what is left of the pixel, and the intersection line
//! of two interpenetrating surfaces is resolved at pixel centres (aliased).
//! The tests measure both (`tests/tests/hsr.rs`). The Weiler–Atherton
//! method ([`weiler`](self)) makes the visible polygons disjoint first, so
//! the accumulation is exact at intersections too.
//!
//! Depth of an edge pixel: the triangle's plane at the pixel centre,
//! clamped to the triangle's vertex depths (an extrapolated centre never
//! claims to be nearer than its triangle is).
//!
//! Aliased (`RenderStyle::ALIASED`), every drawn pixel is full, and the
//! rules reduce to the plain z-buffer in any order.
//!
//! ## Warnock's subdivision
//!
//! [`draw_warnock`] splits the screen into a fixed quadtree of windows
//! (seed 004, rules 1-6): a window is drawn when nothing overlaps it, or
//! when, behind everything visible in it, one surface (or the background)
//! surrounds it and the visible rest are triangles in front of it that do
//! not overlap one another; each then shows its exact area. Windows larger
//! than a pixel are drawn only when filled by one surface; edges are
//! resolved by area in pixel windows (two surfaces passing through each
//! other there are split by their intersection line), or below them down
//! to 1/16 px (the vertex grid), where a window still not simple is point
//! sampled 4 x 4 (at most 1/256 px off). Depth comparisons are exact, the
//! candidate lists live in caller scratch, and the frame does not depend on
//! the band height. Accuracy, storage and cost: [`draw_warnock`].

mod depth_plane;
mod section;
mod warnock;
mod zbuffer;

pub use depth_plane::{DepthPlane, DEPTH_FRAC};
pub use section::Section;
pub use warnock::{
    draw_warnock, scratch_len, WarnockStats, LEVELS, MAX_PARTIAL, MAX_TRIANGLES, ROOT_LOG2_SUB,
};
pub use zbuffer::DepthBuffer;
pub(crate) use zbuffer::FULL;

use core::cmp::Ordering;

use crate::band::BandBuffer;
use crate::geom::SubPoint;
use crate::raster::{walk_outline, Cells, DrawError, RenderStyle, Triangle};
use crate::shade::Plane;

/// Which hidden-surface method draws a frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum HsrMethod {
    /// None: every primitive is accumulated (`I_acc += I * S`), in order.
    #[default]
    None,
    /// The z-buffer in bands, with anti-aliased edges (see above).
    ZBuffer,
    /// Warnock's subdivision, edges resolved by area ([`draw_warnock`]).
    Warnock,
}

/// Why a hidden-surface draw failed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum HsrError {
    /// The primitive was rejected.
    Draw(DrawError),
    /// The depth buffer holds another band than the band buffer.
    BandMismatch,
    /// The scene needs more storage than the caller gave (`needed` items).
    Capacity {
        /// Items the scene needed (at least).
        needed: usize,
    },
}

impl From<DrawError> for HsrError {
    fn from(e: DrawError) -> Self {
        Self::Draw(e)
    }
}

/// A triangle with a colour and a depth per vertex.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct DepthTriangle<const C: usize> {
    /// Vertices in 1/16 px, either orientation.
    pub vertices: [SubPoint; 3],
    /// Linear 12-bit colour per vertex.
    pub colors: [[u16; C]; 3],
    /// Depth per vertex, larger is nearer.
    pub depth: [u16; 3],
}

impl<const C: usize> DepthTriangle<C> {
    /// A triangle with colours and depths per vertex.
    pub const fn new(vertices: [SubPoint; 3], colors: [[u16; C]; 3], depth: [u16; 3]) -> Self {
        Self {
            vertices,
            colors,
            depth,
        }
    }

    /// The 2D triangle for the edge engine (depth dropped).
    pub const fn triangle(&self) -> Triangle<C> {
        Triangle::new(self.vertices, self.colors)
    }

    /// Accumulates the triangle into a band without any depth test
    /// ([`Triangle::draw`]).
    pub fn draw(&self, band: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        self.triangle().draw(band, style)
    }

    /// Draws the triangle through the band's depth buffer (the z-buffer
    /// method above). Draw a frame's triangles in the order
    /// [`sort_front_to_back`] gives, the same order in every band.
    ///
    /// ```
    /// use softedge::hsr::{DepthBuffer, DepthTriangle};
    /// use softedge::{Band, BandBuffer, RenderStyle, SubPoint};
    /// let band = Band { width: 8, y0: 0, rows: 8 };
    /// let (mut acc, mut cover) = ([0i32; 64], [0i32; 80]);
    /// let (mut depth, mut covered) = ([0u16; 64], [0u16; 64]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
    /// let mut zbuf = DepthBuffer::new(&mut depth, &mut covered, band).unwrap();
    /// buf.clear([0]);
    /// let p = |x, y| SubPoint::from_px(x, y);
    /// let far = DepthTriangle::new([p(0, 0), p(8, 0), p(0, 8)], [[1000]; 3], [100; 3]);
    /// let near = DepthTriangle::new([p(0, 0), p(4, 0), p(0, 4)], [[3000]; 3], [900; 3]);
    /// let style = RenderStyle::default();
    /// // Drawn in the wrong order: the nearer one still wins where it is whole.
    /// far.draw_z(&mut buf, &mut zbuf, &style).unwrap();
    /// near.draw_z(&mut buf, &mut zbuf, &style).unwrap();
    /// assert_eq!(buf.lin12(1, 1), Some([3000]));
    /// assert_eq!(buf.lin12(5, 1), Some([1000]));
    /// assert_eq!(zbuf.depth(1, 1), Some(900));
    /// ```
    pub fn draw_z(
        &self,
        band: &mut BandBuffer<'_, C>,
        zbuf: &mut DepthBuffer<'_>,
        style: &RenderStyle,
    ) -> Result<(), HsrError> {
        for v in self.vertices {
            v.check().map_err(DrawError::from)?;
        }
        if zbuf.band() != band.band() {
            return Err(HsrError::BandMismatch);
        }
        let (Some(plane), Some(zplane)) = (
            Plane::triangle(self.vertices, self.colors, band.background()),
            DepthPlane::triangle(self.vertices, self.depth),
        ) else {
            return Ok(());
        };
        if let Some(rows) = walk_outline(band, &self.vertices, &plane, style, Cells::AsCover) {
            band.sweep_depth(rows.start, rows.end, &plane, &zplane, zbuf);
        }
        Ok(())
    }

    /// The sort key of [`sort_front_to_back`]: the sum of the vertex depths
    /// (three times the mean depth).
    pub fn depth_key(&self) -> u32 {
        self.depth.iter().map(|&z| u32::from(z)).sum()
    }
}

/// Sorts triangles front to back: larger [`DepthTriangle::depth_key`]
/// first. Ties are broken by the vertices, depths and colours, so the order
/// is a function of the set of triangles alone (the same on every target).
pub fn sort_front_to_back<const C: usize>(tris: &mut [DepthTriangle<C>]) {
    tris.sort_unstable_by(|a, b| {
        b.depth_key()
            .cmp(&a.depth_key())
            .then_with(|| order_by_content(a, b))
    });
}

fn order_by_content<const C: usize>(a: &DepthTriangle<C>, b: &DepthTriangle<C>) -> Ordering {
    let va = a.vertices.map(|p| (p.y, p.x));
    let vb = b.vertices.map(|p| (p.y, p.x));
    va.cmp(&vb)
        .then_with(|| a.depth.cmp(&b.depth))
        .then_with(|| a.colors.cmp(&b.colors))
}
