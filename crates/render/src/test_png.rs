//! Test helpers: decode a PNG back and look at its colours.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use tiny_skia::Pixmap;

/// A fresh path in the temporary directory, unique to this process.
pub fn temp_path(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("dualex-render-{}-{name}", std::process::id()))
}

/// Decodes the PNG at `path`.
pub fn read_png(path: &Path) -> Pixmap {
    Pixmap::load_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Each opaque RGB colour with its pixel count, most frequent first.
pub fn colours(pix: &Pixmap) -> Vec<([u8; 3], usize)> {
    let mut count: HashMap<[u8; 3], usize> = HashMap::new();
    for p in pix.pixels() {
        let c = p.demultiply();
        if c.alpha() == 255 {
            *count.entry([c.red(), c.green(), c.blue()]).or_insert(0) += 1;
        }
    }
    let mut v: Vec<_> = count.into_iter().collect();
    v.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    v
}

/// Whether some pixel has exactly this colour.
pub fn has_colour(pix: &Pixmap, rgb: [u8; 3]) -> bool {
    pix.pixels().iter().any(|p| {
        let c = p.demultiply();
        [c.red(), c.green(), c.blue()] == rgb && c.alpha() == 255
    })
}

/// Whether some pixel is within `tol` of this colour in every channel.
pub fn has_near(pix: &Pixmap, rgb: [u8; 3], tol: u8) -> bool {
    pix.pixels().iter().any(|p| {
        let c = p.demultiply();
        [c.red(), c.green(), c.blue()]
            .iter()
            .zip(rgb)
            .all(|(&a, b)| a.abs_diff(b) <= tol)
    })
}
