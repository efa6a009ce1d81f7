//! Ordered dithering of γ-encoded codes: Rgb565 (and Gray4) without
//! banding (issue 16).
//!
//! The band buffer resolves 12-bit linear light, but a 5-bit channel has
//! only 32 codes: a dark gradient on Rgb565 shows steps of 1/32 of the code
//! range, a few pixels wide each. Here each channel is γ-encoded to a
//! *finer* code first, `fine = round(max * 2^F * V(I / 4095))` (`V` the
//! inverse of the display [`Curve`], eq. 7 for a power curve), and the `F`
//! fraction bits are spread over a 4x4 tile by an ordered threshold before
//! they are dropped:
//!
//! ```text
//! code(x, y) = (fine + t(x, y)) >> F,    t(x, y) = M4(x mod 4, y mod 4) >> (4 - F)
//! ```
//!
//! `M4` is the 4x4 Bayer matrix (each level `0..16` once), taken from the
//! 8x8 one of [`dither`](super::dither): `M8(x, y) = 4 M4(x, y) + D2(x div
//! 4, y div 4)` for `x, y < 8`, so `M4 = M8 >> 2` on the first quadrant.
//! `t` takes each value `0..2^F` exactly `2^(4-F)` times in the tile; with
//! `fine = q 2^F + r`, `r + t >= 2^F` in `r 2^(4-F)` of the 16 cells, so
//! the tile's mean code is `q + r / 2^F = fine / 2^F` *exactly*: the
//! dithered tile averages to the finer code, the table's rounding (half a
//! fine step) is the only error. A value on a whole code (`r = 0`) gets
//! that code at every position: flat representable colours, black and
//! white among them, carry no pattern.
//!
//! ## Dithering happens on γ-encoded codes
//!
//! The threshold splits the interval between two adjacent *codes* `c` and
//! `c + 1` in proportion to the encoded value, as is usual: the codes of a
//! display are close to perceptually even, so the pattern's amplitude is
//! one code step, equally visible at every level. The light of the mix is
//! then the chord of the display curve between `c` and `c + 1`, not the
//! curve itself; over one 5-bit step the two differ by a fraction of that
//! step's light (most in the darkest step of a pure power curve; on sRGB
//! the curve is linear up to `V = 0.04045`, 1.25 codes of 31, so there the
//! mix is exact in light too). 1-bit displays are different: their one
//! step is the whole range, so [`dither`](super::dither) works in linear
//! light.
//!
//! ## Fine tables
//!
//! A [`DitherLut`] holds one `u8` per `lin12` (4096 bytes) with as many
//! fraction bits as fit a byte, at most 4 (the 16 levels of the tile):
//! 5-bit channels `F = 3` (`31 * 8 = 248`), 6-bit `F = 2` (`63 * 4 = 252`),
//! 4-bit `F = 4` (`15 * 16 = 240`). So red and blue of Rgb565 move in
//! 1/8 codes, green in 1/4 codes (its tile is the 2x2 Bayer pattern
//! repeated). Tables are built by `const fn` with the fixed-point
//! `encode` of [`gamma`](super::gamma), bit-identical on every target.
//!
//! Flash: [`Rgb565Dither`] 8192 bytes (a 5-bit table shared by red and
//! blue, a 6-bit one for green; the same as [`Rgb565Format`]'s tables),
//! [`Gray4Dither`] 4096 bytes. The threshold matrix is 16 bytes.
//!
//! ## Cost per pixel
//!
//! Once per pixel: the cell index `(y & 3) << 2 | (x & 3)` (2 ands, a
//! shift, an or) and one 16-entry matrix look-up. Per channel: a clamp of
//! `lin12` to 4095 (a min), one table look-up, a shift of the matrix level,
//! an add, a shift. Rgb565 packs like [`Rgb565Format`] (2 shifts, 2 ors).
//! Integer only, no division, no branch but the clamps.
//!
//! ## Integer ranges
//!
//! `fine <= max << F <= 255` and `t < 2^F`, so `fine + t <= 255 + 15` fits
//! the `u16` it is computed in, and `(max << F) + t >> F = max`: no code
//! exceeds its channel. The cell index is masked to `0..16` for every
//! `(x, y)`, negative ones too (two's complement: `x & 3` is `x mod 4`).
//!
//! ## Measured error (tests/tests/ordered_dither.rs, every `lin12`)
//!
//! Worst `|tile mean - max * V(I / 4095)|` against an `f64` reference of
//! each curve (sRGB, γ 2.2, γ 2.4): 5-bit 0.062499 codes, 6-bit 0.124999,
//! 4-bit 0.031248 — the bound `2^-(F+1)` (half a fine step), all but
//! reached; rounding without dithering ([`Rgb565Format`]) is off by up to
//! 0.49997 codes at 5 bits. In light (the chord error above), the worst
//! `|mean light of the tile - I / 4095|` of a 5-bit channel is 0.0049
//! (sRGB), 0.0047 (γ 2.2), 0.0051 (γ 2.4) of full scale, against 0.036,
//! 0.035, 0.038 undithered.
//!
//! [`Rgb565Format`]: super::format::Rgb565Format

use super::dither::Bayer8;
use super::fixpow::{self, VALUE_FRAC};
use super::gamma::{encode, Curve};
use super::{lin12_index, LIN_LEN, LIN_MAX};

/// Side of the threshold tile.
const TILE_SIDE: usize = 4;
/// Cells of the tile, and so the levels of [`M4`].
const TILE_LEN: usize = TILE_SIDE * TILE_SIDE;
/// `log2(TILE_LEN)`: the most fraction bits the tile can spread.
const TILE_BITS: u8 = 4;

/// The 4x4 Bayer matrix, row-major: `M4(x, y) = M8(x, y) >> 2` for
/// `x, y < 4` (the 8x8 matrix's first quadrant holds `4 M4`).
const M4: [u8; TILE_LEN] = {
    let mut m = [0u8; TILE_LEN];
    let mut k = 0;
    while k < TILE_LEN {
        m[k] = (Bayer8::level(k % TILE_SIDE, k / TILE_SIDE) >> 2) as u8;
        k += 1;
    }
    m
};

/// The matrix level `0..16` of frame pixel `(x, y)`.
#[inline]
fn level(x: i32, y: i32) -> u16 {
    let k = (((y & 3) << 2) | (x & 3)) as usize;
    // The mask keeps k < 16; the fallback is never taken.
    u16::from(M4.get(k).copied().unwrap_or(0))
}

/// A fine γ table for one channel: `lin12` → the display code of `bits`
/// bits with [`frac_bits`](Self::frac_bits) more bits of fraction, and the
/// ordered threshold that drops them.
///
/// `fine = round((2^bits - 1) * 2^F * V(I / 4095))`, `F` the largest of
/// `0..=4` with `(2^bits - 1) << F <= 255`. Endpoints are exact
/// (`0 → 0`, `4095 → max << F`), the table is monotone.
///
/// ```
/// # use softedge::tone::{Curve, ordered::DitherLut};
/// static LUT5: DitherLut = DitherLut::with_bits(Curve::Srgb, 5);
/// assert_eq!((LUT5.max_code(), LUT5.frac_bits()), (31, 3));
/// assert_eq!(LUT5.fine(4095), 248);
/// // Over a 4x4 tile the codes average to fine / 8.
/// let lin = 1000;
/// let sum: u32 = (0..16).map(|k| u32::from(LUT5.code(lin, k % 4, k / 4))).sum();
/// assert_eq!(sum * 8, 16 * u32::from(LUT5.fine(lin)));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DitherLut {
    fine: [u8; LIN_LEN],
    max: u8,
    frac: u8,
}

impl DitherLut {
    /// The table for `curve` and codes of `bits` bits (clamped to `1..=8`;
    /// 8 bits leave no room for a fraction: no dithering).
    pub const fn with_bits(curve: Curve, bits: u8) -> Self {
        let bits = if bits < 1 {
            1
        } else if bits > 8 {
            8
        } else {
            bits
        };
        let max = ((1u16 << bits) - 1) as u8;
        let mut frac = 0;
        while frac < TILE_BITS && (max as u16) << (frac + 1) <= u8::MAX as u16 {
            frac += 1;
        }
        let scale = (max as u32) << frac;
        let mut fine = [0u8; LIN_LEN];
        let mut i = 1;
        while i < LIN_LEN {
            // x = i / 4095 in Q62; i < 2^12, so i << 62 < 2^74.
            let x = ((i as u128) << VALUE_FRAC) / LIN_MAX as u128;
            fine[i] = fixpow::round_to(encode(curve, x), scale) as u8;
            i += 1;
        }
        DitherLut { fine, max, frac }
    }

    /// The largest code, `2^bits - 1`.
    pub const fn max_code(&self) -> u8 {
        self.max
    }

    /// `F`: fraction bits of the fine code, spread by the tile.
    pub const fn frac_bits(&self) -> u8 {
        self.frac
    }

    /// The fine code `round(max * 2^F * V)` of `lin12` (clamped to 4095).
    #[inline]
    pub fn fine(&self, lin12: u16) -> u8 {
        self.fine[lin12_index(lin12)]
    }

    /// The dithered code of frame pixel `(x, y)` of intensity `lin12`
    /// (clamped to 4095): `(fine + t(x, y)) >> F`.
    ///
    /// ```
    /// # use softedge::tone::{Curve, ordered::DitherLut};
    /// let lut = DitherLut::with_bits(Curve::GAMMA_2_2, 6);
    /// assert_eq!(lut.code(0, -3, 7), 0);
    /// assert_eq!(lut.code(4095, 1, 2), 63);
    /// ```
    #[inline]
    pub fn code(&self, lin12: u16, x: i32, y: i32) -> u8 {
        self.code_at(lin12, level(x, y))
    }

    /// The code for a matrix level `0..16` (the per-pixel step).
    #[inline]
    fn code_at(&self, lin12: u16, level: u16) -> u8 {
        let t = level >> (TILE_BITS - self.frac);
        // fine + t <= 255 + 15 and the sum >> F <= max: fits u8.
        ((u16::from(self.fine(lin12)) + t) >> self.frac) as u8
    }

    /// The code every position gets for `lin12`, if the fine code has no
    /// fraction (else the tile mixes two codes).
    #[inline]
    fn uniform(&self, lin12: u16) -> Option<u8> {
        let f = self.fine(lin12);
        (f & ((1 << self.frac) - 1) == 0).then_some(f >> self.frac)
    }
}

/// Rgb565 with ordered dithering of each channel's γ-encoded code: red
/// and blue in 1/8 codes, green in 1/4 codes, through a 4x4 Bayer tile.
///
/// A profile by reference, like [`Rgb565Format`](super::format::Rgb565Format):
///
/// ```
/// use embedded_graphics_core::pixelcolor::{Rgb565, RgbColor};
/// use softedge::tone::{ordered::Rgb565Dither, profile::Profile, Curve};
/// static RGB565_DITHER: Rgb565Dither = Rgb565Dither::new(Curve::Srgb);
/// let profile = &RGB565_DITHER;
/// assert_eq!(profile.uniform([4095; 3]), Some(Rgb565::WHITE));
/// // A dark grey between two codes: a pattern, not one flat code.
/// assert_eq!(profile.uniform([60; 3]), None);
/// // 31 V(60 / 4095) = 3.92; the fine table holds 31 / 8 = 3.875: the tile
/// // is 14 pixels of red 4 and 2 of red 3.
/// let reds: u32 = (0..16).map(|k| u32::from(profile.color(k % 4, k / 4, [60; 3]).r())).sum();
/// assert_eq!(reds, 62);
/// ```
///
/// With the renderer, exactly as `&Rgb565Format`:
/// `renderer.render(&mut display, &RGB565_DITHER, Rgb565::BLACK, |canvas| ...)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rgb565Dither {
    lut5: DitherLut,
    lut6: DitherLut,
}

impl Rgb565Dither {
    /// The profile for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        Rgb565Dither {
            lut5: DitherLut::with_bits(curve, 5),
            lut6: DitherLut::with_bits(curve, 6),
        }
    }

    /// The three channel codes `(r5, g6, b5)` of frame pixel `(x, y)`.
    ///
    /// ```
    /// # use softedge::tone::{Curve, ordered::Rgb565Dither};
    /// let d = Rgb565Dither::new(Curve::GAMMA_2_2);
    /// assert_eq!(d.channels(5, 9, [4095, 4095, 0]), [31, 63, 0]);
    /// ```
    #[inline]
    pub fn channels(&self, x: i32, y: i32, [r, g, b]: [u16; 3]) -> [u8; 3] {
        let l = level(x, y);
        [
            self.lut5.code_at(r, l),
            self.lut6.code_at(g, l),
            self.lut5.code_at(b, l),
        ]
    }

    /// The packed code `r << 11 | g << 5 | b` of frame pixel `(x, y)`.
    ///
    /// ```
    /// # use softedge::tone::{Curve, ordered::Rgb565Dither};
    /// let d = Rgb565Dither::new(Curve::Srgb);
    /// assert_eq!(d.code(0, 0, [0, 4095, 0]), 0x07E0);
    /// ```
    #[inline]
    pub fn code(&self, x: i32, y: i32, px: [u16; 3]) -> u16 {
        let [r, g, b] = self.channels(x, y, px).map(u16::from);
        (r << 11) | (g << 5) | b
    }

    /// The channel codes every position gets, if no channel has a fraction.
    fn uniform_channels(&self, [r, g, b]: [u16; 3]) -> Option<[u8; 3]> {
        Some([
            self.lut5.uniform(r)?,
            self.lut6.uniform(g)?,
            self.lut5.uniform(b)?,
        ])
    }
}

#[cfg(feature = "embedded-graphics")]
impl Profile<3> for &Rgb565Dither {
    type Color = embedded_graphics_core::pixelcolor::Rgb565;

    #[inline]
    fn color(&self, x: i32, y: i32, lin: [u16; 3]) -> Self::Color {
        let [r, g, b] = self.channels(x, y, lin);
        embedded_graphics_core::pixelcolor::Rgb565::new(r, g, b)
    }

    fn uniform(&self, lin: [u16; 3]) -> Option<Self::Color> {
        let [r, g, b] = self.uniform_channels(lin)?;
        Some(embedded_graphics_core::pixelcolor::Rgb565::new(r, g, b))
    }
}

/// 4-bit gray with ordered dithering of the γ-encoded code in 1/16 codes
/// (the whole 4x4 tile): 241 levels on a 16-level panel.
///
/// ```
/// use embedded_graphics_core::pixelcolor::GrayColor;
/// use softedge::tone::{ordered::Gray4Dither, profile::Profile, Curve};
/// static GRAY4_DITHER: Gray4Dither = Gray4Dither::new(Curve::GAMMA_2_4);
/// let p = &GRAY4_DITHER;
/// assert_eq!(p.color(-1, 3, [4095]).luma(), 15);
/// let fine = GRAY4_DITHER.lut().fine(2048);
/// let sum: u32 = (0..16).map(|k| u32::from(p.color(k % 4, k / 4, [2048]).luma())).sum();
/// assert_eq!(sum, u32::from(fine));
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Gray4Dither {
    lut: DitherLut,
}

impl Gray4Dither {
    /// The profile for a display with `curve`.
    pub const fn new(curve: Curve) -> Self {
        Gray4Dither {
            lut: DitherLut::with_bits(curve, 4),
        }
    }

    /// Its table.
    pub const fn lut(&self) -> &DitherLut {
        &self.lut
    }
}

#[cfg(feature = "embedded-graphics")]
impl Profile<1> for &Gray4Dither {
    type Color = embedded_graphics_core::pixelcolor::Gray4;

    #[inline]
    fn color(&self, x: i32, y: i32, [lin]: [u16; 1]) -> Self::Color {
        embedded_graphics_core::pixelcolor::Gray4::new(self.lut.code(lin, x, y))
    }

    fn uniform(&self, [lin]: [u16; 1]) -> Option<Self::Color> {
        self.lut
            .uniform(lin)
            .map(embedded_graphics_core::pixelcolor::Gray4::new)
    }
}

#[cfg(feature = "embedded-graphics")]
use super::profile::Profile;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn m4_is_the_classic_bayer_4x4() {
        assert_eq!(M4, [0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5]);
    }

    #[test]
    fn fraction_bits_fill_a_byte() {
        let f: [u8; 8] =
            core::array::from_fn(|b| DitherLut::with_bits(Curve::Srgb, b as u8 + 1).frac_bits());
        assert_eq!(f, [4, 4, 4, 4, 3, 2, 1, 0]);
        for bits in 1..=8 {
            let lut = DitherLut::with_bits(Curve::GAMMA_2_4, bits);
            assert_eq!(lut.fine(4095), lut.max_code() << lut.frac_bits());
            assert_eq!(lut.code(4095, 3, 3), lut.max_code());
        }
    }
}
