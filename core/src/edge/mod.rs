//! Edge walk: the Bresenham evaluation-function walker of seed 001.
//!
//! Takes one edge (two sub-pixel vertices), its winding, the primitive's
//! Gouraud [`Plane`] and the band's rows; gives, through an [`EdgeSink`],
//! every pixel the edge cuts (address, signed covered area, `I * S`) and,
//! once per row, the column from which the edge's *cover* applies.
//!
//! ## The idea
//!
//! A polygon's coverage of a pixel is the sum, over its edges, of the signed
//! area each edge cuts off: the area of the pixel to the **right** of the
//! edge, inside the edge's own y-range in that row (`+` for edges whose
//! right side is inside, `-` for the others). Pixels wholly right of the
//! edge get the full height of the edge in that row, the *cover* `h`; so an
//! edge reports a few edge pixels per row, and one cover change, and the
//! span sweep of [`band`](crate::band) fills everything between edges.
//! Because each edge's contribution depends on the edge alone (it is always
//! walked top to bottom, whichever polygon it belongs to), two triangles
//! sharing an edge cancel it exactly: no seam, no double edge
//! (seed 000, eq. 3).
//!
//! ```text
//!   canonical frame: u = major axis, v = minor axis, 0 <= dv <= du
//!
//!   column a:  |<---- 1 px ---->|
//!              +----------------+  row b      S = v(u_c) - b  (main term,
//!              |        ___/----|                 seed 001 eq. 1-3: 1/2 + d)
//!              |___/----   .    |
//!              +----------------+  row b+1    spill T = e^2 / (2k) when the
//!                          u_c                    line leaves the row inside
//!                                                 the column (exact mode)
//! ```
//!
//! Every edge is mapped to the first octant by the rule of duality
//! (seed 001): walked top to bottom, mirrored in x when it runs left, and
//! transposed when it is steeper than 45°. There, per column `a` of the
//! major axis, the row `b` that holds the line at the column centre is
//! chosen by the evaluation function: the main term
//! `S = v(u_c) - b` (in 1/4096 px), kept as an exact floor with its
//! Bresenham remainder. A step adds `q` and the remainder `rr`; a carry adds
//! one; `S >= 4096` (a compare) is the diagonal step, `S -= 4096`.
//!
//! The combined evaluator of seed 001 keeps `P = I * S` (intensity times
//! area) with additions only: with the running products `A = I * q`
//! (`K_I` of the seed), `B = g_u * S` (`K_OF`) and the constant `g_u * q`
//! (`K`), a step is `P += A + B (+ I on a carry)`, and the diagonal step
//! subtracts `I << 12`. All of them are exact integers, so the state at a
//! column is the same whether walked to or computed directly: a band
//! starts the walk at its own first row and every band height gives the same
//! bits.
//!
//! ## Two coverage modes
//!
//! - [`AreaMode::SeedFormula`]: the paper's single formula for every pixel:
//!   exact while the edge stays inside the chosen row across the column;
//!   where it crosses a row boundary inside the column, a triangle of area
//!   `e^2 / (2k)` (`k = dv/du`, `e <= k/2` how far the line passes the
//!   boundary) is given to the wrong pixel. Worst error `k/8` of a pixel:
//!   1/8 at 45°.
//! - [`AreaMode::Exact`]: the same walk, plus that spill moved to the right
//!   pixel at each crossing. Each edge pixel is within 3/4096 px of the
//!   exact area: the main term is an exact floor (error below 1 unit), the
//!   spill's `e` is truncated to whole units (below 1/2 unit of area), its
//!   reciprocal rounded (below 1/1000) and the result floored (below 1).
//!   A pixel's error is at most the sum over the edges that cut it, so the
//!   box model's 1/256 px (16 units) holds for any pixel cut by up to five
//!   edges (measured worst: 2.4 units for one edge, 3.1 for the pixels of
//!   random triangles and star polygons).
//!   A crossing happens once per step of the minor axis; its spill costs
//!   three 64-bit multiplies (`e^2 * (du/dv)` by a reciprocal set up once,
//!   and `I * T` for the two pixels involved). Everything else is add and
//!   compare.
//!
//! In both modes the first and last columns of an edge (sub-pixel end
//! points, at most two pixels each) are computed directly from the exact
//! area, once per edge.
//!
//! ## Ranges
//!
//! Vertices lie within ±2^15 sub-pixels ([`geom`](crate::geom)), so
//! `du, dv <= 2^16`; the numerators of `S` are below `2^41` and the
//! products `P` below `2^43` (`i64`); remainders stay below `du` (`i64`,
//! for simplicity of the carries); the exact areas of the end columns are
//! computed relative to their cell, where every product stays below `2^42`
//! (`i64`, one division per end cell).

mod aliased;
mod area;
mod canon;
mod walk;

pub use aliased::walk_edge_aliased;
pub use walk::walk_edge;

pub use crate::shade::Plane;

/// Which box-coverage formula the walker uses for edge pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum AreaMode {
    /// Exact area (within 3/4096 px per edge pixel): the seed
    /// formula plus the spill correction at each minor-axis crossing.
    #[default]
    Exact,
    /// The single formula of seed 001 (`S = 1/2 - d`): additions only,
    /// error at most `k/8` of a pixel for slope `k <= 1`.
    SeedFormula,
}

/// What an edge walk reports. Coordinates are frame pixels; the walker
/// reports only rows inside the range it was given, but any column (the
/// sink clips).
pub trait EdgeSink<const C: usize> {
    /// Pixel `(x, y)` gets `coverage` (signed, 1/4096 px) and, per channel,
    /// `value = I * coverage / 2^16` in accumulation units (`lin12 * 4096`).
    fn cell(&mut self, x: i32, y: i32, coverage: i32, value: &[i32; C]);
    /// From column `x` of row `y` rightwards, the cover changes by `delta`
    /// (1/4096 px, signed).
    fn cover(&mut self, x: i32, y: i32, delta: i32);
    /// The columns the sink keeps, `lo..hi`. The walker may then skip
    /// edge pixels outside them, and report the cover changes of columns
    /// left of `lo` at `lo` (which is where they apply): a long edge running
    /// far off the frame costs only its visible part. Default: all columns.
    fn columns(&self) -> core::ops::Range<i32> {
        i32::MIN..i32::MAX
    }
}

impl<const C: usize> EdgeSink<C> for crate::band::BandBuffer<'_, C> {
    fn cell(&mut self, x: i32, y: i32, _coverage: i32, value: &[i32; C]) {
        self.add_cell(x, y, value);
    }
    fn cover(&mut self, x: i32, y: i32, delta: i32) {
        self.add_cover(x, y, delta);
    }
    fn columns(&self) -> core::ops::Range<i32> {
        0..i32::from(self.band().width)
    }
}
