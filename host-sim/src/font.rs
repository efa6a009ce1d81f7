//! A 3x5 bitmap font for panel labels, drawn as filled squares.
//!
//! Each glyph is five rows of three bits (bit 2 is the left column). Letters
//! are upper case only (lower case is drawn as upper case); a character the
//! font lacks is drawn as `?`. At scale `s` a glyph is `3s x 5s` pixels and
//! the advance is `4s`.

use crate::image::Image8;

/// Glyph width in font pixels.
pub const GLYPH_W: u32 = 3;
/// Glyph height in font pixels.
pub const GLYPH_H: u32 = 5;
/// Horizontal advance in font pixels (glyph plus one column of space).
pub const ADVANCE: u32 = GLYPH_W + 1;

/// The five rows of a glyph.
fn glyph(c: char) -> [u8; 5] {
    match c.to_ascii_uppercase() {
        'A' => [0b010, 0b101, 0b111, 0b101, 0b101],
        'B' => [0b110, 0b101, 0b110, 0b101, 0b110],
        'C' => [0b011, 0b100, 0b100, 0b100, 0b011],
        'D' => [0b110, 0b101, 0b101, 0b101, 0b110],
        'E' => [0b111, 0b100, 0b110, 0b100, 0b111],
        'F' => [0b111, 0b100, 0b110, 0b100, 0b100],
        'G' => [0b011, 0b100, 0b101, 0b101, 0b011],
        'H' => [0b101, 0b101, 0b111, 0b101, 0b101],
        'I' => [0b111, 0b010, 0b010, 0b010, 0b111],
        'J' => [0b001, 0b001, 0b001, 0b101, 0b010],
        'K' => [0b101, 0b101, 0b110, 0b101, 0b101],
        'L' => [0b100, 0b100, 0b100, 0b100, 0b111],
        'M' => [0b101, 0b111, 0b111, 0b101, 0b101],
        'N' => [0b110, 0b101, 0b101, 0b101, 0b101],
        'O' => [0b010, 0b101, 0b101, 0b101, 0b010],
        'P' => [0b110, 0b101, 0b110, 0b100, 0b100],
        'Q' => [0b010, 0b101, 0b101, 0b110, 0b011],
        'R' => [0b110, 0b101, 0b110, 0b101, 0b101],
        'S' => [0b011, 0b100, 0b010, 0b001, 0b110],
        'T' => [0b111, 0b010, 0b010, 0b010, 0b010],
        'U' => [0b101, 0b101, 0b101, 0b101, 0b111],
        'V' => [0b101, 0b101, 0b101, 0b101, 0b010],
        'W' => [0b101, 0b101, 0b111, 0b111, 0b101],
        'X' => [0b101, 0b101, 0b010, 0b101, 0b101],
        'Y' => [0b101, 0b101, 0b010, 0b010, 0b010],
        'Z' => [0b111, 0b001, 0b010, 0b100, 0b111],
        '0' => [0b111, 0b101, 0b101, 0b101, 0b111],
        '1' => [0b010, 0b110, 0b010, 0b010, 0b111],
        '2' => [0b110, 0b001, 0b010, 0b100, 0b111],
        '3' => [0b110, 0b001, 0b010, 0b001, 0b110],
        '4' => [0b101, 0b101, 0b111, 0b001, 0b001],
        '5' => [0b111, 0b100, 0b110, 0b001, 0b110],
        '6' => [0b011, 0b100, 0b111, 0b101, 0b111],
        '7' => [0b111, 0b001, 0b010, 0b010, 0b010],
        '8' => [0b111, 0b101, 0b111, 0b101, 0b111],
        '9' => [0b111, 0b101, 0b111, 0b001, 0b110],
        ' ' => [0; 5],
        '-' => [0b000, 0b000, 0b111, 0b000, 0b000],
        '+' => [0b000, 0b010, 0b111, 0b010, 0b000],
        '=' => [0b000, 0b111, 0b000, 0b111, 0b000],
        '.' => [0b000, 0b000, 0b000, 0b000, 0b010],
        ',' => [0b000, 0b000, 0b000, 0b010, 0b100],
        ':' => [0b000, 0b010, 0b000, 0b010, 0b000],
        '/' => [0b001, 0b001, 0b010, 0b100, 0b100],
        '(' => [0b001, 0b010, 0b010, 0b010, 0b001],
        ')' => [0b100, 0b010, 0b010, 0b010, 0b100],
        '|' => [0b010, 0b010, 0b010, 0b010, 0b010],
        '%' => [0b101, 0b001, 0b010, 0b100, 0b101],
        '*' | '×' => [0b000, 0b101, 0b010, 0b101, 0b000],
        _ => [0b110, 0b001, 0b010, 0b000, 0b010],
    }
}

/// Width in image pixels of `text` at `scale` (no trailing space).
pub fn text_width(text: &str, scale: u32) -> u32 {
    let n = text.chars().count() as u32;
    (n * ADVANCE).saturating_sub(1) * scale
}

/// Draws `text` with its top-left corner at `(x, y)`, each font pixel a
/// `scale x scale` square of `color` (its length is the image's channel
/// count). Clipped to the image.
pub fn draw_text(img: &mut Image8, x: i64, y: i64, scale: u32, text: &str, color: &[u8]) {
    let s = i64::from(scale);
    for (k, c) in text.chars().enumerate() {
        let gx = x + k as i64 * i64::from(ADVANCE) * s;
        for (row, bits) in glyph(c).iter().enumerate() {
            for col in 0..GLYPH_W {
                if bits >> (GLYPH_W - 1 - col) & 1 == 1 {
                    img.fill_rect(
                        gx + i64::from(col) * s,
                        y + row as i64 * s,
                        scale,
                        scale,
                        color,
                    );
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::image::Channels;

    #[test]
    fn letters_are_drawn_where_their_bits_are() {
        let mut img = Image8::new(8, 6, Channels::Gray, &[0]);
        draw_text(&mut img, 0, 0, 1, "T1", &[255]);
        // T: top row full, stem in the middle column.
        assert_eq!(img.pixel(0, 0), &[255]);
        assert_eq!(img.pixel(2, 0), &[255]);
        assert_eq!(img.pixel(0, 1), &[0]);
        assert_eq!(img.pixel(1, 4), &[255]);
        // The gap column, then '1' starting at x = 4.
        assert_eq!(img.pixel(3, 0), &[0]);
        assert_eq!(img.pixel(5, 0), &[255]);
        assert_eq!(text_width("T1", 2), 14);
    }

    #[test]
    fn every_printable_ascii_has_a_glyph_or_the_fallback() {
        for c in ' '..='~' {
            assert!(glyph(c).iter().all(|r| *r < 8));
        }
    }
}
