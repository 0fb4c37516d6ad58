#!/usr/bin/env python3
"""Closed LA chains through eight points from results/chain_figures_points.csv (exp_chain_figures).

Usage: chain_figures.py RESULTS_DIR. Writes RESULTS_DIR/figures/chain_figures.png: one row per
continuity (G1, G2); left the two chains (alpha = -1 and -0.3) with their curvature combs (normals
scaled by the curvature, pointing away from the centre of curvature) and the eight points; right
the curvature against arc length, with the points marked.
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

POINTS = np.array([[0, 0], [2, -0.5], [4, 0.3], [5, 2], [4, 4], [2, 4.6], [0.2, 3.8], [-0.8, 2]])  # as in chain_figures.cpp


def load(path):
    chains = {}
    with open(path) as fh:
        rows = list(csv.reader(line for line in fh if not line.startswith("#")))
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    for r in rows:
        key = (r[idx["continuity"]], float(r[idx["alpha"]]))
        c = chains.setdefault(key, {k: [] for k in ("s", "x", "y", "theta", "kappa", "pair")})
        for k in c:
            c[k].append(float(r[idx[k]]))
    return {k: {n: np.array(v) for n, v in c.items()} for k, c in chains.items()}


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    chains = load(results / "chain_figures_points.csv")
    (results / "figures").mkdir(parents=True, exist_ok=True)
    fig, axes = plt.subplots(2, 2, figsize=(12, 10))
    for row, cont in enumerate(("g1", "g2")):
        a, b = axes[row]
        a.plot(POINTS[:, 0], POINTS[:, 1], "ko", ms=5, zorder=5, label="points")
        for (c_name, alpha), c in sorted(chains.items()):
            if c_name != cont:
                continue
            line, = a.plot(c["x"], c["y"], lw=1.6, label=f"α = {alpha:g}")
            # Comb: the normal (−sin θ, cos θ) points to the centre of curvature when κ > 0, so
            # −κ·normal points away from it; scaled to a readable length.
            scale = 0.6 / max(1e-12, np.max(np.abs(c["kappa"])))
            ex = c["x"] + scale * c["kappa"] * np.sin(c["theta"])
            ey = c["y"] - scale * c["kappa"] * np.cos(c["theta"])
            step = max(1, len(c["x"]) // 160)
            for i in range(0, len(c["x"]), step):
                a.plot([c["x"][i], ex[i]], [c["y"][i], ey[i]], color=line.get_color(), lw=0.4, alpha=0.6)
            a.plot(ex, ey, color=line.get_color(), lw=0.6, alpha=0.8)
            b.plot(c["s"], c["kappa"], color=line.get_color(), label=f"α = {alpha:g}")
            starts = [c["s"][i] for i in range(1, len(c["s"])) if c["pair"][i] != c["pair"][i - 1]]
            for s in starts:
                b.axvline(s, color="0.85", lw=0.8, ls=":")
        a.set_aspect("equal")
        a.set_title(f"closed {cont.upper()} LA chain through eight points, with curvature comb")
        a.legend(fontsize=8)
        b.axhline(0, color="0.7", lw=0.8)
        b.set_xlabel("arc length s from point 0 (dotted: the points)")
        b.set_ylabel("signed curvature κ")
        b.set_title("curvature: jumps at the points" if cont == "g1" else "curvature: continuous at the points")
        b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(results / "figures" / "chain_figures.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    main()
