//! Text from rasterized glyphs, drawn into a band: the lines laid out
//! from a [`GlyphSource`] and each glyph's mask decoded into the band's
//! coverage scratch, then composed once.
//!
//! Takes lines (text, pen start and baseline in fine units), a source, a
//! linear colour and an opacity; gives the band the text as **one
//! shape**: every glyph's coverage is written into the cover scratch as
//! changes (the band's `add_mask`, one change per run of the code), summed
//! where glyphs overlap (the nonzero rule on the summed coverage, as a
//! run of outlines is filled), and composed by the sweep the shapes use
//! (over, in linear light, with the opacity applied to the text as a
//! whole). A glyph with no mask (a cache without room for it) is walked
//! from its outline into the same scratch.
//!
//! ## Where a glyph lands
//!
//! Its **drawn position** is its pen position rounded: `x` to the nearest
//! of the source's phases (`1/P` px; with the grid option, to a whole
//! pixel), `y` (the baseline) to the nearest pixel boundary (halves
//! up: the top edge of row `floor(y + 1/2)`). The mask is the coverage of the outline
//! drawn there. The pens themselves keep their exact fine positions
//! (advances and kerning in fine units), so rounding errors do not add up
//! along a line.
//!
//! ## Work per band
//!
//! A line whose rows (its baseline plus the source's ink rows) miss the
//! band costs one compare. In a line that meets it, per character: the
//! character map, the advance, the kerning; per glyph whose box meets the
//! band, its code decoded from its first row (a shift and a mask per
//! pixel, a table look-up per level), and for its rows in the band a
//! subtraction and an addition per pixel into the scratch. No outline is
//! parsed, flattened or walked.

use super::code::GlyphMask;
use super::source::{GlyphSource, OutlineGlyph};
use crate::band::{BandBuffer, ComposeOp, Coverage, Paint};
use crate::canvas::Canvas;
use crate::edge::{AreaMode, EdgeWalk};
use crate::geom::{FinePoint, FINE_BITS, FINE_ONE};
use crate::path::{Flattener, SegmentSink, Shape};
use crate::raster::DrawError;
use crate::style::{FillRule, Opacity};

/// One line to draw: its text (no line breaks) and its pen's start on the
/// baseline, fine units.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Line<'t> {
    pub text: &'t str,
    pub x: i64,
    pub y: i64,
}

/// The line's advance (kerning included), fine units, and its first
/// character the source lacks (which advances by nothing).
pub(crate) fn advance<S: GlyphSource>(src: &S, text: &str) -> (i64, Option<char>) {
    // As [`Pens`] steps the pen, without placing the glyphs.
    let mut pen = 0i64;
    let mut missing = None;
    let mut prev: Option<u16> = None;
    for c in text.chars() {
        let Some(g) = src.glyph(c) else {
            missing = missing.or(Some(c));
            prev = None;
            continue;
        };
        if let Some(p) = prev {
            pen += i64::from(src.kerning(p, g));
        }
        pen += i64::from(src.advance(g));
        prev = Some(g);
    }
    (pen, missing)
}

/// The glyphs of a line, placed: for each character, from the pen at
/// fine `x`, its glyph, drawn column and phase ([`drawn_x`]) after the
/// kerning with the glyph before; a character the source lacks is given
/// as `Err` (no advance, no kerning across it). Every walk along a line
/// (its advance, drawing, ink) steps the pen so.
pub(crate) struct Pens<'a, S> {
    src: &'a S,
    chars: core::str::Chars<'a>,
    /// Fine units, after the last glyph given.
    pen: i64,
    prev: Option<u16>,
    phases: u8,
    grid: bool,
}

impl<'a, S: GlyphSource> Pens<'a, S> {
    pub(crate) fn new(src: &'a S, text: &'a str, x: i64, grid: bool) -> Self {
        Self {
            src,
            chars: text.chars(),
            pen: x,
            prev: None,
            phases: src.phases().clamp(1, 16),
            grid,
        }
    }
}

impl<S: GlyphSource> Iterator for Pens<'_, S> {
    /// The glyph, its column and its phase.
    type Item = Result<(u16, i32, u8), char>;

    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        let c = self.chars.next()?;
        let Some(g) = self.src.glyph(c) else {
            self.prev = None;
            return Some(Err(c));
        };
        if let Some(p) = self.prev {
            self.pen += i64::from(self.src.kerning(p, g));
        }
        self.prev = Some(g);
        let (gx, phase) = drawn_x(self.pen, self.phases, self.grid);
        self.pen += i64::from(self.src.advance(g));
        Some(Ok((g, gx, phase)))
    }
}

/// A glyph's drawn column and phase for its pen at fine `x`: `x` rounded
/// to the nearest `1/phases` px (halves up), or to a whole pixel on the
/// `grid`. Shifts for 1, 2, 4, 8 or 16 phases; a division otherwise.
#[inline]
pub(crate) fn drawn_x(x: i64, phases: u8, grid: bool) -> (i32, u8) {
    let px = |v: i64| v.clamp(-(1 << 21), 1 << 21) as i32;
    if grid || phases <= 1 {
        return (px((x + i64::from(FINE_ONE / 2)) >> FINE_BITS), 0);
    }
    if phases.is_power_of_two() {
        let bits = phases.trailing_zeros();
        let shift = FINE_BITS - bits;
        let q = (x + (1 << (shift - 1))) >> shift;
        return (px(q >> bits), (q & (i64::from(phases) - 1)) as u8);
    }
    let p = i64::from(phases);
    let q = (x * p + i64::from(FINE_ONE / 2)) >> FINE_BITS;
    (px(q.div_euclid(p)), q.rem_euclid(p) as u8)
}

/// The pixel row whose top edge is nearest to fine `y` (a baseline).
#[inline]
pub(crate) fn baseline_row(y: i64) -> i32 {
    ((y + i64::from(FINE_ONE / 2)) >> FINE_BITS).clamp(-(1 << 21), 1 << 21) as i32
}

/// Draws `lines` into the canvas's band as one shape (see [the
/// module](self)); `grid`: glyphs on whole pixels; `contrast`: the masks'
/// coverage steepened by `2^contrast` (see
/// [`BOOSTED_COVER`](super::code::BOOSTED_COVER); a glyph walked from
/// its outline is not). Characters the source
/// lacks are skipped (no advance); the first one of the lines that meet
/// the band is returned as [`DrawError::MissingGlyph`] after the rest is
/// drawn (so a text reports it in every band it is drawn in, and a text
/// outside the frame, never drawn, reports nothing).
pub(crate) fn draw_lines<'t, S: GlyphSource, const C: usize, Col>(
    canvas: &mut Canvas<'_, '_, C, Col>,
    src: &S,
    lines: impl Iterator<Item = Line<'t>>,
    color: [u16; C],
    opacity: Opacity,
    grid: bool,
    contrast: u8,
) -> Result<(), DrawError> {
    let buf = canvas.buffer();
    let band = buf.band();
    let (rows, cols) = (band.row_range(), band.column_range());
    let m = src.line_metrics();
    let phases = src.phases().clamp(1, 16);
    let mut touched: Option<(i32, i32)> = None;
    let mut missing: Option<char> = None;
    for line in lines {
        let yb = baseline_row(line.y);
        let (top, bottom) = (
            yb.saturating_add(m.ink_top),
            yb.saturating_add(m.ink_bottom),
        );
        if bottom <= rows.start || top >= rows.end {
            continue;
        }
        for placed in Pens::new(src, line.text, line.x, grid) {
            let (g, gx, phase) = match placed {
                Ok(p) => p,
                Err(c) => {
                    missing = missing.or(Some(c));
                    continue;
                }
            };
            let at = Placed {
                x: gx,
                y: yb,
                rows: rows.clone(),
                cols: cols.clone(),
                contrast,
            };
            let drawn = src.mask(g, phase, |mask| at.mask(buf, mask));
            let span = match drawn {
                Some(span) => span,
                None => src.outline(g).and_then(|o| {
                    let fx = i64::from(gx) * i64::from(FINE_ONE)
                        + i64::from(phase) * i64::from(FINE_ONE) / i64::from(phases);
                    at.outline(buf, &o, fx)
                }),
            };
            if let Some((a, b)) = span {
                touched = Some(touched.map_or((a, b), |(lo, hi)| (lo.min(a), hi.max(b))));
            }
        }
    }
    if let Some((lo, hi)) = touched {
        let color = color.map(|v| v.min(crate::LIN_MAX));
        if opacity.is_opaque() {
            // Blends over palette colours kept as palette colours.
            buf.compose_mask_over(lo, hi, &color);
        } else {
            let rule = Coverage::Rule(FillRule::NonZero);
            buf.compose(lo, hi, rule, &Paint::Flat(color), ComposeOp::Over(opacity));
        }
    }
    match missing {
        Some(c) => Err(DrawError::MissingGlyph(c)),
        None => Ok(()),
    }
}

/// A glyph's drawn position (its pen's pixel and baseline row) and the
/// band's rows and columns.
struct Placed {
    x: i32,
    y: i32,
    rows: core::ops::Range<i32>,
    cols: core::ops::Range<i32>,
    /// The masks' contrast gain, `2^contrast`.
    contrast: u8,
}

impl Placed {
    /// Writes the mask's rows in the band into the scratch; the rows
    /// written (`None`: none).
    #[inline]
    fn mask<B: super::code::CodeBytes + ?Sized, const C: usize>(
        &self,
        buf: &mut BandBuffer<'_, C>,
        mask: &GlyphMask<'_, B>,
    ) -> Option<(i32, i32)> {
        let top = self.y.saturating_add(i32::from(mask.top));
        let bottom = top.saturating_add(i32::from(mask.height));
        let left = self.x.saturating_add(i32::from(mask.left));
        let right = left.saturating_add(i32::from(mask.width));
        if mask.is_empty()
            || bottom <= self.rows.start
            || top >= self.rows.end
            || right <= self.cols.start
            || left >= self.cols.end
        {
            return None;
        }
        let mut dec = mask.rows_boosted(self.contrast);
        let end = bottom.min(self.rows.end);
        let w = u32::from(mask.width);
        if left >= self.cols.start && right < self.cols.end {
            // The whole width in the band's columns: row by row, straight
            // into the scratch's cells (rows above the band passed over).
            for y in top..end {
                if y < self.rows.start {
                    dec.skip(w);
                } else if let Some(cells) = buf.mask_row(left, y, w) {
                    dec.add_row(cells);
                }
            }
        } else {
            // Clipped at a side: run by run.
            buf.add_mask(left, top, w, u32::from(mask.height), || dec.next_run());
        }
        Some((top.max(self.rows.start), end))
    }

    /// Walks glyph `o`'s outline, its origin at fine `(fx, baseline)`,
    /// into the scratch (a glyph without a mask); the rows written.
    fn outline<const C: usize>(
        &self,
        buf: &mut BandBuffer<'_, C>,
        o: &OutlineGlyph<'_>,
        fx: i64,
    ) -> Option<(i32, i32)> {
        let origin = FinePoint::new(
            super::outline::sat_fine(fx),
            super::outline::sat_fine(i64::from(self.y) * i64::from(FINE_ONE)),
        );
        let glyph = super::Glyph::new(o.font, o.id, origin, o.scale);
        let rows = self.rows.clone();
        let mut walker = BandWalker {
            buf,
            rows: rows.clone(),
            cols: self.cols.clone(),
        };
        {
            let mut fl = Flattener::with_tolerance(&mut walker, o.tolerance);
            glyph.describe(&mut fl);
            fl.finish();
        }
        Some((rows.start, rows.end))
    }
}

/// Segments walked straight into the band's scratch (exact area).
struct BandWalker<'b, 'c, const C: usize> {
    buf: &'b mut BandBuffer<'c, C>,
    rows: core::ops::Range<i32>,
    cols: core::ops::Range<i32>,
}

impl<const C: usize> SegmentSink for BandWalker<'_, '_, C> {
    fn segment(&mut self, p0: FinePoint, p1: FinePoint) {
        let (ylo, yhi) = (p0.y.min(p1.y) >> FINE_BITS, p0.y.max(p1.y) >> FINE_BITS);
        if p0.y == p1.y || yhi < self.rows.start || ylo >= self.rows.end {
            return;
        }
        if !(p0.in_range() && p1.in_range()) {
            return;
        }
        let mut out = self.buf.deltas(self.rows.clone());
        if p0.x == p1.x {
            crate::edge::walk_vertical(p0, p1, self.rows.clone(), &mut out);
        } else if let Some(mut w) = EdgeWalk::new(p0, p1, AreaMode::Exact, self.cols.clone()) {
            w.once();
            w.walk_into(self.rows.clone(), out.lend());
        }
    }

    fn window(&self) -> Option<(i32, i32)> {
        Some((
            self.rows.start.saturating_mul(FINE_ONE),
            self.rows.end.saturating_mul(FINE_ONE).saturating_sub(1),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn drawn_positions_are_the_nearest_phase() {
        for phases in 1..=16u8 {
            for x in (-5000i64..5000).step_by(7).chain([-(1 << 30), 1 << 30]) {
                let (gx, p) = drawn_x(x, phases, false);
                // Exact: round(x * phases / 1024), halves up.
                let q = (x * i64::from(phases) * 2 + 1024).div_euclid(2048);
                assert_eq!(
                    (i64::from(gx), i64::from(p)),
                    (
                        q.div_euclid(i64::from(phases)).clamp(-(1 << 21), 1 << 21),
                        q.rem_euclid(i64::from(phases))
                    ),
                    "{x} at {phases}"
                );
            }
        }
        assert_eq!(drawn_x(1535, 4, true), (1, 0));
        assert_eq!(drawn_x(1536, 4, true), (2, 0));
    }
}
