//! Depth triangles through every hidden-surface method (z-buffer in
//! bands, Warnock, Weiler–Atherton, section): no panic, and the same frame
//! (or the same error) for two band heights.
#![no_main]

use libfuzzer_sys::fuzz_target;
use softedge::hsr::{
    draw_warnock, draw_zbuffer, scratch_len, sort_front_to_back, DepthBuffer, DepthTriangle,
    HsrError, Section, VisibleSet,
};
use softedge::{Band, BandBuffer, PixelModel, RenderStyle};
use softedge_fuzz::{assert_band_invariant, Input};

#[derive(Clone, Copy)]
enum Method {
    ZBuffer,
    Warnock,
    Weiler,
    Section(u16),
}

/// The one use of the drawing API: the frame's triangles into one band by
/// `method` (`set`: Weiler–Atherton's pieces, computed once per frame).
fn draw(
    band: &mut BandBuffer<'_, 1>,
    info: Band,
    tris: &[DepthTriangle<1>],
    method: Method,
    style: &RenderStyle,
    set: &VisibleSet<256>,
) -> Result<(), HsrError> {
    match method {
        Method::ZBuffer => {
            let n = DepthBuffer::len(info.width, info.rows);
            let (mut depth, mut covered) = (vec![0u16; n], vec![0u16; 2 * n]);
            let mut zbuf = DepthBuffer::new(&mut depth, &mut covered, info).expect("valid band");
            draw_zbuffer(tris, band, &mut zbuf, style)
        }
        Method::Warnock => {
            let mut scratch = vec![0u16; scratch_len(tris.len())];
            draw_warnock(tris, band, &mut scratch).map(|_| ())
        }
        Method::Weiler => set.draw(tris, band, style),
        Method::Section(z) => {
            for t in tris {
                match t.section(z) {
                    Some(Section::Segment(l)) => l.draw(band, style)?,
                    Some(Section::Face) => t.triangle().draw(band, style)?,
                    None => {}
                }
            }
            Ok(())
        }
    }
}

fuzz_target!(|data: &[u8]| {
    let mut inp = Input::new(data);
    let (w, h) = (inp.side(64), inp.side(48));
    let method = match inp.u8() % 4 {
        0 => Method::ZBuffer,
        1 => Method::Warnock,
        2 => Method::Weiler,
        _ => Method::Section(inp.u16()),
    };
    let style = RenderStyle {
        antialias: !inp.u8().is_multiple_of(4),
        model: if inp.u8().is_multiple_of(6) {
            PixelModel::BedOfNails4
        } else {
            PixelModel::Box
        },
    };
    let background = [inp.lin12()];
    let (rows_a, rows_b) = (inp.side(h), inp.side(h));
    let mut tris = Vec::new();
    while !inp.is_empty() && tris.len() < 24 {
        // Depths: often equal or close (coplanar and interpenetrating
        // triangles are the hard cases).
        let base = inp.u16();
        let z = |inp: &mut Input| match inp.u8() % 4 {
            0 => base,
            1 => base.wrapping_add(u16::from(inp.u8())),
            _ => inp.u16(),
        };
        tris.push(DepthTriangle::new(
            [inp.point(w, h), inp.point(w, h), inp.point(w, h)],
            [inp.color(), inp.color(), inp.color()],
            [z(&mut inp), z(&mut inp), z(&mut inp)],
        ));
    }
    sort_front_to_back(&mut tris);
    let mut set = Box::new(VisibleSet::<256>::new());
    if let Method::Weiler = method {
        if let Err(e) = set.compute(&tris) {
            assert!(set.pieces().is_empty(), "{e:?}: set not emptied");
            return;
        }
    }
    let _ = assert_band_invariant(w, h, rows_a, rows_b, background, |band, info| {
        draw(band, info, &tris, method, &style, &set)
    });
});
