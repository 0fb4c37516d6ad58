#!/usr/bin/env python3
"""Plots like 001 Figs. 7-8 from results/planar_figures_points.csv (written by exp_planar_figures).

Usage: planar_figures.py RESULTS_DIR. Writes RESULTS_DIR/figures/planar_figures_fig7.png and
planar_figures_fig8.png: (left) the curves on the control triangle with their evolutes (dashed) and the
joint marked; (middle) logarithmic curvature graphs recomputed from the samples (rho = 1/|kappa|,
d rho/ds by finite differences), which must be two straight pieces of slopes alpha0, alpha1; (right)
signed curvature along the arc length.
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

TRIANGLE = np.array([[0, 0], [1, 0], [1.8, 1.2]])


def load(path):
    curves = {}
    with open(path) as fh:
        rows = list(csv.reader(line for line in fh if not line.startswith("#")))
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    for r in rows:
        key = (r[idx["figure"]], float(r[idx["alpha0"]]), float(r[idx["alpha1"]]), float(r[idx["r"]]))
        c = curves.setdefault(key, {k: [] for k in header if k != "figure"})
        for k in c:
            c[k].append(float(r[idx[k]]))
    return {k: {n: np.array(v) for n, v in c.items()} for k, c in curves.items()}


def label(key):
    _, a0, a1, r = key
    if r >= 1:
        return f"monotonic α={a0:g}"
    return f"α0={a0:g}, α1={a1:g}, r={r:g}"


def plot_set(curves, figure, out):
    keys = [k for k in curves if k[0] == figure]
    fig, axes = plt.subplots(1, 3, figsize=(17, 5.6))
    ax_c, ax_l, ax_k = axes
    ax_c.plot(TRIANGLE[:, 0], TRIANGLE[:, 1], "o-", color="0.6", lw=1, label="control points")
    colors = plt.cm.tab10(np.linspace(0, 1, 10))
    for i, key in enumerate(keys):
        c = curves[key]
        col = colors[i % 10]
        mono = key[3] >= 1
        style = ":" if mono else "-"
        ax_c.plot(c["x"], c["y"], style, color=col, lw=2, label=label(key))
        nx, ny = -np.sin(c["theta"]), np.cos(c["theta"])
        ex, ey = c["x"] + nx / c["kappa"], c["y"] + ny / c["kappa"]
        ax_c.plot(ex, ey, "--", color=col, lw=1.1)
        piece = c["piece"]
        if not mono:
            j = np.argmax(piece > 0) - 1  # last sample of piece 0 = the joint
            ax_c.plot(c["x"][j], c["y"][j], "o", color="k", ms=5)
            ax_c.plot(ex[j], ey[j], "o", color=col, ms=3)
        rho = 1 / np.abs(c["kappa"])
        for p in (0, 1):
            m = piece == p
            if p == 1:  # the joint (last sample of piece 0) starts piece 1 as well
                m = m.copy()
                m[np.argmax(m) - 1] = True
            if m.sum() < 5:
                continue
            s, rr = c["s"][m], rho[m]
            drho = np.gradient(rr, s, edge_order=2)  # one-sided second order at the piece ends
            ok = np.abs(drho) > 0
            ax_l.plot(np.log(rr[ok]), np.log(rr[ok] / np.abs(drho[ok])), style, color=col, lw=2,
                      label=label(key) if p == 0 else None)
        ax_k.plot(c["s"], c["kappa"], style, color=col, lw=2, label=label(key))
        if not mono:
            ax_k.plot(c["s"][j], c["kappa"][j], "o", color="k", ms=4)
    ax_c.set_aspect("equal")
    ax_c.set_xlim(-3.2, 2.4)
    ax_c.set_ylim(-0.4, 4.6)
    ax_c.set_title("curves (solid), evolutes (dashed), joints (black dots)")
    ax_c.legend(fontsize=7, loc="center right")
    ax_l.set_xlabel("log ρ")
    ax_l.set_ylabel("log(ρ ds/dρ)")
    ax_l.set_title("LCG from the samples: slopes α0 then α1")
    ax_l.grid(alpha=0.3)
    ax_k.set_xlabel("s (from a0)")
    ax_k.set_ylabel("κ")
    ax_k.set_title("curvature")
    ax_k.grid(alpha=0.3)
    name = {"fig7": "like 001 Fig. 7: slopes of opposite sign (V and upside-down V LCGs)",
            "fig8": "like 001 Fig. 8: slopes of the same sign"}[figure]
    fig.suptitle(f"Compound-rhythm LA curves on a0=(0,0), a1=(1,0), a2=(1.8,1.2), {name}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    res = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    curves = load(res / "planar_figures_points.csv")
    (res / "figures").mkdir(parents=True, exist_ok=True)
    for figure in ("fig7", "fig8"):
        plot_set(curves, figure, res / "figures" / f"planar_figures_{figure}.png")


if __name__ == "__main__":
    main()
