//! A frame described as data, and its rendering band by band.
//!
//! [`render`] is the firmware loop on a PC: for each [`Band`] of the frame
//! (top to bottom, `band_rows` rows, the last one possibly shorter) it makes
//! a [`BandBuffer`] over one reused pair of buffers, clears it to the
//! background, draws every primitive in order and resolves the band's rows
//! into the image. Nothing here rounds or converts: the image holds exactly
//! the linear 12-bit values [`BandBuffer::resolve_row`] gave.

use std::fmt;

use softedge::{
    Band, BandBuffer, BandError, Bands, DrawError, Line, Polygon, PolygonColors, RenderStyle,
    SubPoint, Triangle,
};

use crate::image::LinImage;

/// Colours of a [`Primitive::Polygon`], owned.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum PolyColors<const C: usize> {
    /// One colour for the whole polygon.
    Flat([u16; C]),
    /// One colour per vertex.
    PerVertex(Vec<[u16; C]>),
}

/// One primitive of a scene, in drawing order.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Primitive<const C: usize> {
    /// A Gouraud triangle.
    Triangle(Triangle<C>),
    /// A simple polygon (convex or concave), vertices owned.
    Polygon {
        /// Vertices in order.
        vertices: Vec<SubPoint>,
        /// Colours.
        colors: PolyColors<C>,
    },
    /// A 1-px line.
    Line(Line<C>),
}

impl<const C: usize> Primitive<C> {
    /// A flat polygon.
    pub fn flat_polygon(vertices: Vec<SubPoint>, color: [u16; C]) -> Self {
        Self::Polygon {
            vertices,
            colors: PolyColors::Flat(color),
        }
    }

    /// Draws this primitive into one band.
    fn draw(&self, buf: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        match self {
            Self::Triangle(t) => t.draw(buf, style),
            Self::Line(l) => l.draw(buf, style),
            Self::Polygon { vertices, colors } => {
                let colors = match colors {
                    PolyColors::Flat(c) => PolygonColors::Flat(*c),
                    PolyColors::PerVertex(cs) => PolygonColors::PerVertex(cs),
                };
                Polygon::new(vertices, colors).draw(buf, style)
            }
        }
    }
}

/// A frame: size, band height, style, background and primitives.
///
/// `C` is the number of colour channels: 1 (gray) or 3 (RGB). Colours are
/// linear 12-bit, `0..=4095`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Scene<const C: usize> {
    /// Frame width in pixels.
    pub width: u16,
    /// Frame height in pixels.
    pub height: u16,
    /// Rows per band (8 matches an SSD1306 page; the result does not depend
    /// on it).
    pub band_rows: u16,
    /// How every primitive is drawn.
    pub style: RenderStyle,
    /// Background, linear 12-bit.
    pub background: [u16; C],
    /// Primitives, in drawing order.
    pub primitives: Vec<Primitive<C>>,
}

impl<const C: usize> Scene<C> {
    /// An empty scene of `width x height`, bands of 8 rows, default
    /// (anti-aliased, exact box) style.
    pub fn new(width: u16, height: u16, background: [u16; C]) -> Self {
        Self {
            width,
            height,
            band_rows: 8,
            style: RenderStyle::default(),
            background,
            primitives: Vec::new(),
        }
    }

    /// The same scene drawn with another style.
    pub fn with_style(&self, style: RenderStyle) -> Self {
        Self {
            style,
            ..self.clone()
        }
    }

    /// The same scene drawn in bands of another height.
    pub fn with_band_rows(&self, band_rows: u16) -> Self {
        Self {
            band_rows,
            ..self.clone()
        }
    }
}

/// Why a scene could not be rendered.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RenderError {
    /// The frame or band size was rejected by [`BandBuffer::new`].
    Band {
        /// The band.
        band: Band,
        /// Why.
        error: BandError,
    },
    /// A primitive was rejected.
    Draw {
        /// Its index in [`Scene::primitives`].
        index: usize,
        /// Why.
        error: DrawError,
    },
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Band { band, error } => write!(
                f,
                "band at row {} ({}x{}) rejected: {error:?}",
                band.y0, band.width, band.rows
            ),
            Self::Draw { index, error } => write!(f, "primitive #{index} rejected: {error:?}"),
        }
    }
}

impl std::error::Error for RenderError {}

/// Renders `scene` band by band into a linear 12-bit image.
///
/// A primitive that [`draw`](Triangle::draw) rejects stops the render with
/// [`RenderError::Draw`] (firmware could skip it; a simulator should say).
pub fn render<const C: usize>(scene: &Scene<C>) -> Result<LinImage<C>, RenderError> {
    let (w, h) = (scene.width, scene.height);
    let rows = scene.band_rows.max(1);
    let mut img = LinImage::new(u32::from(w), u32::from(h));
    // One pair of buffers for the whole frame, as on a microcontroller.
    let mut acc = vec![0i32; BandBuffer::<C>::acc_len(w, rows)];
    let mut cover = vec![0i32; BandBuffer::<C>::cover_len(w, rows)];
    let mut row = vec![[0u16; C]; usize::from(w)];
    for band in Bands::new(w, h, rows) {
        let mut buf = BandBuffer::<C>::new(&mut acc, &mut cover, band)
            .map_err(|error| RenderError::Band { band, error })?;
        buf.clear(scene.background);
        for (index, p) in scene.primitives.iter().enumerate() {
            p.draw(&mut buf, &scene.style)
                .map_err(|error| RenderError::Draw { index, error })?;
        }
        for y in band.y0..band.y0 + i32::from(band.rows) {
            let n = buf.resolve_row(y, &mut row);
            img.set_row(y as u32, &row[..n]);
        }
    }
    Ok(img)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn star_scene() -> Scene<3> {
        let mut s = Scene::new(40, 37, [100, 200, 300]);
        s.primitives.push(Primitive::Triangle(Triangle::new(
            [
                SubPoint::new(3 * 16 + 5, 2 * 16 + 1),
                SubPoint::new(37 * 16 + 9, 9 * 16 + 14),
                SubPoint::new(11 * 16 + 3, 35 * 16 + 7),
            ],
            [[4095, 0, 0], [0, 4095, 0], [0, 0, 4095]],
        )));
        s.primitives.push(Primitive::Line(Line::new(
            SubPoint::new(-40, 600),
            SubPoint::new(700, 3),
            [[4095; 3], [0; 3]],
        )));
        s
    }

    #[test]
    fn band_height_does_not_change_a_bit() {
        let s = star_scene();
        let reference = render(&s.with_band_rows(37)).unwrap();
        for rows in [1, 3, 8, 16, 100] {
            assert_eq!(
                render(&s.with_band_rows(rows)).unwrap(),
                reference,
                "rows {rows}"
            );
        }
    }

    #[test]
    fn rejected_primitive_is_reported_with_its_index() {
        let mut s = star_scene();
        // A bow tie with unequal lobes (a symmetric one has zero signed
        // area and is silently skipped by core as "zero area").
        s.primitives.push(Primitive::flat_polygon(
            vec![
                SubPoint::from_px(0, 0),
                SubPoint::from_px(10, 10),
                SubPoint::from_px(10, 0),
                SubPoint::from_px(0, 20),
            ],
            [1; 3],
        ));
        let Err(err) = render(&s) else {
            panic!("a self-intersecting polygon was drawn");
        };
        assert_eq!(
            err,
            RenderError::Draw {
                index: 2,
                error: DrawError::SelfIntersecting
            }
        );
        assert!(err.to_string().contains("#2"));
    }

    #[test]
    fn empty_frame_is_background() {
        let img = render(&Scene::<1>::new(5, 3, [77])).unwrap();
        assert!(img.pixels().all(|p| p == [77]));
    }
}
