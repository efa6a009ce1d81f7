//! Edges and coverage: the Bresenham evaluation-function walker of seed 001.
//!
//! Takes one edge (two points on the fine 1/1024-px grid) and the rows of a
//! band; gives, through a [`CoverSink`], every pixel the edge cuts (address
//! and signed covered area) and, once per row, the column from which the
//! edge's *cover* applies. The coverage of a shape is the sum of what its
//! edges report; colour is applied afterwards, when the shape is composed
//! into the band ([`band`](crate::band)).
//!
//! ## The idea
//!
//! A shape's coverage of a pixel is the sum, over its edges, of the signed
//! area each edge cuts off: the area of the pixel to the **right** of the
//! edge, inside the edge's own y-range in that row, `+` for edges running
//! down the screen and `-` for those running up. Summed over closed
//! contours that is the integral of the winding number over the pixel, on
//! which the fill rules (nonzero, even-odd) act. Pixels wholly right of the
//! edge get the full height of the edge in that row, the *cover*; so an edge
//! reports a few edge pixels per row and one cover change, and the span
//! sweep fills everything between edges. Because each edge's contribution
//! depends on the edge alone, two shapes sharing an edge cancel it exactly:
//! no seam, no double edge (seed 000, eq. 3).
//!
//! ```text
//!   canonical frame: u = major axis, v = minor axis, 0 <= dv <= du
//!
//!   column a:  |<---- 1 px ---->|
//!              +----------------+  row b      S = v(u_c) - b  (main term,
//!              |        ___/----|                 seed 001 eq. 1-3: 1/2 + d)
//!              |___/----   .    |
//!              +----------------+  row b+1    spill k x²/2 where the line
//!                          u_c                    crosses a row boundary
//!                                                 inside the column
//! ```
//!
//! Every edge is mapped to the first octant by the rule of duality
//! (seed 001): walked top to bottom, mirrored in x when it runs left, and
//! transposed when it is steeper than 45°. There, per column `a` of the
//! major axis, the row `b` that holds the line at the column centre is
//! chosen by the evaluation function: the main term `S = v(u_c) - b` (in
//! coverage units, 1/65536 px), kept as an exact floor with its Bresenham
//! remainder. A step adds `q` and the remainder `rr`; a carry adds one;
//! `S >= 1 px` (a compare) is the diagonal step, `S -= 1 px`. All of it is
//! exact integers, so the state at a column equals a direct evaluation
//! there: a band can start the walk at its own first row, or resume where
//! the band above stopped, and every band height gives the same bits.
//!
//! ## Two coverage modes
//!
//! - [`AreaMode::SeedFormula`]: the paper's single formula for every pixel:
//!   exact while the edge stays inside the chosen row across the column;
//!   where it crosses a row boundary inside the column, a triangle of area
//!   `k x² / 2` (`k = dv/du`, `x <= 1/2` px the crossing's distance from the
//!   column's near boundary) is given to the wrong pixel. Worst error `k/8`
//!   of a pixel: 1/8 at 45°.
//! - [`AreaMode::Exact`]: the same walk, plus that triangle moved to its
//!   pixel at each crossing, its exact floor tracked from one crossing to
//!   the next by differences (`crossing.rs`): additions and compares only,
//!   no multiply and no division per pixel or crossing. Each edge pixel is
//!   within 2/65536 px of the exact area (two floors: the main term's and
//!   the spill's).
//!
//! In both modes the first and last columns of an edge (sub-pixel end
//! points, at most two pixels each) are computed directly from the exact
//! area, once per edge.
//!
//! A vertical edge (`vertical.rs`) cuts every row at the same place: in
//! the exact mode it is walked row by row from its end points, with no
//! set-up and no state kept between bands (the same changes as the walk).
//!
//! ## Ranges
//!
//! Fine coordinates lie within `±2^21` ([`geom`](crate::geom)), so
//! `du, dv <= 2^22`. Per column the state is `i32`: the main term below
//! `2^16`, its remainder below `du`, the step `q <= 2^16`. Set-up divides in
//! `i64` (numerators below `2^46`); the crossing walk keeps exact rationals
//! over `32 du dv <= 2^49` (see `crossing.rs`).

mod aliased;
mod area;
mod canon;
mod crossing;
pub(crate) mod disc;
mod vertical;
mod walk;

pub use aliased::AliasedWalk;
pub(crate) use canon::Canon;
pub(crate) use vertical::walk as walk_vertical;
pub use walk::EdgeWalk;

/// Which box-coverage formula the walker uses for edge pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum AreaMode {
    /// Exact area (within 2/65536 px per edge pixel): the seed formula plus
    /// the spill of each minor-axis crossing, tracked by differences.
    #[default]
    Exact,
    /// The single formula of seed 001 (`S = 1/2 - d`): additions only,
    /// error at most `k/8` of a pixel for slope `k <= 1`.
    SeedFormula,
}

/// What an edge walk reports: changes of each row's running coverage (a
/// cell of area `S` at column `x` is `+S` at `x` and `-S` at `x + 1`).
/// Coordinates are frame pixels; the walker reports only rows inside the
/// range it was given. Changes left of the columns the sink keeps (set
/// when the edge is set up) apply from its first column; changes right of
/// them may be reported, and the sink ignores them.
pub trait CoverSink {
    /// From column `x` of row `y` rightwards, the cover changes by `delta`
    /// (coverage units, signed). Columns left of the sink's first column
    /// apply from it.
    fn cover(&mut self, x: i32, y: i32, delta: i32);
}

/// Where a walk writes (crate-internal): changes of each row's running
/// coverage, `d` from frame column `x` of row `y` on. A cell of area `S`
/// at `x` is `+S` at `x` and `-S` at `x + 1`. Rows outside the walk's rows
/// are dropped by the sink, columns left of its first apply from it, those
/// right of its last are dropped.
pub(crate) trait DeltaSink {
    /// One change.
    fn put(&mut self, x: i32, y: i32, d: i32);

    /// The columns `x0..x1` the sink keeps, when it clips: changes left of
    /// `x0` apply at `x0`, right of `x1` are dropped (a band's window), so
    /// a walk may sum the ones left of it and skip the ones right of it.
    #[inline]
    fn columns(&self) -> Option<(i32, i32)> {
        None
    }

    /// Two changes in row `y`, at `x0` and `x1` (neighbours).
    #[inline]
    fn put2(&mut self, x0: i32, x1: i32, y: i32, d0: i32, d1: i32) {
        self.put(x0, y, d0);
        self.put(x1, y, d1);
    }

    /// `K` changes in row `y` at `x`, `x + step`, ... (`step` is `±1`).
    #[inline]
    fn put_n<const K: usize>(&mut self, x: i32, y: i32, step: i32, d: [i32; K]) {
        let mut x = x;
        for v in d {
            self.put(x, y, v);
            x += step;
        }
    }

    /// The same two changes, `d0` at `x` and `d1` at `x + 1`, in each of
    /// rows `ys` (a vertical edge's whole rows): `put_n(x, y, 1, [d0, d1])`
    /// for each `y`.
    #[inline]
    fn put_rows(&mut self, x: i32, ys: core::ops::Range<i32>, d0: i32, d1: i32) {
        for y in ys {
            self.put_n(x, y, 1, [d0, d1]);
        }
    }

    /// Up to `n` changes in row `y` at `x`, `x + step`, ..., each drawn
    /// from `f`, which may end the run early with `None`; returns how many
    /// were drawn. `f` is called for rows outside too (it steps the walk).
    /// The columns are within the walk's columns (`c_lo..=c_hi`).
    #[inline]
    fn run<F: FnMut() -> Option<i32>>(
        &mut self,
        x: i32,
        y: i32,
        step: i32,
        n: i32,
        mut f: F,
    ) -> i32 {
        let mut x = x;
        for k in 0..n {
            let Some(d) = f() else {
                return k;
            };
            self.put(x, y, d);
            x += step;
        }
        n.max(0)
    }
}

/// Any [`CoverSink`] as a [`DeltaSink`]: every change a cover change,
/// rows outside the walk's dropped.
pub(crate) struct Forward<'k, K: ?Sized> {
    pub sink: &'k mut K,
    pub rows: core::ops::Range<i32>,
}

impl<K: CoverSink + ?Sized> DeltaSink for Forward<'_, K> {
    #[inline]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        if d != 0 && self.rows.contains(&y) {
            self.sink.cover(x, y, d);
        }
    }
}
