//! Plain surfaces (no map) from files, the input of [`crate::remesh()`].
//!
//! Input: a `.obj` or `.ply` file of polygons. Output: [`PlainSurface`],
//! positions and triangles, polygons fanned into triangles from their
//! first corner (the count of polygons split kept), or an [`Error::Input`]
//! naming the file and the element (a face of fewer than 3 corners).
//! [`has_map_coordinates`] tells a plain surface from a map file.

use crate::{Error, InputError};
use dualex_map::error::{CountError, FaceNeed};
use std::path::Path;

/// A surface read by [`read_surface`].
#[derive(Clone, Debug)]
pub struct PlainSurface {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Triangles (vertex indices, in file order; polygons fanned).
    pub triangles: Vec<[u32; 3]>,
    /// Polygons of more than 3 corners split into triangles.
    pub fanned: usize,
}

/// Reads a polygon surface from `.obj` or `.ply` (map coordinates, if
/// any, ignored), polygons fanned into triangles.
pub fn read_surface(path: impl AsRef<Path>) -> Result<PlainSurface, Error> {
    let path = path.as_ref();
    let poly = dualex_io::read_polygon_mesh(path)?;
    let (triangles, fanned) =
        fan(&poly.faces).map_err(|e| e.in_file(path.display().to_string()))?;
    Ok(PlainSurface {
        positions: poly.positions,
        triangles,
        fanned,
    })
}

/// Polygons fanned into triangles (from their first corner); how many
/// polygons were split. A face of fewer than 3 corners is an error.
fn fan(faces: &[Vec<u32>]) -> Result<(Vec<[u32; 3]>, usize), InputError> {
    let mut tris = Vec::with_capacity(faces.len());
    let mut fanned = 0;
    for (i, f) in faces.iter().enumerate() {
        if f.len() < 3 {
            return Err(CountError::FaceSize {
                face: Some(i as u64),
                vertices: f.len(),
                need: FaceNeed::Unstated,
            }
            .into());
        }
        if f.len() > 3 {
            fanned += 1;
        }
        for k in 1..f.len() - 1 {
            tris.push([f[0], f[k], f[k + 1]]);
        }
    }
    Ok((tris, fanned))
}

/// Whether a `.obj` / `.ply` file holds map coordinates at all: an OBJ
/// `vt` line, a PLY property `texcoord`, `u`, `s` or `texture_u` in the
/// header. (A file without is a plain surface, not a broken map.)
pub fn has_map_coordinates(path: impl AsRef<Path>) -> Result<bool, Error> {
    let path = path.as_ref();
    let bytes =
        std::fs::read(path).map_err(|e| InputError::new(e).in_file(path.display().to_string()))?;
    let ply = bytes.starts_with(b"ply");
    let text = String::from_utf8_lossy(if ply {
        let end = bytes
            .windows(10)
            .position(|w| w == b"end_header")
            .unwrap_or(bytes.len());
        &bytes[..end]
    } else {
        &bytes
    });
    Ok(text.lines().any(|l| {
        let mut words = l.split_whitespace();
        match (ply, words.next()) {
            (false, Some("vt")) => true,
            (true, Some("property")) => words
                .last()
                .is_some_and(|w| matches!(w, "texcoord" | "u" | "s" | "texture_u")),
            _ => false,
        }
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygons_are_fanned_and_short_faces_refused() {
        let (t, n) = fan(&[vec![0, 1, 2, 3], vec![0, 2, 4]]).expect("fanned");
        assert_eq!(t, [[0, 1, 2], [0, 2, 3], [0, 2, 4]]);
        assert_eq!(n, 1);
        let e = fan(&[vec![0, 1, 2], vec![0, 1]]).unwrap_err();
        assert_eq!(e.to_string(), "face 1 has 2 vertices");
    }

    #[test]
    fn map_coordinates_are_told_from_a_plain_surface() {
        let dir = std::env::temp_dir();
        let id = std::process::id();
        let cases: [(&str, &str, bool); 4] = [
            ("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", false),
            (
                "b.obj",
                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1\n",
                true,
            ),
            (
                "c.ply",
                "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nend_header\n",
                false,
            ),
            (
                "d.ply",
                "ply\nformat ascii 1.0\nelement vertex 0\nproperty float u\nend_header\n",
                true,
            ),
        ];
        for (name, text, expected) in cases {
            let p = dir.join(format!("dualex-surface-{id}-{name}"));
            std::fs::write(&p, text).expect("write");
            let got = has_map_coordinates(&p).expect("read");
            std::fs::remove_file(&p).ok();
            assert_eq!(got, expected, "{name}");
        }
    }
}
