//! How gradient errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{GradientError, MAX_STOPS};
use crate::geom::COORD_LIMIT_PX;

impl Display for GradientError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::NoStops => f.write_str("gradient has no stops"),
            Self::TooManyStops { given } => {
                write!(f, "gradient has {given} stops, at most {MAX_STOPS}")
            }
            Self::Unsorted { index } => {
                write!(f, "gradient stop {index} lies before the stop ahead of it")
            }
            Self::Coord(p) => write!(
                f,
                "point ({}, {}) in 1/1024 px is outside ±{COORD_LIMIT_PX} px",
                p.x, p.y
            ),
            Self::Radius { radius } => write!(f, "gradient radius {radius} is negative"),
        }
    }
}

impl Error for GradientError {}
