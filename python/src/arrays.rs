//! numpy arrays in and out.
//!
//! Input: any object numpy can turn into an array (`numpy.asarray`). Float
//! arrays are converted to `float64`, index arrays must hold integers (any
//! integer dtype) and are converted to `int64`. Shapes are checked here
//! (`positions: expected shape (n, 3), got (4, 2)`), negative indices and
//! indices beyond `u32` too; everything else (indices out of range,
//! non-finite values, a vertex twice in a simplex) is checked by the
//! facade's `*_map_from_slices`, whose message names the element. Every
//! failure is a `ValueError`; nothing panics.
//!
//! Output: `float64` arrays of shape (n, 3) for positions, `int64`
//! arrays of shape (m, K) for cells and (m,) for their source simplices.

use numpy::{PyArray1, PyArrayMethods, PyReadonlyArrayDyn, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// `numpy.asarray(obj, dtype, order="C")` after checking the dtype's kind
/// (`kinds`: numpy's one-letter codes, e.g. "fiu").
fn converted<'py>(
    name: &str,
    obj: &Bound<'py, PyAny>,
    kinds: &str,
    dtype: &str,
    what: &str,
) -> PyResult<Bound<'py, PyAny>> {
    let np = obj.py().import("numpy")?;
    let arr = np
        .call_method1("asarray", (obj,))
        .map_err(|e| PyValueError::new_err(format!("{name}: not an array: {e}")))?;
    let dt = arr.getattr("dtype")?;
    let kind: String = dt.getattr("kind")?.extract()?;
    if !kinds.contains(kind.as_str()) {
        let dt: String = dt.str()?.extract()?;
        return Err(PyValueError::new_err(format!(
            "{name}: expected {what}, got an array of dtype {dt}"
        )));
    }
    let kw = PyDict::new(obj.py());
    kw.set_item("dtype", dtype)?;
    kw.set_item("order", "C")?;
    np.call_method("asarray", (arr,), Some(&kw))
}

fn shape_text(s: &[usize]) -> String {
    let parts: Vec<String> = s.iter().map(|d| d.to_string()).collect();
    if parts.len() == 1 {
        format!("({},)", parts[0])
    } else {
        format!("({})", parts.join(", "))
    }
}

/// Checks `shape` against `want` (`None`: any length); the error spells
/// both out.
fn check_shape(name: &str, shape: &[usize], want: &[Option<usize>]) -> PyResult<()> {
    let ok = shape.len() == want.len()
        && shape
            .iter()
            .zip(want)
            .all(|(&s, w)| w.is_none_or(|w| w == s));
    if ok {
        return Ok(());
    }
    let letters = ["n", "m", "k"];
    let w: Vec<String> = want
        .iter()
        .enumerate()
        .map(|(i, w)| w.map_or_else(|| letters[i.min(2)].to_string(), |w| w.to_string()))
        .collect();
    Err(PyValueError::new_err(format!(
        "{name}: expected shape ({}), got {}",
        w.join(", "),
        shape_text(shape)
    )))
}

/// A float array of shape `[n, K]` as rows of `K` values.
pub fn rows<const K: usize>(name: &str, obj: &Bound<'_, PyAny>) -> PyResult<Vec<[f64; K]>> {
    let arr = converted(name, obj, "fiu", "float64", "numbers")?;
    let arr: PyReadonlyArrayDyn<'_, f64> = arr.extract()?;
    check_shape(name, arr.shape(), &[None, Some(K)])?;
    let flat = arr.as_slice()?;
    Ok(flat
        .chunks_exact(K)
        .map(|c| std::array::from_fn(|i| c[i]))
        .collect())
}

/// Per-corner map coordinates: shape `[m, N, D]`.
pub fn corners<const N: usize, const D: usize>(
    name: &str,
    obj: &Bound<'_, PyAny>,
) -> PyResult<Vec<[[f64; D]; N]>> {
    let arr = converted(name, obj, "fiu", "float64", "numbers")?;
    let arr: PyReadonlyArrayDyn<'_, f64> = arr.extract()?;
    check_shape(name, arr.shape(), &[None, Some(N), Some(D)])?;
    let flat = arr.as_slice()?;
    Ok(flat
        .chunks_exact(N * D)
        .map(|c| std::array::from_fn(|i| std::array::from_fn(|j| c[i * D + j])))
        .collect())
}

/// An index array of shape `[m, N]`; `element` names one row in errors
/// ("triangle", "tet", "quad", "hex").
pub fn indices<const N: usize>(
    name: &str,
    element: &str,
    obj: &Bound<'_, PyAny>,
) -> PyResult<Vec<[u32; N]>> {
    let arr = converted(name, obj, "iu", "int64", "integers")?;
    let arr: PyReadonlyArrayDyn<'_, i64> = arr.extract()?;
    check_shape(name, arr.shape(), &[None, Some(N)])?;
    let flat = arr.as_slice()?;
    let mut out = Vec::with_capacity(flat.len() / N.max(1));
    for (r, c) in flat.chunks_exact(N).enumerate() {
        let mut row = [0u32; N];
        for (k, (&v, slot)) in c.iter().zip(&mut row).enumerate() {
            *slot = u32::try_from(v).map_err(|_| {
                PyValueError::new_err(format!(
                    "{element} {r}: corner {k} refers to vertex {v}, which is not a valid index"
                ))
            })?;
        }
        out.push(row);
    }
    Ok(out)
}

/// Positions as a `float64` array of shape (n, 3).
pub fn positions_array<'py>(py: Python<'py>, p: &[[f64; 3]]) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = p.iter().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([p.len(), 3])?
        .into_any())
}

/// Cells or simplices as an `int64` array of shape (m, K).
pub fn cells_array<'py, const K: usize>(
    py: Python<'py>,
    cells: &[[u32; K]],
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<i64> = cells.iter().flatten().map(|&v| i64::from(v)).collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([cells.len(), K])?
        .into_any())
}

/// Per-corner coordinates as a `float64` array of shape (m, N, D).
pub fn corners_array<'py, const N: usize, const D: usize>(
    py: Python<'py>,
    c: &[[[f64; D]; N]],
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<f64> = c.iter().flatten().flatten().copied().collect();
    Ok(PyArray1::from_vec(py, flat)
        .reshape([c.len(), N, D])?
        .into_any())
}

/// The input simplex of each cell as an `int64` array of shape (m,), -1
/// for a cell that no simplex holds (a quad closing a hole).
pub fn sources_array<'py>(
    py: Python<'py>,
    sources: impl Iterator<Item = Option<u32>>,
) -> PyResult<Bound<'py, PyAny>> {
    let flat: Vec<i64> = sources.map(|s| s.map_or(-1, i64::from)).collect();
    Ok(PyArray1::from_vec(py, flat).into_any())
}

/// The map coordinates of each cell's corners, (m, N, D) float64, NaN for
/// a cell made by a repair (no chart of its own).
pub fn optional_corners_array<'py, const N: usize, const D: usize>(
    py: Python<'py>,
    c: &[Option<[[f64; D]; N]>],
) -> PyResult<Bound<'py, PyAny>> {
    let full: Vec<[[f64; D]; N]> = c.iter().map(|x| x.unwrap_or([[f64::NAN; D]; N])).collect();
    corners_array(py, &full)
}
