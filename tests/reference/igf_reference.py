#!/usr/bin/env python3
"""Reference position differences C(theta1) - C(theta0) of standard-form planar LA curves, for the
igf integrator (docs/math.md §1, §1.1). Run: /usr/bin/python3 tests/reference/igf_reference.py
(writes igf_reference.csv next to this file; a few minutes).

C(theta1) - C(theta0) = ∫_theta0^theta1 rho(psi) e^{i psi} dpsi, rho = exp(Lambda psi log1p(k psi)/(k psi)),
k = (alpha - 1) Lambda, by mpmath Gauss-Legendre quadrature (degree raised until converged) at
mp.dps = 30 on sub-intervals where psi moves by at most 0.5 rad and log rho by at most 1. Cross-check (column crosscheck, relative):
the incomplete-gamma closed form with mpmath.gammainc at mp.dps = 60 for alpha != 1 with
|a| = |alpha/(alpha-1)| <= 60, the elementary form for alpha = 1 and Lambda = 0; the generator
stops if a cross-check exceeds 1e-20. All inputs are exact doubles (alpha, Lambda and theta are
rounded to double before evaluation, and printed with 17 digits).

Cases: alpha from -100 to 100 incl. 0, 0.5, 0.9, 10/11 (a = -10), 0.99, 0.999, 1, 1.001, 1.01, 1.1,
10/9 (a = 10), 4/3, 2, 10; Lambda from 1e-3 to 100 and 0 (circle); theta1 in {1e-8, 1e-5, 1e-3, 0.1, 1,
3, -0.5, -2} and 0.5 / 0.95 of each finite bound of the theta domain (|theta| capped at 30), from
theta0 = 0; plus short steps away from 0 (theta0 = 0.5 theta1*, theta1 = theta0 + 1e-7 and + 1e-3).
Rows where |log rho| > 600 are skipped (rho not representable in double), and rows whose condition
number |p k theta / U| + |Lambda theta| (p = 1/(alpha-1), U = 1 + k theta) exceeds 1e3 at either end: there a
one-ulp change of the double input moves C by more than about 1e-13 relative, so no double algorithm can
be held to 1e-12 with margin (e.g. theta = 0.1 at alpha = 0.9, Lambda = 100, where U = 2e-16).

Columns: alpha, lambda, theta0, theta1, re, im (C(theta1) - C(theta0)), abs (its modulus),
crosscheck (relative difference to the closed form, or -1 where none was evaluated).
"""
import csv
import pathlib

import mpmath as mp

HERE = pathlib.Path(__file__).resolve().parent
ALPHAS = ["-100", "-10", "-1", "0", "0.5", "0.9", "10/11", "0.99", "0.999", "1", "1.001", "1.01", "1.1",
          "10/9", "4/3", "2", "10", "100"]
LAMBDAS = ["0.001", "0.1", "1", "10", "100"]
THETA_CAP = mp.mpf(30)


def dbl(x):
    return mp.mpf(float(x))


def parse(text):
    if "/" in text:
        n, d = text.split("/")
        return dbl(mp.mpf(n) / mp.mpf(d))
    return dbl(mp.mpf(text))


def log_rho(alpha, lam, psi):
    if alpha == 1 or lam == 0:
        return lam * psi
    k = (alpha - 1) * lam
    return mp.log1p(k * psi) / (alpha - 1)


def theta_of_log_rho(alpha, lam, L):
    if alpha == 1:
        return L / lam
    return mp.expm1((alpha - 1) * L) / ((alpha - 1) * lam)


def domain(alpha, lam):
    if alpha == 1 or lam == 0:
        return -mp.inf, mp.inf
    if alpha < 1:
        return -mp.inf, 1 / ((1 - alpha) * lam)
    return -1 / ((alpha - 1) * lam), mp.inf


def breakpoints(alpha, lam, t0, t1):
    pts = [t0]
    L0, L1 = log_rho(alpha, lam, t0), log_rho(alpha, lam, t1)
    n = int(mp.ceil(abs(L1 - L0) / mp.mpf("1")))
    if lam > 0:
        for j in range(1, n):
            pts.append(theta_of_log_rho(alpha, lam, L0 + (L1 - L0) * j / n))
    pts.append(t1)
    dense = []
    for a, b in zip(pts[:-1], pts[1:]):
        m = max(1, int(mp.ceil(abs(b - a) / mp.mpf("0.5"))))
        dense += [a + (b - a) * j / m for j in range(m)]
    dense.append(t1)
    if lam == 0 or alpha == 1:
        return dense
    # The integrand has a branch point where U = 1 + k psi = 0, at distance U/|k| from psi:
    # split every piece until it is shorter than half its distance to it (geometric grading).
    k = (alpha - 1) * lam
    out = [dense[0]]
    for b in dense[1:]:
        out += graded(out[-1], b, k)[1:]
    return out


def graded(a, b, k):
    left, right = [a], [b]
    while True:
        x, y = left[-1], right[-1]
        ux, uy = 1 + k * x, 1 + k * y
        d = min(ux, uy) / abs(k)
        if abs(y - x) <= d / 2:
            return left + right[::-1]
        if ux <= uy:
            left.append(x + (d / 2) * mp.sign(y - x))
        else:
            right.append(y - (d / 2) * mp.sign(y - x))


def by_quadrature(alpha, lam, t0, t1):
    with mp.workdps(30):
        f = lambda psi: mp.exp(log_rho(alpha, lam, psi)) * mp.expj(psi)
        return mp.quad(f, breakpoints(alpha, lam, t0, t1), method="gauss-legendre")


def by_closed_form(alpha, lam, t0, t1):
    with mp.workdps(60):
        if lam == 0:
            return -1j * (mp.expj(t1) - mp.expj(t0))
        if alpha == 1:
            w = lam + 1j
            return (mp.exp(w * t1) - mp.exp(w * t0)) / w
        k = (alpha - 1) * lam
        a = alpha / (alpha - 1)
        if abs(a) > 60:
            return None
        z0, z1 = -1j * (1 + k * t0) / k, -1j * (1 + k * t1) / k
        # the difference of two nearly equal Γ values: 60 digits leave > 40 after a 1e-8 step
        return mp.exp(-1j / k) / k * mp.power(1j * k, a) * (mp.gammainc(a, z0) - mp.gammainc(a, z1))


def condition(alpha, lam, t):
    """Relative sensitivity of rho(t) to a relative change of its input: |p k t / U| with
    p = 1/(alpha - 1). A double evaluation of U = 1 + k t is off by about one ulp of 1 + |k t|, so
    no double algorithm can beat ~1e-16 times this; rows above 1e3 are not representable
    to 1e-12 with margin and are skipped."""
    if lam == 0 or alpha == 1:
        return abs(lam * t)
    k = (alpha - 1) * lam
    return abs(k * t / (alpha - 1)) / (1 + k * t) + abs(lam * t)


def cases():
    for at in ALPHAS:
        alpha = parse(at)
        for lt in LAMBDAS + (["0"] if at in ("2", "0.5") else []):
            lam = dbl(lt)
            lo, hi = domain(alpha, lam)
            ends = [mp.mpf(x) for x in ("1e-8", "1e-5", "1e-3", "0.1", "1", "3", "-0.5", "-2")]
            for bound in (lo, hi):
                if mp.isfinite(bound):
                    ends += [bound * mp.mpf("0.95"), bound * mp.mpf("0.5")]
            ends = [max(min(t, THETA_CAP), -THETA_CAP) for t in ends]
            pairs = [(mp.mpf(0), dbl(t)) for t in ends]
            mid = ends[-1] if (mp.isfinite(lo) or mp.isfinite(hi)) else mp.mpf(1)
            mid = dbl(mid)
            pairs += [(mid, dbl(mid + mp.mpf("1e-7"))), (mid, dbl(mid + mp.mpf("1e-3")))]
            seen = set()
            for t0, t1 in pairs:
                key = (float(t0), float(t1))
                if key in seen or t0 == t1 or not (lo < t0 < hi and lo < t1 < hi):
                    continue
                seen.add(key)
                if max(abs(log_rho(alpha, lam, t0)), abs(log_rho(alpha, lam, t1))) > 600:
                    continue
                if condition(alpha, lam, t0) > 1e3 or condition(alpha, lam, t1) > 1e3:
                    continue
                yield alpha, lam, t0, t1


def main():
    rows = []
    for alpha, lam, t0, t1 in cases():
        c = by_quadrature(alpha, lam, t0, t1)
        other = by_closed_form(alpha, lam, t0, t1)
        cross = -1
        if other is not None:
            cross = abs(c - other) / abs(c)
            if cross > mp.mpf("1e-20"):
                raise SystemExit(f"cross-check failed: alpha={alpha} lambda={lam} {t0}..{t1}: {cross}")
        print(f"alpha={mp.nstr(alpha, 8)} lambda={mp.nstr(lam, 4)} theta {mp.nstr(t0, 6)}..{mp.nstr(t1, 6)}"
              f" crosscheck={mp.nstr(cross, 3)}", flush=True)
        rows.append([mp.nstr(x, 17) for x in (alpha, lam, t0, t1, c.real, c.imag, abs(c))] + [mp.nstr(cross, 3)])
    with open(HERE / "igf_reference.csv", "w", newline="") as fh:
        fh.write("# C(theta1) - C(theta0) of the standard-form planar LA curve; written by tests/reference/igf_reference.py\n")
        fh.write("# mpmath Gauss-Legendre at dps=30 on the theta-form, cross-checked by the incomplete-gamma closed form (dps=60)\n")
        fh.write("# columns: alpha, lambda, theta0, theta1, re, im, abs, crosscheck (relative; -1 = none)\n")
        w = csv.writer(fh)
        w.writerow(["alpha", "lambda", "theta0", "theta1", "re", "im", "abs", "crosscheck"])
        w.writerows(rows)
    print(f"igf_reference.csv: {len(rows)} rows")


if __name__ == "__main__":
    main()
