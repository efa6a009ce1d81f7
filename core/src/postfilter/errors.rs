//! How post-filter errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::FilterError;
use crate::band::MAX_WIDTH;

impl Display for FilterError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadSize => write!(f, "frame size is zero or wider than {MAX_WIDTH} px"),
            Self::InputTooShort => f.write_str("filter input holds fewer pixels than its rows"),
            Self::ScratchTooSmall => f.write_str("filter scratch is shorter than scratch_len"),
            Self::OutputTooSmall => f.write_str("filter output is shorter than its row or frame"),
        }
    }
}

impl Error for FilterError {}
