//! A font rasterized ahead of time by `softedge-sim font` (regenerate it
//! with `bash boards/bench-text/make-fonts.sh`): DejaVu Sans 2.37
//! (Debian's `fonts-dejavu-core`) at 16 px, printable ASCII and all of
//! Latin-1 (U+00A0..U+00FF), whole-pixel positions: the flash figure of a
//! 16-px ASCII + Latin-1 font (LVGL's Montserrat 16 at 4 bpp takes about
//! 15 KB). Bitstream Vera / DejaVu licence: `core/fonts/LICENSE-DejaVu.txt`.
//! (The label's font is the bundled one, `softedge::text::bundled::SANS_16`.)

pub mod latin1;
