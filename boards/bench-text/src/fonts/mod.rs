//! Fonts rasterized ahead of time by `softedge-sim font` (regenerate them
//! with `bash boards/bench-text/make-fonts.sh`).
//!
//! - [`sans16`]: the bundled font (Softedge Sans Subset) at 16 px, its
//!   printable ASCII and the Latin-1 characters it has (`£°±²³µ·½×÷`):
//!   the label's font.
//! - [`latin1`]: DejaVu Sans 2.37 (Debian's `fonts-dejavu-core`) at 16 px,
//!   printable ASCII and all of Latin-1 (U+00A0..U+00FF): the flash
//!   figure of a 16-px ASCII + Latin-1 font (LVGL's Montserrat 16 at 4 bpp
//!   takes about 15 KB). Bitstream Vera / DejaVu licence:
//!   `core/fonts/LICENSE-DejaVu.txt`.

pub mod latin1;
pub mod sans16;
