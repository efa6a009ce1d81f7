//! `[[image]]`: a PNG, QOI or BMP file (relative to the scene file) drawn
//! with softedge's `AaImage`: `center` (px, where the image's centre
//! lands, to the fine grid, 1/1024 px), `scale` (a number or `[sx, sy]`,
//! default 1, to 1/65536, within `1/16..=256`), `rotate` (degrees
//! clockwise on screen about the centre, default 0, to 1/65536 degree),
//! `opacity` (default 1, to 1/4096) and `tint` (a colour: the image's
//! alpha, or luminance for an opaque image, as a mask of it).

use softedge::geom::{FinePoint, FINE_ONE};
use softedge::image::Scale;
use softedge::path::Degrees;
use softedge::style::Opacity;
use softedge::COORD_LIMIT_PX;

use super::{raw, Checked, Checker, Origin};
use crate::image_item::{decode, ImageItem};
use crate::scene::Primitive;

/// The `[[image]]` tables, each at its place in the file.
pub(super) fn images<const C: usize>(
    ck: &mut Checker<'_>,
    file: &raw::File,
) -> Checked<Vec<(Origin, Vec<Primitive<C>>)>> {
    let mut out = Vec::new();
    for (k, t) in file.image.iter().enumerate() {
        let field = format!("image[{k}]");
        let tr = t.get_ref();
        let lim = f64::from(COORD_LIMIT_PX);
        let [x, y] = ck.nums::<2>(&tr.center, &format!("{field}.center"), -lim, lim)?;
        let fine = |v: f64| (v * f64::from(FINE_ONE)).round() as i32;
        let dir = ck.src.path.parent().unwrap_or(std::path::Path::new(""));
        let path = dir.join(tr.path.get_ref());
        let bytes = match std::fs::read(&path) {
            Ok(b) => b,
            Err(e) => {
                return ck.err(
                    tr.path.span(),
                    &format!("{field}.path"),
                    format!("cannot read {}: {e}", path.display()),
                )
            }
        };
        let image = match decode(&bytes) {
            Ok(i) => i,
            Err(e) => return ck.err(tr.path.span(), &format!("{field}.path"), e),
        };
        let (min, max) = (1.0 / 16.0, 256.0);
        let scale = match &tr.scale {
            None => (1.0, 1.0),
            Some(s) => {
                let (a, b) = match *s.get_ref() {
                    raw::ScaleValue::One(v) => (v, v),
                    raw::ScaleValue::Two([a, b]) => (a, b),
                };
                for v in [a, b] {
                    if !(min..=max).contains(&v) {
                        return ck.err(
                            s.span(),
                            &format!("{field}.scale"),
                            format!("{v} is outside 1/16..=256"),
                        );
                    }
                }
                (a, b)
            }
        };
        let q16 = |v: f64| Scale::from_bits((v * 65536.0).round() as u32);
        let rotate = match &tr.rotate {
            Some(r) => ck.num(r, &format!("{field}.rotate"), -32767.0, 32767.0)?,
            None => 0.0,
        };
        let opacity = match &tr.opacity {
            Some(o) => {
                let a = ck.num(o, &format!("{field}.opacity"), 0.0, 1.0)?;
                Opacity::from_4096ths((a * 4096.0).round() as u16)
            }
            None => Opacity::OPAQUE,
        };
        let tint = match &tr.tint {
            Some(c) => Some(ck.color::<C>(c, &format!("{field}.tint"))?),
            None => None,
        };
        let item = ImageItem {
            image,
            center: FinePoint::new(fine(x), fine(y)),
            scale: (q16(scale.0), q16(scale.1)),
            rotate: Degrees::from_bits((rotate * 65536.0).round() as i32),
            opacity,
            tint,
        };
        out.push((
            Origin {
                field,
                span: t.span(),
            },
            vec![Primitive::Image(Box::new(item))],
        ));
    }
    Ok(out)
}
