#!/usr/bin/env python3
"""Before/after table of bench_quadratic from two committed Google Benchmark JSON files.

Usage: quadratic_bench.py RESULTS_DIR
Reads RESULTS_DIR/quadratic_bench_before.json and quadratic_bench_after.json (written by
build/bench_quadratic --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
--benchmark_out=FILE --benchmark_out_format=json) and writes RESULTS_DIR/quadratic_bench.md:
median CPU time per benchmark (CPU time varies less between runs than wall time).
"""
import json
import os
import sys

# The targets. κ(s) by 003's hybrid inverse (benchmark argument 1) is there for comparison only.
TARGETS = {"BM_KappaOfS": (200e-9, "≤ 200 ns"), "BM_HermitePolyline1000": (200e-6, "≤ 200 µs"),
           "BM_Polyline1000": (200e-6, "≤ 200 µs")}
SCALE = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def medians(path):
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"]
        out[name] = (b["cpu_time"] * SCALE[b["time_unit"]], b.get("label", ""))
    return out, data["context"].get("date", "?")


def show(seconds):
    for unit, scale in (("ns", 1e-9), ("µs", 1e-6), ("ms", 1e-3)):
        if seconds < 1000 * scale or unit == "ms":
            return "%.3g %s" % (seconds / scale, unit)


def machine_line(path):
    """The machine as the benchmark JSON records it (Google Benchmark's context names no CPU model
    or compiler: those are the ones scripts/setup.sh and scripts/build.sh give)."""
    with open(path) as f:
        c = json.load(f)["context"]
    caches = ", ".join("L%d%s %d KiB" % (x["level"], "d" if x["type"] == "Data" else ("i" if x["type"] == "Instruction" else ""),
                                         x["size"] // 1024) for x in c.get("caches", []))
    return ("Machine (from the JSON context): %s CPUs at %s MHz, caches %s. Build: Release (-O3 -DNDEBUG, as "
            "scripts/build.sh configures it) with the C++ compiler scripts/setup.sh installs (Debian's g++); the JSON "
            "does not record the CPU model." % (c.get("num_cpus", "?"), c.get("mhz_per_cpu", "?"), caches))


def main():
    results = sys.argv[1] if len(sys.argv) > 1 else "results"
    before_path = os.path.join(results, "quadratic_bench_before.json")
    after_path = os.path.join(results, "quadratic_bench_after.json")
    if not (os.path.exists(before_path) and os.path.exists(after_path)):
        print("quadratic_bench.py: no benchmark JSON in %s, nothing to do" % results)
        return
    machine = machine_line(after_path)
    before, date_before = medians(before_path)
    after, date_after = medians(after_path)
    lines = [
        "# bench_quadratic: median CPU time before and after the optimisations",
        "",
        "Written by `experiments/figures/quadratic_bench.py` from `quadratic_bench_before.json` (%s) and "
        "`quadratic_bench_after.json` (%s), each from `build/bench_quadratic --benchmark_repetitions=3 "
        "--benchmark_report_aggregates_only=true --benchmark_out=FILE --benchmark_out_format=json` "
        "(CPU time: it varies less between runs than the wall time)." % (date_before, date_after),
        "",
        machine,
        "",
        "| benchmark | what | CPU before | CPU after | after/before | target | met |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, (t_after, label) in after.items():
        t_before = before.get(name, (None, ""))[0]
        family = name.split("/")[0]
        target, target_text = TARGETS.get(family, (None, ""))
        if "hybrid-003" in label:
            target, target_text = None, "– (003's inverse, comparison)"
        met = "" if target is None else ("yes" if t_after <= target else "no")
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            name, label, show(t_before) if t_before else "–", show(t_after),
            "%.2f" % (t_after / t_before) if t_before else "–", target_text, met))
    path = os.path.join(results, "quadratic_bench.md")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("wrote " + path)


if __name__ == "__main__":
    main()
