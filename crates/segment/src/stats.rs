//! The shared half of the extraction stats: the counts of steps 1–7
//! (the map model, the grid offset, the split, sanitization, the nodes,
//! the traced sides, the opposite relation and untangling) and the stage
//! timings, which both dimensions report under the same JSON keys (and
//! the relaxed retry's report, `relax`, when a driver kept it).
//!
//! Input: the numbered steps of [`crate::steps`] fill a [`SegmentStats`]
//! (untangling: the driver). Output: its JSON keys, merged with a
//! dimension's own ones by [`SegmentStats::to_json`]. Invariant: the keys
//! are those the quad and hex stats always wrote (serde_json sorts them,
//! so the merge order does not show).

use crate::grid_offset::OffsetChoice;
use crate::relax::RelaxReport;
use crate::sanitize_report::{offset_json, times_json, SanitizeReport};
use dualex_graph::walk::{LinkReport, TraceReport};
use dualex_graph::UntangleStats;
use serde_json::{json, Map, Value};

/// What steps 1–7 measured, in both dimensions.
#[derive(Clone, Debug, Default)]
pub struct SegmentStats {
    /// Largest residual of a transition translation.
    pub max_transition_residual: f64,
    /// Transitions rounded (residual above the tolerance: up to 0.1 by
    /// default, any with `--round-transitions`); `transitions_rounded` in
    /// the JSON.
    pub snapped_transitions: usize,
    /// Vertices whose star rotations are inconsistent (3D: on singular
    /// edges).
    pub singular_vertices: usize,
    /// Faces split by step 3 (2D: edges joining two singular vertices
    /// through a grid point, `split_edges` in the JSON; 3D: tet edges and
    /// faces, `split_faces`).
    pub split: usize,
    /// The grid offset used, and the singular vertices on the grid under
    /// each choice (`Auto`).
    pub grid_offset: OffsetChoice,
    /// Sanitization report.
    pub sanitize: SanitizeReport,
    /// Nodes found.
    pub nodes: usize,
    /// Nodes in reverted simplices.
    pub reverted_nodes: usize,
    /// Walk outcomes.
    pub trace: TraceReport,
    /// What linking the walks found (non-mutual walks, rotation
    /// mismatches).
    pub links: LinkReport,
    /// Pairs breaking the pleat label rule after tracing (0 expected).
    pub label_violations: usize,
    /// Isolated nodes dropped: no side glued, every walk lost (noise).
    pub isolated_dropped: usize,
    /// Untangling counts.
    pub untangle: Option<UntangleStats>,
    /// Wall time per stage in milliseconds.
    pub time_ms: Vec<(String, f64)>,
    /// The drivers' relaxed retry, when its result was kept (`relax` in
    /// the JSON, only then: [`crate::relax::retry`]).
    pub relax: Option<RelaxReport>,
}

/// Adds the keys of `more` (an object) to `into`.
fn merge(into: &mut Map<String, Value>, more: Value) {
    if let Value::Object(m) = more {
        into.extend(m);
    }
}

impl SegmentStats {
    /// The stats as one JSON object: the shared keys, with a dimension's
    /// own keys of the `input` and `sanitize` objects and of the top level
    /// added (each an object).
    pub fn to_json(&self, input: Value, sanitize: Value, rest: Value) -> Value {
        let mut input_keys = match json!({
            "max_transition_residual": self.max_transition_residual,
            "snapped_transitions": self.snapped_transitions,
            "transitions_rounded": self.snapped_transitions,
            "singular_vertices": self.singular_vertices,
        }) {
            Value::Object(m) => m,
            _ => Map::new(),
        };
        merge(&mut input_keys, input);
        let mut sanitize_keys = self.sanitize.to_json();
        merge(&mut sanitize_keys, sanitize);
        let mut all = Map::new();
        merge(
            &mut all,
            json!({
                "input": input_keys,
                "grid_offset": self.grid_offset.offset.name(),
                "grid_offset_choice": offset_json(&self.grid_offset),
                "sanitize": sanitize_keys,
                "nodes": self.nodes,
                "isolated_nodes_dropped": self.isolated_dropped,
                "reverted_nodes": self.reverted_nodes,
                "trace": self.trace.to_json(&self.links, self.label_violations),
                "untangle": self.untangle.as_ref().map(|u| u.to_json()),
                "time_ms": times_json(&self.time_ms),
            }),
        );
        if let Some(r) = &self.relax {
            all.insert("relax".into(), r.to_json());
        }
        merge(&mut all, rest);
        Value::Object(all)
    }
}
