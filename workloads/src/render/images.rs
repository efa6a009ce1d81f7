//! Images (issue #35): a 64x64 Rgb565 sprite and a 24-px 1-bpp icon in
//! flash (`const` data), drawn by softedge's `AaImage` alone on a 240x240
//! Rgb565 frame in 16-row bands: unscaled at a whole pixel (the copy
//! path), rotated 30° (bilinear), and the icon scaled to 48 px and tinted.
//! The benchmark's marginal cost is the frame with the image minus
//! [`Image::None`].

use core::hint::black_box;

use embedded_graphics::pixelcolor::Rgb565;
use embedded_graphics::prelude::*;
use softedge::image::{format, AaImage, RawImage, Scale};
use softedge::path::Degrees;
use softedge::prelude::*;

use super::softedge_side::{Buffers, FrameError};
use super::targets::BandStream;
use super::ui::{Frames, Lent};
use crate::FRAME;

/// Band height of the image frames.
pub const BAND_ROWS: u16 = super::ui::BAND_ROWS;

/// Side of the sprite, texels.
pub const SPRITE_SIDE: u16 = 64;
/// Side of the icon, texels.
pub const ICON_SIDE: u16 = 24;

/// The sprite: 64x64 Rgb565, little endian; red along x, green along y,
/// a blue checker of 8-texel squares.
pub static SPRITE: [u8; 2 * 64 * 64] = sprite();

const fn sprite() -> [u8; 2 * 64 * 64] {
    let mut d = [0u8; 2 * 64 * 64];
    let mut j = 0;
    while j < 64 {
        let mut i = 0;
        while i < 64 {
            let r = (i / 2) as u16;
            let g = j as u16;
            let b = if (i / 8 + j / 8) % 2 == 0 { 28 } else { 4 };
            let v = r << 11 | g << 5 | b;
            let k = 2 * (j * 64 + i);
            d[k] = v as u8;
            d[k + 1] = (v >> 8) as u8;
            i += 1;
        }
        j += 1;
    }
    d
}

/// The icon: 24x24, 1 bit a texel (3 bytes a row, the first texel in bit
/// 7): a ring of radius 7..11 about the centre and a bar across it.
pub static ICON: [u8; 3 * 24] = icon();

const fn icon() -> [u8; 3 * 24] {
    let mut d = [0u8; 3 * 24];
    let mut j = 0;
    while j < 24 {
        let mut i = 0;
        while i < 24 {
            // Twice the offsets from the centre (12, 12) of texel centres.
            let (dx, dy) = (2 * i as i32 + 1 - 24, 2 * j as i32 + 1 - 24);
            let r2 = dx * dx + dy * dy;
            let ring = r2 >= 4 * 7 * 7 && r2 <= 4 * 11 * 11;
            let bar = dy * dy <= 4 * 2 * 2 && dx * dx <= 4 * 9 * 9;
            if ring || bar {
                d[j * 3 + i / 8] |= 0x80 >> (i % 8);
            }
            i += 1;
        }
        j += 1;
    }
    d
}

/// What one image frame draws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Image {
    /// Nothing: the frame's fixed cost.
    None,
    /// The sprite unscaled with its top-left corner at pixel (88, 88).
    Copy64,
    /// The sprite rotated 30° about its centre, at the frame's centre.
    Rotated30,
    /// The icon scaled 2x (48 px), tinted, at the frame's centre.
    Icon48,
}

impl Image {
    /// Every case, in the order of the output.
    pub const ALL: [Image; 4] = [Image::None, Image::Copy64, Image::Rotated30, Image::Icon48];

    /// The name printed in the output.
    pub fn name(self) -> &'static str {
        match self {
            Image::None => "none",
            Image::Copy64 => "copy64",
            Image::Rotated30 => "rotated30",
            Image::Icon48 => "icon48",
        }
    }

    /// The pixels the image covers on screen (its transformed area).
    pub fn area(self) -> u32 {
        match self {
            Image::None => 0,
            Image::Copy64 | Image::Rotated30 => 64 * 64,
            Image::Icon48 => 48 * 48,
        }
    }
}

/// The icon's tint.
const TINT: Rgb565 = Rgb565::new(31, 40, 6);

/// A softedge frame of `image` alone, 16-row bands, into `bufs.out16`.
#[inline(never)]
pub fn softedge_image(image: Image, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    image_frame(image, bufs, false)
}

/// [`softedge_image`] with the one-band buffer lent for the band's pixels
/// to be made in (`Renderer::render_lent`).
pub fn softedge_image_lent(image: Image, bufs: &mut Buffers<'_>) -> Result<(), FrameError> {
    image_frame(image, bufs, true)
}

/// One frame of `image` into `bufs.out16`: streamed, or `lent`.
#[inline(never)]
fn image_frame(image: Image, bufs: &mut Buffers<'_>, lent: bool) -> Result<(), FrameError> {
    let sprite = RawImage::<format::Rgb565>::new(&SPRITE, SPRITE_SIDE, SPRITE_SIDE)
        .map_err(|_| FrameError)?;
    let icon =
        RawImage::<format::Alpha1>::new(&ICON, ICON_SIDE, ICON_SIDE).map_err(|_| FrameError)?;
    let out = &mut *bufs.out16;
    let mut sink = BandStream::new(out, u32::from(FRAME), u32::from(FRAME));
    let mut r = softedge::render::Renderer::<3>::new(
        &mut *bufs.acc,
        &mut *bufs.cover,
        &mut *bufs.slots3,
        FRAME,
        FRAME,
        BAND_ROWS,
    )
    .map_err(|_| FrameError)?;
    let centre = FinePoint::from_px(120, 120);
    let draw = |c: &mut softedge::canvas::Canvas<'_, '_, 3, Rgb565>| match image {
        Image::None => Ok(()),
        Image::Copy64 => AaImage::new(&sprite).at(Point::new(88, 88)).draw(c),
        Image::Rotated30 => AaImage::new(&sprite)
            .center(centre)
            .rotate(Degrees::new(30))
            .draw(c),
        Image::Icon48 => AaImage::new(&icon)
            .center(centre)
            .scale(Scale::from_int(2))
            .tint(TINT)
            .draw(c),
    };
    if lent {
        Lent(&mut sink).frame(&mut r, None, draw)?;
    } else {
        sink.frame(&mut r, None, draw)?;
    }
    black_box(sink.pixels());
    Ok(())
}

#[cfg(test)]
mod tests {
    extern crate std;
    use std::vec;

    use super::*;
    use crate::render::softedge_side::{ACC_LEN, COVER_LEN, LIST_LEN, OUT_LEN, SLOTS};
    use softedge::canvas::{ListedTriangle, WalkSlot};

    #[test]
    fn every_image_frame_renders() {
        let mut acc = vec![0; ACC_LEN];
        let mut cover = vec![0; COVER_LEN];
        let mut out16 = vec![0; OUT_LEN];
        let mut out8 = vec![0; OUT_LEN];
        let mut slots3 = vec![WalkSlot::<3>::EMPTY; SLOTS];
        let mut slots1 = vec![WalkSlot::<1>::EMPTY; SLOTS];
        let mut list3 = vec![ListedTriangle::<3>::EMPTY; LIST_LEN];
        let mut bufs = Buffers {
            acc: &mut acc,
            cover: &mut cover,
            out16: &mut out16,
            out8: &mut out8,
            slots3: &mut slots3,
            slots1: &mut slots1,
            list3: &mut list3,
        };
        for image in Image::ALL {
            assert!(softedge_image(image, &mut bufs).is_ok(), "{}", image.name());
        }
        // The icon's ring and bar are set, its corners clear.
        assert_eq!(ICON[0], 0);
        assert_eq!(ICON[12 * 3 + 1], 0xff);
    }
}
