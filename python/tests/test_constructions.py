"""The construction bindings: results, summaries, curves and their evaluation, against the lac CLI."""
import json
import math
import subprocess

import numpy as np
import pytest

import lac

REPORT_KEYS = {"status", "message", "length", "kappa0", "kappa1", "iterations", "evaluations", "seconds", "solver",
               "integrator", "residuals", "error", "accept"}


def cli(lac_cli, *args):
    out = subprocess.run([lac_cli, *args], capture_output=True, text=True, timeout=60)
    assert out.returncode in (0, 3), out.stderr
    return json.loads(out.stdout)


def test_g1_hermite_result_summary_and_curve():
    r = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0)
    assert r.status == "ok" and r.usable and bool(r) and r.message == ""
    assert REPORT_KEYS <= set(r.summary)
    assert r.summary["status"] == "ok" and r.summary["accept"] > 0
    c = r.curve
    assert isinstance(c, lac.Curve) and c.length > 1.0
    pts = c.eval(np.linspace(0, c.length, 1001))
    for key in ("s", "x", "y", "theta", "kappa", "dkappa"):
        assert pts[key].shape == (1001,) and getattr(pts, key) is pts[key]
    assert np.all(pts.status == "ok")
    # end conditions
    assert abs(pts.x[0]) < 1e-14 and abs(pts.y[0]) < 1e-14
    assert math.hypot(pts.x[-1] - 1, pts.y[-1]) < 1e-9
    assert abs(pts.theta[0] - 0.3) < 1e-12 and abs(pts.theta[-1] + 0.4) < 1e-9
    # the positions follow the tangent: dx/ds = cos(theta), dy/ds = sin(theta) (central differences)
    h = pts.s[1] - pts.s[0]
    dx, dy = np.gradient(pts.x, h)[1:-1], np.gradient(pts.y, h)[1:-1]
    assert np.max(np.abs(dx - np.cos(pts.theta[1:-1]))) < 1e-4
    assert np.max(np.abs(dy - np.sin(pts.theta[1:-1]))) < 1e-4
    # dkappa is the derivative of kappa, kappa the derivative of theta
    assert np.max(np.abs(np.gradient(pts.kappa, h)[1:-1] - pts.dkappa[1:-1])) < 1e-3 * np.max(np.abs(pts.dkappa))
    assert np.max(np.abs(np.gradient(pts.theta, h)[1:-1] - pts.kappa[1:-1])) < 1e-4
    # closed forms agree with eval; non-uniform s gives the same points
    assert np.allclose(c.kappa(pts.s), pts.kappa, rtol=0, atol=1e-14)
    s_random = np.sort(np.random.default_rng(1).uniform(0, c.length, 37))
    q = c.eval(s_random)
    assert np.allclose(q.x, np.interp(s_random, pts.s, pts.x), atol=1e-6)
    assert r.info["shape"] in ("convex", "convex_inflection", "s_shaped", "straight", "other")


def test_g1_hermite_matches_cli(lac_cli):
    r = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-2.0)
    j = cli(lac_cli, "g1", "--p0", "0,0", "--theta0", "0.3", "--p1", "1,0", "--theta1", "-0.4", "--alpha", "-2",
            "--samples", "11")
    s = r.summary
    assert s["status"] == j["status"] == "ok"
    for key in ("length", "kappa0", "kappa1", "iterations", "evaluations", "error", "accept"):
        assert s[key] == pytest.approx(j[key], rel=1e-15, abs=0), key
    pts = r.curve.sample(11)
    for p, x, y, k in zip(j["points"], pts.x, pts.y, pts.kappa):
        assert (p["x"], p["y"], p["kappa"]) == pytest.approx((x, y, k), rel=1e-14, abs=1e-15)


def test_g1_options_and_degrees():
    a = lac.g1_hermite(p0=(0, 0), theta0=30, p1=(2, 1), theta1=-20, alpha=0.5, degrees=True, solver="toms748",
                       integrator="gauss-kronrod", winding=0)
    b = lac.g1_hermite(p0=(0, 0), theta0=math.radians(30), p1=(2, 1), theta1=math.radians(-20), alpha=0.5)
    assert a.usable and b.usable
    assert a.summary["solver"] != b.summary["solver"] or a.summary["integrator"] != b.summary["integrator"]
    assert a.curve.length == pytest.approx(b.curve.length, rel=1e-10)
    t = lac.g1_hermite(points=[(0, 0), (1, 0), (2, 1)], alpha=2.0, solver="triangle")
    u = lac.g1_hermite(points=[(0, 0), (1, 0), (2, 1)], alpha=2.0)
    assert t.usable and t.summary["solver"] != u.summary["solver"]
    assert t.curve.length == pytest.approx(u.curve.length, rel=1e-9)
    sc = lac.scurve([(0, 0), (1, 0), (2, 1), (3, 1)], alpha=-1.0, solver="s-curve")
    assert sc.usable and sc.curve.length == pytest.approx(lac.scurve([(0, 0), (1, 0), (2, 1), (3, 1)]).curve.length,
                                                          rel=1e-9)
    w = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0, winding=1)
    assert w.usable and w.info["turning"] == pytest.approx(-0.7 + 2 * math.pi, abs=1e-9)


def test_control_triangle_and_scurve_match_cli(lac_cli):
    r = lac.g1_hermite(points=[(0, 0), (1, 0), (2, 1)], alpha=2.0)
    j = cli(lac_cli, "g1", "--points", "0,0 1,0 2,1", "--alpha", "2")
    assert r.status == j["status"] and r.curve.length == pytest.approx(j["length"], rel=1e-15)
    s = lac.scurve([(0, 0), (1, 0), (2, 1), (3, 1)], alpha=-1.0)
    j = cli(lac_cli, "scurve", "--points", "0,0 1,0 2,1 3,1", "--alpha", "-1")
    assert s.status == j["status"] and s.curve.length == pytest.approx(j["length"], rel=1e-15)


def test_g2_hermite_end_conditions():
    g = lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, alpha=-0.5,
                       solver="newton")
    assert g.usable, g.message
    c = g.curve
    assert len(c.segments) == 3
    e = c.eval([0.0, c.length])
    assert (e.x[1], e.y[1]) == pytest.approx((4.0, 0.0), abs=1e-9)
    assert (e.kappa[0], e.kappa[1]) == pytest.approx((0.5, -0.3), abs=1e-8)
    assert (e.theta[0], e.theta[1]) == pytest.approx((0.6, -0.6), abs=1e-9)
    assert g.info["h"] > 1 and g.summary["residuals"]["position"] < 1e-9


def test_g2_matches_cli(lac_cli):
    g = lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, alpha=-0.5,
                       solver="ceres", integrator="rk45")
    j = cli(lac_cli, "g2", "--p0", "0,0", "--theta0", "0.6", "--kappa0", "0.5", "--p1", "4,0", "--theta1", "-0.6",
            "--kappa1", "-0.3", "--alpha", "-0.5", "--solver", "ceres", "--integrator", "rk45")
    assert g.status == j["status"] and g.curve.length == pytest.approx(j["length"], rel=1e-14)
    assert g.summary["solver"] == j["solver"]


def test_chain_compound_space(lac_cli):
    ch = lac.chain([(0, 0), (2, -0.5), (4, 0.3), (5, 2), (4, 4), (0, 3)], alpha=-1.0, closed=True)
    j = cli(lac_cli, "chain", "--points", "0,0 2,-0.5 4,0.3 5,2 4,4 0,3", "--alpha", "-1", "--closed")
    assert ch.status == j["status"] and ch.curve.length == pytest.approx(j["length"], rel=1e-14)
    assert ch.info["pairs"] == 6 and len(ch.info["thetas"]) == 6
    e = ch.curve.eval([0.0, ch.curve.length])
    assert (e.x[1], e.y[1]) == pytest.approx((e.x[0], e.y[0]), abs=1e-8)  # closed
    g2 = lac.chain([(0, 0), (1, 1), (2, 0), (3, 1)], alpha=-1.0, continuity="g2")
    assert g2.usable and len(g2.curve.segments) == 9

    cp = lac.compound([(0, 0), (1, 0), (2, 1)], alpha0=-0.5, alpha1=1.5, r=0.4)
    j = cli(lac_cli, "compound", "--points", "0,0 1,0 2,1", "--alpha0", "-0.5", "--alpha1", "1.5", "--r", "0.4")
    assert cp.status == j["status"] and cp.curve.length == pytest.approx(j["length"], rel=1e-14)
    assert len(cp.curve.segments) == 2 and cp.info["joint"] is not None
    spent = lac.compound([(0, 0), (1, 0), (2, 1)], alpha0=-0.5, alpha1=1.5, r=0.4, integrator="rk4", max_evaluations=10)
    assert spent.status == "max_iterations" and "max_evaluations = 10" in spent.message
    with pytest.raises(ValueError, match="max_evaluations"):
        lac.compound([(0, 0), (1, 0), (2, 1)], alpha0=-0.5, alpha1=1.5, r=0.4, max_evaluations=0)

    sp = lac.space(p0=(0, 0, 0), v0=(1, 0, 0), p1=(1, 1, 0.3), v1=(0, 1, 0.2), alpha=0.0, beta=0.0, omega=0.1)
    j = cli(lac_cli, "space", "--p0", "0,0,0", "--v0", "1,0,0", "--p1", "1,1,0.3", "--v1", "0,1,0.2", "--alpha", "0",
            "--beta", "0", "--omega", "0.1")
    assert sp.status == j["status"] == "ok" and sp.curve.length == pytest.approx(j["length"], rel=1e-12)
    e = sp.curve.sample(5)
    assert (e.x[-1], e.y[-1], e.z[-1]) == pytest.approx((1, 1, 0.3), abs=1e-8)
    assert set(e) >= {"s", "x", "y", "z", "kappa", "tau", "dkappa", "status"}


def test_not_usable_result_has_no_curve():
    # alpha > 0: an inflection is impossible, the S-shaped data has no curve (a proof, status no_solution)
    r = lac.g1_hermite(p0=(0, 0), theta0=0.5, p1=(1, 0), theta1=0.5, alpha=1.0, winding=0)
    assert not r.usable and r.curve is None and r.status == "no_solution" and r.message
    assert r.summary["length"] is None


def test_standard_form_and_quadratic_match_cli(lac_cli):
    c = lac.LaCurve(-1.0, 1.0)
    e = c.eval(s=[0.5])
    j = cli(lac_cli, "eval", "--alpha", "-1", "--lambda", "1", "--s", "0.5")
    assert (e.x[0], e.y[0], e.kappa[0]) == pytest.approx((j["point"]["x"], j["point"]["y"], j["point"]["kappa"]),
                                                         rel=1e-15)
    # clothoid in standard form: ds/drho = rho^(alpha-1)/Lambda = rho^-2, s = 1 - 1/rho, kappa = 1 - s
    assert e.kappa[0] == pytest.approx(0.5, rel=1e-14) and e.dkappa[0] == pytest.approx(-1.0, rel=1e-14)
    t = lac.eval(alpha=2.0, lambda_=0.5, theta=np.array([0.1, 0.2]))
    assert t.theta == pytest.approx([0.1, 0.2], rel=1e-14)

    q = lac.quadratic(alpha=-1.0, gamma=0.5, lambda_=1.0, samples=5)
    j = cli(lac_cli, "quadratic", "--alpha", "-1", "--gamma", "0.5", "--lambda", "1", "--samples", "5")
    for p, x, y in zip(j["points"], q.x, q.y):
        assert (p["x"], p["y"]) == pytest.approx((x, y), rel=1e-14, abs=1e-15)
    qc = lac.QuadraticCurve(-1.0, 0.5, 1.0)
    pts = qc.eval(np.linspace(-0.5, 0.5, 201))
    h = pts.s[1] - pts.s[0]
    assert np.max(np.abs(np.gradient(pts.kappa, h)[1:-1] - pts.dkappa[1:-1])) < 1e-3 * np.max(np.abs(pts.dkappa))
