//! # dualex — quad and hex meshes from messy grid-preserving maps
//!
//! The one crate a Rust user needs: build or read a map, extract, write.
//! The pipeline crates (`dualex-map`, `dualex-quad`, `dualex-hex`,
//! `dualex-io`, …) stay behind it.
//!
//! | step | 2D (triangles → quads) | 3D (tets → hexes) |
//! |---|---|---|
//! | a map from slices | [`tri_map_from_slices`] | [`tet_map_from_slices`] |
//! | a map from a file | [`read_tri_map`] (`.obj`, `.ply`) | [`read_tet_map`] (`.hexex`, `.ovm`) |
//! | extraction (welds cut meshes first) | [`quad()`] → [`QuadOutput`] | [`hex()`] → [`HexOutput`] |
//! | options, typed counts (one type each for both) | [`Options`], [`Stats`] | [`Options`], [`Stats`] |
//! | geometry: quality, untangling, smoothing | [`Options::geometry`] → [`Stats::geometry`] | the same |
//! | the pipeline step by step (for tools: the CLI) | [`steps`] | [`steps`] |
//! | a plain surface from a file | [`read_surface`] (`.obj`, `.ply`; polygons fanned) | — |
//! | quads from a plain surface (no map) | [`remesh()`] → [`RemeshOutput`] | — |
//! | a mesh to a file | [`write_quad_mesh`] (`.obj`, `.ply`, `.vtk`) | [`write_hex_mesh`] (`.mesh`, `.vtk`, `.ovm`) |
//! | with corner map coordinates | [`write_quad_mesh_uv`] (`.obj`, `.ply`) | — ([`HexOutput`]'s `corners` only) |
//! | a map to a file | [`write_tri_map`] (`.obj`, `.ply`) | [`write_tet_map`] (`.hexex`, `.ovm`) |
//! | a map's `inspect` report as JSON | [`map_report_json`] | [`map_report_json`] |
//!
//! The layers behind the facade, re-exported whole (as lyon does) for
//! tools that need more than the table (the CLI is one; a library user
//! should not need them): [`map`] (the map model: welding, transitions,
//! the `inspect` report), [`io`] (every reader and writer), [`check`] (the
//! validity checker and topology), [`geom`] (the geometric stage's
//! pieces: quality), and behind features [`render`] (`render`: pictures,
//! the WebGL page), [`gen`] (`gen`: test maps), [`extrude`] (`extrude`:
//! tet maps from 2D maps and closed surfaces).
//!
//! Errors are one [`Error`] enum; input errors name the file and the
//! element (`triangle 17: …`). Nothing panics on bad input.
//!
//! After the extraction (and its checks) runs the geometric stage, as in
//! the CLI: it measures every element's scaled Jacobian, puts boundary
//! vertices on the input's boundary and untangles inverted elements
//! ([`GeometryMode::Auto`], the default), keeps the map's positions
//! ([`GeometryMode::Off`]) or smooths the whole mesh
//! ([`GeometryMode::Smooth`]). Its [`GeometryReport`] (quality
//! [`before`](GeometryReport::before) and
//! [`after`](GeometryReport::after)) is in the stats; with `strict`,
//! inverted elements left are [`Error::InvertedElements`].
//!
//! ```
//! // a 1×1 square of 2 triangles whose map covers [0, 3]²: 3×3 quads
//! let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
//! let triangles = [[0, 1, 2], [0, 2, 3]];
//! let uv = triangles.map(|t| t.map(|v| {
//!     let p = positions[v as usize];
//!     [3.0 * p[0], 3.0 * p[1]]
//! }));
//! let map = dualex::tri_map_from_slices(&positions, &triangles, &uv)?;
//! let out = dualex::quad(&map, &dualex::Options::default())?;
//! assert_eq!(out.mesh.cells.len(), 9);
//! assert_eq!((out.stats.cells, out.stats.components, out.stats.boundary_components), (9, 1, 1));
//! assert_eq!(out.stats.valence_interior.get(&4), Some(&4));
//! // the geometric stage: nothing inverted before or after
//! assert_eq!(out.stats.geometry.before.elements, 9);
//! assert_eq!((out.stats.geometry.before.inverted, out.stats.geometry.after.inverted), (0, 0));
//! # Ok::<(), dualex::Error>(())
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod dims;
mod extract;
mod inspect;
pub mod remesh;
mod slices;
pub mod stats;
pub mod steps;
mod surface;

pub use dualex_check as check;
#[cfg(feature = "extrude")]
pub use dualex_extrude as extrude;
#[cfg(feature = "gen")]
pub use dualex_gen as gen;
pub use dualex_geom as geom;
pub use dualex_io as io;
pub use dualex_map as map;
#[cfg(feature = "render")]
pub use dualex_render as render;

pub use dualex_cells::{CellMesh, HexMesh, QuadMesh};
pub use dualex_geom::{
    Mode as GeometryMode, Options as GeometryOptions, Report as GeometryReport, Summary as Quality,
    SMOOTH_ROUNDS,
};
pub use dualex_io::OutputError;
pub use dualex_map::{InputError, InputErrorKind, TetMap, TriMap};
pub use extract::{hex, quad, HexOutput, Options, Output, QuadOutput};
pub use inspect::map_report_json;
pub use remesh::{
    attempt_seed, remesh, remesh_map, remesh_staged, MapOptions, Quantization, RemeshOptions,
    RemeshOutput, RemeshStats, RemeshedMap, Staged, Target, GRID_ATTEMPTS,
};
pub use slices::{map_from_slices, tet_map_from_slices, tri_map_from_slices};
pub use stats::{GridOffset, Repairs, Stats, Topology};
pub use surface::{has_map_coordinates, read_surface, PlainSurface};

use std::fmt;
use std::path::Path;

/// Everything that can go wrong, each kind with its own variant.
#[derive(Debug)]
#[non_exhaustive]
pub enum Error {
    /// The input: an unreadable or malformed file, an invalid map, a map
    /// the extraction refuses. The message names the file (when there is
    /// one) and the element.
    Input(InputError),
    /// Writing an output file.
    Output(OutputError),
    /// The extraction could not make a valid mesh (the checker's findings);
    /// please report the input.
    InvalidOutput(String),
    /// With `strict`: the output's topology differs from the input's.
    TopologyChanged {
        /// The input's topology.
        input: Topology,
        /// The output's.
        output: Topology,
    },
    /// With `strict`: elements with a scaled Jacobian ≤ 0 remain after the
    /// geometric stage (with [`GeometryMode::Off`]: those of the map's
    /// positions).
    InvertedElements {
        /// Inverted elements left.
        count: usize,
    },
    /// [`remesh()`] made no quad (the map covers less than one grid cell).
    Empty(String),
    /// An internal error: [`remesh()`] made a map that is not
    /// grid-preserving or collapsed (its own output, never the user's
    /// input); please report the input.
    Bug(String),
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Error::Input(e) => write!(f, "{e}"),
            Error::Output(e) => write!(f, "{e}"),
            Error::InvalidOutput(e) => write!(f, "could not make a valid mesh: {e}"),
            Error::TopologyChanged { input, output } => write!(
                f,
                "the output's topology differs from the input's: components {} → {}, Euler characteristic {} → {}, boundary components {} → {}",
                input.components,
                output.components,
                input.euler,
                output.euler,
                input.boundary_components,
                output.boundary_components
            ),
            Error::InvertedElements { count } => write!(
                f,
                "{count} inverted {} (scaled Jacobian ≤ 0) {} after the geometric stage",
                if *count == 1 { "element" } else { "elements" },
                if *count == 1 { "remains" } else { "remain" },
            ),
            Error::Empty(e) => write!(f, "empty mesh: {e}"),
            Error::Bug(e) => write!(
                f,
                "internal error (bug) in remesh: {e}; please report this input"
            ),
        }
    }
}

impl std::error::Error for Error {}

impl From<InputError> for Error {
    fn from(e: InputError) -> Self {
        Error::Input(e)
    }
}

impl From<OutputError> for Error {
    fn from(e: OutputError) -> Self {
        Error::Output(e)
    }
}

/// Reads a triangle map from `.obj` (`f v/vt`) or `.ply` (per-face
/// `texcoord`, or per-vertex `u v` / `s t` / `texture_u texture_v`), chosen
/// by extension.
pub fn read_tri_map(path: impl AsRef<Path>) -> Result<TriMap, Error> {
    Ok(dualex_io::read_tri_map(path.as_ref())?)
}

/// Reads a tet map from HexEx's `.hexex` or OpenVolumeMesh ASCII `.ovm`
/// (HexHex's halfface property `HexHex::Parametrization`), chosen by
/// extension.
pub fn read_tet_map(path: impl AsRef<Path>) -> Result<TetMap, Error> {
    Ok(dualex_io::read_tet_map(path.as_ref())?)
}

/// Writes a quad mesh as `.obj`, `.ply` (binary) or `.vtk`, chosen by
/// extension, through a temporary file renamed over the target.
pub fn write_quad_mesh(path: impl AsRef<Path>, mesh: &QuadMesh) -> Result<(), Error> {
    Ok(dualex_io::write_quad_mesh(path.as_ref(), mesh)?)
}

/// Writes a quad mesh with the map coordinates of each quad's corners
/// ([`QuadOutput`]'s `corners`) as `.obj` (`vt`, `f v/vt`) or `.ply` (face
/// `texcoord`), chosen by extension (as `dualex quad --uv`).
pub fn write_quad_mesh_uv(
    path: impl AsRef<Path>,
    mesh: &QuadMesh,
    corner_uv: &[Option<[[f64; 2]; 4]>],
) -> Result<(), Error> {
    Ok(dualex_io::write_quad_mesh_uv(
        path.as_ref(),
        mesh,
        corner_uv,
    )?)
}

/// Writes a hex mesh as `.mesh` (MEDIT), `.vtk` or OpenVolumeMesh ASCII
/// `.ovm` (shared faces), chosen by extension, through a temporary file
/// renamed over the target.
pub fn write_hex_mesh(path: impl AsRef<Path>, mesh: &HexMesh) -> Result<(), Error> {
    Ok(dualex_io::write_hex_mesh(path.as_ref(), mesh)?)
}

/// Writes a triangle map as `.obj` (`f v/vt`) or `.ply` (binary, per-face
/// `texcoord`), chosen by extension; the map is validated first.
pub fn write_tri_map(path: impl AsRef<Path>, map: &TriMap) -> Result<(), Error> {
    Ok(dualex_io::write_tri_map(path.as_ref(), map)?)
}

/// Writes a tet map as `.hexex` or OpenVolumeMesh ASCII `.ovm` (with
/// HexHex's `HexHex::Parametrization`: each halfface holds the map value
/// of its cell's opposite vertex), chosen by extension.
///
/// ```
/// // one tet whose map is its position: written as .ovm, read back equal
/// let positions = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
/// let map = dualex::tet_map_from_slices(&positions, &[[0, 1, 2, 3]], &[positions])?;
/// let path = std::env::temp_dir().join(format!("dualex-doc-{}.ovm", std::process::id()));
/// dualex::write_tet_map(&path, &map)?;
/// let back = dualex::read_tet_map(&path)?;
/// std::fs::remove_file(&path).ok();
/// assert_eq!((back.positions.len(), back.simplices.len()), (4, 1));
/// let corner_of = |m: &dualex::TetMap, v: u32| {
///     let c = m.simplices[0].iter().position(|&w| w == v).unwrap();
///     m.coords[0][c]
/// };
/// for v in 0..4 {
///     assert_eq!(corner_of(&back, v), corner_of(&map, v));
/// }
/// # Ok::<(), dualex::Error>(())
/// ```
pub fn write_tet_map(path: impl AsRef<Path>, map: &TetMap) -> Result<(), Error> {
    Ok(dualex_io::write_tet_map(path.as_ref(), map)?)
}

#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_geometry;
#[cfg(test)]
mod tests_input_shape;
