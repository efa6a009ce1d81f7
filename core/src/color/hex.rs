//! `#rrggbb` hex colours: six hexadecimal digits after a `#`, two per
//! channel, upper or lower case, read as 8-bit sRGB codes.

/// Why a hex colour was not read.
///
/// ```
/// use softedge::color::{parse_hex, ColorError};
/// assert_eq!(parse_hex("808080"), Err(ColorError::MissingHash));
/// assert_eq!(parse_hex("#fff"), Err(ColorError::Length { len: 4 }));
/// assert_eq!(parse_hex("#12g456"), Err(ColorError::Digit { index: 3, byte: b'g' }));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub enum ColorError {
    /// The text does not start with `#`.
    MissingHash,
    /// The text is not 7 bytes long (`#` and six digits).
    Length {
        /// Its length in bytes.
        len: usize,
    },
    /// A byte after the `#` is not a hexadecimal digit.
    Digit {
        /// Its offset in the text (1..=6).
        index: usize,
        /// The byte.
        byte: u8,
    },
}

/// The value of one hexadecimal digit.
const fn digit(b: u8) -> Option<u8> {
    match b {
        b'0'..=b'9' => Some(b - b'0'),
        b'a'..=b'f' => Some(b - b'a' + 10),
        b'A'..=b'F' => Some(b - b'A' + 10),
        _ => None,
    }
}

/// The 8-bit codes `[r, g, b]` of `#rrggbb` (case does not matter).
///
/// ```
/// use softedge::color::parse_hex;
/// assert_eq!(parse_hex("#ff8000"), Ok([255, 128, 0]));
/// assert_eq!(parse_hex("#C0FFEE"), Ok([0xc0, 0xff, 0xee]));
/// ```
pub const fn parse_hex(text: &str) -> Result<[u8; 3], ColorError> {
    let bytes = text.as_bytes();
    let [first, rest @ ..] = bytes else {
        return Err(ColorError::MissingHash);
    };
    if *first != b'#' {
        return Err(ColorError::MissingHash);
    }
    let [r1, r0, g1, g0, b1, b0] = rest else {
        return Err(ColorError::Length { len: bytes.len() });
    };
    let digits = [*r1, *r0, *g1, *g0, *b1, *b0];
    let mut values = [0u8; 6];
    let mut k = 0;
    while k < digits.len() {
        values[k] = match digit(digits[k]) {
            Some(d) => d,
            None => {
                return Err(ColorError::Digit {
                    index: k + 1,
                    byte: digits[k],
                })
            }
        };
        k += 1;
    }
    let [r1, r0, g1, g0, b1, b0] = values;
    Ok([r1 << 4 | r0, g1 << 4 | g0, b1 << 4 | b0])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_digit_of_both_cases_is_read() {
        assert_eq!(parse_hex("#012345"), Ok([0x01, 0x23, 0x45]));
        assert_eq!(parse_hex("#6789ab"), Ok([0x67, 0x89, 0xab]));
        assert_eq!(parse_hex("#CDEFcd"), Ok([0xcd, 0xef, 0xcd]));
    }

    #[test]
    fn malformed_text_is_an_error_not_a_panic() {
        assert_eq!(parse_hex(""), Err(ColorError::MissingHash));
        assert_eq!(parse_hex("#"), Err(ColorError::Length { len: 1 }));
        assert_eq!(parse_hex("#0000000"), Err(ColorError::Length { len: 8 }));
        assert_eq!(
            parse_hex("#00000 "),
            Err(ColorError::Digit {
                index: 6,
                byte: b' '
            })
        );
        // 'é' is two bytes: "#é0000" is 7 bytes, the first of them not a digit.
        assert_eq!(
            parse_hex("#\u{e9}0000"),
            Err(ColorError::Digit {
                index: 1,
                byte: 0xc3
            })
        );
    }
}
