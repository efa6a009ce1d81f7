//! How colour errors print.

use core::error::Error;
use core::fmt::{self, Display, Formatter};

use super::ColorError;

impl Display for ColorError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match *self {
            Self::MissingHash => f.write_str("hex colour must start with `#` (`#rrggbb`)"),
            Self::Length { len } => {
                write!(f, "hex colour `#rrggbb` has 7 characters, not {len}")
            }
            Self::Digit { index, byte } if byte.is_ascii_graphic() => write!(
                f,
                "`{}` at byte {index} is not a hex digit",
                char::from(byte)
            ),
            Self::Digit { index, byte } => {
                write!(f, "byte {index} (0x{byte:02x}) is not a hex digit")
            }
        }
    }
}

impl Error for ColorError {}
