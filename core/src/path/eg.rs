//! embedded-graphics' primitives as softedge shapes (feature
//! `embedded-graphics`).
//!
//! Takes `embedded_graphics::primitives::{Circle, Ellipse, Arc, Sector,
//! Rectangle, RoundedRectangle, Polyline, Line}` and `PrimitiveStyle`;
//! gives the shapes of [`path`](crate::path) with the same geometry, its
//! pixel conventions made explicit in continuous coordinates (pixel
//! `(i, j)` is the square `[i, i+1) x [j, j+1)`):
//!
//! | embedded-graphics | continuous geometry |
//! | --- | --- |
//! | `Point` (vertex of a `Line`, `Polyline`) | the pixel's centre, `(x + 1/2, y + 1/2)` |
//! | `Rectangle { top_left, size }` | `[x, x + w) x [y, y + h)` |
//! | `Circle { top_left, diameter }` | inscribed in the square `[x, x + d)^2`: centre `top_left + d/2`, radius `d/2` |
//! | `Ellipse { top_left, size }` | inscribed in the rectangle: centre `top_left + size/2`, semi-axes `w/2`, `h/2` |
//! | `Arc`, `Sector` | on that circle; angles clockwise on screen from +x (its `Angle`, decoded from the `f32` bits with integer operations) |
//! | `RoundedRectangle` | the rectangle; each corner a quarter ellipse of semi-axes `(width, height)` of its `Size`, confined as embedded-graphics does (`confine_radii`, here in exact arithmetic: no overflow for any radii), then by CSS's rule |
//! | `Polyline { translate, vertices }` | through the vertices' pixel centres, plus `translate` |
//! | `PrimitiveStyle` | [`StrokeStyle`]: width in px; `StrokeAlignment` kept; miter joins with limit 4 (embedded-graphics bevels a miter longer than twice the width); butt caps |
//!
//! So a shape's bounding box here is embedded-graphics' `bounding_box()`
//! exactly (for a `Line`, the segment between the two pixel centres; its
//! stroke's butt ends lie on them). Two conventions differ on purpose:
//! a centred stroke of odd width lies half on each side (embedded-graphics
//! puts the extra pixel inside, as whole pixels force it to), and a
//! `Line` drawn by embedded-graphics lights both end pixels fully, which
//! is the continuous stroke with square caps for a 1-px line.

use embedded_graphics::geometry::{Angle, Point, Size};
use embedded_graphics::pixelcolor::PixelColor;
use embedded_graphics::primitives as eg;

use crate::geom::{FinePoint, FINE_ONE};

use super::{
    Arc, Circle, CornerRadii, Degrees, Ellipse, Line, Polyline, Rectangle, RoundedRectangle,
    Sector, StrokeAlignment, StrokeStyle,
};

/// Pixels to fine units, saturating.
fn fine(v: u32) -> u32 {
    v.saturating_mul(FINE_ONE as u32)
}

/// The top-left corner of a pixel, fine units.
fn corner(p: Point) -> FinePoint {
    FinePoint::from_px(p.x, p.y)
}

/// `top_left + size / 2` in fine units.
fn centre(top_left: Point, size: Size) -> FinePoint {
    let c = corner(top_left);
    let half = |v: u32| (i64::from(v) * i64::from(FINE_ONE) / 2).min(i64::from(i32::MAX)) as i32;
    FinePoint::new(
        c.x.saturating_add(half(size.width)),
        c.y.saturating_add(half(size.height)),
    )
}

/// An embedded-graphics angle as [`Degrees`].
///
/// ```
/// use embedded_graphics::geometry::AngleUnit;
/// use softedge::path::{eg::degrees, Degrees};
/// assert!((degrees(90.0.deg()).bits() - Degrees::new(90).bits()).abs() <= 2);
/// ```
pub fn degrees(a: Angle) -> Degrees {
    Degrees::from_f32_radians_bits(a.to_radians().to_bits())
}

impl From<eg::Circle> for Circle {
    fn from(c: eg::Circle) -> Self {
        Circle::new(
            centre(c.top_left, Size::new(c.diameter, c.diameter)),
            fine(c.diameter) / 2,
        )
    }
}

impl From<eg::Ellipse> for Ellipse {
    fn from(e: eg::Ellipse) -> Self {
        Ellipse::new(
            centre(e.top_left, e.size),
            fine(e.size.width) / 2,
            fine(e.size.height) / 2,
        )
    }
}

impl From<eg::Arc> for Arc {
    fn from(a: eg::Arc) -> Self {
        let c = Circle::from(eg::Circle::new(a.top_left, a.diameter));
        Arc::new(
            c.centre,
            c.radius,
            degrees(a.angle_start),
            degrees(a.angle_sweep),
        )
    }
}

impl From<eg::Sector> for Sector {
    fn from(s: eg::Sector) -> Self {
        let c = Circle::from(eg::Circle::new(s.top_left, s.diameter));
        Sector::new(
            c.centre,
            c.radius,
            degrees(s.angle_start),
            degrees(s.angle_sweep),
        )
    }
}

impl From<eg::Rectangle> for Rectangle {
    fn from(r: eg::Rectangle) -> Self {
        Rectangle::new(corner(r.top_left), fine(r.size.width), fine(r.size.height))
    }
}

/// The corner sizes of `c` confined to a `size` rectangle as
/// embedded-graphics' `confine_radii` does, in exact arithmetic: the side
/// whose two radii overlap it most (the first of equals, in the order
/// top, right, bottom, left) gives the scale `side / sum`, and every
/// radius is `radius * side / sum`, rounded down.
///
/// embedded-graphics 0.8 adds and multiplies the radii in `u32`: radii
/// over 2^31 (a sum) or whose product with the side passes 2^32 panic in
/// debug builds and wrap in release (issue #36, G1). Here the sums are
/// `u64` (two `u32`s) and so are the products (a `u32` radius times a
/// `u32` side), and each result is at most the side, so it fits a `u32`.
/// Where embedded-graphics does not overflow, the radii are its own.
fn confine_radii(c: eg::CornerRadii, size: Size) -> eg::CornerRadii {
    let sum = |a: u32, b: u32| u64::from(a) + u64::from(b);
    let sides = [
        (sum(c.top_left.width, c.top_right.width), size.width),
        (sum(c.top_right.height, c.bottom_right.height), size.height),
        (sum(c.bottom_left.width, c.bottom_right.width), size.width),
        (sum(c.top_left.height, c.bottom_left.height), size.height),
    ];
    let (mut overlap, mut side, mut radii) = (0u64, 0u64, 0u64);
    for (s, extent) in sides {
        let o = s.saturating_sub(u64::from(extent));
        if o > overlap {
            (overlap, side, radii) = (o, u64::from(extent), s);
        }
    }
    if overlap == 0 || radii == 0 {
        return c;
    }
    // v * side / radii <= side <= u32::MAX: v <= radii.
    let f = |v: u32| {
        let q = (u64::from(v) * side).checked_div(radii).unwrap_or(0);
        u32::try_from(q).unwrap_or(u32::MAX)
    };
    let z = |s: Size| Size::new(f(s.width), f(s.height));
    eg::CornerRadii {
        top_left: z(c.top_left),
        top_right: z(c.top_right),
        bottom_right: z(c.bottom_right),
        bottom_left: z(c.bottom_left),
    }
}

impl From<eg::RoundedRectangle> for RoundedRectangle {
    fn from(r: eg::RoundedRectangle) -> Self {
        let c = confine_radii(r.corners, r.rectangle.size);
        let s = |z: Size| (fine(z.width), fine(z.height));
        RoundedRectangle::new(
            r.rectangle.into(),
            CornerRadii {
                top_left: s(c.top_left),
                top_right: s(c.top_right),
                bottom_right: s(c.bottom_right),
                bottom_left: s(c.bottom_left),
            },
        )
    }
}

impl From<eg::Line> for Line {
    fn from(l: eg::Line) -> Self {
        Line::new(l.start.into(), l.end.into())
    }
}

impl<'a> From<eg::Polyline<'a>> for Polyline<'a, Point> {
    fn from(p: eg::Polyline<'a>) -> Self {
        Polyline {
            translate: corner(p.translate),
            vertices: p.vertices,
        }
    }
}

impl From<eg::StrokeAlignment> for StrokeAlignment {
    fn from(a: eg::StrokeAlignment) -> Self {
        match a {
            eg::StrokeAlignment::Inside => StrokeAlignment::Inside,
            eg::StrokeAlignment::Center => StrokeAlignment::Centre,
            eg::StrokeAlignment::Outside => StrokeAlignment::Outside,
        }
    }
}

impl StrokeStyle<'static> {
    /// The stroke embedded-graphics would draw with `style`: `None` when
    /// it draws none (no stroke colour, or width 0). Width in px, the
    /// alignment kept, miter joins with limit 4, butt caps.
    ///
    /// ```
    /// use embedded_graphics::pixelcolor::BinaryColor;
    /// use embedded_graphics::primitives::{PrimitiveStyle, PrimitiveStyleBuilder, StrokeAlignment};
    /// use softedge::path::StrokeStyle;
    /// let style = PrimitiveStyleBuilder::new()
    ///     .stroke_color(BinaryColor::On)
    ///     .stroke_width(3)
    ///     .stroke_alignment(StrokeAlignment::Inside)
    ///     .build();
    /// let s = StrokeStyle::from_primitive_style(&style).unwrap();
    /// assert_eq!(s.width, 3 * 1024);
    /// assert!(StrokeStyle::from_primitive_style(&PrimitiveStyle::<BinaryColor>::new()).is_none());
    /// ```
    pub fn from_primitive_style<C: PixelColor>(style: &eg::PrimitiveStyle<C>) -> Option<Self> {
        if style.stroke_color.is_none() || style.stroke_width == 0 {
            return None;
        }
        Some(
            StrokeStyle::new(fine(style.stroke_width))
                .with_alignment(style.stroke_alignment.into()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use embedded_graphics::geometry::AngleUnit;

    #[test]
    fn circles_are_inscribed_in_their_bounding_square() {
        let c: Circle = eg::Circle::new(Point::new(3, 4), 5).into();
        assert_eq!(c.centre, FinePoint::new(3 * 1024 + 2560, 4 * 1024 + 2560));
        assert_eq!(c.radius, 2560);
    }

    #[test]
    fn angles_decode_exactly_enough() {
        let a: Arc = eg::Arc::new(Point::new(0, 0), 10, 90.0.deg(), (-45.0).deg()).into();
        assert!((a.start.bits() - (90 << 16)).abs() <= 2);
        assert!((a.sweep.bits() + (45 << 16)).abs() <= 2);
    }

    /// Where embedded-graphics' own `confine_radii` does not overflow (radii
    /// and sides below 2^16), ours gives its radii, over a pseudo-random
    /// sweep.
    #[test]
    fn confined_radii_are_embedded_graphics_own_where_it_does_not_overflow() {
        let mut seed = 0x2545_f491_u32;
        let mut next = |m: u32| {
            seed ^= seed << 13;
            seed ^= seed >> 17;
            seed ^= seed << 5;
            seed % m
        };
        for _ in 0..20_000 {
            let mut z = || Size::new(next(300), next(300));
            let corners = eg::CornerRadii {
                top_left: z(),
                top_right: z(),
                bottom_right: z(),
                bottom_left: z(),
            };
            let rect = eg::Rectangle::new(Point::zero(), Size::new(next(400), next(400)));
            let r = eg::RoundedRectangle::new(rect, corners);
            assert_eq!(
                confine_radii(corners, rect.size),
                r.confine_radii().corners,
                "{r:?}"
            );
        }
    }

    #[test]
    fn lines_run_between_pixel_centres() {
        let l: Line = eg::Line::new(Point::new(0, 0), Point::new(10, 0)).into();
        assert_eq!(l.start, FinePoint::new(512, 512));
        assert_eq!(l.end, FinePoint::new(10 * 1024 + 512, 512));
    }
}
