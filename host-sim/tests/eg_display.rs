//! softedge's frame loop (`softedge::render::Renderer`) drawing a
//! scene file into a display type from another crate: the simulator's
//! `SimulatorDisplay`, wrapped in [`BandsOnly`], a `DrawTarget` that
//! accepts whole bands through `fill_contiguous` (or `fill_solid`, for a
//! band nothing was drawn on, or for the background left and right of a
//! band's drawn columns: a band may come in up to three rectangles side
//! by side) and panics on anything else: per-pixel writes (`draw_iter`),
//! clears, writes outside the display, and a band's pixels written twice
//! or left out. It has no way to read pixels back, as a write-only SPI
//! display has none.
//!
//! The display's pixels must equal what the host renderer shows for the
//! same scene (`SceneFile::render_linear`, then its tone stage), for the
//! scene's band height and for others.

use std::path::{Path, PathBuf};

use embedded_graphics::pixelcolor::{Gray8, PixelColor, Rgb565};
use embedded_graphics::prelude::{DrawTarget, IntoStorage, OriginDimensions, Point, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::Pixel;
use embedded_graphics_simulator::SimulatorDisplay;
use softedge::render::{RenderError, Renderer};
use softedge::tone::format::{Gray8Format, Rgb565Format, ToneFormat};
use softedge::tone::Profile;
use softedge::BandBuffer;
use softedge_sim::scene::Scene;
use softedge_sim::scene_file::{self, DisplayFormat, Frame, SceneFile};

/// A display that takes whole bands only: every `fill_contiguous` (or
/// `fill_solid`) must be a rectangle inside the display, either beside
/// the previous ones of the band being sent (its rows, other columns) or,
/// once that band's columns are all sent, directly below it, with exactly
/// one colour per pixel.
struct BandsOnly<D> {
    inner: D,
    /// The bands received, in order (each the full width once complete).
    bands: Vec<Rectangle>,
    /// The columns of the last band received so far.
    columns: Vec<(i32, i32)>,
    /// Rectangles received.
    parts: usize,
}

impl<D: OriginDimensions> BandsOnly<D> {
    fn new(inner: D) -> Self {
        Self {
            inner,
            bands: Vec::new(),
            columns: Vec::new(),
            parts: 0,
        }
    }

    /// Columns of the last band received so far.
    fn sent(&self) -> u32 {
        self.columns.iter().map(|&(a, b)| (b - a) as u32).sum()
    }

    /// Takes `area` as a part of the band being sent or the next band.
    fn take(&mut self, area: &Rectangle) {
        let (x0, x1) = (area.top_left.x, area.top_left.x + area.size.width as i32);
        let width = self.inner.size().width;
        let last = self.bands.last().copied();
        match last {
            Some(band) if self.sent() < width => {
                assert_eq!(
                    (area.top_left.y, area.size.height),
                    (band.top_left.y, band.size.height),
                    "{area:?}: the rest of band {band:?}"
                );
                assert!(
                    self.columns.iter().all(|&(a, b)| x1 <= a || b <= x0),
                    "{area:?}: columns of band {band:?} sent twice"
                );
            }
            _ => {
                let next = last.map_or(0, |r| r.top_left.y + r.size.height as i32);
                assert_eq!(
                    area.top_left.y, next,
                    "{area:?}: bands come top to bottom, each once"
                );
                self.columns.clear();
                self.bands.push(Rectangle::new(
                    Point::new(0, area.top_left.y),
                    Size::new(0, area.size.height),
                ));
            }
        }
        self.columns.push((x0, x1));
        self.parts += 1;
        let sent = self.sent();
        if let Some(band) = self.bands.last_mut() {
            band.size.width = sent;
        }
    }
}

impl<D: OriginDimensions> OriginDimensions for BandsOnly<D> {
    fn size(&self) -> Size {
        self.inner.size()
    }
}

impl<D: DrawTarget + OriginDimensions> DrawTarget for BandsOnly<D> {
    type Color = D::Color;
    type Error = D::Error;

    fn draw_iter<I: IntoIterator<Item = Pixel<Self::Color>>>(
        &mut self,
        _: I,
    ) -> Result<(), D::Error> {
        panic!("draw_iter: softedge must send whole bands through fill_contiguous");
    }

    /// A band of one colour: the same checks as `fill_contiguous`.
    fn fill_solid(&mut self, area: &Rectangle, color: Self::Color) -> Result<(), D::Error> {
        let n = (area.size.width * area.size.height) as usize;
        self.fill_contiguous(area, core::iter::repeat_n(color, n))
    }

    fn clear(&mut self, _: Self::Color) -> Result<(), D::Error> {
        panic!("clear: softedge must send whole bands through fill_contiguous");
    }

    fn fill_contiguous<I: IntoIterator<Item = Self::Color>>(
        &mut self,
        area: &Rectangle,
        colors: I,
    ) -> Result<(), D::Error> {
        let size = self.inner.size();
        let bottom = area.top_left.y + area.size.height as i32;
        assert!(
            area.top_left.y >= 0 && bottom <= size.height as i32,
            "{area:?} is outside the display ({size:?})"
        );
        assert!(
            area.top_left.x >= 0 && area.top_left.x + area.size.width as i32 <= size.width as i32,
            "{area:?} is outside the display ({size:?})"
        );
        assert!(
            area.size.width > 0 && area.size.height > 0,
            "{area:?}: an empty band"
        );
        let colors: Vec<Self::Color> = colors.into_iter().collect();
        assert_eq!(
            colors.len(),
            (area.size.width * area.size.height) as usize,
            "{area:?}: one colour per pixel"
        );
        self.take(area);
        self.inner.fill_contiguous(area, colors)
    }
}

fn example(name: &str) -> SceneFile {
    let path: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../examples/scenes")
        .join(name);
    scene_file::load(&path).unwrap_or_else(|d| panic!("{d}"))
}

/// Renders `scene` into a `w x h` simulator display through
/// `softedge::render::Renderer` in bands of `band_rows`, colours from
/// `format`; returns the display and the bands it received.
fn render_to_display<const C: usize, F>(
    scene: &Scene<C>,
    band_rows: u16,
    format: &F,
) -> (SimulatorDisplay<F::Color>, Vec<Rectangle>)
where
    F: ToneFormat<C>,
    F::Color: PixelColor + Default,
    for<'f> &'f F: Profile<C, Color = F::Color>,
{
    let (w, h) = (scene.width, scene.height);
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(w, band_rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(w, band_rows)];
    let display = SimulatorDisplay::with_default_color(
        Size::new(u32::from(w), u32::from(h)),
        F::Color::default(),
    );
    let mut target = BandsOnly::new(display);
    let mut slots = vec![softedge::canvas::WalkSlot::<C>::EMPTY; 64];
    Renderer::<C>::new(&mut acc, &mut cover, &mut slots, w, h, band_rows)
        .unwrap()
        .render(&mut target, format, scene.background, |canvas| {
            canvas.set_style(scene.style);
            scene.draw_into(canvas)
        })
        .unwrap();
    (target.inner, target.bands)
}

/// Checks the bands: `ceil(h / rows)` full-width bands covering the
/// frame top to bottom (BandsOnly checked each part as it came).
fn assert_whole_bands(bands: &[Rectangle], w: u16, h: u16, rows: u16) {
    assert_eq!(bands.len(), usize::from(h.div_ceil(rows)), "rows {rows}");
    let covered: u32 = bands.iter().map(|r| r.size.height).sum();
    assert_eq!(covered, u32::from(h));
    assert!(bands.iter().all(|r| r.size.width == u32::from(w)));
}

/// The display's codes, row by row.
fn display_codes<C>(display: &SimulatorDisplay<C>) -> Vec<u16>
where
    C: PixelColor + IntoStorage,
    C::Storage: Into<u16>,
{
    let size = display.size();
    (0..size.height as i32)
        .flat_map(|y| (0..size.width as i32).map(move |x| Point::new(x, y)))
        .map(|p| display.get_pixel(p).into_storage().into())
        .collect()
}

#[test]
fn rgb565_simulator_display_receives_whole_bands_equal_to_the_host_render() {
    let file = example("gouraud_rgb.toml");
    assert_eq!(file.format, DisplayFormat::Rgb565);
    let Frame::Rgb(scene) = &file.frame else {
        panic!("an RGB scene");
    };
    let want = file.tone(&file.render_linear().unwrap()).codes;
    let format = Rgb565Format::new(file.curve);
    let (w, h) = (scene.width, scene.height);
    for rows in [scene.band_rows, 1, 7, h] {
        let (display, bands): (SimulatorDisplay<Rgb565>, _) =
            render_to_display(scene, rows, &format);
        assert_whole_bands(&bands, w, h, rows);
        assert!(display_codes(&display) == want, "band rows {rows}");
    }
}

#[test]
fn gray8_simulator_display_receives_whole_bands_equal_to_the_host_render() {
    let file = example("quickstart.toml");
    assert_eq!(file.format, DisplayFormat::Gray8);
    let Frame::Gray(scene) = &file.frame else {
        panic!("a gray scene");
    };
    let want = file.tone(&file.render_linear().unwrap()).codes;
    assert!(want.iter().any(|&c| c != want[0]), "something drawn");
    let format = Gray8Format::new(file.curve);
    let (w, h) = (scene.width, scene.height);
    for rows in [scene.band_rows, 5, h] {
        let (display, bands): (SimulatorDisplay<Gray8>, _) =
            render_to_display(scene, rows, &format);
        assert_whole_bands(&bands, w, h, rows);
        assert!(display_codes(&display) == want, "band rows {rows}");
    }
}

/// A disc in the middle of a wide display: its bands come in three
/// parts each (the background left and right of the drawn columns in
/// `fill_solid`s), the pixels those of the host render.
#[test]
fn a_band_may_come_in_parts_side_by_side() {
    use softedge::geom::FinePoint;
    use softedge::path::Circle;
    let (w, h, rows) = (96u16, 24u16, 8u16);
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, rows)];
    let display = SimulatorDisplay::<Gray8>::new(Size::new(u32::from(w), u32::from(h)));
    let mut t = BandsOnly::new(display);
    static GRAY: Gray8Format = Gray8Format::new(softedge::tone::Curve::Srgb);
    let disc = Circle::new(FinePoint::new(48 << 10, 12 << 10), 6 << 10);
    let draw = |c: &mut softedge::canvas::Canvas<'_, '_, 1, Gray8>| {
        use softedge::style::{Blend, FillRule, Opacity};
        c.fill_shape(
            &disc,
            [3000],
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        )
    };
    Renderer::<1>::new(&mut acc, &mut cover, &mut [], w, h, rows)
        .unwrap()
        .render(&mut t, &GRAY, [100], draw)
        .unwrap();
    assert_whole_bands(&t.bands, w, h, rows);
    // Rows 6..18: bands 0..8, 8..16 and 16..24 each in three parts.
    assert_eq!(t.parts, 9);
    let mut whole = SimulatorDisplay::<Gray8>::new(Size::new(u32::from(w), u32::from(h)));
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(w, h)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(w, h)];
    Renderer::<1>::new(&mut acc, &mut cover, &mut [], w, h, h)
        .unwrap()
        .render(&mut whole, &GRAY, [100], draw)
        .unwrap();
    assert!(display_codes(&t.inner) == display_codes(&whole));
}

#[test]
#[should_panic(expected = "draw_iter")]
fn bands_only_refuses_per_pixel_writes() {
    let mut t = BandsOnly::new(SimulatorDisplay::<Gray8>::new(Size::new(4, 4)));
    let _ = t.draw_iter([Pixel(Point::new(1, 1), Gray8::new(9))]);
}

#[test]
#[should_panic(expected = "outside the display")]
fn bands_only_refuses_writes_outside_the_display() {
    let mut t = BandsOnly::new(SimulatorDisplay::<Gray8>::new(Size::new(4, 4)));
    let band = Rectangle::new(Point::new(0, 2), Size::new(4, 4));
    let _ = t.fill_contiguous(&band, [Gray8::new(0); 16]);
}

#[test]
fn a_frame_taller_than_the_display_is_refused_before_anything_is_sent() {
    let mut acc = vec![0i32; BandBuffer::<1>::acc_len(4, 4)];
    let mut cover = vec![0i32; BandBuffer::<1>::cover_len(4, 4)];
    let mut t = BandsOnly::new(SimulatorDisplay::<Gray8>::new(Size::new(4, 4)));
    static GRAY: Gray8Format = Gray8Format::new(softedge::tone::Curve::Srgb);
    let r = Renderer::<1>::new(&mut acc, &mut cover, &mut [], 4, 6, 4)
        .unwrap()
        .render(&mut t, &GRAY, [0], |_| Ok::<(), softedge::DrawError>(()));
    assert_eq!(
        r,
        Err(RenderError::Size {
            frame: (4, 6),
            display: (4, 4)
        })
    );
    assert!(t.bands.is_empty());
}
