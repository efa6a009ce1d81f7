//! How gradient errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::{GradientError, OpacityError, MAX_STOPS};
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
                "gradient point ({}, {}) px is outside ±{COORD_LIMIT_PX} px",
                crate::error::Px::fine(p.x),
                crate::error::Px::fine(p.y)
            ),
            Self::Radius { radius } => write!(f, "gradient radius {radius} is negative"),
        }
    }
}

impl Error for GradientError {}

impl Display for OpacityError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match self {
            Self::ZeroDenominator { num } => {
                write!(f, "opacity {num}/0: the denominator is zero")
            }
        }
    }
}

impl Error for OpacityError {}
