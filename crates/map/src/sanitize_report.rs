//! What sanitization did, in both dimensions (the report of `quad` and
//! `hex`'s step 2), and its `sanitize` object in the stats JSON; the
//! perturbation schedule both use.

use serde_json::{json, Map, Value};
use std::collections::BTreeMap;

/// Initial perturbation amplitude (map units), doubled every 8 rounds.
pub const AMPLITUDE: f64 = 1e-5;
/// Perturbation rounds before giving up on a vertex.
pub const ROUNDS: usize = 40;

/// What sanitization did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SanitizeReport {
    /// Vertices whose corners were snapped to one GP value.
    pub snapped_vertices: usize,
    /// Largest distance a snap moved a corner.
    pub max_snap: f64,
    /// Distinct vertices perturbed.
    pub perturbed_vertices: usize,
    /// Collapsed clusters (more than one vertex) found.
    pub clusters: usize,
    /// Cluster moves refused (the cluster holds a singular vertex or its
    /// rotations disagree).
    pub stuck_clusters: usize,
    /// Rounds used.
    pub rounds: usize,
    /// 3D: singular vertices moved along their singular edge's axis.
    pub singular_moved: usize,
    /// 2D: singular vertices left on an iso, by kind (`"90_node"`,
    /// `"180_iso"`, `"90_edge"`: only an edge through a grid point, …).
    pub singular_kinds: BTreeMap<String, usize>,
    /// Singular vertices left on an iso (cannot be perturbed).
    pub singular_on_iso: Vec<u32>,
    /// Non-singular vertices still on an iso after all rounds (0 expected).
    pub unresolved: usize,
    /// Singular vertices put exactly on the fixed set of their holonomies
    /// ([`crate::singular_snap`]).
    pub singular_snap: crate::singular_snap::SingularSnap,
}

impl SanitizeReport {
    /// The counts both dimensions report; each adds its own keys.
    pub fn to_json(&self) -> Map<String, Value> {
        let v = json!({
            "snapped_vertices": self.snapped_vertices,
            "max_snap": self.max_snap,
            "perturbed_vertices": self.perturbed_vertices,
            "clusters": self.clusters,
            "stuck_clusters": self.stuck_clusters,
            "rounds": self.rounds,
            "singular_on_iso": self.singular_on_iso.len(),
            "unresolved": self.unresolved,
            "singular_snapped": self.singular_snap.snapped,
            "max_singular_snap": self.singular_snap.max_move,
            "singular_left_unsnapped": self.singular_snap.left,
        });
        match v {
            Value::Object(m) => m,
            _ => Map::new(),
        }
    }
}

/// A histogram (value → count) as a JSON object keyed by the value.
pub fn histogram_json(h: &BTreeMap<usize, usize>) -> Value {
    Value::Object(h.iter().map(|(k, v)| (k.to_string(), json!(v))).collect())
}

/// Stage timings (name, milliseconds) as a JSON object.
pub fn times_json(times: &[(String, f64)]) -> Value {
    Value::Object(times.iter().map(|(k, v)| (k.clone(), json!(v))).collect())
}

/// What the grid offset was chosen on: the singular vertices on a node and
/// on an iso under each offset (zeros when the offset was given).
pub fn offset_json(c: &crate::grid_offset::OffsetChoice) -> Value {
    let on = |g: &crate::grid_offset::OnGrid| json!({"on_node": g.on_node, "on_iso": g.on_iso, "boundary_facets_on_iso": g.boundary_on_iso});
    json!({"half": on(&c.half), "zero": on(&c.zero)})
}
