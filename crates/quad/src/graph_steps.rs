//! Steps 7 (untangling) and 8 (fairing and the clean-up) in the graph,
//! D = 2, all by the graph core (`dualex_graph`):
//! 7. pleats removed; while index fairing leaves valence-1 or 2 vertices,
//!    other untangling orders are tried ([`UNTANGLE_ORDERS`],
//!    `NodeGraph::untangle_best`);
//! 8. a. index fairing by saddle lifts (optional): merge valence-1, then
//!    valence-2 vertices with a vertex of valence ≥ 7 along the shortest
//!    edge path of at most [`MAX_PATH`] edges; b. a valence-1 vertex left
//!    (no partner for fairing) is a folded quad: collapsed, so that the
//!    output has no repeated vertex; c. two nodes glued only to each other
//!    (a fold pocket detached as a component of its own) deleted; d.
//!    bubbles beside the surface of their input component deleted
//!    ([`crate::bubbles`]); e. doublets fairing found no partner for merged
//!    (with fairing; a merged node's corner traced from the node it took
//!    it over from).
//!
//! Input: the linked graph of step 7 and the walks' ends. Output: the
//! graph ready to glue, the ends carried through the merges, the
//! [`Takeover`] of merged corners, and fairing's vertices of the graph
//! ([`Steps::vertices`]) when steps 8b–8e changed nothing. Laps
//! `untangle` and `fairing`.

use crate::{bubbles, QuadOptions, QuadStats};
use dualex_graph::{Glued, NodeGraph, Takeover};
use dualex_segment::nodes::Nodes;
use dualex_segment::steps::Sanitized;
use dualex_segment::trace::End;
use dualex_util::timing::Laps;

/// Longest path a singularity is moved along (the paper uses 10).
pub const MAX_PATH: usize = 10;

/// Other untangling orders tried when fairing leaves valence-1 or 2
/// vertices (`NodeGraph::untangle_best`): on the refined prism maps folded
/// at their poles, 4 orders fixed 5 of the 9 split poles in 67 500 maps,
/// and more orders fixed none of the other 4.
pub const UNTANGLE_ORDERS: u64 = 4;

/// What steps 7 and 8 hand to the gluing.
pub struct Steps {
    /// The corners merged doublets took over.
    pub takeover: Takeover<2>,
    /// The vertices of the graph as it is left, found by fairing
    /// (`NodeGraph::fair_glued`; `None` when not found or changed since).
    pub vertices: Option<Glued<2>>,
}

/// Steps 7 and 8 (module docs).
pub fn run(
    graph: &mut NodeGraph<2>,
    ends: &mut [End<2>],
    s: &Sanitized<'_, 3, 2>,
    nodes: &Nodes<3, 2>,
    opts: &QuadOptions,
    st: &mut QuadStats,
    laps: &mut Laps,
) -> Steps {
    // 7 + 8a
    let (ust, (fst, mut vertices)) = graph.untangle_best(UNTANGLE_ORDERS, |g| {
        if opts.fairing {
            let (f, v) = g.fair_glued(MAX_PATH);
            let left = f.valence1_after + f.valence2_after;
            ((Some(f), v), left)
        } else {
            ((None, None), 0)
        }
    });
    st.segment.untangle = Some(ust);
    st.fairing = fst.map(|f| f.to_json());
    laps.lap("untangle");
    // 8b–8d
    st.folded_corners_collapsed = graph.collapse_folded_corners();
    st.pillows_removed = graph.remove_pillows();
    st.bubbles_removed = bubbles::drop_bubbles(graph, &s.topo, &nodes.simplex);
    // 8e
    let mut takeover = Takeover::default();
    if opts.fairing {
        let merged = graph.dissolve_doublets(&mut takeover);
        takeover.carry_sides(ends);
        st.doublets.dissolved = merged.merged;
        st.doublets.in_graph = merged.merged;
    }
    // each of 8b–8e changes the graph only by what it counts (its
    // operations check before they change anything)
    let changed = st.folded_corners_collapsed + st.pillows_removed + st.bubbles_removed;
    if changed + st.doublets.in_graph > 0 {
        vertices = None;
    }
    laps.lap("fairing");
    Steps { takeover, vertices }
}
