//! How render errors print and log.
use core::error::Error;
use core::fmt::{self, Debug, Display, Formatter};

use super::RenderError;

/// The display's own error is printed with `Debug`: embedded-graphics
/// drivers rarely implement `Display`.
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl<T: Debug, E: Display> Display for RenderError<T, E> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::Band(e) => write!(f, "band buffer: {e}"),
            Self::Size { frame, display } => write!(
                f,
                "frame {}x{} is larger than the display, {}x{}",
                frame.0, frame.1, display.0, display.1
            ),
            Self::Draw { band_y0, error } => {
                write!(f, "drawing failed in the band at row {band_y0}: {error}")
            }
            Self::Target(e) => write!(f, "display error: {e:?}"),
            Self::Buffer { needed, got } => write!(
                f,
                "the display's band buffer holds {got} pixels, a band needs {needed}"
            ),
        }
    }
}

/// `source` is the band buffer's or the drawing closure's error; a
/// display error is not one (its type need not implement `Error`).
#[cfg_attr(docsrs, doc(cfg(feature = "embedded-graphics")))]
impl<T: Debug, E: Error + 'static> Error for RenderError<T, E> {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Band(e) => Some(e),
            Self::Draw { error, .. } => Some(error),
            Self::Size { .. } | Self::Target(_) | Self::Buffer { .. } => None,
        }
    }
}

#[cfg(feature = "defmt")]
#[cfg_attr(
    docsrs,
    doc(cfg(all(feature = "embedded-graphics", feature = "defmt")))
)]
impl<T: defmt::Format, E: defmt::Format> defmt::Format for RenderError<T, E> {
    fn format(&self, f: defmt::Formatter<'_>) {
        match self {
            Self::Band(e) => defmt::write!(f, "Band({})", e),
            Self::Size { frame, display } => {
                defmt::write!(
                    f,
                    "Size({}x{} > {}x{})",
                    frame.0,
                    frame.1,
                    display.0,
                    display.1
                )
            }
            Self::Draw { band_y0, error } => {
                defmt::write!(f, "Draw(row {}: {})", band_y0, error)
            }
            Self::Target(e) => defmt::write!(f, "Target({})", e),
            Self::Buffer { needed, got } => {
                defmt::write!(f, "Buffer({} < {})", got, needed)
            }
        }
    }
}
