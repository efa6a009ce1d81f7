//! [`Text`]: a drawable string — lines, alignment, baseline, line height —
//! and [`FontStyle`], its font, size, colour and opacity.
//!
//! Takes a string (lines split at `'\n'`, a `'\r'` before it dropped, as
//! embedded-graphics does), a position (fine units: the anchor of the
//! first line that the [`TextStyle`] names), a [`FontStyle`] and a
//! [`TextStyle`]; gives
//!
//! - [`Text::draw`]: each line as one [`GlyphRun`] filled into a
//!   [`Canvas`] (exact area, nonzero rule, in linear light, composed over
//!   what is there with the style's opacity), returning the pen position
//!   after the last glyph, as embedded-graphics' `Text::draw` does;
//! - [`Text::measure`]: the same layout without drawing: the advance width
//!   of the widest line, the layout box (lines' advances by their
//!   ascender-to-descender boxes), the ink box (the glyphs' outline boxes)
//!   and the next position.
//!
//! Layout is integer: fine units (1/1024 px), `i64` pens; see
//! [`run`](super::run) for the work per character.
//!
//! ## From embedded-graphics
//!
//! An embedded-graphics `Point` names a pixel; `Text::new(s, p, style)`
//! with `Baseline::Alphabetic` there puts the bottom of an `A` *in* row
//! `p.y`. Its outline equivalent is the baseline on the lower edge of that
//! row: `FinePoint::from_px(p.x, p.y + 1)`.

use super::cache::{CachedFont, GlyphCache};
use super::layout::{Alignment, Baseline, TextStyle};
use super::masked;
use super::run::GlyphRun;
use super::scale::{Scale, TextSize};
use super::sharpen::{round_px, Sharpen};
use super::Font;
use crate::canvas::{Canvas, FineRect};
use crate::color::IntoLinear;
use crate::geom::FinePoint;
use crate::path::Tolerance;
use crate::raster::DrawError;
use crate::style::{Blend, FillRule, Opacity};

/// How characters look: font, size, colour (linear, `C` channels),
/// opacity, kerning and grid fitting.
///
/// ```
/// use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
/// use softedge::text::{Font, FontStyle, Sharpen};
/// let font = Font::bundled().unwrap();
/// let white = FontStyle::<3>::new(&font, 12, Rgb565::WHITE);
/// assert_eq!(white.color, [4095; 3]);
/// let gray = FontStyle::<1>::new(&font, 10, [2048]).with_sharpen(Sharpen::GRID);
/// assert_eq!(gray.size.to_64ths(), 640);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct FontStyle<'f, 'a, const C: usize> {
    /// The font.
    pub font: &'f Font<'a>,
    /// The em in pixels.
    pub size: TextSize,
    /// Linear 12-bit colour.
    pub color: [u16; C],
    /// Opacity of each line as a whole.
    pub opacity: Opacity,
    /// Pair kerning (on by default).
    pub kerning: bool,
    /// Grid fitting (none by default).
    pub sharpen: Sharpen,
    /// How far flattened curves may stray (3 fine units, 1/341 px, by
    /// default; a coarser one means fewer edges to walk: see the README's
    /// text benchmark).
    pub tolerance: Tolerance,
    /// A cache of rasterized glyphs (none by default): with one, each
    /// glyph is rasterized once and drawn from its mask in every band and
    /// frame (see [`with_cache`](Self::with_cache)).
    pub cache: Option<&'f GlyphCache<'f>>,
}

impl<'f, 'a, const C: usize> FontStyle<'f, 'a, C> {
    /// `size_px` pixels per em (`1..=2048`), opaque, kerned, exact
    /// positions; the colour linear (`[u16; C]`) or anything that
    /// becomes linear ([`IntoLinear`]: embedded-graphics' colour types are
    /// read as sRGB).
    pub fn new(font: &'f Font<'a>, size_px: u16, color: impl IntoLinear<C>) -> Self {
        Self {
            font,
            size: TextSize::px(size_px),
            color: color.into_linear().map(|v| v.min(crate::LIN_MAX)),
            opacity: Opacity::OPAQUE,
            kerning: true,
            sharpen: Sharpen::NONE,
            tolerance: Tolerance::DEFAULT,
            cache: None,
        }
    }

    /// Drawn through a glyph cache: each glyph rasterized once (its
    /// exact-area coverage, quantized to 1/29, at its pen position
    /// rounded to a quarter pixel and its baseline to a whole pixel: see
    /// [`CachedFont`]) and decoded from the cache in every band and frame
    /// after, instead of parsed, flattened and walked in each. Give each
    /// size its own cache.
    ///
    /// ```
    /// use softedge::canvas::Canvas;
    /// use softedge::geom::FinePoint;
    /// use softedge::text::{Font, FontStyle, GlyphCache, Text, SLOT_WORDS};
    /// use softedge::{Band, BandBuffer};
    ///
    /// let font = Font::bundled().unwrap();
    /// let (mut codes, mut slots, mut scratch) = ([0u8; 1024], [0u32; 16 * SLOT_WORDS], [0i32; 512]);
    /// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
    /// let style = FontStyle::<1>::new(&font, 12, [4095]).with_cache(&cache);
    /// let text = Text::new("1.5 V", FinePoint::from_px(2, 14), style);
    /// for y0 in [0, 8] {
    ///     let (mut acc, mut cover) = ([0i32; 64 * 8], [0i32; BandBuffer::<1>::cover_len(64, 8)]);
    ///     let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(64, y0, 8)).unwrap();
    ///     buf.clear([0]);
    ///     text.draw(&mut Canvas::new(&mut buf, None)).unwrap();
    /// }
    /// // Two bands, four glyphs with ink and a space: each rasterized once.
    /// assert_eq!(cache.stats().misses, 5);
    /// ```
    pub fn with_cache(mut self, cache: &'f GlyphCache<'f>) -> Self {
        self.cache = Some(cache);
        self
    }

    /// With a flattening tolerance for the glyphs' curves.
    pub fn with_tolerance(mut self, tol: Tolerance) -> Self {
        self.tolerance = tol;
        self
    }

    /// With a size in 1/64 px.
    pub fn with_size(mut self, size: TextSize) -> Self {
        self.size = size;
        self
    }

    /// With an opacity.
    pub fn with_opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// With or without kerning.
    pub fn with_kerning(mut self, on: bool) -> Self {
        self.kerning = on;
        self
    }

    /// With grid fitting.
    pub fn with_sharpen(mut self, sharpen: Sharpen) -> Self {
        self.sharpen = sharpen;
        self
    }

    /// The scale from font units to fine units, with the x-height snapped
    /// when asked.
    pub fn scale(&self) -> Scale {
        let s = Scale::new(self.size, self.font.units_per_em());
        if !self.sharpen.x_height {
            return s;
        }
        let xh = s.y_units(i32::from(self.font.x_height()));
        let one = i64::from(crate::geom::FINE_ONE);
        let target = round_px(xh).max(one);
        if xh <= 0 {
            return s;
        }
        s.with_y_ratio(target, xh)
    }
}

/// What a text occupies, without drawing it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct TextMetrics {
    /// The widest line's advance, fine units.
    pub width: i64,
    /// The lines' advances by their ascender-to-descender boxes.
    pub layout_box: FineRect,
    /// The glyphs' outline boxes together (`None`: nothing with an
    /// outline).
    pub ink_box: Option<FineRect>,
    /// The pen after the last glyph of the last line.
    pub next_position: FinePoint,
}

#[cfg(feature = "defmt")]
impl defmt::Format for TextMetrics {
    fn format(&self, f: defmt::Formatter<'_>) {
        let b = &self.layout_box;
        defmt::write!(
            f,
            "TextMetrics {{ width: {}, layout_box: ({}, {})..({}, {}), next: {} }}",
            self.width,
            b.x0,
            b.y0,
            b.x1,
            b.y1,
            self.next_position
        );
    }
}

/// A string drawn with a font: the outline counterpart of
/// embedded-graphics' `Text`.
///
/// ```
/// use softedge::canvas::Canvas;
/// use softedge::geom::FinePoint;
/// use softedge::text::{Alignment, Font, FontStyle, Text};
/// use softedge::{Band, BandBuffer};
///
/// let font = Font::bundled().unwrap();
/// let style = FontStyle::<1>::new(&font, 16, [4095]);
/// let text = Text::with_alignment("Hi\nthere", FinePoint::from_px(32, 14), style, Alignment::Center);
/// let m = text.measure();
/// assert!(m.width > 30 * 1024 && m.width < 50 * 1024); // "there" at 16 px
///
/// let mut acc = [0i32; BandBuffer::<1>::acc_len(64, 40)];
/// let mut cover = [0i32; BandBuffer::<1>::cover_len(64, 40)];
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(64, 0, 40)).unwrap();
/// buf.clear([0]);
/// let mut canvas = Canvas::new(&mut buf, None);
/// text.draw(&mut canvas).unwrap();
/// let lit = (0..40).flat_map(|y| (0..64).map(move |x| (x, y)))
///     .filter(|&(x, y)| canvas.buffer().lin12(x, y).unwrap()[0] > 0)
///     .count();
/// assert!(lit > 60);
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Text<'t, 'f, 'a, const C: usize> {
    /// The string; lines split at `'\n'`.
    pub text: &'t str,
    /// The anchor of the first line, fine units.
    pub position: FinePoint,
    /// Font, size, colour, opacity.
    pub style: FontStyle<'f, 'a, C>,
    /// Alignment, baseline, line height.
    pub text_style: TextStyle,
}

impl<'t, 'f, 'a, const C: usize> Text<'t, 'f, 'a, C> {
    /// Left-aligned on the alphabetic baseline.
    pub fn new(text: &'t str, position: FinePoint, style: FontStyle<'f, 'a, C>) -> Self {
        Self::with_text_style(text, position, style, TextStyle::default())
    }

    /// With a text style.
    pub fn with_text_style(
        text: &'t str,
        position: FinePoint,
        style: FontStyle<'f, 'a, C>,
        text_style: TextStyle,
    ) -> Self {
        Self {
            text,
            position,
            style,
            text_style,
        }
    }

    /// With an alignment.
    pub fn with_alignment(
        text: &'t str,
        position: FinePoint,
        style: FontStyle<'f, 'a, C>,
        alignment: Alignment,
    ) -> Self {
        Self::with_text_style(text, position, style, TextStyle::with_alignment(alignment))
    }

    /// With a baseline.
    pub fn with_baseline(
        text: &'t str,
        position: FinePoint,
        style: FontStyle<'f, 'a, C>,
        baseline: Baseline,
    ) -> Self {
        Self::with_text_style(text, position, style, TextStyle::with_baseline(baseline))
    }

    /// The distance between baselines, fine units.
    pub fn line_height(&self) -> i64 {
        let s = self.style.scale();
        let h = self
            .text_style
            .line_height
            .to_fine(s.y_units(self.style.font.line_height()));
        if self.style.sharpen.baseline {
            round_px(h)
        } else {
            h
        }
    }

    /// The first line's baseline, fine units.
    fn first_baseline(&self, s: &Scale) -> i64 {
        let font = self.style.font;
        let asc = s.y_units(i32::from(font.ascender()));
        let desc = s.y_units(i32::from(font.descender()));
        let y = i64::from(self.position.y);
        let b = match self.text_style.baseline {
            Baseline::Alphabetic => y,
            Baseline::Top => y + asc,
            Baseline::Bottom => y + desc,
            Baseline::Middle => y + (asc + desc) / 2,
        };
        if self.style.sharpen.baseline {
            round_px(b)
        } else {
            b
        }
    }

    /// Each line as a run, placed.
    pub fn lines(&self) -> impl Iterator<Item = GlyphRun<'t, 'f, 'a>> + '_ {
        let s = self.style.scale();
        let step = self.line_height();
        let mut baseline = self.first_baseline(&s);
        self.text.split('\n').map(move |line| {
            let line = line.strip_suffix('\r').unwrap_or(line);
            let y = super::outline::sat_fine(baseline);
            baseline = baseline.saturating_add(step);
            let at = |x: i64| {
                GlyphRun::new(
                    self.style.font,
                    line,
                    FinePoint::new(super::outline::sat_fine(x), y),
                    s,
                )
                .with_kerning(self.style.kerning)
                .with_sharpen(self.style.sharpen)
                .with_tolerance(self.style.tolerance)
            };
            let x = i64::from(self.position.x);
            match self.text_style.alignment {
                Alignment::Left => at(x),
                Alignment::Right => at(x - at(x).advance()),
                Alignment::Center => at(x - at(x).advance() / 2),
            }
        })
    }

    /// Draws every line into the canvas (each line one shape, in the
    /// style's colour and opacity, composed over what is there) and gives
    /// the pen position after the last glyph.
    ///
    /// A character the font lacks is not drawn (no `.notdef` box, no
    /// advance): the rest is drawn and [`DrawError::MissingGlyph`] names
    /// the first one.
    ///
    /// With a [cache](FontStyle::with_cache), the lines are drawn from
    /// the glyphs' masks as one shape (see [`CachedFont`]); a glyph the
    /// cache cannot keep is walked from its outline into the same shape.
    pub fn draw<Col>(&self, canvas: &mut Canvas<'_, '_, C, Col>) -> Result<FinePoint, DrawError> {
        if let Some(cache) = self.style.cache {
            let source = CachedFont::with_scale(self.style.font, self.style.scale(), cache)
                .with_tolerance(self.style.tolerance)
                .with_kerning(self.style.kerning);
            let lines = self.lines().map(|run| {
                let o = run.origin();
                masked::Line {
                    text: run.text(),
                    x: i64::from(o.x),
                    y: i64::from(o.y),
                }
            });
            masked::draw_lines(
                canvas,
                &source,
                lines,
                self.style.color,
                self.style.opacity,
                self.style.sharpen.glyph_x,
                0,
            )?;
            return Ok(self.end());
        }
        let mut last = None;
        let mut missing = None;
        for run in self.lines() {
            canvas.fill(
                &run,
                self.style.color,
                FillRule::NonZero,
                Blend::Over,
                self.style.opacity,
            )?;
            if missing.is_none() {
                missing = self.style.font.missing(run.text()).next();
            }
            last = Some(run);
        }
        if let Some(c) = missing {
            return Err(DrawError::MissingGlyph(c));
        }
        // One more pass over the last line only (the pen's end).
        Ok(last.map_or(self.position, |run| pen_end(&run)))
    }

    /// The pen after the last glyph of the last line.
    fn end(&self) -> FinePoint {
        self.lines()
            .last()
            .map_or(self.position, |run| pen_end(&run))
    }

    /// The layout without drawing: widths, boxes, next position.
    pub fn measure(&self) -> TextMetrics {
        let s = self.style.scale();
        let font = self.style.font;
        let asc = s.y_units(i32::from(font.ascender()));
        let desc = s.y_units(i32::from(font.descender()));
        let mut width = 0i64;
        let mut layout: Option<(i64, i64, i64, i64)> = None;
        let mut ink: Option<(i64, i64, i64, i64)> = None;
        let mut next = self.position;
        for run in self.lines() {
            let adv = run.advance();
            width = width.max(adv);
            let o = run.origin();
            let (x, y) = (i64::from(o.x), i64::from(o.y));
            layout = Some(union(layout, (x, y - asc, x + adv.max(0), y - desc)));
            for g in run.glyphs() {
                if let Some(r) = font.face().glyph_bounding_box(g.id()) {
                    let gx = i64::from(g.origin().x);
                    let b = (
                        gx + s.x_units(i32::from(r.x_min)),
                        y - s.y_units(i32::from(r.y_max)),
                        gx + s.x_units(i32::from(r.x_max)),
                        y - s.y_units(i32::from(r.y_min)),
                    );
                    ink = Some(union(ink, b));
                }
            }
            next = pen_end(&run);
        }
        let rect = |(x0, y0, x1, y1): (i64, i64, i64, i64)| FineRect {
            x0: super::outline::sat_fine(x0),
            y0: super::outline::sat_fine(y0),
            x1: super::outline::sat_fine(x1),
            y1: super::outline::sat_fine(y1),
        };
        let p = self.position;
        TextMetrics {
            width,
            layout_box: layout.map_or(
                FineRect {
                    x0: p.x,
                    y0: p.y,
                    x1: p.x,
                    y1: p.y,
                },
                rect,
            ),
            ink_box: ink.map(rect),
            next_position: next,
        }
    }
}

/// The pen after a run's last glyph.
fn pen_end(run: &GlyphRun<'_, '_, '_>) -> FinePoint {
    let o = run.origin();
    FinePoint::new(
        super::outline::sat_fine(i64::from(o.x) + run.advance()),
        o.y,
    )
}

fn union(a: Option<(i64, i64, i64, i64)>, b: (i64, i64, i64, i64)) -> (i64, i64, i64, i64) {
    match a {
        None => b,
        Some(a) => (a.0.min(b.0), a.1.min(b.1), a.2.max(b.2), a.3.max(b.3)),
    }
}
