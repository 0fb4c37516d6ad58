#!/usr/bin/env python3
"""Curvature and LCG of the certified B-spline exports from results/export_lcg_points.csv (exp_export_lcg).

Usage: export_lcg.py RESULTS_DIR. Writes RESULTS_DIR/figures/export_lcg.png: one row per curve; left
the curvature against arc length (LA curve and the quintic and cubic exports at tolerance 1e-3 of the
length), middle the curvature difference |kappa_b - kappa_LA| / max |kappa_LA| (log scale, all four
exports), right the logarithmic curvature graph log(rho ds/drho) against log rho (the LA curve's
straight lines, one per segment, and the exports' points).
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

STYLE = {  # (degree, tolerance) -> colour, label
    (5, 1e-3): ("#1f77b4", "quintic, 1e-3"),
    (5, 1e-6): ("#2ca02c", "quintic, 1e-6"),
    (3, 1e-3): ("#d62728", "cubic, 1e-3"),
    (3, 1e-6): ("#ff7f0e", "cubic, 1e-6"),
}


def num(text):
    return float(text) if text != "" else np.nan


def load(path):
    data = {}
    with open(path) as fh:
        rows = list(csv.reader(line for line in fh if not line.startswith("#")))
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    for r in rows:
        key = (r[idx["curve"]], int(r[idx["degree"]]), float(r[idx["tolerance"]]))
        c = data.setdefault(key, {k: [] for k in ("segment", "alpha", "s", "kappa", "kappa_la", "x_lcg", "y_lcg")})
        for k in c:
            c[k].append(num(r[idx[k]]))
    return {k: {n: np.array(v) for n, v in c.items()} for k, c in data.items()}


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    data = load(results / "export_lcg_points.csv")
    (results / "figures").mkdir(parents=True, exist_ok=True)
    curves = list(dict.fromkeys(k[0] for k in data))
    fig, axes = plt.subplots(len(curves), 3, figsize=(16, 4.2 * len(curves)), squeeze=False)
    for row, name in enumerate(curves):
        a, b, c = axes[row]
        la = data[(name, 0, 0.0)]
        a.plot(la["s"], la["kappa"], "k", lw=2.2, label="LA curve")
        for (deg, tol), (colour, label) in STYLE.items():
            d = data.get((name, deg, tol))
            if d is None:
                continue
            if tol == 1e-3:
                a.plot(d["s"], d["kappa"], ".", color=colour, ms=2.5, label="B-spline " + label)
            err = np.abs(d["kappa"] - d["kappa_la"]) / np.max(np.abs(la["kappa"]))
            b.semilogy(d["s"], np.maximum(err, 1e-17), ".", color=colour, ms=2.5, label=label)
            c.plot(d["x_lcg"], d["y_lcg"], ".", color=colour, ms=2.5, label=label)
        for seg in np.unique(la["segment"]):
            m = la["segment"] == seg
            c.plot(la["x_lcg"][m], la["y_lcg"][m], "k", lw=1.6, label="LA curve (slope α)" if seg == 0 else None)
        alphas = ", ".join(f"{v:g}" for v in np.unique(la["alpha"]))
        a.set_title(f"{name}: curvature (exports at 1e-3 × length)")
        a.set_xlabel("arc length s")
        a.set_ylabel("signed curvature κ")
        a.legend(fontsize=8)
        b.set_title(f"{name}: |κ_B-spline − κ_LA| / max |κ|")
        b.set_xlabel("arc length s")
        b.legend(fontsize=8)
        c.set_title(f"{name}: logarithmic curvature graph (α = {alphas})")
        c.set_xlabel("log ρ")
        c.set_ylabel("log(ρ ds/dρ)")
        ys = la["y_lcg"][np.isfinite(la["y_lcg"])]
        if ys.size:
            pad = 0.5 * (ys.max() - ys.min()) + 0.5
            c.set_ylim(ys.min() - pad, ys.max() + pad)  # the cubic's points near dκ/ds = 0 run far off
        c.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(results / "figures" / "export_lcg.png", dpi=100)
    plt.close(fig)


if __name__ == "__main__":
    main()
