#!/usr/bin/env python3
"""Figures like 003 Figs. 3-9: quadratic LA curves, their logarithmic curvature graphs (LCG)
and curvature plots, from exp_quadratic_figures' data (results/data/quadratic_figure_points.csv).

Usage: /usr/bin/python3 experiments/figures/quadratic_figures.py RESULTS_DIR
Writes RESULTS_DIR/figures/quadratic_fig{3..9}.png.
"""
import csv
import math
import os
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

results = sys.argv[1] if len(sys.argv) > 1 else "results"
path = os.path.join(results, "data", "quadratic_figure_points.csv")
curves = OrderedDict()
with open(path) as f:
    rows = [r for r in f if not r.startswith("#")]
for r in csv.DictReader(rows):
    key = (r["figure"], r["alpha"], r["gamma"], r["lambda"])
    curves.setdefault(key, []).append(r)


def num(v):
    try:
        return float(v)
    except ValueError:
        return math.nan


def columns(points, name):
    return [num(p[name]) for p in points]


def figure_number(label):
    return label.split(" ")[0].rstrip("abc")


groups = OrderedDict()
for key, pts in curves.items():
    groups.setdefault(figure_number(key[0]), []).append((key, pts))

os.makedirs(os.path.join(results, "figures"), exist_ok=True)
for fig_no, members in groups.items():
    overlay = fig_no in ("7", "8")
    ncols = 1 if overlay else len(members)
    fig, axes = plt.subplots(3, ncols, figsize=(4.2 * ncols + (2.5 if overlay else 0), 10.5), squeeze=False)
    for j, (key, pts) in enumerate(members):
        label, a, g, lam = key
        col = 0 if overlay else j
        tag = (r"$\gamma$=%s" % g) if fig_no == "7" else (r"$\Lambda$=%s" % lam) if fig_no == "8" else None
        x, y = columns(pts, "x"), columns(pts, "y")
        s, kappa = columns(pts, "s"), columns(pts, "kappa")
        lr, lcg, par = columns(pts, "lcg_log_rho"), columns(pts, "lcg_from_curve"), columns(pts, "lcg_parabola")
        ax = axes[0][col]
        ax.plot(x, y, lw=1.3, label=tag)
        ax.plot([0], [0], "k.", ms=5)
        ax.set_aspect("equal", adjustable="datalim")
        ax.set_title(r"%s: $\alpha$=%s, $\gamma$=%s, $\Lambda$=%s" % (label, a, g, lam) if not overlay else
                     (r"Fig. 7: $\alpha$=-1, $\Lambda$=1, various $\gamma$" if fig_no == "7" else
                      r"Fig. 8: $\alpha$=-0.2, $\gamma$=-0.5, various $\Lambda$"), fontsize=9)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax = axes[1][col]
        ok = [(u, v) for u, v in zip(lr, lcg) if math.isfinite(u) and math.isfinite(v)]
        okp = sorted((u, v) for u, v in zip(lr, par) if math.isfinite(u) and math.isfinite(v))
        line, = ax.plot([u for u, _ in okp], [v for _, v in okp], lw=1.0, label=(tag + " parabola") if tag else "parabola")
        ax.plot([u for u, _ in ok[::8]], [v for _, v in ok[::8]], ".", ms=3, color=line.get_color(),
                label=(tag + " from curve") if tag else "from the curve's points")
        ax.set_xlabel(r"$\log \rho$")
        ax.set_ylabel(r"$\log(\rho\, ds/d\rho)$")
        ax.set_title("LCG", fontsize=9)
        ax = axes[2][col]
        ax.plot(s, kappa, lw=1.2, label=tag)
        ax.set_xlabel("s")
        ax.set_ylabel(r"$\kappa$")
        ax.set_yscale("log")
        ax.set_title("curvature plot", fontsize=9)
    for row in axes:
        for ax in row:
            ax.grid(alpha=0.3)
            if overlay or len(row) == 1:
                ax.legend(fontsize=6)
    if not overlay:
        for ax in axes[1]:
            ax.legend(fontsize=7)
    fig.suptitle("003 Fig. %s (recomputed; quadratic LA curves, standard form)" % fig_no, fontsize=11)
    fig.tight_layout()
    out = os.path.join(results, "figures", "quadratic_fig%s.png" % fig_no)
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print("wrote", out)
