#!/usr/bin/env python3
"""Positions of quadratic LA curves (docs/math.md §4) over a sweep of parameters, at high precision.

Writes quadratic_positions.csv next to this file. Run: /usr/bin/python3 tests/reference/quadratic_positions.py

Sweep: alpha in {-3, -1, 0.5, 3}, gamma in {-0.3, 0.3}, lambda = 1 (8 curves), at u = log kappa in {-2, 2} where s(u) is representable and |theta(u)| <= 100; plus the points of the issue's reproducer
(alpha = -1.5, gamma = -0.3, lambda = 0.7 at s = -14.262385157871448), and three points of the long
oracle campaign (a kink where kappa collapses; a point 003's hybrid inverse got wrong; a point whose
Gauss-Legendre estimate was below its error).
Model as tests/reference/quadratic.py: u = log kappa, E(u) = gamma u^2 - alpha u,
s(u) = -F_alpha(u)/lambda, theta(u) = -F_(alpha-1)(u)/lambda, F_a(u) = int_0^u e^(gamma t^2 - a t) dt
in closed form (erfi / erfc at 40 digits); C(u) = -(1/lambda) int_0^u e^(i theta(t) + E(t)) dt by
mpmath.quad at 25 digits on two subdivisions (8 + 2|theta| and twice as many pieces) that must agree
to 1e-18 relative (points where they do not are left out).
Columns: alpha, gamma, lambda, s (the double the test evaluates at; for sweep rows s(u) rounded,
whose rounding moves C by at most |ds| <= 1.2e-16 |s|), x, y.
"""
import os

import mpmath
from mpmath import mp, mpf

mp.dps = 25
WORK = 40


def F(a, g, u):
    a, g, u = mpf(a), mpf(g), mpf(u)
    with mp.workdps(WORK):
        if g == 0:
            return u if a == 0 else -mp.expm1(-a * u) / a
        if g > 0:
            r = mp.sqrt(g)
            x0 = -a / (2 * r)
            x = x0 + r * u
            return mp.exp(-x0 * x0) / r * mp.sqrt(mp.pi) / 2 * (mp.erfi(x) - mp.erfi(x0))
        r = mp.sqrt(-g)
        y0 = a / (2 * r)
        y = y0 + r * u
        if y0 >= 0 and y >= 0:
            d = mp.erfc(y0) - mp.erfc(y)
        elif y0 <= 0 and y <= 0:
            d = mp.erfc(-y) - mp.erfc(-y0)
        else:
            d = mp.erf(y) - mp.erf(y0)
        return mp.exp(y0 * y0) / r * mp.sqrt(mp.pi) / 2 * d


def inverse_u(a, g, lam, s):
    target = -mpf(lam) * mpf(s)
    with mp.workdps(WORK):
        lo, hi = mpf(-1), mpf(1)
        while F(a, g, lo) > target:
            lo *= 2
        while F(a, g, hi) < target:
            hi *= 2
        for _ in range(200):
            mid = (lo + hi) / 2
            if F(a, g, mid) < target:
                lo = mid
            else:
                hi = mid
        return (lo + hi) / 2


def position(a, g, lam, u, turning):
    """C(u), or None when two subdivisions (n and 2n pieces, n growing with the turning) disagree."""
    f = lambda t: mp.exp(1j * (-F(a - 1, g, t) / lam) + g * t * t - a * t)
    n = 8 + int(2 * abs(turning))
    c1 = -mp.quad(f, mp.linspace(0, u, n + 1)) / lam
    c2 = -mp.quad(f, mp.linspace(0, u, 2 * n + 1)) / lam
    if not abs(c1 - c2) <= mpf(10) ** -18 * max(1, abs(c2)):
        return None
    return c2


def fmt(v):
    return mp.nstr(v, 20, min_fixed=0, max_fixed=0)


rows = []
for a in (-3, -1, 0.5, 3):
    for g in (-0.3, 0.3):
        for lam in (1,):
            for u in (-2, 2):
                s = -F(a, g, u) / lam
                th = -F(a - 1, g, u) / lam
                if not (mp.isfinite(s) and abs(s) < 1e300 and abs(th) <= 100):
                    continue
                c = position(a, g, lam, mpf(u), th)
                if c is None:
                    continue
                rows.append((a, g, lam, repr(float(s)), fmt(c.real), fmt(c.imag)))
print("sweep done: %d rows" % len(rows), flush=True)
for s in (-14.262385157871448, -7.0, -1.0):
    u = inverse_u(-1.5, -0.3, 0.7, s)
    c = position(-1.5, -0.3, 0.7, u, -F(-2.5, -0.3, u) / 0.7)
    rows.append((-1.5, -0.3, 0.7, repr(s), fmt(c.real), fmt(c.imag)))

# Long oracle campaign, seed 1 (docs/robustness.md O5, O6): problem 10591, where κ falls by e^212 within
# s < 1 and θ(s) levels off like a kink; problem 13494, wrong with 003's hybrid inverse of κ;
# problem 173630, where Gauss–Legendre's error estimate was below its error.
for a, g, lam, s in ((-4.7279451547264051, 0.022357074941171895, 0.26475191131312015, 9.311269018225218),
                     (4.4870616650235089, -0.20479128861518792, 0.73971898080129073, 7.5890931935710908),
                     (-3.4452652762090796, 0.4413428641506707, 1.3270049676310292, 6.145781829173643)):
    u = inverse_u(a, g, lam, s)
    c = position(a, g, lam, u, -F(a - 1, g, u) / lam)
    assert c is not None, (a, g, lam, s)
    rows.append((a, g, lam, repr(s), fmt(c.real), fmt(c.imag)))

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "quadratic_positions.csv")
with open(path, "w") as f:
    f.write("# Positions of quadratic LA curves, written by tests/reference/quadratic_positions.py with mpmath %s\n"
            % mpmath.__version__)
    f.write("# (closed forms at %d digits, mpmath.quad at %d digits; see its docstring)\n" % (WORK, mp.dps))
    f.write("alpha,gamma,lambda,s,x,y\n")
    for r in rows:
        f.write(",".join(str(float(v)) if isinstance(v, (int, float)) else v for v in r) + "\n")
print("wrote %d rows to %s" % (len(rows), path))
