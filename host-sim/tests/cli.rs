//! The `softedge-sim` binary: help, exit codes, and errors without panics.

use std::process::{Command, Output};

fn sim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_softedge-sim"))
        .args(args)
        .output()
        .expect("the binary runs")
}

#[test]
fn help_lists_the_subcommands() {
    for flag in ["--help", "-h", "help"] {
        let out = sim(&[flag]);
        assert!(out.status.success());
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(text.contains("gallery -o DIR"), "{text}");
        assert!(text.contains("help"), "{text}");
    }
}

#[test]
fn bad_command_lines_exit_2_with_usage() {
    for args in [&[][..], &["frobnicate"], &["gallery"], &["gallery", "-o"]] {
        let out = sim(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains("USAGE"), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let out = sim(&["gallery", "-o", "x", "--scale", "0"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn unwritable_dir_is_a_message_and_exit_1() {
    let file = std::env::temp_dir().join(format!("softedge-sim-cli-{}", std::process::id()));
    std::fs::write(&file, b"a file, not a directory").unwrap();
    let target = file.join("gallery");
    let out = sim(&["gallery", "-o", target.to_str().unwrap()]);
    std::fs::remove_file(&file).unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("error"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn memory_prints_the_band_ram_table() {
    let out = sim(&["memory"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    // 240x240 Rgb565 (3 channels), 16 rows: 46080 + 19456 plain (the
    // cover scratch with its tags), plus 7680 + 15360 for the z-buffer
    // (depth; coverage and sample mask).
    assert!(
        text.contains("  16    46080    19456     7680    15360    65536     88576"),
        "{text}"
    );
    let out = sim(&["memory", "--width", "128", "--channels", "1", "--rows", "8"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("   8     4096     5248     2048     4096     9344     15488"),
        "{text}"
    );
    for bad in [
        &["memory", "--channels", "2"][..],
        &["memory", "--rows", "0"],
    ] {
        assert_eq!(sim(bad).status.code(), Some(2), "{bad:?}");
    }
}
