//! [`AaTextStyle`]: embedded-graphics' text idiom, anti-aliased —
//! `Text::with_alignment("72%", p, style, Alignment::Center).draw(canvas)`
//! as with a `MonoTextStyle`, the glyphs from a
//! [`RasterFont`](super::RasterFont) in flash or an outline font through a
//! [`GlyphCache`](super::GlyphCache) ([`CachedFont`](super::CachedFont)).
//!
//! Takes embedded-graphics' `Text` (string, `Point`, character style,
//! `TextStyle`: alignment, baseline, line height) with an
//! [`AaTextStyle`] (a glyph source, a text colour of the display's colour
//! type, an opacity); gives, drawn into a band's [`Canvas`], every line
//! laid out as embedded-graphics lays out a `MonoTextStyle`'s (the same
//! calls to the style's `measure_string` and `line_height`, the same
//! arithmetic) and the text composed as one anti-aliased shape in linear
//! light (`text::masked`).
//!
//! ## Coordinates (embedded-graphics')
//!
//! A `Point` names a pixel. With `Baseline::Alphabetic` the glyphs stand
//! on the bottom edge of row `p.y` (an `A`'s bottom row is `p.y`), with
//! `Top` the font's ascender is on the top edge of row `p.y`, with
//! `Bottom` its descender on the bottom edge, with `Middle` the middle of
//! the two on the middle of row `p.y`. The pen starts on the left edge of
//! column `p.x`. A line's width (what alignment uses, what
//! `measure_string` and `draw_string` return) is its advance rounded to
//! whole pixels; the line height is the font's, rounded. The bounding box
//! (`measure_string`'s, and so `Text::bounding_box()`) is the line's box,
//! advance by ascender-to-descender rows, grown to every pixel the glyphs
//! ink: it holds all drawn pixels, as embedded-graphics' `Dimensions`
//! asks.
//!
//! ## Which `draw`
//!
//! embedded-graphics' `Drawable::draw(&self, target)` works with any
//! `DrawTarget`; for a [`Canvas`] this crate adds [`DrawAaText::draw`],
//! which takes the text by value and so is the one method syntax picks
//! (`text.draw(canvas)`, with [`DrawAaText`] in scope: it is in
//! [`prelude`](crate::prelude)): anti-aliased, composed in linear light,
//! returning `Result<Point, DrawError>` with
//! [`DrawError::MissingGlyph`] for a character the font lacks (the rest is
//! drawn). Through `Drawable::draw` (another target, or `(&text).draw`)
//! each pixel whose coverage is at least one half is set to the text
//! colour: 1-bit text, the anti-aliasing needs the canvas; a character the
//! font lacks is skipped there (see
//! [`RasterFont::missing`](super::RasterFont::missing)).
//!
//! ```
//! use embedded_graphics::mock_display::MockDisplay;
//! use embedded_graphics::pixelcolor::Rgb565;
//! use embedded_graphics::prelude::*;
//! use embedded_graphics::text::{Alignment, Text};
//! use softedge::prelude::*;
//! use softedge::text::{AaTextStyle, CachedFont, Font, GlyphCache, TextSize, SLOT_WORDS};
//!
//! let font = Font::bundled()?;
//! let (mut codes, mut slots, mut scratch) = ([0u8; 2048], [0u32; 32 * SLOT_WORDS], [0i32; 1024]);
//! let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
//! let style = AaTextStyle::new(CachedFont::new(&font, TextSize::px(16), &cache), Rgb565::WHITE);
//!
//! let mut display = MockDisplay::<Rgb565>::new();
//! let (mut acc, mut cover) = ([0; BandBuffer::<3>::acc_len(64, 16)], [0; BandBuffer::<3>::cover_len(64, 16)]);
//! let mut renderer = Renderer::new(&mut acc, &mut cover, &mut [], 64, 32, 16)?;
//! renderer.render(&mut display, &Rgb565Format::new(Curve::Srgb), Rgb565::BLACK, |canvas| {
//!     Text::with_alignment("72%", Point::new(32, 20), style, Alignment::Center).draw(canvas)?;
//!     Ok::<(), DrawError>(())
//! })?;
//! assert_eq!(cache.stats().misses, 3); // '7', '2', '%': rasterized once, in the first band
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use embedded_graphics::geometry::{Point, Size};
use embedded_graphics::pixelcolor::PixelColor;
use embedded_graphics::prelude::DrawTarget;
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::renderer::{CharacterStyle, TextMetrics, TextRenderer};
use embedded_graphics::text::{Alignment, Baseline, Text};
use embedded_graphics::Pixel;

use super::masked::{self, Line};
use super::source::GlyphSource;
use crate::canvas::Canvas;
use crate::color::IntoLinear;
use crate::geom::{FINE_BITS, FINE_ONE};
use crate::raster::DrawError;
use crate::style::Opacity;
use crate::COVER_ONE;

/// A character style of anti-aliased glyphs for embedded-graphics' `Text`
/// (see [the module](self)): a glyph source `S` (`&RasterFont` or a
/// [`CachedFont`](super::CachedFont)) and colours of the display's type
/// `Col`.
///
/// ```
/// use embedded_graphics::pixelcolor::Rgb565;
/// use embedded_graphics::prelude::*;
/// use embedded_graphics::text::renderer::TextRenderer;
/// use softedge::style::Opacity;
/// use softedge::text::{AaTextStyle, CachedFont, Font, GlyphCache, TextSize, SLOT_WORDS};
/// let font = Font::bundled().unwrap();
/// let (mut codes, mut slots, mut scratch) = ([0u8; 512], [0u32; 8 * SLOT_WORDS], [0i32; 512]);
/// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
/// let style = AaTextStyle::new(CachedFont::new(&font, TextSize::px(20), &cache), Rgb565::CYAN)
///     .opacity(Opacity::from_percent(75));
/// assert_eq!(style.line_height(), 23); // DejaVu Sans: 1.164 em
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct AaTextStyle<S, Col> {
    /// Where the glyphs come from.
    pub source: S,
    /// The text's colour (`None`: the text is laid out, not drawn).
    pub text_color: Option<Col>,
    /// A colour filled behind each line's box first (`None`: nothing).
    pub background_color: Option<Col>,
    /// The opacity of the text as a whole.
    pub opacity: Opacity,
    /// Glyphs on whole pixels (for static text on 1-bit displays, like
    /// [`Sharpen::GRID`](super::Sharpen::GRID)'s glyph origins).
    pub grid: bool,
    /// The text's coverage steepened by a gain of `2^contrast` before it
    /// is composed (`0..=4`; 0 by default): on a 1-bit display the text's
    /// edges are then decided mostly by their side of 1/2, as
    /// [`ContrastBoost`](super::ContrastBoost) does to a whole frame,
    /// without touching the rest of the frame.
    pub contrast: u8,
}

impl<S: GlyphSource, Col: Copy> AaTextStyle<S, Col> {
    /// Text in `color` from `source`, opaque, at sub-pixel positions.
    pub const fn new(source: S, color: Col) -> Self {
        Self {
            source,
            text_color: Some(color),
            background_color: None,
            opacity: Opacity::OPAQUE,
            grid: false,
            contrast: 0,
        }
    }

    /// With an opacity.
    pub const fn opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// With a background colour behind each line's box.
    pub const fn background_color(mut self, color: Col) -> Self {
        self.background_color = Some(color);
        self
    }

    /// With glyphs on whole pixels.
    pub const fn grid(mut self, on: bool) -> Self {
        self.grid = on;
        self
    }

    /// With the text's coverage steepened by `2^shift` (see
    /// [`contrast`](Self::contrast); `shift` limited to 4).
    pub const fn contrast(mut self, shift: u8) -> Self {
        self.contrast = if shift > 4 { 4 } else { shift };
        self
    }

    /// The baseline's fine y for a `Point`'s row and a baseline choice.
    fn baseline_fine(&self, y: i32, baseline: Baseline) -> i64 {
        let m = self.source.line_metrics();
        let one = i64::from(FINE_ONE);
        let top = i64::from(y) * one;
        match baseline {
            Baseline::Alphabetic => top + one,
            Baseline::Top => top + i64::from(m.ascender),
            Baseline::Bottom => top + one + i64::from(m.descender),
            Baseline::Middle => {
                top + one / 2 + (i64::from(m.ascender) + i64::from(m.descender)) / 2
            }
        }
    }

    /// A line's advance rounded to whole pixels (what alignment and the
    /// next position use), and its first missing character.
    fn width(&self, text: &str) -> (i32, Option<char>) {
        let (adv, missing) = masked::advance(&self.source, text);
        let px = (adv + i64::from(FINE_ONE / 2)) >> FINE_BITS;
        (px.clamp(0, 1 << 21) as i32, missing)
    }

    /// The pixels a line's glyphs ink, where `text::masked` draws them:
    /// `(x0, y0, x1, y1)`, ends excluded (`None`: no ink). A glyph
    /// without a mask (a cache without room) counts with its outline's
    /// box, a pixel wider on each side (its curves flattened, its points
    /// scaled on their own).
    fn ink(&self, text: &str, position: Point, baseline: Baseline) -> Option<(i32, i32, i32, i32)> {
        let src = &self.source;
        let yb = masked::baseline_row(self.baseline_fine(position.y, baseline));
        let phases = src.phases().clamp(1, 16);
        let pen = i64::from(position.x) * i64::from(FINE_ONE);
        let mut ink: Option<(i32, i32, i32, i32)> = None;
        let px = |v: i64| v.clamp(-(1 << 21), 1 << 21) as i32;
        for (g, gx, phase) in masked::Pens::new(src, text, pen, self.grid).flatten() {
            let b = match src.mask(g, phase, |m| {
                let (x, y) = (
                    gx.saturating_add(m.left.into()),
                    yb.saturating_add(m.top.into()),
                );
                (!m.is_empty()).then(|| {
                    let (w, h) = (i32::from(m.width), i32::from(m.height));
                    (x, y, x.saturating_add(w), y.saturating_add(h))
                })
            }) {
                Some(b) => b,
                None => src.outline(g).and_then(|o| {
                    let r = o.font.face().glyph_bounding_box(o.id)?;
                    let one = i64::from(FINE_ONE);
                    let fx = i64::from(gx) * one + i64::from(phase) * one / i64::from(phases);
                    let fy = i64::from(yb) * one;
                    let (s, bits) = (o.scale, FINE_BITS);
                    Some((
                        px(((fx + s.x_units(r.x_min.into())) >> bits) - 1),
                        px(((fy - s.y_units(r.y_max.into())) >> bits) - 1),
                        px(((fx + s.x_units(r.x_max.into()) + one - 1) >> bits) + 1),
                        px(((fy - s.y_units(r.y_min.into()) + one - 1) >> bits) + 1),
                    ))
                }),
            };
            if let Some(b) = b {
                ink = Some(ink.map_or(b, |a| {
                    (a.0.min(b.0), a.1.min(b.1), a.2.max(b.2), a.3.max(b.3))
                }));
            }
        }
        ink
    }

    /// The rows of a line's box (ascender to descender) for a baseline.
    fn box_rows(&self, position: Point, baseline: Baseline) -> (i32, i32) {
        let m = self.source.line_metrics();
        let b = self.baseline_fine(position.y, baseline);
        let one = i64::from(FINE_ONE);
        let top = (b - i64::from(m.ascender)).div_euclid(one);
        let bottom = (b - i64::from(m.descender) + one - 1).div_euclid(one);
        let c = |v: i64| v.clamp(-(1 << 21), 1 << 21) as i32;
        (c(top), c(bottom.max(top)))
    }
}

impl<S: GlyphSource, Col: PixelColor> CharacterStyle for AaTextStyle<S, Col>
where
    S: Clone,
{
    type Color = Col;

    fn set_text_color(&mut self, text_color: Option<Col>) {
        self.text_color = text_color;
    }

    fn set_background_color(&mut self, background_color: Option<Col>) {
        self.background_color = background_color;
    }
}

impl<S: GlyphSource, Col: PixelColor> TextRenderer for AaTextStyle<S, Col> {
    type Color = Col;

    /// Any target: each pixel at least half covered gets the text colour
    /// (see [the module](self): a [`Canvas`] draws anti-aliased through
    /// [`DrawAaText`]).
    fn draw_string<D>(
        &self,
        text: &str,
        position: Point,
        baseline: Baseline,
        target: &mut D,
    ) -> Result<Point, D::Error>
    where
        D: DrawTarget<Color = Col>,
    {
        let (w, _) = self.width(text);
        if let Some(bg) = self.background_color {
            let (top, bottom) = self.box_rows(position, baseline);
            let area = Rectangle::new(
                Point::new(position.x, top),
                Size::new(w as u32, (bottom - top) as u32),
            );
            target.fill_solid(&area, bg)?;
        }
        if let Some(color) = self.text_color {
            let yb = masked::baseline_row(self.baseline_fine(position.y, baseline));
            let x = i64::from(position.x) * i64::from(FINE_ONE);
            let src = &self.source;
            let mut row = [0i32; 64];
            for (g, gx, phase) in masked::Pens::new(src, text, x, self.grid).flatten() {
                let r = src.mask(g, phase, |m| {
                    let mut dec = m.rows();
                    let (left, top) = (gx + i32::from(m.left), yb + i32::from(m.top));
                    for j in 0..i32::from(m.height) {
                        let mut off = 0;
                        while off < usize::from(m.width) {
                            let n = (usize::from(m.width) - off).min(row.len());
                            let Some(px) = row.get_mut(..n) else {
                                break;
                            };
                            dec.fill(px);
                            let lit = px.iter().enumerate().filter(|(_, &v)| 2 * v >= COVER_ONE);
                            let pixels = lit.map(|(i, _)| {
                                Pixel(Point::new(left + (off + i) as i32, top + j), color)
                            });
                            target.draw_iter(pixels)?;
                            off += n;
                        }
                    }
                    Ok(())
                });
                if let Some(r) = r {
                    r?;
                }
            }
        }
        Ok(Point::new(position.x.saturating_add(w), position.y))
    }

    fn draw_whitespace<D>(
        &self,
        width: u32,
        position: Point,
        baseline: Baseline,
        target: &mut D,
    ) -> Result<Point, D::Error>
    where
        D: DrawTarget<Color = Col>,
    {
        if let Some(bg) = self.background_color {
            let (top, bottom) = self.box_rows(position, baseline);
            let area = Rectangle::new(
                Point::new(position.x, top),
                Size::new(width, (bottom - top) as u32),
            );
            target.fill_solid(&area, bg)?;
        }
        let w = i32::try_from(width).unwrap_or(i32::MAX);
        Ok(Point::new(position.x.saturating_add(w), position.y))
    }

    /// The bounding box: the line's box (its advance rounded, from the
    /// ascender to the descender line) grown to every pixel its glyphs
    /// ink, as embedded-graphics' `Dimensions` asks of a drawable (glyphs
    /// reach past their advance and below the descender: `J`, `_`).
    fn measure_string(&self, text: &str, position: Point, baseline: Baseline) -> TextMetrics {
        let (w, _) = self.width(text);
        let (top, bottom) = self.box_rows(position, baseline);
        let mut b = (position.x, top, position.x.saturating_add(w), bottom);
        if let Some(ink) = self.ink(text, position, baseline) {
            b = (
                b.0.min(ink.0),
                b.1.min(ink.1),
                b.2.max(ink.2),
                b.3.max(ink.3),
            );
        }
        TextMetrics {
            bounding_box: Rectangle::new(
                Point::new(b.0, b.1),
                Size::new(b.2.abs_diff(b.0), b.3.abs_diff(b.1)),
            ),
            next_position: Point::new(position.x.saturating_add(w), position.y),
        }
    }

    fn line_height(&self) -> u32 {
        let h = self.source.line_metrics().line_height;
        ((i64::from(h) + i64::from(FINE_ONE / 2)) >> FINE_BITS).clamp(0, 1 << 21) as u32
    }
}

/// embedded-graphics' `Text` drawn anti-aliased into a [`Canvas`] (see
/// [the module](self)): `text.draw(canvas)` as for any drawable, but
/// composed in linear light, and a character the font lacks reported.
pub trait DrawAaText<const C: usize, Col> {
    /// Draws the text (every line one shape with the others) and gives the
    /// position after its last character, as embedded-graphics' `draw`
    /// does; [`DrawError::MissingGlyph`] names the first character the
    /// font lacks (the others are drawn).
    fn draw(self, canvas: &mut Canvas<'_, '_, C, Col>) -> Result<Point, DrawError>;
}

impl<S: GlyphSource, Col: PixelColor + IntoLinear<C>, const C: usize> DrawAaText<C, Col>
    for Text<'_, AaTextStyle<S, Col>>
{
    fn draw(self, canvas: &mut Canvas<'_, '_, C, Col>) -> Result<Point, DrawError> {
        let style = &self.character_style;
        if let Some(bg) = style.background_color {
            for (line, p) in self.placed() {
                let (w, _) = style.width(line);
                let (top, bottom) = style.box_rows(p, self.text_style.baseline);
                let area = Rectangle::new(
                    Point::new(p.x, top),
                    Size::new(w as u32, (bottom - top) as u32),
                );
                let _ = canvas.fill_solid(&area, bg);
            }
        }
        // The last line, seen as the lines go by (its end is what `draw`
        // returns).
        let last = core::cell::Cell::new(None);
        let lines = self.placed().map(|(text, p)| {
            last.set(Some((text, p)));
            Line {
                text,
                x: i64::from(p.x) * i64::from(FINE_ONE),
                y: style.baseline_fine(p.y, self.text_style.baseline),
            }
        });
        match style.text_color {
            Some(color) => masked::draw_lines(
                canvas,
                &style.source,
                lines,
                color.into_linear(),
                style.opacity,
                style.grid,
                style.contrast,
            )?,
            None => lines.for_each(drop),
        }
        Ok(last.get().map_or(self.position, |(line, p)| {
            Point::new(p.x.saturating_add(style.width(line).0), p.y)
        }))
    }
}

/// embedded-graphics' layout of a `Text`'s lines.
trait Placed<'t> {
    /// Each line (a `'\r'` before its end dropped) and its position, as
    /// embedded-graphics' `Text::lines` finds them: `Right` puts the
    /// line's last pixel on the position, `Center` moves it left by half
    /// its width less one; each next line one line height down. Widths
    /// are measured only where the alignment needs them.
    fn placed(&self) -> impl Iterator<Item = (&'t str, Point)> + '_;
}

impl<'t, S: GlyphSource, Col: PixelColor> Placed<'t> for Text<'t, AaTextStyle<S, Col>> {
    fn placed(&self) -> impl Iterator<Item = (&'t str, Point)> + '_ {
        let style = &self.character_style;
        let line_height =
            i32::try_from(self.text_style.line_height.to_absolute(style.line_height()))
                .unwrap_or(i32::MAX);
        let mut y = self.position.y;
        self.text.split('\n').map(move |line| {
            let line = line.strip_suffix('\r').unwrap_or(line);
            let x = match self.text_style.alignment {
                Alignment::Left => self.position.x,
                Alignment::Right => self.position.x - (style.width(line).0 - 1),
                Alignment::Center => self.position.x - (style.width(line).0 - 1) / 2,
            };
            let p = Point::new(x, y);
            y = y.saturating_add(line_height);
            (line, p)
        })
    }
}
