//! # dualex-quad — quad extraction from messy 2D maps
//!
//! The driver [`extract`] reads as the pipeline's numbered steps, one
//! module each:
//! 1. [`local`]: local shifted coordinates (integer offset per triangle),
//!    built once with the grid offset chosen
//!    (`dualex_segment::grid_offset::local_map`);
//! 2. sanitization (`dualex_segment::sanitize`): snap to exact GP, move
//!    vertices off the dual isos;
//! 3. [`nodes`]: integer points inside triangles, reverted flags;
//! 4. [`trace`]: walk every side along its iso to the opposite side;
//! 5. untangling (pleat removal, `dualex_graph`; other orders tried while
//!    fairing leaves valence-1 or 2 vertices, `NodeGraph::untangle_best`);
//! 6. index fairing (`dualex_graph`, optional); folded corners collapsed,
//!    pillows and [`bubbles`] (components beyond one per input component)
//!    deleted; doublets (valence-2 vertices fairing found no partner for)
//!    merged in the graph (`dualex_graph::doublet`, with fairing);
//! 7. gluing (`dualex_graph`; [`digons`] pinched off) and vertex
//!    positions by diagonal tracing (`dualex_segment::diagonal`);
//! 8. [`ambiguous`]: parallel edges and folded cells split; [`repair`]:
//!    holes closed, faces quads cannot represent repaired (or subdivided);
//!    [`pinched`] vertices split, bubbles left by it deleted;
//! 9. [`doublets`]: interior valence-2 vertices the graph did not merge
//!    (made by steps 7–8) dissolved on the mesh;
//! 10. [`corner_uv`]: each quad's corners in its node's chart (kept along
//!     steps 7–9; none for a quad merged from a doublet).
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
mod fairing;
pub mod local;
pub mod nodes;
pub mod pinched;
pub mod repair;
mod slots;
pub mod split;
pub mod stats;
pub mod trace;

use dualex_cells::QuadMesh;
use dualex_graph::{Node, NodeGraph, Side, Takeover};
use dualex_map::{InputError, Stars, Topology, TransitionOptions, Transitions, TriMap};
use dualex_segment::diagonal::diagonal;
pub use dualex_segment::grid_offset::GridOffset;
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

/// In [`extract_traced`]'s sources: a cell that closes a hole (step 8),
/// held by no node.
pub const NO_SOURCE: u32 = u32::MAX;

/// [`extract`], also returning for each quad the triangle of `map` that
/// holds its node ([`NO_SOURCE`] for a face closing a hole). Quads of a
/// subdivision (step 8) name their parent's triangle; a quad merged from
/// two (steps 6e and 9) names the first one's.
pub fn extract_traced(
    map: &TriMap,
    opts: &QuadOptions,
) -> Result<(QuadMesh, QuadStats, Vec<u32>), InputError> {
    extract_full(map, opts).map(|x| (x.mesh, x.stats, x.sources))
}

/// Everything [`extract_full`] returns.
#[derive(Clone, Debug)]
pub struct Extracted {
    /// The quad mesh.
    pub mesh: QuadMesh,
    /// Its counts.
    pub stats: QuadStats,
    /// Per quad, the input triangle holding its node (as
    /// [`extract_traced`]).
    pub sources: Vec<u32>,
    /// Per quad, its corners' map coordinates in that triangle's chart
    /// ([`corner_uv`]), in the quad's corner order.
    pub corner_uv: Vec<corner_uv::QuadCorners>,
}

/// [`extract_traced`], also returning the map coordinates of each quad's
/// corners ([`corner_uv`]).
pub fn extract_full(map: &TriMap, opts: &QuadOptions) -> Result<Extracted, InputError> {
    let mut st = QuadStats::default();
    let mut laps = Laps::start();
    map.validate()?;
    nodes::check_size(map)?;
    st.input_triangles = map.len();
    st.reverted_triangles = (0..map.len()).filter(|&s| map.map_det(s) < 0.0).count();
    let mut owned;
    let mut map = map;
    // the input triangle of each triangle of the (split) map
    let mut parent: Vec<u32> = (0..map.len() as u32).collect();
    let mut grid: Option<dualex_segment::grid_offset::OffsetChoice> = None;
    let (topo, stars, mut local, singular_snap) = loop {
        let topo = Topology::build(map)?;
        let (trans, trep) = Transitions::derive(map, &topo, &opts.transitions)?;
        st.max_transition_residual = trep.max_residual;
        st.snapped_transitions = trep.snapped;
        let stars = Stars::build(map, &topo, &trans);
        st.singular_vertices = stars.singular.iter().filter(|&&s| s).count();
        if grid.is_none() && opts.singularity_stats {
            // the input's singularities (integer part unknown: "k/4 mod 1")
            let (known, unknown) = dualex_map::report::singularity_histogram(map, &topo, &trans);
            st.singularities = known;
            st.singularities
                .extend(unknown.into_iter().map(|(k, n)| (format!("{k} mod 1"), n)));
        }
        // 1: the grid offset chosen (on the first pass), then the local map
        // built with it, taking over the transitions (no second copy), its
        // singular vertices exactly on their fixed points before any test
        let (local, snap, choice) = dualex_segment::grid_offset::local_map(
            map,
            &topo,
            trans,
            &stars,
            opts.grid_offset,
            grid,
        );
        grid = Some(choice);
        st.grid_offset = choice;
        let edges = split::edges_to_split(map, &topo, &stars, &local);
        if edges.is_empty() || st.split_edges >= map.len() {
            break (topo, stars, local, snap);
        }
        let (applied, pieces);
        (owned, applied, pieces) = split::split_edges_traced(map, &edges);
        parent = pieces.iter().map(|&p| parent[p as usize]).collect();
        st.split_edges += applied;
        map = &owned;
    };
    laps.lap("map");
    // 2
    st.sanitize =
        dualex_segment::sanitize::sanitize(map, &topo, &stars, &[], &mut local, opts.seed);
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
    let mut graph = NodeGraph::<2>::new(nodes.reverted.clone());
    st.links = graph.link_mutual(&ends);
    st.isolated_dropped = graph.drop_isolated_lost(&ends);
    st.label_violations = graph.label_violations();
    laps.lap("trace");
    // 5 + 6: untangling and index fairing; while fairing leaves valence-1
    // or 2 vertices, other untangling orders are tried (`untangle_best`)
    let (ust, fst) = graph.untangle_best(fairing::UNTANGLE_ORDERS, |g| {
        if opts.fairing {
            let f = fairing::fair(g);
            let left = f.valence1_after + f.valence2_after;
            (Some(f), left)
        } else {
            (None, 0)
        }
    });
    st.untangle = Some(ust);
    st.fairing = fst.map(|f| f.to_json());
    laps.lap("untangle");
    // 6b: a valence-1 vertex left (no partner for fairing) is a folded quad;
    // collapse it so the output has no repeated vertex
    st.folded_corners_collapsed = graph.collapse_folded_corners();
    // 6c: two nodes glued only to each other (a fold pocket detached as a
    // component of its own) are deleted
    st.pillows_removed = graph.remove_pillows();
    // 6d: bubbles beside the surface of their input component
    st.bubbles_removed = bubbles::drop_bubbles(&mut graph, &topo, &nodes.simplex);
    // 6e: doublets that fairing found no partner for, merged in the graph
    // (a merged node's corner traced from the node it took it over from)
    let mut takeover = Takeover::default();
    if opts.fairing {
        let merged = graph.dissolve_doublets(&mut takeover);
        takeover.carry_sides(&mut ends);
        st.doublets.dissolved = merged.merged;
        st.doublets.in_graph = merged.merged;
    }
    laps.lap("fairing");
    // 7
    let mut glued = graph.glue();
    st.zipped_sides = zip_two_side_holes(&mut graph, &glued);
    if st.zipped_sides > 0 {
        // a pair of adjacent sides of one node zipped is a folded corner
        st.folded_corners_collapsed += graph.collapse_folded_corners();
        glued = graph.glue();
    }
    // 7b: two edges between the same two vertices pinched off, the smaller
    // piece deleted as a bubble
    // (on a closed connected input, also digons around handles the input
    // does not have)
    let handles = |graph: &NodeGraph<2>| {
        let closed = topo.boundary_facets == 0 && glued.components == 1;
        let input_euler = || {
            let shape = dualex_check::topology::surface_shape(map.positions.len(), &map.simplices);
            (shape.components == 1).then_some(shape.euler)
        };
        match closed.then(input_euler).flatten() {
            Some(e) => digons::excess_handles(graph, &glued, e),
            None => 0,
        }
    };
    st.digons_pinched = digons::pinch_digons(&mut graph, &glued, handles);
    if st.digons_pinched > 0 {
        st.bubbles_removed += bubbles::drop_bubbles(&mut graph, &topo, &nodes.simplex);
        glued = graph.glue();
    }
    let mut mesh = place_vertices(map, &local, &topo, &nodes, &glued, &takeover);
    let mut source: Vec<u32> = glued
        .cells()
        .map(|(node, _)| parent[nodes.simplex[node.idx()] as usize])
        .collect();
    let mut corners = corner_uv::of_glued(&glued, &graph, &local, &nodes, &takeover);
    st.finish_output(&graph, &glued, &mesh);
    // 8a: parallel edges and folded cells split by their identity in the
    // graph, so that vertex pairs name every edge of the repair
    let slots = slots::cell_slots(&graph, &glued);
    let holes = slots::hole_slots(&graph, &glued, &slots, &ends, topo.boundary_facets == 0);
    let amb = ambiguous::split(&mesh, &slots.partner, &holes);
    st.parallel_edges_split = amb.parallel_edges;
    st.folded_cells_cut = amb.folded_cells;
    // 8b: holes closed, faces quads cannot represent repaired
    let (fill, open) = dualex_cells::polygons::hole_polygons(&amb.hole_edges);
    st.holes_left_open = open;
    if let Some(rep) = repair::repair_polygons(&amb.positions, &amb.polys, &fill, amb.changed()) {
        st.repair_triangles = repair::odd_cells(&mesh);
        st.holes_filled = fill.len();
        st.repair_dropped = rep.dropped;
        st.subdivided = rep.subdivided;
        st.repair_paths = rep.local_paths;
        st.pinched_vertices_split = rep.pinched;
        // the collapsed sides of the triangles were unmatched sides whose
        // two corners are one vertex, and the filled holes' sides are glued
        // to the new faces: neither is boundary
        let collapsed = collapsed_unmatched_sides(&graph, &glued);
        st.unmatched_sides -= (collapsed + holes.len()).min(st.unmatched_sides);
        st.boundary_loops -= (collapsed + fill.len()).min(st.boundary_loops);
        // origins: a polygon of `amb` (then its cell; its corners only
        // where it is the cell unchanged) or a hole fill
        let cell_of = |o: u32| amb.origin.get(o as usize).copied().unwrap_or(NO_SOURCE);
        let intact_cell = |o: u32| match amb.intact.get(o as usize) {
            Some(true) => cell_of(o),
            _ => NO_SOURCE,
        };
        let carried: Vec<u32> = rep.origin.iter().map(|&o| intact_cell(o)).collect();
        corners = if rep.subdivided {
            corner_uv::subdivided(&mesh, &corners, &rep.mesh, &carried)
        } else {
            dualex_cells::corners::carry(&mesh, &corners, &rep.mesh, &carried)
        };
        source = rep
            .origin
            .iter()
            .map(|&o| {
                source
                    .get(cell_of(o) as usize)
                    .copied()
                    .unwrap_or(NO_SOURCE)
            })
            .collect();
        mesh = rep.mesh;
        // 8c: a pinch point split can leave a pocket of a fold beside the
        // surface, and a node cut off the rest closed by its hole fill is a
        // pillow: deleted as the bubbles of step 6d are
        if let Some((kept, deleted)) = bubbles::drop_mesh_bubbles(&mesh, &topo, &source) {
            st.bubbles_removed += deleted;
            let cells = kept.iter().map(|&c| mesh.cells[c as usize]).collect();
            let pruned = QuadMesh {
                positions: mesh.positions.clone(),
                cells,
            };
            corners = dualex_cells::corners::carry(&mesh, &corners, &pruned, &kept);
            source = kept.iter().map(|&c| source[c as usize]).collect();
            mesh = pruned.without_unused_vertices();
        }
        st.finish_mesh(&mesh);
    }
    // 9: doublets the graph did not merge (only when the counts show an
    // interior vertex of valence 2)
    if opts.fairing && st.valence_interior.contains_key(&2) {
        let (dissolved, rep, kept) = doublets::dissolve_traced(&mesh);
        st.doublets.dissolved += rep.dissolved;
        st.doublets.left = rep.left;
        if rep.dissolved > 0 {
            corners = dualex_cells::corners::carry(&mesh, &corners, &dissolved, &kept);
            mesh = dissolved;
            source = kept.iter().map(|&k| source[k as usize]).collect();
            st.finish_mesh(&mesh);
        }
    }
    laps.lap("glue_geometry");
    st.time_ms = laps.into_laps();
    Ok(Extracted {
        mesh,
        stats: st,
        sources: source,
        corner_uv: corners,
    })
}

/// The two corners (vertex ids) of side `d` of `node`, in the order of the
/// perpendicular axis (− then +).
fn side_corners(glued: &dualex_graph::Glued<2>, node: Node, d: usize) -> [u32; 2] {
    let (axis, bit) = (d >> 1, usize::from(d & 1 == 0));
    let other = 1 - axis;
    let code = |o: usize| (bit << axis) | (o << other);
    [glued.vertex(node, code(0)), glued.vertex(node, code(1))]
}

/// Holes of exactly two unmatched sides whose endpoints the gluing already
/// identified (union–find would close them silently, DESIGN §3.4): glue the
/// two sides to each other explicitly, with the rotation that maps one
/// side's corners onto the other's. Returns the number of pairs glued.
fn zip_two_side_holes(graph: &mut NodeGraph<2>, glued: &dualex_graph::Glued<2>) -> usize {
    let mut by_ends: std::collections::HashMap<(u32, u32), Vec<Side>> = Default::default();
    for (node, _) in glued.cells() {
        for d in 0..4 {
            let s = graph.side(node, d);
            if graph.opposite(s).is_none() {
                let [a, b] = side_corners(glued, node, d);
                if a != b {
                    by_ends.entry((a.min(b), a.max(b))).or_default().push(s);
                }
            }
        }
    }
    let mut zipped = 0;
    for sides in by_ends.values() {
        let [s, t] = sides[..] else { continue };
        // the rotation ρ with the label rule's image of s and matching corners
        if let Some(r) = digons::matching_rotation(graph, glued, s, t) {
            if graph.link(s, t, r).is_ok() {
                zipped += 1;
            }
        }
    }
    zipped
}

/// Unmatched sides whose two corners are the same vertex (a loop of one
/// side: the collapsed edge of a triangle, see [`repair`]).
fn collapsed_unmatched_sides(graph: &NodeGraph<2>, glued: &dualex_graph::Glued<2>) -> usize {
    let mut n = 0;
    for (node, _) in glued.cells() {
        for d in 0..4 {
            if graph.opposite(graph.side(node, d)).is_some() {
                continue;
            }
            let (axis, bit) = (d >> 1, if d & 1 == 0 { 1 } else { 0 });
            let codes: Vec<usize> = (0..4).filter(|c| (c >> axis) & 1 == bit).collect();
            if glued.vertex(node, codes[0]) == glued.vertex(node, codes[1]) {
                n += 1;
            }
        }
    }
    n
}

/// Positions of the glued vertices by diagonal tracing (a corner taken
/// over by a doublet merge from the node it belonged to).
fn place_vertices(
    map: &TriMap,
    local: &local::LocalMap,
    topo: &Topology<3>,
    nodes: &nodes::Nodes,
    glued: &dualex_graph::Glued<2>,
    takeover: &Takeover<2>,
) -> QuadMesh {
    let best = glued.best_per_vertex(
        takeover,
        |node, code| {
            let su = if code & 1 == 1 { 1.0 } else { -1.0 };
            let sv = if code & 2 == 2 { 1.0 } else { -1.0 };
            diagonal(map, local, topo, nodes, node.idx(), [su, sv])
        },
        |c| c.dist,
    );
    QuadMesh {
        positions: best.iter().map(|b| b.map_or([0.0; 3], |c| c.pos)).collect(),
        cells: glued.cells().map(|(_, q)| q).collect(),
    }
}

#[cfg(test)]
mod tests;
