"""Small generated maps: a square of 2 triangles mapped onto [0, s]²
(s² quads), a cube of 6 tets mapped onto [0, s]³ (s³ hexes), and a noisy
grid whose map places some quads inverted."""

import numpy as np


def square(s=3):
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    return V, F, s * V[F][:, :, :2]


def cube(s=2):
    V = np.array([[i & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)], dtype=float)
    T = np.array([[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]])
    return V, T, s * V[T]


def _uniform(seed):
    """Deterministic numbers in [-1, 1) (a 64-bit LCG, independent of numpy's
    generators)."""
    x = seed
    while True:
        x = (x * 6364136223846793005 + 1442695040888963407) % 2**64
        yield (x >> 11) / 2**53 * 2 - 1


def noisy_grid(n=8, amplitude=0.9, seed=3):
    """An n×n grid of unit squares (2 triangles each) whose map is the
    identity with each interior vertex moved by up to `amplitude` grid
    units per axis (one chart: the map stays grid preserving; the boundary
    stays on the grid). The quads' corners sit where the map puts the grid
    points: with the defaults 4 of the 64 quads are inverted."""
    ij = np.array([[i, j] for j in range(n + 1) for i in range(n + 1)], dtype=float)
    V = np.c_[ij, np.zeros(len(ij))]
    F = []
    for j in range(n):
        for i in range(n):
            v = j * (n + 1) + i
            F += [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]]
    F = np.array(F)
    r = _uniform(seed)
    uv = ij.copy()
    for k, (i, j) in enumerate(ij):
        if 0 < i < n and 0 < j < n:
            uv[k] += [amplitude * next(r), amplitude * next(r)]
    return V, F, uv[F]
