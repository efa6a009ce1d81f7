//! How tone errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::ToneError;

impl Display for ToneError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Contrast => "contrast K is below 2",
            Self::Gradations => "number of gradations m is zero",
            Self::GaussTooLong => {
                "gaussian-logarithm table does not reach zero: gradation step too fine for the contrast"
            }
            Self::PlanInput => "planning input out of range (K <= 1, δ <= 0, γ <= 1 or not finite)",
        })
    }
}

impl Error for ToneError {}
