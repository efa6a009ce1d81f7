//! Malformed scene files: one test per kind of error. Each is rejected with
//! a diagnostic naming the file, the line and the field, and the CLI exits
//! with status 1 and that message, never a panic.

use std::path::{Path, PathBuf};
use std::process::Command;

use softedge_sim::scene_file::{parse, Diagnostic, Severity};

const HEAD: &str = "[display]\nwidth = 16\nheight = 8\nformat = \"gray8\"\n";
const HEAD_RGB: &str = "[display]\nwidth = 16\nheight = 8\nformat = \"rgb888\"\n";
const CAMERA: &str = "[camera]\nprojection = \"orthographic\"\neye = [0, 0, 10]\nscale = 2\n";

/// The diagnostic for `text`, which must be rejected.
fn error_of(text: &str) -> Diagnostic {
    match parse(Path::new("bad.toml"), text) {
        Ok(file) => match file.render_linear() {
            Ok(_) => panic!("accepted:\n{text}"),
            Err(d) => d,
        },
        Err(d) => d,
    }
}

/// Checks the diagnostic's line, field and a word of its message, then the
/// CLI on the same text.
fn expect(text: &str, line: usize, field: &str, word: &str) {
    let d = error_of(text);
    assert_eq!(d.severity, Severity::Error);
    assert_eq!(d.path, PathBuf::from("bad.toml"));
    assert_eq!((d.line, d.field.as_str()), (line, field), "{d}");
    assert!(d.message.contains(word), "{d}");
    assert!(
        d.to_string().starts_with(&format!("bad.toml:{line}:")),
        "{d}"
    );

    let dir = std::env::temp_dir().join(format!(
        "softedge-scene-errors-{}-{}",
        std::process::id(),
        field.replace(['[', ']', '.'], "_")
    ));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("bad.toml");
    std::fs::write(&scene, text).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(["render", scene.to_str().unwrap(), "-o"])
        .arg(dir.join("out.png"))
        .output()
        .unwrap();
    let crc = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(["crc", scene.to_str().unwrap()])
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    for out in [out, crc] {
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{err}");
        assert!(err.contains(&format!("bad.toml:{line}:")), "{err}");
        assert!(err.contains(field), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
}

#[test]
fn unknown_key_is_named() {
    expect(
        &format!("{HEAD}colour = [1]\n"),
        5,
        "display.colour",
        "unknown field",
    );
    let text = format!("{HEAD}[[line]]\nfrom = [0, 0]\nto = [4, 4]\nwidht = 2\ncolor = [1]\n");
    expect(&text, 8, "line[0].widht", "unknown field");
}

#[test]
fn unknown_table_is_named() {
    expect(
        &format!("{HEAD}[[star]]\nradius = 3\n"),
        5,
        "star",
        "unknown field",
    );
}

#[test]
fn missing_table_or_key_is_named() {
    let d = error_of("[render]\nantialias = true\n");
    assert_eq!(d.field, "display", "{d}");
    assert!(d.message.contains("missing"), "{d}");
    expect(
        "[display]\nwidth = 16\nformat = \"gray8\"\n",
        1,
        "display.height",
        "missing",
    );
}

#[test]
fn bad_number_is_named() {
    let text = "[display]\nwidth = \"wide\"\nheight = 8\nformat = \"gray8\"\n";
    expect(text, 2, "display.width", "invalid type");
    let text = "[display]\nwidth = 16\nheight = 0\nformat = \"gray8\"\n";
    expect(text, 3, "display.height", "outside 1..=2048");
    let text = format!("{HEAD}[render]\nband_rows = 1.5\n");
    expect(&text, 6, "render.band_rows", "invalid type");
    // Issue #34: a band of no rows is an error naming the field, not a
    // band of one row.
    let text = format!("{HEAD}[render]\nband_rows = 0\n");
    expect(&text, 6, "render.band_rows", "0 is outside 1..=2048");
    let text = format!("{HEAD}[render]\ngamma = 0.5\n");
    expect(&text, 6, "render.gamma", "1.0..=5.0");
    let text = format!("{HEAD}[[line]]\nfrom = [0, \"a\"]\nto = [1, 1]\ncolor = [1]\n");
    expect(&text, 6, "line[0].from", "invalid type");
}

#[test]
fn syntax_error_is_located() {
    expect(&format!("{HEAD}[[triangle]\n"), 5, "triangle", "");
}

#[test]
fn wrong_channel_count_is_named() {
    let text =
        format!("{HEAD}[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = [1, 2, 3]\n");
    expect(&text, 7, "triangle[0].color", "one channel");
    let text = format!(
        "{HEAD_RGB}[[polygon]]\npoints = [[0, 0], [4, 0], [4, 4]]\n\
         colors = [[1, 2, 3], [4, 5, 6], [7]]\n"
    );
    expect(&text, 7, "polygon[0].colors[2]", "three channels");
    let text = format!("{HEAD_RGB}background = [0]\n");
    expect(&text, 5, "display.background", "three channels");
}

#[test]
fn bad_hex_colour_is_named() {
    let tri = "[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\n";
    let text = format!("{HEAD}{tri}color = \"#12345\"\n");
    expect(&text, 7, "triangle[0].color", "has 7 characters, not 6");
    let text = format!("{HEAD}{tri}color = \"808080\"\n");
    expect(&text, 7, "triangle[0].color", "must start with `#`");
    let text = format!("{HEAD_RGB}{tri}colors = [[1, 2, 3], \"#12x456\", \"#000000\"]\n");
    expect(
        &text,
        7,
        "triangle[0].colors[1]",
        "`x` at byte 3 is not a hex digit",
    );
    let text = format!("{HEAD_RGB}background = \"#fff\"\n");
    expect(&text, 5, "display.background", "not 4");
    let text = format!("{HEAD}{tri}color = 7\n");
    expect(&text, 7, "triangle[0].color", "\"#rrggbb\"");
}

#[test]
fn wrong_vertex_or_colour_count_is_named() {
    let text = format!("{HEAD}[[triangle]]\npoints = [[0, 0], [4, 0]]\ncolor = [1]\n");
    expect(&text, 6, "triangle[0].points", "3 points");
    let text =
        format!("{HEAD}[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolors = [[1], [2]]\n");
    expect(&text, 7, "triangle[0].colors", "2 colours for 3 vertices");
    let text = format!("{HEAD}[[line]]\nfrom = [0, 0, 0]\nto = [4, 4]\ncolor = [1]\n");
    expect(&text, 6, "line[0].from", "2 numbers");
    let text = format!("{HEAD}[[polygon]]\npoints = [[0, 0], [4, 0], [0, 4]]\n");
    expect(&text, 5, "polygon[0]", "needs `color`");
}

#[test]
fn colour_out_of_range_is_named() {
    let text = format!("{HEAD}[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = [5000]\n");
    expect(&text, 7, "triangle[0].color[0]", "outside 0..=4095");
    let text = format!("{HEAD}background = [-1]\n");
    expect(&text, 5, "display.background[0]", "outside 0..=4095");
}

#[test]
fn coordinate_out_of_range_is_named() {
    let text =
        format!("{HEAD}[[triangle]]\npoints = [[0, 0], [2048.0625, 0], [0, 4]]\ncolor = [1]\n");
    expect(&text, 6, "triangle[0].points[1][0]", "outside -2048..=2048");
    // The limit itself is accepted.
    let ok = format!("{HEAD}[[triangle]]\npoints = [[0, 0], [2048, 0], [-2048, 4]]\ncolor = [1]\n");
    assert!(parse(Path::new("ok.toml"), &ok)
        .unwrap()
        .render_linear()
        .is_ok());
}

#[test]
fn nan_and_infinity_are_named() {
    let text = format!("{HEAD}[[line]]\nfrom = [nan, 0]\nto = [4, 4]\ncolor = [1]\n");
    expect(&text, 6, "line[0].from[0]", "not a finite number");
    let text = format!("{HEAD}[[line]]\nfrom = [0, 0]\nto = [4, -inf]\ncolor = [1]\n");
    expect(&text, 7, "line[0].to[1]", "not a finite number");
}

#[test]
fn off_grid_coordinate_is_rounded_with_a_warning() {
    let text = format!("{HEAD}[[line]]\nfrom = [0.1, 0]\nto = [4, 4.03]\ncolor = [1]\n");
    let file = parse(Path::new("warn.toml"), &text).unwrap();
    let w: Vec<String> = file.warnings.iter().map(|w| w.to_string()).collect();
    assert_eq!(w.len(), 2, "{w:?}");
    assert_eq!(file.warnings[0].severity, Severity::Warning);
    assert!(w[0].starts_with("warn.toml:6:8: line[0].from: "), "{w:?}");
    assert!(w[0].contains("rounded to [0.125, 0]"), "{w:?}");
    assert!(w[1].contains("rounded to [4, 4]"), "{w:?}");
}

#[test]
fn unknown_pixel_models_are_named_and_every_model_parses() {
    for model in [
        "box", "box-seed", "bed4", "bed8", "hex7", "hex19", "cone", "gauss", "hamming",
    ] {
        let text = format!("{HEAD}[render]\npixel_model = \"{model}\"\n[[line]]\nfrom = [1, 1]\nto = [9, 5]\ncolor = [4095]\n");
        let file = parse(Path::new("model.toml"), &text).unwrap_or_else(|e| panic!("{model}: {e}"));
        assert!(file.warnings.is_empty(), "{model}");
    }
    let text = format!("{HEAD}[render]\npixel_model = \"round\"\n");
    expect(&text, 6, "render.pixel_model", "unknown pixel model");
    let text = "[display]\nwidth = 16\nheight = 8\nformat = \"gray2\"\n";
    expect(text, 4, "display.format", "unknown format");
}

#[test]
fn polygon_core_rejects_is_located() {
    let text =
        format!("{HEAD}[[polygon]]\npoints = [[0, 0], [10, 10], [10, 0], [0, 20]]\ncolor = [1]\n");
    expect(&text, 5, "polygon[0]", "intersects itself");
}

#[test]
fn bad_3d_input_is_named() {
    // An object without a camera.
    let obj = "[[object]]\nshape = \"sphere\"\nradius = 1\ncolor = [4095]\n";
    expect(&format!("{HEAD}{obj}"), 5, "object[0]", "[camera]");
    // The eye at the target.
    let cam = "[camera]\nprojection = \"orthographic\"\neye = [0, 0, 0]\nscale = 2\n";
    expect(
        &format!("{HEAD}{cam}{obj}"),
        5,
        "camera",
        "eye is at the target",
    );
    // A negative radius, a key of another shape, an unknown shape.
    let bad = "[[object]]\nshape = \"sphere\"\nradius = -1\ncolor = [4095]\n";
    expect(
        &format!("{HEAD}{CAMERA}{bad}"),
        11,
        "object[0].radius",
        "outside 0..=4096",
    );
    let bad = "[[object]]\nshape = \"sphere\"\nradius = 1\nheight = 2\ncolor = [4095]\n";
    expect(
        &format!("{HEAD}{CAMERA}{bad}"),
        12,
        "object[0].height",
        "no `height`",
    );
    let bad = "[[object]]\nshape = \"teapot\"\ncolor = [4095]\n";
    expect(
        &format!("{HEAD}{CAMERA}{bad}"),
        10,
        "object[0].shape",
        "unknown shape",
    );
    // A torus whose tube is thicker than its ring: core's OutOfRange.
    let bad = "[[object]]\nshape = \"torus\"\nradius = 1\nminor_radius = 2\ncolor = [4095]\n";
    expect(
        &format!("{HEAD}{CAMERA}{bad}"),
        9,
        "object[0]",
        "minor_radius < radius",
    );
    // A zero light direction with diffuse light: at the direction (line
    // 10), not at the first object (line 12; issue #18).
    let light = "[light]\ndirection = [0, 0, 0]\ndiffuse = 0.5\n";
    expect(
        &format!("{HEAD}{CAMERA}{light}{obj}"),
        10,
        "light.direction",
        "zero",
    );
    let d = error_of(&format!("{HEAD}{CAMERA}{light}{obj}"));
    assert_eq!(d.column, 13, "{d}");
    // A perspective camera without fov_y.
    let cam = "[camera]\nprojection = \"perspective\"\neye = [0, 0, 10]\n";
    expect(
        &format!("{HEAD}{cam}{obj}"),
        5,
        "camera.fov_y",
        "needs `fov_y`",
    );
}

#[test]
fn unreadable_file_is_an_error_not_a_panic() {
    let out = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(["render", "/nonexistent/scene.toml", "-o", "/tmp/x.png"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("/nonexistent/scene.toml"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn hidden_surface_keys() {
    // Line 6: the [render] table's hsr value.
    expect(
        &format!("{HEAD}[render]\nhsr = \"painter\"\n"),
        6,
        "render.hsr",
        "unknown method",
    );
    expect(
        &format!("{HEAD}[render]\nsection = 1.5\n"),
        6,
        "render.section",
        "outside",
    );
    expect(
        &format!("{HEAD}[[triangle]]\npoints = [[0, 0], [4, 0], [0, 4]]\ncolor = [9]\ndepths = [0.5, 0.5]\n"),
        8,
        "triangle[0].depths",
        "one depth per point",
    );
    expect(
        &format!("{HEAD}[[polygon]]\npoints = [[0, 0], [4, 0], [4, 4], [0, 4]]\ncolor = [9]\ndepths = [0.5, 0.5, 0.5, 2]\n"),
        8,
        "polygon[0].depths[3]",
        "outside",
    );
    expect(
        &format!("{HEAD}[render]\nhsr = \"zbuffer\"\n[[line]]\nfrom = [0, 0]\nto = [4, 4]\ncolor = [9]\ndepths = [0.5]\n"),
        11,
        "line[0].depths",
        "one depth per point",
    );
    expect(
        &format!(
            "{HEAD}{CAMERA}far = 0.01\n[[object]]\nshape = \"sphere\"\nradius = 1\ncolor = [9]\n"
        ),
        9,
        "camera.far",
        "beyond near",
    );
}

// ------------------------------------------------- bounds (issue #18)

/// A torus object table.
fn torus(segments: u32, tube: u32, x: f64) -> String {
    format!(
        "[[object]]\nshape = \"torus\"\nradius = 2\nminor_radius = 0.5\n\
         segments = {segments}\ntube_segments = {tube}\nposition = [{x}, 0, 0]\n\
         rotation = [60, 0, 0]\ncolor = [3000]\n"
    )
}

#[test]
fn a_thousand_objects_are_refused_at_the_first_one_over_the_limit() {
    use softedge_sim::scene_file::MAX_OBJECTS;
    let mut text = format!("{HEAD}{CAMERA}");
    for k in 0..1000 {
        text += &torus(3, 3, f64::from(k % 5));
    }
    // Each table is 9 lines, after 8 lines of head and camera.
    let line = 8 + 9 * MAX_OBJECTS + 1;
    let field = format!("object[{MAX_OBJECTS}]");
    expect(&text, line, &field, "more than 256 objects");
    assert!(error_of(&text).message.contains("(1000 here)"));
}

#[test]
fn too_many_triangles_are_refused_before_the_mesh_is_built() {
    use softedge_sim::scene_file::MAX_TRIANGLES;
    // 1024 x 64 tori: 131 072 triangles each, four reach the limit of
    // 524 288 exactly, the fifth passes it.
    let mut text = format!("{HEAD}{CAMERA}");
    for k in 0..5 {
        text += &torus(1024, 64, f64::from(k));
    }
    let d = error_of(&text);
    assert_eq!(d.field, "object[4]", "{d}");
    assert_eq!(d.line, 8 + 9 * 4 + 1, "{d}");
    assert!(d.message.contains(&MAX_TRIANGLES.to_string()), "{d}");
    assert!(d.message.contains("655360"), "{d}");
}

#[test]
fn weiler_atherton_capacity_names_the_object_and_the_limit_in_words() {
    // Three spheres of 16 384 triangles: about 8 000 face the camera each,
    // so more than the 8 192 depth triangles hsr = "weiler-atherton" takes.
    let mut text = format!("{HEAD}[render]\nhsr = \"weiler-atherton\"\n{CAMERA}");
    for k in 0..3 {
        text += &format!(
            "[[object]]\nshape = \"sphere\"\nradius = 2\nsegments = 128\n\
             position = [{k}, 0, 0]\ncolor = [3000]\n"
        );
    }
    let d = error_of(&text);
    println!("{d}");
    assert_eq!(d.field, "object[1]", "{d}");
    assert!(d.message.contains("at most 8192 triangles"), "{d}");
    assert!(!d.message.contains("Capacity"), "{d}");
    // Fewer triangles than that, but more visible pieces than the 4 096
    // the simulator stores: named at the object being clipped, in words.
    let text = format!(
        "{HEAD}[render]\nhsr = \"weiler-atherton\"\n{CAMERA}\
         [[object]]\nshape = \"sphere\"\nradius = 2\nsegments = 120\ncolor = [3000]\n"
    );
    let d = error_of(&text);
    println!("{d}");
    assert!(d.field.starts_with("object["), "{d}");
    assert!(d.message.contains("4096 visible pieces"), "{d}");
    assert!(!d.message.contains("Capacity"), "{d}");
    assert!(d.line > 1, "{d}");
}

#[test]
fn render_scale_is_bounded_by_the_image_size() {
    let dir = std::env::temp_dir().join(format!("softedge-scale-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scene = dir.join("big.toml");
    std::fs::write(
        &scene,
        "[display]\nwidth = 2048\nheight = 2048\nformat = \"rgb888\"\n",
    )
    .unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(["render", scene.to_str().unwrap(), "--scale", "64", "-o"])
        .arg(dir.join("out.png"))
        .output()
        .unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("131072x131072"), "{err}");
    assert!(err.contains("--scale 4 or less"), "{err}");
    assert!(!err.contains("memory allocation"), "{err}");
}
