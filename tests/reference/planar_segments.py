#!/usr/bin/python3
"""Reference values for planar G1 (monotonic-rhythm) and compound-rhythm LA segments.

Independent of the C++ code: positions by mpmath quadrature of the theta-form
C(theta) = int rho(psi) e^{i psi} dpsi at 40 digits, segment 1 placed the way 001 Sec. 4 and
docs/math.md §2 describe it (start angle theta_s where rho_1 = rho_c, drawn from theta_s to
theta_s + theta_1 on LaCurve(alpha1, Lambda1), Lambda1 = Lambda0 rho_c^(alpha1 - alpha0)),
and Lambda0 found by mpmath's bracketing root finder (anderson) on the start angle.

Writes planar_segments.csv next to this file. Run: /usr/bin/python3 planar_segments.py
"""
import os
import mpmath as mp

mp.mp.dps = 40

# (name, kind, a0, a1, a2, alpha0, alpha1, r): user triangles of every orientation.
CASES = [
    ("g1_base_m1", "g1", (0, 0), (1, 0), (2, 1), -1, None, None),
    ("g1_base_0", "g1", (0, 0), (1, 0), (2, 1), 0, None, None),
    ("g1_base_05", "g1", (0, 0), (1, 0), (2, 1), 0.5, None, None),
    ("g1_base_1", "g1", (0, 0), (1, 0), (2, 1), 1, None, None),
    ("g1_base_2", "g1", (0, 0), (1, 0), (2, 1), 2, None, None),
    ("g1_swapped_mirrored_15", "g1", (3, 2), (1.5, 0.2), (0.5, 0.9), 1.5, None, None),
    ("g1_mirrored_m05", "g1", (-1, 4), (2, 3.5), (3.5, 0.5), -0.5, None, None),
    ("g1_swapped_3", "g1", (6, 0), (2, 0), (0, 3), 3, None, None),
    ("g1_scaled_1e3_m2", "g1", (1000, -2000), (1800, -1500), (1900, -500), -2, None, None),
    ("g1_wide_turn_07", "g1", (0, 0), (1, 0), (0.2, 1.5), 0.7, None, None),
    ("cmp_m1_15_r04", "compound", (0, 0), (1, 0), (2, 1), -1, 1.5, 0.4),
    ("cmp_15_m1_r06", "compound", (0, 0), (1, 0), (2, 1), 1.5, -1, 0.6),
    ("cmp_05_2_r03", "compound", (0, 0), (1, 0), (2, 1), 0.5, 2, 0.3),
    ("cmp_2_05_r05", "compound", (0, 0), (1, 0), (2, 1), 2, 0.5, 0.5),
    ("cmp_1_m05_r05", "compound", (0, 0), (1, 0), (2, 1), 1, -0.5, 0.5),
    ("cmp_m05_m05_r05", "compound", (0, 0), (1, 0), (2, 1), -0.5, -0.5, 0.5),
    ("cmp_swapped_mirrored_0_3", "compound", (3, 2), (1.5, 0.2), (0.5, 0.9), 0, 3, 0.5),
    ("cmp_mirrored_25_m1", "compound", (-1, 4), (2, 3.5), (3.5, 0.5), 2.5, -1, 0.7),
]


def rho(alpha, lam, theta):
    alpha = mp.mpf(alpha)
    if alpha == 1:
        return mp.e ** (lam * theta)
    return (1 + (alpha - 1) * lam * theta) ** (1 / (alpha - 1))


def s_of(alpha, lam, theta):  # docs/math.md §1 table
    alpha = mp.mpf(alpha)
    if alpha == 0:
        return -mp.log(1 - lam * theta) / lam
    if alpha == 1:
        return (mp.e ** (lam * theta) - 1) / lam
    return ((1 + (alpha - 1) * lam * theta) ** (alpha / (alpha - 1)) - 1) / (alpha * lam)


def theta_at_rho(alpha, lam, r):
    alpha = mp.mpf(alpha)
    if alpha == 1:
        return mp.log(r) / lam
    return (r ** (alpha - 1) - 1) / ((alpha - 1) * lam)


def C(alpha, lam, t0, t1):
    return mp.quad(lambda p: rho(alpha, lam, p) * mp.expj(p), [t0, t1])


def curve(a0, a1, th0, th1, lam0):
    """Standard-form compound curve (001 Fig. 5): start, start tangent, end, rho_c, Lambda1, theta_s."""
    a0 = mp.mpf(a0)
    if a0 <= 1:  # configuration (a)
        p0, t0 = mp.mpc(0), mp.mpf(0)
        J = C(a0, lam0, 0, th0)
        rc = rho(a0, lam0, th0)
        joint_tangent = th0
    else:  # configuration (b)
        p0, t0 = C(a0, lam0, 0, -th0), -th0
        J, rc, joint_tangent = mp.mpc(0), mp.mpf(1), mp.mpf(0)
    end, lam1, ts = J, None, None
    if th1 > 0:
        lam1 = lam0 * rc ** (mp.mpf(a1) - a0)  # 001 Eq. (3.5)
        ts = theta_at_rho(a1, lam1, rc)
        end = J + mp.expj(joint_tangent - ts) * C(a1, lam1, ts, ts + th1)
    return p0, t0, J, end, rc, lam1, ts


def solve(case):
    name, kind, A0, A1, A2, al0, al1, r = case
    A0, A1, A2 = (mp.mpc(*p) for p in (A0, A1, A2))
    d0, d1 = A1 - A0, A2 - A1
    sign = 1 if mp.im(mp.conj(d0) * d1) > 0 else -1
    swapped = abs(d0) > abs(d1)
    B0, B2 = (A2, A0) if swapped else (A0, A2)
    mirrored = mp.im(mp.conj(A1 - B0) * (B2 - A1)) < 0
    if mirrored:  # reflect so that the canonical triangle turns left
        B0, B1, B2 = mp.conj(B0), mp.conj(A1), mp.conj(B2)
    else:
        B1 = A1
    theta = abs(mp.arg((B2 - B1) / (B1 - B0)))
    target = abs(mp.arg((B2 - B0) / (B1 - B0)))
    if kind == "g1":
        al1, r = al0, 1
    th0 = r * theta
    th1 = theta - th0
    al0m, al1m = mp.mpf(al0), mp.mpf(al1)
    if al0m <= 1:
        D = (1 - al0m) * th0 + max(0, 1 - al1m) * th1
    else:
        D = max((al0m - 1) * th0, max(0, 1 - al1m) * th1)
    lam_max = 1 / D if D > 0 else mp.mpf(50) / theta

    def phi(lam):
        p0, t0, J, end, *_ = curve(al0, al1, th0, th1, lam)
        return mp.arg((end - p0) * mp.expj(-t0)) - target

    # Bracket by a scan, then anderson's method (bracketing).
    grid = [lam_max * mp.mpf(k) / 64 for k in range(1, 64)]
    lo = mp.mpf(0)
    hi = None
    for g in grid:
        if phi(g) > 0:
            hi = g
            break
        lo = g
    assert hi is not None, name + ": no sign change"
    if lo == 0:
        lo = hi / 1000
        assert phi(lo) < 0
    lam0 = mp.findroot(phi, (lo, hi), solver="anderson", tol=mp.mpf(10) ** -35)
    p0, t0, J, end, rc, lam1, ts = curve(al0, al1, th0, th1, lam0)
    k = abs(B2 - B0) / abs(end - p0)
    if al0m <= 1:
        L0, rho_start = s_of(al0, lam0, th0), mp.mpf(1)
    else:
        L0, rho_start = -s_of(al0, lam0, -th0), rho(al0, lam0, -th0)
    L1, rho_end = mp.mpf(0), rc
    if th1 > 0:
        L1 = s_of(al1, lam1, ts + th1) - s_of(al1, lam1, ts)
        rho_end = rho(al1, lam1, ts + th1)
    length = k * (L0 + L1)
    kb0, kb2 = sign / (k * rho_start), sign / (k * rho_end)
    kappa0, kappa1 = (kb2, kb0) if swapped else (kb0, kb2)
    return dict(name=name, kind=kind, A=(A0, A1, A2), al0=al0, al1=al1 if kind == "compound" else "",
                r=r if kind == "compound" else "", lam0=lam0, lam1=lam1 if lam1 is not None else "",
                length=length, kappa0=kappa0, kappa1=kappa1, rho_joint=k * rc if kind == "compound" else "")


def main():
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "planar_segments.csv")
    rows = [solve(c) for c in CASES]
    with open(out, "w") as f:
        f.write("# Planar G1 and compound-rhythm LA segments from control points (001 Sec. 2-4, docs/math.md §2).\n")
        f.write("# Generated by tests/reference/planar_segments.py (mpmath, mp.dps = 40, theta-form quadrature,\n")
        f.write("# paper's theta_s construction of segment 1, anderson root finding on Lambda0 to 1e-35).\n")
        f.write("# Columns: name; kind (g1 | compound); control points x0..y2; alpha0; alpha1 and r (compound only);\n")
        f.write("# lambda0, lambda1: Lambda of segment 0 and 1 in segment 0's standard-form units (lambda1 = lambda0 rho_c^(alpha1-alpha0));\n")
        f.write("# length (user units); kappa0, kappa1: signed curvature at a0 and a2 (left turn positive);\n")
        f.write("# rho_joint: radius of curvature at the joint (user units, compound only). Segment 0 is at the end with the shorter leg.\n")
        f.write("name,kind,x0,y0,x1,y1,x2,y2,alpha0,alpha1,r,lambda0,lambda1,length,kappa0,kappa1,rho_joint\n")
        for w in rows:
            pts = []
            for p in w["A"]:
                pts += [mp.nstr(mp.re(p), 17), mp.nstr(mp.im(p), 17)]
            vals = [w["name"], w["kind"]] + pts + [str(w["al0"]), str(w["al1"]), str(w["r"])]
            for key in ("lam0", "lam1", "length", "kappa0", "kappa1", "rho_joint"):
                v = w[key]
                vals.append(mp.nstr(v, 30) if v != "" else "")
            f.write(",".join(vals) + "\n")
    print("wrote", out, len(rows), "rows")


if __name__ == "__main__":
    main()
