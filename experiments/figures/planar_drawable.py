#!/usr/bin/env python3
"""Heatmaps of the drawable regions from results/planar_drawable_grid.csv (written by exp_planar_drawable).

Usage: planar_drawable.py RESULTS_DIR. Writes RESULTS_DIR/figures/planar_drawable.png: one panel per
(alpha0, alpha1, r); axes are the control triangle's base angles b0 (at a0) and b2 (at a2) in degrees;
colour: drawable (ok, shaded by log10 of Lambda0 in units where |a2 - a0| = 1), tolerance_not_met (orange),
no curve (proven; light grey), solver did not converge (blue), other failures (red). The upper-right half (b0 + b2 >= 180 deg) has no triangle.
"""
import csv
import math
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402


def main():
    res = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    with open(res / "planar_drawable_grid.csv") as fh:
        rows = list(csv.DictReader(line for line in fh if not line.startswith("#")))
    panels = {}
    for r in rows:
        panels.setdefault(int(r["panel"]), []).append(r)
    b_all = sorted({float(r["b0"]) for r in rows})
    n = len(b_all)
    step = math.pi / n
    cols = 4
    nrows = math.ceil(len(panels) / cols)
    fig, axes = plt.subplots(nrows, cols, figsize=(4.2 * cols, 3.9 * nrows), squeeze=False)
    status_map = ListedColormap(["#d9d9d9", "#ff9f1c", "#1f77b4", "#d62728"])
    lam_im = None
    for ax, (p, cells) in zip(axes.flat, sorted(panels.items())):
        lam = np.full((n, n), np.nan)
        other = np.full((n, n), np.nan)
        for r in cells:
            i = int(round(float(r["b0"]) / step - 0.5))
            j = int(round(float(r["b2"]) / step - 0.5))
            st = r["status"]
            if st == "ok":
                lam[j, i] = math.log10(max(float(r["lambda0_user"]), 1e-6))
            else:
                other[j, i] = {"no_solution": 0, "tolerance_not_met": 1, "not_converged": 2}.get(st, 3)
        ext = [0, 180, 0, 180]
        ax.imshow(other, origin="lower", extent=ext, cmap=status_map, vmin=0, vmax=3, interpolation="nearest")
        lam_im = ax.imshow(lam, origin="lower", extent=ext, cmap="viridis", vmin=-2, vmax=2, interpolation="nearest")
        c = cells[0]
        a0, a1, r_ = float(c["alpha0"]), float(c["alpha1"]), float(c["r"])
        title = f"monotonic α={a0:g}" if r_ >= 1 else f"α0={a0:g}, α1={a1:g}, r={r_:g}"
        ok = sum(1 for x in cells if x["status"] == "ok")
        ax.set_title(f"{title}  ({100 * ok / len(cells):.0f}% drawable)", fontsize=10)
        ax.plot([0, 180], [180, 0], color="k", lw=0.6)
        ax.set_xlim(0, 180)
        ax.set_ylim(0, 180)
        ax.set_xlabel("b0 at a0 (deg)", fontsize=8)
        ax.set_ylabel("b2 at a2 (deg)", fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[len(panels):]:
        ax.axis("off")
    fig.suptitle("Drawable regions over the control triangle's base angles (grey: no curve, orange: tangent tolerance "
                 "not met, blue: not converged, red: other failure; colour: log10 Λ0 in units |a2−a0| = 1)", fontsize=11)
    fig.tight_layout(rect=(0, 0, 0.93, 0.96))
    cax = fig.add_axes((0.94, 0.25, 0.012, 0.5))
    fig.colorbar(lam_im, cax=cax, label="log10 Λ0")
    (res / "figures").mkdir(parents=True, exist_ok=True)
    fig.savefig(res / "figures" / "planar_drawable.png", dpi=100)


if __name__ == "__main__":
    main()
