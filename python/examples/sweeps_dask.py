#!/usr/bin/env python3
"""Parameter sweeps on a Dask cluster with lac.solve_batch(..., client=...):

1. drawable regions of planar G1 / compound-rhythm segments over the control triangle's shape, the
   grid of exp_planar_drawable (experiments/planar_drawable.cpp: 16 panels of (alpha0, alpha1, r),
   base angles b0, b2 at the cell centres of a grid x grid partition of (0, pi)^2 with b0 + b2 < pi),
   written as planar_drawable_grid.csv rows in that experiment's format; with --compare FILE the
   statuses and Lambda values are checked against a run of the experiment (e.g. results/);
2. a G2 Hermite success map over the end tangent angles (theta0, theta1) for fixed curvatures, the
   success share per solver.

    PYTHONPATH=build/python python3 python/examples/sweeps_dask.py --workers 2 \\
        --compare results/planar_drawable_grid.csv          # a LocalCluster of 2 workers
    ... --scheduler tcp://host:8786                          # a running cluster instead

Every cell is independent and deterministic, so the result does not depend on the cluster.
"""
import argparse
import csv
import math
import sys
import time

import numpy as np

import lac
from lac.distributed import local_client

PANELS = [(-2, -2, 1), (-1, -1, 1), (0, 0, 1), (0.5, 0.5, 1), (1, 1, 1), (1.5, 1.5, 1), (2, 2, 1), (3, 3, 1),
          (-1, 1.5, 0.5), (1.5, -1, 0.5), (0.5, 2, 0.5), (2, 0.5, 0.5), (-1, 2, 0.2), (-1, 2, 0.8), (-2, -0.5, 0.5),
          (3, 0, 0.5)]


def drawable_cells(grid):
    """(panel, b0, b2, a1) of every valid cell, in the experiment's order (math: the C++ libm values)."""
    cells = []
    for p in range(len(PANELS)):
        for i in range(grid):
            for j in range(grid):
                if i + j + 1 < grid:
                    b0, b2 = (i + 0.5) * math.pi / grid, (j + 0.5) * math.pi / grid
                    h = math.sin(b0) * math.sin(b2) / math.sin(b0 + b2)
                    cells.append((p, b0, b2, complex(h / math.tan(b0), h)))
    return cells


def drawable_sweep(client, grid, threads):
    cells = drawable_cells(grid)
    status = np.empty(len(cells), dtype="<U17")
    lam = np.zeros(len(cells))
    iters = np.zeros(len(cells), dtype=int)
    for monotonic in (True, False):
        idx = np.array([k for k, c in enumerate(cells) if (PANELS[c[0]][2] == 1) == monotonic])
        a1 = np.array([cells[k][3] for k in idx])
        alpha0 = np.array([PANELS[cells[k][0]][0] for k in idx], float)
        data = {"a0": (0, 0), "a1": a1, "a2": (1, 0)}
        if monotonic:
            t = lac.solve_batch("triangle", {**data, "alpha": alpha0}, client=client, threads=threads)
        else:
            alpha1 = np.array([PANELS[cells[k][0]][1] for k in idx], float)
            r = np.array([PANELS[cells[k][0]][2] for k in idx], float)
            t = lac.solve_batch("compound", {**data, "alpha0": alpha0, "alpha1": alpha1, "r": r}, client=client,
                                threads=threads)
        status[idx] = t.status
        lam[idx] = np.nan_to_num(t.lambda0_user, nan=0.0)
        iters[idx] = t.iterations
    return cells, status, lam, iters


def compare(path, cells, status, lam):
    rows = [r for r in csv.reader(line for line in open(path) if not line.startswith("#"))][1:]
    if len(rows) != len(cells):
        print(f"compare: {path} has {len(rows)} cells, this sweep {len(cells)} (another --grid?)")
        return False
    bad = 0
    for k, r in enumerate(rows):
        same_lambda = math.isclose(float(r[8]), lam[k], rel_tol=1e-9, abs_tol=1e-300)
        if r[7] != status[k] or not same_lambda:
            bad += 1
            if bad <= 5:
                print(f"  cell {k}: experiment {r[7]} {r[8]}, sweep {status[k]} {lam[k]!r}")
    print(f"compare with {path}: {len(rows) - bad} of {len(rows)} cells identical (status, Lambda to 1e-9)")
    return bad == 0


def g2_success_map(client, n, threads):
    th = np.linspace(-1.5, 1.5, n)
    t0, t1 = np.meshgrid(th, th, indexing="ij")
    data = {"p0": (0, 0), "p1": (1, 0), "theta0": t0.ravel(), "theta1": t1.ravel(), "kappa0": 1.0, "kappa1": -1.0,
            "alpha": -0.5}
    for solver in ("newton", "ceres", "paper"):
        a = time.perf_counter()
        t = lac.solve_batch("g2", data, client=client, threads=threads, solver=solver, fallback=False)
        print(f"G2 success map {n}x{n} (kappa0 = 1, kappa1 = -1, alpha = -0.5), solver {solver}: "
              f"{t.usable.mean():.3f} solved, {time.perf_counter() - a:.1f} s")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--scheduler", help="address of a running dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster workers")
    ap.add_argument("--threads", type=int, default=1, help="threads per chunk on a worker")
    ap.add_argument("--grid", type=int, default=36, help="drawable grid (the experiment's default is 36)")
    ap.add_argument("--g2-grid", type=int, default=21, help="G2 success map grid (0: skip)")
    ap.add_argument("--compare", help="planar_drawable_grid.csv of exp_planar_drawable to check against")
    ap.add_argument("--out", help="write planar_drawable_grid.csv rows here")
    args = ap.parse_args()
    if args.scheduler:
        from dask.distributed import Client

        client = Client(args.scheduler)
    else:
        client = local_client(n_workers=args.workers)
    with client:
        a = time.perf_counter()
        cells, status, lam, iters = drawable_sweep(client, args.grid, args.threads)
        print(f"drawable sweep: {len(cells)} cells on {len(client.scheduler_info()['workers'])} workers, "
              f"{time.perf_counter() - a:.1f} s, {np.mean(status == 'ok'):.3f} ok")
        if args.out:
            with open(args.out, "w") as f:
                f.write("index,panel,alpha0,alpha1,r,b0,b2,status,lambda0_user,iterations\n")
                for k, (p, b0, b2, _) in enumerate(cells):
                    a0, a1, r = PANELS[p]
                    f.write(f"{k},{p},{a0:g},{a1:g},{r:g},{b0:.10g},{b2:.10g},{status[k]},{lam[k]:.10g},{iters[k]}\n")
        ok = compare(args.compare, cells, status, lam) if args.compare else True
        if args.g2_grid:
            g2_success_map(client, args.g2_grid, args.threads)
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
