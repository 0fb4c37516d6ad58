#!/usr/bin/env python3
"""Reference values of the quadratic LA curve (docs/math.md §4) at high precision.

Writes quadratic.csv next to this file. Run: /usr/bin/python3 tests/reference/quadratic.py

Model: u = log κ, E(u) = γu² − αu, s(u) = −F_α(u)/Λ, θ(u) = −F_(α−1)(u)/Λ with
F_a(u) = ∫₀^u e^(γt² − a t) dt. F is evaluated in closed form with mpmath at 120 working
digits (erfi for γ > 0; erfc / erf differences for γ < 0, chosen so that nothing cancels at
that precision) and cross-checked against mpmath.quad where the integrand is moderate.

Columns: alpha, gamma, lambda, kind, x, v1, v2
  kind = bounds   x = 0,  v1 = s(κ→∞), v2 = s(κ→0)   (±inf where unbounded or beyond double)
  kind = forward  x = u (a double), v1 = s(u), v2 = θ(u)
  kind = inverse  x = s (a double), v1 = u(s) solving s(u) = x exactly, v2 = θ at that u
  kind = position x = s (a double), v1, v2 = x, y of C(s) = ∫₀^s e^(iθ) ds, integrated in u:
                  C = −(1/Λ) ∫₀^u(s) e^(iθ(t) + E(t)) dt (mpmath.quad at 40 digits, two
                  subdivisions that must agree to 1e-30)
Numbers: inputs printed with 17 significant digits (exact doubles), outputs with 20 digits.
"""
import os

import mpmath
from mpmath import mp, mpf

mp.dps = 40
WORK = 120

# (alpha, gamma, lambda): 003 Figs. 3–9 sets, then scaled-form stress cases
PARAMS = [
    (-1, -0.5, 1), (-1, 0.5, 1), (-1, -1, 1), (0, -1, 1), (3, -1, 1), (0, -0.5, 1), (0, 0.5, 1),
    (1, -0.5, 1), (1, 1, 1), (-0.2, -0.5, 0.5), (-0.2, -0.5, 1), (-0.2, -0.5, 2), (1, -30, 0.5), (1, 30, 0.5),
    (-1, -0.1, 1), (-1, 0.1, 1),
    (2, 1e-6, 1), (2, -1e-6, 1), (-1, 1e-8, 1), (1e-3, 1e-6, 1), (1e-3, -1e-6, 1),
    (40, -1, 1), (60, -1, 1), (-60, -1, 1), (-100, 1, 1), (100, 1, 1), (0.5, 2, 1e-3), (0.5, 2, 1e3),
    (5, -0.01, 1), (-5, 0.01, 1),
]
US = [-700, -300, -100, -30, -10, -3, -1, -0.25, -1e-3, -1e-9, 1e-9, 1e-3, 0.25, 1, 3, 10, 30, 100, 300, 700]


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


def F_limits(a, g):
    a, g = mpf(a), mpf(g)
    with mp.workdps(WORK):
        if g > 0:
            return mp.inf, -mp.inf
        if g == 0:
            return (1 / a if a > 0 else mp.inf), (1 / a if a < 0 else -mp.inf)
        r = mp.sqrt(-g)
        y0 = a / (2 * r)
        c = mp.sqrt(mp.pi) / (2 * r)
        return c * mp.exp(y0 * y0) * mp.erfc(y0), -c * mp.exp(y0 * y0) * mp.erfc(-y0)


def check_against_quad(a, g, u):
    E = lambda t: g * t * t - a * t
    if abs(u) > 50 or max(abs(E(u)), abs(E(u / 2))) > 200:
        return
    with mp.workdps(60):
        q = mp.quad(lambda t: mp.exp(g * t * t - a * t), mp.linspace(0, u, 9))
    closed = F(a, g, u)
    assert abs(q - closed) <= mpf(10) ** (-28) * abs(closed), (a, g, u, q, closed)


def representable(v):
    return mp.isfinite(v) and abs(v) < mpf("1e300")


def inverse_u(a, g, lam, s):
    """u with F_a(u) = −Λ s, by bisection then Newton at WORK digits."""
    target = -mpf(lam) * mpf(s)
    with mp.workdps(WORK):
        fp, fm = F_limits(a, g)
        if not (fm < target < fp):
            return None  # the rounded s left the domain
        lo, hi = mpf(-1), mpf(1)
        while F(a, g, lo) > target:
            lo *= 2
            if lo < -4096:
                return None
        while F(a, g, hi) < target:
            hi *= 2
            if hi > 4096:
                return None
        for _ in range(60):
            mid = (lo + hi) / 2
            if F(a, g, mid) < target:
                lo = mid
            else:
                hi = mid
        u = (lo + hi) / 2
        for _ in range(20):
            step = (F(a, g, u) - target) / mp.exp(g * u * u - a * u)
            u -= step
            if abs(step) < mpf(10) ** (-(WORK - 20)) * max(1, abs(u)):
                break
        assert abs(F(a, g, u) - target) <= mpf(10) ** (-60) * max(1, abs(target)) * mp.exp(g * u * u - a * u) + mpf(10) ** (-100)
        return u


def fmt(v):
    if v == mp.inf or (mp.isfinite(v) and v > mpf("1.7976931348623157e308")):
        return "inf"
    if v == -mp.inf or (mp.isfinite(v) and v < -mpf("1.7976931348623157e308")):
        return "-inf"
    return mp.nstr(v, 20, min_fixed=0, max_fixed=0)


rows = []
for (a, g, lam) in PARAMS:
    a, g, lam = float(a), float(g), float(lam)
    fp, fm = F_limits(a, g)
    rows.append((a, g, lam, "bounds", "0", fmt(-fp / lam), fmt(-fm / lam)))
    for u in US:
        s = -F(a, g, u) / lam
        th = -F(a - 1, g, u) / lam
        if not (representable(s) and representable(th)):
            continue
        check_against_quad(a, g, u)
        rows.append((a, g, lam, "forward", repr(float(u)), fmt(s), fmt(th)))
        sd = float(s)
        # skip s = 0 and s within a few ulps of a finite bound (the open end in double)
        near_bound = any(mp.isfinite(b) and abs(mpf(sd) - b) <= 8 * mpf(2) ** -52 * abs(b) for b in (-fp / lam, -fm / lam))
        if sd == 0.0 or near_bound:
            continue
        ui = inverse_u(a, g, lam, sd)
        if ui is None or abs(ui) > 740:  # κ not representable
            continue
        rows.append((a, g, lam, "inverse", repr(sd), fmt(ui), fmt(-F(a - 1, g, ui) / lam)))

# Positions: for the sets of tests/quadratic's hermite_polyline test, three s per set (near the
# ends of the domain used there, and one inside), printed as short decimals so that the test
# can make them exact end points of a polyline.
POSITION_SETS = [(-1, -0.5, 1), (1, 1, 1), (3, -1, 1), (1, -30, 0.5), (0, 0, 1), (-1, 0.5, 1)]


def position(a, g, lam, s):
    u = inverse_u(a, g, lam, s)
    with mp.workdps(40):
        f = lambda t: mp.exp(1j * (-F(a - 1, g, t) / lam) + g * t * t - a * t)
        c1 = -mp.quad(f, mp.linspace(0, u, 9)) / lam
        c2 = -mp.quad(f, mp.linspace(0, u, 17)) / lam
        assert abs(c1 - c2) <= mpf(10) ** -30 * max(1, abs(c2)), (a, g, lam, s, c1, c2)
        return c2


for (a, g, lam) in POSITION_SETS:
    a, g, lam = float(a), float(g), float(lam)
    fp, fm = F_limits(a, g)
    lo = -fp / lam if mp.isfinite(fp) else mpf(-3)
    hi = -fm / lam if mp.isfinite(fm) else mpf(3)
    for s in (0.99 * lo, 0.3 * lo + 0.7 * hi, 0.99 * hi):
        sd = float(mp.nstr(s, 4))
        c = position(a, g, lam, sd)
        rows.append((a, g, lam, "position", repr(sd), fmt(c.real), fmt(c.imag)))

path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "quadratic.csv")
with open(path, "w") as f:
    f.write("# Reference values for curves/quadratic (tests/quadratic). Generated by\n")
    f.write("# tests/reference/quadratic.py with mpmath %s (closed forms at %d digits, checked against\n" % (mpmath.__version__, WORK))
    f.write("# mpmath.quad); see its docstring for the columns.\n")
    f.write("alpha,gamma,lambda,kind,x,v1,v2\n")
    for r in rows:
        f.write(",".join(repr(v) if isinstance(v, float) else v for v in r) + "\n")
print("wrote %d rows to %s" % (len(rows), path))
