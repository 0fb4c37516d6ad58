#!/usr/bin/env python3
"""Reference values of the upper incomplete gamma function Γ(a, z) for real a and complex z.

Run: /usr/bin/python3 tests/reference/gamma_inc.py   (writes gamma_inc.csv and
gamma_inc_diff.csv next to this file; about half a minute).

All inputs are exact doubles (decimal orders and moduli are rounded to double first).
Values come from mpmath.gammainc (principal branch) at mp.dps = 40. Each value is computed
again at mp.dps = 60 and the generator stops if the two differ by more than 1e-30 relative,
so every printed digit (17 significant) is settled.

gamma_inc.csv columns: a, z_re, z_im, re, im, group
  re + i im = Γ(a, z_re + i z_im); group names the part of the grid:
  imag     z = ±i y, y from 1e-3 to 1e4 (the igf closed form's case), every order a;
  complex  z = r e^(iφ), r from 1e-3 to 200, φ over (−π, π], a subset of orders.
  Orders: a ∈ [−10, 10] incl. 0, negative and positive integers, non-integers, and orders
  within 1e-3 of 0 and of −3.
gamma_inc_diff.csv columns: a, z1_re, z1_im, z2_re, z2_im, re, im, group
  re + i im = Γ(a, z1) − Γ(a, z2), subtracted at 80 digits (checked at 100); z2 = z1 (1 + δ) with relative
  gaps δ from 1e-12 to 0.5 (group near), and far-apart pairs on one ray (group ray), as in
  the igf closed form (z = −iU/k).
"""
import csv
import math
import pathlib

import mpmath as mp

HERE = pathlib.Path(__file__).resolve().parent

ORDERS = ["-10", "-9.5", "-7", "-5.3", "-3.001", "-3", "-2.5", "-1", "-0.7", "-0.3", "-0.001", "0",
          "0.001", "0.3", "0.5", "1", "1.7", "2", "3.5", "5", "7.25", "10"]
IMAG_MODULI = ["1e-3", "1e-2", "0.1", "0.5", "1", "1.4", "1.6", "2", "3", "5", "8", "12", "20", "35",
               "50", "100", "1e3", "1e4"]
COMPLEX_ORDERS = ["-10", "-5.3", "-3", "-1", "-0.3", "0", "0.5", "1", "2", "3.5", "7.25", "10"]
COMPLEX_MODULI = ["1e-3", "0.5", "1.4", "3", "10", "25", "60", "200"]
# Angles as fractions of π; 1 is the negative real axis (approached from above).
COMPLEX_ANGLES = ["0", "0.25", "-0.4", "0.6", "-0.75", "0.9", "-0.97", "1"]

DIFF_ORDERS = ["-10", "-3", "-0.5", "0", "0.5", "1", "2", "4", "10"]
DIFF_POINTS = ["-0.001j", "-0.3j", "-1j", "-1.4j", "-3j", "-10j", "-100j", "5j", "0.5+2j", "-2+1j"]
DIFF_GAPS = ["1e-12", "1e-8", "1e-5", "1e-3", "0.05", "0.3", "0.5", "-0.3"]
RAY_FACTORS = ["0.05", "0.4", "3", "20", "300"]


def value(fn, *args, dps=40):
    """fn(*args) at dps digits, checked against dps + 20 digits."""
    # Arguments are rounded to doubles first, so the reference is the function at exactly
    # the inputs the C++ test passes.
    args = [mp.mpf(float(x)) if isinstance(x, str) else x for x in args]
    with mp.workdps(dps):
        v40 = fn(*[mp.mpmathify(x) for x in args])
    with mp.workdps(dps + 20):
        v60 = fn(*[mp.mpmathify(x) for x in args])
        if abs(v60) == 0 or abs(v40 - v60) > mp.mpf("1e-30") * abs(v60):
            raise SystemExit(f"precision check failed for {args}: {v40} vs {v60}")
    return v60


def difference(a, z1, z2):
    """Γ(a, z1) − Γ(a, z2) by plain subtraction at the working precision (80 digits leave
    more than 60 after the worst cancellation of this grid, a gap of 1e-12)."""
    return mp.gammainc(a, z1) - mp.gammainc(a, z2)


def num(x):
    return mp.nstr(x, 17, min_fixed=-1, max_fixed=-1) if x != 0 else "0"


def cnum(z):
    return num(mp.re(z)), num(mp.im(z))


def main():
    rows = []
    for a in ORDERS:
        for y in IMAG_MODULI:
            for sign in ("-1", "1"):
                z = mp.mpc(0, float(mp.mpf(sign) * mp.mpf(y)))
                v = value(lambda aa, zz: mp.gammainc(aa, zz), a, z)
                rows.append([a, *cnum(z), *cnum(v), "imag"])
    for a in COMPLEX_ORDERS:
        for r in COMPLEX_MODULI:
            for phi in COMPLEX_ANGLES:
                with mp.workdps(60):
                    ang = mp.mpf(phi) * mp.pi
                    z = mp.mpc(mp.mpf(r) * mp.cos(ang), mp.mpf(r) * mp.sin(ang))
                    if phi == "1":
                        z = mp.mpc(-mp.mpf(r), 0)
                    # the double nearest to z is the argument: round it first
                    z = mp.mpc(float(mp.re(z)), float(mp.im(z)))
                    if phi == "1":
                        z = mp.mpc(mp.re(z), 0)
                if mp.re(z) < -700:  # e^(-z) beyond double range
                    continue
                v = value(lambda aa, zz: mp.gammainc(aa, zz), a, z)
                rows.append([a, *cnum(z), *cnum(v), "complex"])
    with open(HERE / "gamma_inc.csv", "w", newline="") as f:
        f.write("# Gamma(a, z) upper incomplete gamma, principal branch; written by tests/reference/gamma_inc.py\n")
        f.write("# mpmath.gammainc at mp.dps=40, checked against mp.dps=60 (<= 1e-30 relative); 17 significant digits\n")
        f.write("# columns: a, z_re, z_im, re, im (value), group (imag | complex)\n")
        w = csv.writer(f)
        w.writerow(["a", "z_re", "z_im", "re", "im", "group"])
        w.writerows(rows)
    print(f"gamma_inc.csv: {len(rows)} rows")

    drows = []
    for a in DIFF_ORDERS:
        for p in DIFF_POINTS:
            z1 = mp.mpc(complex(p))
            for g in DIFF_GAPS:
                z2 = z1 * (1 + mp.mpf(g))
                z2 = mp.mpc(float(mp.re(z2)), float(mp.im(z2)))
                v = value(difference, a, z1, z2, dps=80)
                drows.append([a, *cnum(z1), *cnum(z2), *cnum(v), "near"])
            if mp.re(z1) == 0:
                for fct in RAY_FACTORS:
                    z2 = mp.mpc(0, float(mp.im(z1) * mp.mpf(fct)))
                    v = value(difference, a, z1, z2, dps=80)
                    drows.append([a, *cnum(z1), *cnum(z2), *cnum(v), "ray"])
    with open(HERE / "gamma_inc_diff.csv", "w", newline="") as f:
        f.write("# Gamma(a, z1) - Gamma(a, z2) (mpmath.gammainc of each, subtracted); written by tests/reference/gamma_inc.py\n")
        f.write("# mp.dps=80 checked against mp.dps=100 (<= 1e-30 relative after cancellation); z1, z2 are exact doubles\n")
        f.write("# columns: a, z1_re, z1_im, z2_re, z2_im, re, im (value), group (near | ray)\n")
        w = csv.writer(f)
        w.writerow(["a", "z1_re", "z1_im", "z2_re", "z2_im", "re", "im", "group"])
        w.writerows(drows)
    print(f"gamma_inc_diff.csv: {len(drows)} rows")


if __name__ == "__main__":
    main()
