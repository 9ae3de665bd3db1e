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


def test_corner_uv_are_the_maps_grid_points():
    """return_uv=True: each quad's corners in its node's chart, exact grid
    points of the input map; on the identity-like square map they are the
    map's value at the quad's vertices."""
    V, F, UV = square(3)
    Q, quads, _, uv = dualex.quad(V, F, UV, return_uv=True)
    assert uv.shape == (9, 4, 2) and uv.dtype == np.float64
    assert np.array_equal(uv, np.round(uv))
    # (vertex positions come from the sanitized map: within 1e-5 of exact)
    assert np.allclose(uv, 3 * Q[quads][:, :, :2], atol=1e-4)
    # with sources too: sources first, then uv
    out = dualex.quad(V, F, UV, return_sources=True, return_uv=True)
    assert len(out) == 5 and out[3].shape == (9,) and np.array_equal(out[4], uv)
    H, hexes, _, uvw = dualex.hex(*cube(2), return_uv=True)
    assert uvw.shape == (8, 8, 3)
    assert np.allclose(uvw, 2 * H[hexes], atol=1e-4)
