//! What the stage measured and did: the [`Report`] of the stats'
//! `geometry` section.

use super::Input;
use crate::constraint::{Constraints, Kind, Role};
use crate::quality::{norm, sub, Summary};
use crate::reference::Reference;

/// What the stage measured and did.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// The mode's name (`off`, `auto`, `smooth`).
    pub mode: &'static str,
    /// Quality of the positions it was given.
    pub before: Summary,
    /// Quality of the positions it returned.
    pub after: Summary,
    /// Vertices it moved.
    pub moved_vertices: usize,
    /// The largest move, in model units.
    pub max_move: f64,
    /// The mean edge length of the mesh it was given.
    pub mean_edge: f64,
    /// Output boundary vertices.
    pub boundary_vertices: usize,
    /// Of them, those farther than [`ON_BOUNDARY`](super::ON_BOUNDARY) mean edge lengths from
    /// the input's boundary before the stage, put onto it.
    pub boundary_off: usize,
    /// Boundary vertices released from the input's boundary (left where
    /// the map puts them, free on the surface or in the volume): corners
    /// of the mesh (vertices of one cell) without a corner of the input's
    /// curves within half an edge (for quads: one whose interior angle is
    /// at most [`MESH_CORNER_ANGLE`](super::MESH_CORNER_ANGLE)), and their neighbours in that cell;
    /// on a smooth or concave boundary that cell would be flat or
    /// inverted.
    pub boundary_released: usize,
    /// The largest distance of a boundary vertex to the input's boundary,
    /// before and after (model units; 0 when not measured).
    pub boundary_distance: [f64; 2],
    /// Vertices released from the input's feature curves (left free on
    /// the surface) because a cell at them stayed inverted after every
    /// ring of the untangling: the last attempt runs without them bound.
    pub features_released: usize,
    /// Optimisation rounds, and the rings of the last region (auto).
    pub rounds: usize,
    /// Rings around the inverted elements that were moved (auto).
    pub rings: usize,
    /// Time of the stage, ms.
    pub time_ms: f64,
}

impl Report {
    /// The largest move in mean edge lengths.
    pub fn max_move_edges(&self) -> f64 {
        if self.mean_edge > 0.0 {
            self.max_move / self.mean_edge
        } else {
            0.0
        }
    }

    /// Whether it moved anything.
    pub fn moved(&self) -> bool {
        self.moved_vertices > 0
    }

    /// As JSON (the `geometry` section of the stats; its time goes with
    /// the other stages' times).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "mode": self.mode,
            "measure": "scaled Jacobian",
            "before": self.before.to_json(),
            "after": self.after.to_json(),
            "moved_vertices": self.moved_vertices,
            "max_move": self.max_move,
            "max_move_edges": self.max_move_edges(),
            "mean_edge": self.mean_edge,
            "boundary": {
                "vertices": self.boundary_vertices,
                "off_input_boundary_before": self.boundary_off,
                "put_on_boundary": self.boundary_off,
                "released_mesh_corners": self.boundary_released,
                "max_distance_before": self.boundary_distance[0],
                "max_distance_after": self.boundary_distance[1],
            },
            "features_released": self.features_released,
            "rounds": self.rounds,
            "rings": self.rings,
        })
    }
}

/// 6. The report's moves (vertices moved, the longest move) and the
///    distance to the input's boundary (curves in 2D, surface in 3D) of
///    the boundary vertices kept on it.
pub(super) fn moves_and_distances<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    start: &[[f64; 3]],
    input: &Input<D, K>,
    cons: &Constraints,
    r: &Reference,
    boundary: bool,
    rep: &mut Report,
) {
    use rayon::prelude::*;
    // per vertex: its move (0 when it did not), its distance to the
    // boundary (0 when not measured); counted and maximised (exact in any
    // order) over the vertices in parallel
    let per_vertex = |v: usize| {
        let moved = norm(sub(x[v], start[v]));
        let on_it = match input.role {
            Role::Surface => matches!(cons.kind[v], Kind::Curve { boundary: true }),
            Role::Volume => cons.kind[v] != Kind::Free,
        };
        let off = if boundary && input.on_boundary[v] && on_it {
            match input.role {
                Role::Surface => r.closest_on_curves(x[v], true).map_or(0.0, |c| c.2),
                Role::Volume => r.closest(x[v], None).map_or(0.0, |f| f.distance),
            }
        } else {
            0.0
        };
        (usize::from(moved > 0.0), moved, off)
    };
    let (count, max_move, max_off) = (0..x.len())
        .into_par_iter()
        .with_min_len(256)
        .map(per_vertex)
        .reduce(
            || (0, 0.0, 0.0),
            |a, b| (a.0 + b.0, a.1.max(b.1), a.2.max(b.2)),
        );
    rep.moved_vertices += count;
    rep.max_move = rep.max_move.max(max_move);
    rep.boundary_distance[1] = rep.boundary_distance[1].max(max_off);
}
