//! Tone: from linear 12-bit intensity to display codes (seed 000).
//!
//! Takes linear-light intensities `lin12` (`u16`, `0..=4095`, as resolved by
//! the band buffer; larger values are clamped to 4095 everywhere), or 8-bit
//! logarithmic intensity codes; gives display codes and pixel colours.
//!
//! - [`gamma`]: the γ-correction table `V = I^(1/γ)` (eq. 7), so that the
//!   display's brightness `B = B_min + k * I` is linear in the accumulated
//!   intensity (eqs. 6, 8) — without it an object split over two pixels
//!   loses up to 62 % of its brightness at γ = 2.4.
//! - [`log_code`]: logarithmic intensity codes `I_i = i / m`,
//!   `B_i = B_min * K^(I_i)` (eqs. 11-13), the potentiation table (fig. 7a),
//!   log arithmetic with a Gaussian-logarithm table (fig. 7b) and the output
//!   table `V = ((K^I - 1) / (K - 1))^(1/γ)` (eq. 15).
//! - [`format`]: rows of `lin12` to Gray8, Gray4, Rgb565, Rgb888 codes (and
//!   the embedded-graphics colour types behind the `embedded-graphics`
//!   feature).
//! - [`dither`]: rows of `lin12` to 1-bit pixels, ordered (Bayer 8x8) or
//!   error diffusion (Floyd–Steinberg), in linear light.
//! - [`ordered`]: rows of `lin12` to Rgb565 (and Gray4) through a finer
//!   γ code and a 4x4 Bayer threshold: no banding, the tile averages to the
//!   finer code (issue 16).
//! - [`bits`]: the bit-depth calculator of eqs. 9-10 and `m = ln K / ln(1+δ)`
//!   (a planning tool, `f64`).
//!
//! ## Integer ranges
//!
//! Per pixel, every stage is a table look-up indexed by a clamped value
//! (`lin12.min(4095)`, a log value clamped to its table) plus, in the
//! dithering, additions, shifts and compares of `i32` values bounded by
//! `|e| <= 2 * 4095`. Tables are built in `const fn`s with integer
//! fixed-point `log2`/`exp2` (`u128` Q62 values, `i64` Q32 logarithms; the
//! bounds are stated in that file), so they are bit-identical on every
//! target and can live in flash.

pub mod bits;
pub mod dither;
mod errors;
pub(crate) mod fixpow;
pub mod format;
pub mod gamma;
pub mod log_code;
pub mod ordered;
pub mod profile;

pub use bits::{levels, BitDepth};
pub use dither::{Bayer8, FloydSteinberg};
pub use gamma::{Curve, Gamma, GammaLut};
pub use log_code::{GaussLog, LogOutputLut, LogScale, LogValue, PotentiationLut};
pub use ordered::{DitherLut, Gray4Dither, Rgb565Dither};
pub use profile::{DiffusionProfile, Profile, ToneRow};

pub use crate::shade::LIN_MAX;

/// Entries of a table indexed by `lin12`: 4096.
pub const LIN_LEN: usize = LIN_MAX as usize + 1;

/// Why a tone table or plan could not be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ToneError {
    /// Contrast `K` below 2.
    Contrast,
    /// Number of gradations `m` is zero.
    Gradations,
    /// The Gaussian-logarithm table cannot reach zero within its length for
    /// this `K` and `m` (the gradation step is too fine for the contrast).
    GaussTooLong,
    /// A planning input is out of range (`K <= 1`, `δ <= 0`, `γ <= 1`, or
    /// not finite).
    PlanInput,
}

/// `lin12` clamped to 4095, as a table index.
#[inline]
pub(crate) fn lin12_index(lin12: u16) -> usize {
    usize::from(lin12.min(LIN_MAX))
}
