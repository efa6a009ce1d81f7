//! The reference scenes that host and boards share (`softedge-refscenes`,
//! Rust data) written as scene files in `refscenes/scenes/`: `softedge-sim
//! crc refscenes/scenes/NAME.toml` must print the very line the Cortex-M
//! firmware prints for NAME (`boards/check.sh`). The files are generated
//! from the Rust data by this test; `SOFTEDGE_BLESS=1 cargo test -p
//! softedge-sim --test refscenes_toml` rewrites them after a change.

use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::Command;

use softedge::path::LineCap;
use softedge::scene3d::{Projection, Shape as Solid};
use softedge::{PixelModel, SubPoint};
use softedge_refscenes::stream::Format;
use softedge_refscenes::{
    render_crc, Buffers, Fill, Pen, Scene, Shape, ACC_LEN, COVERED_LEN, COVER_LEN, DEPTH_LEN,
    SCENES,
};

fn px(v: i32) -> String {
    // Sub-pixels to pixels: v / 16 is exact in binary and in decimal.
    format!("{:?}", f64::from(v) / 16.0)
}

fn point(p: SubPoint) -> String {
    format!("[{}, {}]", px(p.x), px(p.y))
}

/// Linear 12-bit colour with the scene's channels; core clamps above 4095,
/// so writing the clamped value draws the same.
fn color(scene: &Scene, c: [u16; 3]) -> String {
    let n = usize::from(scene.channels);
    let v: Vec<String> = c.iter().take(n).map(|v| v.min(&4095).to_string()).collect();
    format!("[{}]", v.join(", "))
}

fn colors(scene: &Scene, cs: &[[u16; 3]]) -> String {
    let v: Vec<String> = cs.iter().map(|&c| color(scene, c)).collect();
    format!("[{}]", v.join(", "))
}

fn num(v: f64) -> String {
    format!("{v:?}")
}

/// Fine units (1/1024 px) to pixels, exact in binary and in decimal.
fn fine(v: i64) -> String {
    num(v as f64 / 1024.0)
}

fn fine_point(p: softedge::geom::FinePoint) -> String {
    format!("[{}, {}]", fine(p.x.into()), fine(p.y.into()))
}

/// Degrees from 1/65536 degree, exact (read back by `I16F16::from_num`).
fn degrees(d: softedge::path::Degrees) -> String {
    num(f64::from(d.bits()) / 65536.0)
}

/// The paint keys of a circle or an arc.
fn pen(scene: &Scene, pen: Pen, c: [u16; 3]) -> String {
    match pen {
        Pen::Fill => format!("color = {}", color(scene, c)),
        Pen::Stroke { width, cap } => {
            let cap = match cap {
                LineCap::Butt => "butt",
                LineCap::Round => "round",
                LineCap::Square => "square",
            };
            format!(
                "stroke_color = {}\nstroke_width = {}\ncap = \"{cap}\"",
                color(scene, c),
                fine(width.into())
            )
        }
    }
}

fn to_toml(scene: &Scene) -> String {
    let format = match scene.format {
        Format::Gray8 => "gray8",
        Format::Gray4 => "gray4",
        Format::Rgb565 => "rgb565",
        Format::Rgb888 => "rgb888",
        Format::Binary => "binary",
    };
    let model = match scene.style.model {
        PixelModel::BoxSeed => "box-seed",
        _ => "box",
    };
    let mut t = String::new();
    let _ = writeln!(
        t,
        "# Generated from softedge-refscenes by host-sim/tests/refscenes_toml.rs: do not edit."
    );
    let _ = writeln!(
        t,
        "# `softedge-sim crc` of this file prints the line boards/check.sh expects."
    );
    let _ = writeln!(
        t,
        "[display]\nwidth = {}\nheight = {}\nformat = \"{format}\"",
        scene.width, scene.height
    );
    let _ = writeln!(t, "background = {}", color(scene, scene.background));
    // Circles and arcs are composed over (painter's order), everything
    // else added: a scene holds one kind or the other (a refscenes test).
    let blend = if scene.shapes.iter().any(Shape::is_over) {
        "over"
    } else {
        "add"
    };
    let _ = writeln!(
        t,
        "[render]\nantialias = {}\npixel_model = \"{model}\"\ngamma = 2.2\nband_rows = {}\nblend = \"{blend}\"",
        scene.style.antialias, scene.band_rows
    );
    if scene.zbuffer {
        let _ = writeln!(t, "hsr = \"zbuffer\"");
    }
    for shape in scene.shapes {
        match *shape {
            Shape::Triangle(v, c) => {
                let _ = writeln!(
                    t,
                    "[[triangle]]\npoints = [{}, {}, {}]\ncolors = {}",
                    point(v[0]),
                    point(v[1]),
                    point(v[2]),
                    colors(scene, &c)
                );
            }
            Shape::Depth(v, c, z) => {
                // z / 65535 prints as the shortest f64 that rounds back to
                // z when the scene file scales it by 65535.
                let d: Vec<String> = z.iter().map(|&z| num(f64::from(z) / 65535.0)).collect();
                let _ = writeln!(
                    t,
                    "[[triangle]]\npoints = [{}, {}, {}]\ncolors = {}\ndepths = [{}]",
                    point(v[0]),
                    point(v[1]),
                    point(v[2]),
                    colors(scene, &c),
                    d.join(", ")
                );
            }
            Shape::Line(a, b, c) => {
                let _ = writeln!(
                    t,
                    "[[line]]\nfrom = {}\nto = {}\ncolors = {}",
                    point(a),
                    point(b),
                    colors(scene, &c)
                );
            }
            Shape::Polygon(v, fill) => {
                let pts: Vec<String> = v.iter().map(|&p| point(p)).collect();
                let _ = writeln!(t, "[[polygon]]\npoints = [{}]", pts.join(", "));
                let _ = match fill {
                    Fill::Flat(c) => writeln!(t, "color = {}", color(scene, c)),
                    Fill::PerVertex(cs) => writeln!(t, "colors = {}", colors(scene, cs)),
                };
            }
            Shape::Image(i) => {
                let _ = writeln!(
                    t,
                    "[[image]]\npath = \"{}\"\ncenter = [{}, {}]\nscale = [{}, {}]\nrotate = {}\nopacity = {}",
                    i.file,
                    num(f64::from(i.center.0) / 1024.0),
                    num(f64::from(i.center.1) / 1024.0),
                    num(f64::from(i.scale.0) / 65536.0),
                    num(f64::from(i.scale.1) / 65536.0),
                    num(f64::from(i.rotate) / 65536.0),
                    num(f64::from(i.opacity) / 4096.0),
                );
            }
            Shape::Circle(c, p, col) => {
                let _ = writeln!(
                    t,
                    "[[circle]]\ncentre = {}\nradius = {}\n{}",
                    fine_point(c.centre),
                    fine(c.radius.into()),
                    pen(scene, p, col)
                );
            }
            Shape::Arc(a, p, col) => {
                let _ = writeln!(
                    t,
                    "[[arc]]\ncentre = {}\nradius = {}\nstart = {}\nsweep = {}\n{}",
                    fine_point(a.centre),
                    fine(a.radius.into()),
                    degrees(a.start),
                    degrees(a.sweep),
                    pen(scene, p, col)
                );
            }
            Shape::Object(o) => {
                let c = &o.camera;
                let v3 = |v: softedge::scene3d::Vec3| {
                    let b = v.to_bits();
                    format!(
                        "[{}, {}, {}]",
                        num(f64::from(b[0]) / 65536.0),
                        num(f64::from(b[1]) / 65536.0),
                        num(f64::from(b[2]) / 65536.0)
                    )
                };
                let Projection::Orthographic { px_per_unit } = c.projection else {
                    panic!("{}: only orthographic cameras are exported", scene.name);
                };
                let _ = writeln!(
                    t,
                    "[camera]\nprojection = \"orthographic\"\neye = {}\ntarget = {}\nup = {}\nscale = {}",
                    v3(c.eye),
                    v3(c.target),
                    v3(c.up),
                    num(px_per_unit.to_num::<f64>())
                );
                let [ambient, diffuse] = o.ambient_diffuse;
                let _ = writeln!(
                    t,
                    "[light]\ndirection = {}\nambient = {}\ndiffuse = {}",
                    v3(o.to_light),
                    num(f64::from(ambient) / 4096.0),
                    num(f64::from(diffuse) / 4096.0)
                );
                let Solid::Sphere { radius, segments } = o.shape else {
                    panic!("{}: only spheres are exported", scene.name);
                };
                let deg = |a: softedge::scene3d::Angle| num(f64::from(a.0) * 360.0 / 65536.0);
                let _ = writeln!(
                    t,
                    "[[object]]\nshape = \"sphere\"\nradius = {}\nsegments = {segments}\nposition = [0.0, 0.0, 0.0]\nrotation = [{}, {}, {}]\ncolor = {}",
                    num(radius.to_num::<f64>()),
                    deg(o.rotation[0]),
                    deg(o.rotation[1]),
                    deg(o.rotation[2]),
                    color(scene, o.color)
                );
            }
        }
    }
    t
}

fn dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../refscenes/scenes")
}

#[test]
fn scene_files_of_the_reference_scenes_are_up_to_date() {
    let bless = std::env::var_os("SOFTEDGE_BLESS").is_some();
    for scene in SCENES {
        let path = dir().join(format!("{}.toml", scene.name));
        let text = to_toml(scene);
        if bless {
            std::fs::create_dir_all(dir()).unwrap();
            std::fs::write(&path, &text).unwrap();
        }
        let committed = std::fs::read_to_string(&path).unwrap_or_default();
        assert_eq!(
            committed,
            text,
            "{} is stale: regenerate with SOFTEDGE_BLESS=1 cargo test -p softedge-sim --test refscenes_toml",
            path.display()
        );
    }
}

/// The PNG files of the scenes' images hold their texels (written when
/// blessing).
#[test]
fn image_files_of_the_reference_scenes_hold_their_texels() {
    let bless = std::env::var_os("SOFTEDGE_BLESS").is_some();
    for scene in SCENES {
        for shape in scene.shapes {
            let Shape::Image(i) = shape else { continue };
            let path = dir().join(i.file);
            if bless {
                let file = std::fs::File::create(&path).unwrap();
                let mut enc = png::Encoder::new(file, u32::from(i.width), u32::from(i.height));
                enc.set_color(png::ColorType::Rgba);
                enc.set_depth(png::BitDepth::Eight);
                enc.set_compression(png::Compression::Best);
                let mut w = enc.write_header().unwrap();
                w.write_image_data(i.rgba).unwrap();
            }
            let bytes = std::fs::read(&path).unwrap_or_default();
            let img = softedge_sim::image_item::decode(&bytes).unwrap_or_else(|e| {
                panic!("{}: {e}: regenerate with SOFTEDGE_BLESS=1", path.display())
            });
            assert_eq!((img.width, img.height), (i.width, i.height));
            assert!(&*img.data == i.rgba, "{} is stale", path.display());
        }
    }
}

#[test]
fn softedge_sim_crc_of_each_reference_scene_file_equals_the_firmware_line() {
    let (mut acc, mut cover) = (vec![0i32; ACC_LEN], vec![0i32; COVER_LEN]);
    let (mut depth, mut covered) = (vec![0u16; DEPTH_LEN], vec![0u16; COVERED_LEN]);
    let mut bufs = Buffers {
        acc: &mut acc,
        cover: &mut cover,
        depth: &mut depth,
        covered: &mut covered,
    };
    for scene in SCENES {
        let expected = format!(
            "crc {} {:08x}",
            scene.name,
            render_crc(scene, &mut bufs).unwrap()
        );
        let path = dir().join(format!("{}.toml", scene.name));
        let out = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
            .arg("crc")
            .arg(&path)
            .output()
            .unwrap();
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success(),
            "{}: {}",
            scene.name,
            String::from_utf8_lossy(&out.stderr)
        );
        assert_eq!(stdout.trim(), expected, "{}", scene.name);
    }
}
