//! # dualex-hex — hex extraction from messy 3D maps
//!
//! The driver [`extract`] reads as the pipeline's numbered steps, one
//! module each:
//! 1. [`local`]: local shifted coordinates (integer offset per tet), built
//!    once with the grid offset chosen
//!    (`dualex_segment::grid_offset::local_map`);
//!    then [`split`]: edges and faces spanned by unmovable vertices across
//!    the dual grid are split (repeated until none is left);
//! 2. sanitization (`dualex_segment::sanitize`): snap to exact GP, move
//!    vertices off the dual isos (`dualex_segment::near` says what "on"
//!    means at D = 3);
//! 3. [`nodes`]: integer points inside tets, reverted flags;
//! 4. [`trace`]: walk every side along its iso-line to the opposite side;
//! 5. untangling (pleat removal, `dualex_graph`); 5b. on a graph made of
//!    columns (an extruded map's), index fairing and the collapse of
//!    folded corners in every layer (`dualex_graph::columns`); 5c. chains
//!    of valence-2 edges merged in the graph (`dualex_graph::doublet`);
//! 6. gluing (`dualex_graph`) and vertex positions by diagonal tracing
//!    (`dualex_segment::diagonal`); 6b. [`columns`]: holes through
//!    columns (singular edges through dual nodes) repaired as the 2D local
//!    repair, replayed in every layer;
//! 7. [`doublets`]: folded hexes collapsed, chains of valence-2 interior
//!    edges the graph did not merge dissolved (in rounds);
//! 8. [`corner_uvw`]: each hex's corners in its node's chart (kept along
//!    steps 6b and 7).
//!
//! Input: a [`TetMap`]. Output: a [`HexMesh`] (VTK order) and [`HexStats`]
//! ([`extract_traced`]: also the input tet holding each hex's node;
//! [`extract_full`]: also the map coordinates of its corners).
//! Walks that leave the mesh leave their side unmatched: free boundaries
//! become boundary faces of the hex mesh.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod columns;
pub mod corner_uvw;
pub mod doublets;
pub mod local;
pub mod nodes;
pub mod split;
pub mod stats;
pub mod trace;

use dualex_cells::HexMesh;
use dualex_graph::{NodeGraph, Takeover};
use dualex_map::singularity::{edge_singularities_with_stars, quality};
use dualex_map::{InputError, Stars, TetMap, Topology, TransitionOptions, Transitions};
use dualex_segment::diagonal::diagonal;
pub use dualex_segment::grid_offset::GridOffset;
use dualex_util::timing::Laps;
pub use stats::HexStats;

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

/// Extracts the hex mesh of `map`.
pub fn extract(map: &TetMap, opts: &HexOptions) -> Result<(HexMesh, HexStats), InputError> {
    extract_traced(map, opts).map(|(mesh, st, _)| (mesh, st))
}

/// [`extract`], also returning for each hex the tet of `map` that holds
/// its node (a hex merged from a pair, steps 5c and 7, names the kept one's).
pub fn extract_traced(
    map: &TetMap,
    opts: &HexOptions,
) -> Result<(HexMesh, HexStats, Vec<u32>), InputError> {
    extract_full(map, opts).map(|x| (x.mesh, x.stats, x.sources))
}

/// Everything [`extract_full`] returns.
#[derive(Clone, Debug)]
pub struct Extracted {
    /// The hex mesh.
    pub mesh: HexMesh,
    /// Its counts.
    pub stats: HexStats,
    /// Per hex, the input tet holding its node (as [`extract_traced`]).
    pub sources: Vec<u32>,
    /// Per hex, its corners' map coordinates in that tet's chart
    /// ([`corner_uvw`]), in VTK order.
    pub corner_uvw: Vec<corner_uvw::HexCorners>,
}

/// [`extract_traced`], also returning the map coordinates of each hex's
/// corners ([`corner_uvw`]).
pub fn extract_full(map: &TetMap, opts: &HexOptions) -> Result<Extracted, InputError> {
    let mut st = HexStats::default();
    let mut laps = Laps::start();
    map.validate()?;
    nodes::check_size(map)?;
    map.check_not_reflected()?;
    st.input_tets = map.len();
    let owned;
    // the input tet of each tet of the (split) map
    let mut parent: Vec<u32> = (0..map.len() as u32).collect();
    let (map, topo, stars, mut local, singular_snap, free) = {
        let mut map = std::borrow::Cow::Borrowed(map);
        loop {
            let topo = Topology::build(&map)?;
            let (trans, trep) = Transitions::derive(&map, &topo, &opts.transitions)?;
            st.max_transition_residual = trep.max_residual;
            st.snapped_transitions = trep.snapped;
            let stars = Stars::build(&map, &topo, &trans);
            let singular = edge_singularities_with_stars(&map, &topo, &trans, &stars);
            if st.split_faces == 0 {
                // the input's own counts, not those of the split map
                st.singular_vertices = stars.singular.iter().filter(|&&s| s).count();
                st.singular_edges = singular.len();
                st.singular_edge_angles = dualex_map::report::singular_edge_histogram(&singular);
                (st.reverted_tets, st.degenerate_tets) = quality(&map);
            }
            // 1: the grid offset chosen (on the first pass), then the local
            // map built with it, taking over the transitions (no second
            // copy), its singular vertices exactly on their fixed sets
            let chosen = (st.split_faces > 0).then_some(st.grid_offset);
            let (local, snap, choice) = dualex_segment::grid_offset::local_map(
                &map,
                &topo,
                trans,
                &stars,
                opts.grid_offset,
                chosen,
            );
            st.grid_offset = choice;
            // 1b: edges and faces that unmovable vertices span across the grid
            let pairs = singular
                .iter()
                .map(|e| (e.edge[0].min(e.edge[1]), e.edge[0].max(e.edge[1])))
                .collect();
            let free = dualex_segment::sanitize::free_axes(&topo, &stars, &local);
            let faces = split::faces_to_split(&map, &stars, &free, &pairs, &local);
            if faces.is_empty() || st.split_faces >= st.input_tets {
                owned = map;
                break (&*owned, topo, stars, local, snap, free);
            }
            let (next, applied, pieces) = dualex_segment::split::split_faces_traced(&map, &faces);
            parent = pieces.iter().map(|&p| parent[p as usize]).collect();
            st.split_faces += applied;
            map = std::borrow::Cow::Owned(next);
        }
    };
    laps.lap("map");
    // 2
    st.sanitize =
        dualex_segment::sanitize::sanitize(map, &topo, &stars, &free, &mut local, opts.seed);
    st.sanitize.singular_snap = singular_snap;
    drop(stars);
    laps.lap("sanitize");
    // 3
    let nodes = nodes::Nodes::find(&local);
    st.nodes = nodes.len();
    st.reverted_nodes = nodes.reverted.iter().filter(|&&r| r).count();
    laps.lap("nodes");
    // 4
    let (mut ends, trep) = trace::trace_all(&local, &topo, &nodes);
    st.trace = trep;
    let mut graph = NodeGraph::<3>::new(nodes.reverted.clone());
    st.links = graph.link_mutual(&ends);
    st.isolated_dropped = graph.drop_isolated_lost(&ends);
    st.label_violations = graph.label_violations();
    laps.lap("trace");
    // 5
    st.untangle = Some(graph.untangle());
    laps.lap("untangle");
    // 5b: index fairing on columns (an extruded map's graph: the 2D saddle
    // lifts and folded-corner collapses, in every layer alike)
    if opts.fairing {
        st.column_fairing = graph.fair_columns(FAIRING_MAX_PATH);
        laps.lap("fairing");
    }
    // 5c: chains of valence-2 edges merged in the graph (a merged node's
    // corners traced from the nodes it took them over from)
    let mut takeover = Takeover::default();
    let merged = graph.dissolve_doublets(&mut takeover);
    takeover.carry_sides(&mut ends);
    st.doublets.dissolved = merged.merged;
    st.doublets.edges = merged.pairs;
    st.doublets.rounds = merged.rounds;
    st.doublets.in_graph = merged.merged;
    // 6
    let glued = graph.glue();
    let mut mesh = place_vertices(map, &local, &topo, &nodes, &glued, &takeover);
    let mut source: Vec<u32> = glued
        .cells()
        .map(|(node, _)| parent[nodes.simplex[node.idx()] as usize])
        .collect();
    let mut corners = corner_uvw::of_glued(&glued, &graph, &local, &nodes, &takeover);
    st.finish_output(&graph, &glued, &mesh);
    // cracks: unmatched sides that are not on the input's boundary
    st.open_interior_faces = graph.lost_unmatched_sides(&ends, topo.boundary_facets == 0);
    // 6b: holes through columns (an extruded map's singular edges through
    // nodes) repaired locally, as the 2D local repair in every layer
    if st.open_interior_faces > 0 {
        let open = open_faces(&graph, &glued, &ends, topo.boundary_facets == 0);
        if let Some(rep) = columns::repair(&mesh, &open) {
            st.columns = rep.report;
            st.open_interior_faces -= open.len().min(st.open_interior_faces);
            corners = dualex_cells::corners::carry(&mesh, &corners, &rep.mesh, &rep.origin);
            mesh = rep.mesh;
            source = rep.origin.iter().map(|&o| source[o as usize]).collect();
            st.finish_mesh(&mesh);
        }
    }
    // 7: folded hexes collapsed, doublet chains dissolved (the extrusions
    // of the 2D collapse of folded quads and of doublet removal)
    // (only when the checker's counts show a repeated corner or an
    // interior edge of valence 2: both passes hash every edge)
    let repeated = mesh
        .cells
        .iter()
        .any(|h| (0..8).any(|i| (i + 1..8).any(|j| h[i] == h[j])));
    if repeated || st.edge_valence_interior.contains_key(&2) {
        let (collapsed, folded, kept_folded) = doublets::collapse_folded_traced(&mesh);
        let (dissolved, chains, kept_chains) = doublets::dissolve_all_traced(&collapsed);
        st.folded_collapsed = folded;
        st.doublets.dissolved += chains.dissolved;
        st.doublets.edges += chains.edges;
        st.doublets.rounds += chains.rounds;
        st.doublets.left = chains.left;
        if folded + chains.edges > 0 {
            corners = dualex_cells::corners::carry(&mesh, &corners, &collapsed, &kept_folded);
            corners = dualex_cells::corners::carry(&collapsed, &corners, &dissolved, &kept_chains);
            mesh = dissolved;
            source = kept_chains
                .iter()
                .map(|&k| source[kept_folded[k as usize] as usize])
                .collect();
            st.finish_mesh(&mesh);
        }
    }
    laps.lap("glue_geometry");
    st.time_ms = laps.into_laps();
    Ok(Extracted {
        mesh,
        stats: st,
        sources: source,
        corner_uvw: corners,
    })
}

/// The corners of the unmatched sides that are cracks, not boundary (see
/// `NodeGraph::lost_unmatched_sides`).
fn open_faces(
    graph: &NodeGraph<3>,
    glued: &dualex_graph::Glued<3>,
    ends: &[trace::End],
    closed: bool,
) -> Vec<[u32; 4]> {
    graph
        .lost_sides(ends, closed)
        .map(|s| {
            let (node, d) = (graph.node_of(s), graph.dir_of(s));
            // the side's corners: cube codes with the axis bit of its side
            let (axis, want) = (d >> 1, usize::from(d & 1 == 0));
            let mut f = [0u32; 4];
            let codes = (0..8).filter(|c| (c >> axis) & 1 == want);
            for (k, c) in codes.enumerate() {
                f[k] = glued.vertex(node, c);
            }
            f
        })
        .collect()
}

/// Positions of the glued vertices by diagonal tracing (corner code bits:
/// bit0 u, bit1 v, bit2 w, set = + side; a corner taken over by a doublet
/// merge traced from the node it belonged to).
fn place_vertices(
    map: &TetMap,
    local: &local::LocalMap,
    topo: &Topology<4>,
    nodes: &nodes::Nodes,
    glued: &dualex_graph::Glued<3>,
    takeover: &Takeover<3>,
) -> HexMesh {
    let best = glued.best_per_vertex(
        takeover,
        |node, code| {
            let sgn = [0, 1, 2].map(|a| if code >> a & 1 == 1 { 1.0 } else { -1.0 });
            diagonal(map, local, topo, nodes, node.idx(), sgn)
        },
        |c| c.dist,
    );
    HexMesh {
        positions: best.iter().map(|b| b.map_or([0.0; 3], |c| c.pos)).collect(),
        cells: glued.cells().map(|(_, h)| h).collect(),
    }
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
