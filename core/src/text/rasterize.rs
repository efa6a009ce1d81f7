//! [`rasterize_glyph`]: one glyph's outline to a mask, once — for a
//! [`GlyphCache`](super::GlyphCache) at run time and for
//! `softedge-sim font` ahead of time (the same function, so a font made
//! ahead and a cache hold the same bits).
//!
//! Takes a glyph of a [`Font`], its [`Scale`], a flattening tolerance, a
//! horizontal phase (the origin's offset into its pixel, fine units), a
//! scratch of `i32` cells and a byte sink; gives the glyph's [`MaskBox`]
//! and its code ([`code`](super::code)) through the sink.
//!
//! The outline is flattened ([`Flattener`]) and its edges walked by the
//! canvas's exact-area edge walker (`edge::EdgeWalk`,
//! seed 001 with the spill of each crossing) into the scratch as changes
//! of running coverage, row by row over the glyph's box (from the font's
//! glyph box, widened by a pixel); a running sum along each row gives
//! every pixel its winding integral, and the nonzero rule its coverage
//! (`min(|sum|, 1)` px): the very coverage the canvas composes for the
//! glyph drawn as a shape. Each pixel is then quantized to its level
//! (shifts, subtractions and compares, once per glyph rasterized),
//! rounded so that the glyph keeps its ink (see `Quantizer`).
//!
//! The box is walked in strips of as many rows as the scratch holds
//! (`scratch.len() / width`): a first pass finds the box of the inked
//! pixels, a second writes their code (when the whole box fits in the
//! scratch at once, the first pass's coverage is kept and encoded).

use core::cell::Cell;
use core::ops::Range;

use super::code::{MaskEncoder, LEVEL_MAX};
use super::outline::Glyph;
use super::scale::Scale;
use super::{Font, GlyphId};
use crate::edge::{AreaMode, DeltaSink, EdgeWalk};
use crate::geom::{FinePoint, FINE_BITS, FINE_ONE};
use crate::path::{Flattener, SegmentSink, Shape, Tolerance};
use crate::COVER_ONE;

/// Largest width or height of a rasterized glyph's box, pixels.
pub const MAX_MASK_SIDE: i32 = 1024;

/// The box of a glyph's mask (see [`GlyphMask`](super::GlyphMask)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct MaskBox {
    /// Columns from the pen's pixel to the box's first.
    pub left: i16,
    /// Rows from the baseline to the box's first (negative above it).
    pub top: i16,
    /// Width in pixels (0: nothing inked).
    pub width: u16,
    /// Height in pixels.
    pub height: u16,
}

/// Why a glyph was not rasterized.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum RasterizeError {
    /// Its box is wider than the scratch or than [`MAX_MASK_SIDE`].
    TooLarge,
    /// The byte sink had no room for its code.
    NoRoom,
}

impl core::fmt::Display for RasterizeError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            Self::TooLarge => write!(f, "glyph box wider than the scratch or {MAX_MASK_SIDE} px"),
            Self::NoRoom => f.write_str("no room for the glyph's code"),
        }
    }
}

impl core::error::Error for RasterizeError {}

/// Rasterizes glyph `id` of `font` with its origin at `(phase_fine, 0)`
/// (fine units; the baseline on the top edge of row 0) and writes its
/// code through `put` (see [the module](self)).
///
/// ```
/// use core::cell::Cell;
/// use softedge::path::Tolerance;
/// use softedge::text::{rasterize_glyph, Font, GlyphMask, Scale, TextSize};
///
/// let font = Font::bundled().unwrap();
/// let scale = Scale::new(TextSize::px(16), font.units_per_em());
/// let mut cells = [0i32; 512];
/// let scratch = Cell::from_mut(&mut cells[..]).as_slice_of_cells();
/// let mut code = Vec::new();
/// let b = rasterize_glyph(&font, font.glyph('l'), scale, Tolerance::DEFAULT, 0, scratch, |byte| {
///     code.push(byte);
///     true
/// })
/// .unwrap();
/// // DejaVu's 'l': a bar 1.44 px wide, 12.16 px tall, 1.47 px right of the origin.
/// assert_eq!((b.left, b.top, b.width, b.height), (1, -13, 2, 13));
/// let mut px = [0i32; 26];
/// GlyphMask::new(b.left, b.top, b.width, b.height, &code[..]).rows().fill(&mut px);
/// let ink = px.iter().map(|&v| f64::from(v) / 65536.0).sum::<f64>();
/// assert!((ink - 184.0 * 1556.0 * (16.0f64 / 2048.0).powi(2)).abs() < 0.1, "{ink}"); // 17.5 px²
/// ```
pub fn rasterize_glyph(
    font: &Font<'_>,
    id: GlyphId,
    scale: Scale,
    tol: Tolerance,
    phase_fine: i32,
    scratch: &[Cell<i32>],
    put: impl FnMut(u8) -> bool,
) -> Result<MaskBox, RasterizeError> {
    let Some(r) = font.face().glyph_bounding_box(id) else {
        return Ok(MaskBox::default());
    };
    let phase = phase_fine.clamp(0, FINE_ONE - 1);
    // The outline's box in fine units (y down), widened by a pixel for
    // the flattening and the rounding of points to the grid.
    let fx0 = i64::from(phase) + scale.x_units(i32::from(r.x_min.min(r.x_max)));
    let fx1 = i64::from(phase) + scale.x_units(i32::from(r.x_min.max(r.x_max)));
    let fy0 = -scale.y_units(i32::from(r.y_min.max(r.y_max)));
    let fy1 = -scale.y_units(i32::from(r.y_min.min(r.y_max)));
    let px = |v: i64| (v >> FINE_BITS).clamp(-i64::from(MAX_MASK_SIDE), i64::from(MAX_MASK_SIDE));
    let (x0, x1) = (px(fx0) - 1, px(fx1) + 2);
    let (y0, y1) = (px(fy0) - 1, px(fy1) + 2);
    let (w, h) = ((x1 - x0) as i32, (y1 - y0) as i32);
    if w > MAX_MASK_SIDE || h > MAX_MASK_SIDE {
        return Err(RasterizeError::TooLarge);
    }
    let grid = Grid {
        x0: x0 as i32,
        y0: y0 as i32,
        w: w as usize,
    };
    let strip = scratch.len() / grid.w.max(1);
    if strip == 0 {
        return Err(RasterizeError::TooLarge);
    }
    let strip = strip.min(h as usize) as i32;
    let glyph = Glyph::new(font, id, FinePoint::new(phase, 0), scale);
    // First pass: the inked pixels' box (band-relative rows and columns).
    let mut ink: Option<(i32, i32, i32, i32)> = None;
    let mut r0 = 0;
    while r0 < h {
        let rows = r0..(r0 + strip).min(h);
        grid.coverage(&glyph, tol, scratch, rows.clone());
        for r in rows.clone() {
            for c in 0..grid.w as i32 {
                if grid.cell(scratch, r - rows.start, c) > INK_MIN {
                    ink = Some(match ink {
                        None => (c, r, c + 1, r + 1),
                        Some((a, b, e, d)) => (a.min(c), b.min(r), e.max(c + 1), d.max(r + 1)),
                    });
                }
            }
        }
        r0 = rows.end;
    }
    let Some((c0, r0, c1, r1)) = ink else {
        return Ok(MaskBox::default());
    };
    // Second pass: the code of the inked box, its levels rounded by
    // `Quantizer` (each pixel within 3/4 of a level of its coverage, the
    // glyph's sum within a level of the sum of its coverage).
    let mut enc = MaskEncoder::new(put);
    let mut q = Quantizer::default();
    let whole = strip >= h;
    let mut row = r0;
    while row < r1 {
        let rows = row..(row + strip).min(r1);
        if !whole {
            grid.coverage(&glyph, tol, scratch, rows.clone());
        }
        let base = if whole { 0 } else { rows.start };
        for r in rows.clone() {
            for c in c0..c1 {
                enc.pixel(q.level(grid.cell(scratch, r - base, c)));
            }
        }
        row = rows.end;
    }
    enc.finish().ok_or(RasterizeError::NoRoom)?;
    Ok(MaskBox {
        left: (grid.x0 + c0) as i16,
        top: (grid.y0 + r0) as i16,
        width: (c1 - c0) as u16,
        height: (r1 - r0) as u16,
    })
}

/// A coverage below which a pixel has level 0 whatever the quantizer's
/// carry: a quarter of a level (the quantizer rounds within 3/4 of one).
const INK_MIN: i32 = COVER_ONE / (4 * LEVEL_MAX as i32);

/// Rounds coverage to levels keeping the running sum: each pixel gets the
/// level nearest its coverage plus the carry (the sum so far of coverage
/// less levels), limited to within 3/4 of a level of its own coverage and
/// to `0..=LEVEL_MAX` (so an empty pixel stays empty and a whole one
/// whole). In units of 1/65536 level: `x = k * 29` for a coverage of `k`
/// units (at most `29 * 2^16`, within `i32`; made by shifts: `29 = 32 -
/// 2 - 1`).
///
/// Nearest rounding alone errs by up to half a level a pixel the same way
/// along a stem (every row of a vertical bar has the same fraction), so a
/// glyph's ink could be off by over 1 %; with the carry the error of one
/// pixel is made up by the next ones that can be rounded either way, so a
/// glyph's sum is within about a level of its coverage's (a pixel whose
/// fraction is under 1/4 of a level, or over 3/4, cannot be rounded the
/// other way), while every pixel stays within `3/4 / 29 = 0.026` of its
/// coverage (0.029 of the exact area with the rasterizer's 0.003: under
/// 1/32).
#[derive(Default)]
struct Quantizer {
    carry: i32,
}

impl Quantizer {
    /// One level = 2^16 units; the bound 3/4 of one.
    const ONE: i32 = 1 << 16;
    const BOUND: i32 = 3 << 14;

    fn level(&mut self, k: i32) -> u8 {
        // `k * 29` as shifts and subtractions: `32 k - 2 k - k`.
        let k = k.clamp(0, COVER_ONE);
        let x = (k << 5) - (k << 1) - k;
        let want = (x + self.carry + Self::ONE / 2).div_euclid(Self::ONE);
        let lo = (x - Self::BOUND + Self::ONE - 1)
            .div_euclid(Self::ONE)
            .max(0);
        let hi = (x + Self::BOUND)
            .div_euclid(Self::ONE)
            .min(i32::from(LEVEL_MAX));
        let q = want.clamp(lo, hi);
        self.carry += x - q * Self::ONE;
        q as u8
    }
}

/// The glyph's box in pixels: frame columns `x0..x0 + w`, rows from `y0`.
struct Grid {
    x0: i32,
    y0: i32,
    w: usize,
}

impl Grid {
    /// The coverage of box rows `rows` (at most the scratch's strip), into
    /// the scratch's first rows: the edges walked as changes, then summed
    /// along each row.
    fn coverage(
        &self,
        glyph: &Glyph<'_, '_>,
        tol: Tolerance,
        scratch: &[Cell<i32>],
        rows: Range<i32>,
    ) {
        let n = (rows.end - rows.start).max(0) as usize;
        for c in scratch.iter().take(n * self.w) {
            c.set(0);
        }
        let frame_rows = self.y0 + rows.start..self.y0 + rows.end;
        let mut walker = Walker {
            out: CellDeltas {
                cells: scratch,
                w: self.w as i32,
                x0: self.x0,
                y_first: frame_rows.start,
                n: n as i32,
            },
            rows: frame_rows.clone(),
            cols: self.x0..self.x0 + self.w as i32,
        };
        {
            let mut fl = Flattener::with_tolerance(&mut walker, tol);
            glyph.describe(&mut fl);
            fl.finish();
        }
        // Running sums: each pixel's winding integral, then its share by
        // the nonzero rule.
        for r in 0..n {
            let mut s = 0i32;
            for c in scratch.iter().skip(r * self.w).take(self.w) {
                s = s.wrapping_add(c.get());
                let a = s.unsigned_abs();
                c.set(if a >= COVER_ONE as u32 {
                    COVER_ONE
                } else {
                    a as i32
                });
            }
        }
    }

    /// The coverage of scratch row `r`, column `c` (0 outside).
    fn cell(&self, scratch: &[Cell<i32>], r: i32, c: i32) -> i32 {
        if r < 0 || c < 0 || c as usize >= self.w {
            return 0;
        }
        scratch
            .get(r as usize * self.w + c as usize)
            .map_or(0, Cell::get)
    }
}

/// Segments into edge walks over the strip.
struct Walker<'s> {
    out: CellDeltas<'s>,
    rows: Range<i32>,
    cols: Range<i32>,
}

impl SegmentSink for Walker<'_> {
    fn segment(&mut self, p0: FinePoint, p1: FinePoint) {
        let (ylo, yhi) = (p0.y.min(p1.y) >> FINE_BITS, p0.y.max(p1.y) >> FINE_BITS);
        if p0.y == p1.y || yhi < self.rows.start || ylo >= self.rows.end {
            return;
        }
        if !(p0.in_range() && p1.in_range()) {
            return;
        }
        if p0.x == p1.x {
            crate::edge::walk_vertical(p0, p1, self.rows.clone(), &mut self.out);
        } else if let Some(mut w) = EdgeWalk::new(p0, p1, AreaMode::Exact, self.cols.clone()) {
            w.once();
            w.walk_into(self.rows.clone(), self.out);
        }
    }

    fn window(&self) -> Option<(i32, i32)> {
        Some((
            self.rows.start.saturating_mul(FINE_ONE),
            self.rows.end.saturating_mul(FINE_ONE).saturating_sub(1),
        ))
    }
}

/// Changes of running coverage into cells: rows `y_first..y_first + n`,
/// `w` columns from frame column `x0` (changes left of them apply from
/// the first, right of them are dropped: only the coverage inside the box
/// is read).
#[derive(Clone, Copy)]
struct CellDeltas<'s> {
    cells: &'s [Cell<i32>],
    w: i32,
    x0: i32,
    y_first: i32,
    n: i32,
}

impl DeltaSink for CellDeltas<'_> {
    #[inline]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        let r = y.wrapping_sub(self.y_first);
        if r < 0 || r >= self.n {
            return;
        }
        let c = x.saturating_sub(self.x0).max(0);
        if c >= self.w {
            return;
        }
        if let Some(cell) = self.cells.get(r as usize * self.w as usize + c as usize) {
            cell.set(cell.get().wrapping_add(d));
        }
    }
}

impl DeltaSink for &mut CellDeltas<'_> {
    #[inline]
    fn put(&mut self, x: i32, y: i32, d: i32) {
        (**self).put(x, y, d);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quantized_levels_stay_near_and_keep_the_sum() {
        let mut rng = crate::path::testing::Lcg(0x0033_0a11);
        for case in 0..500 {
            let n = 1 + rng.below(200) as usize;
            // Stems: one fraction repeated, as along a vertical edge.
            let f = rng.below(COVER_ONE as u64 + 1) as i32;
            let mut q = Quantizer::default();
            let (mut sum_k, mut sum_q) = (0i64, 0i64);
            for i in 0..n {
                let k = match (case % 3, i % 4) {
                    (0, _) => f,
                    (1, 0) => 0,
                    (1, 1) => COVER_ONE,
                    _ => rng.below(COVER_ONE as u64 + 1) as i32,
                };
                let l = q.level(k);
                let err = f64::from(l) / 29.0 - f64::from(k) / 65536.0;
                assert!(err.abs() <= 0.75 / 29.0 + 1e-9, "case {case}: {k} -> {l}");
                if k == 0 || k == COVER_ONE {
                    assert_eq!(l, if k == 0 { 0 } else { LEVEL_MAX });
                }
                sum_k += i64::from(k) * 29;
                sum_q += i64::from(l) << 16;
            }
            // Within 1.5 levels when pixels can be rounded either way; a
            // stem of one fraction within a quarter level a pixel (a
            // fraction under 1/4 cannot be rounded up within 3/4).
            let bound = if case % 3 == 0 {
                (n as i64 + 4) << 14
            } else {
                3 << 15
            };
            assert!(
                (sum_k - sum_q).abs() <= bound,
                "case {case}: {sum_k} vs {sum_q}"
            );
        }
    }
}
