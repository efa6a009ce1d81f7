//! Path errors are `core::error::Error`s (their `Display` is beside them).

use core::error::Error;

impl Error for crate::path::StrokeError {}

impl Error for crate::path::svg::SvgError {}
