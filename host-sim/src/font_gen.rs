//! `softedge-sim font`: a TrueType / OpenType font, a size and a
//! character set made into a Rust `static` [`RasterFont`] for flash.
//!
//! Takes the font file's bytes ([`Font`]: `glyf` or CFF), a size in 1/64
//! px, the characters (see [`parse_chars`]: `ascii`, `latin1`, ranges, or
//! the characters of strings), a number of horizontal phases and a
//! flattening tolerance; gives Rust source (one `pub static`) and a
//! [`Report`]: the characters the font lacks (left out, and named), the
//! bytes the font takes in flash, part by part, and what a
//! [`GlyphCache`](softedge::text::GlyphCache) of the same glyphs would
//! need.
//!
//! Every glyph is rasterized by [`rasterize_glyph`], the function a
//! `GlyphCache` uses at run time: softedge's exact-area edge walk, each
//! pixel quantized to 1/29 within 3/4 of a level, the glyph's ink kept
//! (see `softedge::text::code`). Per glyph and phase the source holds the
//! mask's box (4 bytes) and its code; per glyph the advance and two
//! kerning classes (4 bytes) and an offset per phase (2 or 4); the
//! kerning is a matrix of classes (the distinct rows and columns of the
//! pairs' table) in `i8`, in fine units shifted so the largest fits.

use std::cell::Cell;
use std::fmt::Write as _;

use softedge::path::Tolerance;
use softedge::text::{rasterize_glyph, Font, GlyphId, LineMetrics, MaskBox, Scale, TextSize};

/// What to make.
#[derive(Debug, Clone)]
pub struct FontSpec {
    /// The `static`'s name.
    pub name: String,
    /// The em, 1/64 px.
    pub size_64ths: u32,
    /// The characters, in the order given (duplicates dropped, sorted by
    /// the generator).
    pub chars: Vec<char>,
    /// Horizontal phases per pixel (1..=16).
    pub phases: u8,
    /// Flattening tolerance of the rasterizer.
    pub tolerance: Tolerance,
    /// Pair kerning kept.
    pub kerning: bool,
    /// Where the font came from (for the generated comment).
    pub source_name: String,
    /// The path of the `softedge` crate in the generated source
    /// (`softedge`; `crate` inside softedge itself).
    pub crate_path: String,
    /// The x-height a whole number of pixels (the vertical scale
    /// multiplied by `round(x_px) / x_px`, as `Sharpen::GRID` does): for
    /// small text on 1-bit displays, with one phase and a baseline on the
    /// pixel grid (which a raster font always has).
    pub snap_x_height: bool,
}

/// What was made, in numbers.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Report {
    /// Glyphs in the font (characters kept).
    pub glyphs: usize,
    /// Characters asked for that the font lacks.
    pub missing: Vec<char>,
    /// Bytes of the masks (boxes and codes).
    pub mask_bytes: usize,
    /// Bytes of the offsets into them.
    pub offset_bytes: usize,
    /// Bytes of the glyph table (advance, kerning classes).
    pub glyph_bytes: usize,
    /// Bytes of the character ranges.
    pub char_bytes: usize,
    /// Bytes of the kerning matrix, and its classes (left, right).
    pub kern_bytes: usize,
    /// Kerning classes (left, right), the zero classes included.
    pub kern_classes: (usize, usize),
    /// The font's bytes in flash: every part, and the `RasterFont`
    /// itself.
    pub flash_bytes: usize,
    /// A `GlyphCache` of every glyph at one phase: code bytes, and the
    /// widest glyph's box (the scratch needs `width` cells a row).
    pub cache_code_bytes: usize,
    /// The widest and tallest rasterizer box (for a cache's scratch).
    pub max_box: (u16, u16),
}

impl Report {
    /// The report as lines of text.
    pub fn text(&self, spec: &FontSpec) -> String {
        let mut s = String::new();
        let px = f64::from(spec.size_64ths) / 64.0;
        let _ = writeln!(
            s,
            "{}: {} glyphs at {px} px, {} phase(s)",
            spec.name, self.glyphs, spec.phases
        );
        if !self.missing.is_empty() {
            let list: String = self
                .missing
                .iter()
                .map(|c| format!("{c:?} U+{:04X}", *c as u32))
                .collect::<Vec<_>>()
                .join(", ");
            let _ = writeln!(s, "missing ({}): {list}", self.missing.len());
        }
        let _ = writeln!(
            s,
            "flash {} bytes: masks {}, offsets {}, glyphs {}, character ranges {}, kerning {} ({} x {} classes); {:.1} bytes a glyph",
            self.flash_bytes,
            self.mask_bytes,
            self.offset_bytes,
            self.glyph_bytes,
            self.char_bytes,
            self.kern_bytes,
            self.kern_classes.0,
            self.kern_classes.1,
            self.flash_bytes as f64 / self.glyphs.max(1) as f64,
        );
        let _ = writeln!(
            s,
            "as a GlyphCache at one phase: {} code bytes, {} slots ({} bytes, twice as many advised), a scratch of {} x 32 cells ({} bytes)",
            self.cache_code_bytes,
            self.glyphs,
            self.glyphs * softedge::text::SLOT_WORDS * 4,
            self.max_box.0,
            usize::from(self.max_box.0) * 32 * 4,
        );
        s
    }
}

/// The characters a list names: comma-separated `ascii` (U+0020..U+007E),
/// `latin1` (ASCII and U+00A0..U+00FF), `U+XXXX` or `U+XXXX-U+YYYY`
/// (also `0x`), or a single character.
///
/// ```
/// use softedge_sim::font_gen::parse_chars;
/// assert_eq!(parse_chars("ascii").unwrap().len(), 95);
/// assert_eq!(parse_chars("latin1").unwrap().len(), 191);
/// assert_eq!(parse_chars("U+0030-U+0039,%").unwrap().len(), 11);
/// assert!(parse_chars("U+D800").is_err());
/// ```
pub fn parse_chars(list: &str) -> Result<Vec<char>, String> {
    let mut out = Vec::new();
    let code = |t: &str| -> Result<u32, String> {
        let hex = t
            .strip_prefix("U+")
            .or_else(|| t.strip_prefix("u+"))
            .or_else(|| t.strip_prefix("0x"))
            .ok_or_else(|| format!("`{t}` is not U+XXXX"))?;
        u32::from_str_radix(hex, 16).map_err(|_| format!("`{t}` is not U+XXXX"))
    };
    for item in list.split(',').filter(|s| !s.is_empty()) {
        match item {
            "ascii" => out.extend((0x20u8..0x7f).map(char::from)),
            "latin1" => {
                out.extend((0x20u8..0x7f).map(char::from));
                out.extend((0xa0u32..=0xff).filter_map(char::from_u32));
            }
            _ if item.chars().count() == 1 => out.extend(item.chars()),
            _ => {
                let (a, b) = match item.split_once('-') {
                    Some((a, b)) => (code(a)?, code(b)?),
                    None => {
                        let a = code(item)?;
                        (a, a)
                    }
                };
                if b < a || b - a > 0x1_0000 {
                    return Err(format!("bad range `{item}`"));
                }
                for v in a..=b {
                    out.push(
                        char::from_u32(v).ok_or_else(|| format!("U+{v:04X} is not a character"))?,
                    );
                }
            }
        }
    }
    Ok(out)
}

/// One glyph made: its advance (fine units), kerning classes, masks.
struct Made {
    ch: char,
    id: GlyphId,
    advance: i64,
    masks: Vec<(MaskBox, Vec<u8>)>,
}

/// Makes the font (see [the module](self)): the Rust source and its
/// report.
pub fn generate(data: &[u8], spec: &FontSpec) -> Result<(String, Report), String> {
    let font = Font::new(data).map_err(|e| format!("cannot read the font: {e}"))?;
    if spec.phases == 0 || spec.phases > 16 {
        return Err("phases is 1..=16".into());
    }
    let size = TextSize::from_64ths(spec.size_64ths);
    let mut scale = Scale::new(size, font.units_per_em());
    if spec.snap_x_height {
        // As `FontStyle::scale` with `Sharpen::x_height`.
        let xh = scale.y_units(i32::from(font.x_height()));
        let target = ((xh + 512).div_euclid(1024) * 1024).max(1024);
        if xh > 0 {
            scale = scale.with_y_ratio(target, xh);
        }
    }
    let mut chars = spec.chars.clone();
    chars.sort_unstable();
    chars.dedup();
    let mut report = Report {
        missing: chars
            .iter()
            .copied()
            .filter(|&c| !font.has_glyph(c))
            .collect(),
        ..Report::default()
    };
    chars.retain(|&c| font.has_glyph(c));
    if chars.is_empty() {
        return Err("the font has none of the characters".into());
    }
    // Rasterize.
    let mut cells = vec![0i32; 1 << 18];
    let scratch = Cell::from_mut(&mut cells[..]).as_slice_of_cells();
    let mut made = Vec::new();
    for &ch in &chars {
        let id = font.glyph(ch);
        let mut masks = Vec::new();
        for p in 0..spec.phases {
            let phase_fine = i32::from(p) * 1024 / i32::from(spec.phases);
            let mut code = Vec::new();
            let b = rasterize_glyph(
                &font,
                id,
                scale,
                spec.tolerance,
                phase_fine,
                scratch,
                |byte| {
                    code.push(byte);
                    true
                },
            )
            .map_err(|e| format!("{ch:?}: {e}"))?;
            if b.width > 255
                || b.height > 255
                || !(-128..=127).contains(&b.left)
                || !(-128..=127).contains(&b.top)
            {
                return Err(format!(
                    "{ch:?}: its box ({} x {} px at {}, {}) is too large for a RasterFont (255 px, offsets within ±127)",
                    b.width, b.height, b.left, b.top
                ));
            }
            masks.push((b, code));
        }
        made.push(Made {
            ch,
            id,
            advance: scale.x_units(i32::from(font.advance(id))),
            masks,
        });
    }
    // Character ranges.
    let mut ranges: Vec<(u32, u16, u16)> = Vec::new();
    for (i, m) in made.iter().enumerate() {
        let c = m.ch as u32;
        match ranges.last_mut() {
            Some((first, len, _)) if *first + u32::from(*len) == c && *len < u16::MAX => *len += 1,
            _ => ranges.push((c, 1, i as u16)),
        }
    }
    // Advances.
    let max_adv = made.iter().map(|m| m.advance.max(0)).max().unwrap_or(0);
    let mut advance_shift = 0u8;
    while (max_adv + (1 << advance_shift) / 2) >> advance_shift > i64::from(u16::MAX) {
        advance_shift += 1;
    }
    // Kerning: the pairs' table, its distinct rows and columns.
    let n = made.len();
    let kern: Vec<Vec<i64>> = made
        .iter()
        .map(|a| {
            made.iter()
                .map(|b| {
                    if spec.kerning {
                        scale.x_units(font.kerning(a.id, b.id))
                    } else {
                        0
                    }
                })
                .collect()
        })
        .collect();
    let max_k = kern.iter().flatten().map(|k| k.abs()).max().unwrap_or(0);
    let mut kern_shift = 0u8;
    while (max_k + (1 << kern_shift) / 2) >> kern_shift > 127 {
        kern_shift += 1;
    }
    let q = |k: i64| -> i8 {
        let half = (1i64 << kern_shift) / 2;
        let v = if k >= 0 {
            (k + half) >> kern_shift
        } else {
            -((-k + half) >> kern_shift)
        };
        v.clamp(-127, 127) as i8
    };
    let qk: Vec<Vec<i8>> = kern
        .iter()
        .map(|r| r.iter().map(|&k| q(k)).collect())
        .collect();
    let zero_row = vec![0i8; n];
    let mut rows: Vec<Vec<i8>> = vec![zero_row.clone()];
    let mut left = vec![0u8; n];
    for (i, r) in qk.iter().enumerate() {
        if r.iter().all(|&v| v == 0) {
            continue;
        }
        let k = match rows.iter().position(|x| x == r) {
            Some(k) => k,
            None => {
                rows.push(r.clone());
                rows.len() - 1
            }
        };
        left[i] = u8::try_from(k).map_err(|_| "more than 255 kerning classes: use --no-kerning")?;
    }
    let cols_of = |j: usize| -> Vec<i8> { qk.iter().map(|r| r[j]).collect() };
    let mut cols: Vec<Vec<i8>> = vec![zero_row.clone()];
    let mut right = vec![0u8; n];
    for (j, class) in right.iter_mut().enumerate() {
        let c = cols_of(j);
        if c.iter().all(|&v| v == 0) {
            continue;
        }
        let k = match cols.iter().position(|x| *x == c) {
            Some(k) => k,
            None => {
                cols.push(c);
                cols.len() - 1
            }
        };
        *class = u8::try_from(k).map_err(|_| "more than 255 kerning classes: use --no-kerning")?;
    }
    // The matrix: a left class's row is any of its glyphs' row, read at a
    // glyph of each right class.
    let rep_col: Vec<usize> = (0..cols.len())
        .map(|k| right.iter().position(|&r| usize::from(r) == k).unwrap_or(0))
        .collect();
    let mut matrix = Vec::new();
    if rows.len() > 1 {
        for row in &rows {
            for (k, &j) in rep_col.iter().enumerate() {
                matrix.push(if k == 0 { 0 } else { row[j] });
            }
        }
    } else {
        matrix.push(0);
    }
    let kern_columns = if rows.len() > 1 { cols.len() } else { 1 };
    // Masks and offsets.
    let mut mask_bytes = Vec::new();
    let mut offsets = Vec::new();
    let (mut ink_top, mut ink_bottom) = (i32::MAX, i32::MIN);
    let mut cache_code = 0usize;
    let mut max_box = (0u16, 0u16);
    for m in &made {
        for (p, (b, code)) in m.masks.iter().enumerate() {
            offsets.push(mask_bytes.len());
            mask_bytes.extend([
                b.left as i8 as u8,
                b.top as i8 as u8,
                b.width as u8,
                b.height as u8,
            ]);
            mask_bytes.extend(code);
            if b.width > 0 {
                ink_top = ink_top.min(i32::from(b.top));
                ink_bottom = ink_bottom.max(i32::from(b.top) + i32::from(b.height));
            }
            if p == 0 {
                cache_code += code.len();
            }
            max_box = (max_box.0.max(b.width + 3), max_box.1.max(b.height + 3));
        }
    }
    if ink_top > ink_bottom {
        (ink_top, ink_bottom) = (0, 0);
    }
    let long = mask_bytes.len() > usize::from(u16::MAX);
    let fine = |v: i64| v.clamp(-(1 << 30), 1 << 30) as i32;
    let line = LineMetrics {
        ascender: fine(scale.y_units(i32::from(font.ascender()))),
        descender: fine(scale.y_units(i32::from(font.descender()))),
        line_height: fine(scale.y_units(font.line_height())),
        ink_top,
        ink_bottom,
    };
    report.glyphs = n;
    report.mask_bytes = mask_bytes.len();
    report.offset_bytes = offsets.len() * if long { 4 } else { 2 };
    report.glyph_bytes = n * std::mem::size_of::<softedge::text::RasterGlyph>();
    report.char_bytes = ranges.len() * std::mem::size_of::<softedge::text::CharRange>();
    report.kern_bytes = matrix.len();
    report.kern_classes = (rows.len(), cols.len());
    report.flash_bytes = std::mem::size_of::<softedge::text::RasterFont<'static>>()
        + report.mask_bytes
        + report.offset_bytes
        + report.glyph_bytes
        + report.char_bytes
        + report.kern_bytes;
    report.cache_code_bytes = cache_code;
    report.max_box = max_box;

    // The source.
    let mut s = String::new();
    let k = &spec.crate_path;
    let px = f64::from(spec.size_64ths) / 64.0;
    let _ = writeln!(
        s,
        "// Generated by `softedge-sim font`: {}, {px} px, {} glyphs, {} phase(s), tolerance {} fine units{}.",
        spec.source_name,
        n,
        spec.phases,
        spec.tolerance.fine(),
        if spec.snap_x_height { ", x-height on the pixel grid" } else { "" }
    );
    if let Some(c) = copyright(&font) {
        let _ = writeln!(s, "// The font: {c}");
    }
    let _ = writeln!(s, "// Do not edit: run `softedge-sim font` again.");
    let _ = writeln!(s);
    let chars_doc: String = made
        .iter()
        .map(|m| m.ch)
        .filter(|c| !c.is_control())
        .collect();
    let _ = writeln!(
        s,
        "/// {} at {px} px, rasterized ahead of time ({} bytes of flash): `{}`",
        spec.source_name,
        report.flash_bytes,
        chars_doc.replace('`', "'")
    );
    let _ = writeln!(s, "#[rustfmt::skip]");
    let _ = writeln!(
        s,
        "pub static {}: {k}::text::RasterFont<'static> = {k}::text::RasterFont::new(",
        spec.name
    );
    let _ = writeln!(s, "    {k}::text::RasterMetrics {{");
    let _ = writeln!(s, "        size_64ths: {},", spec.size_64ths);
    let _ = writeln!(
        s,
        "        line: {k}::text::LineMetrics {{ ascender: {}, descender: {}, line_height: {}, ink_top: {}, ink_bottom: {} }},",
        line.ascender, line.descender, line.line_height, line.ink_top, line.ink_bottom
    );
    let _ = writeln!(s, "        phases: {},", spec.phases);
    let _ = writeln!(s, "        advance_shift: {advance_shift},");
    let _ = writeln!(s, "        kern_shift: {kern_shift},");
    let _ = writeln!(s, "        kern_columns: {kern_columns},");
    let _ = writeln!(s, "    }},");
    let _ = writeln!(s, "    &[");
    for (first, len, glyph) in &ranges {
        let _ = writeln!(
            s,
            "        {k}::text::CharRange {{ first: 0x{first:04x}, len: {len}, glyph: {glyph} }},"
        );
    }
    let _ = writeln!(s, "    ],");
    let _ = writeln!(s, "    &[");
    for (i, m) in made.iter().enumerate() {
        let half = (1i64 << advance_shift) / 2;
        let adv = ((m.advance.max(0) + half) >> advance_shift).min(i64::from(u16::MAX));
        let _ = writeln!(
            s,
            "        {k}::text::RasterGlyph {{ advance: {adv}, kern_left: {}, kern_right: {} }}, // {:?}",
            left[i], right[i], m.ch
        );
    }
    let _ = writeln!(s, "    ],");
    let _ = write!(
        s,
        "    {k}::text::MaskOffsets::{}(&[",
        if long { "Long" } else { "Short" }
    );
    write_numbers(&mut s, offsets.iter().map(|&o| o as i64));
    let _ = writeln!(s, "]),");
    let _ = write!(s, "    &[");
    write_numbers(&mut s, matrix.iter().map(|&k| i64::from(k)));
    let _ = writeln!(s, "],");
    let _ = write!(s, "    &[");
    write_numbers(&mut s, mask_bytes.iter().map(|&b| i64::from(b)));
    let _ = writeln!(s, "],");
    let _ = writeln!(s, ");");
    Ok((s, report))
}

/// Numbers, 24 a line.
fn write_numbers(s: &mut String, v: impl Iterator<Item = i64>) {
    for (i, x) in v.enumerate() {
        if i % 24 == 0 {
            s.push_str("\n        ");
        } else {
            s.push(' ');
        }
        let _ = write!(s, "{x},");
    }
    s.push_str("\n    ");
}

/// The font's copyright notice (name 0, the first one in UTF-16).
fn copyright(font: &Font<'_>) -> Option<String> {
    font.face()
        .names()
        .into_iter()
        .filter(|n| n.name_id == 0 && n.is_unicode())
        .find_map(|n| {
            let units: Vec<u16> = n
                .name
                .chunks_exact(2)
                .map(|b| u16::from_be_bytes([b[0], b[1]]))
                .collect();
            String::from_utf16(&units).ok()
        })
        .map(|s| s.replace(['\n', '\r'], " ").trim().to_string())
}
