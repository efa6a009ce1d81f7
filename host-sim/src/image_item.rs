//! Images in a host scene (`[[image]]`): a PNG, QOI or BMP file decoded
//! to 8-bit RGBA (straight alpha), drawn into a band through the canvas
//! with softedge's `AaImage` (`softedge::image`, format `Rgba8888`).
//!
//! The decoders of QOI and BMP are small and written here from the
//! formats' descriptions (QOI 1.0; BMP's `BITMAPINFOHEADER` with 24- or
//! 32-bit uncompressed rows); PNG goes through the `png` crate.

use std::sync::Arc;

use softedge::canvas::Canvas;
use softedge::geom::FinePoint;
use softedge::image::{format::Rgba8888, AaImage, ImageError, RawImage, Scale};
use softedge::path::Degrees;
use softedge::style::{Blend, Opacity};
use softedge::{BandBuffer, DrawError, RenderStyle};

/// A decoded image: `width x height` texels of 8-bit `r, g, b, a`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rgba {
    /// Width, texels.
    pub width: u16,
    /// Height, texels.
    pub height: u16,
    /// Rows top to bottom, 4 bytes a texel.
    pub data: Arc<[u8]>,
}

/// Decodes a PNG, QOI or BMP file (told apart by their signatures).
pub fn decode(bytes: &[u8]) -> Result<Rgba, String> {
    if bytes.starts_with(b"\x89PNG") {
        decode_png(bytes)
    } else if bytes.starts_with(b"qoif") {
        decode_qoi(bytes)
    } else if bytes.starts_with(b"BM") {
        decode_bmp(bytes)
    } else {
        Err("not a PNG, QOI or BMP file".into())
    }
}

fn sized(width: u32, height: u32, data: Vec<u8>) -> Result<Rgba, String> {
    let max = u32::from(softedge::image::MAX_SIDE);
    if width == 0 || height == 0 || width > max || height > max {
        return Err(format!(
            "size {width}x{height} is empty or above {max} texels a side"
        ));
    }
    Ok(Rgba {
        width: width as u16,
        height: height as u16,
        data: Arc::from(data),
    })
}

fn decode_png(bytes: &[u8]) -> Result<Rgba, String> {
    let mut dec = png::Decoder::new(bytes);
    dec.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = dec.read_info().map_err(|e| format!("PNG: {e}"))?;
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("PNG: {e}"))?;
    let n = info.width as usize * info.height as usize;
    let src = &buf[..info.buffer_size()];
    let data: Vec<u8> = match info.color_type {
        png::ColorType::Rgba => src.to_vec(),
        png::ColorType::Rgb => src
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::Grayscale => src.iter().flat_map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::GrayscaleAlpha => src
            .chunks_exact(2)
            .flat_map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        other => return Err(format!("PNG: colour type {other:?} after expansion")),
    };
    if data.len() != 4 * n {
        return Err("PNG: unexpected data length".into());
    }
    sized(info.width, info.height, data)
}

fn decode_qoi(bytes: &[u8]) -> Result<Rgba, String> {
    let be = |k: usize| -> Result<u32, String> {
        bytes
            .get(k..k + 4)
            .map(|b| u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
            .ok_or_else(|| "QOI: truncated header".to_string())
    };
    let (width, height) = (be(4)?, be(8)?);
    let img = sized(width, height, Vec::new())?;
    let n = usize::from(img.width) * usize::from(img.height);
    let mut out = Vec::with_capacity(4 * n);
    let mut index = [[0u8; 4]; 64];
    let mut px = [0u8, 0, 0, 255];
    let mut at = 14;
    let byte = |k: usize| -> Result<u8, String> {
        bytes
            .get(k)
            .copied()
            .ok_or_else(|| "QOI: truncated data".to_string())
    };
    while out.len() < 4 * n {
        let op = byte(at)?;
        at += 1;
        let mut run = 1;
        match op {
            0xfe => {
                px = [byte(at)?, byte(at + 1)?, byte(at + 2)?, px[3]];
                at += 3;
            }
            0xff => {
                px = [byte(at)?, byte(at + 1)?, byte(at + 2)?, byte(at + 3)?];
                at += 4;
            }
            _ => match op >> 6 {
                0 => px = index[usize::from(op & 63)],
                1 => {
                    let d = |s: u8| ((op >> s) & 3).wrapping_sub(2);
                    px = [
                        px[0].wrapping_add(d(4)),
                        px[1].wrapping_add(d(2)),
                        px[2].wrapping_add(d(0)),
                        px[3],
                    ];
                }
                2 => {
                    let dg = (op & 63).wrapping_sub(32);
                    let b2 = byte(at)?;
                    at += 1;
                    let dr = (b2 >> 4).wrapping_sub(8).wrapping_add(dg);
                    let db = (b2 & 15).wrapping_sub(8).wrapping_add(dg);
                    px = [
                        px[0].wrapping_add(dr),
                        px[1].wrapping_add(dg),
                        px[2].wrapping_add(db),
                        px[3],
                    ];
                }
                _ => run = usize::from(op & 63) + 1,
            },
        }
        let [r, g, b, a] = px;
        let h =
            (usize::from(r) * 3 + usize::from(g) * 5 + usize::from(b) * 7 + usize::from(a) * 11)
                % 64;
        index[h] = px;
        for _ in 0..run {
            if out.len() < 4 * n {
                out.extend_from_slice(&px);
            }
        }
    }
    sized(width, height, out)
}

fn decode_bmp(bytes: &[u8]) -> Result<Rgba, String> {
    let le32 = |k: usize| -> Result<u32, String> {
        bytes
            .get(k..k + 4)
            .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
            .ok_or_else(|| "BMP: truncated header".to_string())
    };
    let le16 = |k: usize| -> Result<u16, String> {
        bytes
            .get(k..k + 2)
            .map(|b| u16::from_le_bytes([b[0], b[1]]))
            .ok_or_else(|| "BMP: truncated header".to_string())
    };
    let offset = le32(10)? as usize;
    let width = le32(18)? as i32;
    let height = le32(22)? as i32;
    let bpp = le16(28)?;
    let compression = le32(30)?;
    if !(bpp == 24 && compression == 0 || bpp == 32 && (compression == 0 || compression == 3)) {
        return Err(format!(
            "BMP: {bpp} bits a pixel, compression {compression}: only uncompressed 24- and 32-bit"
        ));
    }
    if width <= 0 || height == 0 {
        return Err("BMP: bad size".into());
    }
    let (w, h) = (width as u32, height.unsigned_abs());
    let bytes_pp = usize::from(bpp / 8);
    let stride = (w as usize * bytes_pp).div_ceil(4) * 4;
    let mut out = Vec::with_capacity(4 * w as usize * h as usize);
    let mut any_alpha = false;
    for j in 0..h as usize {
        let row = if height > 0 { h as usize - 1 - j } else { j };
        let start = offset + row * stride;
        let src = bytes
            .get(start..start + w as usize * bytes_pp)
            .ok_or("BMP: truncated data")?;
        for p in src.chunks_exact(bytes_pp) {
            let a = if bpp == 32 { p[3] } else { 255 };
            any_alpha |= a != 0;
            out.extend_from_slice(&[p[2], p[1], p[0], a]);
        }
    }
    if bpp == 32 && !any_alpha {
        // An alpha channel of zeros is an unused one.
        for p in out.chunks_exact_mut(4) {
            p[3] = 255;
        }
    }
    sized(w, h, out)
}

/// One `[[image]]` of a scene.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImageItem<const C: usize> {
    /// The decoded image.
    pub image: Rgba,
    /// Where its centre lands, fine units.
    pub center: FinePoint,
    /// Horizontal and vertical scale.
    pub scale: (Scale, Scale),
    /// Clockwise on screen about the centre.
    pub rotate: Degrees,
    /// Opacity of the whole image.
    pub opacity: Opacity,
    /// Drawn in this colour, the image's alpha (or luminance) as a mask.
    pub tint: Option<[u16; C]>,
}

impl<const C: usize> ImageItem<C> {
    /// Draws the image into one band with the scene's pixel model, added
    /// (seed 000's accumulation, as the other primitives of `draw`).
    pub fn draw(&self, buf: &mut BandBuffer<'_, C>, style: &RenderStyle) -> Result<(), DrawError> {
        let mut canvas = Canvas::new(buf, None);
        canvas.set_style(*style);
        self.compose(&mut canvas, Blend::Add, Opacity::OPAQUE)
    }

    /// Draws the image into a band's canvas with `blend`, at `opacity`
    /// (times its own).
    pub fn compose<Col>(
        &self,
        canvas: &mut Canvas<'_, '_, C, Col>,
        blend: Blend,
        opacity: Opacity,
    ) -> Result<(), DrawError> {
        let src = RawImage::<Rgba8888>::new(&self.image.data, self.image.width, self.image.height)
            .map_err(|fault| DrawError::Image(ImageError { image: "", fault }))?;
        let a = Opacity::from_4096ths(
            ((u32::from(self.opacity.to_4096ths()) * u32::from(opacity.to_4096ths()) + 2048) >> 12)
                as u16,
        );
        let img = AaImage::new(&src)
            .center(self.center)
            .scale_xy(self.scale.0, self.scale.1)
            .rotate(self.rotate)
            .opacity(a)
            .blend(blend);
        match self.tint {
            Some(t) => {
                let rgb: [u16; 3] = core::array::from_fn(|k| t[k.min(C - 1)]);
                canvas.draw_image(&img.tint(rgb))
            }
            None => canvas.draw_image(&img),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A QOI file written here by hand: 3x1, an RGB op, a run of 1, a diff.
    #[test]
    fn qoi_ops_decode() {
        let mut f = b"qoif".to_vec();
        f.extend_from_slice(&3u32.to_be_bytes());
        f.extend_from_slice(&1u32.to_be_bytes());
        f.extend_from_slice(&[4, 0]);
        f.extend_from_slice(&[0xfe, 10, 20, 30]); // rgb
        f.push(0xc0); // run of 1
        f.push(0x40 | (3 << 4) | (2 << 2) | 1); // dr +1, dg 0, db -1
        f.extend_from_slice(&[0, 0, 0, 0, 0, 0, 0, 1]);
        let img = decode(&f).unwrap();
        assert_eq!((img.width, img.height), (3, 1));
        assert_eq!(
            &*img.data,
            &[10, 20, 30, 255, 10, 20, 30, 255, 11, 20, 29, 255]
        );
    }

    #[test]
    fn bmp_rows_are_bottom_up_bgr() {
        // 1x2, 24-bit: rows padded to 4 bytes, the bottom row first.
        let mut f = vec![0u8; 54];
        f[0..2].copy_from_slice(b"BM");
        f[10..14].copy_from_slice(&54u32.to_le_bytes());
        f[14..18].copy_from_slice(&40u32.to_le_bytes());
        f[18..22].copy_from_slice(&1i32.to_le_bytes());
        f[22..26].copy_from_slice(&2i32.to_le_bytes());
        f[28..30].copy_from_slice(&24u16.to_le_bytes());
        f.extend_from_slice(&[1, 2, 3, 0, 4, 5, 6, 0]);
        let img = decode(&f).unwrap();
        assert_eq!(&*img.data, &[6, 5, 4, 255, 3, 2, 1, 255]);
        assert!(decode(b"GIF89a").is_err());
    }
}
