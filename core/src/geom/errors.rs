//! How a coordinate error prints.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{CoordError, COORD_LIMIT_PX};

impl Display for CoordError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "vertex ({}, {}) in 1/16 px is outside ±{COORD_LIMIT_PX} px",
            self.point.x, self.point.y
        )
    }
}

impl Error for CoordError {}
