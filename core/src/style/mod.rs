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

/// How a shape's edge pixels are drawn: its exact coverage (`Smooth`, the
/// default), or that coverage pushed towards whole pixels for a 1-bit
/// display, this shape only.
///
/// On a 1-bit display a dithered edge scatters into dots: stray dots in
/// small text, notches along an arc. A frame-wide
/// [`ContrastBoost`](crate::text::ContrastBoost) sharpens text but erases
/// every half-tone of the frame with it (a track at 1/3 opacity goes
/// dark); `Edges` belongs to the shape, so text and value arcs can be
/// crisp while a translucent track keeps its dithered tone. Applied to
/// the share `s` (`0..=1`) a shape's fill rule gives a pixel, before its
/// opacity and colour: integer subtract, shift, compare, once per run of
/// equal coverage, not per pixel. Triangles and meshes (linear coverage,
/// for seamless tiling) are always smooth.
///
/// ```
/// use softedge::style::Edges;
/// const HALF: i32 = 1 << 15; // coverage units: 2^16 is a whole pixel
/// assert_eq!(Edges::Smooth.sharpen(HALF + 100), HALF + 100);
/// assert_eq!(Edges::Boost(2).sharpen(HALF + 100), HALF + 400);
/// assert_eq!(Edges::Boost(2).sharpen(HALF / 4), 0);
/// assert_eq!(Edges::Crisp.sharpen(HALF), 2 * HALF);
/// assert_eq!(Edges::Crisp.sharpen(HALF - 1), 0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Edges {
    /// Exact coverage: anti-aliased edges (the default).
    #[default]
    Smooth,
    /// `s' = clamp((s - 1/2) 2^k + 1/2, 0, 1)` with `k` the value (1..=8;
    /// 0 is smooth, more is 8): [`ContrastBoost`](crate::text::ContrastBoost)'s
    /// rule on this shape only. `Boost(2)` is the README's "boost x4" for
    /// 10-12 px text: stems straddling two pixels still share the ink.
    Boost(u8),
    /// Whole pixels: a pixel at least half covered is covered, any other
    /// one is not (the threshold at 1/2 of the exact coverage). Crisp
    /// 1-bit output: white on black it is never dithered.
    Crisp,
}

impl Edges {
    /// The largest shift of [`Boost`](Self::Boost).
    pub const MAX_BOOST: u8 = 8;

    /// The share `s` of a pixel (coverage units, `0..=COVER_ONE`: a whole
    /// pixel is 2^16) after this rule; a value outside that range is
    /// clamped to it first.
    pub const fn sharpen(self, s: i32) -> i32 {
        const ONE: i32 = crate::units::COVER_ONE;
        const HALF: i32 = ONE / 2;
        let s = if s < 0 {
            0
        } else if s > ONE {
            ONE
        } else {
            s
        };
        match self {
            Self::Smooth | Self::Boost(0) => s,
            Self::Crisp => {
                if s >= HALF {
                    ONE
                } else {
                    0
                }
            }
            Self::Boost(k) => {
                let k = if k > Self::MAX_BOOST {
                    Self::MAX_BOOST
                } else {
                    k
                };
                // |s - HALF| <= 2^15, shifted by at most 8: below 2^24.
                let v = ((s - HALF) << k) + HALF;
                if v < 0 {
                    0
                } else if v > ONE {
                    ONE
                } else {
                    v
                }
            }
        }
    }
}

/// Why an [`Opacity`] could not be made.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum OpacityError {
    /// [`Opacity::from_ratio`] with a zero denominator.
    ZeroDenominator {
        /// The numerator given.
        num: u32,
    },
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

    /// From a fraction `num / den` (`round(4096 num / den)`, clamped to
    /// `0..=1`); a zero `den` is an error, not an opacity.
    ///
    /// ```
    /// use softedge::style::{Opacity, OpacityError};
    /// assert_eq!(Opacity::from_ratio(1, 2)?.to_4096ths(), 2048);
    /// assert_eq!(Opacity::from_ratio(3, 2)?, Opacity::OPAQUE);
    /// let e = Opacity::from_ratio(1, 0).unwrap_err();
    /// assert_eq!(e, OpacityError::ZeroDenominator { num: 1 });
    /// assert_eq!(e.to_string(), "opacity 1/0: the denominator is zero");
    /// // In a `const`, where `?` is not available:
    /// const THREE_QUARTERS: Opacity = match Opacity::from_ratio(3, 4) {
    ///     Ok(o) => o,
    ///     Err(_) => Opacity::OPAQUE,
    /// };
    /// # Ok::<(), OpacityError>(())
    /// ```
    pub const fn from_ratio(num: u32, den: u32) -> Result<Self, OpacityError> {
        if den == 0 {
            return Err(OpacityError::ZeroDenominator { num });
        }
        if num >= den {
            return Ok(Self::OPAQUE);
        }
        Ok(Self(
            ((num as u64 * 8192 + den as u64) / (2 * den as u64)) as u16,
        ))
    }

    /// From a percentage, `100` opaque (`round(4096 p / 100)`, clamped to
    /// `0..=100`): the infallible `const` form of
    /// [`from_ratio`](Self::from_ratio)`(p, 100)`.
    ///
    /// ```
    /// use softedge::style::Opacity;
    /// const HALF: Opacity = Opacity::from_percent(50);
    /// assert_eq!(HALF.to_4096ths(), 2048);
    /// assert_eq!(Opacity::from_percent(250), Opacity::OPAQUE);
    /// ```
    pub const fn from_percent(p: u8) -> Self {
        if p >= 100 {
            return Self::OPAQUE;
        }
        Self(((p as u32 * 8192 + 100) / 200) as u16)
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

    /// Every share through every rule against the formula in `i64`.
    #[test]
    fn edges_sharpen_by_their_formula() {
        let one = i64::from(crate::units::COVER_ONE);
        for s in (-5..=one + 5)
            .step_by(7)
            .chain([one / 2 - 1, one / 2, one / 2 + 1])
        {
            let c = s.clamp(0, one);
            assert_eq!(i64::from(Edges::Smooth.sharpen(s as i32)), c);
            assert_eq!(
                i64::from(Edges::Crisp.sharpen(s as i32)),
                if 2 * c >= one { one } else { 0 }
            );
            for k in 0..=12u8 {
                let kk = u32::from(k.min(Edges::MAX_BOOST));
                let want = ((c - one / 2) * (1 << kk) + one / 2).clamp(0, one);
                assert_eq!(
                    i64::from(Edges::Boost(k).sharpen(s as i32)),
                    want,
                    "{s} {k}"
                );
            }
        }
    }

    #[test]
    fn opacity_conversions_round_and_clamp() {
        assert_eq!(Opacity::from_u8(255), Opacity::OPAQUE);
        assert_eq!(Opacity::from_u8(0), Opacity::TRANSPARENT);
        assert_eq!(Opacity::from_u8(128).to_4096ths(), 2056);
        assert_eq!(Opacity::from_ratio(1, 2).unwrap().to_4096ths(), 2048);
        assert_eq!(Opacity::from_ratio(3, 2), Ok(Opacity::OPAQUE));
        assert_eq!(
            Opacity::from_ratio(7, 0),
            Err(OpacityError::ZeroDenominator { num: 7 })
        );
        // round(4096 p / 100) in f64, every percentage.
        for p in 0..=255u8 {
            let exact = (4096.0 * f64::from(p.min(100)) / 100.0).round() as u16;
            assert_eq!(Opacity::from_percent(p).to_4096ths(), exact, "{p} %");
            if p <= 100 {
                assert_eq!(
                    Ok(Opacity::from_percent(p)),
                    Opacity::from_ratio(u32::from(p), 100)
                );
            }
        }
        assert_eq!(Opacity::from_4096ths(9999), Opacity::OPAQUE);
    }
}
