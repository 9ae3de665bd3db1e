"""Small generated maps: a square of 2 triangles mapped onto [0, s]²
(s² quads) and a cube of 6 tets mapped onto [0, s]³ (s³ hexes)."""

import numpy as np


def square(s=3):
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=float)
    F = np.array([[0, 1, 2], [0, 2, 3]])
    return V, F, s * V[F][:, :, :2]


def cube(s=2):
    V = np.array([[i & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)], dtype=float)
    T = np.array([[0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7], [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7]])
    return V, T, s * V[T]
