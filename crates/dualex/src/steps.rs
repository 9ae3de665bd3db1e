//! The pipeline one step at a time, for tools that report on every step
//! (the CLI: its own checks, messages and `--stats` JSON); [`quad()`] and
//! [`hex()`] run these same steps in this order:
//!
//! 1. weld ([`weld`]: coincident boundary vertices merged, a cut mesh
//!    made whole);
//! 2. extract ([`extract_quads`], [`extract_hexes`]): the mesh, the
//!    extraction's own detailed report ([`QuadReport`], [`HexReport`]:
//!    every stage's counts, its JSON, the sanitization's leftovers), the
//!    cells' sources and corner map coordinates;
//! 3. check: [`crate::check`] (the output's validity and topology);
//! 4. the geometric stage ([`quad_geometry`], [`hex_geometry`]): positions
//!    moved, cells untouched.
//!
//! Input: a map and the facade's [`Options`]; nothing here fails on bad
//! input other than by an [`InputError`] naming the element.
//!
//! [`quad()`]: crate::quad()
//! [`hex()`]: crate::hex()

use crate::{GeometryOptions, GeometryReport, HexMesh, InputError, Options, TetMap, TriMap};
use dualex_map::{SimplexMap, TransitionOptions};

pub use dualex_hex::{Extracted as HexExtraction, HexStats as HexReport};
pub use dualex_quad::{Extracted as QuadExtraction, QuadStats as QuadReport};
pub use dualex_segment::sanitize_report::SanitizeReport;
/// The clock of the reports' `time_ms` (laps by name), for a tool's own.
pub use dualex_util::timing::Laps;

/// Step 1: `map` with its coincident boundary vertices merged (the seams of
/// a cut mesh), and how many were merged; the simplices and their order are
/// kept. A map with nothing to merge is returned as it is.
pub fn weld<const N: usize, const D: usize>(map: SimplexMap<N, D>) -> (SimplexMap<N, D>, usize) {
    let (map, rep) = dualex_map::weld::weld_owned(map);
    (map, rep.welded_vertices)
}

fn transitions(round: bool) -> TransitionOptions {
    TransitionOptions {
        round,
        ..Default::default()
    }
}

/// The quad extraction's own options from the facade's; `singularities`:
/// count the input's singularities by index in the report (about 10 % of
/// the extraction; the CLI does where stats are shown).
pub(crate) fn quad_options(opts: &Options, singularities: bool) -> dualex_quad::QuadOptions {
    dualex_quad::QuadOptions {
        fairing: opts.fairing,
        transitions: transitions(opts.round_transitions),
        seed: opts.seed,
        grid_offset: opts.grid_offset,
        singularity_stats: singularities,
    }
}

/// Step 2 in 2D: the quad extraction of `map` (not welded here) with
/// `opts`' extraction knobs (`fairing`, `round_transitions`,
/// `grid_offset`, `seed`); `singularities` fills
/// [`QuadReport::singularities`] (about 10 % of the extraction).
pub fn extract_quads(
    map: &TriMap,
    opts: &Options,
    singularities: bool,
) -> Result<QuadExtraction, InputError> {
    dualex_quad::extract_full(map, &quad_options(opts, singularities))
}

/// Step 2 in 3D: the hex extraction of `map` (not welded here) with
/// `opts`' extraction knobs (`fairing`: on columns, `round_transitions`,
/// `grid_offset`, `seed`).
pub fn extract_hexes(map: &TetMap, opts: &Options) -> Result<HexExtraction, InputError> {
    let inner = dualex_hex::HexOptions {
        transitions: transitions(opts.round_transitions),
        seed: opts.seed,
        grid_offset: opts.grid_offset,
        fairing: opts.fairing,
    };
    dualex_hex::extract_full(map, &inner)
}

/// Step 4 in 2D: the geometric stage on the quads of `x` (their positions
/// moved in place) against `map`'s surface (the map `x` was extracted
/// from).
pub fn quad_geometry(
    map: &TriMap,
    x: &mut QuadExtraction,
    opts: &GeometryOptions,
) -> GeometryReport {
    // the stage's "none" is u32::MAX, the extraction's NO_SOURCE
    const _: () = assert!(dualex_quad::NO_SOURCE == u32::MAX);
    dualex_geom::quads(
        &mut x.mesh.positions,
        &x.mesh.cells,
        &map.positions,
        &map.simplices,
        &x.sources,
        opts,
    )
}

/// Step 4 in 3D: the geometric stage on `mesh` (its positions moved in
/// place) against `map`'s tets (the map it was extracted from).
pub fn hex_geometry(map: &TetMap, mesh: &mut HexMesh, opts: &GeometryOptions) -> GeometryReport {
    dualex_geom::hexes(
        &mut mesh.positions,
        &mesh.cells,
        &map.positions,
        &map.simplices,
        opts,
    )
}
