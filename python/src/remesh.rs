//! `remesh(V, F, **options)`: quads from a plain triangle surface, through
//! the facade's pipeline ([`dualex::remesh()`], the one `dualex remesh`
//! runs).
//!
//! Input: numpy positions (n, 3) and triangles (m, 3), keyword options.
//! Output: `(Q, quads, stats)`, plus the map `(V, F, UV)` (over the welded
//! surface, as `read` returns a map) with `return_map=True`. The stats
//! dict is `quad`'s with the `"remesh"` section of `dualex remesh
//! --stats`. Errors are `ValueError`s with the CLI's one-line message
//! (remesh's own bugs start `internal error (bug) in remesh`); the GIL is
//! released while Rust works.

use crate::arrays::{cells_array, indices, positions_array, rows};
use crate::{dicts, value_error};
use dualex::{MapOptions, Quantization, RemeshOptions, Target};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

fn rounding(s: &str) -> PyResult<Quantization> {
    match s {
        "direct" => Ok(Quantization::Direct),
        "greedy" => Ok(Quantization::Greedy),
        "off" => Ok(Quantization::SingularitiesOff),
        _ => Err(PyValueError::new_err(format!(
            "rounding: expected \"direct\", \"greedy\" or \"off\", got {s:?}"
        ))),
    }
}

/// Quads from a plain triangle surface (as `dualex remesh`).
///
/// V: (n, 3) vertex positions; F: (m, 3) vertex indices of the triangles
/// (cut surfaces are welded first). quads: about this many quads (>= 1);
/// sharp: edges whose dihedral angle exceeds this many degrees (0-180) are
/// features the field follows; rounding: "direct", "greedy" or "off"
/// (singular vertices left off the grid); seed: where the grid falls;
/// round_transitions and strict as for `quad`. Returns (positions (k, 3)
/// float64, quads (q, 4) int64, stats dict with a "remesh" section); with
/// return_map=True also the map (V, F, UV) that was extracted. Raises
/// ValueError on bad arrays, a bad option, a surface that is not a
/// manifold, no quad at all, or a map remesh could not make (reported as
/// its bug).
#[pyfunction]
#[pyo3(signature = (V, F, *, quads=1000, sharp=35.0, rounding="direct", seed=1, round_transitions=false, strict=false, return_map=false))]
#[allow(non_snake_case, clippy::too_many_arguments)]
pub fn remesh<'py>(
    py: Python<'py>,
    V: &Bound<'py, PyAny>,
    F: &Bound<'py, PyAny>,
    quads: usize,
    sharp: f64,
    rounding: &str,
    seed: u64,
    round_transitions: bool,
    strict: bool,
    return_map: bool,
) -> PyResult<Bound<'py, PyTuple>> {
    if quads == 0 {
        return Err(PyValueError::new_err("quads: expected at least 1, got 0"));
    }
    if !(0.0..=180.0).contains(&sharp) {
        return Err(PyValueError::new_err(format!(
            "sharp: expected an angle from 0 to 180 degrees, got {sharp}"
        )));
    }
    let defaults = RemeshOptions::default();
    let opts = RemeshOptions {
        map: MapOptions {
            target: Target::Quads(quads),
            sharp_degrees: sharp,
            quantization: self::rounding(rounding)?,
            seed,
        },
        extract: dualex::Options {
            round_transitions,
            strict,
            ..defaults.extract
        },
    };
    let (p, t) = (rows::<3>("V", V)?, indices::<3>("F", "triangle", F)?);
    let out = py
        .allow_threads(|| dualex::remesh(&p, &t, &opts))
        .map_err(value_error)?;
    let stats = dicts::stats(py, &out.quads.stats, 2)?;
    let section = py
        .import("json")?
        .call_method1("loads", (out.remesh.to_json().to_string(),))?;
    stats.set_item("remesh", section)?;
    let mut items = vec![
        positions_array(py, &out.quads.mesh.positions)?,
        cells_array(py, &out.quads.mesh.cells)?,
        stats.into_any(),
    ];
    if return_map {
        items.push(crate::map_tuple(py, &out.map)?.into_any());
    }
    PyTuple::new(py, items)
}
