//! Counts at each stage of hex extraction and the output summary
//! (DESIGN §7), serialised as one JSON object with the keys of the quad
//! stats where they apply (`input`, `sanitize`, `nodes`, `reverted_nodes`,
//! `trace`, `untangle`, `output`, `time_ms`).

use crate::sanitize::SanitizeReport;
use crate::trace::TraceReport;
use dualex_map::HexMesh;
use serde_json::{json, Map, Value};
use std::collections::{BTreeMap, HashMap};

/// Everything measured by one extraction.
#[derive(Clone, Debug, Default)]
pub struct HexStats {
    /// Input tets.
    pub input_tets: usize,
    /// Tets with det < 0.
    pub reverted_tets: usize,
    /// Tets with a (near) zero map volume.
    pub degenerate_tets: usize,
    /// Largest residual of a transition translation.
    pub max_transition_residual: f64,
    /// Transitions snapped by `round`.
    pub snapped_transitions: usize,
    /// Vertices whose star rotations are inconsistent (on singular edges).
    pub singular_vertices: usize,
    /// Singular interior edges.
    pub singular_edges: usize,
    /// Sanitization report.
    pub sanitize: SanitizeReport,
    /// Nodes found.
    pub nodes: usize,
    /// Nodes in reverted tets.
    pub reverted_nodes: usize,
    /// Walk outcomes.
    pub trace: TraceReport,
    /// Walks whose target did not walk back to them.
    pub non_mutual: usize,
    /// Mutual pairs whose rotations disagree (0 expected).
    pub rotation_mismatches: usize,
    /// Pairs breaking the pleat label rule after tracing (0 expected).
    pub label_violations: usize,
    /// Untangling counts.
    pub untangle: Option<dualex_graph::UntangleStats>,
    /// Output: hexes.
    pub hexes: usize,
    /// Output: vertices.
    pub vertices: usize,
    /// Output: unmatched sides in the final graph (boundary faces).
    pub unmatched_sides: usize,
    /// Output: boundary surfaces, counted in the graph.
    pub boundary_surfaces: usize,
    /// Output: connected components.
    pub components: usize,
    /// Output: pairs whose corners could not be matched when gluing.
    pub corner_mismatches: usize,
    /// Output: interior edge valences (cells around the edge → count).
    pub edge_valence_interior: BTreeMap<usize, usize>,
    /// Output: Euler characteristic V − E + F − C.
    pub euler: i64,
    /// Wall time per stage in milliseconds.
    pub time_ms: Vec<(String, f64)>,
}

/// The 6 faces of a hex (VTK order), as corner positions.
const FACES: [[usize; 4]; 6] = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
];
/// The 12 edges of a hex (VTK order).
const EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 0],
    [4, 5],
    [5, 6],
    [6, 7],
    [7, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// Combinatorial counts of a hex mesh.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Counts {
    /// Distinct edges.
    pub edges: usize,
    /// Distinct faces.
    pub faces: usize,
    /// Faces with one cell.
    pub boundary_faces: usize,
    /// Interior edge valences (edges on no boundary face).
    pub valence_interior: BTreeMap<usize, usize>,
}

/// Edges, faces, boundary faces and interior edge valences of `mesh`.
pub fn counts(mesh: &HexMesh) -> Counts {
    let key2 = |a: u32, b: u32| (a.min(b), a.max(b));
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    let mut faces: HashMap<[u32; 4], usize> = HashMap::new();
    for h in &mesh.cells {
        for e in EDGES {
            *edges.entry(key2(h[e[0]], h[e[1]])).or_default() += 1;
        }
        for f in FACES {
            let mut k = f.map(|i| h[i]);
            k.sort_unstable();
            *faces.entry(k).or_default() += 1;
        }
    }
    // boundary edges: the cycles of the boundary faces (read from the cells)
    let mut on_boundary: std::collections::HashSet<(u32, u32)> = Default::default();
    for h in &mesh.cells {
        for f in FACES {
            let mut k = f.map(|i| h[i]);
            k.sort_unstable();
            if faces.get(&k) == Some(&1) {
                for i in 0..4 {
                    on_boundary.insert(key2(h[f[i]], h[f[(i + 1) % 4]]));
                }
            }
        }
    }
    let mut valence_interior = BTreeMap::new();
    for (e, &c) in &edges {
        if !on_boundary.contains(e) {
            *valence_interior.entry(c).or_insert(0) += 1;
        }
    }
    Counts {
        edges: edges.len(),
        faces: faces.len(),
        boundary_faces: faces.values().filter(|&&c| c == 1).count(),
        valence_interior,
    }
}

impl HexStats {
    /// Fills the output counts from the final graph and mesh.
    pub fn finish_output(
        &mut self,
        graph: &dualex_graph::NodeGraph<3>,
        glued: &dualex_graph::Glued<3>,
        mesh: &HexMesh,
    ) {
        self.hexes = mesh.cells.len();
        self.vertices = mesh.positions.len();
        self.unmatched_sides = graph.unmatched_sides();
        self.boundary_surfaces = glued.boundary_loops;
        self.components = glued.components;
        self.corner_mismatches = glued.corner_mismatches;
        let c = counts(mesh);
        self.euler =
            mesh.positions.len() as i64 - c.edges as i64 + c.faces as i64 - mesh.cells.len() as i64;
        self.edge_valence_interior = c.valence_interior;
    }

    /// The stats as one JSON object.
    pub fn to_json(&self) -> Value {
        let hist = |h: &BTreeMap<usize, usize>| {
            Value::Object(
                h.iter()
                    .map(|(k, v)| (k.to_string(), json!(v)))
                    .collect::<Map<_, _>>(),
            )
        };
        let times: Map<String, Value> = self
            .time_ms
            .iter()
            .map(|(k, v)| (k.clone(), json!(v)))
            .collect();
        let s = &self.sanitize;
        json!({
            "input": {
                "tets": self.input_tets,
                "reverted_tets": self.reverted_tets,
                "degenerate_tets": self.degenerate_tets,
                "max_transition_residual": self.max_transition_residual,
                "snapped_transitions": self.snapped_transitions,
                "singular_vertices": self.singular_vertices,
                "singular_edges": self.singular_edges,
            },
            "sanitize": {
                "snapped_vertices": s.snapped_vertices,
                "max_snap": s.max_snap,
                "perturbed_vertices": s.perturbed_vertices,
                "clusters": s.clusters,
                "stuck_clusters": s.stuck_clusters,
                "rounds": s.rounds,
                "singular_moved": s.singular_moved,
                "singular_on_iso": s.singular_on_iso.len(),
                "unresolved": s.unresolved,
            },
            "nodes": self.nodes,
            "reverted_nodes": self.reverted_nodes,
            "trace": {
                "to_node": self.trace.to_node,
                "to_boundary": self.trace.to_boundary,
                "inconsistent": self.trace.inconsistent,
                "loops": self.trace.loops,
                "max_steps": self.trace.max_steps,
                "non_mutual": self.non_mutual,
                "rotation_mismatches": self.rotation_mismatches,
                "label_violations": self.label_violations,
            },
            "untangle": self.untangle.as_ref().map(|u| u.to_json()),
            "output": {
                "hexes": self.hexes,
                "vertices": self.vertices,
                "unmatched_sides": self.unmatched_sides,
                "boundary_faces": self.unmatched_sides,
                "boundary_surfaces": self.boundary_surfaces,
                "components": self.components,
                "corner_mismatches": self.corner_mismatches,
                "euler": self.euler,
                "edge_valence_interior": hist(&self.edge_valence_interior),
                "holes": 0,
            },
            "time_ms": times,
        })
    }
}
