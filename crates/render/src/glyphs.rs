//! A tiny built-in 5×7 bitmap font, for labels in the PNG pictures
//! (tiny-skia draws no text).
//!
//! Input: a string, a pixel scale, a position. Output: filled squares, one
//! per lit font pixel, not anti-aliased. Covered: digits, `+ - / : ( )`,
//! `. , = %`, space and the lower-case letters; any other character
//! is drawn as a hollow box, so a missing glyph shows instead of vanishing.
//!
//! Each glyph is 7 rows of 5 bits, the high bit on the left; a character
//! advances by 6 font pixels.

use tiny_skia::{Pixmap, Rect, Transform};

use crate::canvas::paint;

/// Width of a glyph cell in font pixels, spacing included.
pub const ADVANCE: u32 = 6;
/// Height of a glyph in font pixels.
pub const HEIGHT: u32 = 7;

const BOX: [u8; 7] = [
    0b11111, 0b10001, 0b10001, 0b10001, 0b10001, 0b10001, 0b11111,
];

/// The rows of `c` (see the module docs).
fn glyph(c: char) -> [u8; 7] {
    match c {
        '0' => [14, 17, 19, 21, 25, 17, 14],
        '1' => [4, 12, 4, 4, 4, 4, 14],
        '2' => [14, 17, 1, 2, 4, 8, 31],
        '3' => [30, 1, 1, 14, 1, 1, 30],
        '4' => [2, 6, 10, 18, 31, 2, 2],
        '5' => [31, 16, 30, 1, 1, 17, 14],
        '6' => [6, 8, 16, 30, 17, 17, 14],
        '7' => [31, 1, 2, 4, 8, 8, 8],
        '8' => [14, 17, 17, 14, 17, 17, 14],
        '9' => [14, 17, 17, 15, 1, 2, 12],
        '+' => [0, 4, 4, 31, 4, 4, 0],
        '-' => [0, 0, 0, 31, 0, 0, 0],
        '/' => [1, 1, 2, 4, 8, 16, 16],
        ':' => [0, 12, 12, 0, 12, 12, 0],
        '(' => [2, 4, 8, 8, 8, 4, 2],
        ')' => [8, 4, 2, 2, 2, 4, 8],
        '.' => [0, 0, 0, 0, 0, 12, 12],
        ',' => [0, 0, 0, 0, 12, 4, 8],
        '=' => [0, 0, 31, 0, 31, 0, 0],
        '%' => [24, 25, 2, 4, 8, 19, 3],
        ' ' => [0; 7],
        'a' => [0, 0, 14, 1, 15, 17, 15],
        'b' => [16, 16, 22, 25, 17, 17, 30],
        'c' => [0, 0, 14, 16, 16, 17, 14],
        'd' => [1, 1, 13, 19, 17, 17, 15],
        'e' => [0, 0, 14, 17, 31, 16, 14],
        'f' => [6, 9, 8, 28, 8, 8, 8],
        'g' => [0, 0, 15, 16, 19, 17, 15],
        'h' => [16, 16, 22, 25, 17, 17, 17],
        'i' => [4, 0, 12, 4, 4, 4, 14],
        'j' => [2, 0, 6, 2, 2, 18, 12],
        'k' => [16, 16, 18, 20, 24, 20, 18],
        'l' => [12, 4, 4, 4, 4, 4, 14],
        'm' => [0, 0, 26, 21, 21, 17, 17],
        'n' => [0, 0, 22, 25, 17, 17, 17],
        'o' => [0, 0, 14, 17, 17, 17, 14],
        'p' => [0, 0, 30, 17, 30, 16, 16],
        'q' => [0, 0, 15, 17, 17, 15, 1],
        'r' => [0, 0, 22, 25, 16, 16, 16],
        's' => [0, 0, 15, 16, 14, 1, 30],
        't' => [8, 8, 28, 8, 8, 9, 6],
        'u' => [0, 0, 17, 17, 17, 19, 13],
        'v' => [0, 0, 17, 17, 17, 10, 4],
        'w' => [0, 0, 17, 17, 21, 21, 10],
        'x' => [0, 0, 17, 10, 4, 10, 17],
        'y' => [0, 0, 17, 17, 15, 1, 14],
        'z' => [0, 0, 31, 2, 4, 8, 31],
        _ => BOX,
    }
}

/// Width in pixels of `text` at `scale`, without the trailing gap.
pub fn text_width(text: &str, scale: u32) -> u32 {
    let n = text.chars().count() as u32;
    (n * ADVANCE).saturating_sub(1) * scale
}

/// Draws `text` with its top-left corner at `(x, y)`, each font pixel a
/// `scale × scale` square of colour `rgb`.
pub fn draw_text(pix: &mut Pixmap, text: &str, x: f32, y: f32, scale: u32, rgb: [u8; 3]) {
    let mut p = paint(rgb, 255);
    p.anti_alias = false;
    let s = scale as f32;
    for (i, c) in text.chars().enumerate() {
        let x0 = x + (i as u32 * ADVANCE) as f32 * s;
        for (row, bits) in glyph(c).iter().enumerate() {
            for col in 0..5u32 {
                if bits & (1 << (4 - col)) == 0 {
                    continue;
                }
                let px = x0 + col as f32 * s;
                let py = y + row as f32 * s;
                if let Some(r) = Rect::from_xywh(px, py, s, s) {
                    pix.fill_rect(r, &p, Transform::identity(), None);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::canvas::white;
    use crate::test_png::has_colour;

    #[test]
    fn every_legend_character_has_its_own_glyph() {
        for c in "0123456789+-/:().,=% abcdefghijklmnopqrstuvwxyz".chars() {
            assert!(c == ' ' || glyph(c) != BOX, "{c:?} has no glyph");
            assert!(glyph(c).iter().all(|&r| r < 32), "{c:?} is wider than 5");
        }
        assert_eq!(glyph('?'), BOX);
    }

    #[test]
    fn text_is_drawn_in_its_box_only() {
        let mut pix = white(32).unwrap();
        draw_text(&mut pix, "1", 2.0, 3.0, 2, [0, 0, 0]);
        assert!(has_colour(&pix, [0, 0, 0]));
        assert_eq!(text_width("12", 2), 22);
        for (i, p) in pix.pixels().iter().enumerate() {
            let (x, y) = (i as u32 % 32, i as u32 / 32);
            if p.red() == 0 {
                assert!((2..12).contains(&x) && (3..17).contains(&y), "({x}, {y})");
            }
        }
    }
}
