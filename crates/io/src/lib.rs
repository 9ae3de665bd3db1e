//! # dualex-io — readers and writers
//!
//! The first and last steps of the pipeline: read a map, write a mesh.
//!
//! | data | read | write |
//! |---|---|---|
//! | triangle map ([`TriMap`]) | `.obj` (`f v/vt`), `.ply` (face `texcoord`, or vertex `u v` / `s t` / `texture_u texture_v`) | `.obj`, `.ply` (binary LE) |
//! | tet map ([`TetMap`]) | `.hexex`, `.ovm` (HexHex's `HexHex::Parametrization`) | `.hexex`, `.ovm` |
//! | polygon mesh ([`PolyMesh`]) | `.obj`, `.ply` | — |
//! | quad mesh ([`QuadMesh`]) | (as a polygon mesh) | `.obj`, `.ply` (binary LE), `.vtk`; with per-corner map coordinates ([`write_uv`]) `.obj`, `.ply` |
//! | hex mesh ([`HexMesh`]) | — | `.mesh` (MEDIT), `.vtk`, `.ovm` |
//!
//! Readers: `parse_*` take bytes (for fuzzers and embedded data), `read_*`
//! take a path, choose the format by extension and attach the file name to
//! the [`InputError`]. Every error is one line naming the line / record;
//! no count read from a file is trusted before it is checked against the
//! bytes left. Map readers end with [`dualex_map::SimplexMap::validate`].
//! `read_tri_map` / `read_tet_map` map a regular file into memory instead
//! of copying it (`mapped`; a measured gain): a file truncated by another
//! process while it is being read ends the process (SIGBUS), where a copy
//! would have read a shorter file.
//!
//! Writers: by extension; the data is checked first, then written to a
//! temporary file renamed over the target ([`output`]), so a failure never
//! leaves a half-written file. Errors are [`OutputError`]s. The `write_*`
//! modules also write to any `std::io::Write`.
#![deny(unsafe_code)] // but `mapped::map`: a measured gain (BENCHMARKS.md)
#![warn(missing_docs)]

mod cursor;
mod decimal;
mod exact;
mod fast;
mod fmt;
mod hexex;
mod mapped;
mod medit;
mod obj;
mod ovm;
mod ovm_out;
mod ply;
mod ply_header;
mod ply_out;
mod pow5;
mod scan;
mod vtk;

pub mod output;
pub mod write_cells;
pub mod write_map;
pub mod write_uv;

#[cfg(test)]
mod cursor_tests;
#[cfg(test)]
mod data_tests;
#[cfg(test)]
mod fast_tests;
#[cfg(test)]
mod float_tests;
#[cfg(test)]
mod fuzz_tests;
#[cfg(test)]
mod ovm_tests;
#[cfg(test)]
mod ply_uv_tests;
#[cfg(test)]
mod pow5_tests;
#[cfg(test)]
mod roundtrip_tests;
#[cfg(test)]
mod test_scratch;

pub use hexex::parse_hexex;
pub use medit::parse_medit_hex;
pub use obj::{parse_obj, parse_polygon_obj};
pub use output::{
    check_output, check_writable, write_bytes, write_text, OutputError, OutputErrorKind,
};
pub use ovm::{parse_ovm_tet_map, HEXHEX_PARAM};
pub use ovm_out::{hex_ovm, tet_map_ovm};

/// Extensions [`write_quad_mesh`] accepts.
pub const QUAD_MESH_EXTENSIONS: &[&str] = &["obj", "ply", "vtk"];
/// Extensions [`write_hex_mesh`] accepts.
pub const HEX_MESH_EXTENSIONS: &[&str] = &["mesh", "vtk", "ovm"];
/// Extensions [`write_tri_map`] accepts.
pub const TRI_MAP_EXTENSIONS: &[&str] = &["obj", "ply"];
/// Extensions [`write_tet_map`] accepts.
pub const TET_MAP_EXTENSIONS: &[&str] = &["hexex", "ovm"];
pub use ply::{parse_ply, parse_polygon_ply};
pub use ply_header::PlyFormat;
pub use vtk::{parse_vtk, VtkMesh};

use dualex_cells::{HexMesh, QuadMesh};
use dualex_map::error::FormatError;
use dualex_map::{InputError, TetMap, TriMap};
use output::{extension, write_atomic};
use std::path::Path;

/// A polygon mesh (e.g. a reference quad mesh): positions and faces of 3 or
/// more vertex indices (0-based, in range).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct PolyMesh {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Faces as vertex indices, in file order.
    pub faces: Vec<Vec<u32>>,
}

/// Reads the whole file; the error names it.
fn read_bytes(path: &Path) -> Result<Vec<u8>, InputError> {
    std::fs::read(path).map_err(|e| InputError::new(e).in_file(path.display().to_string()))
}

/// The extension of `path` in lower case (`""` when it has none): what
/// the readers and writers choose the format by.
pub fn lower_extension(path: &Path) -> String {
    path.extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase()
}

/// The lower-case extension if it is one of `allowed`, else an error naming them.
fn input_extension(path: &Path, allowed: &'static [&'static str]) -> Result<String, InputError> {
    let extension = lower_extension(path);
    if allowed.contains(&extension.as_str()) {
        return Ok(extension);
    }
    let e = FormatError::UnsupportedExtension { extension, allowed };
    Err(InputError::new(e).in_file(path.display().to_string()))
}

/// Reads a triangle map from `.obj` or `.ply`.
pub fn read_tri_map(path: &Path) -> Result<TriMap, InputError> {
    let parse = match input_extension(path, &["obj", "ply"])?.as_str() {
        "obj" => parse_obj,
        _ => parse_ply,
    };
    parse(&mapped::map_or_read(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

/// Reads a tet map from `.hexex` or OpenVolumeMesh ASCII `.ovm` (with
/// HexHex's halfface property `HexHex::Parametrization`).
pub fn read_tet_map(path: &Path) -> Result<TetMap, InputError> {
    let parse = match input_extension(path, &["hexex", "ovm"])?.as_str() {
        "hexex" => parse_hexex,
        _ => parse_ovm_tet_map,
    };
    parse(&mapped::map_or_read(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

/// Reads a hex mesh from a MEDIT `.mesh` (as written by `dualex hex`).
pub fn read_hex_mesh(path: &Path) -> Result<HexMesh, InputError> {
    input_extension(path, &["mesh"])?;
    parse_medit_hex(&read_bytes(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

/// Reads a quad or hex mesh from a legacy ASCII `.vtk` (as written by
/// [`write_quad_mesh`] / [`write_hex_mesh`]).
pub fn read_vtk(path: &Path) -> Result<VtkMesh, InputError> {
    input_extension(path, &["vtk"])?;
    parse_vtk(&read_bytes(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

/// Reads a polygon mesh from `.obj`.
pub fn read_polygon_obj(path: &Path) -> Result<PolyMesh, InputError> {
    parse_polygon_obj(&read_bytes(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

/// Reads a polygon mesh from `.obj` or `.ply`.
pub fn read_polygon_mesh(path: &Path) -> Result<PolyMesh, InputError> {
    let parse = match input_extension(path, &["obj", "ply"])?.as_str() {
        "obj" => parse_polygon_obj,
        _ => parse_polygon_ply,
    };
    parse(&read_bytes(path)?).map_err(|e| e.in_file(path.display().to_string()))
}

fn invalid(path: &Path, message: String) -> OutputError {
    OutputError::new(path, OutputErrorKind::InvalidData(message))
}

/// Writes a quad mesh as `.obj`, `.ply` (binary little endian) or `.vtk`.
pub fn write_quad_mesh(path: &Path, mesh: &QuadMesh) -> Result<(), OutputError> {
    let ext = extension(path, QUAD_MESH_EXTENSIONS)?;
    write_cells::check_cells(mesh).map_err(|m| invalid(path, m))?;
    write_atomic(path, |w| match ext.as_str() {
        "obj" => write_cells::quad_obj(w, mesh),
        "ply" => write_cells::quad_ply(w, mesh, PlyFormat::BinaryLittleEndian),
        _ => write_cells::quad_vtk(w, mesh),
    })
}

/// Writes a quad mesh with per-corner map coordinates (`uv`, one entry per
/// quad, see [`write_uv`]) as `.obj` (`vt`, `f v/vt`) or `.ply` (binary
/// little endian, face `texcoord`).
pub fn write_quad_mesh_uv(
    path: &Path,
    mesh: &QuadMesh,
    uv: &[write_uv::CornerUv],
) -> Result<(), OutputError> {
    let ext = extension(path, write_uv::UV_EXTENSIONS)?;
    write_cells::check_cells(mesh).map_err(|m| invalid(path, m))?;
    write_uv::check_uv(mesh, uv).map_err(|m| invalid(path, m))?;
    write_atomic(path, |w| match ext.as_str() {
        "obj" => write_uv::quad_obj_uv(w, mesh, uv),
        _ => write_uv::quad_ply_uv(w, mesh, uv, PlyFormat::BinaryLittleEndian),
    })
}

/// Writes a hex mesh as `.mesh` (MEDIT), `.vtk` or OpenVolumeMesh ASCII `.ovm`.
pub fn write_hex_mesh(path: &Path, mesh: &HexMesh) -> Result<(), OutputError> {
    let ext = extension(path, HEX_MESH_EXTENSIONS)?;
    write_cells::check_cells(mesh).map_err(|m| invalid(path, m))?;
    write_atomic(path, |w| match ext.as_str() {
        "mesh" => write_cells::hex_medit(w, mesh),
        "ovm" => hex_ovm(w, mesh),
        _ => write_cells::hex_vtk(w, mesh),
    })
}

/// Writes a triangle map as `.obj` or `.ply` (binary little endian).
pub fn write_tri_map(path: &Path, map: &TriMap) -> Result<(), OutputError> {
    let ext = extension(path, TRI_MAP_EXTENSIONS)?;
    map.validate().map_err(|e| invalid(path, e.to_string()))?;
    write_atomic(path, |w| match ext.as_str() {
        "obj" => write_map::tri_map_obj(w, map),
        _ => write_map::tri_map_ply(w, map, PlyFormat::BinaryLittleEndian),
    })
}

/// Writes a tet map as `.hexex` or OpenVolumeMesh ASCII `.ovm` (HexHex's
/// `HexHex::Parametrization`).
pub fn write_tet_map(path: &Path, map: &TetMap) -> Result<(), OutputError> {
    let ext = extension(path, TET_MAP_EXTENSIONS)?;
    map.validate().map_err(|e| invalid(path, e.to_string()))?;
    write_atomic(path, |w| match ext.as_str() {
        "hexex" => write_map::tet_map_hexex(w, map),
        _ => tet_map_ovm(w, map),
    })
}
