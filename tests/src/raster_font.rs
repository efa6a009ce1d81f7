//! A [`RasterFont`] made at run time, owned (what `softedge-sim font`
//! writes as a `static`): every glyph rasterized by softedge's
//! `rasterize_glyph` at each phase, exact advances, no kerning. For the
//! text tests that draw fonts rasterized ahead of time.

use std::cell::Cell;

use softedge::path::Tolerance;
use softedge::text::{
    rasterize_glyph, CharRange, Font, LineMetrics, MaskOffsets, RasterFont, RasterGlyph,
    RasterMetrics, Scale, TextSize,
};

/// A raster font's parts, owned.
pub struct Built {
    metrics: RasterMetrics,
    chars: Vec<CharRange>,
    glyphs: Vec<RasterGlyph>,
    offsets: Vec<u32>,
    masks: Vec<u8>,
}

impl Built {
    /// `chars` of `font` at `size` px and `phases` phases.
    pub fn new(font: &Font<'_>, size: u16, chars: &[char], phases: u8) -> Self {
        let scale = Scale::new(TextSize::px(size), font.units_per_em());
        Self::with_scale(font, size, scale, chars, phases)
    }

    /// The same with a scale of its own (the x-height snapped).
    pub fn with_scale(
        font: &Font<'_>,
        size: u16,
        scale: Scale,
        chars: &[char],
        phases: u8,
    ) -> Self {
        let mut chars: Vec<char> = chars.to_vec();
        chars.sort_unstable();
        chars.dedup();
        let mut cells = vec![0i32; 1 << 16];
        let scratch = Cell::from_mut(&mut cells[..]).as_slice_of_cells();
        let (mut glyphs, mut offsets, mut masks) = (Vec::new(), Vec::new(), Vec::new());
        let (mut top, mut bottom) = (0, 0);
        let mut ranges: Vec<CharRange> = Vec::new();
        for (i, &c) in chars.iter().enumerate() {
            let id = font.glyph(c);
            for p in 0..phases {
                offsets.push(masks.len() as u32);
                let mut code = Vec::new();
                let b = rasterize_glyph(
                    font,
                    id,
                    scale,
                    Tolerance::MIN,
                    i32::from(p) * 1024 / i32::from(phases),
                    scratch,
                    |x| {
                        code.push(x);
                        true
                    },
                )
                .unwrap();
                top = top.min(i32::from(b.top));
                bottom = bottom.max(i32::from(b.top) + i32::from(b.height));
                masks.extend([
                    b.left as i8 as u8,
                    b.top as i8 as u8,
                    b.width as u8,
                    b.height as u8,
                ]);
                masks.extend(code);
            }
            let adv = scale.x_units(i32::from(font.advance(id)));
            glyphs.push(RasterGlyph {
                advance: adv as u16,
                kern_left: 0,
                kern_right: 0,
            });
            match ranges.last_mut() {
                Some(r) if r.first + u32::from(r.len) == c as u32 => r.len += 1,
                _ => ranges.push(CharRange {
                    first: c as u32,
                    len: 1,
                    glyph: i as u16,
                }),
            }
        }
        let line = LineMetrics {
            ascender: scale.y_units(i32::from(font.ascender())) as i32,
            descender: scale.y_units(i32::from(font.descender())) as i32,
            line_height: scale.y_units(font.line_height()) as i32,
            ink_top: top,
            ink_bottom: bottom,
        };
        Self {
            metrics: RasterMetrics {
                size_64ths: u32::from(size) * 64,
                line,
                phases,
                advance_shift: 0,
                kern_shift: 0,
                kern_columns: 1,
            },
            chars: ranges,
            glyphs,
            offsets,
            masks,
        }
    }

    /// The font over the parts.
    pub fn font(&self) -> RasterFont<'_> {
        RasterFont::new(
            self.metrics,
            &self.chars,
            &self.glyphs,
            MaskOffsets::Long(&self.offsets),
            &[0],
            &self.masks,
        )
    }
}
