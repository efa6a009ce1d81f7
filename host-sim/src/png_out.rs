//! PNG output with the `png` crate: 8-bit gray or RGB, sRGB tagged; and
//! reading such files back (for golden-image tests).

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::Path;

use crate::image::{Channels, Image8};

/// Encodes `img` as PNG into `w`, fast.
pub fn encode_png<W: Write>(img: &Image8, w: W) -> io::Result<()> {
    encode(img, w, false)
}

/// Encodes `img` as PNG into `w`, as small as the encoder can (best
/// deflate, a filter chosen per row): for files kept in the repository.
/// Several times slower than [`encode_png`]; the same pixels.
pub fn encode_png_compact<W: Write>(img: &Image8, w: W) -> io::Result<()> {
    encode(img, w, true)
}

fn encode<W: Write>(img: &Image8, w: W, compact: bool) -> io::Result<()> {
    let mut enc = png::Encoder::new(w, img.width(), img.height());
    if compact {
        enc.set_compression(png::Compression::Best);
        enc.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    }
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

/// Writes `img` as a PNG file at `path` with [`encode_png_compact`].
pub fn write_png_compact(path: &Path, img: &Image8) -> io::Result<()> {
    let file = File::create(path)?;
    let mut w = BufWriter::new(file);
    encode_png_compact(img, &mut w)?;
    w.flush()
}

/// Reads an 8-bit gray or RGB PNG file (as [`write_png`] writes them)
/// into an [`Image8`]; other colour types and depths are an
/// [`io::ErrorKind::InvalidData`] error.
pub fn read_png(path: &Path) -> io::Result<Image8> {
    let file = File::open(path)?;
    let mut reader = png::Decoder::new(io::BufReader::new(file))
        .read_info()
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))?;
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| io::Error::new(io::ErrorKind::InvalidData, e))?;
    buf.truncate(info.buffer_size());
    let channels = match (info.color_type, info.bit_depth) {
        (png::ColorType::Grayscale, png::BitDepth::Eight) => Channels::Gray,
        (png::ColorType::Rgb, png::BitDepth::Eight) => Channels::Rgb,
        (c, d) => {
            return Err(io::Error::new(
                io::ErrorKind::InvalidData,
                format!("{}: {c:?} {d:?}, not 8-bit gray or RGB", path.display()),
            ))
        }
    };
    Image8::from_raw(info.width, info.height, channels, buf).ok_or_else(|| {
        io::Error::new(
            io::ErrorKind::InvalidData,
            format!("{}: pixel data does not fit its size", path.display()),
        )
    })
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
    fn compact_encoding_keeps_the_pixels_and_reads_back() {
        let img = pattern(40, 30, Channels::Rgb);
        let (mut fast, mut small) = (Vec::new(), Vec::new());
        encode_png(&img, &mut fast).unwrap();
        encode_png_compact(&img, &mut small).unwrap();
        assert_eq!(decode(&small).1, img.data());
        let dir = std::env::temp_dir().join(format!("softedge-sim-png-c-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("c.png");
        write_png_compact(&path, &img).unwrap();
        let back = read_png(&path).unwrap();
        std::fs::write(&path, b"not a png").unwrap();
        let bad = read_png(&path);
        std::fs::remove_dir_all(&dir).unwrap();
        assert_eq!(back, img);
        assert_eq!(bad.unwrap_err().kind(), io::ErrorKind::InvalidData);
    }

    #[test]
    fn unwritable_path_is_an_error_not_a_panic() {
        let img = pattern(1, 1, Channels::Gray);
        let path = Path::new("/nonexistent-softedge-dir/x/y.png");
        assert!(write_png(path, &img).is_err());
    }
}
