//! # dualex-extrude — 3D maps from 2D ones
//!
//! Turns a triangle map into a tet map so that the quad and hex paths can
//! be held against each other: prisms over every triangle, `L` layers, `w`
//! integer at the layer interfaces (`0..=L`), so the dual has exactly `L`
//! layers of hexes (nodes at `w = k + ½`). Steps of [`extrude`]:
//! 1. [`slab`]: the layered points (planar maps offset along ±z, surfaces
//!    along area-weighted vertex normals, turned where those do not see
//!    an incident triangle from above: [`offset`]) and prisms;
//! 2. [`plc`]: the prism walls as constraint facets, one region per prism;
//! 3. [`chain`]: [`tetgen`], TetGen run as an external program (`tetgen -pYzQFN`,
//!    each tet's prism from its nodes by [`label`]; `-pYzQAF` when that
//!    fails or TetGen added points; `-pzQAFq` with quality); when TetGen
//!    refuses the slab, a thinner one, then the built-in 3-tet prism split
//!    ([`split`]), also used straight away when the surface itself
//!    self-intersects ([`intersect`]) and, when asked (`fallback`), when
//!    TetGen is absent;
//! 4. [`chart`]: each tet gets its prism's triangle chart plus `w`;
//!    Steiner points get the map of their preimage in the prism.
//!
//! TetGen is AGPL: it is never linked, only run when found at run time.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod chain;
pub mod chart;
pub mod grid;
pub mod intersect;
pub mod label;
pub mod offset;
pub mod plc;
pub mod slab;
pub mod split;
pub mod tetgen;
pub mod text;
pub mod volume;

#[cfg(test)]
mod tests;

use dualex_map::{InputError, TetMap, TriMap};
use std::path::PathBuf;
use std::time::Instant;

pub use chain::Method;
pub use slab::{Slab, DEFAULT_THICKNESS_FRACTION};

/// How to extrude.
#[derive(Clone, Debug)]
pub struct ExtrudeOptions {
    /// Number of layers `L ≥ 1`.
    pub layers: usize,
    /// Total thickness; `None`: [`DEFAULT_THICKNESS_FRACTION`] × mean edge length.
    pub thickness: Option<f64>,
    /// TetGen's quality refinement (`-q`).
    pub quality: bool,
    /// The TetGen program (looked up on `PATH` when not a path).
    pub program: PathBuf,
    /// Use the built-in prism split when the program is not found (when
    /// TetGen refuses the slab, [`chain`] always ends with the split).
    pub fallback: bool,
}

impl Default for ExtrudeOptions {
    fn default() -> Self {
        ExtrudeOptions {
            layers: 1,
            thickness: None,
            quality: false,
            program: "tetgen".into(),
            fallback: false,
        }
    }
}

/// What [`extrude`] did.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtrudeReport {
    /// The charts were shifted by (½, ½): the 2D grid offset is 0 ([`grid`]).
    pub uv_shifted: bool,
    /// `true`: TetGen made the tets; `false`: the built-in prism split.
    pub tetgen: bool,
    /// How the tets were made ([`chain`]).
    pub method: Method,
    /// Why not TetGen on the requested slab, one line (TetGen missing, or
    /// refusing the slab and what followed), e.g. "TetGen refused the slab
    /// (…); thinner slab (T = …) accepted".
    pub note: Option<String>,
    /// Base triangles that cross another one ([`intersect`] before TetGen,
    /// TetGen's `-d` after a refusal).
    pub intersecting_triangles: usize,
    /// Vertices whose offset direction was turned away from the
    /// area-weighted normal ([`offset`]).
    pub turned_vertices: usize,
    /// Vertices where no offset direction sees every incident triangle from
    /// above ([`offset`]).
    pub folded_vertices: usize,
    /// Prisms (triangles × layers).
    pub prisms: usize,
    /// Tets written.
    pub tets: usize,
    /// Points added by TetGen (inside prisms).
    pub steiner_points: usize,
    /// Tets whose map is flat (`det = 0`): TetGen spanned a bent prism
    /// wall (its 4 points map onto one edge × `w`); only on surfaces.
    pub flat_tets: usize,
    /// Tets whose map is reverted (`det < 0`): with Steiner points on a
    /// curved slab, where TetGen's tets straddle the prism's linear pieces.
    pub reverted_tets: usize,
    /// Total thickness used.
    pub thickness: f64,
    /// Whether the map was planar (offset along ±z).
    pub planar: bool,
    /// Whether `w` runs downward (map with negative total area).
    pub w_reversed: bool,
    /// Wall time of [`chain`] (the slab, the crossing check, TetGen and its
    /// retries, or the split), milliseconds.
    pub tetrahedralize_ms: f64,
    /// Total wall time, milliseconds.
    pub total_ms: f64,
}

/// Why [`extrude`] failed; displayed as one line.
#[derive(Clone, Debug, PartialEq)]
pub enum ExtrudeError {
    /// The input map cannot be extruded.
    Input(InputError),
    /// The TetGen program was not found.
    TetgenMissing(PathBuf),
    /// TetGen failed or wrote something unreadable.
    TetgenFailed(String),
    /// TetGen's tets do not respect the prisms.
    Output(String),
    /// A temporary file could not be written.
    Io(String),
}

impl std::fmt::Display for ExtrudeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExtrudeError::Input(e) => write!(f, "{e}"),
            ExtrudeError::TetgenMissing(p) => write!(
                f,
                "TetGen not found ({}): install it (Debian/Ubuntu: apt-get install tetgen), set DUALEX_TETGEN to its path, or pass --fallback for the built-in prism split",
                p.display()
            ),
            ExtrudeError::TetgenFailed(m) => write!(f, "TetGen failed: {m}"),
            ExtrudeError::Output(m) => write!(f, "TetGen output does not respect the prisms: {m}"),
            ExtrudeError::Io(m) => write!(f, "temporary file: {m}"),
        }
    }
}

impl std::error::Error for ExtrudeError {}

impl From<InputError> for ExtrudeError {
    fn from(e: InputError) -> Self {
        ExtrudeError::Input(e)
    }
}

/// Extrudes `map` into a tet map (crate docs).
pub fn extrude(
    map: &TriMap,
    opts: &ExtrudeOptions,
) -> Result<(TetMap, ExtrudeReport), ExtrudeError> {
    let start = Instant::now();
    let uv_shifted = grid::zero_in_2d(map)?;
    let owned;
    let map = if uv_shifted {
        owned = grid::shifted(map);
        &owned
    } else {
        map
    };
    let t0 = Instant::now();
    let chain::Outcome {
        slab,
        mesh,
        method,
        note,
        intersecting_triangles,
    } = chain::tetrahedralize(map, opts)?;
    let tetrahedralize_ms = t0.elapsed().as_secs_f64() * 1e3;
    let (tets, steiner_points) = chart::tet_map(&slab, &mesh)?;
    let report = ExtrudeReport {
        uv_shifted,
        tetgen: method != Method::Split,
        method,
        note,
        intersecting_triangles,
        turned_vertices: slab.turned,
        folded_vertices: slab.folded,
        prisms: slab.prisms(),
        tets: tets.len(),
        steiner_points,
        flat_tets: (0..tets.len()).filter(|&s| tets.map_det(s) == 0.0).count(),
        reverted_tets: (0..tets.len()).filter(|&s| tets.map_det(s) < 0.0).count(),
        thickness: slab.thickness,
        planar: slab.planar,
        w_reversed: slab.w_sign < 0.0,
        tetrahedralize_ms,
        total_ms: start.elapsed().as_secs_f64() * 1e3,
    };
    Ok((tets, report))
}
