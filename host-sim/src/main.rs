//! `softedge-sim`: the host simulator's command line.

use std::path::PathBuf;
use std::process::ExitCode;

use softedge_sim::gallery::{write_gallery, GalleryOptions};

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
        other => Err(Failure::Usage(format!("unknown command `{other}`"))),
    }
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

fn number(name: &str, text: &str, lo: u64, hi: u64) -> Result<u64, Failure> {
    match text.parse::<u64>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(Failure::Usage(format!(
            "{name} takes a whole number in {lo}..={hi}, not `{text}`"
        ))),
    }
}
