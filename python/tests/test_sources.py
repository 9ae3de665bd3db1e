"""``return_sources=True``: the input simplex of each cell. On the
generated maps (the map is affine, so positions are the map scaled down)
each cell's centroid lies in its source simplex's image, up to the
sanitizer's tiny perturbations (nodes on a shared face move by ~1e-7)."""

import numpy as np
import pytest

import dualex
from maps import cube, square

EPS = 1e-6


def barycentric(corners, p):
    """Barycentric coordinates of p in a simplex given by its corners
    (a triangle in the plane, or a tet in space)."""
    d = len(corners) - 1
    A = np.vstack([np.asarray(corners)[:, :d].T, np.ones(d + 1)])
    return np.linalg.solve(A, np.append(p[:d], 1.0))


def test_quad_sources_hold_the_centroids():
    V, F, UV = square(3)
    Q, quads, stats, sources = dualex.quad(V, F, UV, return_sources=True)
    assert sources.shape == (len(quads),) == (9,) and sources.dtype == np.int64
    assert stats["quads"] == 9
    assert ((sources >= 0) & (sources < len(F))).all()  # no hole in a square
    for q, s in zip(quads, sources):
        b = barycentric(V[F[s]], Q[q].mean(axis=0))
        assert (b > -EPS).all(), (q, s, b)


def test_hex_sources_hold_the_centroids():
    V, T, UVW = cube(2)
    H, hexes, stats, sources = dualex.hex(V, T, UVW, return_sources=True)
    assert sources.shape == (len(hexes),) == (8,) and sources.dtype == np.int64
    assert ((sources >= 0) & (sources < len(T))).all()
    for h, s in zip(hexes, sources):
        b = barycentric(V[T[s]], H[h].mean(axis=0))
        assert (b > -EPS).all(), (h, s, b)


@pytest.mark.parametrize("flag", [False, None])
def test_without_the_keyword_three_values(flag):
    kw = {} if flag is None else {"return_sources": flag}
    assert len(dualex.quad(*square(2), **kw)) == 3
    assert len(dualex.hex(*cube(1), **kw)) == 3
