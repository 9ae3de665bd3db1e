"""Extraction through the Python API: generated maps with exact counts,
the shared maps with the CLI's counts (fandisk 897 quads, hand_q 956
hexes), read/write/inspect, and the GIL released during extraction."""

import threading

import numpy as np

import dualex
from maps import cube, square


def test_square_gives_nine_quads():
    Q, quads, stats = dualex.quad(*square(3))
    assert Q.shape == (16, 3) and Q.dtype == np.float64
    assert quads.shape == (9, 4) and quads.dtype == np.int64
    assert (stats["quads"], stats["components"], stats["boundary_loops"]) == (9, 1, 1)
    assert stats["valence_interior"] == {4: 4}
    assert stats["topology"]["matches"]
    assert stats["grid_offset"] in ("half", "zero")


def test_cube_gives_eight_hexes():
    H, hexes, stats = dualex.hex(*cube(2))
    assert hexes.shape == (8, 8) and H.shape == (27, 3)
    assert stats["hexes"] == 8 and stats["topology"]["matches"]


def test_options_are_keywords():
    V, F, UV = square(2)
    _, quads, stats = dualex.quad(V, F, UV, weld=False, fairing=False, grid_offset="half", seed=7, strict=True)
    assert len(quads) == 4 and stats["welded_vertices"] == 0
    # integer lists and int32 work as well as numpy defaults
    _, quads, _ = dualex.quad(V.tolist(), F.astype(np.int32), UV.astype(np.float32))
    assert len(quads) == 4


def test_fandisk_as_the_cli(shared):
    V, F, UV = dualex.read(shared("qex/fandisk_param.obj"))
    assert F.shape[1:] == (3,) and UV.shape == (len(F), 3, 2)
    Q, quads, stats = dualex.quad(V, F, UV)
    assert len(quads) == stats["quads"] == 897
    assert stats["topology"]["matches"]


def test_hand_as_the_cli(shared):
    V, T, UVW = dualex.read(shared("hexex/hand_q.hexex"))
    assert T.shape[1:] == (4,) and UVW.shape == (len(T), 4, 3)
    H, hexes, stats = dualex.hex(V, T, UVW)
    assert len(hexes) == stats["hexes"] == 956


def test_inspect_a_file_and_arrays(shared):
    r = dualex.inspect(shared("hexex/hand_q.hexex"))
    assert r["dimension"] == 3 and r["simplices"] == 11472
    r = dualex.inspect(*square(3))
    assert (r["dimension"], r["simplices"], r["components"]) == (2, 2, 1)
    assert dualex.inspect(*cube(2))["dimension"] == 3


def test_write_then_read_back(tmp_path):
    Q, quads, _ = dualex.quad(*square(3))
    for ext in ("obj", "ply", "vtk"):
        dualex.write(tmp_path / f"q.{ext}", Q, quads)
        assert (tmp_path / f"q.{ext}").stat().st_size > 0
    H, hexes, _ = dualex.hex(*cube(2))
    dualex.write(str(tmp_path / "h.mesh"), H, hexes)
    text = (tmp_path / "h.mesh").read_text()
    assert "Hexahedra" in text


def test_extractions_run_in_threads():
    """With the GIL released, threads extract side by side (and agree)."""
    results = [None] * 4

    def run(i):
        results[i] = len(dualex.hex(*cube(3))[1])

    threads = [threading.Thread(target=run, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results == [27] * 4
