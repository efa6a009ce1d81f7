//! [`GlyphRun`]: one line of text laid out — glyphs, advances, kerning —
//! as one shape.
//!
//! Takes a [`Font`], one line of text (`&str` without newlines), the pen's
//! start on the baseline (fine units, y down) and a [`Scale`]; gives the
//! glyphs' origins (the pen moved by each advance and pair kerning, in
//! fine units: sub-pixel positions to 1/1024 px), the run's advance width,
//! and the whole run as one shape: a [`Shape`] (outlines into any
//! [`PathSink`]) and a canvas [`Outline`] (closed contours, with bounds
//! from the font's global box and the character count, so a band the line
//! misses is rejected without reading a glyph).
//!
//! A run is one shape: where glyphs overlap (kerned pairs) nothing is
//! covered twice, and an opacity applies to the run as a whole.
//!
//! ## Work and ranges
//!
//! Per character: one `cmap` look-up, one `hmtx` read, one kerning look-up
//! (at most [`MAX_KERN_LOOKUPS`](super::font::MAX_KERN_LOOKUPS) lookups,
//! each a binary search of its coverage), and for drawing the glyph's
//! outline, parsed in place, flattened within 3 fine units. The pen is an
//! `i64` of fine units; each advance is rounded once (1/2048 px per glyph
//! at most); origins are saturated to `±2^30` and clamped into the
//! coordinate range when drawn.

use ttf_parser::GlyphId;

use super::outline::{sat_fine, Glyph};
use super::scale::Scale;
use super::sharpen::{round_px, Sharpen};
use super::Font;
use crate::canvas::{FineRect, Outline};
use crate::geom::{FinePoint, PathSink, FINE_LIMIT};
use crate::path::{Flattener, SegmentSink, Shape, Tolerance};

/// One line of text laid out from a pen position on the baseline.
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::text::{Font, GlyphRun, Scale, Sharpen, TextSize};
/// let font = Font::bundled().unwrap();
/// let scale = Scale::new(TextSize::px(20), font.units_per_em());
/// let run = GlyphRun::new(&font, "AVA", FinePoint::from_px(0, 20), scale);
/// let kerned = run.advance();
/// let plain = run.with_kerning(false).advance();
/// assert!(kerned < plain); // A-V and V-A kern tighter
/// let origins: Vec<i32> = run.glyphs().map(|g| g.origin().x).collect();
/// assert_eq!(origins.len(), 3);
/// assert_eq!(origins[0], 0);
/// # let _ = Sharpen::NONE;
/// ```
#[derive(Debug, Clone, Copy)]
pub struct GlyphRun<'t, 'f, 'a> {
    font: &'f Font<'a>,
    text: &'t str,
    origin: FinePoint,
    scale: Scale,
    kerning: bool,
    sharpen: Sharpen,
    tol: Tolerance,
}

impl<'t, 'f, 'a> GlyphRun<'t, 'f, 'a> {
    /// A run of `text` (one line: a `'\n'` is a character like any other)
    /// from the pen position `origin` on the baseline, with kerning, exact
    /// positions and the default flattening tolerance. Characters the font
    /// lacks are left out (not drawn, no advance).
    pub fn new(font: &'f Font<'a>, text: &'t str, origin: FinePoint, scale: Scale) -> Self {
        Self {
            font,
            text,
            origin,
            scale,
            kerning: true,
            sharpen: Sharpen::NONE,
            tol: Tolerance::DEFAULT,
        }
    }

    /// With or without pair kerning.
    pub fn with_kerning(mut self, on: bool) -> Self {
        self.kerning = on;
        self
    }

    /// With the grid roundings of `sharpen` for the glyph origins (the
    /// baseline and scale are the caller's: see [`Text`](super::Text)).
    pub fn with_sharpen(mut self, sharpen: Sharpen) -> Self {
        self.sharpen = sharpen;
        self
    }

    /// With a flattening tolerance for the curves.
    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.tol = tol;
        self
    }

    /// The text.
    pub fn text(&self) -> &'t str {
        self.text
    }

    /// The pen's start on the baseline.
    pub fn origin(&self) -> FinePoint {
        self.origin
    }

    /// The glyphs with their origins, in order.
    pub fn glyphs(&self) -> impl Iterator<Item = Glyph<'f, 'a>> + '_ {
        Pen::new(self).map(|(id, x)| {
            let x = if self.sharpen.glyph_x { round_px(x) } else { x };
            Glyph::new(
                self.font,
                id,
                FinePoint::new(sat_fine(x), self.origin.y),
                self.scale,
            )
        })
    }

    /// The advance width of the run (kerning included), fine units.
    pub fn advance(&self) -> i64 {
        let mut pen = Pen::new(self);
        for _ in pen.by_ref() {}
        pen.x - i64::from(self.origin.x)
    }

    /// A box that holds every outline point of the run, without reading a
    /// glyph: y from the font's global box, x from the character count (at
    /// most the largest advance plus an em of kerning per character, either
    /// way), widened by a pixel and clamped into the coordinate range;
    /// `None` for an empty run. (A band engine rejects by rows; x only
    /// needs to be safe.)
    pub fn bounds(&self) -> Option<FineRect> {
        if self.text.is_empty() {
            return None;
        }
        let (x_min, y_min, x_max, y_max) = self.font.global_bbox();
        let one = i64::from(crate::geom::FINE_ONE);
        let n = self.text.chars().count().min(1 << 20) as i32;
        let upem = i32::from(self.font.units_per_em());
        let ahead = n.saturating_mul(i32::from(self.font.max_advance()) + upem);
        let back = n.saturating_mul(upem);
        let x = i64::from(self.origin.x);
        let x0 = x + self
            .scale
            .x_units(i32::from(x_min).min(0).saturating_sub(back))
            - one;
        let x1 = x
            + self
                .scale
                .x_units(ahead.saturating_add(i32::from(x_max).max(0)))
            + one;
        let y = i64::from(self.origin.y);
        let y0 = y - self.scale.y_units(i32::from(y_max)) - one;
        let y1 = y - self.scale.y_units(i32::from(y_min)) + one;
        let c = |v: i64| v.clamp(-i64::from(FINE_LIMIT), i64::from(FINE_LIMIT)) as i32;
        Some(FineRect {
            x0: c(x0.min(x1)),
            y0: c(y0.min(y1)),
            x1: c(x0.max(x1)),
            y1: c(y0.max(y1)),
        })
    }
}

/// The pen walking a run: each glyph and its origin's x (fine units).
struct Pen<'r, 't, 'f, 'a> {
    run: &'r GlyphRun<'t, 'f, 'a>,
    chars: core::str::Chars<'t>,
    prev: Option<GlyphId>,
    x: i64,
}

impl<'r, 't, 'f, 'a> Pen<'r, 't, 'f, 'a> {
    fn new(run: &'r GlyphRun<'t, 'f, 'a>) -> Self {
        Self {
            run,
            chars: run.text.chars(),
            prev: None,
            x: i64::from(run.origin.x),
        }
    }
}

impl Iterator for Pen<'_, '_, '_, '_> {
    type Item = (GlyphId, i64);

    fn next(&mut self) -> Option<Self::Item> {
        let font = self.run.font;
        // A character the font lacks is left out: no glyph, no advance,
        // no kerning across it ([`Text::draw`](super::Text::draw) reports
        // it).
        let g = loop {
            let c = self.chars.next()?;
            match font.face().glyph_index(c) {
                Some(g) => break g,
                None => self.prev = None,
            }
        };
        if let (Some(p), true) = (self.prev, self.run.kerning) {
            self.x += self.run.scale.x_units(font.kerning(p, g));
        }
        let at = self.x;
        self.x += self.run.scale.x_units(i32::from(font.advance(g)));
        self.prev = Some(g);
        Some((g, at))
    }
}

impl Shape for GlyphRun<'_, '_, '_> {
    /// Every glyph's outline, in order.
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        for g in self.glyphs() {
            g.describe(sink);
        }
    }
}

/// Segments to a closure.
struct ToClosure<F>(F);

impl<F: FnMut(FinePoint, FinePoint)> SegmentSink for ToClosure<F> {
    fn segment(&mut self, from: FinePoint, to: FinePoint) {
        (self.0)(from, to);
    }
}

impl Outline for GlyphRun<'_, '_, '_> {
    fn bounds(&self) -> Option<FineRect> {
        GlyphRun::bounds(self)
    }

    fn segments<F: FnMut(FinePoint, FinePoint)>(&self, f: F) {
        self.segments_into(&mut ToClosure(f));
    }

    /// Curves that miss the sink's window are counted, not flattened.
    fn segments_into<K: SegmentSink>(&self, sink: &mut K) {
        for g in self.glyphs() {
            // Each glyph's contours closed on their own.
            let mut fl = Flattener::with_tolerance(&mut *sink, self.tol);
            g.describe(&mut fl);
            fl.finish();
        }
    }
}
