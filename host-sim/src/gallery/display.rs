//! A simulated γ = 2.4 display, seen on a PC's sRGB monitor.
//!
//! The firmware sends 8-bit codes; a display of exponent γ emits
//! `B = (code / 255)^γ` of its white (seed 000, eq. 6, no stray light). Two
//! ways to get the codes from the band's linear 12-bit intensity:
//!
//! - uncorrected: the linear value's top 8 bits, `code = lin12 >> 4`, as a
//!   driver that ignores γ does;
//! - corrected: [`GammaLut`] for γ = 2.4 (eq. 7), `code ≈ 255 (lin12 /
//!   4095)^(1/2.4)`.
//!
//! To show "what the display emits" in a PNG, `B` is encoded for the sRGB
//! monitor the PNG is viewed on ([`emitted_to_srgb8`]).

use softedge::tone::{Curve, GammaLut};

use crate::image::{emitted_to_srgb8, Channels, Image8, LinImage};

/// Exponent of the simulated display (seed 000's CRT, and BT.1886).
pub(super) const DISPLAY_GAMMA: f64 = 2.4;

/// The firmware's γ table for that display, built at compile time.
pub(super) static GAMMA_2_4: GammaLut = GammaLut::new(Curve::GAMMA_2_4);

/// How a driver turns `lin12` into an 8-bit display code.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Codes {
    /// `lin12 >> 4`: no γ correction.
    Uncorrected,
    /// Through [`GAMMA_2_4`].
    Corrected,
}

impl Codes {
    /// The 8-bit code sent for `lin12`.
    pub(super) fn code(self, lin12: u16) -> u8 {
        match self {
            Self::Uncorrected => (lin12.min(softedge::LIN_MAX) >> 4) as u8,
            Self::Corrected => GAMMA_2_4.code(lin12),
        }
    }

    /// The light the simulated display emits for `lin12`, a fraction of
    /// its white: `(code / 255)^2.4`.
    pub(super) fn emitted(self, lin12: u16) -> f64 {
        (f64::from(self.code(lin12)) / 255.0).powf(DISPLAY_GAMMA)
    }
}

/// A gray frame as the simulated display shows it, encoded for viewing on
/// an sRGB monitor.
pub(super) fn show(img: &LinImage<1>, codes: Codes) -> Image8 {
    // Only 4096 inputs: tabulate once per frame.
    let table: Vec<u8> = (0..=softedge::LIN_MAX)
        .map(|v| emitted_to_srgb8(codes.emitted(v)))
        .collect();
    let data = img
        .pixels()
        .map(|[v]| table[usize::from(v.min(softedge::LIN_MAX))])
        .collect();
    Image8::from_raw(img.width(), img.height(), Channels::Gray, data)
        .unwrap_or_else(|| Image8::new(1, 1, Channels::Gray, &[0]))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_light_split_over_two_pixels_loses_62_percent_uncorrected() {
        // Seed 000: S1 = S2 = 1/2 at γ = 2.4 shows 2 (1/2)^2.4 = 0.379.
        let lost = 2.0 * Codes::Uncorrected.emitted(2048) - 1.0;
        assert!((-0.63..-0.61).contains(&lost), "{lost}");
        let kept = 2.0 * Codes::Corrected.emitted(2048) - 1.0;
        assert!(kept.abs() < 0.01, "{kept}");
    }

    #[test]
    fn ends_are_black_and_white() {
        for c in [Codes::Uncorrected, Codes::Corrected] {
            assert_eq!(c.emitted(0), 0.0);
            assert_eq!(c.code(4095), 255);
        }
    }
}
