#!/usr/bin/env python3
"""Peano-kernel constants of the cubic Hermite interpolant on [0, 1] used by export/to_bspline.cpp:
C_m = max_t int_0^1 |K_m(t, tau)| dtau, where f(t) - (Hf)(t) = int K_m(t, tau) f^(m)(tau) dtau.
Prints C_2 (< 1/16), C_3 (= 1/96) and C_4 (= 1/384) with mpmath."""
from math import factorial
from mpmath import mp, mpf, quad

mp.dps = 30


def hermite(f0, d0, f1, d1, t):
    return f0 * (2*t**3 - 3*t**2 + 1) + d0 * (t**3 - 2*t**2 + t) + f1 * (3*t**2 - 2*t**3) + d1 * (t**3 - t**2)


def kernel(m, t, tau):
    # f_tau(x) = (x - tau)_+^(m-1) / (m-1)!: f(0) = f'(0) = 0 for tau > 0.
    f = lambda x: max(x - tau, 0)**(m - 1) / factorial(m - 1)
    d1 = (1 - tau)**(m - 2) / factorial(m - 2)
    return f(t) - hermite(0, 0, f(1), d1, t)


for m in (2, 3, 4):
    best = max(quad(lambda tau: abs(kernel(m, mpf(i) / 2000, tau)), [0, mpf(i) / 2000, 1]) for i in range(1, 2000))
    print(m, best)
