#!/usr/bin/python3
"""Reference positions of planar LA segments (curves/planar/la_segment.hpp) through and near
inflections, for the LaSegment tests.

Independent of the C++ code. A segment of slope alpha in linear-q form (004 Eqs. 2-8): q linear
in u from qa at ua to qb at ub, K(q) = sgn(q)|q|^(-1/alpha) (alpha = 0: sigma e^q), and with
F' = K (004 Eqs. 5, 7, 8: F = alpha/(alpha-1)|q|^((alpha-1)/alpha), log|q| for alpha = 1,
sigma e^q for alpha = 0) the tangent angle phi(u) = phi_a + (F(q(u)) - F(qa))/c, c the slope of q.
Placed by start + scale * R * int_{ua}^{u} exp(i phi(v)) dv, theta = arg R + phi, kappa = K/scale.
The integral by mpmath.quad (tanh-sinh) at 40 digits, split at the zero of q (where phi is not
smooth) and into pieces of at most 1/64 of the interval; each piece's error estimate is checked.
Every input is a double (written with repr) and used exactly.

Columns: id, alpha, sigma, ua, ub, qa, qb, phi_a, x0, y0, scale, rx, ry (the segment),
u, s (= scale (u - ua)), x, y, theta, kappa (at u).
Run: /usr/bin/python3 tests/reference/la_segment.py > tests/reference/la_segment.csv
"""
import math

import mpmath as mp

mp.mp.dps = 40


def F(alpha, sigma, q):
    if alpha == 0:
        return sigma * mp.exp(q)
    if alpha == 1:
        return mp.log(abs(q))
    return alpha / (alpha - 1) * abs(q) ** ((alpha - 1) / alpha)


def K(alpha, sigma, q):
    if alpha == 0:
        return sigma * mp.exp(q)
    if q == 0:
        return mp.mpf(0)
    return mp.sign(q) * abs(q) ** (-1 / alpha)


def reference(case, u):
    alpha, sigma, ua, ub, qa, qb, phi_a, x0, y0, scale, rx, ry = [mp.mpf(v) for v in case]
    c = (qb - qa) / (ub - ua)
    Fa = F(alpha, sigma, qa)

    def q(v):
        return qa + c * (v - ua)

    def phi(v):
        return phi_a + (F(alpha, sigma, q(v)) - Fa) / c

    cuts = [ua + (u - ua) * k / 64 for k in range(65)]
    if alpha != 0 and abs(alpha) < 1e-3:
        # Steep F (|p| = |1 - 1/alpha| large): the turning sits in layers ~1/|p| of |q| wide at the
        # ends of largest |q|; geometric cuts toward both ends.
        cuts = sorted(set(cuts + [ua + (u - ua) * mp.mpf(2) ** -k for k in range(7, 40)] +
                          [u - (u - ua) * mp.mpf(2) ** -k for k in range(7, 40)]))
    if alpha < 0 and qa * qb < 0:
        zero = ua - qa / c
        if ua < zero < u:
            cuts = sorted(set(cuts + [zero]))
    total = mp.mpc(0)
    for a, b in zip(cuts[:-1], cuts[1:]):
        value, err = mp.quad(lambda v: mp.expj(phi(v)), [a, b], error=True, maxdegree=10)
        assert err < mp.mpf(10) ** -28 * (b - a) + mp.mpf(10) ** -32, (case, a, b, err)
        total += value
    R = mp.mpc(rx, ry)
    z = mp.mpc(x0, y0) + scale * R * total
    theta = mp.arg(R) + phi(u)
    kappa = K(alpha, sigma, q(u)) / scale
    return scale * (u - ua), z, theta, kappa


def rotation(angle):
    return math.cos(angle), math.sin(angle)


# (alpha, sigma, ua, ub, qa, qb, phi_a, x0, y0, scale, rotation angle); dyadic values.
CASES = []
for alpha in (-3.0, -2.0, -1.0, -0.5):
    CASES += [
        (alpha, 1.0, 0.0, 1.0, 1.0, -0.75, 0.25, 0.0, 0.0, 1.0, 0.0),           # through the inflection
        (alpha, 1.0, 0.25, 0.75, -0.5, 1.25, -0.5, 1.5, -2.0, 3.0, 0.75),       # through, placed
        (alpha, 1.0, 0.0, 1.0, 0.0625, 1.5, 0.0, 0.0, 0.0, 1.0, 0.0),          # zero just before ua
        (alpha, 1.0, 0.0, 1.0, -1.5, -0.125, 0.125, 0.5, 0.5, 0.5, -2.5),      # zero just after ub
        (alpha, 1.0, 0.0, 1.0, 1.25, 0.0, 0.0, 0.0, 0.0, 2.0, 1.0),            # ends at the inflection
        (alpha, 1.0, 0.0, 1.0, 0.0, -0.875, 0.0, 0.0, 0.0, 1.0, 0.0),          # starts at the inflection
        (alpha, 1.0, 0.0, 1.0, 2.0, 3.0, 0.375, -1.0, 4.0, 0.25, 3.0),         # far from a zero
    ]
CASES += [
    (0.0, 1.0, 0.0, 1.0, 0.5, -1.25, 0.0, 0.0, 0.0, 1.0, 0.0),
    (0.0, -1.0, 0.0, 1.0, 0.5, -1.25, 0.25, 1.0, 1.0, 2.0, 0.5),
    (0.0, 1.0, 0.0, 1.0, 4.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0),               # ~20 rad of turning
    (0.0, -1.0, 0.0, 1.0, 6.5, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0),              # ~102 rad: pieces of <= 64 rad
    (0.5, 1.0, 0.0, 1.0, 1.0, 2.5, 0.0, 0.0, 0.0, 1.0, 0.0),
    (0.5, 1.0, 0.0, 1.0, -0.25, -1.0, 0.5, 2.0, -1.0, 0.75, -1.0),
    (1.0, 1.0, 0.0, 1.0, 0.125, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0),
    (1.0, 1.0, 0.5, 1.5, -2.0, -0.25, 0.0, -3.0, 0.0, 4.0, 2.0),
    (2.0, 1.0, 0.0, 1.0, 0.5, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0),
    (2.0, 1.0, 0.0, 1.0, -3.0, -0.0625, 1.0, 0.0, 0.0, 1.0, 0.25),
    (3.0, 1.0, 0.0, 1.0, 1.5, 0.25, 0.0, 0.0, 0.0, 1.0, 0.0),
    (3.0, 1.0, 0.0, 2.0, -1.0, -4.0, -0.25, 1.0, 2.0, 0.5, -0.5),
    # Small |alpha| through an inflection: |q| changes by 2e-4 (3e-5) of itself on the side of
    # each end, and the whole turning of ~0.7 rad (~1 rad) happens within ~1e-4 (~1e-6) of the ends.
    (-2.0540882710784719e-05, 1.0, 0.0, 1.0, 1.0002290459227217, -1.0002290459227217, -0.71403470027125093,
     0.0, 0.0, 1.0, 0.0),
    (-2.4592826297817304e-06, 1.0, 0.0, 1.0, 1.0000333786010742, -1.0000337362289429, 0.5, 0.0, 0.0, 1.0, 0.0),
]

FRACTIONS = (0.1376953125, 0.5, 0.8125, 1.0)


def main():
    print("# Planar LA segment positions (linear-q form, 004 Eqs. 2-8); generator: tests/reference/la_segment.py")
    print("# mpmath %s, mp.dps = 40, mpmath.quad split at the zero of q and into 64 pieces" % mp.__version__)
    print("id,alpha,sigma,ua,ub,qa,qb,phi_a,x0,y0,scale,rx,ry,u,s,x,y,theta,kappa")
    for i, (alpha, sigma, ua, ub, qa, qb, phi_a, x0, y0, scale, angle) in enumerate(CASES):
        rx, ry = rotation(angle)
        case = (alpha, sigma, ua, ub, qa, qb, phi_a, x0, y0, scale, rx, ry)
        us = [ua + (ub - ua) * f for f in FRACTIONS]
        if alpha < 0 and qa * qb < 0:
            us.append(float(ua - qa / ((qb - qa) / (ub - ua))))  # at the inflection (as a double)
        for u in us:
            s, z, theta, kappa = reference(case, mp.mpf(u))
            # A curvature below the double range (small |alpha|: K = |q|^(-1/alpha)) is written as 0.
            kappa = mp.mpf(0) if abs(kappa) < mp.mpf(10) ** -300 else kappa
            cells = [str(i)] + [repr(v) for v in case] + [repr(u)] + [mp.nstr(v, 25) for v in (s, z.real, z.imag, theta, kappa)]
            print(",".join(cells))


if __name__ == "__main__":
    main()
