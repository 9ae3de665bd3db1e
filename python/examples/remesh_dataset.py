"""Remesh every surface of a folder with Dask, on one machine or a cluster.

    python examples/remesh_dataset.py IN_DIR OUT_DIR [--scheduler ADDRESS]
        [--quads N] [--seed N] [--workers N]

Every `.obj` / `.ply` of IN_DIR (a plain surface) is remeshed by
`dualex.remesh` in a Dask task; its quads go to OUT_DIR/NAME.obj and one
row per surface to OUT_DIR/summary.csv: surface, quads, singularities,
valid (quads written, the surface's topology), seconds, error. A surface
that fails (unreadable, not a manifold, a map remesh could not make) is a
row with its error; it never stops the batch. Progress is drawn on stderr.

Without --scheduler a LocalCluster of --workers processes (one thread
each) runs here; with it the tasks go to that scheduler
(`dask scheduler` on one machine, `dask worker ADDRESS` on each other,
every worker with `pip install ./python`). The client reads the surfaces
and writes the results, so the workers need no access to the folders.
The exit status is 0 when the summary is written, whatever failed in it.
"""

import argparse
import csv
import pathlib
import sys
import time

import dualex

COLUMNS = ["surface", "quads", "singularities", "valid", "seconds", "error"]


def remesh_one(name, V, F, quads, seed):
    """One task: (row, Q, cells) with Q and cells None on an error."""
    t = time.perf_counter()
    try:
        Q, cells, stats = dualex.remesh(V, F, quads=quads, seed=seed)
    except ValueError as e:
        return _row(name, None, None, False, t, str(e)), None, None
    valid = bool(stats["topology"]["matches"]) and len(cells) > 0
    row = _row(name, len(cells), stats["remesh"]["singularities"], valid, t, "")
    return row, Q, cells


def _row(name, quads, singularities, valid, t0, error):
    values = [name, quads, singularities, valid, round(time.perf_counter() - t0, 3), error]
    return dict(zip(COLUMNS, values))


def surfaces(folder):
    """The surfaces of a folder, by name."""
    return sorted(p for p in folder.iterdir() if p.suffix.lower() in (".obj", ".ply"))


def progress(done, total, width=30):
    filled = width * done // max(total, 1)
    print(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total}", end="", file=sys.stderr, flush=True)


def run(client, paths, out_dir, quads, seed):
    """Submits one task per readable surface; rows in the order of paths."""
    from dask.distributed import as_completed

    rows, futures = {}, []
    for p in paths:
        try:
            # (a map file is remeshed as its surface, its map ignored)
            V, F, _uv = dualex.read(p)
        except ValueError as e:
            rows[p.name] = _row(p.name, None, None, False, time.perf_counter(), str(e))
            continue
        futures.append(client.submit(remesh_one, p.name, V, F, quads, seed, pure=False))
    done = len(rows)
    progress(done, len(paths))
    for f in as_completed(futures):
        row, Q, cells = f.result()
        if Q is not None:
            dualex.write(out_dir / (pathlib.Path(row["surface"]).stem + ".obj"), Q, cells)
        rows[row["surface"]] = row
        done += 1
        progress(done, len(paths))
    print(file=sys.stderr)
    return [rows[p.name] for p in paths]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("in_dir", type=pathlib.Path)
    ap.add_argument("out_dir", type=pathlib.Path)
    ap.add_argument("--scheduler", metavar="ADDRESS", help="a Dask scheduler (default: a local cluster)")
    ap.add_argument("--workers", type=int, default=2, help="local cluster: worker processes (default 2)")
    ap.add_argument("--quads", type=int, default=1000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args(argv)
    if not a.in_dir.is_dir():
        ap.error(f"{a.in_dir}: not a folder")
    paths = surfaces(a.in_dir)
    if not paths:
        ap.error(f"{a.in_dir}: no .obj or .ply surface")
    a.out_dir.mkdir(parents=True, exist_ok=True)
    from dask.distributed import Client, LocalCluster

    if a.scheduler:
        client = Client(a.scheduler)
    else:
        cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, dashboard_address=None)
        client = Client(cluster)
    try:
        rows = run(client, paths, a.out_dir, a.quads, a.seed)
    finally:
        client.close()
        if not a.scheduler:
            cluster.close()
    summary = a.out_dir / "summary.csv"
    with open(summary, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=COLUMNS)
        w.writeheader()
        w.writerows(rows)
    failed = sum(1 for r in rows if not r["valid"])
    print(f"{len(rows)} surfaces, {failed} failed or invalid -> {summary}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
