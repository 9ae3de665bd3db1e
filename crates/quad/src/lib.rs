//! # dualex-quad — quad extraction from messy 2D maps
//!
//! The driver [`extract`] runs the pipeline's numbered steps
//! (ARCHITECTURE.md), one call each:
//! 1–7. the segmentation, shared with `dualex-hex`
//!    (`dualex_segment::steps`): 1. the map model; 2. the local map, built
//!    once with the grid offset chosen, singular vertices snapped; 3. edges
//!    joining two singular vertices through a grid point split; 4.
//!    sanitization; 5. nodes; 6. traced sides; 7. the opposite relation,
//!    then untangling ([`graph_steps`]: other orders tried while fairing
//!    leaves valence-1 or 2 vertices, `NodeGraph::untangle_best`);
//! 8. in the graph ([`graph_steps`]): 8a. index fairing (optional); 8b.
//!    folded corners collapsed; 8c. pillows and 8d. [`bubbles`]
//!    (components beyond one per input component) deleted; 8e. doublets
//!    (valence-2 vertices fairing found no partner for) merged
//!    (`dualex_graph::doublet`);
//! 9. [`gluing`]: 9a. glued (`dualex_graph`), holes of two sides zipped;
//!    9b. [`digons`] pinched; 9c. placed: vertex positions by diagonal
//!    tracing, each quad's source triangle and corners' map coordinates
//!    (`dualex_segment::place`, carried along steps 10–11; none for a quad
//!    merged from a doublet, [`corner_uv`] through a subdivision);
//! 10. [`repairs`] on the mesh: 10a. [`ambiguous`] parallel edges and
//!     folded cells split; 10b. [`repair`]: holes closed, faces quads
//!     cannot represent repaired (or subdivided); 10c. [`pinched`]
//!     vertices split, bubbles left by it deleted;
//! 11. [`doublets`]: interior valence-2 vertices the graph did not merge
//!     (made by steps 9–10) dissolved on the mesh.
//!
//! A map with reverted nodes where fairing left valence-1 or 2 vertices
//! (collapsed or dissolved: `dualex quad` warns) is extracted once more,
//! its local map relaxed in the fold regions between steps 3 and 4
//! (`dualex_segment::relax::retry`, issue 22); that result is kept only if
//! valid with no such vertex (`relax` in the stats), else the first one
//! stands.
//!
//! Input: a validated [`TriMap`]. Output: a [`QuadMesh`] and [`QuadStats`]
//! ([`extract_traced`]: also the input triangle holding each quad's node;
//! [`extract_full`]: also the map coordinates of its corners).
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod ambiguous;
pub mod bubbles;
pub mod corner_uv;
pub mod digons;
pub mod doublets;
pub mod gluing;
pub mod graph_steps;
pub mod pinched;
pub mod repair;
pub mod repairs;
mod slots;
pub mod stats;

use dualex_cells::QuadMesh;
use dualex_check::{glued, topology::InputShape};
use dualex_map::{InputError, TransitionOptions, TriMap};
pub use dualex_segment::grid_offset::GridOffset;
use dualex_segment::place::Placed;
use dualex_segment::relax;
use dualex_segment::steps::{self, Segmented};
use dualex_util::timing::Laps;
pub use stats::QuadStats;

/// Options of [`extract`].
#[derive(Clone, Debug)]
pub struct QuadOptions {
    /// Run index fairing after untangling.
    pub fairing: bool,
    /// Transition derivation options.
    pub transitions: TransitionOptions,
    /// Seed of the sanitization perturbations.
    pub seed: u64,
    /// Where the dual grid sits (`--grid-offset`).
    pub grid_offset: GridOffset,
    /// Fill [`QuadStats::singularities`] (the input's singularities by
    /// index: an angle sum at every vertex, ~10 % of the extraction on
    /// maps without singularities; off by default, on where stats are
    /// shown).
    pub singularity_stats: bool,
}

impl Default for QuadOptions {
    fn default() -> Self {
        QuadOptions {
            fairing: true,
            transitions: TransitionOptions::default(),
            seed: 1,
            grid_offset: GridOffset::Auto,
            singularity_stats: false,
        }
    }
}

/// Extracts the quad mesh of `map`.
pub fn extract(map: &TriMap, opts: &QuadOptions) -> Result<(QuadMesh, QuadStats), InputError> {
    extract_traced(map, opts).map(|(mesh, st, _)| (mesh, st))
}

/// In [`extract_traced`]'s sources: a cell that closes a hole (step 10),
/// held by no node.
pub const NO_SOURCE: u32 = u32::MAX;

/// [`extract`], also returning for each quad the triangle of `map` that
/// holds its node ([`NO_SOURCE`] for a face closing a hole). Quads of a
/// subdivision (step 10) name their parent's triangle; a quad merged from
/// two (steps 8e and 11) names the first one's.
pub fn extract_traced(
    map: &TriMap,
    opts: &QuadOptions,
) -> Result<(QuadMesh, QuadStats, Vec<u32>), InputError> {
    extract_full(map, opts).map(Extracted::traced)
}

/// Everything [`extract_full`] returns: the quads, their stats, sources
/// (as [`extract_traced`]) and corners' map coordinates (`corners`, in the
/// quad's corner order: [`corner_uv::QuadCorners`]).
pub type Extracted = dualex_segment::place::Extracted<2, 4, QuadStats>;

/// [`extract_traced`], also returning the map coordinates of each quad's
/// corners ([`corner_uv`]).
pub fn extract_full(map: &TriMap, opts: &QuadOptions) -> Result<Extracted, InputError> {
    let mut st = QuadStats::default();
    let mut laps = Laps::start();
    // 1–7: the segmentation (3: edges between singular vertices split),
    // the input's own counts and shape read on the first pass
    let o = steps::Options::new(&opts.transitions, opts.grid_offset, opts.seed);
    let seg = steps::segment(map, &o, &mut st.segment, &mut laps, |m, model, (), n| {
        st.input_triangles = m.len();
        st.reverted_triangles = n.reverted;
        if opts.singularity_stats {
            st.singularities = stats::input_singularities(m, model);
        }
        let shape = glued::surface_shape(m.positions.len(), &m.simplices, &model.topo.adj);
        st.input = Some(InputShape {
            shape,
            boundary: (),
        });
    })?;
    let before = st.clone();
    let out = graph_and_mesh(seg, opts, (&mut st, &mut laps));
    // a folded map whose degenerate vertices fairing found no partner for
    // (the mesh may differ from the map's there): relaxed where it folds
    // and extracted again, the result kept only if it has none and is
    // valid (issue 22)
    let rest = |seg, s: &mut QuadStats, l: &mut Laps| graph_and_mesh(seg, opts, (s, l));
    let retried = (degenerate(&st) && st.segment.reverted_nodes > 0)
        .then(|| {
            relax::retry(map, &o, before, &mut laps, rest, |s| {
                !degenerate(s) && s.mesh_valid
            })
        })
        .flatten();
    let (out, mut st) = retried.unwrap_or((out, st));
    st.segment.time_ms = laps.into_laps();
    Ok(out.extracted(st))
}

/// Whether fairing left valence-1 or 2 vertices (collapsed or dissolved
/// in the graph: `dualex quad` warns).
fn degenerate(st: &QuadStats) -> bool {
    st.folded_corners_collapsed > 0 || st.doublets.dissolved > 0
}

/// Steps 7 (untangling) to 11 on the segmented map (`seg`), counted in
/// the stats and laps (`stats`).
fn graph_and_mesh(
    seg: Segmented<'_, 3, 2>,
    opts: &QuadOptions,
    (st, laps): (&mut QuadStats, &mut Laps),
) -> Placed<2, 4> {
    let Segmented {
        sanitized: s,
        nodes,
        mut ends,
        mut graph,
    } = seg;
    // 7–8: untangled, faired, cleaned up in the graph
    let steps = graph_steps::run(&mut graph, &mut ends, &s, &nodes, opts, st, laps);
    // 9: glued and placed
    let (glued, mut out) = gluing::glue_and_place(&mut graph, &s, &nodes, steps, st);
    // 10: repairs on the mesh
    repairs::repair(&graph, &glued, &ends, &s.topo, &mut out, st);
    // 11: doublets the graph did not merge (only when the counts show an
    // interior vertex of valence 2)
    if opts.fairing && st.valence_interior.contains_key(&2) {
        doublets::dissolve_left(&mut out, st);
    }
    laps.lap("glue_geometry");
    out
}

#[cfg(test)]
mod tests;
