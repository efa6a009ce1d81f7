//! How a coordinate error prints.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{CoordError, COORD_LIMIT_PX};

impl Display for CoordError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "vertex ({}, {}) px is outside ±{COORD_LIMIT_PX} px",
            crate::error::Px {
                v: i64::from(self.point.x),
                bits: super::SUB_BITS
            },
            crate::error::Px {
                v: i64::from(self.point.y),
                bits: super::SUB_BITS
            }
        )
    }
}

impl Error for CoordError {}
