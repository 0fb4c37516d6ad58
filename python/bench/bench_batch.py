#!/usr/bin/env python3
"""Benchmark (not a test) of the Python module's overheads, printed as a Markdown table:

- lac.solve_batch of N G1 Hermite problems on 1 and more threads, against the same solves in a plain
  C++ loop on one thread (lac._lac._g1_loop_seconds: solve_g1_hermite in a for loop, nothing stored);
- the per-call cost of the scalar functions (lac.g1_hermite, lac.erf, Curve.eval of one point)
  against the C++ time the summary reports.

Usage: PYTHONPATH=build/python python3 python/bench/bench_batch.py [N] [repeats]
"""
import os
import sys
import time

import numpy as np

import lac
from lac import _lac


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    rng = np.random.default_rng(42)
    th0, th1 = rng.uniform(-2.5, 2.5, n), rng.uniform(-2.5, 2.5, n)
    zeros, ones = np.zeros(n), np.ones(n)
    data = {"p0": (0, 0), "p1": (1, 0), "theta0": th0, "theta1": th1, "alpha": -1.0}
    print(f"N = {n} G1 Hermite problems (alpha = -1, random end angles in [-2.5, 2.5]), best / median of {repeats}\n")
    # The C++ loop and the batch runs alternate, so that a change of machine load hits both alike.
    cores = os.cpu_count() or 1
    thread_counts = sorted({1, 2, cores})
    cpp, batch = [], {t: [] for t in thread_counts}
    for _ in range(repeats):
        cpp.append(_lac._g1_loop_seconds(zeros, zeros, th0, ones, zeros, th1, -1.0))
        for threads in thread_counts:
            a = time.perf_counter()
            lac.solve_batch("g1", data, threads=threads)
            batch[threads].append(time.perf_counter() - a)
    cpp = np.array(cpp)
    print("| what | threads | best s | median s | per problem us (best) | best / best C++ | median of run-wise ratios |")
    print("|---|---|---|---|---|---|---|")
    print(f"| C++ loop solve_g1_hermite | 1 | {cpp.min():.4f} | {np.median(cpp):.4f} | {1e6 * cpp.min() / n:.2f} | 1.00 | 1.00 |")
    for threads in thread_counts:
        b = np.array(batch[threads])
        print(f"| lac.solve_batch | {threads} | {b.min():.4f} | {np.median(b):.4f} | {1e6 * b.min() / n:.2f} | "
              f"{b.min() / cpp.min():.2f} | {np.median(b / cpp):.2f} |")

    print("\nPer-call overhead of the scalar functions (median of 2000 calls; C++ = the summary's seconds)\n")
    print("| call | Python us | C++ us | overhead us |")
    print("|---|---|---|---|")
    k = 2000
    t = []
    cxx = []
    for i in range(k):
        a = time.perf_counter()
        r = lac.g1_hermite(p0=(0, 0), theta0=th0[i], p1=(1, 0), theta1=th1[i], alpha=-1.0)
        t.append(time.perf_counter() - a)
        cxx.append(r.summary["seconds"])
    py_us, c_us = 1e6 * np.median(t), 1e6 * np.median(cxx)
    print(f"| lac.g1_hermite(...) | {py_us:.2f} | {c_us:.2f} | {py_us - c_us:.2f} |")
    t = []
    for i in range(k):
        a = time.perf_counter()
        lac.erf(0.3)
        t.append(time.perf_counter() - a)
    print(f"| lac.erf(0.3) (scalar) | {1e6 * np.median(t):.2f} | — | — |")
    x = np.linspace(-3, 3, 10**6)
    a = time.perf_counter()
    lac.erf(x)
    print(f"| lac.erf(array of 10^6), per element | {1e6 * (time.perf_counter() - a) / 1e6:.4f} | — | — |")
    c = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0).curve
    t = []
    for _ in range(k):
        a = time.perf_counter()
        c.eval(0.5)
        t.append(time.perf_counter() - a)
    print(f"| Curve.eval(0.5) (one point) | {1e6 * np.median(t):.2f} | — | — |")


if __name__ == "__main__":
    main()
