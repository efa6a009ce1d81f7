//! Texel formats of softedge's own images ([`RawImage`](super::RawImage)):
//! how the bytes of a row hold a texel, and how a texel becomes
//! premultiplied linear light.
//!
//! Colours are sRGB codes, decoded by the tables of
//! [`color::srgb`](crate::color::srgb) (`round(4095 L(code / max))`); alpha
//! is straight (not premultiplied) in the data and premultiplied here:
//! a texel is `c a / 1024` per channel with `a` the alpha in `0..=1024`
//! (`round(1024 code / max)`), so an opaque texel is its colour exactly.
//!
//! | format | bytes per texel | data |
//! | --- | --- | --- |
//! | [`Rgb565`] | 2 | little endian (e-g's `ImageRawLE<Rgb565>`) |
//! | [`Rgb565Be`] | 2 | big endian (e-g's `ImageRawBE<Rgb565>`) |
//! | [`Rgb888`] | 3 | `r, g, b` |
//! | [`Gray8`] | 1 | the gray code |
//! | [`Rgba8888`] | 4 | `r, g, b, a`, straight alpha (PNG's order) |
//! | [`Alpha1`], [`Alpha2`], [`Alpha4`], [`Alpha8`] | 1/8 .. 1 | alpha only (a mask, drawn in a tint); the first texel in the high bits of a byte, rows padded to whole bytes |
//! | [`Keyed<F>`] | as `F` | `F`'s colours; texels equal to the image's colour key are transparent |
//! | [`PlaneAlpha<F>`] | as `F` | `F`'s colours, alpha from a separate 8-bit plane (one byte a texel, rows of `width` bytes) |

use crate::color::srgb::{luminance, SRGB5_TO_LIN12, SRGB6_TO_LIN12, SRGB8_TO_LIN12};

/// Alpha of an opaque texel: `1024`.
pub(crate) const ALPHA_ONE: u32 = 1 << ALPHA_BITS;
/// Bits of a texel's alpha.
pub(crate) const ALPHA_BITS: u32 = 10;

use super::sealed;
pub(crate) use super::sealed::Lin;

/// `round(1024 code / max)` for the codes of a `bits`-bit alpha.
const fn alpha_table<const N: usize>() -> [u16; N] {
    let mut t = [0u16; N];
    let max = (N - 1) as u32;
    let mut k = 0;
    while k < N {
        t[k] = ((k as u32 * ALPHA_ONE * 2 + max) / (2 * max)) as u16;
        k += 1;
    }
    t
}

/// 8-bit alpha codes to `0..=1024`.
const ALPHA8: [u16; 256] = alpha_table::<256>();
const ALPHA4: [u16; 16] = alpha_table::<16>();
const ALPHA2: [u16; 4] = alpha_table::<4>();

/// `c a / 1024`, rounded, per channel.
#[inline(always)]
fn premultiply(c: [u32; 3], a: u32) -> [u32; 3] {
    c.map(|v| (v * a + ALPHA_ONE / 2) >> ALPHA_BITS)
}

/// A texel format of a [`RawImage`](super::RawImage) (see the module
/// table). Sealed: softedge's formats only; other images come in through
/// embedded-graphics' `GetPixel` ([`Pixels`](super::Pixels)).
pub trait TexelFormat: sealed::Decode {}

impl<T: sealed::Decode> TexelFormat for T {}

macro_rules! marker {
    ($(#[$m:meta])* $name:ident) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
        pub struct $name;
    };
}

marker!(
    /// 16-bit `RRRRRGGG GGGBBBBB`, little endian (low byte first).
    Rgb565
);
marker!(
    /// 16-bit `RRRRRGGG GGGBBBBB`, big endian (high byte first).
    Rgb565Be
);
marker!(
    /// Three bytes: `r, g, b`.
    Rgb888
);
marker!(
    /// One byte: the gray code.
    Gray8
);
marker!(
    /// Four bytes: `r, g, b, a` (straight alpha).
    Rgba8888
);
marker!(
    /// A 1-bit mask: 8 texels a byte, the first in bit 7.
    Alpha1
);
marker!(
    /// A 2-bit mask: 4 texels a byte, the first in bits 7..6.
    Alpha2
);
marker!(
    /// A 4-bit mask: 2 texels a byte, the first in bits 7..4.
    Alpha4
);
marker!(
    /// An 8-bit mask: one byte a texel.
    Alpha8
);

/// `F`'s colours, and its texels equal to the image's colour key (the
/// raw bits: an `Rgb565` value, an `Rgb888` `0xrrggbb`) transparent.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct Keyed<F>(pub F);

/// `F`'s colours under a separate 8-bit alpha plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct PlaneAlpha<F>(pub F);

/// A 16-bit texel's three channels, linear.
#[inline(always)]
fn rgb565(v: u32) -> [u32; 3] {
    let t5 = |i: u32| u32::from(SRGB5_TO_LIN12[(i & 31) as usize]);
    [
        t5(v >> 11),
        u32::from(SRGB6_TO_LIN12[((v >> 5) & 63) as usize]),
        t5(v),
    ]
}

#[inline(always)]
fn srgb8(v: u32) -> u32 {
    u32::from(SRGB8_TO_LIN12[(v & 255) as usize])
}

impl sealed::Decode for Rgb565 {
    const BITS: u32 = 16;
    const OPAQUE: bool = true;
    const RGB565: bool = true;
    const MASK: bool = false;
    const GRAY: bool = false;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        let b = row.get(2 * x..2 * x + 2)?;
        Some(u32::from(b[0]) | u32::from(b[1]) << 8)
    }
    #[inline(always)]
    fn decode(raw: u32, _: u8, _: u32) -> Lin {
        Lin {
            c: rgb565(raw),
            a: ALPHA_ONE,
        }
    }
}

impl sealed::Decode for Rgb565Be {
    const BITS: u32 = 16;
    const OPAQUE: bool = true;
    const RGB565: bool = true;
    const MASK: bool = false;
    const GRAY: bool = false;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        let b = row.get(2 * x..2 * x + 2)?;
        Some(u32::from(b[1]) | u32::from(b[0]) << 8)
    }
    #[inline(always)]
    fn decode(raw: u32, _: u8, _: u32) -> Lin {
        Lin {
            c: rgb565(raw),
            a: ALPHA_ONE,
        }
    }
}

impl sealed::Decode for Rgb888 {
    const BITS: u32 = 24;
    const OPAQUE: bool = true;
    const MASK: bool = false;
    const GRAY: bool = false;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        let b = row.get(3 * x..3 * x + 3)?;
        Some(u32::from(b[0]) << 16 | u32::from(b[1]) << 8 | u32::from(b[2]))
    }
    #[inline(always)]
    fn decode(raw: u32, _: u8, _: u32) -> Lin {
        Lin {
            c: [srgb8(raw >> 16), srgb8(raw >> 8), srgb8(raw)],
            a: ALPHA_ONE,
        }
    }
}

impl sealed::Decode for Gray8 {
    const BITS: u32 = 8;
    const OPAQUE: bool = true;
    const MASK: bool = false;
    const GRAY: bool = true;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        row.get(x).map(|&b| u32::from(b))
    }
    #[inline(always)]
    fn decode(raw: u32, _: u8, _: u32) -> Lin {
        let g = srgb8(raw);
        Lin {
            c: [g; 3],
            a: ALPHA_ONE,
        }
    }
}

impl sealed::Decode for Rgba8888 {
    const BITS: u32 = 32;
    const OPAQUE: bool = false;
    const MASK: bool = false;
    const GRAY: bool = false;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        let b = row.get(4 * x..4 * x + 4)?;
        Some(u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
    }
    #[inline(always)]
    fn decode(raw: u32, _: u8, _: u32) -> Lin {
        let a = u32::from(ALPHA8[(raw & 255) as usize]);
        let c = [srgb8(raw >> 24), srgb8(raw >> 16), srgb8(raw >> 8)];
        Lin {
            c: premultiply(c, a),
            a,
        }
    }
}

macro_rules! mask {
    ($name:ident, $bits:expr, $alpha:expr) => {
        impl sealed::Decode for $name {
            const BITS: u32 = $bits;
            const OPAQUE: bool = false;
            const MASK: bool = true;
            const GRAY: bool = true;
            #[inline(always)]
            // One texel a byte for `Alpha8`: `x % 1` is 0, as it should be.
            #[allow(clippy::modulo_one, clippy::identity_op)]
            fn raw(row: &[u8], x: usize) -> Option<u32> {
                const PER_BYTE: usize = 8 / $bits;
                let b = u32::from(*row.get(x / PER_BYTE)?);
                let shift = 8 - $bits * (1 + (x % PER_BYTE) as u32);
                Some((b >> shift) & ((1 << $bits) - 1))
            }
            #[inline(always)]
            fn decode(raw: u32, _: u8, _: u32) -> Lin {
                let alpha: fn(u32) -> u32 = $alpha;
                let a = alpha(raw);
                Lin { c: [0; 3], a }
            }
        }
    };
}

mask!(Alpha1, 1, |v| v << ALPHA_BITS);
mask!(Alpha2, 2, |v| u32::from(ALPHA2[(v & 3) as usize]));
mask!(Alpha4, 4, |v| u32::from(ALPHA4[(v & 15) as usize]));
mask!(Alpha8, 8, |v| u32::from(ALPHA8[(v & 255) as usize]));

impl<F: sealed::Decode + Default> sealed::Decode for Keyed<F> {
    const BITS: u32 = F::BITS;
    const OPAQUE: bool = false;
    const MASK: bool = F::MASK;
    const GRAY: bool = F::GRAY;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        F::raw(row, x)
    }
    #[inline(always)]
    fn decode(raw: u32, plane: u8, key: u32) -> Lin {
        if raw == key {
            Lin { c: [0; 3], a: 0 }
        } else {
            F::decode(raw, plane, key)
        }
    }
}

impl<F: sealed::Decode + Default> sealed::Decode for PlaneAlpha<F> {
    const BITS: u32 = F::BITS;
    const OPAQUE: bool = false;
    const MASK: bool = F::MASK;
    const GRAY: bool = F::GRAY;
    const PLANE: bool = true;
    #[inline(always)]
    fn raw(row: &[u8], x: usize) -> Option<u32> {
        F::raw(row, x)
    }
    #[inline(always)]
    fn decode(raw: u32, plane: u8, key: u32) -> Lin {
        let t = F::decode(raw, plane, key);
        let a = (t.a * u32::from(ALPHA8[usize::from(plane)]) + ALPHA_ONE / 2) >> ALPHA_BITS;
        Lin {
            c: premultiply(t.c, u32::from(ALPHA8[usize::from(plane)])),
            a,
        }
    }
}

/// 8-bit `r, g, b, a` (straight alpha) decoded as [`Rgba8888`] does.
#[inline(always)]
pub(crate) fn rgba(t: [u8; 4]) -> Lin {
    <Rgba8888 as sealed::Decode>::decode(u32::from_be_bytes(t), u8::MAX, 0)
}

/// A texel's linear luminance (Rec. 709 weights of
/// [`luminance`](crate::color::srgb::luminance)).
#[inline(always)]
pub(crate) fn luma(c: [u32; 3]) -> u32 {
    u32::from(luminance([c[0] as u16, c[1] as u16, c[2] as u16]))
}

#[cfg(test)]
mod tests {
    use super::sealed::Decode;
    use super::*;

    #[test]
    fn alpha_tables_span_zero_to_one() {
        assert_eq!(ALPHA8[0], 0);
        assert_eq!(ALPHA8[255], 1024);
        assert_eq!(ALPHA8[128], 514); // 1024 * 128 / 255 = 514.0
        assert_eq!(ALPHA2, [0, 341, 683, 1024]);
        assert_eq!(ALPHA4[15], 1024);
    }

    #[test]
    fn masks_read_high_bits_first() {
        let row = [0b1000_0001u8, 0b0100_0000];
        let bits: [u32; 16] = core::array::from_fn(|x| Alpha1::raw(&row, x).unwrap());
        assert_eq!(bits, [1, 0, 0, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 0, 0]);
        assert_eq!(Alpha1::raw(&row, 16), None);
        assert_eq!(Alpha2::raw(&[0b11_01_00_10], 1), Some(1));
        assert_eq!(Alpha4::raw(&[0xa5], 0), Some(0xa));
        assert_eq!(Alpha4::raw(&[0xa5], 1), Some(0x5));
        assert_eq!(Alpha1::decode(1, 255, 0).a, 1024);
    }

    #[test]
    fn colours_decode_by_the_srgb_tables() {
        // Rgb565 0xf81f: red and blue full, green 0.
        let le = [0x1f, 0xf8];
        let raw = Rgb565::raw(&le, 0).unwrap();
        assert_eq!(raw, 0xf81f);
        assert_eq!(Rgb565::decode(raw, 255, 0).c, [4095, 0, 4095]);
        assert_eq!(Rgb565Be::raw(&[0xf8, 0x1f], 0), Some(0xf81f));
        let t = Rgba8888::decode(Rgba8888::raw(&[255, 128, 0, 128], 0).unwrap(), 255, 0);
        assert_eq!(t.a, 514);
        assert_eq!(t.c, [(4095 * 514 + 512) >> 10, (884 * 514 + 512) >> 10, 0]);
        assert_eq!(
            Keyed::<Rgb565>::decode(0xf81f, 255, 0xf81f),
            Lin { c: [0; 3], a: 0 }
        );
        let p = PlaneAlpha::<Gray8>::decode(255, 0, 0);
        assert_eq!(p, Lin { c: [0; 3], a: 0 });
    }
}
