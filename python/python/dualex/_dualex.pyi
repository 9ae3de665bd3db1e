"""Type stubs of the extension module (re-exported by ``dualex``)."""

import os
from typing import Any, Dict, Literal, Optional, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

_Path = Union[str, "os.PathLike[str]"]
_Floats = npt.ArrayLike
_Ints = npt.ArrayLike
_Offset = Literal["auto", "half", "zero"]
_Untangle = Literal["auto", "off"]

__version__: str

_Mesh = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Dict[str, Any]]
_MeshSources = Tuple[
    npt.NDArray[np.float64],
    npt.NDArray[np.int64],
    Dict[str, Any],
    npt.NDArray[np.int64],
]

@overload
def quad(
    V: _Floats,
    F: _Ints,
    UV: _Floats,
    *,
    weld: bool = True,
    fairing: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: Literal[False] = False,
    return_uv: Literal[False] = False,
) -> _Mesh: ...
@overload
def quad(
    V: _Floats,
    F: _Ints,
    UV: _Floats,
    *,
    weld: bool = True,
    fairing: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: Literal[True],
    return_uv: Literal[False] = False,
) -> _MeshSources: ...
@overload
def quad(
    V: _Floats,
    F: _Ints,
    UV: _Floats,
    *,
    weld: bool = True,
    fairing: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: bool = False,
    return_uv: bool,
) -> Tuple[Any, ...]:
    """Extracts the all-quad mesh of a triangle mesh with a 2D map.

    V: (n, 3) positions; F: (m, 3) triangles; UV: (m, 3, 2) map
    coordinates per triangle corner. Returns (positions (k, 3), quads
    (q, 4), stats); with return_sources=True also sources (q,) int64: the
    triangle (row of F) holding each quad's node, -1 for a quad that
    closes a hole. Raises ValueError on bad arrays or a refused map.

    The geometric stage follows the extraction (as the CLI's):
    untangle="auto" puts boundary vertices on the input's boundary and
    untangles inverted quads (scaled Jacobian <= 0), moving only the
    vertices near them; untangle="off" keeps the map's positions;
    smooth=N optimises every quad in at most N rounds (True: the default
    rounds, 10). stats["geometry"] is the CLI's "geometry" section: mode,
    before / after ({elements, inverted, degenerate, min, p5, median} of
    the scaled Jacobian), moved_vertices, max_move, boundary, ... With
    strict=True, inverted quads left are a ValueError. A bad untangle or
    smooth value is a ValueError naming the argument.

    With return_uv=True also the map coordinates of each cell's corners
    ((q, 4, 2) / (h, 8, 3), the node's chart, node ± ½; NaN for a cell made
    by a repair), after sources when both are asked.
    """

@overload
def hex(
    V: _Floats,
    T: _Ints,
    UVW: _Floats,
    *,
    weld: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: Literal[False] = False,
    return_uv: Literal[False] = False,
) -> _Mesh: ...
@overload
def hex(
    V: _Floats,
    T: _Ints,
    UVW: _Floats,
    *,
    weld: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: Literal[True],
    return_uv: Literal[False] = False,
) -> _MeshSources: ...
@overload
def hex(
    V: _Floats,
    T: _Ints,
    UVW: _Floats,
    *,
    weld: bool = True,
    round_transitions: bool = False,
    grid_offset: _Offset = "auto",
    seed: int = 1,
    strict: bool = False,
    untangle: _Untangle = "auto",
    smooth: Union[None, bool, int] = None,
    return_sources: bool = False,
    return_uv: bool,
) -> Tuple[Any, ...]:
    """Extracts the all-hex mesh of a tet mesh with a 3D map.

    V: (n, 3) positions; T: (m, 4) tets; UVW: (m, 4, 3) map coordinates per
    tet corner. Returns (positions (k, 3), hexes (h, 8) in VTK order,
    stats); with return_sources=True also sources (h,) int64: the tet (row
    of T) holding each hex's node. Raises ValueError on bad arrays or a
    refused map. untangle, smooth, strict and stats["geometry"] as for
    quad (boundary vertices onto the tets' boundary surface).
    With return_uv=True also the map coordinates of each cell's corners
    ((q, 4, 2) / (h, 8, 3), the node's chart, node ± ½; NaN for a cell made
    by a repair), after sources when both are asked.
    """

def read(
    path: _Path,
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Optional[npt.NDArray[np.float64]]]:
    """Reads a map: .obj/.ply (triangles, (m, 3, 2) coords; a PLY holds them
    per face, `texcoord`, or per vertex, `u v` / `s t` /
    `texture_u texture_v`) or .hexex / .ovm (tets, (m, 4, 3) coords; .ovm
    with HexHex's `HexHex::Parametrization`). A .obj / .ply without any map
    coordinate is a plain surface: (V, F, None), polygons fanned into
    triangles (the input of `remesh`). Raises ValueError naming the file."""

def write(path: _Path, positions: _Floats, cells: _Ints) -> None:
    """Writes a quad mesh (cells (m, 4): .obj, .ply, .vtk) or a hex mesh
    (cells (m, 8): .mesh, .vtk, .ovm)."""

def write_map(path: _Path, V: _Floats, simplices: _Ints, coords: _Floats) -> None:
    """Writes a map (the arrays `read` returns): triangles (m, 3) with
    coords (m, 3, 2) to .obj / .ply, tets (m, 4) with (m, 4, 3) to .hexex /
    .ovm (HexHex's `HexHex::Parametrization`). Raises ValueError on bad
    arrays or a failed write."""

def inspect(
    map: Union[_Path, _Floats],
    simplices: Optional[_Ints] = None,
    coords: Optional[_Floats] = None,
    *,
    weld: bool = True,
    round_transitions: bool = False,
) -> Dict[str, Any]:
    """The map report (as `dualex inspect --json`) of a file or of arrays."""

_Map = Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], npt.NDArray[np.float64]]
_Rounding = Literal["direct", "greedy", "off"]

@overload
def remesh(
    V: _Floats,
    F: _Ints,
    *,
    quads: int = 1000,
    sharp: float = 35.0,
    rounding: _Rounding = "direct",
    seed: int = 1,
    round_transitions: bool = False,
    strict: bool = False,
    return_map: Literal[False] = False,
) -> _Mesh: ...
@overload
def remesh(
    V: _Floats,
    F: _Ints,
    *,
    quads: int = 1000,
    sharp: float = 35.0,
    rounding: _Rounding = "direct",
    seed: int = 1,
    round_transitions: bool = False,
    strict: bool = False,
    return_map: Literal[True],
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Dict[str, Any], _Map]:
    """Quads from a plain triangle surface, as `dualex remesh`: V (n, 3),
    F (m, 3) (cut surfaces welded first); about `quads` quads; edges sharper
    than `sharp` degrees are features; `rounding` "direct", "greedy" or
    "off"; `seed` moves the grid. Returns (positions (k, 3) float64, quads
    (q, 4) int64, stats dict with a "remesh" section), plus the map (V, F,
    UV) extracted with return_map=True. Raises ValueError on bad input, no
    quad, or a map remesh could not make ("internal error (bug) in
    remesh")."""
