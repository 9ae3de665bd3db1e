//! Drawing surface shared by the PNG renderers: a white [`Pixmap`], the
//! fit of a 2D bounding box into it, and the atomic PNG write.
//!
//! Invariant: [`write_png`] writes `PATH.tmp-PID` beside `PATH` and renames
//! it over `PATH`; on any error the temporary file is removed and `PATH`
//! is untouched.

use std::path::Path;

use crate::error::RenderError;

use tiny_skia::{Color, Paint, Pixmap};

/// Smallest and largest accepted picture size in pixels.
pub const SIZE_RANGE: std::ops::RangeInclusive<u32> = 16..=16384;

/// A white square pixmap of `size × size` pixels.
pub fn white(size: u32) -> Result<Pixmap, RenderError> {
    if !SIZE_RANGE.contains(&size) {
        return Err(RenderError::Size(size));
    }
    let mut pix =
        Pixmap::new(size, size).ok_or_else(|| RenderError::Allocate(format!("{size}²")))?;
    pix.fill(Color::WHITE);
    Ok(pix)
}

/// An anti-aliased solid paint.
pub fn paint(rgb: [u8; 3], alpha: u8) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(rgb[0], rgb[1], rgb[2], alpha);
    p.anti_alias = true;
    p
}

/// Maps a 2D box `[lo, hi]` into a `size`² picture with a margin, keeping
/// the aspect ratio, `y` up.
#[derive(Clone, Copy, Debug)]
pub struct Fit {
    lo: [f64; 2],
    scale: f64,
    offset: [f64; 2],
    size: f64,
}

impl Fit {
    /// The fit of the box `lo..hi` (finite) into `size` pixels.
    pub fn new(lo: [f64; 2], hi: [f64; 2], size: u32) -> Fit {
        let size = f64::from(size);
        let margin = (0.04 * size).max(4.0);
        let ext = [(hi[0] - lo[0]).max(0.0), (hi[1] - lo[1]).max(0.0)];
        let big = ext[0].max(ext[1]);
        let scale = if big > 0.0 {
            (size - 2.0 * margin) / big
        } else {
            1.0
        };
        let offset = [0.5 * (size - scale * ext[0]), 0.5 * (size - scale * ext[1])];
        Fit {
            lo,
            scale,
            offset,
            size,
        }
    }

    /// Pixels per unit.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The pixel position of `p`.
    pub fn px(&self, p: [f64; 2]) -> (f32, f32) {
        let x = self.offset[0] + self.scale * (p[0] - self.lo[0]);
        let y = self.size - (self.offset[1] + self.scale * (p[1] - self.lo[1]));
        (x as f32, y as f32)
    }
}

/// Bounding box of points; `None` when there is none.
pub fn bbox(points: impl Iterator<Item = [f64; 2]>) -> Option<([f64; 2], [f64; 2])> {
    points.fold(None, |acc, p| {
        let (lo, hi) = acc.unwrap_or((p, p));
        Some((
            [lo[0].min(p[0]), lo[1].min(p[1])],
            [hi[0].max(p[0]), hi[1].max(p[1])],
        ))
    })
}

/// Encodes `pix` as PNG.
pub fn encode(pix: &Pixmap) -> Result<Vec<u8>, RenderError> {
    pix.encode_png().map_err(|e| RenderError::Encode {
        file: None,
        reason: e.to_string(),
    })
}

/// Encodes `pix` as PNG and writes it to `path` through a temporary file
/// and a rename.
pub fn write_png(pix: &Pixmap, path: &Path) -> Result<(), RenderError> {
    let data = pix.encode_png().map_err(|e| RenderError::Encode {
        file: Some(path.to_path_buf()),
        reason: e.to_string(),
    })?;
    let name = path
        .file_name()
        .ok_or_else(|| RenderError::NotAFileName(path.to_path_buf()))?;
    let mut tmp_name = name.to_os_string();
    tmp_name.push(format!(".tmp-{}", std::process::id()));
    let tmp = path.with_file_name(tmp_name);
    let result = std::fs::write(&tmp, &data).and_then(|()| std::fs::rename(&tmp, path));
    result.map_err(|error| {
        let _ = std::fs::remove_file(&tmp);
        RenderError::Write {
            file: path.to_path_buf(),
            error,
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_keeps_aspect_and_centres() {
        let f = Fit::new([0.0, 0.0], [2.0, 1.0], 100);
        let (x0, y0) = f.px([0.0, 0.0]);
        let (x1, y1) = f.px([2.0, 1.0]);
        assert_eq!((x0, x1), (4.0, 96.0));
        // height 46 px centred: y from 73 down to 27 (y up)
        assert_eq!((y0, y1), (73.0, 27.0));
    }

    #[test]
    fn size_out_of_range_is_refused() {
        assert!(white(15).is_err());
        assert!(white(16).is_ok());
        assert!(white(16385).is_err());
    }

    #[test]
    fn write_to_missing_dir_fails_and_leaves_nothing() {
        let dir = std::env::temp_dir().join(format!("render-nodir-{}", std::process::id()));
        let path = dir.join("x.png");
        let pix = white(16).unwrap();
        let err = write_png(&pix, &path).unwrap_err();
        assert!(
            err.to_string().starts_with(&path.display().to_string()),
            "{err}"
        );
        assert!(!dir.exists());
    }
}
