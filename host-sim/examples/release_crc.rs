//! Prints a CRC-32 of every reference scene and example scene under every
//! tone stage and dither mode, one line each, for comparing an optimized
//! build with a debug build (issue #18: a release build dithered
//! differently). CI runs it both ways and fails on any difference:
//!
//! ```sh
//! cargo run -q -p softedge-sim --example release_crc > debug.txt
//! cargo run -q --release -p softedge-sim --example release_crc > release.txt
//! diff debug.txt release.txt
//! ```
//!
//! Lines: `crc <refscene> <crc>` (the boards' listing, `host_crc`), then per
//! scene file `<mode> <file> <crc>` for its display's own stream (`display`),
//! and for channel 0 of its linear frame: `gray8`, `gray4`, `bayer` (Bayer
//! 8x8, each row from column 0 and from a column near `i32::MAX`) and
//! `floyd-steinberg`; RGB frames also `rgb565` and `rgb888`.

use std::path::{Path, PathBuf};

use softedge::tone::format::{Gray4Format, Gray8Format, Rgb565Format, Rgb888Format, ToneFormat};
use softedge::tone::{Bayer8, Curve, FloydSteinberg};
use softedge_refscenes::{render_crc, Buffers, ACC_LEN, COVERED_LEN, COVER_LEN, DEPTH_LEN, SCENES};
use softedge_sim::scene_file::{self, Linear};

fn main() {
    let mut acc = vec![0i32; ACC_LEN];
    let mut cover = vec![0i32; COVER_LEN];
    let (mut depth, mut covered) = (vec![0u16; DEPTH_LEN], vec![0u16; COVERED_LEN]);
    let mut bufs = Buffers {
        acc: &mut acc,
        cover: &mut cover,
        depth: &mut depth,
        covered: &mut covered,
    };
    let mut failed = false;
    for scene in SCENES {
        match render_crc(scene, &mut bufs) {
            Ok(crc) => println!("crc {} {crc:08x}", scene.name),
            Err(e) => {
                println!("error {} {e:?}", scene.name);
                failed = true;
            }
        }
    }
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let mut files: Vec<PathBuf> = ["refscenes/scenes", "examples/scenes"]
        .iter()
        .flat_map(|d| std::fs::read_dir(root.join(d)).into_iter().flatten())
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "toml"))
        .collect();
    files.sort();
    for path in files {
        let name = format!(
            "{}/{}",
            path.parent()
                .and_then(|p| p.file_name())
                .map(|s| s.to_string_lossy())
                .unwrap_or_default(),
            path.file_name().unwrap_or_default().to_string_lossy()
        );
        let lin = scene_file::load(&path).and_then(|f| {
            let lin = f.render_linear()?;
            println!("display {name} {:08x}", f.tone(&lin).crc32());
            Ok(lin)
        });
        match lin {
            Ok(lin) => tones(&name, &lin),
            Err(d) => {
                println!("error {name} {d}");
                failed = true;
            }
        }
    }
    if failed {
        std::process::exit(1);
    }
}

/// The CRC lines of every tone stage of `lin`.
fn tones(name: &str, lin: &Linear) {
    let (w, _) = lin.size();
    let w = w as usize;
    let gray: Vec<[u16; 1]> = match lin {
        Linear::Gray(img) => img.pixels().collect(),
        Linear::Rgb(img) => img.pixels().map(|[r, _, _]| [r]).collect(),
    };
    let crc = |bytes: &[u8]| crc32fast::hash(bytes);
    let g8 = Gray8Format::new(Curve::GAMMA_2_2);
    let g4 = Gray4Format::new(Curve::Srgb);
    let bytes: Vec<u8> = gray.iter().map(|&p| g8.code(p)).collect();
    println!("gray8 {name} {:08x}", crc(&bytes));
    let bytes: Vec<u8> = gray.iter().map(|&p| g4.code(p)).collect();
    println!("gray4 {name} {:08x}", crc(&bytes));
    let bayer = Bayer8::new();
    for x0 in [0, i32::MAX - 5] {
        let mut bytes = Vec::with_capacity(gray.len());
        let mut out = vec![0u8; w];
        for (y, row) in gray.chunks(w.max(1)).enumerate() {
            bayer.row(row, x0, y as i32, &mut out);
            bytes.extend_from_slice(&out);
        }
        println!("bayer@{x0} {name} {:08x}", crc(&bytes));
    }
    let mut err = vec![0i16; w];
    let mut fs = FloydSteinberg::new(&mut err);
    let mut bytes = Vec::with_capacity(gray.len());
    let mut out = vec![0u8; w];
    for row in gray.chunks(w.max(1)) {
        fs.row(row, &mut out);
        bytes.extend_from_slice(&out);
    }
    println!("floyd-steinberg {name} {:08x}", crc(&bytes));
    if let Linear::Rgb(img) = lin {
        let f = Rgb565Format::new(Curve::GAMMA_2_2);
        let bytes: Vec<u8> = img.pixels().flat_map(|p| f.code(p).to_be_bytes()).collect();
        println!("rgb565 {name} {:08x}", crc(&bytes));
        let f = Rgb888Format::new(Curve::Srgb);
        let bytes: Vec<u8> = img.pixels().flat_map(|p| f.code(p)).collect();
        println!("rgb888 {name} {:08x}", crc(&bytes));
    }
}
