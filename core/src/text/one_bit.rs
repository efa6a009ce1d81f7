//! [`ContrastBoost`]: steeper coverage before 1-bit dithering, for small
//! text on monochrome displays.
//!
//! Takes a 1-bit display profile (Floyd–Steinberg's
//! [`DiffusionProfile`](crate::tone::profile::DiffusionProfile), or
//! [`Bayer8`](crate::tone::Bayer8)) and a gain `2^shift`; gives the same
//! profile fed with
//!
//! ```text
//! v' = clamp(((v - 2048) << shift) + 2048, 0, 4095)
//! ```
//!
//! per pixel (a subtract, a shift, an add and two compares: no multiply),
//! so that partly covered edge pixels are pushed towards off or on before
//! the ditherer spreads them. Dithering a glyph's edge scatters its
//! half-covered pixels into dots that read as noise at 10-12 px; with the
//! boost an edge pixel is decided mostly by which side of one half its
//! coverage lies, while pixels near 1/2 (a stem straddling two pixels)
//! still share the ink. Flat regions of `0` and `4095` are unchanged; mid
//! grays become saturated, so use it for text and line art, not for
//! images. The measured effect is in the README (*Text on a 1-bit OLED*).
//!
//! ## Integer ranges
//!
//! `v <= 4095`, `shift <= 4`: `|v - 2048| << 4 < 2^16`, clamped back to
//! `0..=4095`; the accumulator values handed on are `v' << 16 < 2^28`.

use crate::tone::profile::{Profile, ToneRow};
use crate::COVER_BITS;

/// The largest gain: `2^4`.
pub const MAX_CONTRAST_SHIFT: u8 = 4;

/// A 1-bit profile fed with contrast-boosted values (see the module).
///
/// ```
/// use embedded_graphics_core::pixelcolor::BinaryColor;
/// use softedge::text::ContrastBoost;
/// use softedge::tone::profile::{DiffusionProfile, Profile};
/// use softedge::tone::Bayer8;
/// // Over Bayer (stateless), the boost is a per-pixel map.
/// let mut scratch = [0i32; 8];
/// let boosted = ContrastBoost::new(Bayer8::new(), 2, &mut scratch);
/// assert_eq!(boosted.uniform([4095]), Some(BinaryColor::On));
/// assert_eq!(ContrastBoost::<Bayer8>::boost(2048 + 300, 2), 2048 + 1200);
/// assert_eq!(ContrastBoost::<Bayer8>::boost(1000, 2), 0);
/// // Over Floyd–Steinberg, rows are boosted into the scratch first.
/// let (mut err, mut bits) = ([0i16; 128], [false; 128]);
/// let mut scratch = [0i32; 128];
/// let _fs = ContrastBoost::new(DiffusionProfile::new(&mut err, &mut bits), 2, &mut scratch);
/// ```
#[derive(Debug)]
pub struct ContrastBoost<'s, P> {
    inner: P,
    shift: u8,
    scratch: &'s mut [i32],
}

impl<'s, P> ContrastBoost<'s, P> {
    /// `inner` fed with the gain `2^shift` (`shift` limited to
    /// `0..=4`; 0 changes nothing), over a scratch row as long as the
    /// widest row drawn (a longer row's pixels past it are sent as 0).
    pub fn new(inner: P, shift: u8, scratch: &'s mut [i32]) -> Self {
        Self {
            inner,
            shift: shift.min(MAX_CONTRAST_SHIFT),
            scratch,
        }
    }

    /// The boosted value of `v` (`0..=4095`) for a gain of `2^shift`.
    pub const fn boost(v: u16, shift: u8) -> u16 {
        let s = if shift > MAX_CONTRAST_SHIFT {
            MAX_CONTRAST_SHIFT
        } else {
            shift
        };
        let half = 1i32 << 11;
        let v = if v > crate::LIN_MAX {
            crate::LIN_MAX
        } else {
            v
        } as i32;
        let b = ((v - half) << s) + half;
        if b < 0 {
            0
        } else if b > crate::LIN_MAX as i32 {
            crate::LIN_MAX
        } else {
            b as u16
        }
    }

    /// The profile inside.
    pub fn into_inner(self) -> P {
        self.inner
    }
}

impl<P: Profile<1>> Profile<1> for ContrastBoost<'_, P> {
    type Color = P::Color;

    fn start_frame(&mut self) {
        self.inner.start_frame();
    }

    fn start_row(&mut self, row: &ToneRow<'_, 1>) {
        let n = row.len().min(self.scratch.len());
        for (k, s) in self.scratch[..n].iter_mut().enumerate() {
            let [v] = row.lin12(k);
            *s = i32::from(Self::boost(v, self.shift)) << COVER_BITS;
        }
        let boosted = ToneRow::new(row.y, row.x0, &self.scratch[..n]);
        self.inner.start_row(&boosted);
    }

    #[inline]
    fn color(&self, x: i32, y: i32, [v]: [u16; 1]) -> Self::Color {
        self.inner.color(x, y, [Self::boost(v, self.shift)])
    }

    fn uniform(&self, [v]: [u16; 1]) -> Option<Self::Color> {
        self.inner.uniform([Self::boost(v, self.shift)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn boost_keeps_the_ends_and_the_middle_and_saturates() {
        type B = ContrastBoost<'static, ()>;
        for s in 0..=6u8 {
            assert_eq!(B::boost(0, s), 0);
            assert_eq!(B::boost(4095, s), 4095);
            assert_eq!(B::boost(2048, s), 2048);
            assert_eq!(B::boost(u16::MAX, s), 4095);
        }
        assert_eq!(B::boost(1234, 0), 1234);
        assert_eq!(B::boost(2048 - 100, 1), 2048 - 200);
        assert_eq!(B::boost(2048 + 200, 4), 4095); // 2048 + 3200, clamped
        assert_eq!(B::boost(100, 4), 0);
    }
}
