"""Bad arrays and bad files raise ValueError with a one-line message
naming the array or the element; the process never crashes."""

import numpy as np
import pytest

import dualex
from maps import cube, square


def raises(match, f, *args, **kw):
    with pytest.raises(ValueError, match=match) as e:
        f(*args, **kw)
    assert "\n" not in str(e.value)


def test_wrong_shapes():
    V, F, UV = square()
    raises(r"V: expected shape \(n, 3\), got \(4, 2\)", dualex.quad, V[:, :2], F, UV)
    raises(r"F: expected shape \(n, 3\), got \(2, 4\)", dualex.quad, V, np.c_[F, F[:, :1]], UV)
    raises(r"UV: expected shape \(n, 3, 2\), got \(2, 3\)", dualex.quad, V, F, UV[:, :, 0])
    raises(r"UV: expected shape \(n, 3, 2\), got \(2, 3, 3\)", dualex.quad, V, F, np.zeros((2, 3, 3)))
    Vc, T, UVW = cube()
    raises(r"UVW: expected shape \(n, 4, 3\)", dualex.hex, Vc, T, UVW[:, :, :2])
    raises(r"V: expected shape \(n, 3\), got \(\)", dualex.quad, 1.0, F, UV)
    raises("2 triangles but 1 sets", dualex.quad, V, F, UV[:1])


def test_nan_and_infinity():
    V, F, UV = square()
    UV[1, 2, 0] = np.nan
    raises("triangle 1: corner 2 has a non-finite map coordinate", dualex.quad, V, F, UV)
    V, F, UV = square()
    V[3, 1] = np.inf
    raises("vertex 3: position", dualex.quad, V, F, UV)
    Vc, T, UVW = cube()
    UVW[5, 0, 2] = np.nan
    raises("tet 5: corner 0 has a non-finite", dualex.hex, Vc, T, UVW)


def test_indices_out_of_range():
    V, F, UV = square()
    F[1, 2] = 4
    raises("triangle 1: corner 2 refers to vertex 4, but there are 4 vertices", dualex.quad, V, F, UV)
    F[1, 2] = -1
    raises("triangle 1: corner 2 refers to vertex -1", dualex.quad, V, F, UV)
    F[1, 2] = 2**40
    raises("triangle 1: corner 2 refers to vertex", dualex.quad, V, F, UV)
    Vc, T, UVW = cube()
    T[0, 3] = 8
    raises("tet 0: corner 3 refers to vertex 8", dualex.hex, Vc, T, UVW)
    F[1] = [0, 1, 1]
    raises("triangle 1: vertex 1 appears twice", dualex.quad, V, F, UV)


def test_wrong_types_and_empty():
    V, F, UV = square()
    raises("F: expected integers, got an array of dtype float64", dualex.quad, V, F.astype(float), UV)
    raises("V: expected numbers", dualex.quad, np.array([["a"] * 3] * 4), F, UV)
    raises("no triangles", dualex.quad, V, np.zeros((0, 3), int), np.zeros((0, 3, 2)))
    raises('grid_offset: expected "auto", "half" or "zero"', dualex.quad, V, F, UV, grid_offset="x")
    with pytest.raises(TypeError):
        dualex.quad(V, F, UV, wled=False)  # misspelt option


def test_refused_map():
    V, F, UV = square()
    UV[1] += 0.37  # the seam's translation is not an integer
    with pytest.raises(ValueError) as e:
        dualex.quad(V, F, UV, weld=True)
    assert str(e.value) and "\n" not in str(e.value)


def test_bad_files(tmp_path):
    raises("cannot read", dualex.read, tmp_path / "missing.obj")
    (tmp_path / "bad.obj").write_text("v 0 0 0\nf 1 2 3\n")
    raises("bad.obj", dualex.read, tmp_path / "bad.obj")
    raises("bad.hexex", dualex.inspect, tmp_path / "bad.hexex")
    Q, quads, _ = dualex.quad(*square())
    raises("quad 0: corner 0 refers to vertex 99", dualex.write, tmp_path / "q.obj", Q, quads + 99)
    raises(r"cells: expected shape \(n, 4\), got \(9, 3\).*8 for hexes", dualex.write, tmp_path / "q.obj", Q, quads[:, :3])
    raises(r"\.xyz", dualex.write, tmp_path / "q.xyz", Q, quads)
    raises("give a path alone", dualex.inspect, *square()[:2])


def test_a_hint_names_the_keyword_that_works():
    # two triangles whose charts differ by a translation of 0.3: refused,
    # with a hint that must be this module's keyword, not the CLI's option
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [1, 3, 2]])
    UV = np.array([[[0, 0], [1, 0], [0, 1]], [[1.3, 0], [1.3, 1], [0.3, 1]]], dtype=float)
    with pytest.raises(ValueError) as e:
        dualex.quad(V, F, UV)
    message = str(e.value)
    assert "round_transitions=True" in message and "--" not in message, message
    # the suggestion, followed, is accepted
    dualex.quad(V, F, UV, round_transitions=True)
