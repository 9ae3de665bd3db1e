"""Quad mesh of a libigl map: load a textured OBJ with libigl, extract, write.

    python examples/libigl_quads.py fandisk_param.obj quads.obj

The OBJ's texture coordinates are the map (a seamless parametrization or
an integer-grid map, as QEx and Directional export them): libigl gives
positions V, texture coordinates TC, faces F and per-corner texture
indices FTC, so the per-corner map of triangle t is TC[FTC[t]].
"""

import sys

import igl
import numpy as np

import dualex


def read_obj(path):
    """V, TC, F, FTC with the libigl Python API at hand (2.6: readOBJ;
    2.5: read_obj)."""
    if hasattr(igl, "readOBJ"):
        V, TC, _N, F, FTC, _FN = igl.readOBJ(path)
    else:
        V, TC, _N, F, FTC, _FN = igl.read_obj(path)
    return V, TC, F, FTC


def main(argv):
    if len(argv) != 3:
        sys.exit(f"usage: {argv[0]} MAP.obj QUADS.obj")
    V, TC, F, FTC = read_obj(argv[1])
    if FTC.shape != F.shape or F.shape[1:] != (3,):
        sys.exit(f"{argv[1]}: expected a triangle mesh with texture coordinates")
    UV = np.asarray(TC)[FTC][:, :, :2]  # (m, 3, 2): the map per corner
    Q, quads, stats = dualex.quad(V, F, UV)
    igl.writeOBJ(argv[2], Q, quads)
    print(f"{argv[2]}: {stats['quads']} quads, {stats['vertices']} vertices")


if __name__ == "__main__":
    main(sys.argv)
