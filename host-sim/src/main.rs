//! `softedge-sim`: the host simulator's command line.

use std::path::PathBuf;
use std::process::ExitCode;

use softedge_sim::gallery::{write_gallery, GalleryOptions};
use softedge_sim::png_out::write_png;
use softedge_sim::scene_file::{self, pnm16, SceneFile};

const USAGE: &str = "\
softedge-sim: render softedge scenes on a PC

USAGE:
    softedge-sim <COMMAND> [OPTIONS]

COMMANDS:
    gallery -o DIR [--scale N] [--band-rows N]
                Render the demo gallery into DIR as PNG files: anti-aliasing
                modes side by side, Gouraud shading (gray and RGB), and
                seamless meshes. --scale: magnification (default 4, 1..=16);
                --band-rows: rows per band (default 8).
    render SCENE.toml -o OUT.png [--scale N] [--raw OUT.pgm]
                Render a scene file band by band, run the display's tone
                stage (its format and γ) and write what the display shows
                as PNG, upscaled by --scale (default 1, 1..=64, nearest
                neighbour; at most 2^26 pixels in all). --raw: also write
                the linear 12-bit values before the tone stage (after the
                scene's lightness filter, if on) as 16-bit Netpbm (P5
                gray, P6 RGB).
    crc SCENE.toml
                Print `crc <stem> <crc32>`: the CRC-32 of the display's
                byte stream (its codes, row by row).
    bits --contrast K --delta D --gamma G
                Print the levels a display needs (seed 000): N_I (eq. 9),
                N_U (eq. 10) and m = ln K / ln(1 + D), one per line.
    memory [--width W] [--height H] [--channels 1|3] [--rows R,R,..]
           [--triangles N]
                Print the RAM of the band buffers (accumulator, cover
                scratch, z-buffer depth and coverage) for bands of each R
                rows (default 240x240, 3 channels, rows 16,8,1), and of N
                stored depth triangles (default 576, a torus).
    font [FONT.ttf] --size PX [--chars LIST] [--text STRING]... [--phases N]
         [--name NAME] [--tolerance FINE] [--no-kerning] [--grid]
         [--crate-path P] [-o OUT.rs]
                Rasterize a TrueType / OpenType font (default: the bundled
                font) ahead of time into a Rust `static` RasterFont: each
                glyph's exact-area coverage (1/29 levels, 5-bit code) at N
                horizontal phases (default 1: whole pixels), its advance and
                kerning. --size: pixels (fractions allowed, e.g. 12.5);
                --chars: comma-separated ascii, latin1, U+XXXX, U+XXXX-U+YYYY
                or single characters (default ascii); --text: the characters
                of a string (repeatable); --tolerance: flattening, fine units
                (default 1); --grid: the x-height a whole number of pixels
                (small text on 1-bit displays); --crate-path: how the source
                names softedge (default softedge). Writes the source to OUT.rs (default stdout) and
                a report to stderr: missing characters (named, left out),
                flash bytes by part, what a GlyphCache of the glyphs needs.
    window SCENE.toml [--scale N]
                Show the scene in a window (only with the `window` feature,
                which needs SDL2).
    help        Print this help.

OPTIONS:
    -h, --help     Print this help.
    -V, --version  Print the version.
";

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::Usage(msg)) => {
            eprintln!("softedge-sim: {msg}\n\n{USAGE}");
            ExitCode::from(2)
        }
        Err(Failure::Run(msg)) => {
            eprintln!("softedge-sim: error: {msg}");
            ExitCode::FAILURE
        }
    }
}

enum Failure {
    /// Bad command line: message, then usage, exit 2.
    Usage(String),
    /// The command failed: message, exit 1.
    Run(String),
}

fn run(args: &[String]) -> Result<(), Failure> {
    let Some(cmd) = args.first() else {
        return Err(Failure::Usage("no command given".into()));
    };
    match cmd.as_str() {
        "-h" | "--help" | "help" => {
            print!("{USAGE}");
            Ok(())
        }
        "-V" | "--version" => {
            println!("softedge-sim {}", env!("CARGO_PKG_VERSION"));
            Ok(())
        }
        "gallery" => gallery(&args[1..]),
        "render" => render(&args[1..]),
        "crc" => crc(&args[1..]),
        "bits" => bits(&args[1..]),
        "memory" => memory(&args[1..]),
        "font" => font(&args[1..]),
        "window" => window(&args[1..]),
        other => Err(Failure::Usage(format!("unknown command `{other}`"))),
    }
}

fn memory(args: &[String]) -> Result<(), Failure> {
    let (mut w, mut h, mut ch, mut tris) = (240u16, 240u16, 3usize, 576usize);
    let mut rows: Vec<u16> = vec![16, 8, 1];
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| Failure::Usage(format!("{name} needs a value")))
        };
        match a.as_str() {
            "--width" => w = number(a, &value(a)?, 1, 2048)? as u16,
            "--height" => h = number(a, &value(a)?, 1, 2048)? as u16,
            "--channels" => {
                ch = match number(a, &value(a)?, 1, 3)? {
                    1 => 1,
                    3 => 3,
                    _ => return Err(Failure::Usage("--channels is 1 or 3".into())),
                }
            }
            "--triangles" => tris = number(a, &value(a)?, 0, 1 << 20)? as usize,
            "--rows" => {
                let v = value(a)?;
                rows = v
                    .split(',')
                    .map(|r| number(a, r, 1, 2048).map(|n| n as u16))
                    .collect::<Result<_, _>>()?;
            }
            other => return Err(Failure::Usage(format!("unknown memory option `{other}`"))),
        }
    }
    print!("{}", softedge_sim::memory::report(w, h, ch, &rows, tris));
    Ok(())
}

fn font(args: &[String]) -> Result<(), Failure> {
    use softedge_sim::font_gen::{generate, parse_chars, FontSpec};
    let mut path: Option<String> = None;
    let mut size: Option<u32> = None;
    let mut chars: Vec<char> = Vec::new();
    let mut named = false;
    let mut spec = FontSpec {
        name: String::new(),
        size_64ths: 0,
        chars: Vec::new(),
        phases: 1,
        tolerance: softedge::path::Tolerance::MIN,
        kerning: true,
        source_name: String::new(),
        crate_path: "softedge".into(),
        snap_x_height: false,
    };
    let mut out: Option<PathBuf> = None;
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| Failure::Usage(format!("{name} needs a value")))
        };
        match a.as_str() {
            "--size" => {
                let v = value(a)?;
                let px = v
                    .parse::<f64>()
                    .ok()
                    .filter(|p| (1.0 / 64.0..=512.0).contains(p))
                    .ok_or_else(|| {
                        Failure::Usage(format!("--size takes pixels in 1/64..=512, not `{v}`"))
                    })?;
                size = Some((px * 64.0).round() as u32);
            }
            "--chars" => {
                chars.extend(parse_chars(&value(a)?).map_err(Failure::Usage)?);
                named = true;
            }
            "--text" => {
                chars.extend(value(a)?.chars().filter(|&c| c != '\n' && c != '\r'));
                named = true;
            }
            "--phases" => spec.phases = number(a, &value(a)?, 1, 16)? as u8,
            "--tolerance" => {
                spec.tolerance =
                    softedge::path::Tolerance::new(number(a, &value(a)?, 1, 256)? as u16)
            }
            "--name" => spec.name = value(a)?,
            "--crate-path" => spec.crate_path = value(a)?,
            "--no-kerning" => spec.kerning = false,
            "--grid" => spec.snap_x_height = true,
            "-o" | "--out" => out = Some(PathBuf::from(value(a)?)),
            "-h" | "--help" => {
                print!("{USAGE}");
                return Ok(());
            }
            other if other.starts_with('-') => {
                return Err(Failure::Usage(format!("unknown font option `{other}`")))
            }
            other => {
                if path.replace(other.to_string()).is_some() {
                    return Err(Failure::Usage("font takes one font file".into()));
                }
            }
        }
    }
    spec.size_64ths = size.ok_or_else(|| Failure::Usage("font needs --size PX".into()))?;
    if !named {
        chars = parse_chars("ascii").map_err(Failure::Usage)?;
    }
    spec.chars = chars;
    let data = match &path {
        Some(p) => std::fs::read(p).map_err(|e| Failure::Run(format!("cannot read {p}: {e}")))?,
        None => softedge::text::bundled::SOFTEDGE_SANS.to_vec(),
    };
    spec.source_name = match &path {
        Some(p) => std::path::Path::new(p)
            .file_name()
            .map_or(p.clone(), |f| f.to_string_lossy().into_owned()),
        None => "SoftedgeSans-Subset.ttf (the bundled font)".into(),
    };
    if spec.name.is_empty() {
        spec.name = format!("FONT_{}", spec.size_64ths / 64);
    }
    let (source, report) = generate(&data, &spec).map_err(Failure::Run)?;
    match &out {
        Some(o) => std::fs::write(o, &source)
            .map_err(|e| Failure::Run(format!("cannot write {}: {e}", o.display())))?,
        None => print!("{source}"),
    }
    eprint!("{}", report.text(&spec));
    Ok(())
}

fn gallery(args: &[String]) -> Result<(), Failure> {
    let mut dir: Option<PathBuf> = None;
    let mut opts = GalleryOptions::default();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let mut value = |name: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| Failure::Usage(format!("{name} needs a value")))
        };
        match a.as_str() {
            "-o" | "--out" => dir = Some(PathBuf::from(value(a)?)),
            "--scale" => opts.scale = number(a, &value(a)?, 1, 16)? as u32,
            "--band-rows" => opts.band_rows = number(a, &value(a)?, 1, 2048)? as u16,
            "-h" | "--help" => {
                print!("{USAGE}");
                return Ok(());
            }
            other => return Err(Failure::Usage(format!("unknown gallery option `{other}`"))),
        }
    }
    let dir = dir.ok_or_else(|| Failure::Usage("gallery needs -o DIR".into()))?;
    let written = write_gallery(&dir, &opts, &mut |line| println!("{line}"))
        .map_err(|e| Failure::Run(e.to_string()))?;
    println!("{} files in {}", written.len(), dir.display());
    Ok(())
}

/// Loads a scene file, printing its warnings; errors name file, line and
/// field.
fn load_scene(path: &str) -> Result<SceneFile, Failure> {
    let file =
        scene_file::load(std::path::Path::new(path)).map_err(|d| Failure::Run(d.to_string()))?;
    for w in &file.warnings {
        eprintln!("softedge-sim: warning: {w}");
    }
    Ok(file)
}

/// A scene command's options, each `(name, value)`.
type Options<'a> = Vec<(&'a str, String)>;

/// The one positional argument (the scene file) and the options of a
/// scene command, each option with a value.
fn scene_args<'a>(
    cmd: &str,
    args: &'a [String],
    options: &[&str],
) -> Result<(String, Options<'a>), Failure> {
    let mut scene = None;
    let mut opts = Vec::new();
    let mut it = args.iter();
    while let Some(a) = it.next() {
        if options.contains(&a.as_str()) {
            let v = it
                .next()
                .cloned()
                .ok_or_else(|| Failure::Usage(format!("{a} needs a value")))?;
            opts.push((a.as_str(), v));
        } else if a.starts_with('-') {
            return Err(Failure::Usage(format!("unknown {cmd} option `{a}`")));
        } else if scene.is_none() {
            scene = Some(a.clone());
        } else {
            return Err(Failure::Usage(format!(
                "{cmd} takes one scene file, not also `{a}`"
            )));
        }
    }
    let scene = scene.ok_or_else(|| Failure::Usage(format!("{cmd} needs a SCENE.toml")))?;
    Ok((scene, opts))
}

fn render(args: &[String]) -> Result<(), Failure> {
    if args.iter().any(|a| a == "-h" || a == "--help") {
        print!("{USAGE}");
        return Ok(());
    }
    let (scene, opts) = scene_args("render", args, &["-o", "--out", "--scale", "--raw"])?;
    let mut out = None;
    let mut raw = None;
    let mut scale = 1;
    for (name, v) in opts {
        match name {
            "-o" | "--out" => out = Some(PathBuf::from(v)),
            "--raw" => raw = Some(PathBuf::from(v)),
            _ => scale = number(name, &v, 1, 64)? as u32,
        }
    }
    let out = out.ok_or_else(|| Failure::Usage("render needs -o OUT.png".into()))?;
    let file = load_scene(&scene)?;
    check_scaled_size(&file, scale)?;
    let lin = file
        .render_linear()
        .map_err(|d| Failure::Run(d.to_string()))?;
    if let Some(raw) = &raw {
        std::fs::write(raw, pnm16(&lin))
            .map_err(|e| Failure::Run(format!("cannot write {}: {e}", raw.display())))?;
        println!("{}", raw.display());
    }
    let img = file.tone(&lin).to_image8().upscale(scale);
    write_png(&out, &img)
        .map_err(|e| Failure::Run(format!("cannot write {}: {e}", out.display())))?;
    println!("{}", out.display());
    Ok(())
}

fn crc(args: &[String]) -> Result<(), Failure> {
    let (scene, _) = scene_args("crc", args, &[])?;
    let file = load_scene(&scene)?;
    let lin = file
        .render_linear()
        .map_err(|d| Failure::Run(d.to_string()))?;
    println!("crc {} {:08x}", file.stem(), file.tone(&lin).crc32());
    Ok(())
}

fn bits(args: &[String]) -> Result<(), Failure> {
    let (mut k, mut d, mut g) = (None, None, None);
    let mut it = args.iter();
    while let Some(a) = it.next() {
        let slot = match a.as_str() {
            "--contrast" => &mut k,
            "--delta" => &mut d,
            "--gamma" => &mut g,
            other => return Err(Failure::Usage(format!("unknown bits option `{other}`"))),
        };
        let v = it
            .next()
            .ok_or_else(|| Failure::Usage(format!("{a} needs a value")))?;
        let x = v
            .parse::<f64>()
            .map_err(|_| Failure::Usage(format!("{a} takes a number, not `{v}`")))?;
        *slot = Some(x);
    }
    let (Some(k), Some(d), Some(g)) = (k, d, g) else {
        return Err(Failure::Usage(
            "bits needs --contrast, --delta and --gamma".into(),
        ));
    };
    let levels = softedge::tone::levels(k, d, g).map_err(|_| {
        Failure::Run(format!(
            "need contrast > 1, delta > 0 and gamma > 1 (got K = {k}, delta = {d}, gamma = {g})"
        ))
    })?;
    println!("N_I {:.1}", levels.n_i);
    println!("N_U {:.1}", levels.n_u);
    println!("m {:.1}", levels.m);
    Ok(())
}

#[cfg(feature = "window")]
fn window(args: &[String]) -> Result<(), Failure> {
    let (scene, opts) = scene_args("window", args, &["--scale"])?;
    let mut scale = 4;
    for (name, v) in opts {
        scale = number(name, &v, 1, 64)? as u32;
    }
    let file = load_scene(&scene)?;
    check_scaled_size(&file, scale)?;
    scene_file::window::show(&file, scale).map_err(Failure::Run)
}

#[cfg(not(feature = "window"))]
fn window(_args: &[String]) -> Result<(), Failure> {
    Err(Failure::Run(
        "this softedge-sim was built without the `window` feature; rebuild with \
         `cargo run -p softedge-sim --features window -- window SCENE.toml` (needs SDL2)"
            .into(),
    ))
}

/// Most pixels `render` and `window` show after `--scale`: 2^26 (64 Mi
/// pixels, 192 MiB of 8-bit RGB), so a large frame cannot be magnified
/// into tens of gigabytes. A 2048x2048 frame takes `--scale 4`.
const MAX_SCALED_PIXELS: u64 = 1 << 26;

fn check_scaled_size(file: &SceneFile, scale: u32) -> Result<(), Failure> {
    let (w, h) = file.size();
    let (sw, sh) = (
        u64::from(w) * u64::from(scale),
        u64::from(h) * u64::from(scale),
    );
    if sw * sh <= MAX_SCALED_PIXELS {
        return Ok(());
    }
    // The largest scale that fits (at least 1: the frame itself is at most
    // 2048 x 2048 = 2^22 pixels).
    let fit = ((MAX_SCALED_PIXELS / (u64::from(w) * u64::from(h))) as f64)
        .sqrt()
        .floor()
        .max(1.0) as u64;
    Err(Failure::Usage(format!(
        "--scale {scale} would make a {sw}x{sh} image of the {w}x{h} scene \
         ({} pixels); at most {MAX_SCALED_PIXELS} pixels ({} MiB of RGB) are made: \
         use --scale {fit} or less",
        sw * sh,
        (MAX_SCALED_PIXELS * 3) >> 20
    )))
}

fn number(name: &str, text: &str, lo: u64, hi: u64) -> Result<u64, Failure> {
    match text.parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(Failure::Usage(format!(
            "{name} takes a whole number in {lo}..={hi}, not `{text}`"
        ))),
    }
}
