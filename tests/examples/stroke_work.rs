//! Issue #36, G3: the dashed strokes rendered through the
//! Renderer in 1-row bands, for measuring with callgrind:
//! `valgrind --tool=callgrind target/release/examples/stroke_work a [row]`
//! (`a` to `i`, the cases below: the frame in 1-row bands; with `row`, only that
//! band, through `render_window`). Prints the frame's report.

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Rectangle;
use softedge::path::svg::SvgPath;
use softedge::path::{Circle, StrokeStyle};
use softedge::prelude::*;

struct Sink(u32, u32);
impl OriginDimensions for Sink {
    fn size(&self) -> Size {
        Size::new(self.0, self.1)
    }
}
impl DrawTarget for Sink {
    type Color = Rgb565;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<Rgb565>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for p in px {
            core::hint::black_box(p);
        }
        Ok(())
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args.get(1).map(String::as_str).unwrap_or("a");
    let row: Option<i32> = args.get(2).and_then(|r| r.parse().ok());
    let (w, h): (u16, u16) = match which {
        "a" => (4, 15),
        "h" => (5, 32),
        _ => (16, 16),
    };
    let fine = [3u32];
    let dots = [144u32, 0, 0];
    let long = [64u32];
    let path_a = SvgPath::new("M 2 2 C 900 -900 -900 900 2 13 S 2000 -40 1 8 Z").unwrap();
    let path_c = SvgPath::new("M -1000 8 C -300 -1500 300 1500 1000 8").unwrap();
    let path_d = SvgPath::new("M -40 8 L 60 8").unwrap();
    let circle = Circle::new(FinePoint::new(8 * 1024, 8 * 1024), 45 * 512);
    let short = [16u32];
    let ellipse = softedge::path::Ellipse::new(
        FinePoint::new(14 * 1024, 33 * 1024 + 512),
        4 * 1024,
        12 * 1024 + 512,
    );
    let zig_dash = [2000u32, 1];
    let zig: Vec<FinePoint> = (0..400)
        .map(|i| FinePoint::new((i % 2) * 3 * 1024, i * 40))
        .collect();
    let zigzag = softedge::path::Polyline::new(&zig);
    let draw = |c: &mut Canvas<'_, '_, 3, Rgb565>| -> Result<(), DrawError> {
        match which {
            "a" => {
                let s = StrokeStyle::new(22323)
                    .with_cap(LineCap::Round)
                    .with_dash(Dash::new(&fine, 0));
                let _ = c.stroke_shape(&path_a, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "b" => {
                let s = StrokeStyle::new(785 * 1024)
                    .with_cap(LineCap::Round)
                    .with_dash(Dash::new(&dots, 0));
                let _ = c.stroke_shape(&circle, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "c" => {
                let s = StrokeStyle::new(16 * 1024).with_dash(Dash::new(&long, 0));
                let _ = c.stroke_shape(&path_c, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "e" => {}
            "i" => {
                // An ellipse of semi-axes 2000 and 1900 px stroked 4096 px wide.
                let s = StrokeStyle::new(4096 * 1024);
                let big =
                    softedge::path::Ellipse::new(FinePoint::new(0, 0), 2000 * 1024, 1900 * 1024);
                let _ = c.stroke_shape(&big, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "h" => {
                // The renderer fuzz target's slow input: an 8x25-px
                // ellipse stroked 1 799 px wide (solid).
                let s = StrokeStyle::new(1_842_204);
                let _ = c.stroke_shape(&ellipse, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "f" => {
                // Round caps on a thin stroke: many small arcs.
                let s = StrokeStyle::new(2048)
                    .with_cap(LineCap::Round)
                    .with_dash(Dash::new(&fine, 0));
                let _ = c.stroke_shape(&path_a, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "g" => {
                // Round joins at every vertex of a zigzag, dashed finely.
                let s = StrokeStyle::new(2048)
                    .with_join(LineJoin::Round)
                    .with_dash(Dash::new(&zig_dash, 0));
                let _ = c.stroke_shape(&zigzag, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            _ => {
                // Every dash in every band: 1/64-px butt dashes across the
                // frame, 16 px wide.
                let s = StrokeStyle::new(16 * 1024).with_dash(Dash::new(&short, 0));
                let _ = c.stroke_shape(&path_d, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
        }
        Ok(())
    };
    let rows = 1;
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(w, rows)];
    let mut slots = [WalkSlot::<3>::EMPTY; 4];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, w, h, rows).unwrap();
    let mut sink = Sink(u32::from(w), u32::from(h));
    let format = Rgb565Format::new(Curve::Srgb);
    let report = match row {
        Some(y) => r.render_window(
            &mut sink,
            &format,
            Rgb565::BLACK,
            Rectangle::new(Point::new(0, y), Size::new(u32::from(w), 1)),
            draw,
        ),
        None => r.render(&mut sink, &format, Rgb565::BLACK, draw),
    };
    println!("{which} {row:?}: {:?}", report.map(|r| r.skipped));
}
