"""Extraction through the Python API: generated maps with exact counts,
the shared maps with the CLI's counts (fandisk 897 quads, hand_q 956
hexes), read/write/inspect, and the GIL released during extraction."""

import threading

import numpy as np
import pytest

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


def test_hexex_to_ovm_as_hexhex_reads_it(shared, tmp_path):
    """hand_q written as an OpenVolumeMesh map (HexHex's
    `HexHex::Parametrization`) reads back as the same map and gives the
    same 956 hexes."""
    V, T, UVW = dualex.read(shared("hexex/hand_q.hexex"))
    dualex.write_map(tmp_path / "hand_q.ovm", V, T, UVW)
    text = (tmp_path / "hand_q.ovm").read_text()
    assert text.startswith("OVM ASCII") and '"HexHex::Parametrization"' in text
    V2, T2, UVW2 = dualex.read(tmp_path / "hand_q.ovm")
    assert np.array_equal(V, V2)
    # each tet comes back with its corners in an even permutation (same
    # orientation) and each corner with its own map value
    o, o2 = np.argsort(T, axis=1), np.argsort(T2, axis=1)
    rows = np.arange(len(T))[:, None]
    assert np.array_equal(T[rows, o], T2[rows, o2])
    assert np.array_equal(UVW[rows, o], UVW2[rows, o2])
    parity = lambda p: np.linalg.det(np.eye(4)[p]).round()  # noqa: E731
    assert all(parity(a) == parity(b) for a, b in zip(o, o2))
    _, hexes, stats = dualex.hex(V2, T2, UVW2)
    assert len(hexes) == stats["hexes"] == 956


def test_maps_written_and_read_back(tmp_path):
    for name, (V, S, C) in (("m.obj", square(3)), ("m.ply", square(3)),
                            ("m.hexex", cube(2)), ("m.ovm", cube(2))):
        dualex.write_map(tmp_path / name, V, S, C)
        V2, S2, C2 = dualex.read(tmp_path / name)
        assert S2.shape == np.asarray(S).shape and C2.shape == np.asarray(C).shape
        assert np.allclose(V2, V), name
        # per corner: the same map value at the same vertex (tets may come
        # back with their corners rotated)
        S, C = np.asarray(S), np.asarray(C)
        o, o2 = np.argsort(S, axis=1), np.argsort(S2, axis=1)
        rows = np.arange(len(S))[:, None]
        assert np.array_equal(S[rows, o], S2[rows, o2]), name
        assert np.allclose(C[rows, o], C2[rows, o2]), name
    with pytest.raises(ValueError, match="out of range|refers to vertex"):
        dualex.write_map(tmp_path / "bad.ovm", *cube(2)[:1], [[0, 1, 2, 99]], cube(2)[2][:1])
    assert not (tmp_path / "bad.ovm").exists()


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
    # OpenVolumeMesh: the hexes as polyhedra with shared faces
    dualex.write(tmp_path / "h.ovm", H, hexes)
    lines = (tmp_path / "h.ovm").read_text().split("\n")
    assert lines[0] == "OVM ASCII"
    assert int(lines[lines.index("Polyhedra") + 1]) == len(hexes) == 8
    faces = int(lines[lines.index("Faces") + 1])
    assert faces == 36  # 2×2×2 block: 3·2·3·3 shared faces, not 8·6


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
