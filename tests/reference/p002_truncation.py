#!/usr/bin/env python3
"""Reference endpoints for paper 002's Appendix A (timing) and Appendix B (truncation error).

Writes p002_truncation.csv next to this file. Run: /usr/bin/python3 tests/reference/p002_truncation.py

Every row is the position C = x + i y of the standard-form planar LA curve (docs/math.md §1) at the
end of one interval that 002 integrates over, at mp.dps = 40:

  set = appendix_a   the 18 (alpha, Lambda) rows of 002 Appendix A, endpoint theta = 1;
  set = appendix_b   alpha in {2, 4/3, 10/9} x Lambda in {1, 10, 100}, endpoint theta = 1
                     (002: "theta(s) in [0, 1]");
  set = appendix_b_s the same nine curves at arc length s = 1, for the reading
                     "s in [0, 1]" of 002's range (002 says it integrated Eq. (12) in s).

alpha and Lambda are the exact binary64 values that the C++ code uses (e.g. 4/3 is
float(4/3) = 1.3333333333333332593...), so the reference is for the very curve computed in
double; `alpha_text` keeps the paper's spelling.

Two independent evaluations per row, both at 40 digits:
  1. mpmath tanh-sinh quadrature on 64 equal sub-intervals, of the theta-form
     C = ∫_0^theta rho(psi) e^{i psi} dpsi for alpha > 1/2 and of the s-form
     C = ∫_0^s e^{i theta(u)} du for alpha <= 1/2 (where rho grows steeply toward theta = 1);
  2. the closed form through the upper incomplete gamma function of docs/math.md §1.1
     (mpmath.gammainc, complex argument), C = e^{-i/k}/k (ik)^a [G(a,-i/k) - G(a,-iU/k)],
     k = (alpha-1) Lambda, a = alpha/(alpha-1), U = 1 + k theta.
Column `crosscheck` = |C_quad - C_igf| / |C_quad|; the script aborts if it exceeds 1e-25.
Column `igf_cancellation` = max(|G(a,-i/k)|, |G(a,-iU/k)|) / |G(a,-i/k) - G(a,-iU/k)|: the factor by
which rounding errors of the two incomplete gamma values are amplified in their difference, i.e. an
IGF evaluation in double precision cannot be better than about igf_cancellation * eps relative.
x, y are printed with 25 significant digits; s_end, theta_end are the interval's ends in
both variables (docs/math.md §1 closed forms).
"""
import csv
import pathlib

import mpmath as mp

mp.mp.dps = 40
CROSSCHECK_LIMIT = mp.mpf("1e-25")

# 002 Appendix A rows (alpha, Lambda) as printed (page "APPENDIX A: TIMESTAMP IN SECOND").
APPENDIX_A = [("-100", "0.00825"), ("-10", "0.0758"), ("-1", "0.417"), ("-0.1", "0.758"),
              ("-0.01", "0.825"), ("0", "0.833"), ("0.01", "1"), ("0.1", "1"), ("0.9", "1"),
              ("0.99", "1"), ("1.1", "1"), ("6/5", "1"), ("5/4", "1"), ("4/3", "1"), ("3/2", "1"),
              ("2", "1"), ("10", "1"), ("100", "1")]
# 002 Appendix B grid.
APPENDIX_B = [(a, l) for a in ("2", "4/3", "10/9") for l in ("1", "10", "100")]


def as_double(text):
    """The binary64 value the C++ side uses for this decimal or fraction, as an exact mpf."""
    if "/" in text:
        n, d = text.split("/")
        return mp.mpf(float(n) / float(d))
    return mp.mpf(float(text))


def log_rho_at_theta(alpha, lam, theta):
    return mp.log1p((alpha - 1) * lam * theta) / (alpha - 1)


def s_at_theta(alpha, lam, theta):
    L = log_rho_at_theta(alpha, lam, theta)
    if alpha == 0:
        return L / lam
    return mp.expm1(alpha * L) / (alpha * lam)


def theta_at_s(alpha, lam, s):
    if alpha == 0:
        L = lam * s
    else:
        L = mp.log1p(alpha * lam * s) / alpha
    return mp.expm1((alpha - 1) * L) / ((alpha - 1) * lam)


def quad_position(alpha, lam, theta_end):
    if alpha > mp.mpf("0.5"):
        f = lambda psi: mp.exp(log_rho_at_theta(alpha, lam, psi)) * mp.expj(psi)
        end = theta_end
    else:
        f = lambda u: mp.expj(theta_at_s(alpha, lam, u))
        end = s_at_theta(alpha, lam, theta_end)
    return mp.quad(f, mp.linspace(0, end, 65))


def igf_terms(alpha, lam, theta):
    k = (alpha - 1) * lam
    a = alpha / (alpha - 1)
    U = 1 + k * theta
    j = mp.mpc(0, 1)
    g0, g1 = mp.gammainc(a, -j / k), mp.gammainc(a, -j * U / k)
    return mp.exp(-j / k) / k * mp.power(j * k, a), g0, g1


def igf_position(alpha, lam, theta):
    prefactor, g0, g1 = igf_terms(alpha, lam, theta)
    return prefactor * (g0 - g1)


def igf_cancellation(alpha, lam, theta):
    _, g0, g1 = igf_terms(alpha, lam, theta)
    return max(abs(g0), abs(g1)) / abs(g0 - g1)


def row(set_name, alpha_text, lam_text, theta_end):
    alpha, lam = as_double(alpha_text), as_double(lam_text)
    c_quad = quad_position(alpha, lam, theta_end)
    c_igf = igf_position(alpha, lam, theta_end)
    cross = abs(c_quad - c_igf) / abs(c_quad)
    if cross > CROSSCHECK_LIMIT:
        raise SystemExit(f"crosscheck failed for {set_name} alpha={alpha_text} lambda={lam_text}: {mp.nstr(cross, 5)}")
    return [set_name, alpha_text, mp.nstr(alpha, 20), lam_text, mp.nstr(lam, 20), mp.nstr(theta_end, 25),
            mp.nstr(s_at_theta(alpha, lam, theta_end), 25), mp.nstr(c_quad.real, 25), mp.nstr(c_quad.imag, 25),
            mp.nstr(abs(c_quad), 25), mp.nstr(cross, 3), mp.nstr(igf_cancellation(alpha, lam, theta_end), 4)]


def main():
    rows = []
    for a, l in APPENDIX_A:
        rows.append(row("appendix_a", a, l, mp.mpf(1)))
    for a, l in APPENDIX_B:
        rows.append(row("appendix_b", a, l, mp.mpf(1)))
    for a, l in APPENDIX_B:
        alpha, lam = as_double(a), as_double(l)
        rows.append(row("appendix_b_s", a, l, theta_at_s(alpha, lam, mp.mpf(1))))
    out = pathlib.Path(__file__).with_suffix(".csv")
    with out.open("w", newline="") as fh:
        fh.write("# Reference endpoints for 002 Appendices A and B; generated by tests/reference/p002_truncation.py\n")
        fh.write("# mpmath mp.dps=40: tanh-sinh quadrature (theta-form for alpha>1/2, s-form otherwise, 64 pieces),\n")
        fh.write("# cross-checked against the incomplete-gamma closed form (docs/math.md §1.1); crosscheck = relative difference.\n")
        fh.write("# alpha, lambda: exact binary64 values used by the C++ code (alpha_text: the paper's spelling).\n")
        fh.write("# theta_end, s_end: end of the interval [0, end] in both variables; x, y, abs_c: C at that end.\n")
        fh.write("# igf_cancellation: max(|G0|, |G1|) / |G0 - G1| of the closed form's incomplete gammas (rounding amplification).\n")
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["set", "alpha_text", "alpha", "lambda_text", "lambda", "theta_end", "s_end", "x", "y", "abs_c",
                    "crosscheck", "igf_cancellation"])
        w.writerows(rows)
    print(f"wrote {len(rows)} rows to {out}")


if __name__ == "__main__":
    main()
