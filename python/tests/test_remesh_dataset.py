"""The Dask example (examples/remesh_dataset.py) as a user runs it: a
folder of surfaces on a LocalCluster of 2 workers, one surface failing on
purpose (three triangles on one edge: not a manifold), one file that is no
surface, and a CAD cone of two fans (whose map collapsed before issue 23's
refinement; remeshed now); the batch goes on and the summary lists every
row with its error. Dask is a test dependency (.ci/run installs
it), not one of the module."""

import csv
import pathlib
import subprocess
import sys

import numpy as np

from test_remesh import fan_cone, torus

EXAMPLE = pathlib.Path(__file__).resolve().parents[1] / "examples" / "remesh_dataset.py"


def write_obj(path, V, F):
    with open(path, "w") as f:
        f.writelines(f"v {x} {y} {z}\n" for x, y, z in V)
        f.writelines(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in F)


def test_a_folder_on_a_local_cluster_with_a_failure(tmp_path):
    src, out = tmp_path / "in", tmp_path / "out"
    src.mkdir()
    write_obj(src / "torus_a.obj", *torus())
    write_obj(src / "torus_b.obj", *torus(48, 16, 1.0, 0.3))
    write_obj(src / "cone.obj", *fan_cone())
    (src / "broken.obj").write_text("v 0 0 0\nf 1 2 3\n")
    # three triangles on one edge: remesh refuses a non-manifold surface
    (src / "fin.obj").write_text(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"
    )
    run = subprocess.run(
        [sys.executable, str(EXAMPLE), str(src), str(out), "--workers", "2", "--quads", "300"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert run.returncode == 0, run.stderr
    assert "5 surfaces, 2 failed or invalid" in run.stdout, run.stdout
    assert "5/5" in run.stderr  # the progress bar's last state
    with open(out / "summary.csv") as f:
        rows = {r["surface"]: r for r in csv.DictReader(f)}
    assert sorted(rows) == ["broken.obj", "cone.obj", "fin.obj", "torus_a.obj", "torus_b.obj"]
    for name in ["torus_a.obj", "torus_b.obj", "cone.obj"]:
        r = rows[name]
        assert r["valid"] == "True" and r["error"] == "", r
        assert abs(int(r["quads"]) - 300) <= 45, r
        cells = [l for l in (out / name).read_text().splitlines() if l.startswith("f ")]
        assert len(cells) == int(r["quads"])
    fin = rows["fin.obj"]
    assert fin["valid"] == "False" and fin["quads"] == ""
    assert "non-manifold" in fin["error"], fin
    assert not (out / "fin.obj").exists()
    assert rows["broken.obj"]["valid"] == "False"
    assert "broken.obj" in rows["broken.obj"]["error"]
    assert not (out / "broken.obj").exists()
