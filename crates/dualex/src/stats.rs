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

/// What the extraction repaired or had to give up on. A field that
/// applies to one dimension only says so; it is 0 (`false`) in the other.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Repairs {
    /// 2D: edges joining two singular vertices through a grid point,
    /// split; 3D: tet edges and faces split before sanitization.
    pub split: usize,
    /// Vertices snapped to an exactly grid-preserving value.
    pub snapped_vertices: usize,
    /// Vertices moved off the dual iso-lines (iso-surfaces in 3D).
    pub perturbed_vertices: usize,
    /// Pleats (foldovers) removed by untangling.
    pub pleats_removed: usize,
    /// 2D: folded quads (valence-1 vertices) collapsed after fairing.
    pub folded_corners_collapsed: usize,
    /// 2D: holes closed by a face.
    pub holes_filled: usize,
    /// 2D: holes that could not be closed; 3D: interior faces left open
    /// (cracks at singular edges). Either way, interior faces left open.
    pub holes_left_open: usize,
    /// 2D: triangles (90° singularities on a node) that forced a
    /// subdivision.
    pub triangles: usize,
    /// 2D: whether the whole mesh was subdivided once to make it all-quad.
    pub subdivided: bool,
    /// 2D: interior valence-2 vertices dissolved; 3D: doublet chains
    /// (valence-2 interior edges) dissolved.
    pub doublets_dissolved: usize,
}

/// The main counts of an extraction, of quads ([`quad`](crate::quad())) or
/// of hexes ([`hex`](crate::hex())). "Simplices" are the input's
/// triangles or tets, "cells" the output's quads or hexes, "facets" their
/// edges or faces. A field that applies to one dimension only says so; it
/// is 0 (empty) in the other.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    /// Input simplices (triangles, tets).
    pub input_simplices: usize,
    /// Input simplices whose map is reverted (det < 0).
    pub reverted_simplices: usize,
    /// 3D: input tets with a (near) zero map volume.
    pub degenerate_simplices: usize,
    /// Singular vertices of the input map.
    pub singular_vertices: usize,
    /// 3D: singular interior edges of the input map.
    pub singular_edges: usize,
    /// Largest residual of a transition translation.
    pub max_transition_residual: f64,
    /// Transitions whose translation was rounded to the grid.
    pub transitions_rounded: usize,
    /// Coincident boundary vertices welded before extraction (0 without
    /// welding).
    pub welded_vertices: usize,
    /// The grid offset used (`Half` or `Zero`, never `Auto`).
    pub grid_offset: GridOffset,
    /// Nodes found (one per cell before repairs).
    pub nodes: usize,
    /// Output cells (quads, hexes).
    pub cells: usize,
    /// Output vertices.
    pub vertices: usize,
    /// Output boundary facets (edges of one quad, faces of one hex).
    pub boundary_facets: usize,
    /// Output boundary components: loops of a surface, surfaces of a
    /// volume.
    pub boundary_components: usize,
    /// Output connected components.
    pub components: usize,
    /// Output Euler characteristic: V − E + F (2D), V − E + F − C (3D).
    pub euler: i64,
    /// 2D: interior vertex valence (quads around the vertex); 3D: interior
    /// edge valence (hexes around the edge) → how many.
    pub valence_interior: BTreeMap<usize, usize>,
    /// 2D: boundary vertex valence → how many; empty in 3D.
    pub valence_boundary: BTreeMap<usize, usize>,
    /// Repairs.
    pub repairs: Repairs,
    /// Input and output topology.
    pub topology: TopologyComparison,
    /// The geometric stage: quality (scaled Jacobian) before and after,
    /// what it moved (its time is in `geometry.time_ms`, not in
    /// [`time_ms`](Self::time_ms)).
    pub geometry: GeometryReport,
    /// Wall time per stage in milliseconds, in stage order.
    pub time_ms: Vec<(String, f64)>,
}
