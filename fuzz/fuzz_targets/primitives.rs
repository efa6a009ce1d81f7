//! Triangles, polygons and lines, with any vertices and colours, under
//! every pixel model: no panic, and the same frame for two band heights.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::{
    BandBuffer, DrawError, Line, Polygon, PolygonColors, RenderStyle, SubPoint, Triangle,
};
use softedge_fuzz::{assert_band_invariant, FrameSetup, Input};

enum Shape {
    Triangle(Triangle<1>),
    Polygon(Vec<SubPoint>, Vec<[u16; 1]>, bool),
    Line(Line<1>),
}

/// The one use of the drawing API: the shapes, in order, into one band.
fn draw(
    band: &mut BandBuffer<'_, 1>,
    shapes: &[Shape],
    style: &RenderStyle,
) -> Result<(), DrawError> {
    for s in shapes {
        // A rejected primitive is a documented result; keep drawing the
        // others so that later ones are exercised too.
        let _ = match s {
            Shape::Triangle(t) => t.draw(band, style),
            Shape::Polygon(v, c, flat) => {
                let colors = if *flat {
                    PolygonColors::Flat(c[0])
                } else {
                    PolygonColors::PerVertex(c)
                };
                Polygon::new(v, colors).draw(band, style)
            }
            Shape::Line(l) => l.draw(band, style),
        };
    }
    Ok(())
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let FrameSetup {
        w,
        h,
        style,
        background,
        rows: (rows_a, rows_b),
    } = inp.frame_setup();
    let mut shapes = Vec::new();
    while !inp.is_empty() && shapes.len() < 12 {
        shapes.push(match inp.u8() % 3 {
            0 => Shape::Triangle(Triangle::new(
                [inp.point(w, h), inp.point(w, h), inp.point(w, h)],
                [inp.color(), inp.color(), inp.color()],
            )),
            1 => {
                let n = 1 + usize::from(inp.u8() % 70);
                let v: Vec<SubPoint> = (0..n).map(|_| inp.point(w, h)).collect();
                // Sometimes a wrong colour count (must be ColorCount).
                let m = if inp.u8() == 0 { n + 1 } else { n };
                let c: Vec<[u16; 1]> = (0..m).map(|_| inp.color()).collect();
                Shape::Polygon(v, c, inp.bool())
            }
            _ => Shape::Line(Line::new(
                inp.point(w, h),
                inp.point(w, h),
                [inp.color(), inp.color()],
            )),
        });
    }
    let _ = assert_band_invariant(w, h, rows_a, rows_b, background, |band, _| {
        draw(band, &shapes, &style)
    });
});
