#!/usr/bin/env python3
"""Compares two builds' Google Benchmark executables in one run: before/after medians and ratios.

Usage: scripts/bench_compare.py --before DIR --after DIR [--out results] [--name redesign] [--rounds 3]
                                [--repetitions 3] [--only bench_hermite,...]

For every benchmark executable named in GROUPS that exists in both folders, runs the before and the
after binary alternately (`--rounds` rounds, each `--repetitions` repetitions, the same filter) so
that both run under the same conditions, and collects the CPU time of every repetition. Writes
  <out>/<name>_bench_before.json, <out>/<name>_bench_after.json  (Google Benchmark's own JSON, all runs)
  <out>/<name>_bench.md, <out>/<name>_bench.csv  (per benchmark: median and spread of each, ratio)
Absolute times vary between runs: only the ratio of medians from one run is a claim, never a single time.
"""
import argparse
import json
import os
import platform
import statistics
import subprocess
import sys

# Executable -> benchmark filter (regex): the constructions and curve evaluations the library offers.
GROUPS = {
    "bench_hermite": "BM_G2_(newton|paper|ceres)_fast|BM_SCurve",
    "bench_planar_segments": ".",
    "bench_space": "random|fig5a",
    "bench_p002": "Segment|Frames|Polyline|Endpoint/(rk4_h=1e-3|gauss-kronrod_tol=1e-14|igf[^/]*)/alpha=(-1|2|0)/",
    "bench_quadratic": "Polyline|KappaOfS/./0",
}


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def run(exe, pattern, repetitions):
    cmd = [exe, f"--benchmark_filter={pattern}", f"--benchmark_repetitions={repetitions}",
           "--benchmark_format=json", "--benchmark_min_time=0.05"]
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--before", required=True)
    ap.add_argument("--after", required=True)
    ap.add_argument("--out", default="results")
    ap.add_argument("--name", default="redesign")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--repetitions", type=int, default=3)
    ap.add_argument("--only", default="")
    ap.add_argument("--before-label", default="before")
    ap.add_argument("--after-label", default="after")
    a = ap.parse_args()
    only = set(filter(None, a.only.split(",")))
    raw = {"before": [], "after": []}
    times = {}  # benchmark name -> {"before": [...], "after": [...]}
    order = []
    for exe, pattern in GROUPS.items():
        if only and exe not in only:
            continue
        paths = {k: os.path.join(getattr(a, k), exe) for k in ("before", "after")}
        if not all(os.access(p, os.X_OK) for p in paths.values()):
            print(f"bench_compare: {exe} missing in one folder, skipped", file=sys.stderr)
            continue
        for r in range(a.rounds):
            for side in (("before", "after") if r % 2 == 0 else ("after", "before")):
                print(f"bench_compare: {exe} round {r + 1}/{a.rounds} {side}", file=sys.stderr)
                doc = run(paths[side], pattern, a.repetitions)
                doc["executable"] = exe
                raw[side].append(doc)
                for b in doc["benchmarks"]:
                    if b.get("run_type") != "iteration":
                        continue
                    name = f"{exe}:{b['run_name']}"
                    if name not in times:
                        times[name] = {"before": [], "after": []}
                        order.append(name)
                    times[name][side].append(b["cpu_time"] * {"ns": 1e-3, "us": 1.0, "ms": 1e3, "s": 1e6}[b["time_unit"]])
    os.makedirs(a.out, exist_ok=True)
    for side in ("before", "after"):
        with open(os.path.join(a.out, f"{a.name}_bench_{side}.json"), "w") as f:
            json.dump(raw[side], f, indent=1)
    rows = []
    for name in order:
        t = times[name]
        if not t["before"] or not t["after"]:
            continue
        mb, ma = statistics.median(t["before"]), statistics.median(t["after"])
        rows.append((name, mb, min(t["before"]), max(t["before"]), ma, min(t["after"]), max(t["after"]), ma / mb))
    compiler = subprocess.run(["c++", "--version"], capture_output=True, text=True).stdout.splitlines()[0]
    header = ["benchmark", "before_median_us", "before_min_us", "before_max_us", "after_median_us", "after_min_us",
              "after_max_us", "ratio_after_before"]
    with open(os.path.join(a.out, f"{a.name}_bench.csv"), "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join([r[0]] + [f"{v:.4g}" for v in r[1:]]) + "\n")
    with open(os.path.join(a.out, f"{a.name}_bench.md"), "w") as f:
        f.write(f"# Benchmarks before and after: {a.before_label} vs {a.after_label}\n\n")
        f.write(f"Written by `scripts/bench_compare.py --name {a.name}`. CPU: {cpu_model()}; compiler: {compiler}; both builds "
                f"Release (-O3 -DNDEBUG, as scripts/build.sh configures them). The two builds ran alternately, {a.rounds} rounds of {a.repetitions} repetitions "
                "each: CPU time per call, median over all repetitions, min–max beside it; "
                "ratio = after median / before median (< 1: faster).\n\n")
        f.write("| benchmark | before µs (min–max) | after µs (min–max) | ratio |\n|---|---|---|---|\n")
        for r in rows:
            f.write(f"| `{r[0]}` | {r[1]:.4g} ({r[2]:.4g}–{r[3]:.4g}) | {r[4]:.4g} ({r[5]:.4g}–{r[6]:.4g}) | {r[7]:.3f} |\n")
        if rows:
            worst = max(rows, key=lambda r: r[7])
            f.write(f"\nLargest ratio: {worst[7]:.3f} (`{worst[0]}`); median ratio "
                    f"{statistics.median(r[7] for r in rows):.3f} over {len(rows)} benchmarks.\n")
    print(f"bench_compare: wrote {a.out}/{a.name}_bench.{{md,csv}} and the raw JSON", file=sys.stderr)


if __name__ == "__main__":
    main()
