//! `[[text]]` in scene files: drawn, in file order over what comes before,
//! the font found relative to the scene file (the bundled one by default),
//! and each bad value a diagnostic naming its field.

use std::path::Path;

use softedge_sim::scene_file::{load, parse, Linear};

const HEAD: &str = "[display]\nwidth = 64\nheight = 24\nformat = \"gray8\"\n";

fn gray(scene: &softedge_sim::scene_file::SceneFile) -> Vec<u16> {
    match scene.render_linear().unwrap() {
        Linear::Gray(img) => img.pixels().map(|[v]| v).collect(),
        Linear::Rgb(_) => panic!("gray expected"),
    }
}

fn error(text: &str) -> String {
    match parse(Path::new("bad.toml"), text) {
        Ok(_) => panic!("accepted:\n{text}"),
        Err(d) => d.to_string(),
    }
}

#[test]
fn text_draws_with_the_bundled_font_and_with_a_font_file_beside_the_scene() {
    let body =
        "[[text]]\ntext = \"Hi 12 °C\"\nposition = [2.5, 3]\nsize = 14\nbaseline = \"top\"\n";
    let default = parse(Path::new("a.toml"), &format!("{HEAD}{body}")).unwrap();
    let pixels = gray(&default);
    assert!(pixels.iter().filter(|&&v| v > 0).count() > 40);

    let dir = std::env::temp_dir().join(format!("softedge-text-scene-{}", std::process::id()));
    std::fs::create_dir_all(dir.join("fonts")).unwrap();
    std::fs::write(
        dir.join("fonts/f.ttf"),
        softedge::text::bundled::SOFTEDGE_SANS,
    )
    .unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(&scene, format!("{HEAD}{body}font = \"fonts/f.ttf\"\n")).unwrap();
    let from_file = load(&scene).unwrap();
    assert_eq!(gray(&from_file), pixels);
}

#[test]
fn text_is_composed_over_what_is_drawn_before_it() {
    let text = format!(
        "{HEAD}[[polygon]]\npoints = [[0, 0], [64, 0], [64, 24], [0, 24]]\ncolor = [4095]\n\
         [[text]]\ntext = \"MM\"\nposition = [4, 20]\nsize = 20\ncolor = [0]\n"
    );
    let px = gray(&parse(Path::new("a.toml"), &text).unwrap());
    // Black text over white: some pixels fully dark, the rest white.
    assert!(px.contains(&0));
    assert!(px.iter().filter(|&&v| v == 4095).count() > 64 * 24 / 2);
}

#[test]
fn bad_text_values_are_diagnostics() {
    let t = |extra: &str| {
        format!("{HEAD}[[text]]\ntext = \"a\"\nposition = [1, 1]\nsize = 10\n{extra}")
    };
    let e = error(&t("align = \"middle\"\n"));
    assert!(
        e.contains("text[0].align") && e.contains("unknown alignment"),
        "{e}"
    );
    let e = error(&t("baseline = \"hanging\"\n"));
    assert!(e.contains("text[0].baseline"), "{e}");
    let e = error(&t("sharpen = \"hint\"\n"));
    assert!(e.contains("text[0].sharpen"), "{e}");
    let e = error(&t("opacity = 2\n"));
    assert!(e.contains("text[0].opacity"), "{e}");
    let e = error(&t("font = \"no-such-font.ttf\"\n"));
    assert!(
        e.contains("text[0].font") && e.contains("cannot read"),
        "{e}"
    );
    let e = error(&t("colour = [1]\n"));
    assert!(e.contains("unknown field"), "{e}");
    let e = error(&format!(
        "{HEAD}[[text]]\ntext = \"a\"\nposition = [1, 1]\nsize = 0.5\n"
    ));
    assert!(e.contains("text[0].size"), "{e}");
    // A file that is not a font.
    let dir = std::env::temp_dir().join(format!("softedge-text-bad-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("junk.ttf"), b"not a font at all").unwrap();
    let scene = dir.join("s.toml");
    std::fs::write(&scene, t("font = \"junk.ttf\"\n")).unwrap();
    let e = load(&scene).err().unwrap().to_string();
    assert!(e.contains("not a usable font"), "{e}");
}
