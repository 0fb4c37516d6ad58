#!/usr/bin/env python3
"""Reference positions of standard-form planar LA curves (docs/math.md §1) at 40 digits.

Writes la_reference.csv next to this file. Run: /usr/bin/python3 tests/reference/la_reference.py

For each (alpha, lambda, theta) the position C(theta) = ∫_0^theta rho(psi) e^{i psi} dpsi is
computed by mpmath tanh-sinh quadrature at mp.dps = 40, on sub-intervals where theta moves by
at most 0.5 rad and log(rho) by at most 0.5 (so steep growth toward an open end of the
domain is resolved). It is cross-checked against an independent evaluation: the closed form
through the incomplete gamma function (mpmath.gammainc, docs/math.md §1.1) for alpha != 1, the
elementary form for alpha = 1, and the s-form quadrature ∫_0^s e^{i theta(u)} du where the
order a = alpha/(alpha-1) exceeds 12 in magnitude (alpha near 1, where mpmath.gammainc is very
slow); column `crosscheck` is |C_quad - C_other| / |C_quad|.
s and rho come from the closed forms of docs/math.md §1 at the same precision.

Cases: alpha from -100 to 100 (0 and 1 included, near 1 from both sides), lambda from 1e-3
to 100, theta at 0.95 and 0.5 of the finite bound of the theta domain (capped at |theta| <= 30
rad, about five turns), negative theta, theta = 1 and small theta (1e-3, 1e-6); cases where
|log rho| > 200 are left out (near 0.95 of the bound for alpha = 0.99 and 1.01 at large lambda).
"""
import csv
import multiprocessing
import pathlib

import mpmath as mp

mp.mp.dps = 40

ALPHAS = ["-100", "-10", "-3", "-1", "-0.5", "0", "0.25", "0.5", "0.9", "0.99", "1", "1.01",
          "1.1", "4/3", "1.5", "2", "3", "10", "100"]
LAMBDAS = ["0.001", "0.1", "1", "10", "100"]
THETA_CAP = mp.mpf(30)


def frac(text):
    if "/" in text:
        n, d = text.split("/")
        return mp.mpf(n) / mp.mpf(d)
    return mp.mpf(text)


def log_rho(alpha, lam, theta):
    if alpha == 1:
        return lam * theta
    return mp.log1p((alpha - 1) * lam * theta) / (alpha - 1)


def s_of(alpha, lam, theta):
    L = log_rho(alpha, lam, theta)
    if alpha == 0:
        return L / lam
    return mp.expm1(alpha * L) / (alpha * lam)


def theta_of_log_rho(alpha, lam, L):
    if alpha == 1:
        return L / lam
    return mp.expm1((alpha - 1) * L) / ((alpha - 1) * lam)


def theta_domain(alpha, lam):
    if alpha == 1:
        return (-mp.inf, mp.inf)
    if alpha < 1:
        return (-mp.inf, 1 / ((1 - alpha) * lam))
    return (-1 / ((alpha - 1) * lam), mp.inf)


def breakpoints(alpha, lam, theta):
    """0 = t0, ..., tn = theta with |dt| <= 0.5 and |d log rho| <= 0.5."""
    pts = [mp.mpf(0)]
    L_end = log_rho(alpha, lam, theta)
    nL = int(mp.ceil(abs(L_end) / mp.mpf("0.5")))
    for j in range(1, nL):
        pts.append(theta_of_log_rho(alpha, lam, L_end * j / nL))
    pts.append(theta)
    dense = []
    for a, b in zip(pts[:-1], pts[1:]):
        n = max(1, int(mp.ceil(abs(b - a) / mp.mpf("0.5"))))
        dense += [a + (b - a) * j / n for j in range(n)]
    return dense + [theta]


def position_quad(alpha, lam, theta):
    f = lambda psi: mp.exp(log_rho(alpha, lam, psi)) * mp.expj(psi)
    return mp.quad(f, breakpoints(alpha, lam, theta))


def position_closed(alpha, lam, theta):
    if alpha == 1:
        return (mp.exp((lam + 1j) * theta) - 1) / (lam + 1j)
    k = (alpha - 1) * lam
    a = alpha / (alpha - 1)
    U = 1 + k * theta
    z0 = -1j / k
    z1 = -1j * U / k
    return mp.exp(-1j / k) / k * mp.power(1j * k, a) * (mp.gammainc(a, z0) - mp.gammainc(a, z1))


def theta_of_s(alpha, lam, s):
    if alpha == 0:
        L = lam * s
    else:
        L = mp.log1p(alpha * lam * s) / alpha
    return theta_of_log_rho(alpha, lam, L)


def position_s_form(alpha, lam, theta):
    s_end = s_of(alpha, lam, theta)
    pts = [s_of(alpha, lam, t) for t in breakpoints(alpha, lam, theta)]
    return mp.quad(lambda u: mp.expj(theta_of_s(alpha, lam, u)), pts)


def position_check(alpha, lam, theta):
    if alpha != 1 and abs(alpha / (alpha - 1)) > 12:
        return position_s_form(alpha, lam, theta)
    return position_closed(alpha, lam, theta)


def cases():
    for at in ALPHAS:
        alpha = frac(at)
        for lt in LAMBDAS:
            lam = mp.mpf(lt)
            lo, hi = theta_domain(alpha, lam)
            thetas = [mp.mpf("1e-6"), mp.mpf("1e-3"), mp.mpf(1)]
            if mp.isfinite(hi):
                thetas += [min(mp.mpf("0.95") * hi, THETA_CAP), min(mp.mpf("0.5") * hi, THETA_CAP)]
            else:
                thetas += [mp.mpf(5)]
            if mp.isfinite(lo):
                thetas += [max(mp.mpf("0.95") * lo, -THETA_CAP), max(mp.mpf("0.5") * lo, -THETA_CAP)]
            else:
                thetas += [mp.mpf(-1), mp.mpf(-5)]
            seen = set()
            for th in thetas:
                key = mp.nstr(th, 15)
                if key in seen or not (lo < th < hi):
                    continue
                seen.add(key)
                # Keep rho representable in double with margin.
                if abs(log_rho(alpha, lam, th)) > 200:
                    continue
                yield at, alpha, lt, lam, th


def row(case):
    at, alpha, lt, lam, th = case
    c = position_quad(alpha, lam, th)
    other = position_check(alpha, lam, th)
    cross = abs(c - other) / abs(c)
    print(f"alpha={at} lambda={lt} theta={mp.nstr(th, 6)} crosscheck={mp.nstr(cross, 3)}", flush=True)
    return [mp.nstr(alpha, 25), lt, mp.nstr(th, 25), mp.nstr(s_of(alpha, lam, th), 25),
            mp.nstr(mp.exp(log_rho(alpha, lam, th)), 25), mp.nstr(c.real, 25), mp.nstr(c.imag, 25),
            mp.nstr(abs(c), 25), mp.nstr(cross, 3)]


def main():
    out = pathlib.Path(__file__).with_name("la_reference.csv")
    with multiprocessing.Pool(2) as pool:
        rows = pool.map(row, list(cases()), chunksize=1)
    with out.open("w", newline="") as fh:
        fh.write("# Standard-form planar LA curve reference, written by tests/reference/la_reference.py\n")
        fh.write("# mpmath dps=40 tanh-sinh quadrature of the theta-form; crosscheck = relative difference to the\n")
        fh.write("# incomplete-gamma closed form (mpmath.gammainc) or the elementary alpha=1 form.\n")
        fh.write("# columns: alpha, lambda, theta (rad), s (arc length), rho (radius of curvature),\n")
        fh.write("#          x, y (position C(theta)), abs_c (|C|), crosscheck\n")
        w = csv.writer(fh)
        w.writerow(["alpha", "lambda", "theta", "s", "rho", "x", "y", "abs_c", "crosscheck"])
        w.writerows(rows)
    print(f"{len(rows)} cases -> {out}")


if __name__ == "__main__":
    main()
