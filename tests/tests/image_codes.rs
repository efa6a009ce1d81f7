//! An unscaled Rgb565 image at a whole pixel (softedge's `RawImage`, or
//! embedded-graphics' `ImageRaw`) is stored as its codes and, where the
//! display's profile tones every Rgb565 colour back to itself, sent as it
//! was read (issue #35's copy). The promise is the same bits: every frame
//! here is rendered twice, once with the images as plain Rgb565 sources
//! (softedge's or embedded-graphics') and once with the same texels as
//! colour-keyed sources whose key never occurs (decoded texel by texel,
//! composited as any image with alpha is, never stored as codes), and the
//! two frames must be equal pixel for pixel: with shapes, translucent
//! shapes, text, gradients and added shapes over and under the images,
//! bands of 1 to 16 rows, bands of more colours than the palette holds,
//! streamed, lent and in windows, through profiles that keep Rgb565
//! colours (sRGB) and that do not (γ 2.2, ordered dithering, Rgb888).

use embedded_graphics::image::{ImageRawBE, ImageRawLE};
use embedded_graphics::pixelcolor::{PixelColor, Rgb565, Rgb888};
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Rectangle};
use embedded_graphics::text::Text;
use softedge::color::IntoLinear;
use softedge::color::{SRGB5_TO_LIN12, SRGB6_TO_LIN12};
use softedge::geom::FinePoint;
use softedge::image::{format, AaImage, ImageSource, RawImage, Scale};
use softedge::prelude::*;
use softedge::style::{Gradient, Offset, Stop};
use softedge::text::bundled::SANS_16;
use softedge::text::AaTextStyle;
use softedge::tone::format::{RawColor, ToneFormat};
use softedge::tone::Profile;

use softedge_tests::lcg::Lcg;
use softedge_tests::screen::Screen;

const W: u16 = 40;
const H: u16 = 34;

/// A random Rgb565 colour.
fn color(rng: &mut Lcg) -> Rgb565 {
    Rgb565::new(
        rng.below(32) as u8,
        rng.below(64) as u8,
        rng.below(32) as u8,
    )
}

/// An Rgb565 code decoded by the sRGB tables, written here.
fn decode(code: u16) -> [u16; 3] {
    [
        SRGB5_TO_LIN12[usize::from(code >> 11)],
        SRGB6_TO_LIN12[usize::from(code >> 5 & 63)],
        SRGB5_TO_LIN12[usize::from(code & 31)],
    ]
}

#[test]
fn a_format_keeps_rgb565_exactly_when_every_colour_comes_back() {
    for (curve, name) in [
        (Curve::Srgb, "sRGB"),
        (Curve::GAMMA_2_2, "γ 2.2"),
        (Curve::GAMMA_2_4, "γ 2.4"),
    ] {
        let f = Rgb565Format::new(curve);
        let all = (0..=u16::MAX).all(|c| f.code(decode(c)) == c);
        assert_eq!(f.keeps_rgb565(), all, "{name}");
        assert_eq!(Profile::<3>::keeps_rgb565(&&f), all, "{name} as a profile");
    }
    // The curve the images' sRGB tables are made for keeps them.
    assert!(Rgb565Format::new(Curve::Srgb).keeps_rgb565());
    assert!(!Rgb888Format::new(Curve::Srgb).keeps_rgb565());
    assert!(!Profile::<3>::keeps_rgb565(&&Rgb565Dither::new(
        Curve::Srgb
    )));
}

#[test]
fn an_rgb565_colour_is_its_own_code_and_decodes_to_its_linear_value() {
    use embedded_graphics::pixelcolor::raw::RawU16;
    use embedded_graphics::pixelcolor::{Bgr565, IntoStorage, RgbColor};
    for v in 0..=u16::MAX {
        let c = Rgb565::from(RawU16::new(v));
        assert_eq!(IntoLinear::<3>::rgb565_code(&c), Some(c.into_storage()));
        assert_eq!(decode(v), IntoLinear::<3>::into_linear(c));
        let b = Bgr565::new(c.r(), c.g(), c.b());
        assert_eq!(IntoLinear::<3>::rgb565_code(&b), Some(v));
    }
    assert_eq!(IntoLinear::<3>::rgb565_code(&Rgb888::new(1, 2, 3)), None);
    assert_eq!(IntoLinear::<1>::rgb565_code(&Rgb565::RED), None);
}

/// One image of a scene: its texels (little and big endian bytes), size,
/// where it goes and how.
struct Img {
    le: Vec<u8>,
    be: Vec<u8>,
    w: u16,
    h: u16,
    /// A raw value none of its texels has.
    key: u32,
    at: FinePoint,
    scale: Option<Scale>,
    opacity: Opacity,
    add: bool,
    big_endian: bool,
    /// Drawn from embedded-graphics' `ImageRaw` (`ImageRawLE<Rgb565>`,
    /// `ImageRawBE<Rgb565>`) instead of softedge's `RawImage`.
    eg: bool,
}

enum Item {
    Image(Img),
    Disc(Point, u32, Rgb565, Opacity),
    Rect(Point, Size, Rgb565, Opacity, bool),
    Text(Point, Rgb565),
    Ramp(Point, Size, Rgb565, Rgb565),
    /// Many small squares of distinct colours: the band's palette overflows.
    Confetti(u64),
}

fn random_image(rng: &mut Lcg) -> Img {
    let (w, h) = (1 + rng.below(22) as u16, 1 + rng.below(18) as u16);
    // A few colours, repeated, or every texel its own.
    let few: Vec<u16> = (0..1 + rng.below(6)).map(|_| rng.bits() as u16).collect();
    let many = rng.below(2) == 0;
    let codes: Vec<u16> = (0..usize::from(w) * usize::from(h))
        .map(|_| {
            if many {
                rng.bits() as u16
            } else {
                few[rng.below(few.len() as u64) as usize]
            }
        })
        .collect();
    let key = (0..=u16::MAX).find(|k| !codes.contains(k)).unwrap();
    let le = codes.iter().flat_map(|c| c.to_le_bytes()).collect();
    let be = codes.iter().flat_map(|c| c.to_be_bytes()).collect();
    let whole = rng.below(4) != 0;
    let at = if whole {
        FinePoint::from_px(
            rng.below(u64::from(W) + 16) as i32 - 12,
            rng.below(u64::from(H) + 16) as i32 - 12,
        )
    } else {
        FinePoint::new(
            rng.below(1024 * u64::from(W)) as i32 - 4096,
            rng.below(1024 * u64::from(H)) as i32 - 4096,
        )
    };
    Img {
        le,
        be,
        w,
        h,
        key: u32::from(key),
        at,
        scale: (rng.below(6) == 0).then(|| Scale::from_ratio(1 + rng.below(3) as u32, 2)),
        opacity: if rng.below(5) == 0 {
            Opacity::from_percent(40)
        } else {
            Opacity::OPAQUE
        },
        add: rng.below(8) == 0,
        big_endian: rng.below(2) == 0,
        eg: rng.below(3) == 0,
    }
}

fn random_scene(rng: &mut Lcg) -> Vec<Item> {
    let mut items = vec![];
    for _ in 0..2 + rng.below(6) {
        let p = Point::new(
            rng.below(u64::from(W)) as i32 - 4,
            rng.below(u64::from(H)) as i32 - 4,
        );
        let size = Size::new(1 + rng.below(24) as u32, 1 + rng.below(20) as u32);
        let opacity = if rng.below(3) == 0 {
            Opacity::from_percent(1 + rng.below(99) as u8)
        } else {
            Opacity::OPAQUE
        };
        items.push(match rng.below(8) {
            0..=2 => Item::Image(random_image(rng)),
            3 => Item::Disc(p, 2 + rng.below(20) as u32, color(rng), opacity),
            4 => Item::Rect(p, size, color(rng), opacity, rng.below(4) == 0),
            5 => Item::Text(p, color(rng)),
            6 => Item::Ramp(p, size, color(rng), color(rng)),
            _ => Item::Confetti(rng.bits()),
        });
    }
    items
}

/// Draws image `i` from `src`.
fn place<Col, S: ImageSource>(c: &mut Canvas<'_, '_, 3, Col>, src: &S, i: &Img)
where
    Col: PixelColor + IntoLinear<3>,
{
    let a = AaImage::new(src).position(i.at).opacity(i.opacity);
    let a = if i.add { a.blend(Blend::Add) } else { a };
    let a = match i.scale {
        Some(s) => a.scale(s),
        None => a,
    };
    let _ = a.draw(c);
}

/// Draws `items`; `keyed`: every image through the colour-keyed format.
fn draw<Col>(c: &mut Canvas<'_, '_, 3, Col>, items: &[Item], keyed: bool) -> Result<(), DrawError>
where
    Col: PixelColor + From<Rgb565> + IntoLinear<3>,
{
    for item in items {
        match item {
            Item::Image(i) => match (keyed, i.big_endian) {
                (false, false) if i.eg => {
                    let src = ImageRawLE::<Rgb565>::new(&i.le, u32::from(i.w));
                    place(c, &src, i);
                }
                (false, true) if i.eg => {
                    let src = ImageRawBE::<Rgb565>::new(&i.be, u32::from(i.w));
                    place(c, &src, i);
                }
                (false, false) => {
                    let src = RawImage::<format::Rgb565>::new(&i.le, i.w, i.h).unwrap();
                    place(c, &src, i);
                }
                (false, true) => {
                    let src = RawImage::<format::Rgb565Be>::new(&i.be, i.w, i.h).unwrap();
                    place(c, &src, i);
                }
                (true, false) => {
                    let src = RawImage::<format::Keyed<format::Rgb565>>::new(&i.le, i.w, i.h)
                        .unwrap()
                        .with_color_key(i.key);
                    place(c, &src, i);
                }
                (true, true) => {
                    let src = RawImage::<format::Keyed<format::Rgb565Be>>::new(&i.be, i.w, i.h)
                        .unwrap()
                        .with_color_key(i.key);
                    place(c, &src, i);
                }
            },
            Item::Disc(p, d, col, o) => {
                let _ = Circle::new(*p, *d)
                    .into_styled(AaStyle::with_fill(Col::from(*col)).opacity(*o))
                    .draw(c);
            }
            Item::Rect(p, s, col, o, add) => {
                let style = AaStyle::with_fill(Col::from(*col)).opacity(*o);
                let style = if *add { style.blend(Blend::Add) } else { style };
                let _ = Rectangle::new(*p, *s).into_styled(style).draw(c);
            }
            Item::Text(p, col) => {
                let style = AaTextStyle::new(&SANS_16, Col::from(*col));
                let _ = Text::new("Ag8", *p, style).draw(c);
            }
            Item::Ramp(p, s, a, b) => {
                let g = Gradient::linear(
                    FinePoint::from_px(p.x, p.y),
                    FinePoint::from_px(p.x + s.width as i32, p.y + 3),
                    &[
                        Stop::new(Offset::ZERO, Col::from(*a)),
                        Stop::new(Offset::ONE, Col::from(*b)),
                    ],
                )
                .unwrap();
                let _ = Rectangle::new(*p, *s)
                    .into_styled(AaGradient::fill(&g))
                    .draw(c);
            }
            Item::Confetti(seed) => {
                let mut rng = Lcg(*seed);
                for _ in 0..40 {
                    let p = Point::new(
                        rng.below(u64::from(W)) as i32,
                        rng.below(u64::from(H)) as i32,
                    );
                    let _ = Rectangle::new(p, Size::new(2, 2))
                        .into_styled(AaStyle::with_fill(Col::from(color(&mut rng))))
                        .draw(c);
                }
            }
        }
    }
    Ok(())
}

/// A display that lends a band buffer and keeps what it is sent.
struct Lent<Col> {
    band: Vec<u32>,
    screen: Vec<Option<u32>>,
    _c: core::marker::PhantomData<Col>,
}

impl<Col> OriginDimensions for Lent<Col> {
    fn size(&self) -> Size {
        Size::new(u32::from(W), u32::from(H))
    }
}

impl<Col: PixelColor + RawColor> BandTarget for Lent<Col> {
    type Color = Col;
    type Raw = u32;
    type Error = core::convert::Infallible;
    fn buffer(&mut self) -> &mut [u32] {
        // Scrambled: every pixel must be made.
        self.band.fill(0xdead_beef);
        &mut self.band
    }
    fn send(&mut self, area: &Rectangle) -> Result<(), Self::Error> {
        for (k, p) in area.points().enumerate() {
            if p.x >= 0 && p.y >= 0 && p.x < i32::from(W) && p.y < i32::from(H) {
                self.screen[p.y as usize * usize::from(W) + p.x as usize] = Some(self.band[k]);
            }
        }
        Ok(())
    }
}

/// The frame of `items` through `profile`: streamed, lent and (streamed)
/// in a window, each as raw colours.
fn frames<Col, P>(
    items: &[Item],
    keyed: bool,
    rows: u16,
    profile: &P,
    window: Rectangle,
) -> [Vec<Option<u32>>; 3]
where
    Col: PixelColor + From<Rgb565> + IntoLinear<3> + RawColor,
    for<'p> &'p P: Profile<3, Color = Col>,
{
    let mut acc = vec![0i32; BandBuffer::<3>::acc_len(W, rows)];
    let mut cover = vec![0i32; BandBuffer::<3>::cover_len(W, rows)];
    let mut slots = [WalkSlot::<3>::EMPTY; 4];
    let bg = [300u16, 1200, 2500];
    let raw = |s: &Screen<Col>| s.px.iter().map(|p| p.map(|c| c.to_raw())).collect();
    let mut r = Renderer::new(&mut acc, &mut cover, &mut slots, W, H, rows).unwrap();
    let mut screen = Screen::<Col>::new(u32::from(W), u32::from(H));
    r.render(&mut screen, profile, bg, |c| draw::<Col>(c, items, keyed))
        .unwrap();
    let streamed = raw(&screen);
    let mut lent = Lent::<Col> {
        band: vec![0; usize::from(W) * usize::from(rows)],
        screen: vec![None; usize::from(W) * usize::from(H)],
        _c: core::marker::PhantomData,
    };
    r.render_lent(&mut lent, profile, bg, |c| draw::<Col>(c, items, keyed))
        .unwrap();
    let mut part = Screen::<Col>::new(u32::from(W), u32::from(H));
    r.render_window(&mut part, profile, bg, window, |c| {
        draw::<Col>(c, items, keyed)
    })
    .unwrap();
    [streamed, lent.screen, raw(&part)]
}

fn check<Col, P>(rng: &mut Lcg, profile: &P, name: &str, cases: u32)
where
    Col: PixelColor + From<Rgb565> + IntoLinear<3> + RawColor,
    for<'p> &'p P: Profile<3, Color = Col>,
{
    let mut compared = 0usize;
    for case in 0..cases {
        let items = random_scene(rng);
        let rows = [1u16, 3, 5, 16][rng.below(4) as usize];
        let window = Rectangle::new(
            Point::new(rng.below(20) as i32, rng.below(16) as i32),
            Size::new(1 + rng.below(20) as u32, 1 + rng.below(18) as u32),
        );
        let got = frames(&items, false, rows, profile, window);
        let want = frames(&items, true, rows, profile, window);
        for (k, kind) in ["streamed", "lent", "window"].iter().enumerate() {
            for (i, (g, w)) in got[k].iter().zip(&want[k]).enumerate() {
                assert_eq!(
                    g,
                    w,
                    "{name}, case {case}, {kind}, {rows}-row bands: pixel ({}, {})",
                    i % usize::from(W),
                    i / usize::from(W)
                );
            }
            compared += got[k].iter().filter(|p| p.is_some()).count();
        }
        // Every pixel of the frame was sent.
        assert!(got[0].iter().chain(&got[1]).all(Option::is_some));
    }
    println!("{name}: {cases} scenes, {compared} pixels equal");
}

#[test]
fn images_sent_as_codes_give_the_frames_of_decoded_images() {
    let mut rng = Lcg(0x35_c0de);
    check::<Rgb565, _>(
        &mut rng,
        &Rgb565Format::new(Curve::Srgb),
        "Rgb565 sRGB",
        160,
    );
    check::<Rgb565, _>(
        &mut rng,
        &Rgb565Format::new(Curve::GAMMA_2_2),
        "Rgb565 γ 2.2",
        60,
    );
    check::<Rgb565, _>(
        &mut rng,
        &Rgb565Dither::new(Curve::Srgb),
        "Rgb565 dithered",
        60,
    );
    check::<Rgb888, _>(&mut rng, &Rgb888Format::new(Curve::Srgb), "Rgb888", 60);
}
