//! Quad meshes with per-corner map coordinates (`dualex quad --uv`).
//!
//! Each quad carries the map coordinates of its 4 corners in one chart
//! (see `dualex_cells::corners`): a vertex on a seam has different ones in
//! the quads around it, so they are per corner, not per vertex.
//! - OBJ: one `vt u v` per corner (4 per quad, in quad order) after the
//!   `v` lines, and `f a/ta b/tb c/tc d/td`; a quad without coordinates is
//!   written `f a b c d` (no `vt` for it).
//! - PLY: a face property `list uchar double texcoord` of 8 values
//!   `u0 v0 … u3 v3` (the convention `dualex quad` reads, with 4 corners);
//!   an empty list for a quad without coordinates.
//!
//! Legacy VTK has no per-corner attribute: [`UV_EXTENSIONS`] lists the
//! formats that carry them; the CLI refuses `--uv` for the others.
//! Precondition, checked before any byte is written: one entry per quad,
//! finite values (besides the mesh's own checks).

use crate::fmt::{floats_line, int, par_lines};
use crate::ply_out::PlyWriter;
use crate::PlyFormat;
use dualex_cells::QuadMesh;
use std::io::{self, Write};

/// Per quad, its corners' map coordinates (or none).
pub type CornerUv = Option<[[f64; 2]; 4]>;

/// The quad mesh formats that carry per-corner map coordinates.
pub const UV_EXTENSIONS: &[&str] = &["obj", "ply"];

/// Checks `uv` against `mesh`: one entry per quad, every value finite.
pub fn check_uv(mesh: &QuadMesh, uv: &[CornerUv]) -> Result<(), String> {
    if uv.len() != mesh.cells.len() {
        return Err(format!(
            "{} map coordinate entries for {} quads",
            uv.len(),
            mesh.cells.len()
        ));
    }
    match uv
        .iter()
        .position(|c| c.is_some_and(|c| c.iter().flatten().any(|x| !x.is_finite())))
    {
        Some(q) => Err(format!("quad {q} has a non-finite map coordinate")),
        None => Ok(()),
    }
}

/// OBJ with `vt` per corner (module docs).
pub fn quad_obj_uv(w: &mut impl Write, mesh: &QuadMesh, uv: &[CornerUv]) -> io::Result<()> {
    writeln!(
        w,
        "# dualex quad mesh: {} vertices, {} quads; vt: map coordinates of each quad's corners in its node's chart",
        mesh.positions.len(),
        mesh.cells.len()
    )?;
    par_lines(w, &mesh.positions, |out, p| floats_line(out, b"v", p, b""))?;
    let corners: Vec<[f64; 2]> = uv.iter().flatten().flatten().copied().collect();
    par_lines(w, &corners, |out, t| floats_line(out, b"vt", t, b""))?;
    // 1-based index of each quad's first vt
    let mut first = Vec::with_capacity(uv.len());
    let mut next = 1u64;
    for c in uv {
        first.push(c.map(|_| next));
        next += if c.is_some() { 4 } else { 0 };
    }
    let faces: Vec<(&[u32; 4], Option<u64>)> = mesh.cells.iter().zip(first).collect();
    par_lines(w, &faces, |out, (q, t)| {
        out.push(b'f');
        for (k, &v) in q.iter().enumerate() {
            out.push(b' ');
            int(out, u64::from(v) + 1);
            if let Some(t) = t {
                out.push(b'/');
                int(out, t + k as u64);
            }
        }
        out.push(b'\n');
    })
}

/// PLY with a face `texcoord` list (module docs), in `format`.
pub fn quad_ply_uv(
    w: &mut impl Write,
    mesh: &QuadMesh,
    uv: &[CornerUv],
    format: PlyFormat,
) -> io::Result<()> {
    let mut ply = PlyWriter::new(w, format);
    ply.header(&[
        &format!("element vertex {}", mesh.positions.len()),
        "property double x",
        "property double y",
        "property double z",
        &format!("element face {}", mesh.cells.len()),
        "property list uchar int vertex_indices",
        "property list uchar double texcoord",
    ])?;
    for p in &mesh.positions {
        ply.doubles(p)?;
        ply.end_record()?;
    }
    for (q, c) in mesh.cells.iter().zip(uv) {
        ply.index_list(q)?;
        let flat: Vec<f64> = c.iter().flatten().flatten().copied().collect();
        ply.double_list(&flat)?;
        ply.end_record()?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn obj_writes_a_vt_per_corner_and_plain_faces_without() {
        let mesh = QuadMesh {
            positions: vec![[0.0; 3]; 6],
            cells: vec![[0, 1, 2, 3], [1, 4, 5, 2], [0, 3, 5, 4]],
        };
        let sq = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let uv = [Some(sq), None, Some(sq)];
        check_uv(&mesh, &uv).expect("valid");
        let mut out = Vec::new();
        quad_obj_uv(&mut out, &mesh, &uv).expect("write");
        let text = String::from_utf8(out).expect("utf8");
        assert_eq!(text.lines().filter(|l| l.starts_with("vt ")).count(), 8);
        let faces: Vec<&str> = text.lines().filter(|l| l.starts_with("f ")).collect();
        assert_eq!(
            faces,
            ["f 1/1 2/2 3/3 4/4", "f 2 5 6 3", "f 1/5 4/6 6/7 5/8"]
        );
        assert!(check_uv(&mesh, &uv[..2]).is_err());
    }
}
