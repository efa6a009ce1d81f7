//! The hidden-surface methods against each other on the example scene
//! (`examples/scenes/hidden_surfaces.toml`: interpenetrating objects and a
//! card with per-corner depths), and each against band heights.
//!
//! Warnock (`softedge::hsr::draw_warnock`) and Weiler–Atherton
//! (`softedge::hsr::VisibleSet`) are independent implementations of exact
//! visibility by area: Warnock within 1/256 px per pixel where it samples,
//! Weiler–Atherton within its cut vertices' rounding (1/1024 px with the
//! box model; up to 1/16 px of a pixel's area next to a vertex rounded to
//! 1/16 px, the bound used here). Their frames must agree within the sum
//! of those bounds at full contrast, `4095 * (1/16 + 1/256)` = 272 levels,
//! plus one rounding each.

use std::path::Path;

use softedge_sim::image::LinImage;
use softedge_sim::scene::{render, Hsr, Scene};
use softedge_sim::scene_file::{parse, Frame};

fn example() -> Scene<3> {
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/scenes/hidden_surfaces.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    match parse(&path, &text).unwrap().frame {
        Frame::Rgb(s) => s,
        Frame::Gray(_) => panic!("an RGB scene"),
    }
}

fn with(scene: &Scene<3>, hsr: Hsr) -> Scene<3> {
    Scene {
        hsr,
        ..scene.clone()
    }
}

/// Max and mean absolute difference over all channels, in levels.
fn diff(a: &LinImage<3>, b: &LinImage<3>) -> (u16, f64) {
    let (mut max, mut sum, mut n) = (0u16, 0u64, 0u64);
    for (p, q) in a.pixels().zip(b.pixels()) {
        for ch in 0..3 {
            let d = p[ch].abs_diff(q[ch]);
            max = max.max(d);
            sum += u64::from(d);
            n += 1;
        }
    }
    (max, sum as f64 / n as f64)
}

#[test]
fn warnock_and_weiler_atherton_agree() {
    let s = example();
    let warnock = render(&with(&s, Hsr::Warnock)).unwrap();
    let weiler = render(&with(&s, Hsr::WeilerAtherton)).unwrap();
    let (max, mean) = diff(&warnock, &weiler);
    println!("Warnock vs Weiler-Atherton: max {max} levels, mean {mean:.3}");
    assert!(max <= 274, "max {max}");
    // Measured: 4 levels since Weiler–Atherton's cut vertices are on the
    // 1/1024-px grid (issue #18; 272 with 1/16 px): both within
    // `4095 / 256 + 1` of the exact visible area.
    assert!(max <= 2 * 17, "max {max}");
    // Almost every pixel is exact in both: the mean stays far below a level.
    assert!(mean < 1.0, "mean {mean}");
    // The anti-aliased z-buffer differs along intersection curves, which it
    // resolves at pixel centres (measured mean 6.5 levels); the bound is a
    // guard against regressions (hidden surfaces showing through would be
    // off by thousands of levels over whole areas), not a derived one.
    let z = render(&with(&s, Hsr::ZBuffer)).unwrap();
    let (zmax, zmean) = diff(&z, &weiler);
    println!("z-buffer vs Weiler-Atherton: max {zmax} levels, mean {zmean:.3}");
    assert!(zmean < 8.0, "mean {zmean}");
}

#[test]
fn every_method_gives_the_same_frame_for_every_band_height() {
    let s = example();
    for hsr in [Hsr::ZBuffer, Hsr::Warnock, Hsr::WeilerAtherton] {
        let full = render(&with(&s, hsr).with_band_rows(s.height)).unwrap();
        for rows in [1, 7, 16] {
            assert_eq!(
                render(&with(&s, hsr).with_band_rows(rows)).unwrap(),
                full,
                "{hsr:?}, {rows} rows"
            );
        }
    }
}

/// Lines take part in hidden-surface removal by their `depths`: a line in
/// front of a card shows over it, the same line behind it is hidden; a
/// line without depths lies at depth 0, behind everything.
#[test]
fn lines_are_hidden_by_their_depths() {
    let scene = |line_depths: &str| {
        format!(
            "[display]\nwidth = 24\nheight = 16\nformat = \"gray8\"\nbackground = [0]\n\
             [render]\nhsr = \"zbuffer\"\n\
             [[polygon]]\npoints = [[2, 2], [22, 2], [22, 14], [2, 14]]\ncolor = [1000]\n\
             depths = [0.5, 0.5, 0.5, 0.5]\n\
             [[line]]\nfrom = [0, 8]\nto = [24, 8]\ncolor = [4000]\n{line_depths}"
        )
    };
    let value = |text: &str| {
        let file = parse(Path::new("line.toml"), text).unwrap();
        let Frame::Gray(s) = &file.frame else {
            panic!("gray")
        };
        let img = render(s).unwrap();
        // Pixel (12, 7): the line covers its lower half (y 7.5..8.5).
        img.get(12, 7)[0]
    };
    let front = value(&scene("depths = [0.9, 0.9]\n"));
    let behind = value(&scene("depths = [0.1, 0.1]\n"));
    let none = value(&scene(""));
    assert_eq!(front, 2500, "half line (4000), half card (1000)");
    assert_eq!(behind, 1000);
    assert_eq!(none, 1000);
}
