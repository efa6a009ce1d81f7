//! Seed 000's primitives as depth triangles: how polygons and lines enter
//! hidden-surface removal (their own drawing lives in
//! [`raster`](crate::raster), which knows nothing of depths).

use super::range_clip::quad_depth_triangles;
use super::DepthTriangle;
use crate::raster::{DrawError, Line, Polygon, MAX_POLYGON_VERTICES};

impl<const C: usize> Polygon<'_, C> {
    /// The polygon as triangles with a depth per vertex (`depths`, one per
    /// vertex, larger is nearer), for hidden-surface removal
    /// ([`hsr`](crate::hsr)). The same checks as [`draw`](Self::draw);
    /// [`DrawError::ColorCount`] also when `depths` has another length.
    pub fn depth_triangles(
        &self,
        depths: &[u16],
        mut emit: impl FnMut(DepthTriangle<C>),
    ) -> Result<(), DrawError> {
        let Some(p) = self.prepare::<MAX_POLYGON_VERTICES>(Some(depths))? else {
            return Ok(());
        };
        p.triangles(|vertices, colors, depth| {
            emit(DepthTriangle {
                vertices,
                colors,
                depth,
            })
        })
    }
}

impl<const C: usize> Line<C> {
    /// The line's rectangle as two triangles with a depth at each end
    /// (`depths[0]` at `from`), for hidden-surface removal
    /// ([`hsr`](crate::hsr)). The rectangle is the one [`draw`](Self::draw)
    /// fills; its intensity is not rescaled to the ideal area (the depth
    /// triangles do not know the band's background), so its energy may
    /// differ from length times colour by the rounding of its corners to
    /// 1/16 px (a few per cent at some angles).
    ///
    /// A line on or near the coordinate limit has rectangle corners up to
    /// half a pixel beyond it: the rectangle is then clipped to the range
    /// (cut points on the limit lines, so no pixel of a frame moves but
    /// those at the limit itself, by at most 1/64 px; `hsr::range_clip`),
    /// so every hidden-surface method takes it.
    pub fn depth_triangles(
        &self,
        depths: [u16; 2],
        emit: impl FnMut(DepthTriangle<C>),
    ) -> Result<(), DrawError> {
        let Some((q, _, _)) = self.rectangle()? else {
            return Ok(());
        };
        let [c0, c1] = self.colors;
        let [z0, z1] = depths;
        quad_depth_triangles(q, [c0, c1, c1, c0], [z0, z1, z1, z0], emit);
        Ok(())
    }
}
