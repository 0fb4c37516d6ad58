#!/usr/bin/python3
"""Reference clothoids (alpha = -1) for the G1 Hermite tests (constructions/g1_hermite.hpp).

Independent of the C++ code: the end point by Fresnel integrals (mpmath.fresnelc/fresnels) at
30 digits, the G1 condition solved by mpmath.findroot.

Problem set (same as tests/support/g1_problem_set.hpp): P0 = (0, 0), P1 = (1, 0); theta0, theta1
uniform in (-pi/2, pi/2) from splitmix64 with seed 20240601, drawn theta0 then theta1 per problem;
a draw is k = (output >> 11), theta = pi * (k * 2^-53 - 1/2), k = 0 redrawn.

Clothoid [Bertolazzi-Frego 2015]: u = s/L in [0, 1], phi(u) = phi0 + (delta - A) u + A u^2 with
phi0 = theta0, delta = theta1 - theta0 (the chord is the x axis), and Im int_0^1 exp(i phi) du = 0;
A is the root at the sign change of the imaginary part nearest to the small-angle value
3 (phi0 + phi1) (steps of 1/4 outward), refined by Illinois. Then L = 1 / Re int,
kappa0 = (delta - A) / L, kappa1 = (delta + A) / L.

Columns: id, theta0, theta1 (17 significant digits: the C++ test checks they are its own set),
A, length, kappa0, kappa1.
Run: /usr/bin/python3 tests/reference/g1_clothoid.py > tests/reference/g1_clothoid.csv
"""
import multiprocessing
import sys

import mpmath as mp

DPS = 30
SEED = 20240601
COUNT = 2000
MASK = (1 << 64) - 1


def problem_set():
    state = SEED
    out = []

    def next_u64():
        nonlocal state
        state = (state + 0x9E3779B97F4A7C15) & MASK
        z = state
        z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & MASK
        z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & MASK
        return z ^ (z >> 31)

    def draw():
        while True:
            k = next_u64() >> 11
            if k != 0:
                # the same double as the C++ pi * (k * 2^-53 - 0.5): both steps are exact or rounded once
                import math
                return math.pi * (k * 2.0 ** -53 - 0.5)

    for _ in range(COUNT):
        t0 = draw()
        t1 = draw()
        out.append((t0, t1))
    return out


def integral(phi0, delta, A):
    """int_0^1 exp(i (A u^2 + (delta - A) u + phi0)) du by Fresnel integrals."""
    a, b, c = A, delta - A, phi0
    if abs(a) < mp.mpf(10) ** -20:
        if abs(b) < mp.mpf(10) ** -20:
            return mp.expj(c)
        return mp.expj(c) * (mp.expj(b) - 1) / (1j * b)
    sign = 1 if a > 0 else -1
    k = mp.sqrt(2 * abs(a) / mp.pi)
    shift = b / (2 * a)
    const = c - b * b / (4 * a)
    t0, t1 = shift * k, (1 + shift) * k
    val = (mp.fresnelc(t1) - mp.fresnelc(t0)) + 1j * (mp.fresnels(t1) - mp.fresnels(t0))
    if sign < 0:
        val = mp.conj(val)
    return mp.expj(const) * val / k


def solve(args):
    i, (t0, t1) = args
    mp.mp.dps = DPS
    phi0, phi1 = mp.mpf(t0), mp.mpf(t1)
    delta = phi1 - phi0
    f = lambda x: mp.im(integral(phi0, delta, x))
    # The sign change of f nearest to the small-angle value (steps of 1/4 outward), then Illinois.
    A0 = 3 * (phi0 + phi1)
    f0, lo, hi = f(A0), None, None
    prev = {1: (A0, f0), -1: (A0, f0)}
    for j in range(1, 400):
        for side in (1, -1):
            x = A0 + side * j * mp.mpf(1) / 4
            fx = f(x)
            xp, fp = prev[side]
            if (fx > 0) != (fp > 0) and lo is None:
                lo, hi = (xp, x) if xp < x else (x, xp)
            prev[side] = (x, fx)
        if lo is not None:
            break
    A = mp.findroot(f, (lo, hi), solver="illinois", tol=mp.mpf(10) ** -50)
    I = integral(phi0, delta, A)
    assert mp.re(I) > 0 and abs(mp.im(I)) < mp.mpf(10) ** -24
    L = 1 / mp.re(I)
    row = [str(i), repr(t0), repr(t1)] + [mp.nstr(v, 25) for v in (A, L, (delta - A) / L, (delta + A) / L)]
    return ",".join(row)


def main():
    problems = list(enumerate(problem_set()))
    with multiprocessing.Pool(2) as pool:
        rows = pool.map(solve, problems, chunksize=50)
    print("id,theta0,theta1,A,length,kappa0,kappa1")
    for r in rows:
        print(r)


if __name__ == "__main__":
    sys.exit(main())
