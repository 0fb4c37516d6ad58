#!/usr/bin/python3
"""Standard-form LA curves (docs/math.md §1: rho^alpha = 1 + alpha*lambda*s) at arc lengths within 1e-16 .. 1e-11 (relative) of the open end of the s domain,
s -> -1/(alpha*lambda) for alpha > 0, where 1 + alpha*lambda*s cancels in double arithmetic. The
inputs are the oracle campaign's eval problems that exposed the cancellation; every double is
used exactly (mpmath at 60 digits: the products are exact there).

Columns: alpha, lambda, s, one_plus (1 + alpha*lambda*s), theta, rho, kappa.
Run: /usr/bin/python3 tests/reference/la_curve_edge.py > tests/reference/la_curve_edge.csv
"""
import mpmath as mp

mp.mp.dps = 60

CASES = [
    (0.88940239689232103, 82.596375618817376, -0.013612588424644372),
    (0.97506536896511897, 16.005672916667965, -0.064075548175361818),
    (0.95739384615098189, 56.375193499786747, -0.018527692013800702),
    (0.87601153914093322, 22.293987697014479, -0.051203826338995999),
    (0.92131122899147655, 24.328012807941093, -0.044615626913167061),
]


def main():
    print("# Standard-form LA curve near the open end of its s domain; generator: tests/reference/la_curve_edge.py")
    print("# mpmath %s, mp.dps = 60 (exact products of the double inputs)" % mp.__version__)
    print("alpha,lambda,s,one_plus,theta,rho,kappa")
    for alpha, lam, s in CASES:
        a, l, x = mp.mpf(alpha), mp.mpf(lam), mp.mpf(s)
        one_plus = 1 + a * l * x
        rho = one_plus ** (1 / a)
        # theta = int_0^s ds/rho = (rho^(alpha - 1) - 1) / ((alpha - 1) lambda), checked by quadrature
        # of 1/rho toward the end (graded cuts).
        theta = (rho ** (a - 1) - 1) / ((a - 1) * l)
        end = -1 / (a * l)
        cuts = [x] + [end + (x - end) * mp.mpf(2) ** k for k in range(1, 200) if end + (x - end) * mp.mpf(2) ** k < 0] + [0]
        quad = mp.quad(lambda u: (1 + a * l * u) ** (-1 / a), cuts)
        assert abs(quad + theta) < mp.mpf(10) ** -30 * abs(theta), (quad, theta)
        cells = [repr(alpha), repr(lam), repr(s)] + [mp.nstr(v, 25) for v in (one_plus, theta, rho, 1 / rho)]
        print(",".join(cells))


if __name__ == "__main__":
    main()
