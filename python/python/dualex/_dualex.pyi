"""Type stubs of the extension module (re-exported by ``dualex``)."""

import os
from typing import Any, Dict, Literal, Optional, Protocol, Tuple, TypedDict, Union, overload

from typing_extensions import Unpack

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

class _Options(TypedDict, total=False):
    """The keyword options of `quad` and `hex`, one set for both (the
    library's one `Options`): weld=True (cut meshes welded first),
    fairing=True (index fairing; hexes: on columns, extruded maps),
    round_transitions=False, grid_offset="auto", seed=1, strict=False,
    untangle="auto", smooth=None."""

    weld: bool
    fairing: bool
    round_transitions: bool
    grid_offset: _Offset
    seed: int
    strict: bool
    untangle: _Untangle
    smooth: Union[None, bool, int]

class _Extraction(Protocol):
    """`quad(V, F, UV, **options)` and `hex(V, T, UVW, **options)`: the
    map's positions (n, 3), simplices ((m, 3) triangles or (m, 4) tets)
    and per-corner map coordinates ((m, 3, 2) or (m, 4, 3)). Returns
    (positions (k, 3), cells ((q, 4) quads or (h, 8) hexes in VTK order),
    stats); with return_sources=True also sources (int64, one per cell):
    the simplex (row of F / T) holding each cell's node, -1 for a quad that
    closes a hole; with return_uv=True also the map coordinates of each
    cell's corners ((q, 4, 2) / (h, 8, 3), the node's chart, node ± ½; NaN
    for a cell made by a repair), after sources when both are asked.
    Raises ValueError on bad arrays or a refused map.

    The geometric stage follows the extraction (as the CLI's):
    untangle="auto" puts boundary vertices on the input's boundary and
    untangles inverted elements (scaled Jacobian <= 0), moving only the
    vertices near them; untangle="off" keeps the map's positions;
    smooth=N optimises every element in at most N rounds (True: the
    default rounds, 10). stats["geometry"] is the CLI's "geometry"
    section: mode, before / after ({elements, inverted, degenerate, min,
    p5, median} of the scaled Jacobian), moved_vertices, max_move,
    boundary, ... With strict=True, inverted elements left are a
    ValueError. A bad untangle or smooth value is a ValueError naming the
    argument.
    """

    @overload
    def __call__(
        self,
        V: _Floats,
        simplices: _Ints,
        coords: _Floats,
        /,
        *,
        return_sources: Literal[False] = False,
        return_uv: Literal[False] = False,
        **options: Unpack[_Options],
    ) -> _Mesh: ...
    @overload
    def __call__(
        self,
        V: _Floats,
        simplices: _Ints,
        coords: _Floats,
        /,
        *,
        return_sources: Literal[True],
        return_uv: Literal[False] = False,
        **options: Unpack[_Options],
    ) -> _MeshSources: ...
    @overload
    def __call__(
        self,
        V: _Floats,
        simplices: _Ints,
        coords: _Floats,
        /,
        *,
        return_sources: bool = False,
        return_uv: bool,
        **options: Unpack[_Options],
    ) -> Tuple[Any, ...]: ...

quad: _Extraction
"""Extracts the all-quad mesh of a triangle mesh with a 2D map:
quad(V, F, UV, **options) (see `_Extraction`)."""

hex: _Extraction
"""Extracts the all-hex mesh of a tet mesh with a 3D map:
hex(V, T, UVW, **options) (see `_Extraction`; boundary vertices onto the
tets' boundary surface)."""

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

class _RemeshOptions(TypedDict, total=False):
    """The keyword options of `remesh` but `return_map`: quads=1000,
    sharp=35.0, rounding="direct", seed=1, round_transitions=False,
    strict=False."""

    quads: int
    sharp: float
    rounding: _Rounding
    seed: int
    round_transitions: bool
    strict: bool

@overload
def remesh(
    V: _Floats,
    F: _Ints,
    *,
    return_map: Literal[False] = False,
    **options: Unpack[_RemeshOptions],
) -> _Mesh: ...
@overload
def remesh(
    V: _Floats,
    F: _Ints,
    *,
    return_map: Literal[True],
    **options: Unpack[_RemeshOptions],
) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Dict[str, Any], _Map]:
    """Quads from a plain triangle surface, as `dualex remesh`: V (n, 3),
    F (m, 3) (cut surfaces welded first); about `quads` quads; edges sharper
    than `sharp` degrees are features; `rounding` "direct", "greedy" or
    "off"; `seed` moves the grid. Returns (positions (k, 3) float64, quads
    (q, 4) int64, stats dict with a "remesh" section), plus the map (V, F,
    UV) extracted with return_map=True. Raises ValueError on bad input, no
    quad, or a map remesh could not make ("internal error (bug) in
    remesh")."""
