#!/usr/bin/env python3
"""Plots for 000 Figs. 5-7 from results/space_figures_points.csv (written by exp_space_figures).

Usage: space_figures.py RESULTS_DIR. Writes RESULTS_DIR/figures/space_figures_type1.png (Fig. 5 sets),
space_figures_type2.png (Fig. 6 sets) and space_rtheta.png (Fig. 7 sweep). Each curve: top view (x, y),
side view (x, z) with the joint marked, and curvature / torsion along s (user units).
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

CAPTIONS = {
    "5a": "α0=-1, α1=1, β0=-1, β1=1, Ω0=0.1",
    "5b": "α0=0, α1=-1, β0=2, β1=1, Ω0=0.1",
    "5c": "α0=-1, α1=1, β0=2, β1=-1, Ω0=0.6",
    "6a": "α0=1, α1=0, β0=0, β1=1, Ω0=0.3",
    "6b": "α0=1, α1=-1, β0=1, β1=-2, Ω0=0.3",
    "6c": "α0=-1, α1=1, β0=-1, β1=2, Ω0=0.15",
}


def load(path):
    curves = {}
    with open(path) as fh:
        rows = [r for r in csv.reader(line for line in fh if not line.startswith("#"))]
    header, rows = rows[0], rows[1:]
    idx = {name: i for i, name in enumerate(header)}
    for r in rows:
        key = (r[idx["figure"]], float(r[idx["r_theta"]]))
        c = curves.setdefault(key, {k: [] for k in header})
        for k in header:
            c[k].append(r[idx[k]] if k == "figure" else float(r[idx[k]]))
    return curves


def draw_curve(axes, c, title):
    ax_xy, ax_xz, ax_k = axes
    for piece, style in ((0, "-"), (1, "-")):
        sel = [i for i, p in enumerate(c["piece"]) if p == piece]
        color = "tab:blue" if piece == 0 else "tab:orange"
        x = [c["x"][i] for i in sel]
        y = [c["y"][i] for i in sel]
        z = [c["z"][i] for i in sel]
        ax_xy.plot(x, y, style, color=color, lw=1.8, label=f"segment {piece}")
        ax_xz.plot(x, z, style, color=color, lw=1.8)
    joint = [i for i in range(1, len(c["piece"])) if c["piece"][i] != c["piece"][i - 1]]
    for ax, comp in ((ax_xy, "y"), (ax_xz, "z")):
        ax.plot([c["x"][0], c["x"][-1]], [c[comp][0], c[comp][-1]], "ko", ms=4)
        if joint:
            ax.plot([c["x"][joint[0]]], [c[comp][joint[0]]], "rs", ms=5, label="joint" if comp == "y" else None)
        ax.set_aspect("equal", adjustable="datalim")
        ax.grid(alpha=0.3)
        ax.set_xlabel("x")
        ax.set_ylabel(comp)
    ax_xy.set_title(title + ": top (x, y)", fontsize=9)
    ax_xz.set_title("side (x, z)", fontsize=9)
    ax_k.plot(c["s"], c["kappa"], color="tab:green", label="curvature κ")
    ax_k.plot(c["s"], c["tau"], color="tab:purple", label="torsion τ")
    if joint:
        ax_k.axvline(c["s"][joint[0]], color="r", lw=0.8, ls="--", label="joint")
    ax_k.set_xlabel("s")
    ax_k.set_title("κ and τ along s", fontsize=9)
    ax_k.grid(alpha=0.3)


def figure_sets(curves, names, out, suptitle):
    fig, axes = plt.subplots(len(names), 3, figsize=(13, 3.4 * len(names)))
    for row, name in enumerate(names):
        keys = [k for k in curves if k[0] == name]
        if not keys:
            for ax in axes[row]:
                ax.text(0.5, 0.5, f"{name}: not solved", ha="center")
            continue
        draw_curve(axes[row], curves[keys[0]], f"({name}) {CAPTIONS[name]}")
    axes[0][0].legend(fontsize=8)
    axes[0][2].legend(fontsize=8)
    fig.suptitle(suptitle)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def figure_rtheta(curves, out):
    keys = sorted(k for k in curves if k[0] == "7")
    if not keys:
        return
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    cmap = plt.get_cmap("viridis")
    for j, key in enumerate(keys):
        c = curves[key]
        color = cmap(j / max(1, len(keys) - 1))
        joint = [i for i in range(1, len(c["piece"])) if c["piece"][i] != c["piece"][i - 1]]
        axes[0].plot(c["x"], c["y"], color=color, lw=1.2)
        axes[1].plot(c["x"], c["z"], color=color, lw=1.2)
        axes[2].plot(c["s"], c["kappa"], color=color, lw=1.2, label=f"r_θ = {key[1]:g}")
        if joint:
            axes[0].plot(c["x"][joint[0]], c["y"][joint[0]], "s", color=color, ms=5)
            axes[1].plot(c["x"][joint[0]], c["z"][joint[0]], "s", color=color, ms=5)
    for ax, lab in ((axes[0], "y"), (axes[1], "z")):
        ax.set_xlabel("x")
        ax.set_ylabel(lab)
        ax.grid(alpha=0.3)
    axes[0].set_title("top (x, y); squares: joints", fontsize=9)
    axes[1].set_title("side (x, z)", fontsize=9)
    axes[2].set_title("curvature κ along s", fontsize=9)
    axes[2].set_xlabel("s")
    axes[2].legend(fontsize=7)
    axes[2].grid(alpha=0.3)
    fig.suptitle("000 Fig. 7: r_θ moves the joint (parameter set of Fig. 5a, same endpoints)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    src = results / "space_figures_points.csv"
    if not src.exists():
        print(f"{src} missing: run build/exp_space_figures first", file=sys.stderr)
        return 1
    curves = load(src)
    figs = results / "figures"
    figs.mkdir(parents=True, exist_ok=True)
    figure_sets(curves, ["5a", "5b", "5c"], figs / "space_figures_type1.png",
                "000 Fig. 5: compound-rhythm LA space curves, type 1 (ρ and μ increasing)")
    figure_sets(curves, ["6a", "6b", "6c"], figs / "space_figures_type2.png",
                "000 Fig. 6: compound-rhythm LA space curves, type 2 (ρ increasing, μ decreasing)")
    figure_rtheta(curves, figs / "space_rtheta.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
