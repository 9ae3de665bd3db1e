//! Typed summaries of one extraction: the main counts of the CLI's
//! `--stats` JSON as plain fields (no JSON values), built from the
//! extraction crates' own stats and the validity checker's counts.
//!
//! Invariants: the output counts (`quads`/`hexes`, `vertices`, `euler`,
//! valences) are those of the returned mesh; `topology.matches()` is the
//! CLI's `topology_matches_input`; `geometry` is the CLI's `geometry`
//! section (its [`GeometryReport::to_json`] is that JSON), `geometry.after`
//! the quality of the returned positions.

use crate::GeometryReport;
use dualex_check::topology::Shape;
use std::collections::BTreeMap;

pub use dualex_segment::grid_offset::GridOffset;

/// Components, Euler characteristic and boundary components of one side
/// (input or output) of an extraction.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Topology {
    /// Connected components.
    pub components: usize,
    /// Euler characteristic (of a volume: of its boundary surface).
    pub euler: i64,
    /// Boundary loops of a surface; boundary surfaces of a volume.
    pub boundary_components: usize,
}

impl From<Shape> for Topology {
    fn from(s: Shape) -> Self {
        Topology {
            components: s.components,
            euler: s.euler,
            boundary_components: s.boundary_components,
        }
    }
}

/// The topology of the input and of the output, as compared by the CLI's
/// last check (an extraction should not change it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TopologyComparison {
    /// The input map's mesh (after welding).
    pub input: Topology,
    /// The output mesh.
    pub output: Topology,
}

impl TopologyComparison {
    /// Whether input and output have the same topology.
    pub fn matches(&self) -> bool {
        self.input == self.output
    }
}

/// What the extraction repaired or had to give up on (quads).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct QuadRepairs {
    /// Edges joining two singular vertices through a grid point, split.
    pub split_edges: usize,
    /// Vertices snapped to an exactly grid-preserving value.
    pub snapped_vertices: usize,
    /// Vertices moved off the dual iso-lines.
    pub perturbed_vertices: usize,
    /// Pleats (foldovers) removed by untangling.
    pub pleats_removed: usize,
    /// Folded quads (valence-1 vertices) collapsed after fairing.
    pub folded_corners_collapsed: usize,
    /// Holes closed by a face.
    pub holes_filled: usize,
    /// Holes that could not be closed (interior faces left open).
    pub holes_left_open: usize,
    /// Triangles (90° singularities on a node) that forced a subdivision.
    pub triangles: usize,
    /// Whether the whole mesh was subdivided once to make it all-quad.
    pub subdivided: bool,
    /// Interior valence-2 vertices dissolved.
    pub doublets_dissolved: usize,
}

/// The main counts of a quad extraction.
#[derive(Clone, Debug, Default)]
pub struct QuadStats {
    /// Input triangles.
    pub input_triangles: usize,
    /// Input triangles whose map is reverted (det < 0).
    pub reverted_triangles: usize,
    /// Singular vertices of the input map.
    pub singular_vertices: usize,
    /// Largest residual of a transition translation.
    pub max_transition_residual: f64,
    /// Transitions whose translation was rounded to the grid.
    pub transitions_rounded: usize,
    /// Coincident boundary vertices welded before extraction (0 without
    /// welding).
    pub welded_vertices: usize,
    /// The grid offset used (`Half` or `Zero`, never `Auto`).
    pub grid_offset: GridOffset,
    /// Nodes found (one per quad before repairs).
    pub nodes: usize,
    /// Output quads.
    pub quads: usize,
    /// Output vertices.
    pub vertices: usize,
    /// Output boundary loops.
    pub boundary_loops: usize,
    /// Output connected components.
    pub components: usize,
    /// Output Euler characteristic V − E + F.
    pub euler: i64,
    /// Interior vertex valence → number of vertices.
    pub valence_interior: BTreeMap<usize, usize>,
    /// Boundary vertex valence → number of vertices.
    pub valence_boundary: BTreeMap<usize, usize>,
    /// Repairs.
    pub repairs: QuadRepairs,
    /// Input and output topology.
    pub topology: TopologyComparison,
    /// The geometric stage: quality (scaled Jacobian) before and after,
    /// what it moved (its time is in `geometry.time_ms`, not in
    /// [`time_ms`](Self::time_ms)).
    pub geometry: GeometryReport,
    /// Wall time per stage in milliseconds, in stage order.
    pub time_ms: Vec<(String, f64)>,
}

impl QuadStats {
    pub(crate) fn new(
        s: &dualex_quad::QuadStats,
        welded: usize,
        t: TopologyComparison,
        geometry: GeometryReport,
    ) -> Self {
        QuadStats {
            input_triangles: s.input_triangles,
            reverted_triangles: s.reverted_triangles,
            singular_vertices: s.singular_vertices,
            max_transition_residual: s.max_transition_residual,
            transitions_rounded: s.snapped_transitions,
            welded_vertices: welded,
            grid_offset: s.grid_offset.offset,
            nodes: s.nodes,
            quads: s.quads,
            vertices: s.vertices,
            boundary_loops: s.boundary_loops,
            components: s.components,
            euler: s.euler,
            valence_interior: s.valence_interior.clone(),
            valence_boundary: s.valence_boundary.clone(),
            repairs: QuadRepairs {
                split_edges: s.split_edges,
                snapped_vertices: s.sanitize.snapped_vertices,
                perturbed_vertices: s.sanitize.perturbed_vertices,
                pleats_removed: s.untangle.as_ref().map_or(0, |u| u.pleats_removed),
                folded_corners_collapsed: s.folded_corners_collapsed,
                holes_filled: s.holes_filled,
                holes_left_open: s.holes_left_open,
                triangles: s.repair_triangles,
                subdivided: s.subdivided,
                doublets_dissolved: s.doublets.dissolved,
            },
            topology: t,
            geometry,
            time_ms: s.time_ms.clone(),
        }
    }
}

/// What the extraction repaired or had to give up on (hexes).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HexRepairs {
    /// Tet edges and faces split before sanitization.
    pub split_faces: usize,
    /// Vertices snapped to an exactly grid-preserving value.
    pub snapped_vertices: usize,
    /// Vertices moved off the dual iso-surfaces.
    pub perturbed_vertices: usize,
    /// Pleats (foldovers) removed by untangling.
    pub pleats_removed: usize,
    /// Interior faces left open (cracks at singular edges).
    pub open_interior_faces: usize,
    /// Doublet chains (valence-2 interior edges) dissolved.
    pub doublet_chains_dissolved: usize,
}

/// The main counts of a hex extraction.
#[derive(Clone, Debug, Default)]
pub struct HexStats {
    /// Input tets.
    pub input_tets: usize,
    /// Input tets whose map is reverted (det < 0).
    pub reverted_tets: usize,
    /// Input tets with a (near) zero map volume.
    pub degenerate_tets: usize,
    /// Singular vertices of the input map.
    pub singular_vertices: usize,
    /// Singular interior edges of the input map.
    pub singular_edges: usize,
    /// Largest residual of a transition translation.
    pub max_transition_residual: f64,
    /// Transitions whose translation was rounded to the grid.
    pub transitions_rounded: usize,
    /// Coincident boundary vertices welded before extraction.
    pub welded_vertices: usize,
    /// The grid offset used (`Half` or `Zero`).
    pub grid_offset: GridOffset,
    /// Nodes found (one per hex before repairs).
    pub nodes: usize,
    /// Output hexes.
    pub hexes: usize,
    /// Output vertices.
    pub vertices: usize,
    /// Output boundary faces.
    pub boundary_faces: usize,
    /// Output boundary surfaces.
    pub boundary_surfaces: usize,
    /// Output connected components.
    pub components: usize,
    /// Output Euler characteristic V − E + F − C.
    pub euler: i64,
    /// Interior edge valence (hexes around the edge) → number of edges.
    pub edge_valence_interior: BTreeMap<usize, usize>,
    /// Repairs.
    pub repairs: HexRepairs,
    /// Input and output topology.
    pub topology: TopologyComparison,
    /// The geometric stage: quality (scaled Jacobian) before and after,
    /// what it moved (its time is in `geometry.time_ms`, not in
    /// [`time_ms`](Self::time_ms)).
    pub geometry: GeometryReport,
    /// Wall time per stage in milliseconds, in stage order.
    pub time_ms: Vec<(String, f64)>,
}

impl HexStats {
    pub(crate) fn new(
        s: &dualex_hex::HexStats,
        welded: usize,
        t: TopologyComparison,
        geometry: GeometryReport,
    ) -> Self {
        HexStats {
            input_tets: s.input_tets,
            reverted_tets: s.reverted_tets,
            degenerate_tets: s.degenerate_tets,
            singular_vertices: s.singular_vertices,
            singular_edges: s.singular_edges,
            max_transition_residual: s.max_transition_residual,
            transitions_rounded: s.snapped_transitions,
            welded_vertices: welded,
            grid_offset: s.grid_offset.offset,
            nodes: s.nodes,
            hexes: s.hexes,
            vertices: s.vertices,
            boundary_faces: s.unmatched_sides,
            boundary_surfaces: s.boundary_surfaces,
            components: s.components,
            euler: s.euler,
            edge_valence_interior: s.edge_valence_interior.clone(),
            repairs: HexRepairs {
                split_faces: s.split_faces,
                snapped_vertices: s.sanitize.snapped_vertices,
                perturbed_vertices: s.sanitize.perturbed_vertices,
                pleats_removed: s.untangle.as_ref().map_or(0, |u| u.pleats_removed),
                open_interior_faces: s.open_interior_faces,
                doublet_chains_dissolved: s.doublets.dissolved,
            },
            topology: t,
            geometry,
            time_ms: s.time_ms.clone(),
        }
    }
}
