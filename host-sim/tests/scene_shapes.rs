//! Scene files' shapes, strokes, meshes, opacity and blend: what they
//! draw (against independent numbers: areas, midpoints, codes) and what
//! they reject, with the field named.

use std::f64::consts::PI;
use std::path::Path;

use softedge_sim::scene_file::{parse, Linear, SceneFile};

fn file(text: &str) -> SceneFile {
    parse(Path::new("t.toml"), text).unwrap_or_else(|d| panic!("{d}"))
}

fn gray(text: &str) -> Vec<u16> {
    match file(text).render_linear().unwrap_or_else(|d| panic!("{d}")) {
        Linear::Gray(img) => img.pixels().map(|p| p[0]).collect(),
        Linear::Rgb(_) => panic!("a gray scene"),
    }
}

fn rgb(text: &str) -> Vec<[u16; 3]> {
    match file(text).render_linear().unwrap_or_else(|d| panic!("{d}")) {
        Linear::Rgb(img) => img.pixels().collect(),
        Linear::Gray(_) => panic!("an RGB scene"),
    }
}

fn head(w: u32, h: u32, format: &str) -> String {
    let bg = if format.starts_with("rgb") {
        "[0, 0, 0]"
    } else {
        "[0]"
    };
    format!("[display]\nwidth = {w}\nheight = {h}\nformat = \"{format}\"\nbackground = {bg}\n")
}

fn err(text: &str) -> String {
    parse(Path::new("t.toml"), text)
        .err()
        .map(|d| d.to_string())
        .unwrap_or_else(|| panic!("accepted:\n{text}"))
}

#[test]
fn every_shape_table_draws_its_area() {
    let h = head(64, 64, "gray8");
    // (table, expected area in px^2), each drawn at 4095 over 0.
    let cases = [
        ("[[circle]]\ncentre = [32.3, 31.7]\nradius = 20\ncolor = [4095]\n", PI * 400.0),
        (
            "[[ellipse]]\ncenter = [32, 32]\nradii = [25, 10]\nrotation = 30\ncolor = [4095]\n",
            PI * 250.0,
        ),
        (
            "[[sector]]\ncentre = [32, 32]\nradius = 20\nstart = -90\nsweep = 90\ncolor = [4095]\n",
            PI * 100.0,
        ),
        (
            "[[rect]]\nposition = [10.5, 12.25]\nsize = [30, 20]\nradius = 5\ncolor = [4095]\n",
            600.0 - (4.0 - PI) * 25.0,
        ),
        (
            "[[rect]]\nposition = [10, 12]\nsize = [30, 20]\nradius = [0, 4, 8, 2]\ncolor = [4095]\n",
            600.0 - (1.0 - PI / 4.0) * (16.0 + 64.0 + 4.0),
        ),
        (
            "[[arc]]\ncentre = [32, 32]\nradius = 20\nstart = 0\nsweep = 180\nstroke_color = [4095]\nstroke_width = 4\n",
            PI / 2.0 * (22.0 * 22.0 - 18.0 * 18.0),
        ),
        (
            "[[polyline]]\npoints = [[5, 5], [55, 5]]\nstroke_color = [4095]\nstroke_width = 3\ncap = \"square\"\n",
            53.0 * 3.0,
        ),
        (
            "[[path]]\nd = \"M 10 10 h 40 v 40 h -40 Z M 20 20 v 20 h 20 v -20 Z\"\ncolor = [4095]\n",
            1600.0 - 400.0,
        ),
        (
            "[[path]]\nd = \"M 10 10 h 40 v 40 h -40 Z M 20 20 h 20 v 20 h -20 Z\"\nfill_rule = \"evenodd\"\ncolor = [4095]\n",
            1600.0 - 400.0,
        ),
    ];
    for (table, area) in cases {
        let img = gray(&format!("{h}{table}"));
        let sum: f64 = img.iter().map(|&v| f64::from(v)).sum::<f64>() / 4095.0;
        // The 12-bit rounding of each edge pixel adds at most 1/8190 each.
        assert!((sum / area - 1.0).abs() < 3e-3, "{table}: {sum} vs {area}");
    }
}

#[test]
fn later_entries_paint_over_earlier_ones() {
    let text = format!(
        "{}[[rect]]\nposition = [2, 2]\nsize = [10, 10]\ncolor = \"#ff0000\"\n\
         [[circle]]\ncentre = [12, 12]\nradius = 6\ncolor = \"#00ff00\"\n",
        head(24, 24, "rgb888")
    );
    let img = rgb(&text);
    let at = |x: usize, y: usize| img[y * 24 + x];
    assert_eq!(at(3, 3), [4095, 0, 0]);
    assert_eq!(at(11, 11), [0, 4095, 0], "green over red");
    assert_eq!(at(14, 14), [0, 4095, 0]);
    // Blend "add" sums them instead (seed 000).
    let add = rgb(&text.replace("[[rect]]", "[render]\nblend = \"add\"\n[[rect]]"));
    assert_eq!(add[11 * 24 + 11], [4095, 4095, 0]);
}

#[test]
fn half_opacity_is_the_linear_midpoint_and_hex_grey_is_code_128() {
    let text = "[display]\nwidth = 8\nheight = 8\nformat = \"gray8\"\nbackground = \"#808080\"\n\
         [render]\ngamma = \"srgb\"\n\
         [[rect]]\nposition = [0, 0]\nsize = [4, 8]\ncolor = [4095]\nopacity = 0.5\n";
    let f = file(text);
    let lin = f.render_linear().unwrap();
    let Linear::Gray(img) = &lin else { panic!() };
    let px: Vec<u16> = img.pixels().map(|p| p[0]).collect();
    // sRGB 128 is linear 884 of 4095; halfway to 4095 is 2489.5.
    assert_eq!(px[7], 884);
    assert!((f64::from(px[0]) - 2489.5).abs() <= 1.0, "{}", px[0]);
    let codes = f.tone(&lin).codes;
    assert_eq!(codes[7], 128, "\"#808080\" back out as 128");
}

/// The square as `[[polygon]]` and as a `[[mesh]]` of 2 and of 64
/// triangles: the same frame, bit for bit, in both modes.
#[test]
fn a_square_mesh_equals_the_square_polygon_in_both_modes() {
    let (x0, y0, x1, y1) = (3.25, 2.5, 29.75, 21.125);
    let polygon = format!(
        "[[polygon]]\npoints = [[{x0}, {y0}], [{x1}, {y0}], [{x1}, {y1}], [{x0}, {y1}]]\ncolor = [3000]\nopacity = 0.75\n"
    );
    let mesh = |n: usize, m: usize| {
        let q = |v: f64| (v * 16.0).round() / 16.0;
        let mut pts = Vec::new();
        for b in 0..=m {
            for a in 0..=n {
                let x = q(x0 + (x1 - x0) * a as f64 / n as f64);
                let y = q(y0 + (y1 - y0) * b as f64 / m as f64);
                pts.push(format!("[{x}, {y}]"));
            }
        }
        let mut tris = Vec::new();
        for b in 0..m {
            for a in 0..n {
                let at = |a: usize, b: usize| b * (n + 1) + a;
                tris.push(format!(
                    "[{}, {}, {}]",
                    at(a, b),
                    at(a + 1, b),
                    at(a + 1, b + 1)
                ));
                tris.push(format!(
                    "[{}, {}, {}]",
                    at(a, b),
                    at(a + 1, b + 1),
                    at(a, b + 1)
                ));
            }
        }
        format!(
            "[[mesh]]\npoints = [{}]\ntriangles = [{}]\ncolor = [3000]\nopacity = 0.75\n",
            pts.join(", "),
            tris.join(", ")
        )
    };
    for blend in ["over", "add"] {
        let h = format!(
            "{}[render]\nblend = \"{blend}\"\nband_rows = 5\n",
            head(32, 24, "gray8")
        );
        let want = gray(&format!("{h}{polygon}"));
        for (n, m) in [(1, 1), (4, 8)] {
            let got = gray(&format!("{h}{}", mesh(n, m)));
            assert!(got == want, "{blend}: a mesh of {} triangles", 2 * n * m);
        }
    }
}

#[test]
fn a_mesh_is_one_shape_where_its_triangles_one_by_one_are_not() {
    // Two triangles sharing a diagonal, at half opacity: as one mesh the
    // diagonal is invisible; as two entries it is a seam (the second half
    // of each diagonal pixel over the first: 1/4 + 3/4 * 1/4 of 4000).
    let h = head(16, 16, "gray8");
    let one = gray(&format!(
        "{h}[[mesh]]\npoints = [[1, 1], [15, 1], [15, 15], [1, 15]]\ntriangles = [[0, 1, 2], [0, 2, 3]]\ncolor = [4000]\nopacity = 0.5\n"
    ));
    let two = gray(&format!(
        "{h}[[triangle]]\npoints = [[1, 1], [15, 1], [15, 15]]\ncolor = [4000]\nopacity = 0.5\n\
         [[triangle]]\npoints = [[1, 1], [15, 15], [1, 15]]\ncolor = [4000]\nopacity = 0.5\n"
    ));
    let inside: Vec<u16> = (2..14).map(|k| one[k * 16 + k]).collect();
    assert!(inside.iter().all(|&v| v == 2000), "{inside:?}");
    let seam: Vec<u16> = (2..14).map(|k| two[k * 16 + k]).collect();
    assert!(seam.iter().all(|&v| v == 1750), "{seam:?}");
}

#[test]
fn strokes_take_joins_caps_dashes_and_alignment() {
    let h = head(64, 40, "gray8");
    let base = "[[polyline]]\npoints = [[5, 30], [30, 8], [58, 30]]\nstroke_color = [4095]\nstroke_width = 4\n";
    let sum = |t: &str| {
        gray(&format!("{h}{t}"))
            .iter()
            .map(|&v| f64::from(v))
            .sum::<f64>()
            / 4095.0
    };
    let miter = sum(&format!("{base}join = \"miter\"\n"));
    let round = sum(&format!("{base}join = \"round\"\n"));
    let bevel = sum(&format!("{base}join = \"bevel\"\n"));
    assert!(miter > round && round > bevel, "{miter} {round} {bevel}");
    let dashed = sum(&format!("{base}dash = [6, 6]\n"));
    assert!((dashed / bevel - 0.5).abs() < 0.1, "{dashed} vs {bevel}");
    let caps = sum(&format!("{base}cap = \"round\"\n")) - sum(base);
    assert!(
        (caps - PI * 4.0).abs() < 0.1,
        "two half discs of radius 2: {caps}"
    );
    let r =
        "[[rect]]\nposition = [10, 10]\nsize = [20, 20]\nstroke_color = [4095]\nstroke_width = 2\n";
    let inside = sum(&format!("{r}stroke_alignment = \"inside\"\n"));
    let outside = sum(&format!("{r}stroke_alignment = \"outside\"\n"));
    assert!((inside - (400.0 - 256.0)).abs() < 0.01, "{inside}");
    assert!((outside - (576.0 - 400.0)).abs() < 0.01, "{outside}");
}

#[test]
fn bad_shapes_are_rejected_with_their_field() {
    let h = head(16, 16, "gray8");
    for (table, field, words) in [
        ("[[circle]]\ncentre = [4, 4]\nradius = nan\ncolor = [1]\n", "circle[0].radius", "finite"),
        ("[[circle]]\ncentre = [4, 4]\nradius = -1\ncolor = [1]\n", "circle[0].radius", "outside"),
        ("[[circle]]\ncentre = [4, 1e9]\nradius = 1\ncolor = [1]\n", "circle[0].centre[1]", "outside"),
        ("[[circle]]\ncentre = [4, 4]\nradius = 2\n", "circle[0]", "draws nothing"),
        ("[[circle]]\ncentre = [4, 4]\nradius = 2\ncolor = [1]\nstroke_width = 2\n", "circle[0].stroke_width", "stroke_color"),
        ("[[polyline]]\npoints = [[1, 1], [5, 5]]\nstroke_color = [1]\njoin = \"sharp\"\n", "polyline[0].join", "miter, round, bevel"),
        ("[[polyline]]\npoints = [[1, 1], [5, 5]]\nstroke_color = [1]\ndash = [2, -1]\n", "polyline[0].dash[1]", "outside"),
        ("[[polyline]]\npoints = [[1, 1]]\nstroke_color = [1]\n", "polyline[0].points", "at least 2"),
        ("[[path]]\nd = \"L 4 4\"\ncolor = [1]\n", "path[0].d", "M or m"),
        ("[[path]]\nd = \"M 0 0 L 9999 0\"\ncolor = [1]\n", "path[0].d", "beyond"),
        ("[[rect]]\nposition = [1, 1]\nsize = [4, 4]\nradius = [1, 2]\ncolor = [1]\n", "rect[0].radius", "four"),
        ("[[arc]]\ncentre = [4, 4]\nradius = 3\nstart = 0\nsweep = 400\nstroke_color = [1]\n", "arc[0].sweep", "outside"),
        ("[[mesh]]\npoints = [[0, 0], [4, 0], [0, 4]]\ntriangles = [[0, 1, 3]]\ncolor = [1]\n", "mesh[0].triangles[0]", "outside"),
        ("[[mesh]]\npoints = [[0, 0], [4, 0], [0, 4]]\ntriangles = [[0, 1]]\ncolor = [1]\n", "mesh[0].triangles[0]", "3 point indices"),
        ("[[mesh]]\npoints = [[0, 0], [4, 0], [0, 4]]\ntriangles = [[0, 1, 2]]\ncolors = [[1], [2]]\n", "mesh[0].colors", "3 vertices"),
        ("[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = [1]\nopacity = 1.5\n", "triangle[0].opacity", "outside"),
        ("[render]\nblend = \"multiply\"\n", "render.blend", "over, add"),
    ] {
        let e = err(&format!("{h}{table}"));
        assert!(e.contains(field) && e.contains(words), "{table}: {e}");
    }
}

#[test]
fn degenerate_shapes_draw_nothing() {
    let h = head(16, 16, "gray8");
    for table in [
        "[[circle]]\ncentre = [4, 4]\nradius = 0\ncolor = [4095]\n",
        "[[ellipse]]\ncentre = [4, 4]\nradii = [0, 5]\ncolor = [4095]\n",
        "[[rect]]\nposition = [4, 4]\nsize = [0, 5]\ncolor = [4095]\nradius = 2\n",
        "[[sector]]\ncentre = [4, 4]\nradius = 3\nstart = 10\nsweep = 0\ncolor = [4095]\n",
        "[[polyline]]\npoints = [[3, 3], [3, 3]]\nstroke_color = [4095]\n",
        "[[path]]\nd = \"M 3 3 Z\"\ncolor = [4095]\nstroke_color = [4095]\n",
        "[[circle]]\ncentre = [4, 4]\nradius = 3\ncolor = [4095]\nopacity = 0\n",
    ] {
        let img = gray(&format!("{h}{table}"));
        assert!(img.iter().all(|&v| v == 0), "{table}");
    }
}

#[test]
fn gradients_interpolate_in_linear_light_and_check_their_stops() {
    let text = "[display]\nwidth = 240\nheight = 4\nformat = \"gray8\"\nbackground = [0]\n\
                [render]\ngamma = \"srgb\"\n\
                [[rect]]\nposition = [0, 0]\nsize = [240, 4]\n\
                gradient = { kind = \"linear\", from = [0, 0], to = [240, 0], stops = [{ offset = 0, color = \"#000000\" }, { offset = 1, color = \"#ffffff\" }] }\n";
    let f = file(text);
    let lin = f.render_linear().unwrap();
    let Linear::Gray(img) = &lin else { panic!() };
    let row: Vec<u16> = img.pixels().take(240).map(|p| p[0]).collect();
    // Pixel 119's centre is at t = 119.5 / 240: half the light, linear.
    let want = 4095.0 * 119.5 / 240.0;
    assert!((f64::from(row[119]) - want).abs() <= 1.0, "{}", row[119]);
    assert!(row.windows(2).all(|w| w[0] <= w[1]), "monotone");
    let codes = f.tone(&lin).codes;
    assert!(
        (186..=188).contains(&codes[119]),
        "sRGB code {}",
        codes[119]
    );
    let radial = "[display]\nwidth = 20\nheight = 20\nformat = \"rgb888\"\nbackground = [0, 0, 0]\n\
                  [[circle]]\ncentre = [10, 10]\nradius = 10\n\
                  gradient = { kind = \"radial\", center = [10, 10], radius = 10, stops = [{ offset = 0, color = \"#ffffff\" }, { offset = 1, color = [0, 0, 4095] }] }\n";
    let img = rgb(radial);
    // Pixel (10, 10)'s centre is 0.71 px from the centre: 7 % of the way to blue.
    assert!(
        (3700..3900).contains(&img[10 * 20 + 10][0]),
        "{:?}",
        img[10 * 20 + 10]
    );
    assert!(
        img[10 * 20 + 1][2] == 4095 && img[10 * 20 + 1][0] < 700,
        "{:?}",
        img[10 * 20 + 1]
    );
    let h = head(16, 16, "gray8");
    let g = "gradient = { kind = \"linear\", from = [0, 0], to = [9, 0], stops = [{ offset = 0.5, color = [1] }, { offset = 0.25, color = [2] }] }\n";
    for (extra, field, words) in [
        (g.to_string(), "rect[0].gradient.stops", "before"),
        (format!("color = [1]\n{g}"), "rect[0].gradient", "not both"),
        (
            g.replace("linear", "conic"),
            "rect[0].gradient.kind",
            "linear, radial",
        ),
        (
            g.replace("from = [0, 0], ", ""),
            "rect[0].gradient",
            "`from`",
        ),
    ] {
        let e = err(&format!(
            "{h}[[rect]]\nposition = [0, 0]\nsize = [8, 8]\n{extra}"
        ));
        assert!(e.contains(field) && e.contains(words), "{extra}: {e}");
    }
}
