//! Counts at each stage of hex extraction and the output summary
//! (DESIGN §7), serialised as one JSON object: the shared half of steps
//! 1–7 ([`SegmentStats`], the keys both dimensions write: `input`,
//! `sanitize`, `nodes`, `reverted_nodes`, `trace`, `untangle`, `time_ms`
//! …) with the hex steps' own counts (`output`, `fairing`, `repair`).

use dualex_cells::HexMesh;
use dualex_graph::Glued;
use dualex_segment::sanitize_report::histogram_json;
use dualex_segment::stats::SegmentStats;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// Everything measured by one extraction.
#[derive(Clone, Debug, Default)]
pub struct HexStats {
    /// Input tets.
    pub input_tets: usize,
    /// Tets with det < 0.
    pub reverted_tets: usize,
    /// Tets with a (near) zero map volume.
    pub degenerate_tets: usize,
    /// Steps 1–7: the map model, grid offset, split edges and faces
    /// (`split`), sanitization, nodes, traced sides, links, untangling;
    /// timings.
    pub segment: SegmentStats,
    /// Singular interior edges.
    pub singular_edges: usize,
    /// Singular interior edges by angle label (`"+90°"` → count).
    pub singular_edge_angles: BTreeMap<String, usize>,
    /// Doublet chains (valence-2 interior edges) dissolved, in the graph
    /// (step 8e) and after gluing (step 11).
    pub doublets: crate::doublets::Chains,
    /// Index fairing on columns (`None`: not columns, or off).
    pub column_fairing: Option<dualex_graph::ColumnFairing>,
    /// Holes through columns repaired locally (`crate::columns`).
    pub columns: crate::columns::ColumnRepair,
    /// Folded hexes collapsed after gluing.
    pub folded_collapsed: usize,
    /// Output: hexes.
    pub hexes: usize,
    /// Output: vertices.
    pub vertices: usize,
    /// Output: unmatched sides in the final graph (boundary faces).
    pub unmatched_sides: usize,
    /// Output: unmatched sides that are cracks, not input boundary (walks
    /// lost at a singular edge; every unmatched side of a closed input).
    pub open_interior_faces: usize,
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
    /// Output: valid by the checker without positions (the driver's
    /// trigger of the relaxed retry; not in the JSON).
    pub mesh_valid: bool,
    /// The checker's report of the output as last counted, handed over to
    /// the facade's last check (read there while the mesh is unchanged;
    /// not in the JSON).
    pub checked: Option<dualex_check::Checked<dualex_check::HexReport>>,
    /// The input's components and faces of one tet, read off the first
    /// pass's adjacency (`dualex_check::glued::tet_glued`), for the
    /// facade's input shape (not in the JSON).
    pub input: Option<dualex_check::glued::TetGlued>,
}

impl AsMut<SegmentStats> for HexStats {
    fn as_mut(&mut self) -> &mut SegmentStats {
        &mut self.segment
    }
}

impl HexStats {
    /// Fills the output counts from the final gluing (its graph's counts)
    /// and mesh.
    pub fn finish_output(&mut self, glued: &Glued<3>, mesh: &HexMesh) {
        self.hexes = mesh.cells.len();
        self.vertices = mesh.positions.len();
        self.unmatched_sides = glued.unmatched_sides;
        self.boundary_surfaces = glued.boundary_loops;
        self.components = glued.components;
        self.corner_mismatches = glued.corner_mismatches;
        self.count_checked(mesh);
    }

    /// Recounts the output after a change of the mesh alone (holes through
    /// columns repaired, doublet chains dissolved): cells, vertices, Euler
    /// characteristic, edge valences, boundary faces and surfaces and
    /// components from the validity checker.
    pub fn finish_mesh(&mut self, mesh: &HexMesh) {
        self.hexes = mesh.cells.len();
        self.vertices = mesh.positions.len();
        let c = self.count_checked(mesh);
        let counts = (c.boundary_faces, c.boundary.components, c.components);
        // the repairs close holes and may split the boundary surface
        (
            self.unmatched_sides,
            self.boundary_surfaces,
            self.components,
        ) = counts;
    }

    /// The counts of the validity checker (one piece of code for both):
    /// Euler characteristic, validity, edge valences; its report kept
    /// ([`HexStats::checked`]) and returned.
    fn count_checked(&mut self, mesh: &HexMesh) -> &dualex_check::HexReport {
        let c = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
        self.euler = c.euler;
        self.mesh_valid = c.is_valid();
        self.edge_valence_interior = c
            .interior_edge_valence
            .iter()
            .map(|(&k, &v)| (k as usize, v))
            .collect();
        let n = mesh.positions.len();
        self.checked
            .insert(dualex_check::Checked::new(c, n, &mesh.cells))
            .report()
    }

    /// The stats as one JSON object.
    pub fn to_json(&self) -> Value {
        let input = json!({
            "tets": self.input_tets,
            "reverted_tets": self.reverted_tets,
            "degenerate_tets": self.degenerate_tets,
            "singular_edges": self.singular_edges,
            "singularities": self.singular_edge_angles,
        });
        let sanitize = json!({
            "singular_moved": self.segment.sanitize.singular_moved,
            "split_faces": self.segment.split,
        });
        let rest = json!({
            "output": {
                "hexes": self.hexes,
                "vertices": self.vertices,
                "unmatched_sides": self.unmatched_sides,
                "boundary_faces": self.unmatched_sides,
                "boundary_surfaces": self.boundary_surfaces,
                "components": self.components,
                "corner_mismatches": self.corner_mismatches,
                "euler": self.euler,
                "edge_valence_interior": histogram_json(&self.edge_valence_interior),
                "open_interior_faces": self.open_interior_faces,
                "holes": self.open_interior_faces,
                "folded_collapsed": self.folded_collapsed,
                "doublet_chains_dissolved": self.doublets.dissolved,
                "doublet_edges_dissolved": self.doublets.edges,
                "doublet_edges_left": self.doublets.left,
                "doublet_chains_in_graph": self.doublets.in_graph,
            },
            "fairing": self.column_fairing.as_ref().map(|f| {
                let mut j = f.fairing.to_json();
                j["folded_columns_collapsed"] = json!(f.collapsed);
                j["columns"] = json!(f.columns);
                j["layers"] = json!(f.layers);
                j
            }),
            "repair": {
                "local_paths": self.columns.paths,
                "holes_filled": self.columns.holes,
                "columns_split": self.columns.split,
                "column_layers": self.columns.layers,
                "doublet_rounds": self.doublets.rounds,
            },
        });
        self.segment.to_json(input, sanitize, rest)
    }
}
