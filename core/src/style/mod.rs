//! Styles several stages share: how a shape's coverage becomes a pixel's
//! share (fill rule), and how a shape meets what is under it (blend,
//! opacity).

mod errors;
pub mod gradient;
pub use gradient::{Gradient, GradientError, GradientKind, Offset, Stop, MAX_STOPS};

/// Which points a path's contours enclose.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum FillRule {
    /// Inside where the winding number is not zero (SVG `nonzero`).
    #[default]
    NonZero,
    /// Inside where the winding number is odd (SVG `evenodd`).
    EvenOdd,
}

/// How a shape is composed into what the band already holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Blend {
    /// Painter's order: the shape covers what is under it by its exact
    /// coverage `c` and opacity `α`, in linear light,
    /// `acc = acc (1 - c α) + I c α`. The default for 2D drawing.
    #[default]
    Over,
    /// Seed 000's accumulation, `acc += (I - background) c α`: exact for
    /// disjoint visible surfaces (what hidden-surface removal gives) and for
    /// meshes drawn triangle by triangle. A path's, shape's or stroke's
    /// coverage `c` is its fill rule's, as in over (a contour wound
    /// several times adds once); a pixel takes at most one whole coverage
    /// per shape.
    Add,
}

/// Opacity in 1/4096: `Opacity::OPAQUE` is 4096.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Opacity(u16);

impl Opacity {
    /// Fully opaque.
    pub const OPAQUE: Self = Self(Self::ONE);
    /// Invisible.
    pub const TRANSPARENT: Self = Self(0);
    const ONE: u16 = 1 << 12;

    /// From 1/4096 units, clamped to `0..=4096`.
    pub const fn from_4096ths(v: u16) -> Self {
        Self(if v > Self::ONE { Self::ONE } else { v })
    }

    /// From a byte, `255` opaque (`round(v * 4096 / 255)`).
    pub const fn from_u8(v: u8) -> Self {
        Self(((v as u32 * 8192 + 255) / 510) as u16)
    }

    /// From a fraction `num / den` (rounded, clamped to `0..=1`; a zero
    /// `den` is opaque).
    pub const fn from_ratio(num: u32, den: u32) -> Self {
        if den == 0 || num >= den {
            return Self::OPAQUE;
        }
        Self(((num as u64 * 8192 + den as u64) / (2 * den as u64)) as u16)
    }

    /// The value in 1/4096.
    pub const fn to_4096ths(self) -> u16 {
        self.0
    }

    /// True when fully opaque.
    pub const fn is_opaque(self) -> bool {
        self.0 == Self::ONE
    }
}

impl Default for Opacity {
    fn default() -> Self {
        Self::OPAQUE
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opacity_conversions_round_and_clamp() {
        assert_eq!(Opacity::from_u8(255), Opacity::OPAQUE);
        assert_eq!(Opacity::from_u8(0), Opacity::TRANSPARENT);
        assert_eq!(Opacity::from_u8(128).to_4096ths(), 2056);
        assert_eq!(Opacity::from_ratio(1, 2).to_4096ths(), 2048);
        assert_eq!(Opacity::from_ratio(3, 2), Opacity::OPAQUE);
        assert_eq!(Opacity::from_4096ths(9999), Opacity::OPAQUE);
    }
}
