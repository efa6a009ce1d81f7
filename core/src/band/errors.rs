//! How band errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{BandError, MAX_WIDTH};
use crate::geom::COORD_LIMIT_PX;

impl Display for BandError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadBand => write!(
                f,
                "band is empty, wider than {MAX_WIDTH} px or starts beyond ±{COORD_LIMIT_PX} px"
            ),
            Self::AccTooSmall => f.write_str("accumulation buffer is shorter than acc_len"),
            Self::CoverTooSmall => f.write_str("cover buffer is shorter than cover_len"),
            Self::DepthTooSmall => f.write_str("depth buffer is shorter than DepthBuffer::len"),
        }
    }
}

impl Error for BandError {}
