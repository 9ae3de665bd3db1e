//! The legend of the map picture: a small box in the emptiest corner.
//!
//! Input: the picture already drawn, the number of reverted triangles and
//! the marks. Output: one row per thing the picture shows, a swatch and a
//! label in the built-in font ([`crate::glyphs`]):
//! - a purple square, `reverted: N` (N triangles), when some are reverted;
//! - a dot per singularity class, `+1/4: N`, `-1/4: N`, `other: N`
//!   (N vertices), in the colour of the marks.
//!
//! The box (white, 90 % opaque, grey border) goes into the corner whose
//! area holds the fewest non-white pixels, so it hides as little of the
//! map as it can. The font scale grows with the picture (1 below 600 px).
//! No rows, no box.

use tiny_skia::{FillRule, PathBuilder, Pixmap, Rect, Stroke, Transform};

use super::{MapMark, PURPLE};
use crate::canvas::paint;
use crate::glyphs::{draw_text, text_width, HEIGHT};
use crate::valence::ValenceClass;

/// Text colour of the legend.
pub const INK: [u8; 3] = [0x22, 0x22, 0x22];
/// Border colour of the legend box.
pub const BORDER: [u8; 3] = [0x88, 0x88, 0x88];

/// What a legend row's swatch looks like.
#[derive(Clone, Copy)]
enum Swatch {
    Square([u8; 3]),
    Dot([u8; 3]),
}

/// The rows of the legend (see the module docs).
fn rows(reverted: usize, marks: &[MapMark]) -> Vec<(Swatch, String)> {
    let mut out = Vec::new();
    if reverted > 0 {
        out.push((Swatch::Square(PURPLE), format!("reverted: {reverted}")));
    }
    let classes = [
        (ValenceClass::V3, "+1/4"),
        (ValenceClass::V5, "-1/4"),
        (ValenceClass::Other, "other"),
    ];
    for (class, label) in classes {
        let n = marks.iter().filter(|m| m.class == class).count();
        if let (true, Some(rgb)) = (n > 0, class.rgb()) {
            out.push((Swatch::Dot(rgb), format!("{label}: {n}")));
        }
    }
    out
}

/// The font scale for a picture of `size` pixels.
pub fn scale(size: u32) -> u32 {
    (size / 600).max(1)
}

/// Draws the legend; returns its box, `None` when there is nothing to say.
pub fn draw_legend(pix: &mut Pixmap, reverted: usize, marks: &[MapMark]) -> Option<Rect> {
    let rows = rows(reverted, marks);
    let s = scale(pix.width());
    let pad = 4 * s;
    let line = (HEIGHT + 4) * s;
    let swatch = HEIGHT * s;
    let text = rows.iter().map(|r| text_width(&r.1, s)).max()?;
    let w = pad + swatch + 3 * s + text + pad;
    let h = pad + rows.len() as u32 * line - 4 * s + pad;
    let margin = 2 * s;
    let (x, y) = emptiest_corner(pix, w, h, margin)?;
    let rect = Rect::from_xywh(x as f32, y as f32, w as f32, h as f32)?;
    let id = Transform::identity();
    pix.fill_rect(rect, &paint([255; 3], 230), id, None);
    let border = PathBuilder::from_rect(rect);
    let stroke = Stroke {
        width: 1.0,
        ..Stroke::default()
    };
    pix.stroke_path(&border, &paint(BORDER, 255), &stroke, id, None);
    for (i, (sw, label)) in rows.iter().enumerate() {
        let top = (y + pad + i as u32 * line) as f32;
        let left = (x + pad) as f32;
        let side = swatch as f32;
        match *sw {
            Swatch::Square(rgb) => {
                if let Some(r) = Rect::from_xywh(left, top, side, side) {
                    pix.fill_rect(r, &paint(rgb, 255), id, None);
                }
            }
            Swatch::Dot(rgb) => {
                let c = side / 2.0;
                if let Some(d) = PathBuilder::from_circle(left + c, top + c, c) {
                    pix.fill_path(&d, &paint(rgb, 255), FillRule::Winding, id, None);
                }
            }
        }
        let tx = left + side + (3 * s) as f32;
        draw_text(pix, label, tx, top, s, INK);
    }
    Some(rect)
}

/// The top-left corner of a `w × h` box in the picture corner that covers
/// the fewest non-white pixels (top right first on ties); `None` when the
/// box does not fit.
fn emptiest_corner(pix: &Pixmap, w: u32, h: u32, margin: u32) -> Option<(u32, u32)> {
    let (pw, ph) = (pix.width(), pix.height());
    if w + 2 * margin > pw || h + 2 * margin > ph {
        return None;
    }
    let (right, bottom) = (pw - w - margin, ph - h - margin);
    let corners = [
        (right, margin),
        (margin, margin),
        (right, bottom),
        (margin, bottom),
    ];
    let busy = |&(x0, y0): &(u32, u32)| {
        let mut n = 0usize;
        for y in y0..y0 + h {
            let row = &pix.pixels()[(y * pw + x0) as usize..(y * pw + x0 + w) as usize];
            n += row
                .iter()
                .filter(|p| p.red() < 250 || p.green() < 250 || p.blue() < 250)
                .count();
        }
        n
    };
    corners.iter().min_by_key(|c| busy(c)).copied()
}
