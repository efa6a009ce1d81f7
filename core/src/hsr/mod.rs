//! Hidden surfaces (seed 004): primitives with a depth per vertex, and the
//! methods that keep only what is nearest.
//!
//! Takes [`DepthTriangle`]s (from 3D objects, [`scene3d`](crate::scene3d),
//! or 2D primitives with depths:
//! [`Polygon::depth_triangles`](crate::Polygon::depth_triangles),
//! [`Line::depth_triangles`](crate::Line::depth_triangles)); gives the
//! visible surfaces, anti-aliased, in the band's accumulator, by one of
//! four methods: the z-buffer in bands ([`draw_zbuffer`]), section mode
//! ([`DepthTriangle::section`]), Warnock's subdivision ([`draw_warnock`])
//! and Weiler–Atherton clipping ([`VisibleSet`]).
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
//! accumulation alone would add hidden surfaces in. Per pixel the band
//! keeps, besides the depth, the coverage `K` already claimed, and a
//! primitive's share of a pixel is composited *under* what is there:
//! `s = min(S, 1 - K)`, `I_acc += I * s`, `K += s` (coverage saturates at
//! a whole pixel). What is drawn first must then be what is nearest, which
//! a sort by triangle cannot promise per pixel; [`draw_zbuffer`] therefore
//! walks the frame's triangles in three passes per band:
//!
//! 1. [`ZPass::Centres`]: seed 004's z-buffer of the nearest surface, per
//!    pixel (anti-aliased walk): the nearest depth of any fragment touching
//!    the pixel, less that fragment's depth slope across one pixel, is the
//!    pixel's threshold `T`. (It used to be the surface at the pixel centre
//!    alone; a pixel whose centre no surface covers then sent every
//!    fragment to the front pass, hidden ones too: issue #18.)
//! 2. [`ZPass::Front`]: every fragment (a triangle's part of a pixel:
//!    coverage `S`, colour and depth at the centre) whose depth, plus its
//!    own slope across a pixel, reaches `T`: the nearest surface, its mesh
//!    neighbours, and nearer edges partly covering the pixel.
//! 3. [`ZPass::Back`]: the other fragments, behind the nearest surface,
//!    which fill what the front left (the far side of a silhouette pixel).
//!
//! A fragment's share of a pixel that nearer fragments claim `K` of lies
//! between `max(0, S - K)` (wholly under them) and `min(S, 1 - K)` (wholly
//! in the room left); a count cannot tell which. So the depth buffer also
//! keeps which of the pixel's 4 x 4 sample points ([`SAMPLES`]: the corners
//! and two rows and columns between) the drawn fragments cover, and each
//! partial fragment tests its own: all claimed, it lies under them (the
//! lower bound: nothing, for a fragment hidden by a nearer one); every
//! unclaimed sample in it, it covers the room (the upper bound: a
//! silhouette over a farther surface, exactly as before); between, the
//! weighted share of its unclaimed samples, within the bounds. A sliver
//! between the samples is judged by the samples within 3/16 px of it, in
//! the back pass only (in front, its near samples may be a mesh
//! neighbour's).
//!
//! Within each pass the triangles go front to back ([`sort_front_to_back`],
//! once per frame, by the sum of vertex depths; the same order in every
//! band).
//!
//! Exact (within the box model's 3/4096 px per edge): a mesh's triangles
//! sharing an edge do not overlap, so their edge pixels add up to the
//! single-polygon value (no seam, no double edge, no background showing
//! through); a hidden surface is rejected wherever the nearest surface is
//! more than a pixel's depth slope in front of it, whatever the drawing
//! order (interpenetrating objects included); a silhouette pixel of a
//! nearer surface over a farther one gets exactly
//! `S * I_near + (1 - S) * I_far`; and a pixel where one surface alone is
//! visible is exact in front-to-back order (measured on random flat
//! polygons at constant depths, `tests/tests/hsr_exact.rs`: worst 4.2
//! levels of 4095 over 400 scenes, the engine's edge rounding; it was 898
//! before the sample masks). One rounding more: the depth buffer keeps a
//! pixel's claimed coverage in 1/32768 px, so each partly covering
//! fragment's share is truncated to that unit, and as the accumulator
//! holds what surfaces add to the band's clear value, each such fragment
//! may leave up to 1/32768 of its contrast to the clear value showing (at
//! most 0.125 levels of 4095 per fragment; a CI run found a pixel with
//! three, 0.061 levels over the exact value, which tipped its rounding).
//!
//! Not exact, with the error bounded by one pixel's value along the curves
//! where it happens: (a) two partly covering fragments overlapping inside
//! a pixel where both show (a silhouette crossing another silhouette): the
//! second takes the sample estimate of its share (measured worst 499
//! levels, 1/8 of full scale, over the same 400 scenes; 1196 before); (b) where
//! two surfaces are within one pixel's depth slope of each other at a
//! centre (along the intersection curve of interpenetrating surfaces), both
//! are front fragments and their sort order decides the mix; (c) a nearer
//! partial edge over the centre's surface drawn after it in sort order gets
//! only what is left. The tests measure these (`tests/tests/hsr.rs`). The
//! Weiler–Atherton method ([`weiler`]) makes the visible polygons
//! disjoint first, so the accumulation is exact at intersections too.
//!
//! Cost: each of the three passes walks every triangle anti-aliased (the
//! threshold pass only keeps a maximum), and the drawing passes test the
//! partial pixels they draw against the 4 x 4 samples (three edge values
//! per pixel stepped by additions; at most 48 compares in a pixel an edge
//! crosses): about 4 times one anti-aliased accumulation (the lit torus of
//! `softedge-sim`'s `bench`: 62.2 M instructions against 15.7 M, 39.1 M
//! before issue #18). [`ZPass::Single`] is the one-pass variant
//! (sorted, replace a pixel where a whole fragment is nearer than all of
//! it, else composite under): cheaper, with the errors above also where a
//! hidden fragment is drawn before the surface that hides it.
//!
//! Depth of a fragment: the triangle's plane at the pixel centre, clamped
//! to the triangle's vertex depths (an extrapolated centre never claims to
//! be nearer than its triangle is).
//!
//! Aliased (`RenderStyle::ALIASED`), every drawn pixel is whole and
//! [`draw_zbuffer`] makes the single pass, which is then exactly seed 004's
//! z-buffer in any drawing order.
//!
//! With [`PixelModel::BoxSeed`](crate::PixelModel::BoxSeed), a triangle's
//! own coverage of a pixel may leave `0..1` by up to 1/8 px (the seed
//! formula's error); clamped per triangle it no longer cancels across a
//! mesh's shared edges: seams up to 1/8 of the contrast. The exact box
//! model and the sampled models stay seamless.
//!
//! ## Weiler–Atherton
//!
//! [`VisibleSet::compute`] clips the frame's triangles once per frame into
//! disjoint visible pieces (each triangle minus the parts of the others
//! that are nearer, interpenetration included: within two triangles the
//! nearer region is a half-plane), whose cut vertices are shared by both
//! sides of each cut; [`VisibleSet::draw`] accumulates them in every band
//! with their source triangle's Gouraud plane, so seed 000's accumulation
//! is exact at intersections too. Exact where the visible boundaries are
//! the triangles' own edges; elsewhere the boundary passes through cut
//! vertices rounded to the fine grid, 1/1024 px ([`weiler`] states the
//! bound: within 1/1024 px of coverage per moved edge; measured worst 2.4
//! levels of 4095 against the exact visible area).
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

mod errors;
mod fine_fill;
mod primitives;
mod range_clip;
mod section;
mod warnock;
pub mod weiler;

pub(crate) use crate::band::SampleEdges;
pub use crate::band::{DepthBuffer, ZPass, SAMPLES};
pub use crate::shade::{DepthPlane, DEPTH_FRAC};
pub use section::Section;
pub use warnock::{
    draw_warnock, scratch_len, WarnockStats, LEVELS, MAX_PARTIAL, MAX_TRIANGLES, ROOT_LOG2_SUB,
};
pub use weiler::{VisiblePiece, VisibleSet, WeilerStats, PIECE_VERTICES};

use core::cmp::Ordering;

use crate::band::BandBuffer;
use crate::geom::SubPoint;
use crate::raster::{walk_outline, DrawError, RenderStyle, Triangle};
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
    /// Weiler–Atherton: disjoint visible pieces, accumulated exactly
    /// ([`weiler`]).
    WeilerAtherton,
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

    /// Draws the triangle through the band's depth buffer: one `pass` of
    /// the z-buffer method above. Draw a frame's triangles in the order
    /// [`sort_front_to_back`] gives, the same order in every band and pass;
    /// [`draw_zbuffer`] does all of it for a slice of triangles.
    ///
    /// ```
    /// use softedge::hsr::{DepthBuffer, DepthTriangle, ZPass};
    /// use softedge::{Band, BandBuffer, RenderStyle, SubPoint};
    /// let band = Band::new(8, 0, 8);
    /// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
    /// let (mut depth, mut covered) = ([0u16; 64], [0u16; 128]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
    /// let mut zbuf = DepthBuffer::new(&mut depth, &mut covered, band).unwrap();
    /// buf.clear([0]);
    /// let p = |x, y| SubPoint::from_px(x, y);
    /// let far = DepthTriangle::new([p(0, 0), p(8, 0), p(0, 8)], [[1000]; 3], [100; 3]);
    /// let near = DepthTriangle::new([p(0, 0), p(4, 0), p(0, 4)], [[3000]; 3], [900; 3]);
    /// let style = RenderStyle::default();
    /// // Drawn in the wrong order: the nearer one still wins where it is whole.
    /// far.draw_z(&mut buf, &mut zbuf, &style, ZPass::Single).unwrap();
    /// near.draw_z(&mut buf, &mut zbuf, &style, ZPass::Single).unwrap();
    /// assert_eq!(buf.lin12(1, 1), Some([3000]));
    /// assert_eq!(buf.lin12(5, 1), Some([1000]));
    /// assert_eq!(zbuf.depth(1, 1), Some(900));
    /// ```
    pub fn draw_z(
        &self,
        band: &mut BandBuffer<'_, C>,
        zbuf: &mut DepthBuffer<'_>,
        style: &RenderStyle,
        pass: ZPass,
    ) -> Result<(), HsrError> {
        for v in self.vertices {
            v.check().map_err(DrawError::from)?;
        }
        if zbuf.band() != band.band() {
            return Err(HsrError::BandMismatch);
        }
        // (All passes walk with the style: the centres pass takes the
        // nearest fragment touching each pixel.)
        let (Some(plane), Some(zplane)) = (
            Plane::triangle(self.vertices, self.colors, band.background()),
            DepthPlane::triangle(self.vertices, self.depth),
        ) else {
            return Ok(());
        };
        let walk_style = *style;
        let slope = zplane.slope();
        if let Some(rows) = walk_outline(band, &self.vertices, &walk_style) {
            // The drawing passes test partial fragments by their samples
            // too (set up only for a triangle that touches the band).
            let samples = match pass {
                ZPass::Front | ZPass::Back => SampleEdges::new(&self.vertices),
                ZPass::Single | ZPass::Centres => None,
            };
            band.sweep_depth(
                rows.start,
                rows.end,
                &plane,
                &zplane,
                slope,
                samples.as_ref(),
                zbuf,
                pass,
            );
        }
        Ok(())
    }

    /// The sort key of [`sort_front_to_back`]: the sum of the vertex depths
    /// (three times the mean depth).
    pub fn depth_key(&self) -> u32 {
        self.depth.iter().map(|&z| u32::from(z)).sum()
    }
}

/// Draws a frame's triangles into one band by the z-buffer method above:
/// anti-aliased, the three passes (centres, front, back); aliased, the
/// single pass. Sort the triangles once per frame first
/// ([`sort_front_to_back`]); clear the band and the depth buffer before.
///
/// ```
/// use softedge::hsr::{draw_zbuffer, sort_front_to_back, DepthBuffer, DepthTriangle};
/// use softedge::{Band, BandBuffer, RenderStyle, SubPoint};
/// let band = Band::new(8, 0, 8);
/// let (mut acc, mut cover) = ([0i32; 64], [0i32; BandBuffer::<1>::cover_len(8, 8)]);
/// let (mut depth, mut covered) = ([0u16; 64], [0u16; 128]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, band).unwrap();
/// let mut zbuf = DepthBuffer::new(&mut depth, &mut covered, band).unwrap();
/// buf.clear([0]);
/// let p = |x, y| SubPoint::from_px(x, y);
/// let mut tris = [
///     // A far wall, and a nearer triangle whose edge halves pixel (4, 1).
///     DepthTriangle::new([p(0, 0), p(8, 0), p(0, 8)], [[1000]; 3], [100; 3]),
///     DepthTriangle::new([p(0, 0), p(8, 0), p(8, 8)], [[1000]; 3], [100; 3]),
///     DepthTriangle::new([p(0, 0), p(4, 0), p(4, 4)], [[3000]; 3], [900; 3]),
/// ];
/// sort_front_to_back(&mut tris);
/// draw_zbuffer(&tris, &mut buf, &mut zbuf, &RenderStyle::default()).unwrap();
/// assert_eq!(buf.lin12(3, 1), Some([3000]));
/// assert_eq!(buf.lin12(6, 1), Some([1000]));
/// assert_eq!(buf.lin12(2, 2), Some([2000])); // half near, half wall
/// ```
pub fn draw_zbuffer<const C: usize>(
    tris: &[DepthTriangle<C>],
    band: &mut BandBuffer<'_, C>,
    zbuf: &mut DepthBuffer<'_>,
    style: &RenderStyle,
) -> Result<(), HsrError> {
    for &pass in zbuffer_passes(style) {
        for t in tris {
            t.draw_z(band, zbuf, style, pass)?;
        }
        if pass == ZPass::Centres {
            zbuf.finish_centres();
        }
    }
    Ok(())
}

/// The passes [`draw_zbuffer`] makes for `style`, for a caller that
/// produces its triangles again in every pass (projecting a mesh three
/// times instead of storing it): per pass, every triangle in the same
/// order, then [`DepthBuffer::finish_centres`] after [`ZPass::Centres`].
pub const fn zbuffer_passes(style: &RenderStyle) -> &'static [ZPass] {
    if style.antialias {
        &[ZPass::Centres, ZPass::Front, ZPass::Back]
    } else {
        &[ZPass::Single]
    }
}

/// Sorts triangles front to back: larger [`DepthTriangle::depth_key`]
/// first. Ties are broken by the vertices, depths and colours, so the order
/// is a function of the set of triangles alone (the same on every target).
pub fn sort_front_to_back<const C: usize>(tris: &mut [DepthTriangle<C>]) {
    tris.sort_unstable_by(front_to_back);
}

/// The order of [`sort_front_to_back`], for sorting triangles kept with
/// something else (a caller's record of where each came from): `Less` when
/// `a` is drawn before `b`.
///
/// ```
/// use softedge::hsr::{front_to_back, DepthTriangle};
/// use softedge::SubPoint;
/// let p = |x, y| SubPoint::from_px(x, y);
/// let far = DepthTriangle::new([p(0, 0), p(8, 0), p(0, 8)], [[1000]; 3], [100; 3]);
/// let near = DepthTriangle::new([p(0, 0), p(4, 0), p(0, 4)], [[3000]; 3], [900; 3]);
/// // Sorted with their sources' names, without searching afterwards.
/// let mut tagged = [(far, "wall"), (near, "card")];
/// tagged.sort_unstable_by(|(a, _), (b, _)| front_to_back(a, b));
/// assert_eq!(tagged.map(|(_, name)| name), ["card", "wall"]);
/// ```
pub fn front_to_back<const C: usize>(a: &DepthTriangle<C>, b: &DepthTriangle<C>) -> Ordering {
    b.depth_key()
        .cmp(&a.depth_key())
        .then_with(|| order_by_content(a, b))
}

fn order_by_content<const C: usize>(a: &DepthTriangle<C>, b: &DepthTriangle<C>) -> Ordering {
    let va = a.vertices.map(|p| (p.y, p.x));
    let vb = b.vertices.map(|p| (p.y, p.x));
    va.cmp(&vb)
        .then_with(|| a.depth.cmp(&b.depth))
        .then_with(|| a.colors.cmp(&b.colors))
}
