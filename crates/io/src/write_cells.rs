//! Quad and hex mesh output, to any `Write`.
//!
//! Formats (all exact: floats are printed in shortest round-trip form —
//! ryu for OBJ and MEDIT, formatted in parallel chunks ([`crate::fmt`]),
//! Rust's `{:?}` for VTK — or stored as binary doubles):
//! - quads: OBJ (`v`, `f a b c d`, 1-based), PLY (binary little endian,
//!   double positions, `list uchar int vertex_indices`), legacy VTK ASCII
//!   unstructured grid (`VTK_QUAD` = 9);
//! - hexes: MEDIT ASCII (`MeshVersionFormatted 2`, 1-based, reference 0),
//!   legacy VTK (`VTK_HEXAHEDRON` = 12).
//!
//! Cell corner orders are those of [`dualex_cells::cells`] (= VTK = MEDIT),
//! written unchanged. Precondition, checked by [`check_cells`] before any
//! byte is written by the file writers: indices in range, positions finite.

use crate::fmt::{floats_line, int, par_lines};
use crate::ply_out::PlyWriter;
use crate::PlyFormat;
use dualex_cells::{CellMesh, HexMesh, QuadMesh};
use std::io::{self, Write};

/// Checks that every cell index is a vertex and every position is finite.
pub fn check_cells<const K: usize>(mesh: &CellMesh<K>) -> Result<(), String> {
    if let Some(i) = mesh
        .positions
        .iter()
        .position(|p| p.iter().any(|x| !x.is_finite()))
    {
        return Err(format!("vertex {i} has a non-finite position"));
    }
    let nv = mesh.positions.len();
    for (c, cell) in mesh.cells.iter().enumerate() {
        if let Some(v) = cell.iter().find(|&&v| v as usize >= nv) {
            return Err(format!(
                "cell {c} refers to vertex {v}, but there are {nv} vertices"
            ));
        }
    }
    Ok(())
}

/// Wavefront OBJ: `v x y z` lines then `f a b c d` (1-based).
pub fn quad_obj(w: &mut impl Write, mesh: &QuadMesh) -> io::Result<()> {
    writeln!(
        w,
        "# dualex quad mesh: {} vertices, {} quads",
        mesh.positions.len(),
        mesh.cells.len()
    )?;
    par_lines(w, &mesh.positions, |out, p| floats_line(out, b"v", p, b""))?;
    par_lines(w, &mesh.cells, |out, q| {
        out.push(b'f');
        for &v in q {
            out.push(b' ');
            int(out, u64::from(v) + 1);
        }
        out.push(b'\n');
    })
}

/// PLY with double positions and `vertex_indices` lists, in `format`.
pub fn quad_ply(w: &mut impl Write, mesh: &QuadMesh, format: PlyFormat) -> io::Result<()> {
    let mut ply = PlyWriter::new(w, format);
    ply.header(&[
        &format!("element vertex {}", mesh.positions.len()),
        "property double x",
        "property double y",
        "property double z",
        &format!("element face {}", mesh.cells.len()),
        "property list uchar int vertex_indices",
    ])?;
    for p in &mesh.positions {
        ply.doubles(p)?;
        ply.end_record()?;
    }
    for q in &mesh.cells {
        ply.index_list(q)?;
        ply.end_record()?;
    }
    Ok(())
}

/// Legacy VTK ASCII unstructured grid of quads (cell type 9).
pub fn quad_vtk(w: &mut impl Write, mesh: &QuadMesh) -> io::Result<()> {
    cells_vtk(w, mesh, "quad", 9)
}

/// Legacy VTK ASCII unstructured grid of hexes (cell type 12).
pub fn hex_vtk(w: &mut impl Write, mesh: &HexMesh) -> io::Result<()> {
    cells_vtk(w, mesh, "hex", 12)
}

fn cells_vtk<const K: usize>(
    w: &mut impl Write,
    mesh: &CellMesh<K>,
    what: &str,
    ty: u8,
) -> io::Result<()> {
    let m = mesh.cells.len();
    writeln!(w, "# vtk DataFile Version 3.0")?;
    writeln!(w, "dualex {what} mesh")?;
    writeln!(w, "ASCII")?;
    writeln!(w, "DATASET UNSTRUCTURED_GRID")?;
    writeln!(w, "POINTS {} double", mesh.positions.len())?;
    for p in &mesh.positions {
        writeln!(w, "{:?} {:?} {:?}", p[0], p[1], p[2])?;
    }
    writeln!(w, "CELLS {m} {}", m * (K + 1))?;
    for cell in &mesh.cells {
        write!(w, "{K}")?;
        for v in cell {
            write!(w, " {v}")?;
        }
        writeln!(w)?;
    }
    writeln!(w, "CELL_TYPES {m}")?;
    for _ in 0..m {
        writeln!(w, "{ty}")?;
    }
    Ok(())
}

/// MEDIT ASCII `.mesh` with vertices and hexahedra (1-based, reference 0).
pub fn hex_medit(w: &mut impl Write, mesh: &HexMesh) -> io::Result<()> {
    writeln!(w, "MeshVersionFormatted 2")?;
    writeln!(w, "Dimension 3")?;
    writeln!(w, "Vertices")?;
    writeln!(w, "{}", mesh.positions.len())?;
    par_lines(w, &mesh.positions, |out, p| floats_line(out, b"", p, b" 0"))?;
    writeln!(w, "Hexahedra")?;
    writeln!(w, "{}", mesh.cells.len())?;
    par_lines(w, &mesh.cells, |out, h| {
        for &v in h {
            int(out, u64::from(v) + 1);
            out.push(b' ');
        }
        out.extend_from_slice(b"0\n");
    })?;
    writeln!(w, "End")
}

#[cfg(test)]
#[path = "write_cells_tests.rs"]
mod tests;
