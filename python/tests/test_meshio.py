"""Round trips through meshio: the extraction's arrays written by meshio
and read back, and dualex's own files read by meshio, with the same
counts."""

import numpy as np
import pytest

import dualex
from maps import cube, square

meshio = pytest.importorskip("meshio", reason="meshio is not installed (pip install meshio)")


def meshio_round_trip(path, points, kind, cells):
    meshio.write(str(path), meshio.Mesh(points, [(kind, cells)]))
    back = meshio.read(str(path))
    assert len(back.points) == len(points)
    got = np.concatenate([c.data for c in back.cells if c.type == kind])
    assert got.shape == cells.shape
    np.testing.assert_array_equal(got, cells)


def test_quads_through_meshio(tmp_path):
    Q, quads, stats = dualex.quad(*square(4))
    for ext in ("vtu", "vtk", "obj"):
        meshio_round_trip(tmp_path / f"q.{ext}", Q, "quad", quads)


def test_hexes_through_meshio(tmp_path):
    H, hexes, _ = dualex.hex(*cube(3))
    for ext in ("vtu", "vtk", "mesh"):
        meshio_round_trip(tmp_path / f"h.{ext}", H, "hexahedron", hexes)


def test_dualex_files_read_by_meshio(tmp_path):
    Q, quads, _ = dualex.quad(*square(4))
    H, hexes, _ = dualex.hex(*cube(3))
    cases = [("q.vtk", Q, quads, "quad"), ("q.obj", Q, quads, "quad"), ("h.vtk", H, hexes, "hexahedron"), ("h.mesh", H, hexes, "hexahedron")]
    for name, points, cells, kind in cases:
        dualex.write(tmp_path / name, points, cells)
        back = meshio.read(str(tmp_path / name))
        assert len(back.points) == len(points), name
        assert sum(len(c.data) for c in back.cells if c.type == kind) == len(cells), name


def test_shared_map_through_meshio(shared, tmp_path):
    Q, quads, _ = dualex.quad(*dualex.read(shared("qex/fandisk_param.obj")))
    meshio_round_trip(tmp_path / "fandisk.vtu", Q, "quad", quads)
    H, hexes, _ = dualex.hex(*dualex.read(shared("hexex/hand_q.hexex")))
    meshio_round_trip(tmp_path / "hand.vtu", H, "hexahedron", hexes)
