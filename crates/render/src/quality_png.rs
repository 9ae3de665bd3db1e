//! PNG histogram of per-element quality values (the scaled Jacobian).
//!
//! Input: one value per element in [−1, 1] (values outside are counted in
//! the end bins), a title line, a width and a height in pixels. Output: a
//! PNG, white background:
//! - [`BINS`] bars over [−1, 1], right-closed bins `(a, b]` (the first
//!   also holds −1), so that every bin lies wholly at or below 0 or wholly
//!   above it: bars of elements ≤ 0 (inverted) red [`INVERTED_RGB`], the
//!   others blue-grey [`VALID_RGB`]; a bar's height is proportional to its
//!   count, and a non-empty bin is at least [`MIN_BAR`] pixels high, so a
//!   single inverted element among millions still shows;
//! - an x axis with ticks and labels at −1, −0.5, 0, 0.5, 1 (a thin grey
//!   line up from 0), a y axis labelled 0 and the largest count;
//! - the title on top (one line per `\n`), in the built-in font
//!   ([`crate::glyphs`]), 3 font pixels per pixel on a 1000 px wide
//!   picture, less when a line would not fit.
//!
//! Red appears exactly when some value is ≤ 0: no other element of the
//! picture is red. A non-finite value is an error naming the element.

use tiny_skia::{Color, Pixmap, Rect, Transform};

use crate::canvas::{encode, paint, SIZE_RANGE};
use crate::error::RenderError;
use crate::glyphs::{draw_text, text_width, HEIGHT};
use crate::valence::V5_RGB;

/// Number of bars over [−1, 1].
pub const BINS: usize = 40;
/// Bars of inverted elements (≤ 0).
pub const INVERTED_RGB: [u8; 3] = V5_RGB;
/// Bars of the other elements.
pub const VALID_RGB: [u8; 3] = [0x5b, 0x7f, 0xa6];
/// Least height in pixels of a non-empty bar.
pub const MIN_BAR: f32 = 3.0;
const INK: [u8; 3] = [0x22, 0x22, 0x22];
const GUIDE: [u8; 3] = [0xbb, 0xbb, 0xbb];

/// The bin of value `v` (see the module docs).
pub fn bin(v: f64) -> usize {
    let k = ((v + 1.0) / 2.0 * BINS as f64).ceil() as i64 - 1;
    k.clamp(0, BINS as i64 - 1) as usize
}

/// The count of every bin. Errors: a value is not finite.
pub fn bin_counts(values: &[f64]) -> Result<[usize; BINS], RenderError> {
    let mut counts = [0; BINS];
    for (i, &v) in values.iter().enumerate() {
        if !v.is_finite() {
            return Err(RenderError::QualityValue {
                element: i,
                value: v,
            });
        }
        counts[bin(v)] += 1;
    }
    Ok(counts)
}

/// The PNG bytes of the histogram (see the module docs). Errors: a size
/// outside [`SIZE_RANGE`], a non-finite value.
pub fn quality_histogram_png(
    values: &[f64],
    title: &str,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, RenderError> {
    encode(&draw_histogram(values, title, width, height)?)
}

/// Draws the histogram into a pixmap: the title, then the plot box
/// ([`Plot`]) with its bars and axes.
pub(crate) fn draw_histogram(
    values: &[f64],
    title: &str,
    width: u32,
    height: u32,
) -> Result<Pixmap, RenderError> {
    for side in [width, height] {
        if !SIZE_RANGE.contains(&side) {
            return Err(RenderError::Sides { width, height });
        }
    }
    let counts = bin_counts(values)?;
    let mut pix = Pixmap::new(width, height)
        .ok_or_else(|| RenderError::Allocate(format!("{width}×{height}")))?;
    pix.fill(Color::WHITE);
    let max = counts.iter().copied().max().unwrap_or(0);
    let max_label = max.to_string();
    let plot = Plot::new(&mut pix, title, &max_label, width, height)?;
    plot.bars(&mut pix, &counts, max);
    plot.axes(&mut pix, max_label, width);
    Ok(pix)
}

/// The plot box of a histogram (pixels) and its font.
struct Plot {
    /// Font scale.
    s: u32,
    /// Height of a text line.
    line: f32,
    left: f32,
    right: f32,
    top: f32,
    bottom: f32,
}

impl Plot {
    /// Draws the title and places the plot box: right of the y labels
    /// (`max_label` the widest), under the title, over the x labels.
    /// Errors: the picture is too small for it.
    fn new(
        pix: &mut Pixmap,
        title: &str,
        max_label: &str,
        width: u32,
        height: u32,
    ) -> Result<Plot, RenderError> {
        // font scale: 3 on a 1000 px wide picture, smaller when a title line
        // would not fit
        let margin = (width / 40).max(4);
        let mut s = (width / 330).max(1);
        let widest = title.lines().map(|l| text_width(l, 1)).max().unwrap_or(0);
        while s > 1 && widest * s + 2 * margin > width {
            s -= 1;
        }
        let line = (HEIGHT * s) as f32;
        let mut lines = 0;
        for (i, l) in title.lines().enumerate() {
            let y = margin as f32 + i as f32 * 1.6 * line;
            draw_text(pix, l, margin as f32, y, s, INK);
            lines += 1;
        }
        let left = (margin + text_width(max_label, s) + 6 * s) as f32;
        let right = (width - margin) as f32;
        let top = margin as f32 + (1.6 * lines as f32 + 1.0) * line;
        let bottom = height as f32 - margin as f32 - 1.8 * line;
        if right - left < BINS as f32 || bottom - top < 4.0 * MIN_BAR {
            return Err(RenderError::TooSmall { width, height });
        }
        Ok(Plot {
            s,
            line,
            left,
            right,
            top,
            bottom,
        })
    }

    /// The x of quality `v` in [−1, 1].
    fn x_of(&self, v: f64) -> f32 {
        self.left + (self.right - self.left) * ((v + 1.0) / 2.0) as f32
    }

    /// The guide at 0, then a bar per non-empty bin (inverted red).
    fn bars(&self, pix: &mut Pixmap, counts: &[usize; BINS], max: usize) {
        let (left, right, top, bottom) = (self.left, self.right, self.top, self.bottom);
        // the guide at 0, under the bars
        fill(pix, self.x_of(0.0) - 0.5, top, 1.0, bottom - top, GUIDE);
        let bin_w = (right - left) / BINS as f32;
        let gap = (0.12 * bin_w).max(1.0);
        for (k, &n) in counts.iter().enumerate() {
            if n == 0 {
                continue;
            }
            let h = ((bottom - top) * n as f32 / max as f32).max(MIN_BAR);
            let rgb = if k < BINS / 2 {
                INVERTED_RGB
            } else {
                VALID_RGB
            };
            let x = left + k as f32 * bin_w + gap / 2.0;
            fill(pix, x, bottom - h, bin_w - gap, h, rgb);
        }
    }

    /// The axes (x along the bottom, y on the left), their ticks and
    /// labels (`max_label` at the top of y).
    fn axes(&self, pix: &mut Pixmap, max_label: String, width: u32) {
        let (s, line) = (self.s, self.line);
        let (left, right, top, bottom) = (self.left, self.right, self.top, self.bottom);
        let t = s as f32;
        fill(pix, left - t, bottom, right - left + t, t, INK);
        fill(pix, left - t, top, t, bottom - top + t, INK);
        for (v, label) in [
            (-1.0, "-1"),
            (-0.5, "-0.5"),
            (0.0, "0"),
            (0.5, "0.5"),
            (1.0, "1"),
        ] {
            let x = self.x_of(v);
            let tick = if v == 0.0 || v == 1.0 || v == -1.0 {
                3.0 * t
            } else {
                2.0 * t
            };
            fill(pix, x - t / 2.0, bottom, t, tick, INK);
            let w = text_width(label, s) as f32;
            let lx = (x - w / 2.0).clamp(0.0, width as f32 - w);
            draw_text(pix, label, lx, bottom + tick + t, s, INK);
        }
        for (y, label) in [(bottom, "0".to_string()), (top, max_label)] {
            let w = text_width(&label, s) as f32;
            fill(pix, left - 3.0 * t, y - t / 2.0, 2.0 * t, t, INK);
            draw_text(pix, &label, left - 5.0 * t - w, y - line / 2.0, s, INK);
        }
    }
}

/// A solid rectangle (none when it is empty).
fn fill(pix: &mut Pixmap, x: f32, y: f32, w: f32, h: f32, rgb: [u8; 3]) {
    if let Some(r) = Rect::from_xywh(x, y, w, h) {
        pix.fill_rect(r, &paint(rgb, 255), Transform::identity(), None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_png::{has_colour, temp_path};

    #[test]
    fn bins_are_right_closed_and_split_at_zero() {
        assert_eq!(bin(-1.0), 0);
        assert_eq!(bin(-2.0), 0);
        assert_eq!(bin(0.0), BINS / 2 - 1);
        assert_eq!(bin(1e-12), BINS / 2);
        assert_eq!(bin(1.0), BINS - 1);
        assert_eq!(bin(1.5), BINS - 1);
        assert!(matches!(
            bin_counts(&[0.5, f64::NAN]),
            Err(RenderError::QualityValue { element: 1, .. })
        ));
    }

    #[test]
    fn red_exactly_when_an_element_is_inverted() {
        let mut values = vec![1.0; 5000];
        let pix = draw_histogram(&values, "5000 quads, 0 inverted", 800, 500).unwrap();
        assert!(!has_colour(&pix, INVERTED_RGB));
        assert!(has_colour(&pix, VALID_RGB));
        values[17] = 0.0;
        let pix = draw_histogram(&values, "5000 quads, 1 inverted", 800, 500).unwrap();
        assert!(has_colour(&pix, INVERTED_RGB));
        assert_eq!((pix.width(), pix.height()), (800, 500));
        if std::env::var_os("DUALEX_KEEP_PICTURES").is_some() {
            let p = temp_path("histogram.png");
            crate::canvas::write_png(&pix, &p).unwrap();
            eprintln!("kept {}", p.display());
        }
    }

    #[test]
    fn bad_sizes_and_values_are_refused() {
        assert!(quality_histogram_png(&[1.0], "x", 15, 100).is_err());
        assert!(quality_histogram_png(&[1.0], "x", 100, 20).is_err());
        assert!(quality_histogram_png(&[f64::INFINITY], "x", 400, 300).is_err());
        assert!(quality_histogram_png(&[], "empty", 400, 300).is_ok());
    }
}
