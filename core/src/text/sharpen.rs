//! [`Sharpen`]: hinting-free grid fitting for small text on 1-bit and
//! low-resolution displays.
//!
//! Takes a run's pen positions, baseline and vertical scale; gives them
//! moved to the pixel grid, so that horizontal features (baseline, x-height,
//! flat tops and bottoms) and the starts of glyphs fall on pixel edges
//! instead of being spread over two half-covered rows, which dithering to
//! 1 bit turns into noise. No instruction of the font is run (there are
//! none in the bundled subset): only three integer roundings.
//!
//! - `baseline`: the baseline (and each line's) rounded to a whole pixel.
//! - `x_height`: the vertical scale multiplied by
//!   `round(x_px) / x_px` (`x_px` the x-height in pixels, at least 1), so
//!   the tops of lowercase letters end on a pixel edge too; ascenders and
//!   caps move by the same ratio (at 10..12 px at most a third of a pixel).
//! - `glyph_x`: each glyph's origin rounded to a whole pixel (the pen
//!   itself keeps its exact position, so spacing errors do not add up),
//!   so a glyph looks the same wherever it is drawn. Sub-pixel positioning
//!   is given up: leave it off where text moves.
//!
//! Exact area coverage is kept: a sharpened glyph is still anti-aliased,
//! only placed differently. [`Sharpen::NONE`] (the default) changes nothing.

/// Which roundings to the pixel grid a run gets (see the module).
///
/// ```
/// use softedge::text::Sharpen;
/// assert_eq!(Sharpen::default(), Sharpen::NONE);
/// assert!(Sharpen::GRID.baseline && Sharpen::GRID.x_height && Sharpen::GRID.glyph_x);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Sharpen {
    /// Baselines on whole pixels.
    pub baseline: bool,
    /// The x-height a whole number of pixels.
    pub x_height: bool,
    /// Glyph origins on whole pixels.
    pub glyph_x: bool,
}

impl Sharpen {
    /// Exact positions, sub-pixel (the default).
    pub const NONE: Sharpen = Sharpen {
        baseline: false,
        x_height: false,
        glyph_x: false,
    };
    /// Everything on the grid: for static text on 1-bit displays.
    pub const GRID: Sharpen = Sharpen {
        baseline: true,
        x_height: true,
        glyph_x: true,
    };
    /// Only the vertical roundings: sharper rows, sub-pixel x kept.
    pub const VERTICAL: Sharpen = Sharpen {
        baseline: true,
        x_height: true,
        glyph_x: false,
    };
}

/// `v` fine units rounded to the nearest whole pixel (halves up).
pub(crate) const fn round_px(v: i64) -> i64 {
    let one = crate::geom::FINE_ONE as i64;
    (v + one / 2).div_euclid(one) * one
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_to_pixels() {
        assert_eq!(round_px(511), 0);
        assert_eq!(round_px(512), 1024);
        assert_eq!(round_px(-512), 0);
        assert_eq!(round_px(-513), -1024);
        assert_eq!(round_px(5 * 1024 + 100), 5 * 1024);
    }
}
