//! `softedge-sim render`, `crc` and `bits`, and the example scenes.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use softedge::postfilter::LightnessFilter;
use softedge_sim::scene_file::{load, Linear};

fn sim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn examples() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes")
}

fn quickstart() -> String {
    examples()
        .join("quickstart.toml")
        .to_str()
        .unwrap()
        .to_string()
}

/// A fresh temporary directory for one test.
fn temp_dir(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softedge-scene-cli-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn decode_png(path: &Path) -> (png::OutputInfo, Vec<u8>) {
    let dec = png::Decoder::new(std::fs::File::open(path).unwrap());
    let mut reader = dec.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size()];
    let info = reader.next_frame(&mut buf).unwrap();
    buf.truncate(info.buffer_size());
    (info, buf)
}

#[test]
fn help_lists_the_scene_commands() {
    let text = String::from_utf8(sim(&["--help"]).stdout).unwrap();
    for cmd in [
        "render SCENE.toml -o OUT.png",
        "crc SCENE.toml",
        "bits --contrast",
        "window SCENE.toml",
    ] {
        assert!(text.contains(cmd), "{cmd}: {text}");
    }
}

#[test]
fn render_writes_a_png_of_the_display_size_times_scale() {
    let dir = temp_dir("png");
    let out = dir.join("q.png");
    let run = sim(&[
        "render",
        &quickstart(),
        "-o",
        out.to_str().unwrap(),
        "--scale",
        "3",
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let (info, pixels) = decode_png(&out);
    assert_eq!((info.width, info.height), (64 * 3, 48 * 3));
    assert_eq!(info.color_type, png::ColorType::Grayscale);
    // Nearest-neighbour: each 3x3 block is one code, the codes of gray8.
    let file = load(&examples().join("quickstart.toml")).unwrap();
    let codes = file.tone(&file.render_linear().unwrap());
    for (y, x) in [(0, 0), (5, 7), (20, 30), (47, 63)] {
        let want = codes.bytes()[y * 64 + x];
        for (dy, dx) in [(0, 0), (2, 2)] {
            assert_eq!(pixels[(y * 3 + dy) * 192 + x * 3 + dx], want, "({x}, {y})");
        }
    }
    // Without --scale: 1:1.
    let run = sim(&["render", &quickstart(), "-o", out.to_str().unwrap()]);
    assert!(run.status.success());
    assert_eq!(decode_png(&out).0.width, 64);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn raw_is_16_bit_netpbm_of_the_linear_values() {
    let dir = temp_dir("raw");
    let (png_path, raw) = (dir.join("q.png"), dir.join("q.pgm"));
    let run = sim(&[
        "render",
        &quickstart(),
        "-o",
        png_path.to_str().unwrap(),
        "--raw",
        raw.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let bytes = std::fs::read(&raw).unwrap();
    let header = b"P5\n64 48\n4095\n";
    assert_eq!(&bytes[..header.len()], header);
    let body = &bytes[header.len()..];
    assert_eq!(body.len(), 64 * 48 * 2);
    let file = load(&examples().join("quickstart.toml")).unwrap();
    let Linear::Gray(img) = file.render_linear().unwrap() else {
        panic!("quickstart is gray");
    };
    let values: Vec<u16> = body
        .chunks_exact(2)
        .map(|b| u16::from_be_bytes([b[0], b[1]]))
        .collect();
    let want: Vec<u16> = img.pixels().map(|[v]| v).collect();
    assert_eq!(values, want);
    assert!(
        values.iter().any(|&v| v > 0 && v < 4095),
        "anti-aliased values"
    );

    // Three channels: P6, 6 bytes per pixel.
    let rgb = examples().join("gouraud_rgb.toml");
    let run = sim(&[
        "render",
        rgb.to_str().unwrap(),
        "-o",
        png_path.to_str().unwrap(),
        "--raw",
        raw.to_str().unwrap(),
    ]);
    assert!(run.status.success());
    let bytes = std::fs::read(&raw).unwrap();
    let header = b"P6\n96 64\n4095\n";
    assert_eq!(&bytes[..header.len()], header);
    assert_eq!(bytes.len() - header.len(), 96 * 64 * 6);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn raw_with_the_lightness_filter_is_the_filtered_frame() {
    let dir = temp_dir("filter");
    let scene = dir.join("pale.toml");
    std::fs::write(
        &scene,
        "[display]\nwidth = 24\nheight = 19\nformat = \"gray8\"\nbackground = [2500]\n\
         [render]\nlightness_filter = true\nband_rows = 5\n\
         [[triangle]]\npoints = [[1.5, 2.25], [22.0, 6.5], [6.0, 17.75]]\ncolor = [3900]\n\
         [[line]]\nfrom = [0, 18]\nto = [24, 1]\ncolor = [1500]\n",
    )
    .unwrap();
    let (png_path, raw) = (dir.join("p.png"), dir.join("p.pgm"));
    let run = sim(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        png_path.to_str().unwrap(),
        "--raw",
        raw.to_str().unwrap(),
    ]);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let bytes = std::fs::read(&raw).unwrap();
    let header = b"P5\n24 19\n4095\n";
    assert_eq!(&bytes[..header.len()], header);
    let values: Vec<u16> = bytes[header.len()..]
        .chunks_exact(2)
        .map(|b| u16::from_be_bytes([b[0], b[1]]))
        .collect();
    // The same frame rendered without the filter, then filtered whole.
    let mut file = load(&scene).unwrap();
    assert!(file.lightness_filter);
    file.lightness_filter = false;
    let Linear::Gray(plain) = file.render_linear().unwrap() else {
        panic!("a gray scene");
    };
    let plain: Vec<[u16; 1]> = plain.pixels().collect();
    let mut want = vec![[0u16]; plain.len()];
    let mut scratch = vec![0u16; LightnessFilter::scratch_len(24)];
    let stats = LightnessFilter::new(24, 19)
        .unwrap()
        .filter_frame(&plain, &mut want, &mut scratch)
        .unwrap();
    assert!(stats.changed > 0);
    let want: Vec<u16> = want.iter().map(|[v]| *v).collect();
    assert_eq!(values, want);
    assert_ne!(values, plain.iter().map(|[v]| *v).collect::<Vec<_>>());
    // The PNG is the tone stage of the filtered frame.
    file.lightness_filter = true;
    let codes = file.tone(&file.render_linear().unwrap());
    assert_eq!(decode_png(&png_path).1, codes.bytes());
    std::fs::remove_dir_all(&dir).unwrap();
}

fn bits(k: &str, d: &str, g: &str) -> Vec<(String, f64)> {
    let out = sim(&["bits", "--contrast", k, "--delta", d, "--gamma", g]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| {
            let (name, v) = l.split_once(' ').unwrap();
            (name.to_string(), v.parse().unwrap())
        })
        .collect()
}

#[test]
fn bits_prints_the_seed_numbers() {
    // Seed 000: K = 100, gamma = 2.4; delta 5 % .. 2 %.
    let b = bits("100", "0.05", "2.4");
    let names: Vec<&str> = b.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["N_I", "N_U", "m"]);
    assert_eq!(b[0].1, 1980.0);
    assert!((164.5..166.0).contains(&b[1].1), "{b:?}");
    assert_eq!(b[2].1, 94.4);
    let b = bits("100", "0.02", "2.4");
    assert_eq!(b[0].1, 4950.0);
    assert!((412.0..414.0).contains(&b[1].1), "{b:?}");
    assert_eq!(b[2].1, 232.6);
    let text = String::from_utf8(
        sim(&[
            "bits",
            "--contrast",
            "100",
            "--delta",
            "0.02",
            "--gamma",
            "2.4",
        ])
        .stdout,
    )
    .unwrap();
    assert!(text.starts_with("N_I 4950.0\nN_U "), "{text}");
    assert!(text.ends_with("\nm 232.6\n"), "{text}");
}

#[test]
fn bits_rejects_bad_input() {
    let out = sim(&[
        "bits",
        "--contrast",
        "1",
        "--delta",
        "0.02",
        "--gamma",
        "2.4",
    ]);
    assert_eq!(out.status.code(), Some(1));
    let out = sim(&[
        "bits",
        "--contrast",
        "x",
        "--delta",
        "0.02",
        "--gamma",
        "2.4",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let out = sim(&["bits", "--contrast", "100"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn crc_is_stable_and_follows_the_scene() {
    let a = sim(&["crc", &quickstart()]);
    let b = sim(&["crc", &quickstart()]);
    assert!(a.status.success());
    assert_eq!(a.stdout, b.stdout);
    let line = String::from_utf8(a.stdout).unwrap();
    let parts: Vec<&str> = line.split_whitespace().collect();
    assert_eq!(parts[..2], ["crc", "quickstart"]);
    assert_eq!(parts[2].len(), 8);
    assert!(parts[2]
        .chars()
        .all(|c| c.is_ascii_hexdigit() && !c.is_ascii_uppercase()));

    // The same scene with the rectangle's colour changed.
    let dir = temp_dir("crc");
    let text = std::fs::read_to_string(examples().join("quickstart.toml")).unwrap();
    let changed = text.replace("color = [3000]", "color = [2000]");
    assert_ne!(text, changed);
    let path = dir.join("quickstart.toml");
    std::fs::write(&path, changed).unwrap();
    let c = sim(&["crc", path.to_str().unwrap()]);
    std::fs::remove_dir_all(&dir).unwrap();
    let other = String::from_utf8(c.stdout).unwrap();
    assert!(other.starts_with("crc quickstart "));
    assert_ne!(other, line);
}

#[test]
fn crc_is_of_the_display_byte_stream() {
    let file = load(&examples().join("gouraud_rgb.toml")).unwrap();
    let codes = file.tone(&file.render_linear().unwrap());
    assert_eq!(codes.bytes().len(), 96 * 64 * 2); // rgb565, big-endian
    let out = sim(&["crc", examples().join("gouraud_rgb.toml").to_str().unwrap()]);
    let line = String::from_utf8(out.stdout).unwrap();
    assert_eq!(
        line,
        format!("crc gouraud_rgb {:08x}\n", crc32fast::hash(&codes.bytes()))
    );
}

#[test]
fn binary_display_is_dithered_to_0_and_1() {
    let file = load(&examples().join("oled_binary.toml")).unwrap();
    let codes = file.tone(&file.render_linear().unwrap());
    let bytes = codes.bytes();
    assert_eq!(bytes.len(), 128 * 64);
    assert!(bytes.iter().all(|&b| b <= 1));
    let on = bytes.iter().filter(|&&b| b == 1).count();
    assert!(on > 500 && on < 128 * 64 / 2, "{on} pixels on");
    let img = codes.to_image8();
    assert!(img.data().iter().all(|&v| v == 0 || v == 255));
}

#[test]
fn every_example_scene_renders() {
    let mut names = Vec::new();
    for entry in std::fs::read_dir(examples()).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("toml") {
            continue;
        }
        let file = load(&path).unwrap_or_else(|d| panic!("{d}"));
        assert!(file.warnings.is_empty(), "{:?}", file.warnings);
        let lin = file.render_linear().unwrap_or_else(|d| panic!("{d}"));
        let (w, h) = file.size();
        assert_eq!(lin.size(), (u32::from(w), u32::from(h)));
        // Something was drawn over the background.
        let values = lin.values();
        assert!(values.iter().any(|&v| v != values[0]), "{}", path.display());
        let img = file.tone(&lin).to_image8();
        assert_eq!((img.width(), img.height()), (u32::from(w), u32::from(h)));
        names.push(file.stem());
    }
    names.sort();
    for want in [
        "composite",
        "gouraud_rgb",
        "lines",
        "mesh",
        "oled_binary",
        "quickstart",
        "torus",
    ] {
        assert!(names.iter().any(|n| n == want), "{want} missing: {names:?}");
    }
}

#[test]
fn the_mesh_renders_like_its_polygon() {
    // examples/scenes/mesh.toml: the 24-triangle grid and the same outline
    // as one polygon, 28 px lower, must match to the last bit.
    let file = load(&examples().join("mesh.toml")).unwrap();
    let Linear::Gray(img) = file.render_linear().unwrap() else {
        panic!("gray");
    };
    for y in 0..25 {
        for x in 0..44 {
            assert_eq!(img.get(x, y), img.get(x, y + 28), "({x}, {y})");
        }
    }
}

#[test]
fn window_without_the_feature_says_how_to_get_it() {
    if cfg!(feature = "window") {
        return;
    }
    let out = sim(&["window", &quickstart()]);
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--features window"), "{err}");
}
