//! Text in a host scene: a string, its font file's bytes and its style,
//! drawn into a band through the canvas (`softedge::text`).
//!
//! The font file is shared (`Arc`), parsed again for every band it is drawn
//! into (parsing reads the table directory only), and checked when the
//! item is made, so drawing never meets a bad file.

use std::sync::Arc;

use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::style::Opacity;
use softedge::text::{
    Alignment, Baseline, Font, FontError, FontStyle, LineHeight, Sharpen, Text, TextSize, TextStyle,
};
use softedge::{BandBuffer, DrawError, RenderStyle};

/// One `[[text]]` of a scene.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TextItem<const C: usize> {
    /// The font file (checked to parse).
    font: Arc<[u8]>,
    /// The string; lines split at `'\n'`.
    pub text: String,
    /// The anchor, fine units.
    pub position: FinePoint,
    /// The em.
    pub size: TextSize,
    /// Alignment, baseline, line height.
    pub layout: TextStyle,
    /// Linear colour.
    pub color: [u16; C],
    /// Opacity of each line.
    pub opacity: Opacity,
    /// Grid fitting.
    pub sharpen: Sharpen,
}

impl<const C: usize> TextItem<C> {
    /// Left-aligned, alphabetic baseline, opaque, exact positions; fails
    /// if `font` does not parse.
    pub fn new(
        font: Arc<[u8]>,
        text: &str,
        position: FinePoint,
        size: TextSize,
        color: [u16; C],
    ) -> Result<Self, FontError> {
        Font::new(&font)?;
        Ok(Self {
            font,
            text: text.to_string(),
            position,
            size,
            layout: TextStyle::new(
                Alignment::Left,
                Baseline::Alphabetic,
                LineHeight::Percent(100),
            ),
            color,
            opacity: Opacity::OPAQUE,
            sharpen: Sharpen::NONE,
        })
    }

    /// The bundled font's bytes.
    pub fn bundled_font() -> Arc<[u8]> {
        Arc::from(softedge::text::bundled::SOFTEDGE_SANS)
    }

    /// Draws the text into one band with the scene's pixel model.
    pub fn draw(&self, buf: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        let mut canvas = Canvas::new(buf, None);
        canvas.set_style(*style);
        self.compose(&mut canvas, self.opacity)
    }

    /// Draws the text over what the canvas holds, at `opacity` (instead of
    /// its own).
    pub fn compose<Col>(
        &self,
        canvas: &mut Canvas<'_, '_, C, Col>,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        // Checked in `new`: a file that no longer parses draws nothing.
        let Ok(font) = Font::new(&self.font) else {
            return Ok(());
        };
        let fs = FontStyle::new(&font, 1, self.color)
            .with_size(self.size)
            .with_opacity(opacity)
            .with_sharpen(self.sharpen);
        Text::with_text_style(&self.text, self.position, fs, self.layout)
            .draw(canvas)
            .map(|_| ())
    }
}
