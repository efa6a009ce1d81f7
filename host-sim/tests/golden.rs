//! Golden images: every gallery image and every example scene, compared
//! pixel for pixel with the PNGs kept in `tests/golden/`.
//!
//! The set:
//! - every gallery image as `softedge-sim gallery --scale 2` writes them
//!   (most panels magnified 2x: small files, labels still legible); any
//!   change of coverage, shading, tone, dithering, the 3D path or the
//!   post-filter, or of a figure printed in a label, shows;
//! - every scene in `examples/scenes/` as `softedge-sim render` shows it
//!   (`scene-<stem>.png`): the scene-file path and the tone stage of each
//!   display format (gray4, gray8, rgb565, binary dithering), which the
//!   gallery does not go through.
//!
//! Pixels are compared after decoding, so a different PNG encoder gives no
//! false alarm. On a mismatch the new image is written beside the golden
//! one as `NAME.actual.png` (ignored by git) and the test fails naming the
//! command that accepts the new images:
//!
//! ```text
//! SOFTEDGE_BLESS=1 cargo test -p softedge-sim --test golden
//! ```
//!
//! That rewrites every golden PNG (compact encoding) and removes goldens
//! and `.actual.png` files that no longer correspond to an image.

use std::path::{Path, PathBuf};

use softedge_sim::gallery::{write_gallery, GalleryOptions};
use softedge_sim::image::Image8;
use softedge_sim::png_out::{read_png, write_png_compact};
use softedge_sim::scene_file;

/// The command that regenerates the goldens on purpose.
const BLESS_COMMAND: &str = "SOFTEDGE_BLESS=1 cargo test -p softedge-sim --test golden";

fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn golden_dir() -> PathBuf {
    repo().join("tests/golden")
}

fn blessing() -> bool {
    std::env::var_os("SOFTEDGE_BLESS").is_some_and(|v| !v.is_empty() && v != "0")
}

/// A fresh temporary directory.
fn temp_dir(tag: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("softedge-golden-{tag}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// The gallery at scale 2, each image under its file name.
fn gallery_images() -> Vec<(String, Image8)> {
    let dir = temp_dir("gallery");
    let opts = GalleryOptions {
        scale: 2,
        ..GalleryOptions::default()
    };
    let written = write_gallery(&dir, &opts, &mut |_| {}).expect("the gallery renders");
    let images = written
        .iter()
        .map(|w| {
            let name = w.path.file_name().unwrap().to_string_lossy().into_owned();
            (
                name,
                read_png(&w.path).expect("the gallery's PNG reads back"),
            )
        })
        .collect();
    std::fs::remove_dir_all(&dir).unwrap();
    images
}

/// Every example scene as the display shows it, 1:1.
fn scene_images() -> Vec<(String, Image8)> {
    let mut paths: Vec<PathBuf> = std::fs::read_dir(repo().join("examples/scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    assert!(!paths.is_empty(), "no example scenes");
    paths
        .iter()
        .map(|p| {
            let file = scene_file::load(p).unwrap_or_else(|d| panic!("{d}"));
            let lin = file.render_linear().unwrap_or_else(|d| panic!("{d}"));
            (
                format!("scene-{}.png", file.stem()),
                file.tone(&lin).to_image8(),
            )
        })
        .collect()
}

/// Why an image does not match its golden.
#[derive(Debug, PartialEq, Eq)]
enum Problem {
    /// No golden file for a rendered image.
    Missing(String),
    /// A golden file that no rendered image has.
    Stale(String),
    /// Sizes differ.
    Size {
        name: String,
        golden: (u32, u32),
        actual: (u32, u32),
    },
    /// Pixels differ: how many, and the first (x, y).
    Pixels {
        name: String,
        count: usize,
        first: (u32, u32),
    },
    /// The golden file cannot be read.
    Unreadable { name: String, error: String },
}

/// `name` without `.png`.
fn stem(name: &str) -> &str {
    name.strip_suffix(".png").unwrap_or(name)
}

/// Pixels of `a` and `b` (same size) that differ, as RGB, and the first.
fn differing(a: &Image8, b: &Image8) -> (usize, (u32, u32)) {
    let (a, b) = (a.to_rgb(), b.to_rgb());
    let mut first = None;
    let mut count = 0;
    for (k, (p, q)) in a.data().chunks(3).zip(b.data().chunks(3)).enumerate() {
        if p != q {
            count += 1;
            let w = a.width() as usize;
            first.get_or_insert(((k % w) as u32, (k / w) as u32));
        }
    }
    (count, first.unwrap_or((0, 0)))
}

/// Compares `images` with the goldens in `dir`, or (`bless`) rewrites
/// them. A mismatching image is written as `NAME.actual.png` in `dir`; a
/// matching one's old `.actual.png` is removed.
fn check(dir: &Path, images: &[(String, Image8)], bless: bool) -> Vec<Problem> {
    std::fs::create_dir_all(dir).unwrap();
    let mut problems = Vec::new();
    for (name, img) in images {
        let golden = dir.join(name);
        let actual = dir.join(format!("{}.actual.png", stem(name)));
        if bless {
            write_png_compact(&golden, img).unwrap();
            let _ = std::fs::remove_file(&actual);
            continue;
        }
        let problem = if !golden.exists() {
            Some(Problem::Missing(name.clone()))
        } else {
            match read_png(&golden) {
                Err(e) => Some(Problem::Unreadable {
                    name: name.clone(),
                    error: e.to_string(),
                }),
                Ok(g) if (g.width(), g.height()) != (img.width(), img.height()) => {
                    Some(Problem::Size {
                        name: name.clone(),
                        golden: (g.width(), g.height()),
                        actual: (img.width(), img.height()),
                    })
                }
                Ok(g) => match differing(&g, img) {
                    (0, _) => None,
                    (count, first) => Some(Problem::Pixels {
                        name: name.clone(),
                        count,
                        first,
                    }),
                },
            }
        };
        match problem {
            Some(p) => {
                write_png_compact(&actual, img).unwrap();
                problems.push(p);
            }
            None => {
                let _ = std::fs::remove_file(&actual);
            }
        }
    }
    // Goldens (and leftovers) that no image corresponds to any more.
    let mut entries: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    entries.sort();
    for n in entries {
        let base = n.strip_suffix(".actual.png").map(|s| format!("{s}.png"));
        let known = |x: &str| images.iter().any(|(name, _)| name == x);
        match base {
            Some(b) if !known(&b) => {
                let _ = std::fs::remove_file(dir.join(&n));
            }
            None if !known(&n) => {
                if bless {
                    std::fs::remove_file(dir.join(&n)).unwrap();
                } else {
                    problems.push(Problem::Stale(n));
                }
            }
            _ => {}
        }
    }
    problems
}

fn report(dir: &Path, problems: &[Problem]) -> String {
    let mut msg = format!(
        "{} golden image problem(s) in {}:\n",
        problems.len(),
        dir.display()
    );
    for p in problems {
        let line = match p {
            Problem::Missing(n) => format!("  {n}: no golden image (new image?)"),
            Problem::Stale(n) => format!("  {n}: golden image of nothing rendered any more"),
            Problem::Size {
                name,
                golden,
                actual,
            } => format!(
                "  {name}: size {}x{} (golden {}x{}); see {}.actual.png",
                actual.0,
                actual.1,
                golden.0,
                golden.1,
                stem(name)
            ),
            Problem::Pixels { name, count, first } => format!(
                "  {name}: {count} pixel(s) differ, first at ({}, {}); see {}.actual.png",
                first.0,
                first.1,
                stem(name)
            ),
            Problem::Unreadable { name, error } => format!("  {name}: {error}"),
        };
        msg.push_str(&line);
        msg.push('\n');
    }
    msg.push_str(&format!(
        "If the change is intended, look at the .actual.png files, then regenerate the goldens with\n  {BLESS_COMMAND}\n"
    ));
    msg
}

#[test]
fn gallery_and_example_scenes_match_the_golden_images() {
    let mut images = gallery_images();
    images.extend(scene_images());
    let mut names: Vec<&str> = images.iter().map(|(n, _)| n.as_str()).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), images.len(), "image names must be unique");
    let dir = golden_dir();
    let bless = blessing();
    let problems = check(&dir, &images, bless);
    if bless {
        println!("wrote {} golden images to {}", images.len(), dir.display());
    }
    assert!(problems.is_empty(), "{}", report(&dir, &problems));
    // The goldens are committed: keep the set well under 1 MiB (640 KiB
    // since the gallery's images 18 and 13's raster text: 19 images and
    // the example scenes, about 530 KB).
    const BUDGET: u64 = 640 * 1024;
    let total: u64 = images
        .iter()
        .map(|(n, _)| std::fs::metadata(dir.join(n)).unwrap().len())
        .sum();
    assert!(total < BUDGET, "{total} bytes of golden images");
}

#[test]
fn a_changed_image_fails_with_its_actual_png_and_the_bless_command() {
    use softedge_sim::image::Channels;
    let dir = temp_dir("check");
    let a = Image8::new(4, 3, Channels::Rgb, &[10, 20, 30]);
    let gray = Image8::new(2, 2, Channels::Gray, &[7]);
    let set = vec![("a.png".to_string(), a.clone()), ("g.png".into(), gray)];
    assert!(check(&dir, &set, true).is_empty());
    assert!(check(&dir, &set, false).is_empty());

    // One pixel changed, one image resized, one image new.
    let mut changed = a.clone();
    changed.fill_rect(2, 1, 1, 1, &[10, 20, 31]);
    let set2 = vec![
        ("a.png".to_string(), changed),
        ("g.png".into(), Image8::new(3, 2, Channels::Gray, &[7])),
        ("new.png".into(), a.clone()),
    ];
    let problems = check(&dir, &set2, false);
    assert_eq!(
        problems,
        [
            Problem::Pixels {
                name: "a.png".into(),
                count: 1,
                first: (2, 1)
            },
            Problem::Size {
                name: "g.png".into(),
                golden: (2, 2),
                actual: (3, 2)
            },
            Problem::Missing("new.png".into()),
        ]
    );
    assert!(dir.join("a.actual.png").exists());
    assert!(dir.join("g.actual.png").exists());
    let msg = report(&dir, &problems);
    assert!(msg.contains(BLESS_COMMAND), "{msg}");
    assert!(
        msg.contains("a.png: 1 pixel(s) differ, first at (2, 1)"),
        "{msg}"
    );

    // Back to the original: passes, and the .actual.png files are gone
    // (new.actual.png belongs to no image of this set any more).
    assert!(check(&dir, &set, false).is_empty());
    assert!(!dir.join("a.actual.png").exists());
    assert!(!dir.join("new.actual.png").exists());

    // A golden nothing renders is stale; blessing removes it.
    let only_a = vec![("a.png".to_string(), a)];
    assert_eq!(
        check(&dir, &only_a, false),
        [Problem::Stale("g.png".into())]
    );
    assert!(check(&dir, &only_a, true).is_empty());
    assert!(!dir.join("g.png").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}
