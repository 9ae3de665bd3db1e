//! Counts at each stage of quad extraction and the output summary
//! (DESIGN §7), serialised as one JSON object: the shared half of steps
//! 1–7 ([`SegmentStats`], the keys both dimensions write) with the quad
//! steps' own counts.

use dualex_cells::QuadMesh;
use dualex_check::QuadReport;
use dualex_graph::Glued;
use dualex_map::TriMap;
use dualex_segment::sanitize_report::histogram_json;
use dualex_segment::stats::SegmentStats;
use dualex_segment::steps::Model;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// Everything measured by one extraction.
#[derive(Clone, Debug, Default)]
pub struct QuadStats {
    /// Input triangles.
    pub input_triangles: usize,
    /// Triangles with det < 0.
    pub reverted_triangles: usize,
    /// Steps 1–7: the map model, grid offset, split edges (`split`),
    /// sanitization, nodes, traced sides, links, untangling; timings.
    pub segment: SegmentStats,
    /// Singularities by index (fraction string → count), when known.
    pub singularities: BTreeMap<String, usize>,
    /// Index fairing counts.
    pub fairing: Option<serde_json::Value>,
    /// Folded quads (valence-1 vertices) collapsed after fairing.
    pub folded_corners_collapsed: usize,
    /// Pillows (two nodes glued only to each other, a detached fold
    /// pocket) deleted before gluing.
    pub pillows_removed: usize,
    /// Closed components beside the surface of their input component
    /// (fold bubbles) deleted before gluing (`crate::bubbles`).
    pub bubbles_removed: usize,
    /// Digons (two glued edges between the same two vertices) pinched off
    /// after gluing (`crate::digons`).
    pub digons_pinched: usize,
    /// Holes of two unmatched sides with identified ends, glued explicitly.
    pub zipped_sides: usize,
    /// Edges given a point because another edge joins the same two
    /// vertices ([`crate::ambiguous`]).
    pub parallel_edges_split: usize,
    /// Cells whose opposite corners are one vertex, cut in two
    /// ([`crate::ambiguous`]).
    pub folded_cells_cut: usize,
    /// Vertex copies made where the repaired surface was pinched
    /// ([`crate::pinched`]).
    pub pinched_vertices_split: usize,
    /// Holes (unmatched sides not on the input boundary) closed by a face.
    pub holes_filled: usize,
    /// Holes that could not be closed (a cycle through a vertex twice).
    pub holes_left_open: usize,
    /// Triangles (90° singularities on a node) that forced a subdivision.
    pub repair_triangles: usize,
    /// Cells of fewer than 3 distinct corners dropped by the subdivision.
    pub repair_dropped: usize,
    /// Whether the whole mesh was subdivided once (a triangle, or a hole
    /// that is not a quad, could not be made a quad otherwise).
    pub subdivided: bool,
    /// Paths of the local repair of faces quads cannot represent.
    pub repair_paths: usize,
    /// Interior valence-2 vertices dissolved (in the graph, step 8e, and
    /// after gluing, [`crate::doublets`]) and those left (preconditions not
    /// met).
    pub doublets: crate::doublets::Doublets,
    /// Output: quads.
    pub quads: usize,
    /// Output: vertices.
    pub vertices: usize,
    /// Output: unmatched sides in the final graph (boundary edges).
    pub unmatched_sides: usize,
    /// Output: boundary loops, counted in the graph.
    pub boundary_loops: usize,
    /// Output: connected components.
    pub components: usize,
    /// Output: interior vertex valences.
    pub valence_interior: BTreeMap<usize, usize>,
    /// Output: boundary vertex valences.
    pub valence_boundary: BTreeMap<usize, usize>,
    /// Output: Euler characteristic V − E + F.
    pub euler: i64,
    /// Output: valid by the checker (the relaxed retry's condition; not
    /// in the JSON).
    pub mesh_valid: bool,
    /// The checker's report of the output as last counted, handed over to
    /// the facade's last check (read there while the mesh is unchanged;
    /// not in the JSON).
    pub checked: Option<dualex_check::Checked<dualex_check::QuadReport>>,
    /// The input's shape, read off the first pass's adjacency
    /// (`dualex_check::glued`), for the facade's last check (not in the
    /// JSON).
    pub input: Option<dualex_check::topology::InputShape<()>>,
}

impl AsMut<SegmentStats> for QuadStats {
    fn as_mut(&mut self) -> &mut SegmentStats {
        &mut self.segment
    }
}

impl QuadStats {
    /// Fills the output counts from the final gluing (its graph's counts)
    /// and mesh; `checked`: the checker's report of this very mesh, when
    /// made already.
    pub fn finish_output(
        &mut self,
        glued: &Glued<2>,
        mesh: &QuadMesh,
        checked: Option<QuadReport>,
    ) {
        self.unmatched_sides = glued.unmatched_sides;
        self.boundary_loops = glued.boundary_loops;
        self.components = glued.components;
        match checked {
            Some(c) => self.finish_checked(mesh, c),
            None => self.finish_mesh(mesh),
        }
    }

    /// Fills the counts read from the output mesh itself.
    pub fn finish_mesh(&mut self, mesh: &QuadMesh) {
        let c = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
        self.finish_checked(mesh, c);
    }

    /// [`Self::finish_mesh`] with the checker's report `c` of `mesh`.
    fn finish_checked(&mut self, mesh: &QuadMesh, c: QuadReport) {
        self.quads = mesh.cells.len();
        self.vertices = mesh.positions.len();
        // the counts of the validity checker (one piece of code for both)
        let hist = |h: &BTreeMap<u32, usize>| h.iter().map(|(&k, &v)| (k as usize, v)).collect();
        self.valence_interior = hist(&c.interior_valence);
        self.valence_boundary = hist(&c.boundary_valence);
        self.euler = c.euler;
        self.mesh_valid = c.is_valid();
        let n = mesh.positions.len();
        self.checked = Some(dualex_check::Checked::new(c, n, &mesh.cells));
    }

    /// The stats as one JSON object.
    pub fn to_json(&self) -> Value {
        let input = json!({
            "triangles": self.input_triangles,
            "reverted_triangles": self.reverted_triangles,
            "singularities": self.singularities,
        });
        let sanitize = json!({
            "split_edges": self.segment.split,
            "singular_on_iso_kinds": self.segment.sanitize.singular_kinds,
        });
        let rest = json!({
            "fairing": self.fairing,
            "folded_corners_collapsed": self.folded_corners_collapsed,
            "pillows_removed": self.pillows_removed,
            "bubbles_removed": self.bubbles_removed,
            "digons_pinched": self.digons_pinched,
            "repair": {
                "zipped_sides": self.zipped_sides,
                "parallel_edges_split": self.parallel_edges_split,
                "folded_cells_cut": self.folded_cells_cut,
                "pinched_vertices_split": self.pinched_vertices_split,
                "holes_filled": self.holes_filled,
                "holes_left_open": self.holes_left_open,
                "triangles": self.repair_triangles,
                "subdivided": self.subdivided,
                "local_paths": self.repair_paths,
                "dropped_cells": self.repair_dropped,
                "doublets_dissolved": self.doublets.dissolved,
                "doublets_left": self.doublets.left,
                "doublets_in_graph": self.doublets.in_graph,
            },
            "output": {
                "quads": self.quads,
                "vertices": self.vertices,
                "unmatched_sides": self.unmatched_sides,
                "boundary_loops": self.boundary_loops,
                "components": self.components,
                "euler": self.euler,
                "valence_interior": histogram_json(&self.valence_interior),
                "valence_boundary": histogram_json(&self.valence_boundary),
                "holes": self.holes_left_open,
            },
        });
        self.segment.to_json(input, sanitize, rest)
    }
}

/// The input's singularities by index, for [`QuadStats::singularities`]
/// (read on the first pass of steps 1–3; integer part unknown: "k/4 mod
/// 1").
pub fn input_singularities(map: &TriMap, model: &Model<3, 2>) -> BTreeMap<String, usize> {
    let (mut known, unknown) = dualex_map::report::singularity_histogram_with(
        map,
        &model.topo,
        &model.trans,
        &model.corners,
    );
    known.extend(unknown.into_iter().map(|(k, n)| (format!("{k} mod 1"), n)));
    known
}
