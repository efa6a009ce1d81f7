//! [`TextSize`] and [`Scale`]: font units to the fine grid, in fixed point.
//!
//! Takes a pixel size (the em in pixels, in 1/64 px) and the font's
//! `units_per_em`; gives the factor that maps outline coordinates in
//! 1/64 font unit (`u64ths`, what [`outline`](super::outline) makes of the
//! parser's `f32`) to fine units (1/1024 px):
//!
//! ```text
//! fine = u64ths * size_px * 1024 / (64 * units_per_em)
//!      = (u64ths * k + 2^23) >> 24,   k = round(size_64ths * 2^24 / (4 * units_per_em))
//! ```
//!
//! One multiply and a shift per outline point (set-up, never per pixel).
//!
//! ## Integer ranges
//!
//! `size_64ths <= 2048 * 64 = 2^17` and `units_per_em >= 16`, so
//! `k <= 2^17 * 2^24 / 64 = 2^35`; coordinates are clamped to
//! `|u64ths| <= 2^26` (a million font units), so `u64ths * k < 2^61` fits
//! `i64`. At 1 px and 16384 units per em `k = 2^14`, so its rounding is a
//! relative error below `2^-15`; at the smallest size (1/64 px) `k = 256`
//! and the error, relative `2^-9`, is below a thousandth of a fine unit.

/// Text size: the em square in pixels, in 1/64 px (`1..=2048` px).
///
/// ```
/// use softedge::text::TextSize;
/// assert_eq!(TextSize::px(12).to_64ths(), 768);
/// assert_eq!(TextSize::from_64ths(12 * 64 + 32).to_64ths(), 800); // 12.5 px
/// assert_eq!(TextSize::px(0), TextSize::MIN);
/// assert_eq!(TextSize::px(5000), TextSize::MAX);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TextSize(u32);

impl TextSize {
    /// 1/64 px.
    pub const MIN: TextSize = TextSize(1);
    /// 2048 px.
    pub const MAX: TextSize = TextSize(2048 * 64);

    /// An em of `px` pixels, limited to `1..=2048`.
    pub const fn px(px: u16) -> Self {
        Self::from_64ths(px as u32 * 64)
    }

    /// An em of `v / 64` pixels, limited to `1/64..=2048` px.
    pub const fn from_64ths(v: u32) -> Self {
        if v < Self::MIN.0 {
            Self::MIN
        } else if v > Self::MAX.0 {
            Self::MAX
        } else {
            Self(v)
        }
    }

    /// The size in 1/64 px.
    pub const fn to_64ths(self) -> u32 {
        self.0
    }
}

/// Largest `|coordinate|` in 1/64 font unit (clamped beyond).
pub const U64THS_LIMIT: i32 = 1 << 26;
/// Fraction bits of [`Scale`]'s factors.
pub const SCALE_SHIFT: u32 = 24;

/// Font units (in 1/64) to fine units, x and y separately (the vertical
/// factor differs when the x-height is snapped, see
/// [`Sharpen`](super::Sharpen)).
///
/// ```
/// use softedge::text::{Scale, TextSize};
/// // 2048 units per em at 16 px: 1 unit is 1/128 px = 8 fine units.
/// let s = Scale::new(TextSize::px(16), 2048);
/// assert_eq!(s.x_units(1), 8);
/// assert_eq!(s.x_units(-2048), -16 * 1024);
/// assert_eq!(s.x(64 * 3 + 32), 28); // 3.5 units
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Scale {
    kx: i64,
    ky: i64,
}

impl Scale {
    /// The factor for `size` at `units_per_em` (taken as at least 16).
    pub const fn new(size: TextSize, units_per_em: u16) -> Self {
        let upem = if units_per_em < 16 { 16 } else { units_per_em } as i64;
        let num = (size.0 as i64) << SCALE_SHIFT;
        let den = 4 * upem;
        let k = (num + den / 2) / den;
        Self { kx: k, ky: k }
    }

    /// The same with the vertical factor multiplied by `num / den`
    /// (rounded; `den` 0 leaves it).
    pub const fn with_y_ratio(self, num: i64, den: i64) -> Self {
        if den <= 0 || num <= 0 {
            return self;
        }
        let ky = (self.ky as i128 * num as i128 + den as i128 / 2) / den as i128;
        let ky = if ky > (1 << 36) { 1 << 36 } else { ky as i64 };
        Self { kx: self.kx, ky }
    }

    /// An x distance of `u64ths` (1/64 font unit) in fine units.
    pub const fn x(&self, u64ths: i32) -> i64 {
        apply(u64ths, self.kx)
    }

    /// A y distance of `u64ths` (1/64 font unit, y up) in fine units (y
    /// up too: subtract from a baseline).
    pub const fn y(&self, u64ths: i32) -> i64 {
        apply(u64ths, self.ky)
    }

    /// An x distance of whole font units, fine units.
    pub const fn x_units(&self, units: i32) -> i64 {
        self.x(units.saturating_mul(64))
    }

    /// A y distance of whole font units, fine units.
    pub const fn y_units(&self, units: i32) -> i64 {
        self.y(units.saturating_mul(64))
    }
}

/// `round(u * k / 2^24)`, `u` clamped to `±U64THS_LIMIT`.
const fn apply(u: i32, k: i64) -> i64 {
    let u = if u > U64THS_LIMIT {
        U64THS_LIMIT
    } else if u < -U64THS_LIMIT {
        -U64THS_LIMIT
    } else {
        u
    };
    (u as i64 * k + (1 << (SCALE_SHIFT - 1))) >> SCALE_SHIFT
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scale_matches_the_exact_ratio_over_the_range() {
        for upem in [16u16, 1000, 1024, 2048, 16384] {
            for px in [1u16, 8, 12, 24, 48, 2048] {
                let s = Scale::new(TextSize::px(px), upem);
                for u in [
                    -U64THS_LIMIT,
                    -64 * 2048,
                    -1,
                    0,
                    1,
                    333,
                    64 * 2048,
                    U64THS_LIMIT,
                ] {
                    let exact = u as f64 * px as f64 * 1024.0 / (64.0 * upem as f64);
                    assert!((s.x(u) as f64 - exact).abs() <= 0.5 + exact.abs() * 2f64.powi(-15));
                }
            }
        }
    }

    #[test]
    fn y_ratio_scales_only_y() {
        let s = Scale::new(TextSize::px(10), 1000).with_y_ratio(11, 10);
        assert_eq!(s.x_units(1000), 10 * 1024);
        assert_eq!(s.y_units(1000), 11 * 1024);
        assert_eq!(s.with_y_ratio(1, 0), s);
    }
}
