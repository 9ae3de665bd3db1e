//! # dualex-hex — hex extraction from messy 3D maps
//!
//! The driver [`extract`] runs the pipeline's numbered steps
//! (ARCHITECTURE.md), one call each:
//! 1–7. the segmentation, shared with `dualex-quad`
//!    (`dualex_segment::steps`): 1. the map model (after the refusal of
//!    reflected charts); 2. the local map, built once with the grid
//!    offset chosen, singular vertices snapped; 3. tet edges and faces
//!    spanned by unmovable vertices across the dual grid split (repeated
//!    until none is left); 4. sanitization (`dualex_segment::near` says
//!    what "on" means at D = 3); 5. nodes; 6. traced sides; 7. the
//!    opposite relation, then untangling (pleat removal, `dualex_graph`);
//! 8. in the graph: 8a. on a graph made of columns (an extruded map's),
//!    index fairing and the collapse of folded corners in every layer
//!    (`dualex_graph::columns`); 8e. chains of valence-2 edges merged
//!    (`dualex_graph::doublet`);
//! 9. glued (`dualex_graph`) and placed: vertex positions by diagonal
//!    tracing, each hex's source tet and corners' map coordinates
//!    (`dualex_segment::place`, carried along steps 10–11);
//! 10. [`columns`]: holes through columns (singular edges through dual
//!     nodes) repaired as the 2D local repair, replayed in every layer;
//! 11. [`doublets`]: folded hexes collapsed, chains of valence-2 interior
//!     edges the graph did not merge dissolved (in rounds).
//!
//! A map with reverted nodes whose glued mesh is invalid is extracted once
//! more, its local map relaxed in the fold regions between steps 3 and 4
//! (`dualex_segment::relax::retry`, issue 22); that result is kept only if
//! valid (`relax` in the stats), else the first one stands.
//!
//! Input: a [`TetMap`]. Output: a [`HexMesh`] (VTK order) and [`HexStats`]
//! ([`extract_traced`]: also the input tet holding each hex's node;
//! [`extract_full`]: also the map coordinates of its corners).
//! Walks that leave the mesh leave their side unmatched: free boundaries
//! become boundary faces of the hex mesh.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod columns;
pub mod doublets;
pub mod stats;

use dualex_cells::HexMesh;
use dualex_graph::Takeover;
use dualex_map::{InputCounts, InputError, TetMap, TransitionOptions};
pub use dualex_segment::grid_offset::GridOffset;
use dualex_segment::place::{place, Placed};
use dualex_segment::relax;
use dualex_segment::steps::{self, Model, Segmented};
use dualex_util::timing::Laps;
pub use stats::HexStats;

/// The map coordinates of a hex's corners in the input chart of the tet
/// holding its node, in VTK order (`dualex_segment::place`,
/// [`dualex_cells::corners`]).
pub type HexCorners = dualex_cells::corners::Corners<3, 8>;

/// Options of [`extract`].
#[derive(Clone, Debug)]
pub struct HexOptions {
    /// Transition derivation options.
    pub transitions: TransitionOptions,
    /// Seed of the sanitization perturbations.
    pub seed: u64,
    /// Where the dual grid sits (`--grid-offset`).
    pub grid_offset: GridOffset,
    /// Index fairing on columns (extruded maps: the 2D saddle lifts in
    /// every layer, `dualex_graph::columns`). Default: on.
    pub fairing: bool,
}

impl Default for HexOptions {
    fn default() -> Self {
        HexOptions {
            transitions: TransitionOptions::default(),
            seed: 1,
            grid_offset: GridOffset::Auto,
            fairing: true,
        }
    }
}

/// Longest path a singularity is moved along by fairing (as in 2D, the
/// paper's 10).
pub const FAIRING_MAX_PATH: usize = 10;

/// Everything [`extract_full`] returns: the hexes (VTK order), their
/// stats, sources (as [`extract_traced`]) and corners' map coordinates
/// (`corners`: [`HexCorners`]).
pub type Extracted = dualex_segment::place::Extracted<3, 8, HexStats>;

/// Extracts the hex mesh of `map`.
pub fn extract(map: &TetMap, opts: &HexOptions) -> Result<(HexMesh, HexStats), InputError> {
    extract_traced(map, opts).map(|(mesh, st, _)| (mesh, st))
}

/// [`extract`], also returning for each hex the tet of `map` that holds
/// its node (a hex merged from a pair, steps 8e and 11, names the kept one's).
pub fn extract_traced(
    map: &TetMap,
    opts: &HexOptions,
) -> Result<(HexMesh, HexStats, Vec<u32>), InputError> {
    extract_full(map, opts).map(Extracted::traced)
}

/// [`extract_traced`], also returning the map coordinates of each hex's
/// corners ([`HexCorners`]).
pub fn extract_full(map: &TetMap, opts: &HexOptions) -> Result<Extracted, InputError> {
    let mut st = HexStats::default();
    let mut laps = Laps::start();
    // 1–7: the segmentation (1: reflected charts refused; 3: stuck edges
    // and faces split), the input's own counts and shape (not those of
    // the split map) read on the first pass
    let o = steps::Options::new(&opts.transitions, opts.grid_offset, opts.seed);
    let first_pass = |m: &TetMap, model: &Model<4, 3>, singular: &Vec<_>, n: &InputCounts| {
        st.input_tets = m.len();
        st.singular_edges = singular.len();
        st.singular_edge_angles = dualex_map::report::singular_edge_histogram(singular);
        st.reverted_tets = n.reverted;
        st.degenerate_tets = n.degenerate.unwrap_or_default();
        st.input = Some(dualex_check::glued::tet_glued(&model.topo.adj));
    };
    let seg = steps::segment(map, &o, &mut st.segment, &mut laps, first_pass)?;
    let before = st.clone();
    let out = graph_and_mesh(seg, opts, &mut st, &mut laps);
    // a folded map whose glued mesh is invalid: relaxed where it folds and
    // extracted again, the result kept only if valid (issue 22)
    let rest = |seg, s: &mut HexStats, l: &mut Laps| graph_and_mesh(seg, opts, s, l);
    let retried = (!st.mesh_valid && st.segment.reverted_nodes > 0)
        .then(|| relax::retry(map, &o, before, &mut laps, rest, |s| s.mesh_valid))
        .flatten();
    let (out, mut st) = retried.unwrap_or((out, st));
    st.segment.time_ms = laps.into_laps();
    Ok(out.extracted(st))
}

/// Steps 7 (untangling) to 11 on the segmented map.
fn graph_and_mesh(
    seg: Segmented<'_, 4, 3>,
    opts: &HexOptions,
    st: &mut HexStats,
    laps: &mut Laps,
) -> Placed<3, 8> {
    let Segmented {
        sanitized: s,
        nodes,
        mut ends,
        mut graph,
    } = seg;
    st.segment.untangle = Some(graph.untangle());
    laps.lap("untangle");
    // 8a: index fairing on columns (an extruded map's graph: the 2D saddle
    // lifts and folded-corner collapses, in every layer alike)
    if opts.fairing {
        st.column_fairing = graph.fair_columns(FAIRING_MAX_PATH);
        laps.lap("fairing");
    }
    // 8e: chains of valence-2 edges merged in the graph (a merged node's
    // corners traced from the nodes it took them over from)
    let mut takeover = Takeover::default();
    let merged = graph.dissolve_doublets(&mut takeover);
    takeover.carry_sides(&mut ends);
    st.doublets.dissolved = merged.merged;
    st.doublets.edges = merged.pairs;
    st.doublets.rounds = merged.rounds;
    st.doublets.in_graph = merged.merged;
    // 9
    let glued = graph.glue();
    let mut out = place(&s, &nodes, &graph, &glued, &takeover);
    st.finish_output(&glued, &out.mesh);
    // 10: holes through columns repaired locally
    let closed = s.topo.boundary_facets == 0;
    columns::repair_open(&graph, &glued, &ends, closed, &mut out, st);
    // 11: folded hexes collapsed, doublet chains dissolved
    doublets::collapse_and_dissolve(&mut out, st);
    laps.lap("glue_geometry");
    out
}

#[cfg(test)]
mod data_tests;
#[cfg(test)]
use dualex_util::rng;
#[cfg(test)]
mod scan_tests;
#[cfg(test)]
mod testblock;
#[cfg(test)]
mod tests;
