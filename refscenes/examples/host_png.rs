//! Writes every reference scene as an 8-bit PNG (linear 12-bit values
//! shifted to 8 bits, no γ: a look at the geometry, not a display preview)
//! into the directory given as the first argument (default `target/refscenes`),
//! each pixel blown up to a `ZOOM x ZOOM` square (second argument, default 1).
//!
//! `cargo run -p softedge-refscenes --example host_png -- DIR ZOOM`

use softedge_refscenes::{render, stream::ByteSink, ACC_LEN, COVER_LEN, SCENES};
use std::{fs::File, io::BufWriter, path::PathBuf};

/// Collects the display stream (2 bytes big-endian per channel) as 8 bits.
struct Bytes8 {
    out: Vec<u8>,
    pending: Option<u8>,
}

impl ByteSink for Bytes8 {
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            match self.pending.take() {
                None => self.pending = Some(b),
                Some(hi) => self.out.push((u16::from_be_bytes([hi, b]) >> 4) as u8),
            }
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let dir = PathBuf::from(std::env::args().nth(1).unwrap_or("target/refscenes".into()));
    let zoom: usize = std::env::args().nth(2).map_or(Ok(1), |z| z.parse())?;
    std::fs::create_dir_all(&dir)?;
    let (mut acc, mut cover) = (vec![0i32; ACC_LEN], vec![0i32; COVER_LEN]);
    for scene in SCENES {
        let mut sink = Bytes8 {
            out: Vec::new(),
            pending: None,
        };
        let color = match scene.channels {
            1 => {
                render::<1>(scene, scene.band_rows, &mut acc, &mut cover, &mut sink)
                    .map_err(|e| format!("{}: {e:?}", scene.name))?;
                png::ColorType::Grayscale
            }
            _ => {
                render::<3>(scene, scene.band_rows, &mut acc, &mut cover, &mut sink)
                    .map_err(|e| format!("{}: {e:?}", scene.name))?;
                png::ColorType::Rgb
            }
        };
        let (w, h, ch) = (
            usize::from(scene.width),
            usize::from(scene.height),
            usize::from(scene.channels),
        );
        let mut big = Vec::with_capacity(sink.out.len() * zoom * zoom);
        for row in sink.out.chunks_exact(w * ch) {
            let mut line = Vec::with_capacity(row.len() * zoom);
            for px in row.chunks_exact(ch) {
                for _ in 0..zoom {
                    line.extend_from_slice(px);
                }
            }
            for _ in 0..zoom {
                big.extend_from_slice(&line);
            }
        }
        debug_assert_eq!(big.len(), w * h * ch * zoom * zoom);
        let path = dir.join(format!("{}.png", scene.name));
        let mut enc = png::Encoder::new(
            BufWriter::new(File::create(&path)?),
            (w * zoom) as u32,
            (h * zoom) as u32,
        );
        enc.set_color(color);
        enc.set_depth(png::BitDepth::Eight);
        enc.write_header()?.write_image_data(&big)?;
        println!("{}", path.display());
    }
    Ok(())
}
