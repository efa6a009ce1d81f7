//! Issue #34, item 3: on a 1-bit display, legibility belongs to the shape,
//! not the frame. Text and a value arc drawn with `Edges::Crisp` come out
//! as the threshold at 1/2 of their exact coverage (no stray dots, no
//! notches), while a gauge track at 1/3 opacity in the same frame keeps
//! its dithered tone; a frame-wide `ContrastBoost` erases that track, and
//! plain Floyd–Steinberg scatters the text's edges.
//!
//! The references are the same shapes drawn alone, smooth, into a gray
//! band (their exact coverage as linear values), thresholded here.

use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::Arc;
use softedge::prelude::*;
use softedge::text::{ContrastBoost, Font, FontStyle, Text};
use softedge::{Band, BandBuffer};

const W: u16 = 128;
const H: u16 = 64;

/// Which parts of the scene to draw, and how their edges are drawn.
#[derive(Clone, Copy)]
struct Parts {
    text: Option<Edges>,
    track: bool,
    value: Option<Edges>,
}

const ALL_CRISP: Parts = Parts {
    text: Some(Edges::Crisp),
    track: true,
    value: Some(Edges::Crisp),
};

fn scene(c: &mut Canvas<'_, '_, 1, BinaryColor>, parts: Parts) -> Result<(), DrawError> {
    let font = Font::new(softedge::text::bundled::SOFTEDGE_SANS).unwrap();
    if let Some(e) = parts.text {
        let style = FontStyle::<1>::new(&font, 12, BinaryColor::On);
        c.set_edges(e);
        Text::new("23.5 °C  AVAWAY", FinePoint::from_px(3, 18), style).draw(c)?;
        Text::new("Oil 87 kPa", FinePoint::from_px(3, 40), style).draw(c)?;
        c.set_edges(Edges::Smooth);
    }
    if parts.track {
        Arc::new(
            Point::new(84, 20),
            40,
            Angle::from_degrees(135.0),
            Angle::from_degrees(270.0),
        )
        .into_styled(
            AaStyle::with_stroke(BinaryColor::On, 6).opacity(Opacity::from_ratio(1, 3).unwrap()),
        )
        .draw(c)?;
    }
    if let Some(e) = parts.value {
        Arc::new(
            Point::new(96, 32),
            16,
            Angle::from_degrees(135.0),
            Angle::from_degrees(200.0),
        )
        .into_styled(
            AaStyle::with_stroke(BinaryColor::On, 3)
                .cap(LineCap::Round)
                .edges(e),
        )
        .draw(c)?;
    }
    Ok(())
}

/// The scene's linear values in one gray band.
fn gray(parts: Parts) -> Vec<u16> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, H)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, H)];
    let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(W, 0, H)).unwrap();
    buf.clear([0]);
    let mut canvas: Canvas<'_, '_, 1, BinaryColor> = Canvas::typed(&mut buf, None);
    scene(&mut canvas, parts).unwrap();
    let mut out = vec![0; usize::from(W) * usize::from(H)];
    for y in 0..i32::from(H) {
        for x in 0..i32::from(W) {
            out[(y * i32::from(W) + x) as usize] = buf.lin12(x, y).unwrap()[0];
        }
    }
    out
}

/// A 1-bit display keeping what it is sent.
struct Oled(Vec<bool>);

impl OriginDimensions for Oled {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(H))
    }
}

impl DrawTarget for Oled {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;
    fn draw_iter<I: IntoIterator<Item = Pixel<BinaryColor>>>(
        &mut self,
        px: I,
    ) -> Result<(), Self::Error> {
        for Pixel(p, c) in px {
            self.0[(p.y * i32::from(W) + p.x) as usize] = c.is_on();
        }
        Ok(())
    }
}

/// The frame on the OLED through Floyd–Steinberg (boosted x4 frame-wide
/// with `boost`), in bands of 8 rows.
fn oled(parts: Parts, boost: bool) -> Vec<bool> {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(W, 8)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(W, 8)];
    let mut r = Renderer::new(&mut acc, &mut cover, &mut [], W, H, 8).unwrap();
    let (mut err, mut bits) = ([0i16; W as usize], [false; W as usize]);
    let mut fs = DiffusionProfile::new(&mut err, &mut bits);
    let mut display = Oled(vec![false; usize::from(W) * usize::from(H)]);
    if boost {
        let mut scratch = [0i32; W as usize];
        let boosted = ContrastBoost::new(&mut fs, 2, &mut scratch);
        r.render(&mut display, boosted, BinaryColor::Off, |c| scene(c, parts))
            .unwrap();
    } else {
        r.render(&mut display, &mut fs, BinaryColor::Off, |c| scene(c, parts))
            .unwrap();
    }
    display.0
}

/// Pixels of a part's footprint (`alone` > 0) that no other part reaches:
/// where the 1-bit frame differs from the threshold at 1/2 of `alone`
/// (pixels within 2 of the threshold are left out: rounding there is a
/// coin toss of the test's own reference); and how many were compared.
fn off_threshold(bits: &[bool], alone: &[u16], others: &[u16]) -> (usize, usize) {
    let (mut wrong, mut n) = (0, 0);
    for k in 0..bits.len() {
        if alone[k] == 0 || others[k] != 0 || alone[k].abs_diff(2048) <= 2 {
            continue;
        }
        n += 1;
        if bits[k] != (alone[k] >= 2048) {
            wrong += 1;
        }
    }
    (wrong, n)
}

/// The fraction of the track's interior (its own value whole: 1/3 of
/// white, nothing else near) that is lit.
fn track_density(bits: &[bool], track: &[u16], others: &[u16]) -> f64 {
    let full = track.iter().copied().max().unwrap();
    let (mut on, mut n) = (0, 0);
    for k in 0..bits.len() {
        if track[k] == full && others[k] == 0 {
            n += 1;
            on += usize::from(bits[k]);
        }
    }
    assert!(n > 200, "{n}");
    on as f64 / n as f64
}

#[test]
fn crisp_text_and_arcs_are_the_threshold_of_their_coverage_and_the_track_keeps_its_tone() {
    let none = Parts {
        text: None,
        track: false,
        value: None,
    };
    let text = gray(Parts {
        text: Some(Edges::Smooth),
        ..none
    });
    let track = gray(Parts {
        track: true,
        ..none
    });
    let value = gray(Parts {
        value: Some(Edges::Smooth),
        ..none
    });
    let sum = |a: &[u16], b: &[u16]| a.iter().zip(b).map(|(x, y)| x + y).collect::<Vec<u16>>();
    let not_text = sum(&track, &value);
    let not_value = sum(&track, &text);

    // Per-shape crispness: text and value arc exact, the track a tone.
    let bits = oled(ALL_CRISP, false);
    let (wrong, n) = off_threshold(&bits, &text, &not_text);
    assert!(n > 300, "{n}");
    assert_eq!(
        wrong, 0,
        "crisp text: {wrong} of {n} pixels off the threshold"
    );
    let (wrong, n) = off_threshold(&bits, &value, &not_value);
    assert!(n > 60, "{n}");
    assert_eq!(
        wrong, 0,
        "crisp arc: {wrong} of {n} pixels off the threshold"
    );
    // Nothing lit where nothing was drawn.
    let all = sum(&not_text, &text);
    assert!(bits.iter().zip(&all).all(|(&b, &v)| !b || v > 0));
    let d = track_density(&bits, &track, &sum(&text, &value));
    assert!((0.26..=0.41).contains(&d), "the track's tone: {d}");

    // The frame-wide boost erases the track; plain error diffusion
    // scatters the text (the problems `Edges` solves).
    let smooth = Parts {
        text: Some(Edges::Smooth),
        track: true,
        value: Some(Edges::Smooth),
    };
    let boosted = oled(smooth, true);
    let d = track_density(&boosted, &track, &sum(&text, &value));
    assert!(d < 0.05, "ContrastBoost keeps {d} of the track");
    let plain = oled(smooth, false);
    let (wrong, n) = off_threshold(&plain, &text, &not_text);
    assert!(
        wrong * 20 > n,
        "plain Floyd–Steinberg: only {wrong} of {n} text pixels off"
    );
    eprintln!(
        "track density: crisp shapes {:.3}, frame boost {:.3}; plain FS text pixels off threshold {wrong} of {n}",
        track_density(&bits, &track, &sum(&text, &value)),
        d
    );
}

/// `Edges::Boost(2)` on the text is the README's boost x4 on that text
/// alone: white text on black, its 1-bit pixels are those of the
/// frame-wide `ContrastBoost` with shift 2 wherever the track is not.
#[test]
fn boosted_text_matches_the_frame_boost_on_that_text() {
    let text_only = |e| Parts {
        text: Some(e),
        track: false,
        value: None,
    };
    let per_shape = oled(text_only(Edges::Boost(2)), false);
    let frame = oled(text_only(Edges::Smooth), true);
    let differ = per_shape.iter().zip(&frame).filter(|(a, b)| a != b).count();
    // The boost of a value (12-bit, after the frame's rounding) and of a
    // coverage (16 bits, before it) could round apart by a level (none
    // do here: measured 0).
    eprintln!("per-shape boost vs frame boost: {differ} pixels differ");
    assert!(differ <= 4, "{differ} pixels differ");
}
