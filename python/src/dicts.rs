//! Typed stats and reports as Python dicts.
//!
//! Keys are the facade's field names ([`dualex::QuadStats`],
//! [`dualex::HexStats`]); nested structs (`repairs`, `topology`) are nested
//! dicts, valence histograms are `{valence: count}` with int keys,
//! `grid_offset` is `"half"` or `"zero"`, `time_ms` is `{stage: ms}` in
//! stage order (the geometric stage last, as `"geometry"`), `geometry` is the CLI's `geometry` section of the stats
//! (the geometric stage's report, [`crate::geometry::report`]). The map report is the CLI's `inspect --json` object.

use dualex::{GridOffset, HexStats, QuadStats};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::BTreeMap;

use dualex::stats::TopologyComparison;

fn offset(g: GridOffset) -> &'static str {
    match g {
        GridOffset::Zero => "zero",
        GridOffset::Half => "half",
        GridOffset::Auto => "auto",
    }
}

fn histogram<'py>(py: Python<'py>, h: &BTreeMap<usize, usize>) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (k, v) in h {
        d.set_item(k, v)?;
    }
    Ok(d)
}

fn times<'py>(py: Python<'py>, t: &[(String, f64)]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    for (k, v) in t {
        d.set_item(k, v)?;
    }
    Ok(d)
}

fn topology<'py>(py: Python<'py>, t: &TopologyComparison) -> PyResult<Bound<'py, PyDict>> {
    let side = |s: &dualex::Topology| -> PyResult<Bound<'py, PyDict>> {
        let d = PyDict::new(py);
        d.set_item("components", s.components)?;
        d.set_item("euler", s.euler)?;
        d.set_item("boundary_components", s.boundary_components)?;
        Ok(d)
    };
    let d = PyDict::new(py);
    d.set_item("input", side(&t.input)?)?;
    d.set_item("output", side(&t.output)?)?;
    d.set_item("matches", t.matches())?;
    Ok(d)
}

/// The stats of [`dualex::quad`] as a dict.
pub fn quad_stats<'py>(py: Python<'py>, s: &QuadStats) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("input_triangles", s.input_triangles)?;
    d.set_item("reverted_triangles", s.reverted_triangles)?;
    d.set_item("singular_vertices", s.singular_vertices)?;
    d.set_item("max_transition_residual", s.max_transition_residual)?;
    d.set_item("transitions_rounded", s.transitions_rounded)?;
    d.set_item("welded_vertices", s.welded_vertices)?;
    d.set_item("grid_offset", offset(s.grid_offset))?;
    d.set_item("nodes", s.nodes)?;
    d.set_item("quads", s.quads)?;
    d.set_item("vertices", s.vertices)?;
    d.set_item("boundary_loops", s.boundary_loops)?;
    d.set_item("components", s.components)?;
    d.set_item("euler", s.euler)?;
    d.set_item("valence_interior", histogram(py, &s.valence_interior)?)?;
    d.set_item("valence_boundary", histogram(py, &s.valence_boundary)?)?;
    let r = &s.repairs;
    let rd = PyDict::new(py);
    rd.set_item("split_edges", r.split_edges)?;
    rd.set_item("snapped_vertices", r.snapped_vertices)?;
    rd.set_item("perturbed_vertices", r.perturbed_vertices)?;
    rd.set_item("pleats_removed", r.pleats_removed)?;
    rd.set_item("folded_corners_collapsed", r.folded_corners_collapsed)?;
    rd.set_item("holes_filled", r.holes_filled)?;
    rd.set_item("holes_left_open", r.holes_left_open)?;
    rd.set_item("triangles", r.triangles)?;
    rd.set_item("subdivided", r.subdivided)?;
    rd.set_item("doublets_dissolved", r.doublets_dissolved)?;
    d.set_item("repairs", rd)?;
    d.set_item("topology", topology(py, &s.topology)?)?;
    d.set_item("geometry", crate::geometry::report(py, &s.geometry)?)?;
    let t = times(py, &s.time_ms)?;
    t.set_item("geometry", s.geometry.time_ms)?;
    d.set_item("time_ms", t)?;
    Ok(d)
}

/// The stats of [`dualex::hex`] as a dict.
pub fn hex_stats<'py>(py: Python<'py>, s: &HexStats) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("input_tets", s.input_tets)?;
    d.set_item("reverted_tets", s.reverted_tets)?;
    d.set_item("degenerate_tets", s.degenerate_tets)?;
    d.set_item("singular_vertices", s.singular_vertices)?;
    d.set_item("singular_edges", s.singular_edges)?;
    d.set_item("max_transition_residual", s.max_transition_residual)?;
    d.set_item("transitions_rounded", s.transitions_rounded)?;
    d.set_item("welded_vertices", s.welded_vertices)?;
    d.set_item("grid_offset", offset(s.grid_offset))?;
    d.set_item("nodes", s.nodes)?;
    d.set_item("hexes", s.hexes)?;
    d.set_item("vertices", s.vertices)?;
    d.set_item("boundary_faces", s.boundary_faces)?;
    d.set_item("boundary_surfaces", s.boundary_surfaces)?;
    d.set_item("components", s.components)?;
    d.set_item("euler", s.euler)?;
    d.set_item(
        "edge_valence_interior",
        histogram(py, &s.edge_valence_interior)?,
    )?;
    let r = &s.repairs;
    let rd = PyDict::new(py);
    rd.set_item("split_faces", r.split_faces)?;
    rd.set_item("snapped_vertices", r.snapped_vertices)?;
    rd.set_item("perturbed_vertices", r.perturbed_vertices)?;
    rd.set_item("pleats_removed", r.pleats_removed)?;
    rd.set_item("open_interior_faces", r.open_interior_faces)?;
    rd.set_item("doublet_chains_dissolved", r.doublet_chains_dissolved)?;
    d.set_item("repairs", rd)?;
    d.set_item("topology", topology(py, &s.topology)?)?;
    d.set_item("geometry", crate::geometry::report(py, &s.geometry)?)?;
    let t = times(py, &s.time_ms)?;
    t.set_item("geometry", s.geometry.time_ms)?;
    d.set_item("time_ms", t)?;
    Ok(d)
}

/// The map report (the CLI's `inspect --json`) as a dict.
pub fn map_report<'py>(
    py: Python<'py>,
    r: &dualex_map::report::MapReport,
) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?
        .call_method1("loads", (dualex::map_report_json(r).to_string(),))
}
