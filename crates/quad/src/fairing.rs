//! Step 6: index fairing, by the graph core's saddle lifts (D = 2): merge
//! valence-1, then valence-2 vertices with a vertex of valence ≥ 7 along the
//! shortest edge path of at most [`MAX_PATH`] edges.
use dualex_graph::{FairingStats, NodeGraph};

/// Longest path a singularity is moved along (the paper uses 10).
pub const MAX_PATH: usize = 10;

/// Other untangling orders tried when fairing leaves valence-1 or 2
/// vertices (`NodeGraph::untangle_best`): on the refined prism maps folded
/// at their poles, 4 orders fixed 5 of the 9 split poles in 67 500 maps,
/// and more orders fixed none of the other 4.
pub const UNTANGLE_ORDERS: u64 = 4;

/// Runs index fairing.
pub fn fair(graph: &mut NodeGraph<2>) -> FairingStats {
    graph.fair(MAX_PATH)
}
