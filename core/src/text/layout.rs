//! Layout settings in embedded-graphics' idiom: [`Alignment`],
//! [`Baseline`], [`LineHeight`] and the [`TextStyle`] that holds them.
//!
//! Takes nothing but the choices; gives the offsets a [`Text`](super::Text)
//! applies, with embedded-graphics 0.8's conventions:
//!
//! - **Alignment** is per line: `Left` starts the line at the position,
//!   `Right` ends its advance there, `Center` puts the middle of its
//!   advance there.
//! - **Baseline** places the **first** line: `Alphabetic` puts the
//!   baseline at the position (the bottom of an `A`), `Top` and `Bottom`
//!   the top and bottom of the line's box (the font's ascender and
//!   descender), `Middle` halfway between them. The other lines follow
//!   one line height further down each.
//! - **Line height** is the distance between baselines: a number of
//!   pixels, or a percentage of the font's (ascender - descender + line
//!   gap); 100 % by default.
//!
//! With the `embedded-graphics` feature each converts from
//! embedded-graphics' type of the same name (`.into()`).

/// Horizontal alignment of each line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Alignment {
    /// The line starts at the position.
    #[default]
    Left,
    /// The line's advance is centred on the position.
    Center,
    /// The line's advance ends at the position.
    Right,
}

/// Vertical placement of the first line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum Baseline {
    /// The top of the line's box (ascender) at the position.
    Top,
    /// The bottom of the line's box (descender) at the position.
    Bottom,
    /// Halfway between ascender and descender at the position.
    Middle,
    /// The alphabetic baseline at the position.
    #[default]
    Alphabetic,
}

/// The distance between the baselines of two lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum LineHeight {
    /// Whole pixels.
    Pixels(u32),
    /// A percentage of the font's line height at the text size.
    Percent(u32),
}

impl Default for LineHeight {
    fn default() -> Self {
        LineHeight::Percent(100)
    }
}

impl LineHeight {
    /// The distance in fine units, given the font's line height in fine
    /// units (`Percent` rounded; both limited to 2^24 px).
    ///
    /// ```
    /// use softedge::text::LineHeight;
    /// assert_eq!(LineHeight::Percent(150).to_fine(2000), 3000);
    /// assert_eq!(LineHeight::Pixels(12).to_fine(2000), 12 * 1024);
    /// ```
    pub fn to_fine(self, font_line_fine: i64) -> i64 {
        const LIMIT: i64 = 1 << 34;
        match self {
            LineHeight::Pixels(p) => i64::from(p) * i64::from(crate::geom::FINE_ONE),
            LineHeight::Percent(p) => {
                (font_line_fine.clamp(-LIMIT, LIMIT) * i64::from(p) + 50) / 100
            }
        }
        .clamp(-LIMIT, LIMIT)
    }
}

/// How the lines of a [`Text`](super::Text) are placed: alignment,
/// baseline, line height (embedded-graphics' `TextStyle`).
///
/// ```
/// use softedge::text::{Alignment, Baseline, LineHeight, TextStyle};
/// let s = TextStyle::with_alignment(Alignment::Center);
/// assert_eq!(s.baseline, Baseline::Alphabetic);
/// assert_eq!(s.line_height, LineHeight::Percent(100));
/// let t = TextStyle::new(Alignment::Right, Baseline::Top, LineHeight::Pixels(14));
/// assert_eq!(t.alignment, Alignment::Right);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct TextStyle {
    /// Horizontal alignment of each line.
    pub alignment: Alignment,
    /// Vertical placement of the first line.
    pub baseline: Baseline,
    /// Distance between baselines.
    pub line_height: LineHeight,
}

impl TextStyle {
    /// All three settings.
    pub const fn new(alignment: Alignment, baseline: Baseline, line_height: LineHeight) -> Self {
        Self {
            alignment,
            baseline,
            line_height,
        }
    }

    /// An alignment, the other settings by default.
    pub const fn with_alignment(alignment: Alignment) -> Self {
        Self::new(alignment, Baseline::Alphabetic, LineHeight::Percent(100))
    }

    /// A baseline, the other settings by default.
    pub const fn with_baseline(baseline: Baseline) -> Self {
        Self::new(Alignment::Left, baseline, LineHeight::Percent(100))
    }
}

#[cfg(feature = "embedded-graphics")]
mod eg {
    use super::{Alignment, Baseline, LineHeight, TextStyle};
    use embedded_graphics::text as t;

    impl From<t::Alignment> for Alignment {
        fn from(a: t::Alignment) -> Self {
            match a {
                t::Alignment::Left => Alignment::Left,
                t::Alignment::Center => Alignment::Center,
                t::Alignment::Right => Alignment::Right,
            }
        }
    }

    impl From<t::Baseline> for Baseline {
        fn from(b: t::Baseline) -> Self {
            match b {
                t::Baseline::Top => Baseline::Top,
                t::Baseline::Bottom => Baseline::Bottom,
                t::Baseline::Middle => Baseline::Middle,
                t::Baseline::Alphabetic => Baseline::Alphabetic,
            }
        }
    }

    impl From<t::LineHeight> for LineHeight {
        fn from(h: t::LineHeight) -> Self {
            match h {
                t::LineHeight::Pixels(p) => LineHeight::Pixels(p),
                t::LineHeight::Percent(p) => LineHeight::Percent(p),
            }
        }
    }

    impl From<t::TextStyle> for TextStyle {
        /// The same alignment, baseline and line height.
        ///
        /// ```
        /// use embedded_graphics::text::{Alignment, TextStyleBuilder};
        /// let eg = TextStyleBuilder::new().alignment(Alignment::Center).build();
        /// let ours: softedge::text::TextStyle = eg.into();
        /// assert_eq!(ours.alignment, softedge::text::Alignment::Center);
        /// ```
        fn from(s: t::TextStyle) -> Self {
            TextStyle::new(s.alignment.into(), s.baseline.into(), s.line_height.into())
        }
    }
}
