//! Step 9, D = 2: the graph glued into quads and placed.
//! - 9a. glued (`dualex_graph`: union–find over node corners); holes of
//!   exactly two unmatched sides whose endpoints the gluing already
//!   identified (union–find would close them silently, DESIGN §3.4) are
//!   zipped: the two sides glued to each other explicitly, with the
//!   rotation that maps one side's corners onto the other's; a pair of
//!   adjacent sides of one node zipped is a folded corner, collapsed;
//! - 9b. two edges between the same two vertices pinched off, the smaller
//!   piece deleted as a bubble ([`crate::digons`]; on a closed connected
//!   input, also digons around handles the input does not have);
//! - 9c. placed (`dualex_segment::place`): vertex positions by diagonal
//!   tracing, each quad's source triangle and corners' map coordinates.
//!
//! 9c runs first, with the output's check of the same cells beside it;
//! 9b runs only where that check finds an edge of more than two cells or
//! a cell it leaves out, or a pair's corners did not match, and a pinch
//! glues and places again.
//!
//! Input: the cleaned graph of step 8, the sanitized map, its nodes, the
//! corners merges took over and fairing's vertices of the graph when
//! unchanged since (not found again). Output: the gluing, the placed
//! quads, the output counts. Invariant: the graph changes only by the zipped pairs,
//! the collapsed folded corners and the pinched digons' pieces.

use crate::graph_steps::Steps;
use crate::{bubbles, digons, QuadStats};
use dualex_graph::{Glued, Node, NodeGraph, Side};
use dualex_segment::nodes::Nodes;
use dualex_segment::place::{place, Placed};
use dualex_segment::steps::Sanitized;
use rayon::prelude::*;

/// Step 9 (module docs).
pub fn glue_and_place(
    graph: &mut NodeGraph<2>,
    s: &Sanitized<'_, 3, 2>,
    nodes: &Nodes<3, 2>,
    steps: Steps,
    st: &mut QuadStats,
) -> (Glued<2>, Placed<2, 4>) {
    let takeover = &steps.takeover;
    // 9a (fairing's vertices of this very graph: asserted where the
    // crate's tests extract)
    #[cfg(test)]
    if let Some(v) = &steps.vertices {
        assert!(
            graph.glue_from(Some(v.clone())) == graph.glue(),
            "stale vertices"
        );
    }
    let mut glued = graph.glue_from(steps.vertices);
    st.zipped_sides = zip_two_side_holes(graph, &glued);
    if st.zipped_sides > 0 {
        st.folded_corners_collapsed += graph.collapse_folded_corners();
        glued = graph.glue();
    }
    // 9b's allowance of handles (asked only when a digon is found)
    let handles = |graph: &NodeGraph<2>| {
        let closed = s.topo.boundary_facets == 0 && glued.components == 1;
        let input_euler = || {
            let shape =
                dualex_check::topology::surface_shape(s.map.positions.len(), &s.map.simplices);
            (shape.components == 1).then_some(shape.euler)
        };
        match closed.then(input_euler).flatten() {
            Some(e) => digons::excess_handles(graph, &glued, e),
            None => 0,
        }
    };
    // 9c, and the output's check of the same cells beside it (the placed
    // mesh has the gluing's cells and vertices)
    let (mut out, checked) = {
        let g = &*graph;
        rayon::join(
            || place(s, nodes, g, &glued, takeover),
            || digons::check(&glued),
        )
    };
    #[cfg(test)]
    assert!(checked == dualex_check::check_quad_mesh(out.mesh.positions.len(), &out.mesh.cells));
    // 9b, only where the check finds an edge of more than two cells or a
    // cell it leaves out, or a pair's corners did not match (two glued
    // pairs between the same two vertices are four uses of one edge of
    // good cells)
    let clean = digons::none_by_check(&glued, &checked);
    #[cfg(test)]
    assert!(
        !clean || !digons::any_digon(graph, &glued),
        "a digon the check missed"
    );
    st.digons_pinched = 0;
    if !clean {
        st.digons_pinched = digons::pinch_digons(graph, &glued, handles);
    }
    let mut checked = Some(checked);
    if st.digons_pinched > 0 {
        st.bubbles_removed += bubbles::drop_bubbles(graph, &s.topo, &nodes.simplex);
        glued = graph.glue();
        out = place(s, nodes, graph, &glued, takeover);
        checked = None;
    }
    st.finish_output(&glued, &out.mesh, checked);
    (glued, out)
}

/// The two corners (vertex ids) of side `d` of `node`, in the order of the
/// perpendicular axis (− then +).
pub(crate) fn side_corners(glued: &Glued<2>, node: Node, d: usize) -> [u32; 2] {
    let (axis, bit) = (d >> 1, usize::from(d & 1 == 0));
    let other = 1 - axis;
    let code = |o: usize| (bit << axis) | (o << other);
    [glued.vertex(node, code(0)), glued.vertex(node, code(1))]
}

/// Step 9a's zip (module docs). Returns the number of pairs glued.
fn zip_two_side_holes(graph: &mut NodeGraph<2>, glued: &Glued<2>) -> usize {
    // the unmatched sides between two distinct vertices, found in parallel
    let free: Vec<((u32, u32), Side)> = glued
        .nodes
        .par_iter()
        .flat_map_iter(|&node| {
            let graph = &*graph;
            (0..4).filter_map(move |d| {
                let s = graph.side(node, d);
                let [a, b] = side_corners(glued, node, d);
                (graph.opposite(s).is_none() && a != b).then_some(((a.min(b), a.max(b)), s))
            })
        })
        .collect();
    let mut by_ends: std::collections::HashMap<(u32, u32), Vec<Side>> = Default::default();
    for (ends, s) in free {
        by_ends.entry(ends).or_default().push(s);
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
