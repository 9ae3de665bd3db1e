//! The two dimensions of the steps ([`crate::steps`]): one [`Dimension`]
//! impl per map type (which extraction, checker, topology and geometric
//! stage run) and one [`Report`] impl per extraction report (what it
//! shares with the other, and the facade's [`Stats`] of it).
//!
//! Input: a map and the facade's options; output: the steps' generic
//! [`Extraction`], the input's shape and boundary ([`InputShape`]: tets,
//! their faces of one tet), [`Check`] and the geometric stage's report.
//! Invariants: the reports' shared half ([`SegmentStats`]) is read in one
//! place (`report!`, [`common_stats`]), so that both dimensions say the
//! same thing by the same field; sources keep the extraction's numbering
//! ([`NO_SOURCE`] only for a quad closing a hole).

use crate::stats::{Repairs, Stats, TopologyComparison};
use crate::steps::{Check, Dimension, InputShape, Report, SegmentStats};
use crate::steps::{HexExtraction, HexReport, QuadExtraction, QuadReport};
use crate::{GeometryOptions, GeometryReport, InputError, Options, TetMap, TriMap};
use dualex_check::glued;
use dualex_check::topology as topo;
use dualex_check::Checked;
use dualex_map::TransitionOptions;

#[cfg(doc)]
use crate::steps::{Extraction, NO_SOURCE};

/// The transition options of the facade's `round_transitions`.
fn transitions(round: bool) -> TransitionOptions {
    TransitionOptions {
        round,
        ..Default::default()
    }
}

impl Dimension<4, 2> for TriMap {
    type Report = QuadReport;
    type Boundary = ();

    fn input_shape(&self) -> InputShape<()> {
        InputShape {
            shape: topo::surface_shape(self.positions.len(), &self.simplices),
            boundary: (),
        }
    }

    fn carried(&self, x: &QuadExtraction) -> Option<InputShape<()>> {
        x.stats.input.clone()
    }

    fn extract(&self, opts: &Options, singularities: bool) -> Result<QuadExtraction, InputError> {
        let inner = dualex_quad::QuadOptions {
            fairing: opts.fairing,
            transitions: transitions(opts.round_transitions),
            seed: opts.seed,
            grid_offset: opts.grid_offset,
            singularity_stats: singularities,
        };
        dualex_quad::extract_full(self, &inner)
    }

    fn check(&self, input: &InputShape<()>, x: &QuadExtraction) -> Check {
        let (n, cells) = (x.mesh.positions.len(), &x.mesh.cells);
        let rep = Checked::or_check(x.stats.checked.as_ref(), n, cells, || {
            dualex_check::check_quad_mesh(n, cells)
        });
        let (input, output) = (input.shape, topo::quad_shape(&rep));
        Check::new(rep.errors(), (input, output), rep.boundary_edges)
    }

    fn geometry(
        &self,
        _: &InputShape<()>,
        x: &mut QuadExtraction,
        opts: &GeometryOptions,
    ) -> GeometryReport {
        // the stage's "none" is u32::MAX, the extraction's NO_SOURCE
        let (m, s) = (&mut x.mesh, &x.sources);
        // the extraction's check of these very cells: every edge of two
        // quads, so no boundary vertex for the stage to find
        let report = x.stats.checked.as_ref();
        let closed = report
            .and_then(|c| c.of(m.positions.len(), &m.cells))
            .is_some_and(|r| {
                r.boundary_edges == 0
                    && r.degenerate_faces.is_empty()
                    && r.out_of_range_faces.is_empty()
            });
        dualex_geom::quads(
            &mut m.positions,
            &m.cells,
            &self.positions,
            &self.simplices,
            s,
            closed,
            opts,
        )
    }
}

impl Dimension<8, 3> for TetMap {
    type Report = HexReport;
    /// The places `4·tet + f` of the faces of one tet, in no order.
    type Boundary = Vec<usize>;

    fn input_shape(&self) -> InputShape<Vec<usize>> {
        let (shape, boundary) = topo::tet_shape_and_boundary(self.positions.len(), &self.simplices);
        InputShape { shape, boundary }
    }

    /// The boundary surface's shape found here, from the faces of one
    /// tet carried (`dualex_check::glued::tet_shape`).
    fn carried(&self, x: &HexExtraction) -> Option<InputShape<Vec<usize>>> {
        let g = x.stats.input.as_ref()?;
        Some(InputShape {
            shape: glued::tet_shape(self.positions.len(), &self.simplices, g),
            boundary: g.lone.clone(),
        })
    }

    /// (3D always counts its singular edges: no `singularities` switch.)
    fn extract(&self, opts: &Options, _: bool) -> Result<HexExtraction, InputError> {
        let inner = dualex_hex::HexOptions {
            transitions: transitions(opts.round_transitions),
            seed: opts.seed,
            grid_offset: opts.grid_offset,
            fairing: opts.fairing,
        };
        dualex_hex::extract_full(self, &inner)
    }

    /// Combinatorial validity only: hexes of a messy map may be inverted
    /// (the geometric stage measures them).
    fn check(&self, input: &InputShape<Vec<usize>>, x: &HexExtraction) -> Check {
        let (n, cells) = (x.mesh.positions.len(), &x.mesh.cells);
        let rep = Checked::or_check(x.stats.checked.as_ref(), n, cells, || {
            dualex_check::check_hex_mesh(n, cells, None)
        });
        let input = input.shape;
        let output = topo::hex_shape(&rep);
        Check::new(rep.errors(), (input, output), rep.boundary_faces)
    }

    fn geometry(
        &self,
        input: &InputShape<Vec<usize>>,
        x: &mut HexExtraction,
        opts: &GeometryOptions,
    ) -> GeometryReport {
        let m = &mut x.mesh;
        dualex_geom::hexes(
            &mut m.positions,
            &m.cells,
            &self.positions,
            &self.simplices,
            &input.boundary,
            opts,
        )
    }
}

/// [`Report`] for both reports: their shared half, their own JSON, and
/// the facade's stats: the fields both fill alike ([`common_stats`]),
/// then the dimension's own (`$stats`).
macro_rules! report {
    ($report:ty, $stats:ident) => {
        impl Report for $report {
            fn segment(&self) -> &SegmentStats {
                &self.segment
            }

            fn to_json(&self) -> serde_json::Value {
                <$report>::to_json(self)
            }

            fn stats(&self, check: &Check) -> Stats {
                $stats(self, check, common_stats(&self.segment, check))
            }
        }
    };
}

report!(QuadReport, quad_stats);
report!(HexReport, hex_stats);

/// The [`Stats`] fields that both dimensions fill alike: from the shared
/// half of the report `s` and the output `check`.
fn common_stats(s: &SegmentStats, check: &Check) -> Stats {
    Stats {
        singular_vertices: s.singular_vertices,
        max_transition_residual: s.max_transition_residual,
        transitions_rounded: s.snapped_transitions,
        grid_offset: s.grid_offset.offset,
        nodes: s.nodes,
        repairs: Repairs {
            split: s.split,
            snapped_vertices: s.sanitize.snapped_vertices,
            perturbed_vertices: s.sanitize.perturbed_vertices,
            pleats_removed: s.untangle.as_ref().map_or(0, |u| u.pleats_removed),
            ..Repairs::default()
        },
        topology: TopologyComparison {
            input: check.topology.input.into(),
            output: check.topology.output.into(),
        },
        time_ms: s.time_ms.clone(),
        ..Stats::default()
    }
}

/// The facade's stats of a quad extraction: its own fields over `common`.
fn quad_stats(s: &QuadReport, check: &Check, common: Stats) -> Stats {
    Stats {
        input_simplices: s.input_triangles,
        reverted_simplices: s.reverted_triangles,
        cells: s.quads,
        vertices: s.vertices,
        // the checker's count (holes closed by a face are no boundary)
        boundary_facets: check.boundary_facets,
        boundary_components: s.boundary_loops,
        components: s.components,
        euler: s.euler,
        valence_interior: s.valence_interior.clone(),
        valence_boundary: s.valence_boundary.clone(),
        repairs: Repairs {
            folded_corners_collapsed: s.folded_corners_collapsed,
            holes_filled: s.holes_filled,
            holes_left_open: s.holes_left_open,
            triangles: s.repair_triangles,
            subdivided: s.subdivided,
            doublets_dissolved: s.doublets.dissolved,
            ..common.repairs
        },
        ..common
    }
}

/// The facade's stats of a hex extraction: its own fields over `common`
/// (the boundary facets are the extraction's, not the checker's).
fn hex_stats(s: &HexReport, _: &Check, common: Stats) -> Stats {
    Stats {
        input_simplices: s.input_tets,
        reverted_simplices: s.reverted_tets,
        degenerate_simplices: s.degenerate_tets,
        singular_edges: s.singular_edges,
        cells: s.hexes,
        vertices: s.vertices,
        boundary_facets: s.unmatched_sides,
        boundary_components: s.boundary_surfaces,
        components: s.components,
        euler: s.euler,
        valence_interior: s.edge_valence_interior.clone(),
        repairs: Repairs {
            holes_left_open: s.open_interior_faces,
            doublets_dissolved: s.doublets.dissolved,
            ..common.repairs
        },
        ..common
    }
}
