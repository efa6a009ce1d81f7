//! PNG output with the `png` crate: 8-bit gray or RGB, sRGB tagged.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use crate::image::{Channels, Image8};

/// Encodes `img` as PNG into `w`.
pub fn encode_png<W: Write>(img: &Image8, w: W) -> io::Result<()> {
    let mut enc = png::Encoder::new(w, img.width(), img.height());
    enc.set_color(match img.channels() {
        Channels::Gray => png::ColorType::Grayscale,
        Channels::Rgb => png::ColorType::Rgb,
    });
    enc.set_depth(png::BitDepth::Eight);
    // The bytes are sRGB codes (see `image::lin12_to_srgb8`).
    enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = enc.write_header().map_err(to_io)?;
    writer.write_image_data(img.data()).map_err(to_io)?;
    writer.finish().map_err(to_io)
}

/// Writes `img` as a PNG file at `path`.
pub fn write_png(path: &Path, img: &Image8) -> io::Result<()> {
    let file = File::create(path)?;
    let mut w = BufWriter::new(file);
    encode_png(img, &mut w)?;
    w.flush()
}

fn to_io(e: png::EncodingError) -> io::Error {
    match e {
        png::EncodingError::IoError(e) => e,
        other => io::Error::other(other),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn decode(bytes: &[u8]) -> (png::OutputInfo, Vec<u8>) {
        let dec = png::Decoder::new(bytes);
        let mut reader = dec.read_info().unwrap();
        let mut buf = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut buf).unwrap();
        buf.truncate(info.buffer_size());
        (info, buf)
    }

    fn pattern(w: u32, h: u32, channels: Channels) -> Image8 {
        let n = w as usize * h as usize * channels.count();
        let data = (0..n).map(|k| (k * 37 % 251) as u8).collect();
        Image8::from_raw(w, h, channels, data).unwrap()
    }

    #[test]
    fn rgb_round_trip_is_lossless() {
        let img = pattern(13, 7, Channels::Rgb);
        let mut bytes = Vec::new();
        encode_png(&img, &mut bytes).unwrap();
        let (info, pixels) = decode(&bytes);
        assert_eq!((info.width, info.height), (13, 7));
        assert_eq!(info.color_type, png::ColorType::Rgb);
        assert_eq!(info.bit_depth, png::BitDepth::Eight);
        assert_eq!(pixels, img.data());
    }

    #[test]
    fn gray_round_trip_through_a_file() {
        let img = pattern(5, 9, Channels::Gray);
        let dir = std::env::temp_dir().join(format!("softedge-sim-png-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("gray.png");
        write_png(&path, &img).unwrap();
        let (info, pixels) = decode(&std::fs::read(&path).unwrap());
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(info.color_type, png::ColorType::Grayscale);
        assert_eq!((info.width, info.height), (5, 9));
        assert_eq!(pixels, img.data());
    }

    #[test]
    fn unwritable_path_is_an_error_not_a_panic() {
        let img = pattern(1, 1, Channels::Gray);
        let path = Path::new("/nonexistent-softedge-dir/x/y.png");
        assert!(write_png(path, &img).is_err());
    }
}
