//! # softedge-refscenes
//!
//! The reference scenes that the host and the firmware boards render, as
//! plain Rust data (consts in flash, no heap), and the one renderer they
//! share: [`render_crc`] draws a scene band by band into caller-provided
//! buffers and returns the CRC-32 of its display byte stream
//! ([`stream::encode_row`]). Equal CRCs on the host, on Cortex-M0 and on
//! Cortex-M3 are the bit-identity check of `DESIGN.md`.
//!
//! ```
//! use softedge_refscenes::{render_crc, Buffers, ACC_LEN, COVERED_LEN, COVER_LEN, DEPTH_LEN, SCENES};
//! let (mut acc, mut cover) = ([0i32; ACC_LEN], [0i32; COVER_LEN]);
//! let (mut depth, mut covered) = ([0u16; DEPTH_LEN], [0u16; COVERED_LEN]);
//! let mut bufs = Buffers { acc: &mut acc, cover: &mut cover, depth: &mut depth, covered: &mut covered };
//! for scene in SCENES {
//!     let crc = render_crc(scene, &mut bufs).unwrap();
//!     println!("crc {} {:08x}", scene.name, crc);
//! }
//! ```
//!
//! Buffers: a scene of `C` channels needs
//! `BandBuffer::<C>::acc_len(width, band_rows)` and
//! `BandBuffer::<C>::cover_len(width, band_rows)` `i32`s, and a scene with
//! the z-buffer `DepthBuffer::len(width, band_rows)` `u16`s twice;
//! [`ACC_LEN`], [`COVER_LEN`], [`DEPTH_LEN`] and [`COVERED_LEN`] are the largest over
//! [`SCENES`], so a firmware sizes its static buffers with them once.
#![no_std]
#![forbid(unsafe_code)]
#![deny(missing_docs)]

mod crc;
mod scenes;
pub mod stream;

pub use crc::{crc32, Crc32, POLY_REFLECTED, TABLE as CRC_TABLE};
pub use scenes::{
    ALIASED, DIAL, GOURAUD, IMAGE, LIMITS, LINES, MESH, ONEBIT, SEEDBOX, SPHERE3D, ZBUFFER,
};

use softedge::hsr::{zbuffer_passes, DepthBuffer, DepthTriangle, HsrError, ZPass};
use softedge::path;
use softedge::scene3d;
use softedge::{
    BandBuffer, BandError, Bands, DrawError, Line, Polygon, PolygonColors, RenderStyle, SubPoint,
    Triangle, MAX_POLYGON_VERTICES,
};

/// Widest scene [`render_crc`] accepts: the resolved row lives on the
/// stack, `MAX_SCENE_WIDTH * 3 * 2` bytes (and the dither error row
/// `MAX_SCENE_WIDTH * 2`; both count on a 16 KiB Cortex-M0).
pub const MAX_SCENE_WIDTH: u16 = 96;

/// Every reference scene, in the order the listings print them.
pub const SCENES: &[&Scene] = &[
    &GOURAUD, &MESH, &LINES, &ALIASED, &ONEBIT, &SEEDBOX, &LIMITS, &SPHERE3D, &ZBUFFER, &IMAGE,
    &DIAL,
];

/// `i32`s of `acc` that every scene of [`SCENES`] fits in.
pub const ACC_LEN: usize = max_len(SCENES, Need::Acc);
/// `i32`s of `cover` that every scene of [`SCENES`] fits in.
pub const COVER_LEN: usize = max_len(SCENES, Need::Cover);
/// `u16`s of `depth` that every scene of [`SCENES`] fits in (at least 1).
pub const DEPTH_LEN: usize = max_len(SCENES, Need::Depth);
/// `u16`s of `covered` that every scene of [`SCENES`] fits in: two per
/// pixel of `depth` (coverage count and sample mask,
/// `softedge::hsr::DepthBuffer::covered_len`).
pub const COVERED_LEN: usize = 2 * DEPTH_LEN;

#[derive(Clone, Copy)]
enum Need {
    Acc,
    Cover,
    Depth,
}

const fn max_len(scenes: &[&Scene], need: Need) -> usize {
    let mut max = 1;
    let mut k = 0;
    while k < scenes.len() {
        let s = scenes[k];
        let n = match need {
            Need::Acc => s.buffer_len(true),
            Need::Cover => s.buffer_len(false),
            Need::Depth => s.depth_len(),
        };
        if n > max {
            max = n;
        }
        k += 1;
    }
    max
}

/// The band buffers a scene is rendered into (see the crate docs for
/// their sizes).
#[derive(Debug)]
pub struct Buffers<'a> {
    /// The accumulator.
    pub acc: &'a mut [i32],
    /// The cover scratch.
    pub cover: &'a mut [i32],
    /// The z-buffer's depths (scenes with [`Scene::zbuffer`]).
    pub depth: &'a mut [u16],
    /// The z-buffer's coverage counts and sample masks.
    pub covered: &'a mut [u16],
}

/// A reference scene.
#[derive(Debug, Clone, Copy)]
pub struct Scene {
    /// Name printed in the CRC listings (one word).
    pub name: &'static str,
    /// Frame width in pixels.
    pub width: u16,
    /// Frame height in pixels.
    pub height: u16,
    /// 1 (gray) or 3 (RGB).
    pub channels: u8,
    /// What the display takes: the tone stage between the band and the
    /// byte stream.
    pub format: stream::Format,
    /// Rows per band.
    pub band_rows: u16,
    /// How the primitives are drawn.
    pub style: RenderStyle,
    /// Background, linear 12-bit (only the first `channels` are used).
    pub background: [u16; 3],
    /// What is drawn, in order.
    pub shapes: &'static [Shape],
    /// Hidden surfaces by the z-buffer (`softedge::hsr`): the shapes are
    /// then [`Shape::Depth`] triangles, given front to back (in the order
    /// `softedge::hsr::sort_front_to_back` puts them, which a test checks).
    pub zbuffer: bool,
}

impl Scene {
    /// `i32`s the scene needs in `acc` (`acc == true`) or `cover`, at its
    /// own band height; 0 for an unsupported channel count.
    pub const fn buffer_len(&self, acc: bool) -> usize {
        let (w, r) = (self.width, self.band_rows);
        match (self.channels, acc) {
            (1, true) => BandBuffer::<1>::acc_len(w, r),
            (1, false) => BandBuffer::<1>::cover_len(w, r),
            (3, true) => BandBuffer::<3>::acc_len(w, r),
            (3, false) => BandBuffer::<3>::cover_len(w, r),
            _ => 0,
        }
    }

    /// `u16`s the scene needs in each of `depth` and `covered`: 0 without
    /// the z-buffer.
    pub const fn depth_len(&self) -> usize {
        if self.zbuffer {
            DepthBuffer::len(self.width, self.band_rows)
        } else {
            0
        }
    }
}

/// The fill of a [`Shape::Polygon`].
#[derive(Debug, Clone, Copy)]
pub enum Fill {
    /// One colour.
    Flat([u16; 3]),
    /// One colour per vertex (as many as vertices).
    PerVertex(&'static [[u16; 3]]),
}

/// One primitive of a scene. Colours are linear 12-bit, always given for
/// three channels; a gray scene uses the first.
#[derive(Debug, Clone, Copy)]
pub enum Shape {
    /// A Gouraud triangle.
    Triangle([SubPoint; 3], [[u16; 3]; 3]),
    /// A 1-px line, colour interpolated along it.
    Line(SubPoint, SubPoint, [[u16; 3]; 2]),
    /// A simple polygon.
    Polygon(&'static [SubPoint], Fill),
    /// A lit 3D object, projected by `softedge::scene3d` in every band.
    Object(&'static Object3d),
    /// A triangle with a depth per vertex (larger is nearer), for scenes
    /// with the z-buffer.
    Depth([SubPoint; 3], [[u16; 3]; 3], [u16; 3]),
    /// An image (`softedge::image::AaImage`), added to the band (seed
    /// 000's accumulation, as every shape above).
    Image(&'static ImageShape),
    /// A circle (`softedge::path::Circle`) filled, or stroked (a ring),
    /// through a canvas, composed over what is drawn before it (painter's
    /// order, `Blend::Over`: a scene with circles or arcs holds no shapes
    /// that add, and its scene file says `blend = "over"`). RGB scenes
    /// only, as [`Shape::Image`].
    Circle(path::Circle, Pen, [u16; 3]),
    /// An arc (`softedge::path::Arc`), stroked (or filled: the region
    /// between the arc and its chord) through a canvas, over, as
    /// [`Shape::Circle`].
    Arc(path::Arc, Pen, [u16; 3]),
}

/// How a [`Shape::Circle`] or [`Shape::Arc`] is painted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Pen {
    /// Filled (non-zero rule).
    Fill,
    /// Stroked, solid and centred, miter joins.
    Stroke {
        /// Width, 1/1024 px.
        width: u32,
        /// The caps of an open outline.
        cap: path::LineCap,
    },
}

impl Shape {
    /// Whether the shape is composed over what is drawn before it
    /// ([`Shape::Circle`], [`Shape::Arc`]) rather than added.
    pub const fn is_over(&self) -> bool {
        matches!(self, Shape::Circle(..) | Shape::Arc(..))
    }
}

/// An image of a scene: 8-bit RGBA texels (straight alpha, rows top to
/// bottom), drawn by `softedge::image` as a `[[image]]` of a scene file
/// draws the PNG file `file` (the same texels) beside the scene files.
#[derive(Debug, Clone, Copy)]
pub struct ImageShape {
    /// Width, texels.
    pub width: u16,
    /// Height, texels.
    pub height: u16,
    /// `width x height x 4` bytes.
    pub rgba: &'static [u8],
    /// The PNG file of the same texels, in `refscenes/scenes/`.
    pub file: &'static str,
    /// Where the image's centre lands, 1/1024 px.
    pub center: (i32, i32),
    /// Horizontal and vertical scale, 1/65536.
    pub scale: (u32, u32),
    /// Clockwise, 1/65536 degree.
    pub rotate: i32,
    /// 1/4096.
    pub opacity: u16,
}

/// Largest mesh a reference [`Object3d`] may have (vertices, triangles):
/// an 8-segment sphere, so the mesh and its projection scratch (about
/// 1.4 KiB, on the stack) fit the Cortex-M0's 16 KiB beside the band
/// buffers (10 segments did not).
pub const OBJECT_VERTICES: usize = 26;
/// See [`OBJECT_VERTICES`].
pub const OBJECT_TRIANGLES: usize = 48;

/// A canonical object seen through a camera, lit by one directional light.
#[derive(Debug, Clone, Copy)]
pub struct Object3d {
    /// The object (at most [`OBJECT_VERTICES`] / [`OBJECT_TRIANGLES`]).
    pub shape: scene3d::Shape,
    /// Rotation about x, then y, then z.
    pub rotation: [scene3d::Angle; 3],
    /// Linear 12-bit colour per channel.
    pub color: [u16; 3],
    /// The camera.
    pub camera: scene3d::Camera,
    /// Direction towards the light.
    pub to_light: scene3d::Vec3,
    /// Ambient and diffuse weights, 4096 = 1.
    pub ambient_diffuse: [u16; 2],
}

/// Why a scene could not be rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Error {
    /// The band buffer could not be made (buffers too small, bad size).
    Band(BandError),
    /// A primitive was rejected by core.
    Draw(DrawError),
    /// A 3D object could not be built or projected.
    Scene(scene3d::SceneError),
    /// `channels` is neither 1 nor 3.
    Channels,
    /// Wider than [`MAX_SCENE_WIDTH`].
    TooWide,
    /// The z-buffer failed.
    Hsr(HsrError),
    /// A z-buffer scene holds a shape that is not a depth triangle.
    NotDepth,
}

impl From<BandError> for Error {
    fn from(e: BandError) -> Self {
        Self::Band(e)
    }
}

impl From<DrawError> for Error {
    fn from(e: DrawError) -> Self {
        Self::Draw(e)
    }
}

/// Renders `scene` band by band into `acc` / `cover` and returns the
/// CRC-32 ([`Crc32`]) of its display byte stream ([`stream::encode_row`]).
pub fn render_crc(scene: &Scene, bufs: &mut Buffers<'_>) -> Result<u32, Error> {
    render_crc_rows(scene, scene.band_rows, bufs)
}

/// [`render_crc`] with `band_rows` rows per band instead of the scene's
/// own (the bytes must not depend on it).
pub fn render_crc_rows(
    scene: &Scene,
    band_rows: u16,
    bufs: &mut Buffers<'_>,
) -> Result<u32, Error> {
    let mut crc = Crc32::new();
    match scene.channels {
        1 => render::<1>(scene, band_rows, bufs, &mut crc)?,
        3 => render::<3>(scene, band_rows, bufs, &mut crc)?,
        _ => return Err(Error::Channels),
    }
    Ok(crc.finish())
}

/// Renders `scene` into `sink`, band by band.
pub fn render<const C: usize>(
    scene: &Scene,
    band_rows: u16,
    bufs: &mut Buffers<'_>,
    sink: &mut impl stream::ByteSink,
) -> Result<(), Error> {
    if scene.width > MAX_SCENE_WIDTH {
        return Err(Error::TooWide);
    }
    let mut row = [[0u16; C]; MAX_SCENE_WIDTH as usize];
    let row = row
        .get_mut(..usize::from(scene.width))
        .ok_or(Error::TooWide)?;
    // The Floyd–Steinberg error row, carried across bands.
    let mut err = [0i16; MAX_SCENE_WIDTH as usize];
    let mut encoder = stream::Encoder::new(scene, &mut err);
    for band in Bands::new(scene.width, scene.height, band_rows) {
        let mut buf = BandBuffer::<C>::new(bufs.acc, bufs.cover, band)?;
        buf.clear(channels(scene.background));
        if scene.zbuffer {
            let mut zbuf = DepthBuffer::new(bufs.depth, bufs.covered, band)?;
            draw_zbuffer(scene, &mut buf, &mut zbuf)?;
        } else {
            for shape in scene.shapes {
                match shape {
                    Shape::Object(o) => draw_object(o, scene, &mut buf)?,
                    Shape::Image(i) => draw_image(i, &mut buf, &scene.style)?,
                    Shape::Circle(..) | Shape::Arc(..) => {
                        draw_round(shape, &mut buf, &scene.style)?
                    }
                    _ => draw(shape, &mut buf, &scene.style)?,
                }
            }
        }
        for r in 0..band.rows {
            let y = band.y0 + i32::from(r);
            buf.resolve_row(y, row);
            // Bands start at row 0 and stop at `height`, so `y` fits.
            encoder.row(y as u16, row, sink);
        }
    }
    Ok(())
}

/// Draws a z-buffer scene's depth triangles into the band, pass by pass
/// (the passes and order of `softedge::hsr::draw_zbuffer`, without a
/// triangle store: the shapes are read again in each pass).
// This, `draw` and `draw_object` are out of line: inlined into `render`,
// their locals shared one 4.3 KB frame, and the Cortex-M0 check's stack
// (16 KiB micro:bit) came within 472 bytes of the statics.
#[inline(never)]
fn draw_zbuffer<const C: usize>(
    scene: &Scene,
    buf: &mut BandBuffer<'_, C>,
    zbuf: &mut DepthBuffer<'_>,
) -> Result<(), Error> {
    for &pass in zbuffer_passes(&scene.style) {
        for shape in scene.shapes {
            let Some(t) = depth_triangle::<C>(shape) else {
                return Err(Error::NotDepth);
            };
            t.draw_z(buf, zbuf, &scene.style, pass)
                .map_err(Error::Hsr)?;
        }
        if pass == ZPass::Centres {
            zbuf.finish_centres();
        }
    }
    Ok(())
}

/// A [`Shape::Depth`] as core's triangle with `C` channels.
pub fn depth_triangle<const C: usize>(shape: &Shape) -> Option<DepthTriangle<C>> {
    match *shape {
        Shape::Depth(v, c, z) => Some(DepthTriangle::new(v, c.map(channels), z)),
        _ => None,
    }
}

/// The first `C` of three channels (0 past the third).
fn channels<const C: usize>(c: [u16; 3]) -> [u16; C] {
    let mut out = [0u16; C];
    for (o, v) in out.iter_mut().zip(c) {
        *o = v;
    }
    out
}

#[inline(never)]
fn draw<const C: usize>(
    shape: &Shape,
    buf: &mut BandBuffer<'_, C>,
    style: &RenderStyle,
) -> Result<(), DrawError> {
    match *shape {
        Shape::Triangle(v, c) => Triangle::new(v, c.map(channels)).draw(buf, style),
        Shape::Line(a, b, c) => Line::new(a, b, c.map(channels)).draw(buf, style),
        Shape::Polygon(v, Fill::Flat(c)) => {
            Polygon::new(v, PolygonColors::Flat(channels(c))).draw(buf, style)
        }
        Shape::Polygon(v, Fill::PerVertex(c)) => {
            let mut colors = [[0u16; C]; MAX_POLYGON_VERTICES];
            for (o, &k) in colors.iter_mut().zip(c) {
                *o = channels(k);
            }
            // More colours than MAX_POLYGON_VERTICES: core rejects the
            // vertex count (or the count mismatch) itself.
            let n = c.len().min(MAX_POLYGON_VERTICES);
            let colors = colors.get(..n).unwrap_or(&[]);
            Polygon::new(v, PolygonColors::PerVertex(colors)).draw(buf, style)
        }
        // Drawn by `draw_object`, which needs the scene's frame, by
        // `draw_image` and by `draw_round`.
        Shape::Object(_) | Shape::Image(_) | Shape::Circle(..) | Shape::Arc(..) => Ok(()),
        // Without the z-buffer, a depth triangle is a plain triangle.
        Shape::Depth(v, c, _) => Triangle::new(v, c.map(channels)).draw(buf, style),
    }
}

/// Draws an image into the band through a canvas, added. RGB scenes only
/// (a gray scene draws none): each instance of the image code costs the
/// Cortex-M0 firmware's 256 KiB of flash some 18 KB.
#[inline(never)]
fn draw_image<const C: usize>(
    i: &ImageShape,
    buf: &mut BandBuffer<'_, C>,
    style: &RenderStyle,
) -> Result<(), DrawError> {
    if C != 3 {
        return Ok(());
    }
    use softedge::image::{format::Rgba8888, AaImage, ImageError, RawImage, Scale};
    let src = RawImage::<Rgba8888>::new(i.rgba, i.width, i.height).map_err(|fault| {
        DrawError::Image(ImageError {
            image: i.file,
            fault,
        })
    })?;
    let mut canvas = softedge::canvas::Canvas::new(buf, None);
    canvas.set_style(*style);
    let img = AaImage::new(&src)
        .center(softedge::geom::FinePoint::new(i.center.0, i.center.1))
        .scale_xy(Scale::from_bits(i.scale.0), Scale::from_bits(i.scale.1))
        .rotate(softedge::path::Degrees::from_bits(i.rotate))
        .opacity(softedge::style::Opacity::from_4096ths(i.opacity))
        .blend(softedge::style::Blend::Add)
        .name(i.file);
    canvas.draw_image(&img)
}

/// Draws a circle or an arc into the band through a canvas, over (the
/// way an application draws them: circles, rings and stroked arcs take
/// core's exact circle areas). RGB scenes only (a gray scene draws none),
/// for the Cortex-M0 firmware's flash, as [`draw_image`].
#[inline(never)]
fn draw_round<const C: usize>(
    shape: &Shape,
    buf: &mut BandBuffer<'_, C>,
    style: &RenderStyle,
) -> Result<(), DrawError> {
    if C != 3 {
        return Ok(());
    }
    let mut canvas = softedge::canvas::Canvas::new(buf, None);
    canvas.set_style(*style);
    match *shape {
        Shape::Circle(ref c, pen, color) => paint_round(&mut canvas, c, pen, channels(color)),
        Shape::Arc(ref a, pen, color) => paint_round(&mut canvas, a, pen, channels(color)),
        _ => Ok(()),
    }
}

/// Fills or strokes `shape` over the canvas, opaque.
fn paint_round<const C: usize, S: path::Shape>(
    canvas: &mut softedge::canvas::Canvas<'_, '_, C>,
    shape: &S,
    pen: Pen,
    color: [u16; C],
) -> Result<(), DrawError> {
    use softedge::style::{Blend, FillRule, Opacity};
    match pen {
        Pen::Fill => canvas.fill_shape(
            shape,
            color,
            FillRule::NonZero,
            Blend::Over,
            Opacity::OPAQUE,
        ),
        Pen::Stroke { width, cap } => {
            let style = path::StrokeStyle::new(width).with_cap(cap);
            canvas.stroke_shape(shape, &style, color, Blend::Over, Opacity::OPAQUE)
        }
    }
}

/// Builds, lights and projects a 3D object, drawing its front faces into
/// the band (back-face culling only: use convex objects).
#[inline(never)]
fn draw_object<const C: usize>(
    o: &Object3d,
    scene: &Scene,
    buf: &mut BandBuffer<'_, C>,
) -> Result<(), Error> {
    let mesh =
        scene3d::Mesh::<OBJECT_VERTICES, OBJECT_TRIANGLES>::new(&o.shape).map_err(Error::Scene)?;
    let [rx, ry, rz] = o.rotation;
    let transform = scene3d::Transform::rotation_x(rx)
        .then(&scene3d::Transform::rotation_y(ry))
        .and_then(|t| t.then(&scene3d::Transform::rotation_z(rz)))
        .map_err(Error::Scene)?;
    let view = o
        .camera
        .view(scene.width, scene.height)
        .map_err(Error::Scene)?;
    let [ambient, diffuse] = o.ambient_diffuse;
    let light = scene3d::Light::new(o.to_light, [ambient; C], [diffuse; C]);
    let mut scratch = [scene3d::ViewVertex::<C>::EMPTY; OBJECT_VERTICES];
    let mut result = Ok(());
    scene3d::project_mesh(
        mesh.as_ref(),
        &transform,
        channels(o.color),
        &view,
        &light,
        &mut scratch,
        |t| {
            if result.is_ok() {
                result = t.draw(buf, &scene.style);
            }
        },
    )
    .map_err(Error::Scene)?;
    result.map_err(Error::Draw)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Runs `f` with buffers big enough for every scene at any band height
    /// up to 64 rows.
    fn with_buffers<R>(f: impl FnOnce(&mut Buffers<'_>) -> R) -> R {
        const BIG: usize = 3 * 128 * 64;
        let mut acc = [0i32; BIG];
        let mut cover = [0i32; 130 * 64];
        let (mut depth, mut covered) = ([0u16; 128 * 64], [0u16; 2 * 128 * 64]);
        f(&mut Buffers {
            acc: &mut acc,
            cover: &mut cover,
            depth: &mut depth,
            covered: &mut covered,
        })
    }

    #[test]
    fn every_scene_renders_and_fits_the_shared_buffers() {
        let (mut acc, mut cover) = ([0i32; ACC_LEN], [0i32; COVER_LEN]);
        let (mut depth, mut covered) = ([0u16; DEPTH_LEN], [0u16; COVERED_LEN]);
        let mut bufs = Buffers {
            acc: &mut acc,
            cover: &mut cover,
            depth: &mut depth,
            covered: &mut covered,
        };
        for scene in SCENES {
            assert!(scene.width <= MAX_SCENE_WIDTH, "{}", scene.name);
            assert!(scene.buffer_len(true) > 0, "{}", scene.name);
            render_crc(scene, &mut bufs).unwrap_or_else(|e| panic!("{}: {e:?}", scene.name));
        }
    }

    #[test]
    fn scene_names_are_unique_words() {
        for (i, a) in SCENES.iter().enumerate() {
            assert!(!a.name.is_empty() && !a.name.contains(char::is_whitespace));
            for b in &SCENES[i + 1..] {
                assert_ne!(a.name, b.name);
            }
        }
    }

    /// Core promises the same bits whatever the band height: the display
    /// stream of every scene is the same for 1 row, its own rows, and the
    /// whole frame as one band.
    #[test]
    fn crc_does_not_depend_on_band_height() {
        with_buffers(|bufs| {
            for scene in SCENES {
                let own = render_crc(scene, bufs).unwrap();
                for rows in [1, 3, scene.height] {
                    let other = render_crc_rows(scene, rows, bufs).unwrap();
                    assert_eq!(own, other, "{} with {rows} rows", scene.name);
                }
            }
        });
    }

    #[test]
    fn short_buffers_are_an_error_not_a_panic() {
        let (mut acc, mut cover) = ([0i32; 8], [0i32; 8]);
        let (mut depth, mut covered) = ([0u16; 8], [0u16; 8]);
        let mut bufs = Buffers {
            acc: &mut acc,
            cover: &mut cover,
            depth: &mut depth,
            covered: &mut covered,
        };
        assert_eq!(
            render_crc(&GOURAUD, &mut bufs),
            Err(Error::Band(BandError::AccTooSmall))
        );
        with_buffers(|big| {
            let mut bufs = Buffers {
                acc: big.acc,
                cover: big.cover,
                depth: &mut depth,
                covered: &mut covered,
            };
            assert_eq!(
                render_crc(&ZBUFFER, &mut bufs),
                Err(Error::Band(BandError::DepthTooSmall))
            );
        });
    }

    #[test]
    fn scenes_are_not_blank() {
        // A scene whose stream equals the bare background's tests nothing.
        with_buffers(|bufs| {
            for scene in SCENES {
                let blank = Scene {
                    shapes: &[],
                    ..**scene
                };
                assert_ne!(
                    render_crc(scene, bufs).unwrap(),
                    render_crc(&blank, bufs).unwrap(),
                    "{}",
                    scene.name
                );
            }
        });
    }

    /// A scene file has one blend for all its shapes: a scene with circles
    /// or arcs (composed over) holds nothing that adds, is RGB (gray
    /// scenes draw no circles) and has no z-buffer.
    #[test]
    fn scenes_with_circles_or_arcs_hold_only_those() {
        for scene in SCENES {
            if scene.shapes.iter().any(Shape::is_over) {
                assert!(scene.shapes.iter().all(Shape::is_over), "{}", scene.name);
                assert_eq!(scene.channels, 3, "{}", scene.name);
                assert!(!scene.zbuffer, "{}", scene.name);
            }
        }
    }

    /// The dial's circles and arcs drawn over, one by one, each against
    /// the frame without it: every one of them changes some pixel (none is
    /// hidden or off the frame).
    #[test]
    fn every_shape_of_the_dial_shows() {
        with_buffers(|bufs| {
            let all = render_crc(&DIAL, bufs).unwrap();
            for k in 0..DIAL.shapes.len() {
                extern crate std;
                let mut shapes = std::vec::Vec::from(DIAL.shapes);
                shapes.remove(k);
                let without = Scene {
                    shapes: std::boxed::Box::leak(shapes.into_boxed_slice()),
                    ..DIAL
                };
                assert_ne!(render_crc(&without, bufs).unwrap(), all, "shape {k}");
            }
        });
    }

    /// Every circle and arc of the dial takes core's exact circle areas
    /// (`edge::disc`), not the flattened outline: drawn with a shape cache
    /// (room for 4096 segments), none is described into it (a
    /// square-capped arc, which has no exact path, is: the control).
    #[test]
    fn the_dial_draws_its_circles_and_arcs_exactly() {
        use softedge::canvas::{Canvas, ShapeCache, ShapeEntry};
        use softedge::Band;
        let described = |shape: &Shape, bufs: &mut Buffers<'_>| {
            let band = Band::new(DIAL.width, 0, DIAL.height);
            let mut buf = BandBuffer::<3>::new(bufs.acc, bufs.cover, band).unwrap();
            buf.clear(DIAL.background);
            let mut segments = [path::Segment::default(); 4096];
            let mut entries = [ShapeEntry::EMPTY; 2];
            let shapes = ShapeCache::new(&mut segments, &mut entries, 0);
            let mut canvas = Canvas::new(&mut buf, None).with_shapes(shapes);
            canvas.set_style(DIAL.style);
            match *shape {
                Shape::Circle(ref c, pen, color) => paint_round(&mut canvas, c, pen, color),
                Shape::Arc(ref a, pen, color) => paint_round(&mut canvas, a, pen, color),
                _ => panic!("not a circle or an arc"),
            }
            .unwrap();
            canvas.shape_stats().1
        };
        with_buffers(|bufs| {
            for (k, shape) in DIAL.shapes.iter().enumerate() {
                assert_eq!(described(shape, bufs), 0, "shape {k}: {shape:?}");
            }
            let Shape::Arc(a, _, color) = DIAL.shapes[2] else {
                panic!("the track is an arc")
            };
            let square = Pen::Stroke {
                width: 5 * 1024,
                cap: path::LineCap::Square,
            };
            assert_eq!(described(&Shape::Arc(a, square, color), bufs), 1);
        });
    }

    /// The z-buffer scene lists its triangles in the order
    /// `sort_front_to_back` gives (what the host simulator draws them in).
    #[test]
    fn zbuffer_shapes_are_sorted_front_to_back() {
        extern crate std;
        use std::vec::Vec;
        for scene in SCENES.iter().filter(|s| s.zbuffer) {
            let tris: Vec<DepthTriangle<3>> = scene
                .shapes
                .iter()
                .map(|s| depth_triangle::<3>(s).expect("depth triangles only"))
                .collect();
            let mut sorted = tris.clone();
            softedge::hsr::sort_front_to_back(&mut sorted);
            assert_eq!(tris, sorted, "{}", scene.name);
        }
    }
}
