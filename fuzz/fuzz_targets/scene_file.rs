//! The scene-file parser and renderer on any text (seeded with the example
//! scenes): never a panic; an error is a diagnostic with a place; an
//! accepted scene renders (or fails with a diagnostic) and tones.
#![no_main]

use std::path::Path;

use libfuzzer_sys::fuzz_target;
use softedge_sim::scene_file::{parse, Frame};

/// Frames larger than this are parsed but not rendered (rendering is
/// checked by the other targets; this keeps executions fast).
const MAX_RENDER_PIXELS: u32 = 128 * 128;
const MAX_RENDER_PRIMITIVES: usize = 2048;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let file = match parse(Path::new("fuzz.toml"), text) {
        Ok(f) => f,
        Err(d) => {
            // A diagnostic prints (Display) without panicking.
            let _ = d.to_string();
            return;
        }
    };
    let (w, h) = file.size();
    let primitives = match &file.frame {
        Frame::Gray(s) => s.primitives.len(),
        Frame::Rgb(s) => s.primitives.len(),
    };
    if u32::from(w) * u32::from(h) > MAX_RENDER_PIXELS || primitives > MAX_RENDER_PRIMITIVES {
        return;
    }
    // The one use of the renderer: the file's frame, band by band.
    match file.render_linear() {
        Ok(lin) => {
            let codes = file.tone(&lin);
            let _ = codes.crc32();
        }
        Err(d) => {
            assert!(d.line > 0, "a render error without a place: {d}");
            let _ = d.to_string();
        }
    }
});
