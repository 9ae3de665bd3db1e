//! # dualex-quad — quad extraction from messy 2D maps
//!
//! The driver [`extract`] reads as the pipeline's numbered steps, one
//! module each:
//! 1. [`local`]: local shifted coordinates (integer offset per triangle);
//! 2. [`sanitize`]: snap to exact GP, move vertices off the dual isos;
//! 3. [`nodes`]: integer points inside triangles, reverted flags;
//! 4. [`trace`]: walk every side along its iso to the opposite side;
//! 5. untangling (pleat removal, `dualex_graph`);
//! 6. index fairing (`dualex_graph`, optional);
//! 7. gluing (`dualex_graph`) and [`geometry`]: vertex positions by
//!    diagonal tracing.
//!
//! Input: a validated [`TriMap`]. Output: a [`QuadMesh`] and [`QuadStats`].
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod fairing;
pub mod geometry;
pub mod local;
pub mod nodes;
mod rng;
pub mod sanitize;
pub mod split;
pub mod stats;
pub mod trace;

use dualex_graph::{NodeGraph, Side};
use dualex_map::{InputError, QuadMesh, Stars, Topology, TransitionOptions, Transitions, TriMap};
pub use stats::QuadStats;
use std::time::Instant;

/// Options of [`extract`].
#[derive(Clone, Debug)]
pub struct QuadOptions {
    /// Run index fairing after untangling.
    pub fairing: bool,
    /// Transition derivation options.
    pub transitions: TransitionOptions,
    /// Seed of the sanitization perturbations.
    pub seed: u64,
}

impl Default for QuadOptions {
    fn default() -> Self {
        QuadOptions {
            fairing: true,
            transitions: TransitionOptions::default(),
            seed: 1,
        }
    }
}

/// Extracts the quad mesh of `map`.
pub fn extract(map: &TriMap, opts: &QuadOptions) -> Result<(QuadMesh, QuadStats), InputError> {
    let mut st = QuadStats::default();
    let mut clock = Instant::now();
    let mut lap = |st: &mut QuadStats, name: &str| {
        let ms = clock.elapsed().as_secs_f64() * 1e3;
        st.time_ms.push((name.to_string(), ms));
        clock = Instant::now();
    };
    map.validate()?;
    st.input_triangles = map.len();
    st.reverted_triangles = (0..map.len()).filter(|&s| map.map_det(s) < 0.0).count();
    let mut owned;
    let mut map = map;
    let (topo, trans, stars, mut local) = loop {
        let topo = Topology::build(map)?;
        let (trans, trep) = Transitions::derive(map, &topo, &opts.transitions)?;
        st.max_transition_residual = trep.max_residual;
        st.snapped_transitions = trep.snapped;
        let stars = Stars::build(map, &topo, &trans);
        st.singular_vertices = stars.singular.iter().filter(|&&s| s).count();
        // 1
        let local = local::LocalMap::new(map, &topo, &trans);
        let edges = split::edges_to_split(map, &topo, &stars, &local);
        if edges.is_empty() || st.split_edges >= map.len() {
            break (topo, trans, stars, local);
        }
        st.split_edges += edges.len();
        owned = split::split_edges(map, &topo, &edges);
        map = &owned;
    };
    let _ = &trans;
    lap(&mut st, "map");
    // 2
    st.sanitize = sanitize::sanitize(map, &topo, &stars, &mut local, opts.seed);
    lap(&mut st, "sanitize");
    // 3
    let nodes = nodes::Nodes::find(&local);
    st.nodes = nodes.len();
    st.reverted_nodes = nodes.reverted.iter().filter(|&&r| r).count();
    lap(&mut st, "nodes");
    // 4
    let (ends, trep) = trace::trace_all(&local, &topo, &nodes);
    st.trace = trep;
    let mut graph = NodeGraph::<2>::new(nodes.reverted.clone());
    link_mutual(&mut graph, &ends, &mut st);
    st.label_violations = graph.label_violations();
    lap(&mut st, "trace");
    // 5
    st.untangle = Some(graph.untangle());
    lap(&mut st, "untangle");
    // 6
    if opts.fairing {
        st.fairing = Some(fairing::fair(&mut graph));
    }
    // 6b: a valence-1 vertex left (no partner for fairing) is a folded quad;
    // collapse it so the output has no repeated vertex
    st.folded_corners_collapsed = graph.collapse_folded_corners();
    lap(&mut st, "fairing");
    // 7
    let glued = graph.glue();
    let mesh = place_vertices(map, &local, &topo, &nodes, &glued);
    st.finish_output(&graph, &glued, &mesh);
    lap(&mut st, "glue_geometry");
    Ok((mesh, st))
}

/// Links the sides whose walks reached each other.
fn link_mutual(graph: &mut NodeGraph<2>, ends: &[trace::End], st: &mut QuadStats) {
    for (a, end) in ends.iter().enumerate() {
        let trace::End::Node { side: b, rho } = *end else {
            continue;
        };
        let b = b as usize;
        if b < a {
            continue;
        }
        match ends.get(b) {
            Some(trace::End::Node { side, rho: back }) if *side as usize == a => {
                if *back != rho.inverse() {
                    st.rotation_mismatches += 1;
                }
                if b == a {
                    st.non_mutual += 1;
                    continue;
                }
                if graph.link(Side(a as u32), Side(b as u32), rho).is_err() {
                    st.non_mutual += 1;
                }
            }
            _ => st.non_mutual += 1,
        }
    }
}

/// Positions of the glued vertices by diagonal tracing.
fn place_vertices(
    map: &TriMap,
    local: &local::LocalMap,
    topo: &Topology<3>,
    nodes: &nodes::Nodes,
    glued: &dualex_graph::Glued<2>,
) -> QuadMesh {
    let nv = glued.n_vertices;
    let mut best: Vec<Option<geometry::Candidate>> = vec![None; nv];
    for (node, _) in glued.cells() {
        let n = node.idx();
        for code in 0..4 {
            let v = glued.vertex(node, code) as usize;
            if best[v].is_some_and(|b| b.dist == 0.0) {
                continue;
            }
            let su = if code & 1 == 1 { 1.0 } else { -1.0 };
            let sv = if code & 2 == 2 { 1.0 } else { -1.0 };
            let c = geometry::diagonal(map, local, topo, nodes, n, su, sv);
            if best[v].is_none_or(|b| c.dist < b.dist) {
                best[v] = Some(c);
            }
        }
    }
    QuadMesh {
        positions: best.iter().map(|b| b.map_or([0.0; 3], |c| c.pos)).collect(),
        cells: glued.cells().map(|(_, q)| q).collect(),
    }
}

#[cfg(test)]
mod tests;
