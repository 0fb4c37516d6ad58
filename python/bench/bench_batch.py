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


def best(f, repeats):
    t = []
    for _ in range(repeats):
        a = time.perf_counter()
        f()
        t.append(time.perf_counter() - a)
    return min(t), float(np.median(t))


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    repeats = int(sys.argv[2]) if len(sys.argv) > 2 else 5
    rng = np.random.default_rng(42)
    th0, th1 = rng.uniform(-2.5, 2.5, n), rng.uniform(-2.5, 2.5, n)
    zeros, ones = np.zeros(n), np.ones(n)
    data = {"p0": (0, 0), "p1": (1, 0), "theta0": th0, "theta1": th1, "alpha": -1.0}
    print(f"N = {n} G1 Hermite problems (alpha = -1, random end angles in [-2.5, 2.5]), best / median of {repeats}\n")
    print("| what | threads | best s | median s | per problem us | ratio to C++ loop |")
    print("|---|---|---|---|---|---|")
    cpp = best(lambda: _lac._g1_loop_seconds(zeros, zeros, th0, ones, zeros, th1, -1.0), repeats)
    print(f"| C++ loop solve_g1_hermite | 1 | {cpp[0]:.4f} | {cpp[1]:.4f} | {1e6 * cpp[0] / n:.2f} | 1.00 |")
    cores = os.cpu_count() or 1
    for threads in sorted({1, 2, cores}):
        b = best(lambda: lac.solve_batch("g1", data, threads=threads), repeats)
        print(f"| lac.solve_batch | {threads} | {b[0]:.4f} | {b[1]:.4f} | {1e6 * b[0] / n:.2f} | {b[0] / cpp[0]:.2f} |")

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
