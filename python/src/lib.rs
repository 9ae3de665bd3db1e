//! # dualex for Python: the extension module `dualex._dualex`
//!
//! Thin bindings of the `dualex` facade crate: numpy arrays in, the
//! facade's maps and extractions, numpy arrays and dicts out.
//!
//! | Python | facade |
//! |---|---|
//! | `quad(V, F, UV, **options)` (`return_sources=True`: the input triangle of each quad) | [`dualex::tri_map_from_slices`], [`dualex::quad()`] |
//! | `hex(V, T, UVW, **options)` (`return_sources=True`: the input tet of each hex) | [`dualex::tet_map_from_slices`], [`dualex::hex()`] |
//! | `remesh(V, F, quads=N, **options)` (`return_map=True`: the map too) | [`dualex::remesh()`] (`remesh.rs`) |
//! | `read(path)` (a plain surface: `(V, F, None)`) | [`dualex::read_tri_map`] / [`dualex::read_tet_map`] / [`dualex::read_surface`] |
//! | `write(path, V, cells)` | [`dualex::write_quad_mesh`] / [`dualex::write_hex_mesh`] |
//! | `inspect(path)` / `inspect(V, S, C)` | `dualex::map::report::inspect` |
//!
//! `quad` and `hex` run the geometric stage after the extraction
//! (`untangle="auto"|"off"`, `smooth=None|True|rounds`; `geometry.rs`), its
//! report in the stats' `"geometry"` dict.
//!
//! Every error (bad arrays, a map the extraction refuses, an unreadable
//! file, a bad option value) is a `ValueError` whose message is the CLI's
//! one-line message (an option's names the argument); nothing panics on
//! bad input. The GIL is released while Rust works.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod arrays;
mod dicts;
mod geometry;
mod remesh;

use arrays::{
    cells_array, corners, corners_array, indices, optional_corners_array, positions_array, rows,
    sources_array,
};
use dualex::map::report::{inspect as inspect_map, Inspect, InspectOptions, MapReport};
use dualex::GridOffset;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use std::path::PathBuf;

/// A facade error as a `ValueError` with its one-line message; a hint
/// naming a command-line option names the keyword argument instead.
fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(python_hint(&e.to_string()))
}

/// The message with the CLI's options that the library's errors suggest
/// spelled as this module's keyword arguments.
fn python_hint(message: &str) -> String {
    message.replace("--round-transitions", "round_transitions=True")
}

/// `grid_offset=`: the library's one parser ([`GridOffset::parse`]).
fn grid_offset(s: &str) -> PyResult<GridOffset> {
    GridOffset::parse(s).ok_or_else(|| {
        PyValueError::new_err(format!(
            "grid_offset: expected \"auto\", \"half\" or \"zero\", got {s:?}"
        ))
    })
}

fn is_tet_file(path: &std::path::Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("hexex") || e.eq_ignore_ascii_case("ovm"))
}

/// `quad` and `hex`, one template for both: `$name(V, $s, $c,
/// **options)` with the simplices' and coordinates' names of the
/// dimension (`$n` corners, `$d` map coordinates, `$word` in messages),
/// the library's `$run`.
macro_rules! extraction_function {
    ($(#[doc = $doc:literal])* $name:ident($s:ident: $n:literal, $c:ident: $d:literal, $word:literal) => $run:path, $text:literal) => {
        $(#[doc = $doc])*
        #[pyfunction]
        // untangle=None is "auto": the Python signature shows that
        #[pyo3(signature = (V, $s, $c, *, weld=true, fairing=true, round_transitions=false, grid_offset="auto", seed=1, strict=false, untangle=None, smooth=None, return_sources=false, return_uv=false))]
        #[pyo3(text_signature = $text)]
        #[allow(non_snake_case, clippy::too_many_arguments)]
        fn $name<'py>(
            py: Python<'py>,
            V: &Bound<'py, PyAny>,
            $s: &Bound<'py, PyAny>,
            $c: &Bound<'py, PyAny>,
            weld: bool,
            fairing: bool,
            round_transitions: bool,
            grid_offset: &str,
            seed: u64,
            strict: bool,
            untangle: Option<&Bound<'py, PyAny>>,
            smooth: Option<&Bound<'py, PyAny>>,
            return_sources: bool,
            return_uv: bool,
        ) -> PyResult<Bound<'py, PyTuple>> {
            let opts = Kwargs {
                weld,
                fairing,
                round_transitions,
                grid_offset,
                seed,
                strict,
            }
            .options(untangle, smooth)?;
            let (p, t, c) = (
                rows::<3>("V", V)?,
                indices::<$n>(stringify!($s), $word, $s)?,
                corners::<$n, $d>(stringify!($c), $c)?,
            );
            let asked = (return_sources, return_uv);
            extraction(py, (&p, &t, &c), &opts, $run, asked)
        }
    };
}

extraction_function! {
/// Extracts the all-quad mesh of a triangle mesh with a 2D map.
///
/// V: (n, 3) vertex positions; F: (m, 3) vertex indices of the triangles;
/// UV: (m, 3, 2) map coordinates of each triangle corner, in that
/// triangle's chart (cut meshes welded first unless weld=False).
/// The geometric stage follows (as the CLI's): untangle="auto" puts
/// boundary vertices on the input's boundary and untangles inverted quads
/// (scaled Jacobian <= 0), "off" keeps the map's positions; smooth=N (True:
/// the default rounds) optimises every quad in at most N rounds; the stats'
/// "geometry" dict reports the quality before and after.
/// Returns (positions (k, 3) float64, quads (q, 4) int64, stats dict);
/// with return_sources=True also sources (q,) int64: the triangle (row of
/// F) holding each quad's node, -1 for a quad that closes a hole; with
/// return_uv=True also uv (q, 4, 2) float64: the map coordinates of each
/// quad's corners in its node's chart (node ± ½, exact grid points of the
/// input map), NaN for a quad made by a repair.
/// Raises ValueError on bad arrays, a map the extraction refuses or a bad
/// option (strict=True: also when the topology changed or inverted quads
/// remain).
    quad(F: 3, UV: 2, "triangle") => dualex::quad,
    "(V, F, UV, *, weld=True, fairing=True, round_transitions=False, grid_offset=\"auto\", seed=1, strict=False, untangle=\"auto\", smooth=None, return_sources=False, return_uv=False)"
}

extraction_function! {
/// Extracts the all-hex mesh of a tet mesh with a 3D map.
///
/// V: (n, 3) vertex positions; T: (m, 4) vertex indices of the tets
/// (positively oriented); UVW: (m, 4, 3) map coordinates of each tet
/// corner. fairing: on columns (extruded maps), the 2D fairing in every
/// layer. untangle and smooth as for `quad` (boundary vertices onto the
/// boundary surface of the tets). Returns (positions (k, 3) float64,
/// hexes (h, 8) int64 in VTK order, stats dict); with return_sources=True
/// also sources (h,) int64: the tet (row of T) holding each hex's node;
/// with return_uv=True also uvw (h, 8, 3): each hex's corners in its
/// node's chart, NaN for a hex merged by a repair. Raises ValueError on
/// bad arrays, a refused map or a bad option (strict=True: also when the
/// topology changed or inverted hexes remain).
    hex(T: 4, UVW: 3, "tet") => dualex::hex,
    "(V, T, UVW, *, weld=True, fairing=True, round_transitions=False, grid_offset=\"auto\", seed=1, strict=False, untangle=\"auto\", smooth=None, return_sources=False, return_uv=False)"
}

/// The keyword arguments `quad` and `hex` share, but for the geometric
/// stage's (`untangle`, `smooth`).
struct Kwargs<'a> {
    weld: bool,
    fairing: bool,
    round_transitions: bool,
    grid_offset: &'a str,
    seed: u64,
    strict: bool,
}

impl Kwargs<'_> {
    /// The library's one options type for both dimensions.
    fn options(
        &self,
        untangle: Option<&Bound<'_, PyAny>>,
        smooth: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<dualex::Options> {
        Ok(dualex::Options {
            weld: self.weld,
            fairing: self.fairing,
            round_transitions: self.round_transitions,
            grid_offset: self::grid_offset(self.grid_offset)?,
            seed: self.seed,
            strict: self.strict,
            geometry: geometry::options(untangle, smooth)?,
        })
    }
}

/// A map's arrays as read: positions, simplices, per-corner coordinates.
type MapArrays<'a, const N: usize, const D: usize> =
    (&'a [[f64; 3]], &'a [[u32; N]], &'a [[[f64; D]; N]]);

/// `quad` and `hex` after their arguments: the map built, `run` (the
/// library's extraction) without the GIL, the result as a tuple
/// ([`extraction_tuple`]) with the sources and corners `asked`.
fn extraction<'py, const N: usize, const D: usize, const K: usize>(
    py: Python<'py>,
    (p, t, c): MapArrays<N, D>,
    opts: &dualex::Options,
    run: fn(
        &dualex::map::SimplexMap<N, D>,
        &dualex::Options,
    ) -> Result<dualex::Output<K, D>, dualex::Error>,
    (return_sources, return_uv): (bool, bool),
) -> PyResult<Bound<'py, PyTuple>> {
    let out = py
        .allow_threads(|| run(&dualex::map_from_slices(p, t, c)?, opts))
        .map_err(value_error)?;
    let stats = dicts::stats(py, &out.stats, D)?;
    let sources = return_sources.then(|| out.sources.iter().copied());
    let uv = return_uv.then_some(out.corners.as_slice());
    extraction_tuple(py, &out.mesh.positions, &out.mesh.cells, stats, sources, uv)
}

/// What `quad` and `hex` return: (positions, cells, stats), then the
/// sources and the corner coordinates when asked.
fn extraction_tuple<'py, const K: usize, const D: usize>(
    py: Python<'py>,
    positions: &[[f64; 3]],
    cells: &[[u32; K]],
    stats: Bound<'py, PyDict>,
    sources: Option<impl Iterator<Item = Option<u32>>>,
    uv: Option<&[Option<[[f64; D]; K]>]>,
) -> PyResult<Bound<'py, PyTuple>> {
    let mut items = vec![
        positions_array(py, positions)?,
        cells_array(py, cells)?,
        stats.into_any(),
    ];
    if let Some(s) = sources {
        items.push(sources_array(py, s)?);
    }
    if let Some(uv) = uv {
        items.push(optional_corners_array(py, uv)?);
    }
    PyTuple::new(py, items)
}

/// Reads a map: (V (n, 3), simplices (m, 3) or (m, 4), coords (m, 3, 2)
/// or (m, 4, 3)). `.obj` (f v/vt) and `.ply` (per-face texcoord, or
/// per-vertex u v / s t / texture_u texture_v) hold triangle maps,
/// `.hexex` and `.ovm` (HexHex's `HexHex::Parametrization`) tet maps. A
/// `.obj` / `.ply` without any map coordinate is a plain surface: (V (n,
/// 3), F (m, 3), None), polygons fanned into triangles (`remesh`'s input).
/// Raises ValueError naming the file.
#[pyfunction]
fn read<'py>(py: Python<'py>, path: PathBuf) -> PyResult<Bound<'py, PyTuple>> {
    if is_tet_file(&path) {
        let m = py
            .allow_threads(|| dualex::read_tet_map(&path))
            .map_err(value_error)?;
        return map_tuple(py, &m);
    }
    let m = py.allow_threads(|| match dualex::read_tri_map(&path) {
        Ok(m) => Ok(Ok(m)),
        // a file without any map coordinate is a plain surface (for
        // `remesh`); a map's own errors stay errors
        Err(e) => match dualex::has_map_coordinates(&path) {
            Ok(false) => dualex::read_surface(&path).map(Err),
            _ => Err(e),
        },
    });
    match m.map_err(value_error)? {
        Ok(m) => map_tuple(py, &m),
        Err(s) => {
            let (p, f) = (
                positions_array(py, &s.positions)?,
                cells_array(py, &s.triangles)?,
            );
            PyTuple::new(py, [p, f, py.None().into_bound(py)])
        }
    }
}

/// A map as `read` returns it: (V, simplices, coords).
fn map_tuple<'py, const N: usize, const D: usize>(
    py: Python<'py>,
    m: &dualex::map::SimplexMap<N, D>,
) -> PyResult<Bound<'py, PyTuple>> {
    let p = positions_array(py, &m.positions)?;
    PyTuple::new(
        py,
        [
            p,
            cells_array(py, &m.simplices)?,
            corners_array(py, &m.coords)?,
        ],
    )
}

/// The second dimension of an array's shape (`None`: not an array of
/// rows).
fn width(obj: &Bound<'_, PyAny>) -> Option<usize> {
    let shape = obj.getattr("shape").ok()?.extract::<Vec<usize>>().ok()?;
    shape.get(1).copied()
}

/// Writes a quad mesh (cells (m, 4): `.obj`, `.ply`, `.vtk`) or a hex mesh
/// (cells (m, 8), VTK order: `.mesh`, `.vtk`, `.ovm`), chosen by the cells' shape
/// and the extension. Raises ValueError on bad arrays or a failed write.
#[pyfunction]
fn write(
    py: Python<'_>,
    path: PathBuf,
    positions: &Bound<'_, PyAny>,
    cells: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let positions = rows::<3>("positions", positions)?;
    if width(cells) == Some(8) {
        let cells = indices::<8>("cells", "hex", cells)?;
        return write_mesh(py, positions, cells, "hex", |m| {
            dualex::write_hex_mesh(&path, m)
        });
    }
    let cells = indices::<4>("cells", "quad", cells).map_err(|e| {
        PyValueError::new_err(format!("{} (4 for quads, 8 for hexes)", e.value(py)))
    })?;
    write_mesh(py, positions, cells, "quad", |m| {
        dualex::write_quad_mesh(&path, m)
    })
}

/// `write`'s mesh of `K`-cornered cells (`element`s in messages), every
/// index checked below the number of positions (the writers trust their
/// input), then handed to `write` without the GIL.
fn write_mesh<const K: usize>(
    py: Python<'_>,
    positions: Vec<[f64; 3]>,
    cells: Vec<[u32; K]>,
    element: &str,
    write: impl FnOnce(&dualex::CellMesh<K>) -> Result<(), dualex::Error> + Send,
) -> PyResult<()> {
    let n = positions.len();
    for (i, c) in cells.iter().enumerate() {
        if let Some((k, &v)) = c.iter().enumerate().find(|(_, &v)| v as usize >= n) {
            return Err(PyValueError::new_err(format!(
                "{element} {i}: corner {k} refers to vertex {v}, but there are {n} vertices"
            )));
        }
    }
    let mesh = dualex::CellMesh { positions, cells };
    py.allow_threads(|| write(&mesh)).map_err(value_error)
}

/// Writes a map (the arrays `read` returns): triangles (m, 3) with coords
/// (m, 3, 2) to `.obj` / `.ply`, tets (m, 4) with (m, 4, 3) to `.hexex` /
/// `.ovm` (HexHex's `HexHex::Parametrization`). The map is checked as
/// `quad`/`hex` check it; raises ValueError on bad arrays or a failed write.
#[pyfunction]
#[allow(non_snake_case)]
fn write_map(
    py: Python<'_>,
    path: PathBuf,
    V: &Bound<'_, PyAny>,
    simplices: &Bound<'_, PyAny>,
    coords: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let p = rows::<3>("V", V)?;
    let arrays = (p.as_slice(), simplices, coords);
    if is_tet_file(&path) {
        with_map::<4, 3, _>(py, arrays, "tet", |m| dualex::write_tet_map(&path, m))
    } else {
        with_map::<3, 2, _>(py, arrays, "triangle", |m| dualex::write_tri_map(&path, m))
    }
}

/// The map of positions `p`, `simplices` (of `N` corners, `element`s in
/// messages) and `coords` (`D` per corner), validated and handed to
/// `then` without the GIL; every error a ValueError.
fn with_map<const N: usize, const D: usize, T: Send>(
    py: Python<'_>,
    (p, simplices, coords): (&[[f64; 3]], &Bound<'_, PyAny>, &Bound<'_, PyAny>),
    element: &str,
    then: impl FnOnce(&dualex::map::SimplexMap<N, D>) -> Result<T, dualex::Error> + Send,
) -> PyResult<T> {
    let (t, c) = (
        indices::<N>("simplices", element, simplices)?,
        corners::<N, D>("coords", coords)?,
    );
    py.allow_threads(|| then(&dualex::map_from_slices(p, &t, &c)?))
        .map_err(value_error)
}

/// Analyses a map without extracting (the CLI's `inspect --json`): either
/// a file, `inspect(path)`, or arrays, `inspect(V, simplices, coords)`
/// (triangles (m, 3) with (m, 3, 2), or tets (m, 4) with (m, 4, 3)).
/// Returns the report as a dict; raises ValueError on a bad map.
#[pyfunction]
#[pyo3(signature = (map, simplices=None, coords=None, *, weld=true, round_transitions=false))]
fn inspect<'py>(
    py: Python<'py>,
    map: &Bound<'py, PyAny>,
    simplices: Option<&Bound<'py, PyAny>>,
    coords: Option<&Bound<'py, PyAny>>,
    weld: bool,
    round_transitions: bool,
) -> PyResult<Bound<'py, PyAny>> {
    let round = round_transitions;
    let opts = InspectOptions {
        weld,
        round,
        ..Default::default()
    };
    let report = match (simplices, coords) {
        (None, None) => inspect_file(py, map, &opts)?,
        (Some(s), Some(c)) => {
            let p = rows::<3>("V", map)?;
            let arrays = (p.as_slice(), s, c);
            if width(s) == Some(4) {
                with_map::<4, 3, _>(py, arrays, "tet", |m| Ok(inspect_map(m, &opts)?))
            } else {
                with_map::<3, 2, _>(py, arrays, "triangle", |m| Ok(inspect_map(m, &opts)?))
            }?
        }
        _ => {
            return Err(PyValueError::new_err(
                "inspect: give a path alone, or all three arrays V, simplices, coords",
            ))
        }
    };
    dicts::map_report(py, &report)
}

/// `inspect(path)`: the report of the map in the file at `path`, its
/// errors naming the file.
fn inspect_file(
    py: Python<'_>,
    path: &Bound<'_, PyAny>,
    opts: &InspectOptions,
) -> PyResult<MapReport> {
    let path: PathBuf = path.extract().map_err(|_| {
        PyValueError::new_err("inspect: expected a path, or the arrays V, simplices, coords")
    })?;
    let name = path.display().to_string();
    py.allow_threads(|| {
        if is_tet_file(&path) {
            inspect_read(dualex::read_tet_map(&path), opts, name)
        } else {
            inspect_read(dualex::read_tri_map(&path), opts, name)
        }
    })
    .map_err(value_error)
}

/// The report of a map `read` from the file `name`.
fn inspect_read(
    read: Result<impl Inspect, dualex::Error>,
    opts: &InspectOptions,
    name: String,
) -> Result<MapReport, dualex::Error> {
    inspect_map(&read?, opts).map_err(|e| e.in_file(name).into())
}

/// The extension module: `dualex` re-exports everything.
#[pymodule]
fn _dualex(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(quad, m)?)?;
    m.add_function(wrap_pyfunction!(hex, m)?)?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(write, m)?)?;
    m.add_function(wrap_pyfunction!(write_map, m)?)?;
    m.add_function(wrap_pyfunction!(inspect, m)?)?;
    m.add_function(wrap_pyfunction!(remesh::remesh, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
