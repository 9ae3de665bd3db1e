//! What the stage measured and did: the [`Report`] of the stats'
//! `geometry` section.

use crate::quality::Summary;

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
