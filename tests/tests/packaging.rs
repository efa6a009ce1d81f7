//! The `softedge` package carries the licence texts its `license` field
//! names. Cargo packages only files inside the package's folder (an
//! `include` of `../LICENSE-MIT` is silently dropped), so `core/` holds
//! copies of the repository root's files; they must stay identical.

use std::path::Path;

fn read(path: &Path) -> Vec<u8> {
    std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn core_licence_files_are_copies_of_the_root_ones() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    for name in ["LICENSE-MIT", "LICENSE-APACHE"] {
        let top = read(&root.join(name));
        let core = read(&root.join("core").join(name));
        assert!(
            top == core,
            "core/{name} differs from {name}: copy it again"
        );
    }
    let mit = String::from_utf8(read(&root.join("LICENSE-MIT"))).unwrap();
    assert!(mit.contains("Copyright (c) the softedge developers"));
    let apache = String::from_utf8(read(&root.join("LICENSE-APACHE"))).unwrap();
    assert!(apache.contains("Apache License\n                           Version 2.0, January 2004"));
}

#[test]
fn core_manifest_names_the_licence_files_and_the_readme() {
    let manifest =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("../core/Cargo.toml"))
            .unwrap();
    for key in [
        "\"LICENSE-MIT\"",
        "\"LICENSE-APACHE\"",
        "readme = \"../README.md\"",
        "rustdoc-args = [\"--cfg\", \"docsrs\"]",
    ] {
        assert!(manifest.contains(key), "core/Cargo.toml lacks {key}");
    }
}
