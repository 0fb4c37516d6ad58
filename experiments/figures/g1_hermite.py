#!/usr/bin/env python3
"""Status of every G1 Hermite problem over the (theta0, theta1) square, one panel per alpha, from
results/g1_hermite_grid.csv (exp_g1_hermite).

Usage: g1_hermite.py RESULTS_DIR. Writes RESULTS_DIR/figures/g1_hermite.png.
"""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

COLORS = {"ok": "#2a9d4b", "tolerance_not_met": "#e9c46a", "fell_back": "#8ab17d", "no_solution": "#bbbbbb"}


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    by_alpha = {}
    with open(results / "g1_hermite_grid.csv") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    for r in rows:
        by_alpha.setdefault(float(r["alpha"]), []).append(r)
    alphas = sorted(by_alpha)
    cols = 3
    nrows = math.ceil(len(alphas) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(4 * cols, 4 * nrows), squeeze=False)
    for ax, alpha in zip(axes.flat, alphas):
        seen = set()
        for status in sorted({r["status"] for r in by_alpha[alpha]}):
            pts = [r for r in by_alpha[alpha] if r["status"] == status]
            ax.scatter([float(r["theta0"]) for r in pts], [float(r["theta1"]) for r in pts], s=3,
                       color=COLORS.get(status, "#d62828"), label=f"{status} ({len(pts)})")
            seen.add(status)
        ax.set_title(f"α = {alpha:g}")
        ax.set_xlim(-math.pi / 2, math.pi / 2)
        ax.set_ylim(-math.pi / 2, math.pi / 2)
        ax.set_aspect("equal")
        ax.set_xlabel("θ0 (rad)")
        ax.set_ylabel("θ1 (rad)")
        ax.legend(fontsize=7, loc="lower right", markerscale=3)
    for ax in list(axes.flat)[len(alphas):]:
        ax.axis("off")
    fig.suptitle("G1 Hermite by one LA segment: status over the (θ0, θ1) square, P0 = (0,0), P1 = (1,0)")
    fig.tight_layout()
    (results / "figures").mkdir(parents=True, exist_ok=True)
    fig.savefig(results / "figures" / "g1_hermite.png", dpi=100)
    plt.close(fig)


if __name__ == "__main__":
    main()
