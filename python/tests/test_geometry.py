"""The geometry bindings (lac.closest_point, intersect_line, intersect_curves, offset, offset_cusp,
translate, rotate, scale, mirror, split, trim, append, reverse) against dense samples of the curve."""
import math

import numpy as np
import pytest

import lac


@pytest.fixture(scope="module")
def spiral():
    """A G2 Hermite curve turning about 1.5 times (several local minima of the distance)."""
    r = lac.g2_hermite(p0=(0, 0), theta0=0.0, kappa0=1.0, p1=(0.3, 0.2), theta1=9.0, kappa1=8.0, alpha=-1.0)
    assert r.usable, r.message
    return r.curve


def dense(c, n=200001):
    return c.eval(np.linspace(0, c.length, n))


def test_closest_point_is_the_global_minimum(spiral):
    pts = dense(spiral)
    for q in [(0.1, 0.05), (-0.2, 0.3), (0.5, -0.4), (0.15, 0.1)]:
        r = lac.closest_point(spiral, q)
        assert r["status"] == "ok", r["message"]
        d = np.hypot(pts.x - q[0], pts.y - q[1])
        h = spiral.length / (len(pts.s) - 1)
        assert d.min() - h <= r["distance"] <= d.min() + 1e-12
        assert math.isclose(math.dist(r["point"], q), r["distance"], rel_tol=1e-12, abs_tol=1e-15)
        x, y = spiral.eval([r["s"]]).x[0], spiral.eval([r["s"]]).y[0]
        assert math.dist((x, y), r["point"]) < 1e-12


def test_intersect_line_finds_every_sign_change(spiral):
    pts = dense(spiral)
    for angle in np.linspace(0.1, 3.0, 7):
        p, d = (0.1, 0.1), (math.cos(angle), math.sin(angle))
        r = lac.intersect_line(spiral, p, d)
        assert r["status"] == "ok", r["message"]
        h = d[0] * (pts.y - p[1]) - d[1] * (pts.x - p[0])
        changes = np.nonzero(np.sign(h[:-1]) * np.sign(h[1:]) < 0)[0]
        assert len(r["points"]) == len(changes)
        for x, i in zip(r["points"], changes):
            assert pts.s[i] - 1e-12 <= x["s"] <= pts.s[i + 1] + 1e-12 and x["kind"] == "crossing"


def test_intersect_curves_with_a_mirror_image(spiral):
    c = spiral.eval([0.7 * spiral.length])
    p, t = (c.x[0], c.y[0]), (math.cos(c.theta[0]), math.sin(c.theta[0]))
    r = lac.intersect_curves(spiral, lac.mirror(spiral, p, t))
    assert r["status"] == "ok", r["message"]
    kinds = [x["kind"] for x in r["points"]]
    assert kinds.count("tangent") == 1
    touch = next(x for x in r["points"] if x["kind"] == "tangent")
    assert abs(touch["s"] - 0.7 * spiral.length) < 1e-5
    on_line = [x["s"] for x in r["points"] if x["kind"] == "crossing" and abs(x["s"] - x["t"]) < 1e-9]
    line = [x["s"] for x in lac.intersect_line(spiral, p, t)["points"] if x["kind"] == "crossing"]
    assert np.allclose(on_line, line, atol=1e-10)


def test_offset_and_cusp(spiral):
    s = np.linspace(0, spiral.length, 101)
    pts = spiral.eval(s)
    d = 0.05
    o = lac.offset(spiral, s, d)
    assert np.all(o.status == "ok")
    assert np.allclose(o.x, pts.x - d * np.sin(pts.theta), atol=1e-12)
    assert np.allclose(o.y, pts.y + d * np.cos(pts.theta), atol=1e-12)
    assert np.allclose(o.factor, 1 - d * pts.kappa)
    cusp = lac.offset_cusp(spiral, 0.2)  # kappa passes 1/0.2 = 5 on the way from 1 to 8
    assert cusp is not None and 0 < cusp < spiral.length
    assert math.isclose(spiral.kappa(cusp), 5.0, rel_tol=1e-9)
    assert lac.offset_cusp(spiral, -0.1) is None


def test_transforms(spiral):
    L = spiral.length
    m = lac.mirror(spiral, (0, 0), (1, 0))
    assert math.isclose(m.length, L) and math.isclose(m.kappa(0.3 * L), -spiral.kappa(0.3 * L), rel_tol=1e-12)
    assert [seg["alpha"] for seg in m.segments] == [seg["alpha"] for seg in spiral.segments]
    sc = lac.scale(spiral, 2.0, (1, 1))
    assert math.isclose(sc.length, 2 * L) and math.isclose(sc.kappa(0.6 * L), spiral.kappa(0.3 * L) / 2, rel_tol=1e-12)
    r = lac.rotate(lac.translate(spiral, (1, 2)), 0.5, (1, 2))
    a, b = spiral.eval([0.4 * L]), r.eval([0.4 * L])
    z = complex(a.x[0], a.y[0]) * complex(math.cos(0.5), math.sin(0.5)) + complex(1, 2)
    assert abs(z - complex(b.x[0], b.y[0])) < 1e-12
    parts = lac.split(spiral, 0.4 * L)
    assert parts.usable and math.isclose(parts.curve[0].length + parts.curve[1].length, L)
    back = lac.append(parts.curve[0], parts.curve[1], 1e-9)
    assert back.usable and math.isclose(back.curve.length, L)
    t = lac.trim(spiral, 0.2 * L, 0.5 * L)
    assert t.usable and math.isclose(t.curve.length, 0.3 * L)
    rv = lac.reverse(spiral)
    assert rv.usable and math.isclose(rv.curve.kappa(0.1 * L), -spiral.kappa(0.9 * L), rel_tol=1e-9)


def test_bad_input(spiral):
    with pytest.raises(lac.InputError) as e:
        lac.scale(spiral, -1.0)
    assert e.value.parameter == "factor"
    with pytest.raises(lac.InputError) as e:
        lac.append(spiral, lac.translate(spiral, (5, 0)), 1e-9)
    assert e.value.parameter == "b"
    with pytest.raises(lac.InputError) as e:
        lac.closest_point(spiral, (0, 0), tolerance=0.0)
    assert e.value.parameter == "tolerance"
    with pytest.raises(lac.InputError) as e:
        lac.intersect_line(spiral, (0, 0), (0, 0))
    assert e.value.parameter == "direction"
    with pytest.raises(lac.InputError) as e:
        lac.split(spiral, spiral.length)
    assert e.value.parameter == "s"


def test_quadratic_arc_closest_point_and_line():
    """lac.closest_point / intersect_line on an arc of a QuadraticCurve against its dense samples."""
    q = lac.QuadraticCurve(0.5, 0.2, 1.0)
    s0, s1 = -3.0, 3.0  # turning about 28.6 rad: several local minima
    pts = q.eval(np.linspace(s0, s1, 200001))
    h = (s1 - s0) / (len(pts.s) - 1)
    for p in [(0.1, 0.05), (-0.2, 0.3), (0.5, -0.4)]:
        r = lac.closest_point(q, p, s_from=s0, s_to=s1)
        assert r["status"] == "ok", r["message"]
        d = np.hypot(pts.x - p[0], pts.y - p[1])
        assert d.min() - h <= r["distance"] <= d.min() + 1e-12
        assert s0 <= r["s"] <= s1
        e = q.eval([r["s"]])
        assert math.dist((e.x[0], e.y[0]), r["point"]) < 1e-11
    r = lac.intersect_line(q, (0.1, 0.1), (1.0, 0.3), s_from=s0, s_to=s1)
    assert r["status"] == "ok", r["message"]
    hv = 1.0 * (pts.y - 0.1) - 0.3 * (pts.x - 0.1)
    changes = np.nonzero(np.sign(hv[:-1]) * np.sign(hv[1:]) < 0)[0]
    assert len(r["points"]) == len(changes) >= 2
    for x, i in zip(r["points"], changes):
        assert pts.s[i] - 1e-12 <= x["s"] <= pts.s[i + 1] + 1e-12
    # The default arc is the curve's default_range.
    lo, hi = q.default_range
    r = lac.closest_point(q, (0.3, 0.2))
    assert r["status"] == "ok" and lo <= r["s"] <= hi
    with pytest.raises(lac.InputError) as e:
        lac.closest_point(q, (0, 0), s_from=1.0, s_to=0.0)
    assert e.value.parameter == "s1"


def polyline_crossings(p, q):
    """Pairs (i, j) of crossing segments of two polylines (x, y arrays), vectorized."""
    ax, ay, bx, by = p.x[:, None], p.y[:, None], q.x[None, :], q.y[None, :]
    dax, day = np.diff(p.x)[:, None], np.diff(p.y)[:, None]
    dbx, dby = np.diff(q.x)[None, :], np.diff(q.y)[None, :]
    den = dax * dby - day * dbx
    with np.errstate(divide="ignore", invalid="ignore"):
        u = ((bx[:, :-1] - ax[:-1]) * dby - (by[:, :-1] - ay[:-1]) * dbx) / den
        v = ((bx[:, :-1] - ax[:-1]) * day - (by[:, :-1] - ay[:-1]) * dax) / den
    return np.argwhere((u >= 0) & (u < 1) & (v >= 0) & (v < 1))


def test_quadratic_arc_intersect_curves(spiral):
    """lac.intersect_curves with an arc of a QuadraticCurve against a Curve and against another
    arc: as many points as the dense polylines cross, each on both curves, inside both arcs."""
    q = lac.QuadraticCurve(0.5, 0.2, 1.0)
    s0, s1 = -3.0, 3.0
    a = q.eval(np.linspace(s0, s1, 3001))
    b = dense(spiral, 3001)
    r = lac.intersect_curves(q, spiral, s_from=s0, s_to=s1)
    assert r["status"] == "ok", r["message"]
    assert len(r["points"]) == len(polyline_crossings(a, b)) >= 2
    for x in r["points"]:
        assert s0 <= x["s"] <= s1
        e, f = q.eval([x["s"]]), spiral.eval([x["t"]])
        assert math.dist((e.x[0], e.y[0]), x["point"]) < 1e-9
        assert math.dist((f.x[0], f.y[0]), x["point"]) < 1e-9
    o = lac.QuadraticCurve(0.3, 0.25, 1.2)
    t0, t1 = -3.0, -0.2  # its inner coils (kappa grows as s decreases) cross the first arc's
    c = o.eval(np.linspace(t0, t1, 3001))
    r = lac.intersect_curves(q, o, a_from=s0, a_to=s1, b_from=t0, b_to=t1)
    assert r["status"] == "ok", r["message"]
    assert len(r["points"]) == len(polyline_crossings(a, c)) >= 8
    for x in r["points"]:
        assert s0 <= x["s"] <= s1 and t0 <= x["t"] <= t1
        e, f = q.eval([x["s"]]), o.eval([x["t"]])
        assert math.dist((e.x[0], e.y[0]), x["point"]) < 1e-9
        assert math.dist((f.x[0], f.y[0]), x["point"]) < 1e-9
    with pytest.raises(lac.InputError) as e:
        lac.intersect_curves(q, o, a_from=1.0, a_to=0.0)
    assert e.value.parameter == "a1"


def test_space_curve_closest_point_and_plane():
    """lac.closest_point / intersect_plane on a lac.SpaceCurve against its dense samples."""
    sp = lac.space(p0=(0, 0, 0), v0=(1, 0, 0), p1=(1, 1, 0.3), v1=(0, 1, 0.2), alpha=0.0, beta=0.0, omega=0.1)
    assert sp.usable, sp.message
    c = sp.curve
    e = c.sample(20001)
    q = (0.8, 0.2, 0.5)
    r = lac.closest_point(c, q)
    assert r["status"] == "ok", r["message"]
    d = np.sqrt((e.x - q[0]) ** 2 + (e.y - q[1]) ** 2 + (e.z - q[2]) ** 2)
    h = c.length / 20000
    assert d.min() - h <= r["distance"] <= d.min() + 1e-12
    assert math.isclose(math.dist(r["point"], q), r["distance"], rel_tol=1e-12)
    for p, n in [((0.5, 0.5, 0.1), (1, -1, 0.2)), ((0.2, 0.0, 0.0), (1, 0, 0)), ((0, 0, 0.15), (0, 0, 1))]:
        x = lac.intersect_plane(c, p, n)
        assert x["status"] == "ok", x["message"]
        u = np.array(n, dtype=float) / np.linalg.norm(n)
        hv = u[0] * (e.x - p[0]) + u[1] * (e.y - p[1]) + u[2] * (e.z - p[2])
        changes = np.nonzero(np.sign(hv[:-1]) * np.sign(hv[1:]) < 0)[0]
        assert len(x["points"]) == len(changes) >= 1
        for y, i in zip(x["points"], changes):
            assert e.s[i] - 1e-12 <= y["s"] <= e.s[i + 1] + 1e-12 and y["kind"] == "crossing"
            assert abs(np.dot(u, np.subtract(y["point"], p))) == pytest.approx(y["residual"], abs=1e-15)
    with pytest.raises(lac.InputError) as err:
        lac.intersect_plane(c, (0, 0, 0), (0, 0, 0))
    assert err.value.parameter == "normal"
