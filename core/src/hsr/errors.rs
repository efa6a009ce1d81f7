//! How hidden-surface errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::HsrError;

impl Display for HsrError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::Draw(e) => e.fmt(f),
            Self::BandMismatch => {
                f.write_str("depth buffer holds another band than the band buffer")
            }
            Self::Capacity { needed } => {
                write!(f, "scene needs storage for at least {needed} items")
            }
        }
    }
}

impl Error for HsrError {
    fn source(&self) -> Option<&(dyn Error + 'static)> {
        match self {
            Self::Draw(e) => Some(e),
            _ => None,
        }
    }
}
