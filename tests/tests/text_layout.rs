//! Text layout against independent numbers: kerning pairs read from the
//! font by fontTools (hard-coded below), metrics read by `ttf-parser` in
//! the test, embedded-graphics' alignment and baseline conventions, line
//! height and multi-line strings, measuring, `.notdef`, and the typed
//! errors of malformed files.

use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::path::Shape;
use softedge::style::{Blend, FillRule, Opacity};
use softedge::text::{
    Alignment, Baseline, Font, FontError, FontStyle, Glyph, GlyphId, GlyphRun, LineHeight, Scale,
    Sharpen, Text, TextSize, TextStyle,
};
use softedge::{Band, BandBuffer};

const FONT: &[u8] = softedge::text::bundled::SOFTEDGE_SANS;

/// Kerning of the bundled font in font units, read from its GPOS `kern`
/// feature (and, equal, its `kern` table) by fontTools when the subset was
/// made.
const KERN_PAIRS: [(&str, i32); 16] = [
    ("AV", -131),
    ("VA", -131),
    ("AT", -159),
    ("To", -348),
    ("Ty", -319),
    ("LT", -282),
    ("Yo", -272),
    ("AW", -112),
    ("av", 0),
    ("r.", -188),
    ("F,", 0),
    ("P.", -319),
    ("AY", -159),
    ("ff", 0),
    ("xx", 0),
    ("AA", 57),
];

fn font() -> Font<'static> {
    Font::new(FONT).unwrap()
}

fn face() -> ttf_parser::Face<'static> {
    ttf_parser::Face::parse(FONT, 0).unwrap()
}

/// Draws with `f` into a `w x h` gray frame (one band), linear values.
fn frame(w: u16, h: u16, f: impl FnOnce(&mut Canvas<'_, '_, 1>)) -> Vec<u16> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(w, 0, h)).unwrap();
    buf.clear([0]);
    let mut canvas = Canvas::new(&mut buf, None);
    f(&mut canvas);
    let buf = canvas.buffer();
    (0..i32::from(h))
        .flat_map(|y| (0..i32::from(w)).map(move |x| (x, y)))
        .map(|(x, y)| buf.lin12(x, y).unwrap()[0])
        .collect()
}

#[test]
fn kerning_matches_the_font_tools_reading_of_gpos() {
    let font = font();
    for (pair, units) in KERN_PAIRS {
        let mut c = pair.chars();
        let (l, r) = (font.glyph(c.next().unwrap()), font.glyph(c.next().unwrap()));
        assert_eq!(font.kerning(l, r), units, "{pair}");
    }
}

#[test]
fn without_gpos_the_kern_table_gives_the_same_pairs() {
    // The GPOS table renamed in the directory: the legacy `kern` table is
    // what is left.
    let n = usize::from(u16::from_be_bytes([FONT[4], FONT[5]]));
    let mut bytes = FONT.to_vec();
    let r = (0..n)
        .map(|i| 12 + 16 * i)
        .find(|&r| &FONT[r..r + 4] == b"GPOS")
        .unwrap();
    bytes[r..r + 4].copy_from_slice(b"xPOS");
    let font = Font::new(&bytes).unwrap();
    assert!(font.face().tables().gpos.is_none());
    for (pair, units) in KERN_PAIRS {
        let mut c = pair.chars();
        let (l, r) = (font.glyph(c.next().unwrap()), font.glyph(c.next().unwrap()));
        assert_eq!(font.kerning(l, r), units, "{pair}");
    }
}

#[test]
fn run_advance_is_the_sum_of_advances_and_kerning() {
    let font = font();
    let face = face();
    for size in [8u16, 12, 17, 24, 48] {
        let scale = Scale::new(TextSize::px(size), font.units_per_em());
        for (pair, units) in KERN_PAIRS {
            let text = format!("{pair}{pair}");
            let run = GlyphRun::new(&font, &text, FinePoint::new(0, 0), scale);
            let adv: i32 = text
                .chars()
                .map(|c| {
                    i32::from(
                        face.glyph_hor_advance(face.glyph_index(c).unwrap())
                            .unwrap(),
                    )
                })
                .sum();
            // Three pairs: the pair twice, and the pair's end with its start.
            let mut c = pair.chars();
            let (a, b) = (c.next().unwrap(), c.next().unwrap());
            let mid = KERN_PAIRS
                .iter()
                .find(|(p, _)| *p == format!("{b}{a}"))
                .map_or_else(|| font.kerning(font.glyph(b), font.glyph(a)), |p| p.1);
            let units_total = adv + 2 * units + mid;
            let exact = f64::from(units_total) * f64::from(size) * 1024.0 / 2048.0;
            let got = run.advance() as f64;
            // Each advance and kerning rounded once: half a fine unit each.
            assert!(
                (got - exact).abs() <= 3.5,
                "{text} at {size}: {got} vs {exact}"
            );
            let plain = run.with_kerning(false).advance() as f64;
            let exact_plain = f64::from(adv) * f64::from(size) / 2.0;
            assert!((plain - exact_plain).abs() <= 2.0);
        }
    }
}

#[test]
fn a_missing_character_is_left_out_not_drawn_as_a_notdef_box() {
    // Issue #33 (and #34's "characters missing from a font are accepted
    // silently"): a character the font lacks is not drawn as `.notdef` and
    // takes no advance; `Text::draw` reports it (tests/text_raster.rs).
    let font = font();
    assert!(!font.has_glyph('\u{4e2d}'));
    let scale = Scale::new(TextSize::px(20), font.units_per_em());
    let at = FinePoint::new(3 * 1024 + 100, 24 * 1024 + 77);
    let draw = |s: &'static str| {
        frame(60, 32, |c| {
            let run = GlyphRun::new(&font, s, at, scale);
            c.fill(
                &run,
                [4095],
                FillRule::NonZero,
                Blend::Over,
                Opacity::OPAQUE,
            )
            .unwrap();
        })
    };
    let alone = draw("\u{4e2d}");
    assert!(alone.iter().all(|&v| v == 0), "nothing drawn");
    assert_eq!(draw("A\u{4e2d}B"), draw("AB"));
    let run = GlyphRun::new(&font, "A\u{4e2d}B", at, scale);
    assert_eq!(
        run.advance(),
        GlyphRun::new(&font, "AB", at, scale).advance()
    );
    assert_eq!(font.missing("A\u{4e2d}B").collect::<String>(), "\u{4e2d}");
    // The `.notdef` glyph itself still draws when asked for by id.
    let notdef = frame(30, 32, |c| {
        let g = Glyph::new(&font, GlyphId(0), at, scale);
        c.fill_shape(&g, [4095], FillRule::NonZero, Blend::Over, Opacity::OPAQUE)
            .unwrap();
    });
    let lit: u32 = notdef.iter().map(|&v| u32::from(v)).sum();
    assert!(lit > 4095 * 20, "the .notdef box has ink: {lit}");
}

#[test]
fn a_run_as_a_shape_fills_like_the_run_as_an_outline() {
    let font = font();
    let scale = Scale::new(TextSize::px(15), font.units_per_em());
    let run = GlyphRun::new(
        &font,
        "Shape & outline",
        FinePoint::new(1500, 18 * 1024),
        scale,
    );
    let a = frame(130, 24, |c| {
        c.fill(
            &run,
            [4095],
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap()
    });
    let b = frame(130, 24, |c| {
        c.fill_shape(
            &run,
            [4095],
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
        .unwrap()
    });
    assert_eq!(a, b);
    // And its stroke works too (outlined text).
    let stroked = frame(130, 24, |c| {
        let style = softedge::path::StrokeStyle::new(512);
        c.stroke_shape(&run, &style, [4095], Blend::Over, Opacity::OPAQUE)
            .unwrap()
    });
    assert!(stroked.iter().any(|&v| v > 0));
    let mut sink = softedge_tests::path_ref::Segments::new();
    run.fill(&mut sink);
    assert!(sink.is_closed_in_range());
}

/// Ascender, descender and line height from ttf-parser, in fine units at
/// `size`.
fn metrics(size: f64) -> (f64, f64, f64) {
    let face = face();
    let k = size * 1024.0 / f64::from(face.units_per_em());
    let (a, d, g) = (
        f64::from(face.ascender()),
        f64::from(face.descender()),
        f64::from(face.line_gap()),
    );
    (a * k, d * k, (a - d + g) * k)
}

#[test]
fn baselines_follow_embedded_graphics_conventions() {
    let font = font();
    let style = FontStyle::<1>::new(&font, 20, [4095]);
    let (asc, desc, _) = metrics(20.0);
    let p = FinePoint::new(5000, 30_000);
    let first = |b: Baseline| {
        Text::with_baseline("Hx", p, style, b)
            .lines()
            .next()
            .unwrap()
            .origin()
    };
    let y = f64::from(p.y);
    for (b, want) in [
        (Baseline::Alphabetic, y),
        (Baseline::Top, y + asc),
        (Baseline::Bottom, y + desc),
        (Baseline::Middle, y + (asc + desc) / 2.0),
    ] {
        let got = first(b);
        assert_eq!(got.x, p.x);
        assert!(
            (f64::from(got.y) - want).abs() <= 1.0,
            "{b:?}: {} vs {want}",
            got.y
        );
    }
    // e-g's enum converts one to one.
    let eg: Baseline = embedded_graphics::text::Baseline::Middle.into();
    assert_eq!(eg, Baseline::Middle);
}

#[test]
fn alignment_is_per_line_and_lines_are_one_line_height_apart() {
    let font = font();
    let style = FontStyle::<1>::new(&font, 16, [4095]);
    let (_, _, lh) = metrics(16.0);
    let p = FinePoint::new(100 * 1024, 20 * 1024);
    let text = "short\r\na much longer line\n\nend";
    for a in [Alignment::Left, Alignment::Center, Alignment::Right] {
        let t = Text::with_alignment(text, p, style, a);
        let lines: Vec<_> = t.lines().collect();
        assert_eq!(lines.len(), 4);
        assert_eq!(lines[0].text(), "short"); // the '\r' dropped
        for (k, l) in lines.iter().enumerate() {
            let start = f64::from(l.origin().x);
            let adv = l.advance() as f64;
            let (x0, x1) = (start, start + adv);
            let anchor = f64::from(p.x);
            match a {
                Alignment::Left => assert_eq!(x0, anchor),
                Alignment::Right => assert!((x1 - anchor).abs() <= 1.0),
                Alignment::Center => assert!(((x0 + x1) / 2.0 - anchor).abs() <= 1.0),
            }
            let want_y = f64::from(p.y) + k as f64 * lh;
            assert!((f64::from(l.origin().y) - want_y).abs() <= 1.0 + k as f64);
        }
    }
    let t = Text::with_text_style(
        "a\nb",
        p,
        style,
        TextStyle::new(
            Alignment::Left,
            Baseline::Alphabetic,
            LineHeight::Pixels(13),
        ),
    );
    let ys: Vec<i32> = t.lines().map(|l| l.origin().y).collect();
    assert_eq!(ys, vec![p.y, p.y + 13 * 1024]);
    let pct = Text::with_text_style(
        "a\nb",
        p,
        style,
        TextStyle::new(
            Alignment::Left,
            Baseline::Alphabetic,
            LineHeight::Percent(150),
        ),
    );
    let ys: Vec<i32> = pct.lines().map(|l| l.origin().y).collect();
    assert!((f64::from(ys[1] - ys[0]) - 1.5 * lh).abs() <= 1.0);
}

#[test]
fn measuring_agrees_with_drawing() {
    let font = font();
    let style = FontStyle::<1>::new(&font, 14, [4095]);
    let text = Text::with_text_style(
        "Measure me,\nplease: 42 µV ±1 %",
        FinePoint::new(70 * 1024 + 300, 4 * 1024),
        style,
        TextStyle::new(Alignment::Center, Baseline::Top, LineHeight::Percent(110)),
    );
    let m = text.measure();
    let mut next = FinePoint::default();
    let img = frame(140, 44, |c| next = text.draw(c).unwrap());
    assert_eq!(next, m.next_position);
    let ink = m.ink_box.unwrap();
    let mut lit = 0;
    for (k, &v) in img.iter().enumerate() {
        if v == 0 {
            continue;
        }
        lit += 1;
        let (x, y) = ((k % 140) as i32, (k / 140) as i32);
        // A lit pixel overlaps the ink box.
        assert!(x * 1024 + 1024 > ink.x0 && x * 1024 < ink.x1, "x {x}");
        assert!(y * 1024 + 1024 > ink.y0 && y * 1024 < ink.y1, "y {y}");
    }
    assert!(lit > 100);
    // The widest line: the second one's advance.
    let second = text.lines().nth(1).unwrap().advance();
    assert_eq!(m.width, second);
    assert!(m.layout_box.x1 - m.layout_box.x0 >= second as i32);
    // Top baseline: the layout box starts at the position.
    assert!((m.layout_box.y0 - text.position.y).abs() <= 1);
}

#[test]
fn sharpen_puts_baseline_and_x_height_on_the_grid() {
    let font = font();
    let style = FontStyle::<1>::new(&font, 11, [4095]).with_sharpen(Sharpen::GRID);
    let t = Text::new("xo", FinePoint::new(3 * 1024 + 300, 12 * 1024 + 700), style);
    let run = t.lines().next().unwrap();
    assert_eq!(run.origin().y % 1024, 0);
    for g in run.glyphs() {
        assert_eq!(g.origin().x % 1024, 0);
    }
    let s = style.scale();
    let xh = s.y_units(i32::from(font.x_height()));
    assert_eq!(xh % 1024, 0, "x-height {xh}");
    // Not sharpened: the position is kept exactly.
    let exact = Text::new(
        "xo",
        FinePoint::new(3 * 1024 + 300, 12 * 1024 + 700),
        style.with_sharpen(Sharpen::NONE),
    );
    assert_eq!(
        exact.lines().next().unwrap().origin(),
        FinePoint::new(3 * 1024 + 300, 12 * 1024 + 700)
    );
}

#[test]
fn colours_come_in_linear_or_as_embedded_graphics_srgb() {
    let font = font();
    assert_eq!(
        FontStyle::<3>::new(&font, 10, Rgb565::RED).color,
        [4095, 0, 0]
    );
    assert_eq!(FontStyle::<1>::new(&font, 10, [5000]).color, [4095]);
    let lum: [u16; 1] = FontStyle::<1>::new(&font, 10, Rgb565::GREEN).color;
    assert_eq!(lum, [2929]);
}

#[test]
fn malformed_files_are_typed_errors() {
    assert_eq!(Font::new(b"").err(), Some(FontError::UnknownMagic));
    assert_eq!(Font::new(&FONT[..3]).err(), Some(FontError::UnknownMagic));
    assert_eq!(Font::new(&FONT[..40]).err(), Some(FontError::Malformed));
    assert_eq!(Font::with_index(FONT, 1).err(), Some(FontError::FaceIndex));
    // Find a table's record in the directory: (tag, offset of the record).
    let record = |tag: &[u8; 4]| {
        let n = usize::from(u16::from_be_bytes([FONT[4], FONT[5]]));
        (0..n)
            .map(|i| 12 + 16 * i)
            .find(|&r| &FONT[r..r + 4] == tag)
            .unwrap()
    };
    // units_per_em (head + 18) set to 0 and to 20000.
    let head = {
        let r = record(b"head");
        u32::from_be_bytes(FONT[r + 8..r + 12].try_into().unwrap()) as usize
    };
    for upem in [0u16, 20000] {
        let mut bad = FONT.to_vec();
        bad[head + 18..head + 20].copy_from_slice(&upem.to_be_bytes());
        let e = Font::new(&bad).err();
        assert!(
            matches!(
                e,
                Some(FontError::UnitsPerEm(_)) | Some(FontError::Malformed)
            ),
            "{upem}: {e:?}"
        );
    }
    // No outlines: the glyf table renamed.
    let mut bad = FONT.to_vec();
    let r = record(b"glyf");
    bad[r..r + 4].copy_from_slice(b"xxxx");
    assert_eq!(Font::new(&bad).err(), Some(FontError::NoOutlines));
    // Errors print.
    assert_eq!(
        FontError::UnitsPerEm(3).to_string(),
        "units per em 3 is outside 16..=16384"
    );
}
