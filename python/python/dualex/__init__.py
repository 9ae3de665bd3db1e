"""dualex: all-quad and all-hex meshes from messy grid-preserving maps.

    >>> import dualex
    >>> V, F, UV = dualex.read("fandisk_param.obj")   # a triangle map
    >>> Q, quads, stats = dualex.quad(V, F, UV)       # numpy arrays, a dict
    >>> dualex.write("quads.obj", Q, quads)

``quad`` / ``hex`` take numpy arrays (positions (n, 3), simplices (m, 3) or
(m, 4), per-corner map coordinates (m, 3, 2) or (m, 4, 3)) and keyword
options (``untangle="auto"|"off"`` and ``smooth=N`` for the geometric
stage after the extraction, reported in ``stats["geometry"]``); ``read`` /
``write`` / ``write_map`` use the Rust readers and
writers (maps: .obj, .ply, .hexex, .ovm; meshes: .obj, .ply, .vtk, .mesh,
.ovm); ``inspect``
returns the map report. ``remesh(V, F, quads=N)`` makes quads from a plain
surface (``read`` gives ``(V, F, None)`` for a file without map
coordinates), as ``dualex remesh``. Every error is a ``ValueError`` with a one-line
message; the GIL is released while the extraction runs.
"""

from ._dualex import __version__, hex, inspect, quad, read, remesh, write, write_map

__all__ = ["quad", "hex", "remesh", "read", "write", "write_map", "inspect", "__version__"]
