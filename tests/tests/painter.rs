//! Painter's order ("over"), opacity and meshes composed as one shape,
//! against an independent reference: each pixel's exact covered area
//! (polygons clipped to the pixel in `f64`, exact for vertices on the
//! 1/1024-px grid to far below the tolerances) and the real-number over
//! `acc (1 - c a) + I c a`, applied shape by shape.

use embedded_graphics::mono_font::{ascii::FONT_6X10, MonoTextStyle};
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{
    PrimitiveStyle, PrimitiveStyleBuilder, Rectangle, StrokeAlignment,
};
use embedded_graphics::text::Text;
use proptest::prelude::*;
use softedge::canvas::{Contour, MeshColors};
use softedge::geom::FinePoint;
use softedge::prelude::*;
use softedge::{RenderStyle, SubPoint, Triangle, COVER_ONE};
use softedge_tests::frame::{render, render_canvas, render_canvas_of};

const ONE: f64 = 1024.0;

/// The area of convex polygon `poly` (px) inside pixel `(i, j)`.
fn pixel_area(poly: &[(f64, f64)], i: i32, j: i32) -> f64 {
    let (x0, y0) = (f64::from(i), f64::from(j));
    let mut p: Vec<(f64, f64)> = poly.to_vec();
    // Sutherland–Hodgman against the four sides.
    let sides: [(f64, f64, f64); 4] = [
        (1.0, 0.0, x0),
        (-1.0, 0.0, -(x0 + 1.0)),
        (0.0, 1.0, y0),
        (0.0, -1.0, -(y0 + 1.0)),
    ];
    for (a, b, c) in sides {
        let inside = |q: (f64, f64)| a * q.0 + b * q.1 >= c;
        let mut out = Vec::new();
        for k in 0..p.len() {
            let (s, e) = (p[k], p[(k + 1) % p.len()]);
            let (si, ei) = (inside(s), inside(e));
            if si {
                out.push(s);
            }
            if si != ei {
                let (fs, fe) = (a * s.0 + b * s.1 - c, a * e.0 + b * e.1 - c);
                let t = fs / (fs - fe);
                out.push((s.0 + t * (e.0 - s.0), s.1 + t * (e.1 - s.1)));
            }
        }
        p = out;
        if p.is_empty() {
            return 0.0;
        }
    }
    let mut a = 0.0;
    for k in 0..p.len() {
        let (s, e) = (p[k], p[(k + 1) % p.len()]);
        a += s.0 * e.1 - e.0 * s.1;
    }
    (a / 2.0).abs()
}

fn px(p: FinePoint) -> (f64, f64) {
    (f64::from(p.x) / ONE, f64::from(p.y) / ONE)
}

/// A convex quadrilateral around `(cx, cy)` (px) with corners at the
/// given angles and radii, on the fine grid.
fn quad(cx: f64, cy: f64, corners: [(f64, f64); 4]) -> [FinePoint; 4] {
    let mut angles = corners;
    angles.sort_by(|a, b| a.0.total_cmp(&b.0));
    angles.map(|(t, r)| {
        FinePoint::new(
            ((cx + r * t.cos()) * ONE).round() as i32,
            ((cy + r * t.sin()) * ONE).round() as i32,
        )
    })
}

fn corners() -> impl Strategy<Value = [(f64, f64); 4]> {
    // Angles a quarter turn apart, jittered: convex, not degenerate.
    (
        0.0..1.2f64,
        2.0..9.0f64,
        2.0..9.0f64,
        2.0..9.0f64,
        2.0..9.0f64,
    )
        .prop_map(|(t, a, b, c, d)| {
            let q = std::f64::consts::FRAC_PI_2;
            [(t, a), (t + q, b), (t + 2.0 * q, c), (t + 3.0 * q, d)]
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Two overlapping opaque flat shapes: the top one's colour where it
    /// covers the pixel, the bottom one's where only it does, the
    /// background where neither does, and the coverage-weighted over at
    /// edge pixels within 1/256 of full scale + 1 LSB.
    #[test]
    fn two_opaque_shapes_compose_in_painters_order(
        a in corners(), b in corners(),
        ca in (5.0..15.0f64, 5.0..15.0f64), cb in (5.0..15.0f64, 5.0..15.0f64),
        ia in 0u16..=4095, ib in 0u16..=4095, bg in 0u16..=4095,
        rows in prop::sample::select(vec![1u16, 3, 16]),
    ) {
        let (qa, qb) = (quad(ca.0, ca.1, a), quad(cb.0, cb.1, b));
        let f = render_canvas::<1>(20, 20, rows, [bg], 4, |c| {
            c.fill(&Contour(&qa), [ia], FillRule::NonZero, Blend::Over, Opacity::OPAQUE).unwrap();
            c.fill(&Contour(&qb), [ib], FillRule::NonZero, Blend::Over, Opacity::OPAQUE).unwrap();
        });
        let (pa, pb): (Vec<_>, Vec<_>) = (qa.iter().map(|&p| px(p)).collect(), qb.iter().map(|&p| px(p)).collect());
        for j in 0..20 {
            for i in 0..20 {
                let (sa, sb) = (pixel_area(&pa, i, j), pixel_area(&pb, i, j));
                let got = f.lin_at(i, j)[0];
                let want = (f64::from(bg) * (1.0 - sa) + f64::from(ia) * sa) * (1.0 - sb) + f64::from(ib) * sb;
                let full = |s: f64| s > 1.0 - 1e-12;
                let none = |s: f64| s < 1e-12;
                if full(sb) {
                    prop_assert_eq!(got, ib, "({}, {}) under the top shape", i, j);
                } else if full(sa) && none(sb) {
                    prop_assert_eq!(got, ia, "({}, {}) only the bottom shape", i, j);
                } else if none(sa) && none(sb) {
                    prop_assert_eq!(got, bg, "({}, {}) background", i, j);
                } else {
                    let err = (f64::from(got) - want).abs();
                    prop_assert!(err <= 4095.0 / 256.0 + 1.0, "({}, {}): {} vs {:.3}", i, j, got, want);
                    // What the engine actually achieves: its per-pixel
                    // coverage is exact to 2/65536 and rounds once.
                    prop_assert!(err <= 0.5 + 2.0 * 4095.0 / 65536.0 + 1e-9, "({}, {}): {} vs {:.3}", i, j, got, want);
                }
            }
        }
    }

    /// Opacity 0.5 over a background is the linear midpoint, within 1 LSB,
    /// per channel.
    #[test]
    fn half_opacity_is_the_linear_midpoint(
        bg in prop::array::uniform3(0u16..=4095), col in prop::array::uniform3(0u16..=4095),
    ) {
        let p = |x, y| FinePoint::from_px(x, y);
        let square = [p(2, 2), p(10, 2), p(10, 9), p(2, 9)];
        let f = render_canvas::<3>(12, 12, 5, bg, 0, |c| {
            c.fill(&Contour(&square), col, FillRule::NonZero, Blend::Over, Opacity::from_percent(50)).unwrap();
        });
        for j in 2..9 {
            for i in 2..10 {
                let got = f.lin_at(i, j);
                for ch in 0..3 {
                    let mid = (f64::from(bg[ch]) + f64::from(col[ch])) / 2.0;
                    prop_assert!((f64::from(got[ch]) - mid).abs() <= 1.0, "{:?} over {:?}: {:?}", col, bg, got);
                }
            }
        }
        prop_assert_eq!(f.lin_at(0, 0), bg);
    }

    /// A square drawn as a mesh of 2 or of 64 triangles equals the square
    /// drawn as one polygon, bit for bit, in both modes (any opacity over;
    /// opaque add, where each triangle is its own shape), with vertices
    /// on the 1/16-px grid of scene files and `SubPoint`s.
    #[test]
    fn a_square_as_a_mesh_equals_the_square(
        x0 in 16..64i32, y0 in 16..64i32, w in 16..190i32, h in 16..190i32,
        col in prop::array::uniform3(0u16..=4095), bg in prop::array::uniform3(0u16..=4095),
        alpha in 0u16..=4096, rows in prop::sample::select(vec![1u16, 4, 20]),
    ) {
        let d = mesh_vs_square([x0, y0, w, h].map(|v| v * 64), 64, col, bg, Opacity::from_4096ths(alpha), rows);
        prop_assert_eq!(d, (0, 0));
    }

    /// On the 1/1024-px grid the edges the mesh splits (its outline's
    /// vertices between the square's corners, here at least a pixel
    /// apart) round once per piece: the pixels they cross stay within two
    /// units of 1/65536 px, and one level of the result.
    #[test]
    fn a_square_as_a_fine_mesh_is_within_rounding_of_the_square(
        x0 in 1024..4096i32, y0 in 1024..4096i32, w in 4096..15_000i32, h in 8192..15_000i32,
        col in prop::array::uniform3(0u16..=4095), bg in prop::array::uniform3(0u16..=4095),
        alpha in 0u16..=4096, rows in prop::sample::select(vec![1u16, 4, 20]),
    ) {
        let (units, levels) = mesh_vs_square([x0, y0, w, h], 1, col, bg, Opacity::from_4096ths(alpha), rows);
        prop_assert!(units <= 2 && levels <= 1, "{} units, {} levels", units, levels);
    }

    /// Add mode through the canvas gives the frames of the seed-000
    /// accumulation (the legacy `Triangle::draw`) bit for bit.
    #[test]
    fn add_mode_is_the_legacy_accumulation(
        v in prop::array::uniform3((0..320i32, 0..320i32)),
        c in prop::array::uniform3(prop::array::uniform3(0u16..=4095)),
        bg in prop::array::uniform3(0u16..=4095),
        rows in prop::sample::select(vec![1u16, 7, 20]),
    ) {
        let sub = v.map(|(x, y)| SubPoint::new(x, y));
        let fine = sub.map(FinePoint::from);
        let legacy = render::<3>(20, 20, rows, bg, |buf| {
            let _ = Triangle::new(sub, c).draw(buf, &RenderStyle::default());
        });
        let canvas = render_canvas::<3>(20, 20, rows, bg, 0, |cv| {
            let _ = cv.fill_triangle(fine, c, Blend::Add, Opacity::OPAQUE);
        });
        prop_assert_eq!(first_diff(&legacy.raw, &canvas.raw), None);
    }
}

/// The first pixel (index, both values) where two frames differ.
fn first_diff<T: PartialEq + Copy>(a: &[T], b: &[T]) -> Option<(usize, T, T)> {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .enumerate()
        .find(|(_, (x, y))| x != y)
        .map(|(k, (&x, &y))| (k, x, y))
}

/// The square `[x0, x0 + w) x [y0, y0 + h)` (fine units) as one polygon
/// and as meshes of 2 and 64 triangles (points rounded to multiples of
/// `q`), over and add: the largest difference of the raw accumulators in
/// coverage units (the raw difference over `|I - bg|`) and of the 12-bit
/// results.
fn mesh_vs_square(
    [x0, y0, w, h]: [i32; 4],
    q: i32,
    col: [u16; 3],
    bg: [u16; 3],
    opacity: Opacity,
    rows: u16,
) -> (i64, i32) {
    let (x1, y1) = (x0 + w, y0 + h);
    let square = [
        FinePoint::new(x0, y0),
        FinePoint::new(x1, y0),
        FinePoint::new(x1, y1),
        FinePoint::new(x0, y1),
    ];
    // An (n+1) x (m+1) grid of points, two triangles per cell.
    let grid = |n: i32, m: i32| {
        let mut pts = Vec::new();
        for b in 0..=m {
            for a in 0..=n {
                pts.push(FinePoint::new(
                    x0 + (w * a / n) / q * q,
                    y0 + (h * b / m) / q * q,
                ));
            }
        }
        let mut tris = Vec::new();
        let at = |a: i32, b: i32| (b * (n + 1) + a) as u16;
        for b in 0..m {
            for a in 0..n {
                tris.push([at(a, b), at(a + 1, b), at(a + 1, b + 1)]);
                tris.push([at(a, b), at(a + 1, b + 1), at(a, b + 1)]);
            }
        }
        (pts, tris)
    };
    let scale = col
        .iter()
        .zip(bg)
        .map(|(&c, b)| (i64::from(c) - i64::from(b)).abs())
        .max()
        .unwrap_or(0)
        .max(1);
    let mut worst = (0i64, 0i32);
    let mut compare = |a: &softedge_tests::frame::Frame<3>, b: &softedge_tests::frame::Frame<3>| {
        for (ra, rb) in a.raw.iter().zip(&b.raw) {
            for ch in 0..3 {
                let d = (i64::from(ra[ch]) - i64::from(rb[ch])).abs();
                worst.0 = worst.0.max((d + scale - 1) / scale);
            }
        }
        for (la, lb) in a.lin12.iter().zip(&b.lin12) {
            for ch in 0..3 {
                worst.1 = worst.1.max((i32::from(la[ch]) - i32::from(lb[ch])).abs());
            }
        }
    };
    for (n, m) in [(1, 1), (4, 8)] {
        let (pts, tris) = grid(n, m);
        assert_eq!(tris.len(), (2 * n * m) as usize);
        for (blend, op) in [(Blend::Over, opacity), (Blend::Add, Opacity::OPAQUE)] {
            let whole = render_canvas::<3>(20, 20, rows, bg, 0, |c| {
                c.fill(&Contour(&square), col, FillRule::NonZero, blend, op)
                    .unwrap();
            });
            let mesh = render_canvas::<3>(20, 20, rows, bg, 8, |c| {
                c.fill_mesh(&pts, &tris, MeshColors::Flat(col), blend, op)
                    .unwrap();
            });
            compare(&whole, &mesh);
            if blend == Blend::Add {
                // Triangle by triangle, each its own shape.
                let each = render_canvas::<3>(20, 20, rows, bg, 0, |c| {
                    for t in &tris {
                        let v = t.map(|k| pts[usize::from(k)]);
                        c.fill_triangle(v, [col; 3], Blend::Add, Opacity::OPAQUE)
                            .unwrap();
                    }
                });
                compare(&whole, &each);
            }
        }
    }
    worst
}

#[test]
fn coverage_units_are_the_documented_ones() {
    assert_eq!(COVER_ONE, 1 << 16);
}

/// embedded-graphics' own drawings (text in a mono font, aliased
/// primitives) go into the canvas as opaque pixels in painter's order:
/// under a later anti-aliased shape, over an earlier one.
#[test]
fn embedded_graphics_drawings_compose_in_painters_order() {
    let grey = Rgb888::new(128, 128, 128);
    let f = render_canvas_of::<3, Rgb888>(40, 20, 3, [0; 3], 0, |c| {
        // A grey backdrop, white text and an aliased 1-px frame over it,
        // a half-transparent red bar over the text's lower half.
        Rectangle::new(Point::new(0, 0), Size::new(40, 20))
            .into_styled(AaStyle::with_fill(grey))
            .draw(c)
            .unwrap();
        Text::new(
            "Hi",
            Point::new(2, 8),
            MonoTextStyle::new(&FONT_6X10, Rgb888::WHITE),
        )
        .draw(c)
        .unwrap();
        Rectangle::new(Point::new(20, 0), Size::new(20, 20))
            .into_styled(PrimitiveStyle::with_stroke(Rgb888::BLUE, 1))
            .draw(c)
            .unwrap();
        Rectangle::new(Point::new(0, 6), Size::new(40, 14))
            .into_styled(AaStyle::with_fill(Rgb888::RED).opacity(Opacity::from_percent(50)))
            .draw(c)
            .unwrap();
    });
    let g = softedge::color::IntoLinear::<3>::into_linear(grey);
    // Text pixels above the bar are white; the backdrop is grey.
    let lit = (0..6)
        .flat_map(|y| (0..14).map(move |x| (x, y)))
        .filter(|&(x, y)| f.lin_at(x, y) == [4095; 3])
        .count();
    assert!(lit >= 4, "{lit} text pixels above the bar");
    assert_eq!(f.lin_at(15, 2), g);
    assert_eq!(f.lin_at(30, 0), [0, 0, 4095]);
    // The bar over the grey, the blue frame and the text: linear midpoints.
    let mid = |a: [u16; 3], b: [u16; 3]| {
        a.map(|v| v as i32)
            .iter()
            .zip(b)
            .map(|(&v, w)| (v + i32::from(w)) / 2)
            .collect::<Vec<_>>()
    };
    let near = |got: [u16; 3], want: Vec<i32>| {
        got.iter()
            .zip(&want)
            .all(|(&g, &w)| (i32::from(g) - w).abs() <= 1)
    };
    assert!(
        near(f.lin_at(15, 15), mid([4095, 0, 0], g)),
        "{:?}",
        f.lin_at(15, 15)
    );
    assert!(
        near(f.lin_at(39, 15), mid([4095, 0, 0], [0, 0, 4095])),
        "{:?}",
        f.lin_at(39, 15)
    );
    let under_text = (6..10)
        .flat_map(|y| (0..14).map(move |x| (x, y)))
        .filter(|&(x, y)| near(f.lin_at(x, y), mid([4095, 0, 0], [4095; 3])))
        .count();
    assert!(under_text >= 2, "{under_text} text pixels under the bar");
}

/// A styled embedded-graphics rectangle (fill and an inside or outside
/// stroke of whole pixels) covers exactly the pixels embedded-graphics'
/// own aliased drawing does: moving to softedge changes the style, not
/// the geometry.
#[test]
fn whole_pixel_rectangles_match_embedded_graphics_exactly() {
    for (align, width) in [
        (StrokeAlignment::Inside, 2),
        (StrokeAlignment::Outside, 3),
        (StrokeAlignment::Center, 2),
    ] {
        let eg_style = PrimitiveStyleBuilder::new()
            .fill_color(Rgb888::GREEN)
            .stroke_color(Rgb888::RED)
            .stroke_width(width)
            .stroke_alignment(align)
            .build();
        let rect = Rectangle::new(Point::new(5, 4), Size::new(12, 9));
        let aa = render_canvas_of::<3, Rgb888>(24, 20, 4, [0; 3], 0, |c| {
            rect.into_styled(AaStyle::from(eg_style)).draw(c).unwrap();
        });
        let aliased = render_canvas_of::<3, Rgb888>(24, 20, 4, [0; 3], 0, |c| {
            rect.into_styled(eg_style).draw(c).unwrap();
        });
        assert_eq!(aa.lin12, aliased.lin12, "{align:?} {width}");
    }
}

/// "Add" honours the fill rule and the stroke's "one shape": an outline
/// wound many times covers a pixel once (it used to multiply the colour
/// by the winding number, overflowing `i32` in debug builds and wrapping
/// to garbage in release), and a stroke whose pieces overlap (a U-turn)
/// adds its colour once where they do. Reference: a 4x4-px square at
/// whole pixels covers its 16 pixels fully and nothing else; on a black
/// background, add and opaque over give the same accumulator.
#[test]
fn add_covers_a_pixel_once_whatever_the_winding() {
    let p = |x, y| FinePoint::from_px(x, y);
    let square = [p(2, 2), p(6, 2), p(6, 6), p(2, 6)];
    let wound: Vec<FinePoint> = (0..9).flat_map(|_| square).collect();
    for rule in [FillRule::NonZero, FillRule::EvenOdd] {
        let f = render_canvas::<1>(8, 8, 3, [0], 0, |c| {
            c.fill(&Contour(&wound), [3000], rule, Blend::Add, Opacity::OPAQUE)
                .unwrap();
        });
        for y in 0..8 {
            for x in 0..8 {
                let inside = (2..6).contains(&x) && (2..6).contains(&y);
                // Wound 9 times: odd, so even-odd fills it too.
                let want = if inside { 3000 } else { 0 };
                assert_eq!(f.lin_at(x, y), [want], "{rule:?} ({x}, {y})");
            }
        }
    }
    // Wound twice: even-odd leaves it empty.
    let twice: Vec<FinePoint> = (0..2).flat_map(|_| square).collect();
    let f = render_canvas::<1>(8, 8, 3, [0], 0, |c| {
        c.fill(
            &Contour(&twice),
            [3000],
            FillRule::EvenOdd,
            Blend::Add,
            Opacity::OPAQUE,
        )
        .unwrap();
    });
    assert!(f.lin12.iter().all(|&v| v == [0]));
    // A stroke with a U-turn and round joins and caps, and a disc stroked
    // wider than its diameter (its pieces overlap everywhere): add on
    // black equals opaque over on black, bit for bit in the accumulator.
    let uturn = [p(3, 10), p(30, 12), p(4, 14), p(28, 20)];
    let line = softedge::path::Polyline::new(&uturn);
    let thick = softedge::path::StrokeStyle::new(5 * 1024)
        .with_join(LineJoin::Round)
        .with_cap(LineCap::Round);
    let disc = softedge::path::Circle::new(FinePoint::new(20 * 1024 + 300, 12 * 1024), 3 * 1024);
    let wide = softedge::path::StrokeStyle::new(9 * 1024);
    let draw = |blend| {
        render_canvas::<1>(40, 24, 5, [0], 0, move |c| {
            c.stroke_shape(&line, &thick, [2500], blend, Opacity::OPAQUE)
                .unwrap();
        })
        .raw
        .iter()
        .zip(
            render_canvas::<1>(40, 24, 5, [0], 0, move |c| {
                c.stroke_shape(&disc, &wide, [2500], blend, Opacity::OPAQUE)
                    .unwrap();
            })
            .raw
            .iter(),
        )
        .map(|(a, b)| (a[0], b[0]))
        .collect::<Vec<_>>()
    };
    assert_eq!(draw(Blend::Add), draw(Blend::Over));
    // A mesh is walked as one outline in its own orientation: one whose
    // triangles all lie on top of each other (20 times the same square's
    // two halves) adds its colour once, like any shape, instead of
    // overflowing the product of colour and coverage.
    let pts = [p(2, 2), p(6, 2), p(6, 6), p(2, 6)];
    let tris: Vec<[u16; 3]> = (0..20).flat_map(|_| [[0, 1, 2], [0, 2, 3]]).collect();
    for colors in [MeshColors::Flat([4000]), MeshColors::PerPoint(&[[4000]; 4])] {
        let f = render_canvas::<1>(8, 8, 3, [0], 0, |c| {
            c.fill_mesh(&pts, &tris, colors, Blend::Add, Opacity::OPAQUE)
                .unwrap();
        });
        assert_eq!(f.lin_at(3, 3), [4000]);
        assert_eq!(f.lin_at(1, 1), [0]);
    }
}
