//! Images on the canvas: the image's outline (its transformed rectangle,
//! or a clip shape) walked into the scratch like any shape, composed with
//! the image's texels as the paint ([`Paint::Image`]). An opaque image
//! copied texel for pixel, its rectangle on pixel boundaries, is composed
//! row by row without its edges (`BandBuffer::cover_with_image`: the
//! same pixels, none of them partly covered).

use core::ops::Range;

use super::{paths, Canvas, Contour, Outline, WalkKind};
use crate::band::{ComposeOp, Coverage, Paint};
use crate::edge::AreaMode;
use crate::geom::{FinePoint, FINE_BITS};
use crate::image::{AaImage, ImageError, ImageFault, ImageSource};
use crate::path::Shape;
use crate::raster::DrawError;
use crate::style::{FillRule, Opacity};

impl<const C: usize, Col> Canvas<'_, '_, C, Col> {
    /// Draws an image ([`AaImage`]): its transformed rectangle (or its
    /// clip shape) by exact area, painted with the image filtered in
    /// linear light, in painter's order with the image's opacity and blend.
    /// A bad image or transform is not drawn and reported
    /// ([`DrawError::Image`], naming the image).
    ///
    /// ```
    /// use softedge::canvas::Canvas;
    /// use softedge::geom::FinePoint;
    /// use softedge::image::{format::Gray8, AaImage, RawImage};
    /// use softedge::{Band, BandBuffer};
    /// static RAMP: [u8; 4] = [0, 255, 255, 0];
    /// let img = RawImage::<Gray8>::new(&RAMP, 2, 2).unwrap();
    /// let (mut acc, mut cover) = ([0i32; 16 * 8], [0i32; BandBuffer::<1>::cover_len(16, 8)]);
    /// let mut buf = BandBuffer::<1>::new(&mut acc, &mut cover, Band::new(16, 0, 8)).unwrap();
    /// buf.clear([0]);
    /// let mut canvas: Canvas<'_, '_, 1> = Canvas::new(&mut buf, None);
    /// // Whole pixels, unscaled: texel for pixel.
    /// canvas.draw_image(&AaImage::new(&img).position(FinePoint::from_px(3, 2))).unwrap();
    /// assert_eq!(canvas.buffer().lin12(4, 2), Some([4095]));
    /// assert_eq!(canvas.buffer().lin12(3, 2), Some([0]));
    /// ```
    pub fn draw_image<S: ImageSource + ?Sized, K: Shape>(
        &mut self,
        image: &AaImage<'_, S, K>,
    ) -> Result<(), DrawError> {
        let serial = self.next_serial();
        self.image(serial, image)
            .inspect_err(|&e| self.skip(serial, e))
    }

    fn image<S: ImageSource + ?Sized, K: Shape>(
        &mut self,
        serial: u32,
        image: &AaImage<'_, S, K>,
    ) -> Result<(), DrawError> {
        let named = |fault: ImageFault| {
            DrawError::Image(ImageError {
                image: image.name_str(),
                fault,
            })
        };
        let map = image.mapping().map_err(named)?;
        let rect = Contour(&map.corners);
        let tol = crate::path::Tolerance::DEFAULT;
        let clip = image.clip_shape().map(|shape| paths::Filled {
            shape,
            tol,
            bounds: paths::shape_bounds(shape),
        });
        let bounds = match &clip {
            Some(c) => c.bounds(),
            None => rect.bounds(),
        };
        let Some(b) = bounds else {
            return Ok(());
        };
        for (x, y) in [(b.x0, b.y0), (b.x1, b.y1)] {
            let p = crate::geom::FinePoint::new(x, y);
            if !p.in_range() {
                return Err(DrawError::FineCoord(p));
            }
        }
        if !self.touches(&b) {
            return Ok(());
        }
        // The pixels of the band the outline can reach.
        let band = self.buf.band();
        let (rows, cols) = (band.row_range(), band.column_range());
        let xs = (
            (b.x0 >> FINE_BITS).max(cols.start),
            (b.x1 >> FINE_BITS).min(cols.end - 1),
        );
        let ys = (
            (b.y0 >> FINE_BITS).max(rows.start),
            (b.y1 >> FINE_BITS).min(rows.end - 1),
        );
        let tint = image.tint_lin::<C>();
        let op = super::op_of(image.blend_mode(), image.opacity_value());
        // An unscaled image at a whole pixel, opaque, over, unclipped,
        // whose pixels' coverage is exactly whole or none: its rectangle
        // of whole pixels composed directly, without edges.
        let whole_px = match (&clip, WalkKind::of(self.style)) {
            (None, WalkKind::Box(AreaMode::Exact) | WalkKind::Aliased)
                if map.is_copy() && op == ComposeOp::Over(Opacity::OPAQUE) =>
            {
                whole_pixel_rect(&map.corners)
            }
            _ => None,
        };
        let drawn = crate::image::paint(image.source(), &map, tint, (xs, ys), |runs| {
            if let Some((cols, rows)) = whole_px.clone() {
                if self.buf.cover_with_image(runs, cols, rows) {
                    return Ok(());
                }
            }
            let paint = Paint::Image(runs);
            let coverage = Coverage::Rule(FillRule::NonZero);
            match &clip {
                Some(c) => self.fill_outline(serial, 0, c, coverage, &paint, op),
                None => self.fill_outline(serial, 0, &rect, coverage, &paint, op),
            }
        });
        drawn.map_err(named)?
    }
}

/// The pixel columns and rows of a rectangle whose corners `c` (in any
/// order) lie on pixel boundaries with axis-aligned sides; `None` for
/// any other quadrilateral.
fn whole_pixel_rect(c: &[FinePoint; 4]) -> Option<(Range<i32>, Range<i32>)> {
    let (mut x0, mut x1, mut y0, mut y1) = (i32::MAX, i32::MIN, i32::MAX, i32::MIN);
    for p in c {
        (x0, x1, y0, y1) = (x0.min(p.x), x1.max(p.x), y0.min(p.y), y1.max(p.y));
    }
    let on_grid = |v: i32| v & ((1 << FINE_BITS) - 1) == 0;
    let square = c
        .iter()
        .all(|p| (p.x == x0 || p.x == x1) && (p.y == y0 || p.y == y1));
    let distinct = (0..4).all(|i| (i + 1..4).all(|j| c[i] != c[j]));
    (square && distinct && [x0, x1, y0, y1].into_iter().all(on_grid)).then_some((
        (x0 >> FINE_BITS)..(x1 >> FINE_BITS),
        (y0 >> FINE_BITS)..(y1 >> FINE_BITS),
    ))
}
