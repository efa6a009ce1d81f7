//! [`Glyph`]: one glyph's outline, scaled and placed on the fine grid, as a
//! [`Shape`].
//!
//! Takes a [`Font`], a glyph, its origin (the pen position on the
//! baseline, fine units, y down) and a [`Scale`]; gives the outline as a
//! path ([`Shape::describe`]: `move_to`, `line_to`, `quad_to` for `glyf`
//! fonts, `cubic_to` for CFF, `close`) in fine units, so that the canvas
//! fills it ([`Canvas::fill_shape`](crate::canvas::Canvas::fill_shape))
//! by the nonzero rule, exact area, like any path.
//!
//! ## Where floating point appears
//!
//! `ttf-parser`'s `OutlineBuilder` hands every outline point as `f32`. For
//! `glyf` fonts these hold integer font units exactly (`i16`, and composite
//! glyphs' offsets; a composite's 2x2 scale, `F2Dot14`, is applied by the
//! parser in `f32`); CFF charstrings compute in `f32` and may carry
//! fractions. Each coordinate is converted **at once**, in
//! [`to_u64ths`]: one `f32` multiply by 64 (exact: a power of two) and one
//! `f32` to `i32` conversion (Rust's `as`: saturating, NaN to 0) give
//! 1/64 font unit; from there on everything is integer fixed point
//! ([`Scale`]: one `i64` multiply and shift per point). On a Cortex-M0,
//! which has no FPU, these are the soft-float routines `__aeabi_fmul` and
//! `__aeabi_f2iz` (plus what the parser itself does in `f32` for composite
//! transforms and CFF charstrings, and in `f64` for CFF DICT operands when
//! a CFF font is opened): per outline point or per font, in set-up; no FPU
//! is needed and no floating point reaches the per-pixel loops.
//!
//! ## Integer ranges
//!
//! Coordinates are clamped to `±2^26` 1/64 units ([`Scale`]); a point's
//! fine coordinate is the origin (`i32`) plus the scaled offset (`i64`),
//! saturated to `±2^30` and then clamped into the coordinate range by the
//! [`Flattener`](crate::path::Flattener) without changing any winding
//! inside it.

use ttf_parser::{GlyphId, OutlineBuilder};

use super::scale::Scale;
use super::Font;
use crate::geom::{FinePoint, PathSink};
use crate::path::Shape;

/// An outline coordinate from the parser, in 1/64 font unit: `v * 64`
/// truncated toward zero, saturated to `i32`, NaN to 0 (what
/// `(v * 64.0) as i32` gives), read off the number's bits with integer
/// operations only (soft-float multiplies and compares cost a Cortex-M0
/// about a hundred instructions per coordinate).
///
/// `v = m 2^(e - 150)` for the biased exponent `e` and the mantissa `m`
/// with its hidden bit, so `64 v = m 2^(e - 144)`: shifted left below
/// `2^31`, right (truncating) otherwise; subnormals are below `2^-126`.
#[inline]
pub fn to_u64ths(v: f32) -> i32 {
    let bits = v.to_bits();
    let negative = bits >> 31 == 1;
    let exp = ((bits >> 23) & 0xff) as i32;
    let mant = bits & 0x7f_ffff;
    let magnitude: u32 = match exp {
        0xff if mant != 0 => return 0, // NaN
        0xff => u32::MAX,              // infinity: saturates
        0 => 0,                        // subnormal: |64 v| < 1
        _ => {
            let m = mant | 1 << 23;
            let e = exp - 144;
            if e >= 8 {
                u32::MAX // at least 2^31: saturates
            } else if e >= 0 {
                m << e
            } else if e > -24 {
                m >> -e
            } else {
                0
            }
        }
    };
    if negative {
        if magnitude >= 1 << 31 {
            i32::MIN
        } else {
            -(magnitude as i32)
        }
    } else {
        magnitude.min(i32::MAX as u32) as i32
    }
}

/// Saturates an `i64` fine coordinate to `±2^30` (then clamped into range
/// by the flattener).
#[inline]
pub(crate) fn sat_fine(v: i64) -> i32 {
    const L: i64 = 1 << 30;
    v.clamp(-L, L) as i32
}

/// The parser's outline calls, converted to fine units and handed to a
/// [`PathSink`].
pub(crate) struct ToFine<'p, P: PathSink + ?Sized> {
    pub sink: &'p mut P,
    pub origin: FinePoint,
    pub scale: Scale,
}

impl<P: PathSink + ?Sized> ToFine<'_, P> {
    #[inline]
    fn pt(&self, x: f32, y: f32) -> FinePoint {
        let fx = i64::from(self.origin.x) + self.scale.x(to_u64ths(x));
        // Font y grows up, the screen's down.
        let fy = i64::from(self.origin.y) - self.scale.y(to_u64ths(y));
        FinePoint::new(sat_fine(fx), sat_fine(fy))
    }
}

impl<P: PathSink + ?Sized> OutlineBuilder for ToFine<'_, P> {
    fn move_to(&mut self, x: f32, y: f32) {
        let p = self.pt(x, y);
        self.sink.move_to(p);
    }
    fn line_to(&mut self, x: f32, y: f32) {
        let p = self.pt(x, y);
        self.sink.line_to(p);
    }
    fn quad_to(&mut self, x1: f32, y1: f32, x: f32, y: f32) {
        let (c, p) = (self.pt(x1, y1), self.pt(x, y));
        self.sink.quad_to(c, p);
    }
    fn curve_to(&mut self, x1: f32, y1: f32, x2: f32, y2: f32, x: f32, y: f32) {
        let (c1, c2, p) = (self.pt(x1, y1), self.pt(x2, y2), self.pt(x, y));
        self.sink.cubic_to(c1, c2, p);
    }
    fn close(&mut self) {
        self.sink.close();
    }
}

/// One glyph placed on the fine grid: a [`Shape`].
///
/// ```
/// use softedge::geom::FinePoint;
/// use softedge::path::{SegmentSink, Shape};
/// use softedge::text::{Font, Glyph, Scale, TextSize};
///
/// #[derive(Default)]
/// struct Area2(i64);
/// impl SegmentSink for Area2 {
///     fn segment(&mut self, a: FinePoint, b: FinePoint) {
///         self.0 += i64::from(a.x) * i64::from(b.y) - i64::from(b.x) * i64::from(a.y);
///     }
/// }
/// let font = Font::bundled().unwrap();
/// let scale = Scale::new(TextSize::px(24), font.units_per_em());
/// let l = Glyph::new(&font, font.glyph('l'), FinePoint::from_px(10, 30), scale);
/// let mut a = Area2::default();
/// l.fill(&mut a);
/// // DejaVu's 'l' is a bar 184 x 1556 units: at 24 px, 2.16 x 18.23 px.
/// // TrueType outer contours run clockwise on screen: a positive area.
/// let px2 = a.0 as f64 / 2.0 / (1024.0 * 1024.0);
/// assert!((px2 - 184.0 * 1556.0 * (24.0f64 / 2048.0).powi(2)).abs() < 0.05, "{px2}");
/// ```
#[derive(Debug, Clone, Copy)]
pub struct Glyph<'f, 'a> {
    font: &'f Font<'a>,
    id: GlyphId,
    origin: FinePoint,
    scale: Scale,
}

impl<'f, 'a> Glyph<'f, 'a> {
    /// Glyph `id` of `font` with its origin (pen position on the baseline)
    /// at `origin`, scaled by `scale`.
    pub fn new(font: &'f Font<'a>, id: GlyphId, origin: FinePoint, scale: Scale) -> Self {
        Self {
            font,
            id,
            origin,
            scale,
        }
    }

    /// The glyph.
    pub fn id(&self) -> GlyphId {
        self.id
    }

    /// Its origin, fine units.
    pub fn origin(&self) -> FinePoint {
        self.origin
    }
}

impl Shape for Glyph<'_, '_> {
    /// The outline as the font has it (TrueType's outer contours run
    /// clockwise on screen, as softedge's shapes do, CFF's the other way:
    /// fill with the nonzero rule). A glyph without an outline (a space) or a damaged
    /// one describes nothing, or what the parser read of it.
    fn describe<P: PathSink + ?Sized>(&self, sink: &mut P) {
        let mut b = ToFine {
            sink,
            origin: self.origin,
            scale: self.scale,
        };
        let _ = self.font.face().outline_glyph(self.id, &mut b);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bit_conversion_is_the_float_cast() {
        // Every exponent with several mantissas and both signs, and the
        // special values, against `(v * 64.0) as i32`.
        let mut rng = crate::path::testing::Lcg(0x3c6e_f372_fe94_f82a);
        for exp in 0u32..=255 {
            for k in 0..64 {
                let seed = rng.next_u64();
                let mant = match k {
                    0 => 0,
                    1 => 1,
                    2 => 0x7f_ffff,
                    _ => (seed >> 41) as u32 & 0x7f_ffff,
                };
                for sign in [0u32, 1] {
                    let v = f32::from_bits(sign << 31 | exp << 23 | mant);
                    assert_eq!(to_u64ths(v), (v * 64.0) as i32, "{v:e} ({exp}, {mant:#x})");
                }
            }
        }
        for v in [
            0.5f32,
            -0.5,
            1.0 / 64.0,
            -1.0 / 128.0,
            33554431.0,
            33554432.0,
            -33554432.0,
        ] {
            assert_eq!(to_u64ths(v), (v * 64.0) as i32, "{v}");
        }
    }

    #[test]
    fn float_conversion_is_exact_for_font_units_and_total() {
        assert_eq!(to_u64ths(1.0), 64);
        assert_eq!(to_u64ths(-32768.0), -32768 * 64);
        assert_eq!(to_u64ths(0.5), 32);
        assert_eq!(to_u64ths(f32::NAN), 0);
        assert_eq!(to_u64ths(f32::INFINITY), i32::MAX);
        assert_eq!(to_u64ths(f32::NEG_INFINITY), i32::MIN);
        assert_eq!(sat_fine(i64::MAX), 1 << 30);
    }
}
