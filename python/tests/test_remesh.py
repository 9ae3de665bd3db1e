"""`dualex.remesh`: quads from a plain surface through the pipeline of
`dualex remesh` (issue 23): numpy arrays in, (Q, quads, stats) out, the
map on request; one-line ValueErrors on bad input and on remesh's own
failures; the GIL released while it runs."""

import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import dualex


def torus(nu=64, nv=24, big=1.0, small=0.4):
    """A closed torus of 2·nu·nv triangles, outward normals."""
    u, v = np.meshgrid(np.arange(nu), np.arange(nv), indexing="ij")
    a, b = 2 * np.pi * u / nu, 2 * np.pi * v / nv
    r = big + small * np.cos(b)
    V = np.stack([r * np.cos(a), r * np.sin(a), small * np.sin(b)], -1).reshape(-1, 3)
    i = lambda uu, vv: (uu % nu) * nv + (vv % nv)
    p, q, s, t = i(u, v), i(u + 1, v), i(u + 1, v + 1), i(u, v + 1)
    F = np.concatenate([np.stack([p, q, s], -1), np.stack([p, s, t], -1)]).reshape(-1, 3)
    return V, F


def fan_cone(sectors=96, height=1.5):
    """A closed cone as CAD exports it: an apex fan and a base fan."""
    a = 2 * np.pi * np.arange(sectors) / sectors
    V = np.c_[np.cos(a), np.sin(a), np.zeros(sectors)]
    V = np.r_[V, [[0, 0, 0], [0, 0, height]]]
    i = np.arange(sectors)
    j = (i + 1) % sectors
    base = np.c_[np.full(sectors, sectors), j, i]
    side = np.c_[i, j, np.full(sectors, sectors + 1)]
    return V, np.r_[base, side]


def test_a_torus_gives_quads_with_its_topology():
    V, F = torus()
    Q, quads, stats = dualex.remesh(V, F, quads=300)
    assert Q.dtype == np.float64 and Q.shape[1] == 3
    assert quads.shape == (stats["quads"], 4)
    assert quads.min() >= 0 and quads.max() < len(Q)
    assert stats["topology"]["matches"]
    assert stats["euler"] == 0 and stats["components"] == 1 and stats["boundary_loops"] == 0
    assert abs(stats["quads"] - 300) <= 0.15 * 300, stats["quads"]
    r = stats["remesh"]
    assert r["triangles"] == len(F)
    assert sum(r["singularity_index"].values()) == r["singularities"]
    assert "time_ms" in r and "geometry" in stats


def test_the_map_comes_back_and_extracts_to_the_same_quads():
    V, F = torus()
    Q, quads, stats, m = dualex.remesh(V, F, quads=300, seed=2, return_map=True)
    Vm, Fm, UV = m
    assert Vm.shape == V.shape and Fm.shape == F.shape and UV.shape == (len(F), 3, 2)
    # the same map, extracted by `quad` with the same seed: the same count
    assert dualex.quad(Vm, Fm, UV, seed=2)[2]["quads"] == stats["quads"]
    # seeds move the grid: another map
    _, _, _, (_, _, UV1) = dualex.remesh(V, F, quads=300, seed=1, return_map=True)
    assert not np.array_equal(UV, UV1)


def raises(match, f, *args, **kw):
    with pytest.raises(ValueError, match=match) as e:
        f(*args, **kw)
    assert "\n" not in str(e.value)
    return str(e.value)


def test_bad_input_and_bad_options():
    V, F = torus(16, 8)
    bad = F.copy()
    bad[5, 2] = len(V)
    raises(f"triangle 5: corner 2 refers to vertex {len(V)}", dualex.remesh, V, bad)
    raises(r"V: expected shape \(n, 3\)", dualex.remesh, V[:, :2], F)
    raises("F: expected integers", dualex.remesh, V, F.astype(float))
    nan = V.copy()
    nan[3, 0] = np.nan
    raises("vertex 3: position", dualex.remesh, nan, F)
    # a non-manifold edge: one more triangle on an edge of two
    raises("non-manifold", dualex.remesh, V, np.r_[F, [[F[0, 0], F[0, 1], F[9, 2]]]])
    raises("rounding: expected", dualex.remesh, V, F, rounding="nearest")
    raises("quads: expected at least 1", dualex.remesh, V, F, quads=0)
    raises("sharp: expected an angle", dualex.remesh, V, F, sharp=200)
    with pytest.raises(OverflowError):
        dualex.remesh(V, F, quads=-3)


def test_a_cad_cone_of_two_fans_is_remeshed():
    # its map collapsed before remesh split long edges and spread the
    # caps' +1 into quarters (issue 23); the collapse check itself is
    # tested in Rust (`dualex::remesh`'s unit tests)
    V, F = fan_cone()
    Q, quads, stats = dualex.remesh(V, F, quads=300)
    assert stats["topology"]["matches"] is True
    assert abs(stats["quads"] - 300) <= 45 and len(quads) == stats["quads"]
    assert stats["geometry"]["after"]["inverted"] == 0
    assert quads.min() >= 0 and quads.max() < len(Q)


def test_the_one_liner_of_the_issue(tmp_path):
    V, F = torus()
    with open(tmp_path / "x.obj", "w") as f:
        f.writelines(f"v {x} {y} {z}\n" for x, y, z in V)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F)
    # read gives a plain surface as (V, F, None)
    Vr, Fr, none = dualex.read(tmp_path / "x.obj")
    assert none is None and np.array_equal(Fr, F) and np.allclose(Vr, V)
    line = "import dualex; print(dualex.remesh(*dualex.read('x.obj')[:2], quads=500)[2]['quads'])"
    out = subprocess.run([sys.executable, "-c", line], cwd=tmp_path, capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert abs(int(out.stdout) - 500) <= 0.15 * 500, out.stdout


def test_a_broken_map_file_is_still_an_error_not_a_surface(tmp_path):
    p = tmp_path / "m.obj"
    p.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/2\n")
    raises("texture coordinate index 2 is out of range", dualex.read, p)


def test_the_gil_is_released_while_remesh_runs():
    """The main thread keeps running Python while remesh works in another."""
    V, F = torus(128, 48)
    took = []

    def run():
        t = time.perf_counter()
        dualex.remesh(V, F, quads=2000)
        took.append(time.perf_counter() - t)

    worker = threading.Thread(target=run)
    last, gap = time.perf_counter(), 0.0
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        gap, last = max(gap, now - last), now
    worker.join()
    assert took and took[0] > 0.05, took
    # with the GIL held the main thread would stall for the whole call
    assert gap < 0.5 * took[0], (gap, took)
