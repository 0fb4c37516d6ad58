#!/usr/bin/env python3
"""Heat maps of the worst relative endpoint error over (alpha, Lambda) from results/igf_alpha.csv
(written by exp_igf_alpha): the igf closed form beside Gauss-Kronrod, with the 1e-12 target.

Usage: igf_alpha.py RESULTS_DIR. Writes RESULTS_DIR/figures/igf_alpha.png.
"""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    with open(results / "igf_alpha.csv") as fh:
        rows = list(csv.reader(line for line in fh if not line.startswith("#")))
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    rows = [r for r in rows if float(r[idx["Lambda"]]) > 0]  # the circle rows have no Lambda column
    alphas = sorted({float(r[idx["alpha"]]) for r in rows})
    lambdas = sorted({float(r[idx["Lambda"]]) for r in rows})
    grids = {}
    for col in ("igf max rel. error", "gauss-kronrod max rel. error"):
        g = np.full((len(alphas), len(lambdas)), np.nan)
        for r in rows:
            i, j = alphas.index(float(r[idx["alpha"]])), lambdas.index(float(r[idx["Lambda"]]))
            g[i, j] = math.log10(max(float(r[idx[col]]), 1e-17))
        grids[col] = g

    fig, axes = plt.subplots(1, 2, figsize=(10, 7), sharey=True, constrained_layout=True)
    for ax, (col, title) in zip(axes, [("igf max rel. error", "igf (closed form)"),
                                       ("gauss-kronrod max rel. error", "Gauss-Kronrod, tol 1e-14")]):
        im = ax.imshow(grids[col], vmin=-17, vmax=-11, cmap="viridis", aspect="auto", origin="lower")
        for i in range(len(alphas)):
            for j in range(len(lambdas)):
                v = grids[col][i, j]
                if not np.isnan(v):
                    ax.text(j, i, f"{v:.1f}", ha="center", va="center", fontsize=7,
                            color="white" if v < -14.5 else "black")
        ax.set_xticks(range(len(lambdas)), [f"{x:g}" for x in lambdas])
        ax.set_xlabel("Λ")
        ax.set_title(title)
    axes[0].set_yticks(range(len(alphas)), [f"{a:.6g}" for a in alphas])
    axes[0].set_ylabel("α")
    cb = fig.colorbar(im, ax=axes, shrink=0.8)
    cb.set_label("log10 max relative error of C(θ1) − C(θ0) (target −12)")
    fig.suptitle("Worst endpoint error per (α, Λ) over tests/reference/igf_reference.csv")
    out = results / "figures"
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "igf_alpha.png", dpi=110)
    print(f"wrote {out / 'igf_alpha.png'}")


if __name__ == "__main__":
    main()
