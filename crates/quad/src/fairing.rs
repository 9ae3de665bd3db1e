//! Step 6: index fairing, by the graph core's saddle lifts (D = 2): merge
//! valence-1, then valence-2 vertices with a vertex of valence ≥ 7 along the
//! shortest edge path of at most [`MAX_PATH`] edges.
use dualex_graph::NodeGraph;

/// Longest path a singularity is moved along (the paper uses 10).
pub const MAX_PATH: usize = 10;

/// Runs index fairing and returns its stats as JSON.
pub fn fair(graph: &mut NodeGraph<2>) -> serde_json::Value {
    graph.fair(MAX_PATH).to_json()
}
