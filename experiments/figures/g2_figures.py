#!/usr/bin/env python3
"""Plots like 004 Figs. 3, 6-8 from results/g2_figures_points.csv (written by exp_g2_figures).

Usage: g2_figures.py RESULTS_DIR. Writes RESULTS_DIR/figures/g2_figures_fig3.png (S-curves on one
control polygon for several alpha, with curvature), g2_figures_fig7.png (triple LA curves, alpha =
-0.5, several end curvatures; joints S = 0.25, 0.75 marked; curvature profiles as 004 Figs. 6-7) and
g2_figures_fig8.png (two triples of different alpha joined G2, with the curvature along the whole
curve).
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

CONTROL = np.array([[0, 0], [1, 0], [1.6, 1.2], [3, 1.0]])  # as in experiments/g2_figures.cpp


def load(path):
    curves = {}
    with open(path) as fh:
        rows = list(csv.reader(line for line in fh if not line.startswith("#")))
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    for r in rows:
        key = (r[idx["figure"]], r[idx["label"]], int(r[idx["piece"]]))
        c = curves.setdefault(key, {"alpha": float(r[idx["alpha"]]), **{k: [] for k in ("S", "s", "x", "y", "kappa")}})
        for k in ("S", "s", "x", "y", "kappa"):
            c[k].append(float(r[idx[k]]))
    for c in curves.values():
        for k in ("S", "s", "x", "y", "kappa"):
            c[k] = np.array(c[k])
    return curves


def joint_marks(ax, c):
    for S in (0.25, 0.75):
        i = int(np.argmin(np.abs(c["S"] - S)))
        ax.plot(c["x"][i], c["y"][i], "k.", ms=6)


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    curves = load(results / "g2_figures_points.csv")
    (results / "figures").mkdir(parents=True, exist_ok=True)

    # Fig. 3: S-curves.
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    a.plot(CONTROL[:, 0], CONTROL[:, 1], "o--", color="0.6", lw=1, label="control points")
    for key, c in sorted((k, v) for k, v in curves.items() if k[0] == "fig3"):
        a.plot(c["x"], c["y"], label=f"α = {c['alpha']:g}")
        b.plot(c["s"], c["kappa"], label=f"α = {c['alpha']:g}")
    a.set_aspect("equal")
    a.set_title("S-shaped LA curves, one control polygon (cf. 004 Fig. 3)")
    a.legend(fontsize=8)
    b.axhline(0, color="0.7", lw=0.8)
    b.set_xlabel("arc length s")
    b.set_ylabel("signed curvature κ")
    b.set_title("curvature: one inflection each")
    fig.tight_layout()
    fig.savefig(results / "figures" / "g2_figures_fig3.png", dpi=120)
    plt.close(fig)

    # Figs. 6-7: triple LA curves with different end curvatures.
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    for key, c in sorted((k, v) for k, v in curves.items() if k[0] == "fig7"):
        line, = a.plot(c["x"], c["y"], label=key[1].replace("k0", "κ0 =").replace("k1", ", κ1 ="))
        joint_marks(a, c)
        b.plot(c["S"], c["kappa"], color=line.get_color())
    a.set_aspect("equal")
    a.set_title("triple LA curves, α = -0.5 (cf. 004 Fig. 7); dots: joints")
    a.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2)
    for S in (0.25, 0.75):
        b.axvline(S, color="0.8", lw=0.8, ls=":")
    b.axhline(0, color="0.7", lw=0.8)
    b.set_xlabel("normalized arc length S = s/h")
    b.set_ylabel("signed curvature κ")
    b.set_title("curvature profiles (cf. 004 Fig. 6): continuous at S1, S2")
    fig.tight_layout()
    fig.savefig(results / "figures" / "g2_figures_fig7.png", dpi=120)
    plt.close(fig)

    # Fig. 8: two triples joined G2.
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    offset = 0.0
    for key, c in sorted((k, v) for k, v in curves.items() if k[0] == "fig8"):
        a.plot(c["x"], c["y"], label=f"triple {key[2] + 1}: α = {c['alpha']:g}")
        joint_marks(a, c)
        b.plot(offset + c["s"], c["kappa"], label=f"α = {c['alpha']:g}")
        offset += c["s"][-1]
    a.plot([3], [1], "rs", ms=6, label="shared point, tangent, curvature")
    a.set_aspect("equal")
    a.set_title("two triple LA curves joined G2 (cf. 004 Fig. 8)")
    a.legend(fontsize=8, loc="upper center", bbox_to_anchor=(0.5, -0.1), ncol=2)
    b.axhline(0, color="0.7", lw=0.8)
    b.set_xlabel("arc length s along the joined curve")
    b.set_ylabel("signed curvature κ")
    b.set_title("curvature continuous at the junction")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(results / "figures" / "g2_figures_fig8.png", dpi=120)
    plt.close(fig)


if __name__ == "__main__":
    main()
