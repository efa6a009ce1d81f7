//! Prints `crc <scene> <crc32, 8 hex digits>` for every reference scene,
//! rendered on the host with the same code the boards run.
//!
//! `cargo run -p softedge-refscenes --example host_crc`

use softedge_refscenes::{render_crc, Buffers, ACC_LEN, COVERED_LEN, COVER_LEN, DEPTH_LEN, SCENES};

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
            Ok(crc) => println!("crc {} {:08x}", scene.name, crc),
            Err(e) => {
                println!("error {} {:?}", scene.name, e);
                failed = true;
            }
        }
    }
    if failed {
        std::process::exit(1);
    }
}
