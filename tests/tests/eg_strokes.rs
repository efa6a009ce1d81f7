//! Issue #34, item 2: embedded-graphics' primitives stroked with whole
//! pixels land on the pixels embedded-graphics lights. The reference is
//! embedded-graphics itself, drawing the same primitive with the same
//! `PrimitiveStyle` into a plain framebuffer: on axis-aligned edges every
//! pixel it lights is at full coverage in softedge, and every pixel it
//! leaves dark is empty (rectangles, the straight parts of rounded
//! rectangles, horizontal and vertical lines; widths 1 to 5; inside,
//! centre and outside).

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    CornerRadii, Line, PrimitiveStyle, PrimitiveStyleBuilder, Rectangle, RoundedRectangle,
    StrokeAlignment, Styled,
};
use softedge::draw::AaShape;
use softedge::prelude::*;
use softedge::{Band, BandBuffer};

const W: u16 = 48;
const H: u16 = 48;

/// embedded-graphics' pixels: a plain framebuffer.
struct Bits(Vec<bool>);

impl OriginDimensions for Bits {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(H))
    }
}

impl DrawTarget for Bits {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            if (0..i32::from(W)).contains(&p.x) && (0..i32::from(H)).contains(&p.y) {
                self.0[(p.y * i32::from(W) + p.x) as usize] = c.is_on();
            }
        }
        Ok(())
    }
}

/// What embedded-graphics lights for `p` styled with `style`.
fn eg_pixels<P>(p: P, style: PrimitiveStyle<BinaryColor>) -> Vec<bool>
where
    P: Primitive,
    Styled<P, PrimitiveStyle<BinaryColor>>: Drawable<Color = BinaryColor>,
{
    let mut bits = Bits(vec![false; usize::from(W) * usize::from(H)]);
    let _ = p.into_styled(style).draw(&mut bits);
    bits.0
}

/// softedge's linear values for `p` with `style` (white on black), in
/// bands of `rows` rows.
fn softedge_values<P: AaShape + Primitive + Copy>(
    p: P,
    style: AaStyle<'_, BinaryColor>,
    rows: u16,
) -> Vec<u16> {
    let mut out = vec![0u16; usize::from(W) * usize::from(H)];
    let mut y0 = 0;
    while y0 < H {
        let n = rows.min(H - y0);
        let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, n)];
        let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, n)];
        let mut buf =
            BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(W, i32::from(y0), n)).unwrap();
        buf.clear([0]);
        let mut canvas: Canvas<'_, '_, 1, BinaryColor> = Canvas::typed(&mut buf, None);
        p.into_styled(style).draw(&mut canvas).unwrap();
        assert_eq!(canvas.skipped().count, 0);
        for y in y0..y0 + n {
            for x in 0..W {
                out[usize::from(y) * usize::from(W) + usize::from(x)] =
                    buf.lin12(i32::from(x), i32::from(y)).unwrap()[0];
            }
        }
        y0 += n;
    }
    out
}

/// Every pixel `judged` keeps: lit by embedded-graphics → 4095, dark →
/// 0; the count of pixels compared.
fn compare(what: &str, eg: &[bool], se: &[u16], judged: impl Fn(i32, i32) -> bool) -> usize {
    let mut n = 0;
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            if !judged(x, y) {
                continue;
            }
            let k = (y * i32::from(W) + x) as usize;
            let want = if eg[k] { 4095 } else { 0 };
            assert_eq!(se[k], want, "{what}: pixel ({x}, {y}) {}", picture(eg, se));
            n += 1;
        }
    }
    n
}

/// Both pictures side by side, for a failure's message.
fn picture(eg: &[bool], se: &[u16]) -> String {
    let mut s = String::from("\nembedded-graphics | softedge (# whole, + part)\n");
    for y in 0..usize::from(H) {
        for x in 0..usize::from(W) {
            s.push(if eg[y * usize::from(W) + x] { '#' } else { '.' });
        }
        s.push_str(" | ");
        for x in 0..usize::from(W) {
            s.push(match se[y * usize::from(W) + x] {
                4095 => '#',
                0 => '.',
                _ => '+',
            });
        }
        s.push('\n');
    }
    s
}

const ALIGNMENTS: [StrokeAlignment; 3] = [
    StrokeAlignment::Inside,
    StrokeAlignment::Center,
    StrokeAlignment::Outside,
];

/// The e-g style and softedge's two ways to say it.
fn styles(
    w: u32,
    a: StrokeAlignment,
) -> (
    PrimitiveStyle<BinaryColor>,
    [AaStyle<'static, BinaryColor>; 2],
) {
    let eg = PrimitiveStyleBuilder::new()
        .stroke_color(BinaryColor::On)
        .stroke_width(w)
        .stroke_alignment(a)
        .build();
    let own = AaStyle::with_stroke(BinaryColor::On, w).stroke_alignment(a);
    (eg, [AaStyle::from(eg), own])
}

#[test]
fn rectangle_strokes_light_the_pixels_embedded_graphics_lights() {
    let rects = [
        Rectangle::new(Point::new(12, 10), Size::new(20, 15)),
        Rectangle::new(Point::new(14, 13), Size::new(1, 9)),
        Rectangle::new(Point::new(15, 14), Size::new(7, 1)),
        Rectangle::new(Point::new(16, 16), Size::new(2, 2)),
        Rectangle::new(Point::new(13, 11), Size::new(4, 11)),
    ];
    let mut n = 0;
    for r in rects {
        for w in 1..=5 {
            for a in ALIGNMENTS {
                let (eg, ours) = styles(w, a);
                let want = eg_pixels(r, eg);
                for (k, style) in ours.into_iter().enumerate() {
                    let got = softedge_values(r, style, 7);
                    let what = format!("{r:?} width {w} {a:?} style {k}");
                    n += compare(&what, &want, &got, |_, _| true);
                }
            }
        }
    }
    assert!(n > 60_000, "{n}");
}

#[test]
fn rounded_rectangle_straight_parts_light_the_pixels_embedded_graphics_lights() {
    let shapes = [
        RoundedRectangle::with_equal_corners(
            Rectangle::new(Point::new(10, 9), Size::new(26, 22)),
            Size::new(5, 5),
        ),
        RoundedRectangle::new(
            Rectangle::new(Point::new(12, 11), Size::new(21, 18)),
            CornerRadii {
                top_left: Size::new(3, 6),
                top_right: Size::new(7, 2),
                bottom_right: Size::new(1, 1),
                bottom_left: Size::new(4, 4),
            },
        ),
    ];
    let mut n = 0;
    for rr in shapes {
        let c = rr.confine_radii().corners;
        for w in 1..=5 {
            for a in ALIGNMENTS {
                let (eg, ours) = styles(w, a);
                let outside = match a {
                    StrokeAlignment::Inside => 0,
                    StrokeAlignment::Center => w as i32 / 2,
                    StrokeAlignment::Outside => w as i32,
                };
                // The straight parts: every pixel outside the four corner
                // boxes of the stroke's outer edge (its radii grow by
                // `outside` too, as embedded-graphics offsets them).
                let r = rr.rectangle;
                let (x0, y0) = (r.top_left.x - outside, r.top_left.y - outside);
                let (x1, y1) = (
                    r.top_left.x + r.size.width as i32 + outside,
                    r.top_left.y + r.size.height as i32 + outside,
                );
                let corner = |s: Size| (s.width as i32 + outside, s.height as i32 + outside);
                let (tl, tr, br, bl) = (
                    corner(c.top_left),
                    corner(c.top_right),
                    corner(c.bottom_right),
                    corner(c.bottom_left),
                );
                let judged = |x: i32, y: i32| {
                    !((x < x0 + tl.0 && y < y0 + tl.1)
                        || (x >= x1 - tr.0 && y < y0 + tr.1)
                        || (x >= x1 - br.0 && y >= y1 - br.1)
                        || (x < x0 + bl.0 && y >= y1 - bl.1))
                };
                let want = eg_pixels(rr, eg);
                for (k, style) in ours.into_iter().enumerate() {
                    let got = softedge_values(rr, style, 5);
                    let what = format!("{rr:?} width {w} {a:?} style {k}");
                    n += compare(&what, &want, &got, judged);
                }
            }
        }
    }
    assert!(n > 20_000, "{n}");
}

#[test]
fn horizontal_and_vertical_lines_light_the_pixels_embedded_graphics_lights() {
    let (a, b) = (Point::new(9, 20), Point::new(33, 20));
    let (c, d) = (Point::new(22, 8), Point::new(22, 37));
    let lines = [
        Line::new(a, b),
        Line::new(b, a),
        Line::new(c, d),
        Line::new(d, c),
        Line::new(Point::new(20, 20), Point::new(21, 20)),
        Line::new(Point::new(20, 20), Point::new(20, 21)),
    ];
    let mut n = 0;
    for l in lines {
        for w in 1..=5 {
            for al in ALIGNMENTS {
                let (eg, ours) = styles(w, al);
                let want = eg_pixels(l, eg);
                for (k, style) in ours.into_iter().enumerate() {
                    let got = softedge_values(l, style, 6);
                    let what = format!("{l:?} width {w} {al:?} style {k}");
                    n += compare(&what, &want, &got, |_, _| true);
                }
            }
        }
    }
    assert!(n > 60_000, "{n}");
}

/// Slanted edges are anti-aliased, not moved: a 45° line of width 1 is
/// smooth and keeps its area within 1 %.
#[test]
fn a_slanted_line_is_smooth_and_keeps_its_ink() {
    let l = Line::new(Point::new(10, 10), Point::new(34, 34));
    let got = softedge_values(l, AaStyle::with_stroke(BinaryColor::On, 1), 8);
    let partial = got.iter().filter(|&&v| v != 0 && v != 4095).count();
    assert!(partial > 20, "{partial}");
    let ink: f64 = got.iter().map(|&v| f64::from(v) / 4095.0).sum();
    // From pixel centre (10.5, 10.5) to (34.5, 34.5), the ends moved half
    // a pixel along x (and y): (10, 10) to (35, 35), width 1: 25 √2 px².
    let exact = 25.0 * 2f64.sqrt();
    assert!((ink / exact - 1.0).abs() < 0.01, "{ink} vs {exact}");
}

/// Circles follow the same rule: a centred 1-px stroke of
/// embedded-graphics' `Circle` lies inside the circle's bounding square,
/// as embedded-graphics' does (its ring between radii `d/2 - 1` and
/// `d/2`: that ring's exact area, within 0.5 %, and at most 1/1000 of a
/// pixel's light outside).
#[test]
fn a_centred_odd_circle_stroke_stays_in_the_bounding_square() {
    use embedded_graphics::primitives::Circle;
    for d in [9u32, 16, 30] {
        let c = Circle::new(Point::new(6, 7), d);
        let got = softedge_values(c, AaStyle::with_stroke(BinaryColor::On, 1), 9);
        let bb = c.bounding_box();
        let mut ink = 0.0;
        for y in 0..i32::from(H) {
            for x in 0..i32::from(W) {
                let v = got[(y * i32::from(W) + x) as usize];
                if !bb.contains(Point::new(x, y)) {
                    // The area-true polygon's vertices reach a hair out.
                    assert!(v <= 4, "diameter {d}: ({x}, {y}) outside the square: {v}");
                }
                ink += f64::from(v) / 4095.0;
            }
        }
        let r = f64::from(d) / 2.0;
        let exact = std::f64::consts::PI * (r * r - (r - 1.0) * (r - 1.0));
        assert!(
            (ink / exact - 1.0).abs() < 0.005,
            "diameter {d}: {ink} vs {exact}"
        );
    }
}
