//! Why an image was not drawn: [`ImageError`], the image's name and the
//! fault.

use core::fmt::{self, Display, Formatter};

/// What is wrong with an image or its transform.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[non_exhaustive]
pub enum ImageFault {
    /// Width or height is zero or above [`MAX_SIDE`](super::MAX_SIDE).
    Size {
        /// Width, texels.
        width: u32,
        /// Height, texels.
        height: u32,
    },
    /// The data is shorter than the image needs (bytes).
    Truncated {
        /// Bytes needed.
        needed: u32,
        /// Bytes given.
        have: u32,
    },
    /// A scale outside `1/16 ..= 256` (in 1/65536: `4096 ..= 2^24`): the
    /// image would map to (nearly) a point, or beyond the coordinate range.
    Scale {
        /// The scale, 1/65536.
        scale: u32,
    },
    /// The transformed image reaches beyond the coordinate range
    /// (±2048 px).
    Range,
    /// A sequential source (a compressed image decoded into a row cache)
    /// was asked for a row it has passed: it would need random access.
    RandomAccess {
        /// The first row asked for.
        row: u32,
        /// The first row still held.
        held: u32,
    },
    /// A band needs more rows of a sequential source than its row cache
    /// holds.
    RowCache {
        /// Rows needed at once.
        needed: u32,
        /// Rows the cache holds.
        rows: u32,
    },
    /// The source's data is not an image softedge reads (a malformed or
    /// unsupported file).
    Unsupported,
}

/// An image not drawn: its name ([`AaImage::name`](super::AaImage::name),
/// empty when not given) and why.
///
/// ```
/// use softedge::image::{format::Rgb565, ImageFault, RawImage};
/// let short = [0u8; 10];
/// let e = RawImage::<Rgb565>::new(&short, 4, 4).unwrap_err();
/// assert_eq!(e, ImageFault::Truncated { needed: 32, have: 10 });
/// let named = softedge::image::ImageError { image: "logo", fault: e };
/// assert_eq!(named.to_string(), "image `logo`: data has 10 bytes, 32 needed");
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ImageError {
    /// The image's name.
    pub image: &'static str,
    /// What is wrong.
    pub fault: ImageFault,
}

impl Display for ImageFault {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match *self {
            Self::Size { width, height } => write!(
                f,
                "size {width}x{height} is empty or above {} texels a side",
                super::MAX_SIDE
            ),
            Self::Truncated { needed, have } => {
                write!(f, "data has {have} bytes, {needed} needed")
            }
            Self::Scale { scale } => write!(
                f,
                "scale {scale}/65536 is outside 1/16..=256 (maps to a point or beyond the range)"
            ),
            Self::Range => f.write_str("transformed image reaches beyond ±2048 px"),
            Self::RandomAccess { row, held } => write!(
                f,
                "row {row} asked after row {held}: a sequential source needs random access"
            ),
            Self::RowCache { needed, rows } => {
                write!(f, "a band needs {needed} rows, the row cache holds {rows}")
            }
            Self::Unsupported => f.write_str("unsupported or malformed image data"),
        }
    }
}

impl Display for ImageError {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        if self.image.is_empty() {
            write!(f, "image: {}", self.fault)
        } else {
            write!(f, "image `{}`: {}", self.image, self.fault)
        }
    }
}

impl core::error::Error for ImageFault {}
impl core::error::Error for ImageError {}
