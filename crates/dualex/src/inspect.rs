//! The JSON form of a map's `inspect` report ([`MapReport`]), as the CLI's
//! `dualex inspect --json` prints it and Python's `inspect` returns it.
//!
//! Input: a [`MapReport`] (`dualex_map::report`). Output: one JSON object
//! with the report's fields; in 2D the boundary loops and the singularity
//! histograms, in 3D the singular edges' histogram. It lives in the facade
//! because the map model carries no JSON dependency.

use dualex_map::MapReport;
use std::collections::BTreeMap;

/// The report as one JSON object.
pub fn map_report_json(r: &MapReport) -> serde_json::Value {
    let mut v = serde_json::json!({
        "dimension": r.dimension,
        "simplices": r.simplices,
        "vertices": r.vertices,
        "boundary_facets": r.boundary_facets,
        "components": r.components,
        "reverted": r.reverted,
        "degenerate": r.degenerate,
        "max_transition_residual": r.max_transition_residual,
        "snapped_transitions": r.snapped_transitions,
        "ambiguous_facets": r.ambiguous_facets,
        "non_identity_transitions": r.non_identity_transitions,
        "singular_vertices": r.singular_vertices,
        "welded_vertices": r.welded_vertices,
    });
    if let Some(obj) = v.as_object_mut() {
        if r.dimension == 2 {
            obj.insert("boundary_loops".into(), r.boundary_loops.into());
            obj.insert("singularities".into(), map_json(&r.singularities));
            obj.insert(
                "singularities_integer_part_unknown".into(),
                map_json(&r.singularities_integer_part_unknown),
            );
        } else {
            obj.insert("singular_edges".into(), map_json(&r.singular_edges));
        }
    }
    v
}

fn map_json(m: &BTreeMap<String, usize>) -> serde_json::Value {
    serde_json::Value::Object(m.iter().map(|(k, v)| (k.clone(), (*v).into())).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::test_maps::{cube_surface, edge_fan, rechart};
    use dualex_map::{inspect, InspectOptions};

    #[test]
    fn cube_report() {
        let mut m = cube_surface(3);
        rechart(&mut m, 9);
        let r = inspect(&m, &InspectOptions::default()).expect("cube");
        let j = map_report_json(&r);
        assert_eq!(j["simplices"], 6 * 9 * 2);
        assert_eq!(j["vertices"], 6 * 9 + 2);
        assert_eq!(j["boundary_loops"], 0);
        assert_eq!(j["components"], 1);
        assert_eq!(j["reverted"], 0);
        assert_eq!(j["degenerate"], 0);
        assert_eq!(j["max_transition_residual"], 0.0);
        assert_eq!(j["singularities"], serde_json::json!({"1/4": 8}));
        assert_eq!(
            j["singularities_integer_part_unknown"],
            serde_json::json!({})
        );
        assert_eq!(j["welded_vertices"], 0);
        assert_eq!(j["ambiguous_facets"], 0);
        assert!(j.get("singular_edges").is_none());
        let text = r.to_string();
        assert!(
            text.contains("singularities (index: count): 1/4: 8"),
            "{text}"
        );
    }

    #[test]
    fn tet_report() {
        let r = inspect(&edge_fan(5), &InspectOptions::default()).expect("fan");
        let j = map_report_json(&r);
        assert_eq!(j["simplices"], 5);
        assert_eq!(j["singular_edges"], serde_json::json!({"-90": 1}));
        assert!(j.get("boundary_loops").is_none());
        assert_eq!(r.singular_vertices, 2);
    }
}
