//! [`RemeshStats`] as JSON: the `remesh` section of `dualex remesh
//! --stats`, and of the stats dict of the Python `remesh`.
//!
//! Input: the stats. Output: one JSON object, keys the field names,
//! `singularity_index` as `{"k/4": count}`, `time_ms` as `{stage: ms}`.

use crate::RemeshStats;

impl RemeshStats {
    /// The stats as one JSON object (module docs).
    pub fn to_json(&self) -> serde_json::Value {
        let s = self;
        let index: serde_json::Map<String, serde_json::Value> = s
            .singularity_index
            .iter()
            .map(|(q, n)| (format!("{q}/4"), (*n).into()))
            .collect();
        serde_json::json!({
            "triangles": s.triangles,
            "input_triangles": s.input_triangles,
            "singularities": s.singularities,
            "singularity_index": index,
            "boundary_singularities": s.boundary_singularities,
            "sharp_edges": s.sharp_edges,
            "cut_edges": s.cut_edges,
            "flipped": s.flipped,
            "degenerate": s.degenerate,
            "scale": s.scale,
            "first_scale": s.first_scale,
            "map_area": s.map_area,
            "roundings": s.roundings,
            "rounded": s.rounded,
            "off_grid": s.off_grid,
            "max_rounding": s.max_rounding,
            "counted": s.counted,
            "kept": s.kept,
            "grid_attempts": s.grid_attempts,
            "time_ms": {
                "field": s.time_ms[0],
                "cut": s.time_ms[1],
                "integrate": s.time_ms[2],
                "count": s.time_ms[3],
            },
        })
    }
}
