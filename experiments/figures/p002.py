#!/usr/bin/env python3
"""Figures for the paper-002 reproduction (docs/p002.md), from the tables the experiments wrote.

Usage: /usr/bin/python3 experiments/figures/p002.py RESULTS_DIR
  p002_truncation.png  error vs h, log-log, one panel per (alpha, Lambda) of 002 Appendix B:
                       the paper's RK4 and G-K cells beside ours (several readings) and our G-K;
  p002_timing.png      time per method and row of 002 Appendix A: ours (endpoint and polyline,
                       median with p10-p90 bars) and the paper's seconds.
Reads p002_appendix_b_candidates.csv, p002_appendix_b.csv, p002_appendix_a_raw.csv and
experiments/data/p002_appendix_a.csv (the paper's typed seconds).
"""
import csv
import pathlib
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]


def read_csv(path):
    with open(path) as fh:
        return list(csv.DictReader(line for line in fh if not line.startswith("#")))


def num(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


READINGS = [  # key in p002_appendix_b_candidates.csv, label, style
    ("theta-form/h-in-theta", "ours: classical RK4, theta-form, h in theta", dict(color="C0", marker="o")),
    ("theta-form/3/8-rule", "ours: 3/8-rule RK4, theta-form", dict(color="C2", marker="^", ls=":")),
    ("s-form/h-in-s", "ours: classical RK4, s-form (Eq. 12), h in s", dict(color="C1", marker="s", ls="--")),
]


def truncation_figure(results, out):
    cand = read_csv(results / "p002_appendix_b_candidates.csv")
    main = read_csv(results / "p002_appendix_b.csv")
    alphas = ["2", "4/3", "10/9"]
    lambdas = ["1", "10", "100"]
    fig, axes = plt.subplots(3, 3, figsize=(12, 10.5), sharex=True)
    for i, a in enumerate(alphas):
        for j, lam in enumerate(lambdas):
            ax = axes[i][j]
            rows = [r for r in cand if r["alpha"] == a and r["lambda"] == lam]
            paper = sorted({(num(r["h"]), num(r["paper_error"])) for r in rows})
            hs = [p[0] for p in paper]
            ax.loglog(hs, [p[1] for p in paper], "k-", marker="x", ms=8, lw=2, label="002 Appendix B, RK4")
            for key, label, style in READINGS:
                pts = sorted((num(r["h"]), num(r["abs_c_error"])) for r in rows if r["reading"] == key and r["abs_c_error"])
                if pts:
                    ax.loglog([p[0] for p in pts], [p[1] for p in pts], label=label, **style)
            gk = [r for r in main if r["alpha"] == a and r["Lambda"] == lam and not r["method"].startswith("rk4")]
            if gk:
                ax.axhline(num(gk[0]["paper error"]), color="k", ls="-.", lw=1, label="002 G-K")
                ours_gk = num(gk[0]["ours abs(dC)"])
                if ours_gk > 0:
                    ax.axhline(ours_gk, color="C3", ls="-.", lw=1, label="ours G-K")
                abs_c = num(gk[0]["abs(C)"])
                ax.axhline(2.2e-16 * abs_c, color="0.6", ls=":", lw=1, label="eps |C|")
            if hs:
                h0, e0 = hs[-1], paper[-1][1]
                ax.loglog(hs, [e0 * (h / h0) ** 4 for h in hs], color="0.7", lw=4, alpha=0.4, label="slope 4")
            ax.set_title(f"alpha = {a}, Lambda = {lam}", fontsize=10)
            ax.grid(True, which="major", alpha=0.3)
            if i == 2:
                ax.set_xlabel("step h")
            if j == 0:
                ax.set_ylabel("|C_h - C_ref| at theta = 1")
    handles, labels = [], []
    for row in axes:
        for ax in row:
            for h, lab in zip(*ax.get_legend_handles_labels()):
                if lab not in labels:
                    handles.append(h)
                    labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=9, frameon=False)
    fig.suptitle("002 Appendix B: error vs step size, paper (black) and ours against a 40-digit reference", fontsize=12)
    fig.tight_layout(rect=(0, 0.07, 1, 0.97))
    fig.savefig(out / "p002_truncation.png", dpi=110)
    plt.close(fig)


def timing_figure(results, out):
    raw = read_csv(results / "p002_appendix_a_raw.csv")
    paper = read_csv(ROOT / "experiments" / "data" / "p002_appendix_a.csv")
    row_keys = []
    for r in raw:
        k = (r["alpha"], r["lambda"])
        if k not in row_keys:
            row_keys.append(k)
    methods = []
    for r in raw:
        if r["method"] not in methods:
            methods.append(r["method"])
    x = list(range(len(row_keys)))
    fig, axes = plt.subplots(3, 1, figsize=(14, 12), sharex=True)
    for ax, kind in ((axes[0], "endpoint"), (axes[1], "polyline")):
        for k, m in enumerate(methods):
            pts = {(r["alpha"], r["lambda"]): r for r in raw if r["method"] == m and r["kind"] == kind}
            med = [num(pts[key]["median_s"]) * 1e6 if key in pts else float("nan") for key in row_keys]
            lo = [num(pts[key]["p10_s"]) * 1e6 if key in pts else float("nan") for key in row_keys]
            hi = [num(pts[key]["p90_s"]) * 1e6 if key in pts else float("nan") for key in row_keys]
            off = (k - (len(methods) - 1) / 2) * 0.13
            yerr = [[max(mv - lv, 0) for mv, lv in zip(med, lo)], [max(hv - mv, 0) for mv, hv in zip(med, hi)]]
            ax.errorbar([xi + off for xi in x], med, yerr=yerr, fmt="o", ms=4, capsize=2, label=m, color=f"C{k}")
        ax.set_yscale("log")
        ax.set_ylabel("microseconds per call")
        ax.grid(True, which="major", axis="y", alpha=0.3)
        ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.005, 1.0))
    axes[0].set_title("ours: endpoint C(theta = 1), median with p10-p90 (wall time; varies between runs)", fontsize=10)
    axes[1].set_title("ours: polyline of the segment (theta from 0 to 1), median with p10-p90", fontsize=10)
    cols = [("rk4_seconds", "RK4 h = 0.001"), ("igf_seconds", "IGF"), ("gk_seconds", "Gauss-Kronrod")]
    by_key = {(p["alpha_text"], p["lambda"]): p for p in paper}
    for k, (col, label) in enumerate(cols):
        axes[2].plot(x, [num(by_key[key][col]) if key in by_key else float("nan") for key in row_keys], "s-",
                     label=label, color=f"C{k + 5}")
    axes[2].set_yscale("log")
    axes[2].set_ylabel("seconds per segment")
    axes[2].set_title("002 Appendix A: the paper's seconds (Mathematica 8, Pentium D 2.8 GHz)", fontsize=10)
    axes[2].grid(True, which="major", axis="y", alpha=0.3)
    axes[2].legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.005, 1.0))
    axes[2].set_xticks(x)
    axes[2].set_xticklabels([f"{a}\n{lam}" for a, lam in row_keys], fontsize=8)
    axes[2].set_xlabel("alpha / Lambda (002 Appendix A rows)")
    fig.tight_layout()
    fig.savefig(out / "p002_timing.png", dpi=100)
    plt.close(fig)


def main():
    results = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "results")
    out = results / "figures"
    out.mkdir(parents=True, exist_ok=True)
    truncation_figure(results, out)
    timing_figure(results, out)
    print(f"wrote {out / 'p002_truncation.png'} and {out / 'p002_timing.png'}")


if __name__ == "__main__":
    main()
