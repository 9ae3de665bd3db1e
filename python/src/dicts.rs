//! Typed stats and reports as Python dicts.
//!
//! One [`dualex::Stats`] for both dimensions, its dict keys those Python
//! has always had: the dimension's own words (`input_triangles` /
//! `input_tets`, `quads` / `hexes`, `boundary_loops` / `boundary_faces`
//! and `boundary_surfaces`, `valence_interior` / `edge_valence_interior`,
//! the repairs of each), the facade's field names elsewhere; nested structs (`repairs`, `topology`) are nested
//! dicts, valence histograms are `{valence: count}` with int keys,
//! `grid_offset` is `"half"` or `"zero"`, `time_ms` is `{stage: ms}` in
//! stage order (the geometric stage last, as `"geometry"`), `geometry` is the CLI's `geometry` section of the stats
//! (the geometric stage's report, [`crate::geometry::report`]). The map report is the CLI's `inspect --json` object.

use dualex::{Repairs, Stats};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use dualex::stats::TopologyComparison;

/// `{key: value}` of the pairs, in their order (valence histograms,
/// stage times).
fn dict<'py, K, V>(
    py: Python<'py>,
    pairs: impl IntoIterator<Item = (K, V)>,
) -> PyResult<Bound<'py, PyDict>>
where
    K: IntoPyObject<'py>,
    V: IntoPyObject<'py>,
{
    let d = PyDict::new(py);
    for (k, v) in pairs {
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

/// The stats of [`dualex::quad`] (`dim` 2) or [`dualex::hex`] (`dim` 3)
/// as a dict, in the keys and order Python has always had.
pub fn stats<'py>(py: Python<'py>, s: &Stats, dim: usize) -> PyResult<Bound<'py, PyDict>> {
    let hexes = dim == 3;
    let (simplices, cells) = if hexes {
        ("tets", "hexes")
    } else {
        ("triangles", "quads")
    };
    let d = PyDict::new(py);
    d.set_item(format!("input_{simplices}"), s.input_simplices)?;
    d.set_item(format!("reverted_{simplices}"), s.reverted_simplices)?;
    if hexes {
        d.set_item("degenerate_tets", s.degenerate_simplices)?;
    }
    d.set_item("singular_vertices", s.singular_vertices)?;
    if hexes {
        d.set_item("singular_edges", s.singular_edges)?;
    }
    d.set_item("max_transition_residual", s.max_transition_residual)?;
    d.set_item("transitions_rounded", s.transitions_rounded)?;
    d.set_item("welded_vertices", s.welded_vertices)?;
    d.set_item("grid_offset", s.grid_offset.name())?;
    d.set_item("nodes", s.nodes)?;
    d.set_item(cells, s.cells)?;
    d.set_item("vertices", s.vertices)?;
    if hexes {
        d.set_item("boundary_faces", s.boundary_facets)?;
        d.set_item("boundary_surfaces", s.boundary_components)?;
    } else {
        d.set_item("boundary_loops", s.boundary_components)?;
    }
    d.set_item("components", s.components)?;
    d.set_item("euler", s.euler)?;
    if hexes {
        d.set_item("edge_valence_interior", dict(py, &s.valence_interior)?)?;
    } else {
        d.set_item("valence_interior", dict(py, &s.valence_interior)?)?;
        d.set_item("valence_boundary", dict(py, &s.valence_boundary)?)?;
    }
    d.set_item("repairs", repairs(py, &s.repairs, hexes)?)?;
    d.set_item("topology", topology(py, &s.topology)?)?;
    d.set_item("geometry", crate::geometry::report(py, &s.geometry)?)?;
    let t = dict(py, s.time_ms.iter().map(|(k, v)| (k, v)))?;
    t.set_item("geometry", s.geometry.time_ms)?;
    d.set_item("time_ms", t)?;
    Ok(d)
}

/// The repairs of one dimension, in the keys Python has always had.
fn repairs<'py>(py: Python<'py>, r: &Repairs, hexes: bool) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item(if hexes { "split_faces" } else { "split_edges" }, r.split)?;
    d.set_item("snapped_vertices", r.snapped_vertices)?;
    d.set_item("perturbed_vertices", r.perturbed_vertices)?;
    d.set_item("pleats_removed", r.pleats_removed)?;
    if hexes {
        d.set_item("open_interior_faces", r.holes_left_open)?;
        d.set_item("doublet_chains_dissolved", r.doublets_dissolved)?;
        return Ok(d);
    }
    d.set_item("folded_corners_collapsed", r.folded_corners_collapsed)?;
    d.set_item("holes_filled", r.holes_filled)?;
    d.set_item("holes_left_open", r.holes_left_open)?;
    d.set_item("triangles", r.triangles)?;
    d.set_item("subdivided", r.subdivided)?;
    d.set_item("doublets_dissolved", r.doublets_dissolved)?;
    Ok(d)
}

/// The map report (the CLI's `inspect --json`) as a dict.
pub fn map_report<'py>(
    py: Python<'py>,
    r: &dualex::map::report::MapReport,
) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?
        .call_method1("loads", (dualex::map_report_json(r).to_string(),))
}
