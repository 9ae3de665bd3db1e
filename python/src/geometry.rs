//! The geometric stage's keyword arguments of `quad` and `hex`
//! (`untangle`, `smooth`) as the facade's options, and its report as the
//! stats' `"geometry"` dict.
//!
//! `untangle`: `"auto"` (default; `None` too) or `"off"`. `smooth`: `None` (default) or
//! `False` (no smoothing), `True` ([`dualex::SMOOTH_ROUNDS`] rounds) or a
//! number of rounds ≥ 1; smoothing with `untangle="off"` is refused (as
//! the CLI's `--smooth` with `--untangle off`). Anything else is a
//! `ValueError` naming the argument.

use dualex::{GeometryMode, GeometryOptions, GeometryReport};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyBool;

/// The stage's options from the two keyword arguments.
pub fn options(
    untangle: Option<&Bound<'_, PyAny>>,
    smooth: Option<&Bound<'_, PyAny>>,
) -> PyResult<GeometryOptions> {
    let auto = match untangle.map(|u| u.extract::<String>()) {
        None => true,
        Some(Ok(u)) if u == "auto" => true,
        Some(Ok(u)) if u == "off" => false,
        Some(_) => {
            return Err(PyValueError::new_err(format!(
                "untangle: expected \"auto\" or \"off\", got {}",
                shown(untangle)
            )))
        }
    };
    let rounds = match smooth {
        None => None,
        Some(s) if s.is_instance_of::<PyBool>() => {
            s.extract::<bool>()?.then_some(dualex::SMOOTH_ROUNDS)
        }
        Some(s) => match s.extract::<i64>() {
            Ok(n) if n >= 1 => Some(usize::try_from(n).map_err(|_| bad_smooth(s))?),
            _ => return Err(bad_smooth(s)),
        },
    };
    let mode = match (auto, rounds) {
        (true, Some(n)) => GeometryMode::Smooth(n),
        (true, None) => GeometryMode::Auto,
        (false, None) => GeometryMode::Off,
        (false, Some(_)) => {
            return Err(PyValueError::new_err(
                "smooth: smoothing moves the vertices that untangle=\"off\" keeps; give one or the other",
            ))
        }
    };
    Ok(GeometryOptions {
        mode,
        ..Default::default()
    })
}

/// A value as Python prints it (`repr`).
fn shown(x: Option<&Bound<'_, PyAny>>) -> String {
    x.and_then(|x| x.repr().ok())
        .map_or_else(|| "an unprintable value".to_string(), |r| r.to_string())
}

fn bad_smooth(s: &Bound<'_, PyAny>) -> PyErr {
    PyValueError::new_err(format!(
        "smooth: expected None, True or a number of rounds >= 1, got {}",
        shown(Some(s))
    ))
}

/// The stage's report as a dict: the CLI's `geometry` section of the
/// stats (mode, measure, before/after summaries, moves, boundary, rounds).
pub fn report<'py>(py: Python<'py>, r: &GeometryReport) -> PyResult<Bound<'py, PyAny>> {
    py.import("json")?
        .call_method1("loads", (r.to_json().to_string(),))
}
