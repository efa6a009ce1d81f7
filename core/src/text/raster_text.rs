//! [`RasterText`]: a string drawn from rasterized glyphs at a sub-pixel
//! position — the [`Text`](super::Text) of a [`GlyphSource`] (a
//! [`RasterFont`](super::RasterFont) in flash or a
//! [`CachedFont`](super::CachedFont)).
//!
//! Takes a string (lines split at `'\n'`, a `'\r'` before it dropped), a
//! position in fine units (the anchor the [`TextStyle`] names, as for
//! [`Text`](super::Text): `Alphabetic` the first baseline, `Top` /
//! `Bottom` the ascender / descender line, `Middle` halfway), a source, a
//! linear colour and an opacity; gives the lines drawn into a band as one
//! shape (`text::masked`: each glyph at its drawn position, its
//! pen rounded to the source's phases and its baseline to a pixel) and the
//! pen after the last glyph. For embedded-graphics' `Text` and `Point`s,
//! see [`AaTextStyle`](super::AaTextStyle).

use super::layout::{Alignment, Baseline, TextStyle};
use super::masked::{self, Line};
use super::source::GlyphSource;
use crate::canvas::Canvas;
use crate::color::IntoLinear;
use crate::geom::FinePoint;
use crate::raster::DrawError;
use crate::style::Opacity;

/// A string drawn from rasterized glyphs (see [the module](self)).
///
/// ```
/// use softedge::canvas::Canvas;
/// use softedge::geom::FinePoint;
/// use softedge::text::{Alignment, CachedFont, Font, GlyphCache, RasterText, TextSize, SLOT_WORDS};
/// use softedge::{Band, BandBuffer};
///
/// let font = Font::bundled().unwrap();
/// let (mut codes, mut slots, mut scratch) = ([0u8; 1024], [0u32; 16 * SLOT_WORDS], [0i32; 512]);
/// let cache = GlyphCache::new(&mut codes, &mut slots, &mut scratch);
/// let sans = CachedFont::new(&font, TextSize::px(14), &cache);
/// let text = RasterText::new("12.5", FinePoint::new(32 * 1024 + 300, 16 * 1024), sans, [4095])
///     .with_alignment(Alignment::Center);
/// let (mut acc, mut cover) = ([0i32; 64 * 20], [0i32; BandBuffer::<1>::cover_len(64, 20)]);
/// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(64, 0, 20)).unwrap();
/// buf.clear([0]);
/// let end = text.draw(&mut Canvas::new(&mut buf, None)).unwrap();
/// let w = text.width("12.5");
/// assert_eq!(i64::from(end.x), 32 * 1024 + 300 + (w - w / 2)); // centred
/// ```
#[derive(Debug, Clone, Copy)]
pub struct RasterText<'t, S, const C: usize> {
    /// The string; lines split at `'\n'`.
    pub text: &'t str,
    /// The anchor of the first line, fine units.
    pub position: FinePoint,
    /// Where the glyphs come from.
    pub source: S,
    /// Linear 12-bit colour.
    pub color: [u16; C],
    /// The opacity of the text as a whole.
    pub opacity: Opacity,
    /// Alignment, baseline, line height.
    pub text_style: TextStyle,
    /// Glyphs on whole pixels.
    pub grid: bool,
    /// The coverage's contrast gain, `2^contrast` (see
    /// [`AaTextStyle::contrast`](super::AaTextStyle)).
    pub contrast: u8,
}

impl<'t, S: GlyphSource, const C: usize> RasterText<'t, S, C> {
    /// Left-aligned on the alphabetic baseline, opaque; the colour linear
    /// or any [`IntoLinear`] colour (embedded-graphics' as sRGB).
    pub fn new(text: &'t str, position: FinePoint, source: S, color: impl IntoLinear<C>) -> Self {
        Self {
            text,
            position,
            source,
            color: color.into_linear().map(|v| v.min(crate::LIN_MAX)),
            opacity: Opacity::OPAQUE,
            text_style: TextStyle::default(),
            grid: false,
            contrast: 0,
        }
    }

    /// With a text style.
    pub fn with_text_style(mut self, text_style: TextStyle) -> Self {
        self.text_style = text_style;
        self
    }

    /// With an alignment.
    pub fn with_alignment(mut self, alignment: Alignment) -> Self {
        self.text_style.alignment = alignment;
        self
    }

    /// With a baseline.
    pub fn with_baseline(mut self, baseline: Baseline) -> Self {
        self.text_style.baseline = baseline;
        self
    }

    /// With an opacity.
    pub fn with_opacity(mut self, opacity: Opacity) -> Self {
        self.opacity = opacity;
        self
    }

    /// With glyphs on whole pixels.
    pub fn with_grid(mut self, on: bool) -> Self {
        self.grid = on;
        self
    }

    /// With the coverage steepened by `2^shift` before it is composed
    /// (`shift` limited to 4; for 1-bit displays).
    pub fn with_contrast(mut self, shift: u8) -> Self {
        self.contrast = shift.min(4);
        self
    }

    /// The advance of one line (kerning included), fine units.
    pub fn width(&self, line: &str) -> i64 {
        masked::advance(&self.source, line).0
    }

    /// The distance between baselines, fine units.
    pub fn line_height(&self) -> i64 {
        let m = self.source.line_metrics();
        self.text_style
            .line_height
            .to_fine(i64::from(m.line_height))
    }

    /// Each line and its pen's start on its baseline.
    fn lines(&self) -> impl Iterator<Item = Line<'t>> + '_ {
        let m = self.source.line_metrics();
        let y = i64::from(self.position.y);
        let mut baseline = match self.text_style.baseline {
            Baseline::Alphabetic => y,
            Baseline::Top => y + i64::from(m.ascender),
            Baseline::Bottom => y + i64::from(m.descender),
            Baseline::Middle => y + (i64::from(m.ascender) + i64::from(m.descender)) / 2,
        };
        let step = self.line_height();
        let x = i64::from(self.position.x);
        self.text.split('\n').map(move |line| {
            let line = line.strip_suffix('\r').unwrap_or(line);
            let at = match self.text_style.alignment {
                Alignment::Left => x,
                Alignment::Right => x - self.width(line),
                Alignment::Center => x - self.width(line) / 2,
            };
            let l = Line {
                text: line,
                x: at,
                y: baseline,
            };
            baseline = baseline.saturating_add(step);
            l
        })
    }

    /// Draws the text into the canvas (one shape, composed over what is
    /// there in the colour and opacity) and gives the pen after its last
    /// glyph; [`DrawError::MissingGlyph`] names the first character the
    /// font lacks (the rest is drawn).
    pub fn draw<Col>(&self, canvas: &mut Canvas<'_, '_, C, Col>) -> Result<FinePoint, DrawError> {
        masked::draw_lines(
            canvas,
            &self.source,
            self.lines(),
            self.color,
            self.opacity,
            self.grid,
            self.contrast,
        )?;
        Ok(self.lines().last().map_or(self.position, |l| {
            let x = l.x + self.width(l.text);
            FinePoint::new(super::outline::sat_fine(x), super::outline::sat_fine(l.y))
        }))
    }
}
