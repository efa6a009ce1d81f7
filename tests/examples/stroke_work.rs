//! Issue #36, G3: the dashed strokes rendered through the
//! Renderer in 1-row bands, for measuring with callgrind:
//! `valgrind --tool=callgrind target/release/examples/stroke_work a [row]`
//! (`a` to `m` and `t`, the cases below: the frame in 1-row bands; with `row`, only that
//! band, through `render_window`; a third argument sets the frame's width).
//! Prints the frame's report.

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
    // A third argument: the frame's width instead (a display's, 240).
    let w = args.get(3).and_then(|w| w.parse().ok()).unwrap_or(w);
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
    let wide: Vec<FinePoint> = (0..250)
        .map(|i| FinePoint::new((i % 2) * 9 * 1024, i * 8 * 1024))
        .collect();
    let wide_zig = softedge::path::Polyline::new(&wide);
    let mut curves_d = String::from("M -2000 -2000");
    for k in 0.. {
        let s = if k % 2 == 0 { 1 } else { -1 };
        let c = format!(
            " C {} -1900 {} 1900 {} {}",
            2000 * s,
            -2000 * s,
            1990 * s,
            1990 - k * 90
        );
        if curves_d.len() + c.len() > 1024 {
            break;
        }
        curves_d += &c;
    }
    let curves = SvgPath::new(&curves_d).unwrap();
    let mut stairs_d = String::from("M8 8");
    while stairs_d.len() + 4 <= 1024 {
        stairs_d += "h1v1";
    }
    let stairs = SvgPath::new(&stairs_d).unwrap();
    let mut loops_d = String::from("M8 8");
    while loops_d.len() + 16 <= 1024 {
        loops_d += "c1 -1 -1 -1 0 1";
    }
    let loops = SvgPath::new(&loops_d).unwrap();
    let text = "W".repeat(1024);
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
            "j" => {
                // A 1 KiB scene's worth of polyline (250 points), round
                // joins, stroked 4 096 px wide: every join's arc crosses
                // the band.
                let s = StrokeStyle::new(4096 * 1024).with_join(LineJoin::Round);
                let _ = c.stroke_shape(&wide_zig, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "k" => {
                // 1 KiB of SVG: 28 cubic curves across the range, stroked
                // 4 096 px wide with round joins.
                let s = StrokeStyle::new(4096 * 1024).with_join(LineJoin::Round);
                let _ = c.stroke_shape(&curves, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "l" => {
                // 1 KiB of SVG: 512 drawing commands (`h1v1...`), round
                // joins and caps, 4 096 px wide.
                let s = StrokeStyle::new(4096 * 1024)
                    .with_join(LineJoin::Round)
                    .with_cap(LineCap::Round);
                let _ = c.stroke_shape(&stairs, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "m" => {
                // 1 KiB of SVG: 60 tiny cubic loops stroked 1 000 px wide
                // (every chord of them a rectangle, every join round).
                let s = StrokeStyle::new(1000 * 1024).with_join(LineJoin::Round);
                let _ = c.stroke_shape(&loops, &s, [4095; 3], Blend::Over, Opacity::OPAQUE);
            }
            "t" => {
                // Not a stroke: 1 KiB of text on one line (the bundled
                // 16-px font), most of it right of the frame.
                let style = softedge::text::AaTextStyle::new(
                    &softedge::text::bundled::SANS_16,
                    Rgb565::WHITE,
                );
                let _ = embedded_graphics::text::Text::new(&text, Point::new(0, 12), style).draw(c);
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
