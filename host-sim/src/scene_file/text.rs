//! `[[text]]`: a string in an outline font at an anchor (see
//! `softedge::text`): the font file read relative to the scene file (the
//! bundled Softedge Sans Subset by default), the position to the fine grid
//! (1/1024 px, nearest), the size to 1/64 px, the rest as named.

use std::sync::Arc;

use softedge::geom::{FinePoint, FINE_ONE};
use softedge::style::Opacity;
use softedge::text::{Alignment, Baseline, Font, LineHeight, Sharpen, TextSize, TextStyle};
use softedge::COORD_LIMIT_PX;

use super::{raw, Checked, Checker, Origin};
use crate::scene::Primitive;
use crate::text_item::TextItem;

/// `font` errors in words.
fn font_error(e: softedge::text::FontError) -> String {
    format!("not a usable font: {e}")
}

/// The `[[text]]` tables, each at its place in the file.
pub(super) fn texts<const C: usize>(
    ck: &mut Checker<'_>,
    file: &raw::File,
) -> Checked<Vec<(Origin, Vec<Primitive<C>>)>> {
    let mut out = Vec::new();
    for (k, t) in file.text.iter().enumerate() {
        let field = format!("text[{k}]");
        let tr = t.get_ref();
        let lim = f64::from(COORD_LIMIT_PX);
        let [x, y] = ck.nums::<2>(&tr.position, &format!("{field}.position"), -lim, lim)?;
        let fine = |v: f64| (v * f64::from(FINE_ONE)).round() as i32;
        let size = ck.num(&tr.size, &format!("{field}.size"), 1.0, 2048.0)?;
        let font: Arc<[u8]> = match &tr.font {
            None => TextItem::<C>::bundled_font(),
            Some(name) => {
                let dir = ck.src.path.parent().unwrap_or(std::path::Path::new(""));
                let path = dir.join(name.get_ref());
                match std::fs::read(&path) {
                    Ok(bytes) => Arc::from(bytes),
                    Err(e) => {
                        return ck.err(
                            name.span(),
                            &format!("{field}.font"),
                            format!("cannot read {}: {e}", path.display()),
                        )
                    }
                }
            }
        };
        if let Err(e) = Font::new(&font) {
            let span = tr.font.as_ref().map_or(t.span(), |f| f.span());
            return ck.err(span, &format!("{field}.font"), font_error(e));
        }
        let alignment = match tr.align.as_ref().map(|a| (a.get_ref().as_str(), a.span())) {
            None | Some(("left", _)) => Alignment::Left,
            Some(("center", _)) => Alignment::Center,
            Some(("right", _)) => Alignment::Right,
            Some((other, span)) => {
                return ck.err(
                    span,
                    &format!("{field}.align"),
                    format!("unknown alignment `{other}`, expected left, center or right"),
                )
            }
        };
        let baseline = match tr
            .baseline
            .as_ref()
            .map(|b| (b.get_ref().as_str(), b.span()))
        {
            None | Some(("alphabetic", _)) => Baseline::Alphabetic,
            Some(("top", _)) => Baseline::Top,
            Some(("middle", _)) => Baseline::Middle,
            Some(("bottom", _)) => Baseline::Bottom,
            Some((other, span)) => {
                return ck.err(
                    span,
                    &format!("{field}.baseline"),
                    format!(
                        "unknown baseline `{other}`, expected alphabetic, top, middle or bottom"
                    ),
                )
            }
        };
        let sharpen = match tr
            .sharpen
            .as_ref()
            .map(|s| (s.get_ref().as_str(), s.span()))
        {
            None | Some(("none", _)) => Sharpen::NONE,
            Some(("vertical", _)) => Sharpen::VERTICAL,
            Some(("grid", _)) => Sharpen::GRID,
            Some((other, span)) => {
                return ck.err(
                    span,
                    &format!("{field}.sharpen"),
                    format!("unknown sharpening `{other}`, expected none, vertical or grid"),
                )
            }
        };
        let line_height = match &tr.line_height {
            None => LineHeight::Percent(100),
            Some(h) => {
                let pct = ck.num(h, &format!("{field}.line_height"), 0.0, 10.0)?;
                LineHeight::Percent((pct * 100.0).round() as u32)
            }
        };
        let color = match &tr.color {
            Some(c) => ck.color::<C>(c, &format!("{field}.color"))?,
            None => [softedge::LIN_MAX; C],
        };
        let opacity = match &tr.opacity {
            Some(o) => {
                let a = ck.num(o, &format!("{field}.opacity"), 0.0, 1.0)?;
                Opacity::from_4096ths((a * 4096.0).round() as u16)
            }
            None => Opacity::OPAQUE,
        };
        let size = TextSize::from_64ths((size * 64.0).round() as u32);
        let Ok(mut item) = TextItem::new(
            font,
            tr.text.get_ref(),
            FinePoint::new(fine(x), fine(y)),
            size,
            color,
        ) else {
            return ck.err(t.span(), &field, "the font does not parse");
        };
        item.layout = TextStyle::new(alignment, baseline, line_height);
        item.opacity = opacity;
        item.sharpen = sharpen;
        out.push((
            Origin {
                field,
                span: t.span(),
            },
            vec![Primitive::Text(Box::new(item))],
        ));
    }
    Ok(out)
}
