//! Issue #18's findings at the documented limits, through scene files:
//! lines on the coordinate limit under every hidden-surface method.

use std::path::Path;

use softedge_sim::image::LinImage;
use softedge_sim::scene::{render, Hsr, Scene};
use softedge_sim::scene_file::{parse, Frame};

fn gray(text: &str) -> Scene<1> {
    match parse(Path::new("limits.toml"), text).unwrap().frame {
        Frame::Gray(s) => s,
        Frame::Rgb(_) => panic!("a gray scene"),
    }
}

const METHODS: [Hsr; 4] = [Hsr::None, Hsr::ZBuffer, Hsr::Warnock, Hsr::WeilerAtherton];

/// Lines along and onto x = 2048 px and y = 2048 px, in a frame whose last
/// column is 2047 (the widest frame), with depths.
fn limit_lines_scene() -> Scene<1> {
    gray(
        "[display]\nwidth = 2048\nheight = 24\nformat = \"gray8\"\n\
         [[line]]\nfrom = [2048, 0]\nto = [2048, 10]\ncolor = [4000]\ndepths = [0.5, 0.5]\n\
         [[line]]\nfrom = [2000.25, 12]\nto = [2048, 20.5]\ncolors = [[1000], [3000]]\ndepths = [0.25, 0.75]\n\
         [[line]]\nfrom = [1900, 2048]\nto = [2048, -2048]\ncolor = [2000]\ndepths = [0.1, 0.9]\n",
    )
}

fn max_diff(a: &LinImage<1>, b: &LinImage<1>) -> u16 {
    a.pixels()
        .zip(b.pixels())
        .map(|([p], [q])| p.abs_diff(q))
        .max()
        .unwrap_or(0)
}

#[test]
fn lines_on_the_limit_render_with_every_hidden_surface_method() {
    let s = limit_lines_scene();
    let plain = render(&s).unwrap();
    // The line along x = 2048 px covers half of column 2047.
    assert_eq!(plain.get(2047, 5), &[2000]);
    let weiler = render(&Scene {
        hsr: Hsr::WeilerAtherton,
        ..s.clone()
    })
    .unwrap();
    for hsr in METHODS {
        let img = render(&Scene { hsr, ..s.clone() }).unwrap_or_else(|e| panic!("{hsr:?}: {e:?}"));
        assert_eq!(img.get(2047, 5), &[2000], "{hsr:?}");
        // The lines do not overlap, so every method shows the depth
        // triangles' accumulation; `Line::draw` (hsr = none) also rescales
        // an oblique line's intensity to its ideal area (a few per cent).
        let d = max_diff(&img, &weiler);
        println!("{hsr:?}: max {d} levels from Weiler-Atherton");
        if hsr != Hsr::None {
            assert!(d <= 17, "{hsr:?}: {d} levels");
        }
    }
    // Section mode takes them too.
    let section = Scene {
        hsr: Hsr::ZBuffer,
        section: Some(32768),
        ..s.clone()
    };
    render(&section).unwrap();
}
