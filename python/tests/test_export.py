"""The export bindings (lac.to_bspline, lac.export_curve) for planar, quadratic and space curves: the
B-spline evaluated by de Boor's algorithm here stays within its certified bound of the curve; files
are written in every format the module has, and DXF is read back by ezdxf (with its z coordinates
for a space curve, where .svg is refused)."""
import numpy as np
import pytest

import lac


@pytest.fixture(scope="module")
def curve():
    """The acceptance curve of docs/export.md (a G2 triple at alpha = -0.5)."""
    r = lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, alpha=-0.5)
    assert r.usable, r.message
    return r.curve


def de_boor(knots, points, p, t):
    k = np.searchsorted(knots, t, side="right") - 1
    k = min(max(k, p), len(points) - 1)
    d = [points[j + k - p].copy() for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            a = (t - knots[j + k - p]) / (knots[j + 1 + k - r] - knots[j + k - p])
            d[j] = (1 - a) * d[j - 1] + a * d[j]
    return d[p]


@pytest.mark.parametrize("degree", [3, 5])
def test_bspline_within_its_certified_bound(curve, degree):
    b = lac.to_bspline(curve, tolerance=1e-6, degree=degree)
    assert b["usable"] and b["status"] == "ok", b["message"]
    assert b["degree"] == degree
    assert 0 < b["max_deviation"] <= 1e-6
    knots, cp = b["knots"], b["control_points"]
    assert cp.shape[1] == 2 and len(knots) == len(cp) + degree + 1
    # The parameter is the arc length: compare at equal s.
    s = np.linspace(0, curve.length, 1001)
    pts = curve.eval(s, integrator="gauss-kronrod")
    got = np.array([de_boor(knots, cp, degree, t) for t in s])
    dist = np.hypot(got[:, 0] - pts.x, got[:, 1] - pts.y)
    assert dist.max() <= b["max_deviation"]
    # remove_knots=False: the Hermite spans' B-spline, more control points, the same bound's meaning.
    h = lac.to_bspline(curve, tolerance=1e-6, degree=degree, remove_knots=False)
    assert h["usable"] and len(h["control_points"]) > len(cp)
    assert len(h["control_points"]) == (3 if degree == 5 else 2) * h["spans"] + (3 if degree == 5 else 2)
    # fit=True: at most as many control points, within its own certified bound.
    f = lac.to_bspline(curve, tolerance=1e-6, degree=degree, fit=True)
    assert f["usable"] and len(f["control_points"]) <= len(cp) and f["max_deviation"] <= 1e-6
    got = np.array([de_boor(f["knots"], f["control_points"], degree, t) for t in s])
    assert np.hypot(got[:, 0] - pts.x, got[:, 1] - pts.y).max() <= f["max_deviation"]
    # fit_max_degree=8: fits of degree 3 to 8, at most as many points as the fit of `degree`.
    g = lac.to_bspline(curve, tolerance=1e-6, degree=degree, fit=True, fit_max_degree=8)
    assert g["usable"] and len(g["control_points"]) <= len(f["control_points"]) and 3 <= g["degree"] <= 8
    got = np.array([de_boor(g["knots"], g["control_points"], g["degree"], t) for t in s])
    assert np.hypot(got[:, 0] - pts.x, got[:, 1] - pts.y).max() <= g["max_deviation"] <= 1e-6
    with pytest.raises(ValueError, match="fit_max_degree"):
        lac.to_bspline(curve, fit=True, fit_max_degree=10)


def test_tolerance_beyond_reach_is_inaccurate(curve):
    b = lac.to_bspline(curve, tolerance=1e-15, max_spans=10)
    assert not b["usable"]


def test_export_dxf_reads_back(curve, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    path = tmp_path / "curve.dxf"
    r = lac.export_curve(curve, str(path), tolerance=1e-6)
    assert r["file"] == str(path) and r["format"] == "dxf", r["message"]
    doc = ezdxf.readfile(str(path))
    splines = list(doc.modelspace().query("SPLINE"))
    assert len(splines) == 1
    assert len(list(splines[0].control_points)) == len(r["control_points"])
    # fit_max_degree: the fits of degree 3 up to it; the file holds the one chosen.
    f = lac.export_curve(curve, str(path), tolerance=1e-6, fit_max_degree=8)
    assert f["usable"] and f["max_deviation"] <= 1e-6 and 3 <= f["degree"] <= 8
    assert len(f["control_points"]) <= len(r["control_points"])
    spline = list(ezdxf.readfile(str(path)).modelspace().query("SPLINE"))[0]
    assert spline.dxf.degree == f["degree"] and len(list(spline.control_points)) == len(f["control_points"])
    with pytest.raises(ValueError, match="fit_max_degree"):
        lac.export_curve(curve, str(tmp_path / "curve.svg"), fit_max_degree=5)


def test_export_svg_is_cubic_and_bad_input_names_the_parameter(curve, tmp_path):
    r = lac.export_curve(curve, str(tmp_path / "curve.svg"))
    assert r["degree"] == 3 and r["file"]
    assert "<path" in (tmp_path / "curve.svg").read_text()
    with pytest.raises(ValueError, match="degree"):
        lac.export_curve(curve, str(tmp_path / "curve.svg"), degree=5)
    with pytest.raises(ValueError, match="path"):
        lac.export_curve(curve, str(tmp_path / "curve.obj"))
    with pytest.raises(ValueError, match="degree"):
        lac.to_bspline(curve, degree=4)


def test_step_and_iges_are_written_when_built_with_opencascade(curve, tmp_path):
    for name in ("curve.step", "curve.igs"):
        path = tmp_path / name
        try:
            r = lac.export_curve(curve, str(path), tolerance=1e-6)
        except ValueError as e:  # a module built without OpenCASCADE says so, naming the path
            assert "OpenCASCADE" in str(e) and "path" in str(e)
            continue
        assert r["file"] == str(path) and path.stat().st_size > 0
    assert "B_SPLINE_CURVE_WITH_KNOTS" in (tmp_path / "curve.step").read_text() or not (tmp_path / "curve.step").exists()


@pytest.mark.parametrize("degree", [3, 5])
def test_quadratic_curve_within_its_certified_bound(degree):
    """lac.QuadraticCurve: the drawn arc (default_range) against the curve's own positions."""
    q = lac.QuadraticCurve(-1.0, -0.3, 1.0)
    s0, s1 = q.default_range
    b = lac.to_bspline(q, tolerance=1e-7, degree=degree)
    assert b["usable"] and b["status"] == "ok", b["message"]
    assert 0 < b["max_deviation"] <= 1e-7
    knots, cp = b["knots"], b["control_points"]
    assert knots[-1] == pytest.approx(s1 - s0, rel=1e-15)
    s = np.linspace(s0, s1, 1001)
    pts = q.eval(s, integrator="gauss-kronrod")
    got = np.array([de_boor(knots, cp, degree, t) for t in s - s0])
    dist = np.hypot(got[:, 0] - pts.x, got[:, 1] - pts.y)
    assert dist.max() <= b["max_deviation"] + pts.error_estimate.max()
    # An explicit arc, and the file.
    part = lac.to_bspline(q, s_from=-0.2, s_to=0.5, tolerance=1e-8)
    assert part["status"] == "ok" and part["knots"][-1] == pytest.approx(0.7, rel=1e-15)
    with pytest.raises(lac.InputError):
        lac.to_bspline(q, s_from=0.5, s_to=0.5)


def test_quadratic_export_dxf_reads_back(tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    q = lac.QuadraticCurve(2.5, 0.3, 0.7)
    path = tmp_path / "quadratic.dxf"
    r = lac.export_curve(q, str(path))
    assert r["file"] == str(path) and r["status"] == "ok", r["message"]
    splines = list(ezdxf.readfile(str(path)).modelspace().query("SPLINE"))
    assert len(splines) == 1 and len(list(splines[0].control_points)) == len(r["control_points"])


@pytest.fixture(scope="module")
def space_curve():
    """A compound-rhythm segment with the endpoints of tests/cli/cli_space_test.cpp (000 Fig. 5a)."""
    r = lac.space(p0=(0, 0, 0), v0=(1, 0, 0), p1=(0.36235775447667362, 0.93203908596722629, 0),
                  v1=(-0.4838825660252134, 0.8293701183329452, 0.279289937364832), alpha=-1, beta=-1, omega=0.1,
                  type=1, alpha1=1, beta1=1, r_theta=0.5)
    assert r.usable, r.message
    return r.curve


@pytest.mark.parametrize("degree", [3, 5])
def test_space_bspline_within_its_bound(space_curve, degree):
    b = lac.to_bspline(space_curve, tolerance=1e-6, degree=degree)
    assert b["usable"] and b["status"] == "ok", b["message"]
    assert b["degree"] == degree and b["curvature_monotone"] is None
    assert b["continuity"] == ("G2" if degree == 5 else "G1")
    assert 0 < b["max_deviation"] <= 1e-6
    knots, cp = b["knots"], b["control_points"]
    assert cp.shape[1] == 3 and len(knots) == len(cp) + degree + 1
    s = np.linspace(0, space_curve.length, 1001)
    pts = space_curve.eval(s)
    got = np.array([de_boor(knots, cp, degree, t) for t in s])
    dist = np.sqrt((got[:, 0] - pts.x) ** 2 + (got[:, 1] - pts.y) ** 2 + (got[:, 2] - pts.z) ** 2)
    assert dist.max() <= b["max_deviation"]


def test_space_export_dxf_has_z_and_svg_is_refused(space_curve, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    path = tmp_path / "space.dxf"
    r = lac.export_curve(space_curve, str(path))
    assert r["file"] == str(path) and r["format"] == "dxf" and r["degree"] == 5, r["message"]
    spline = list(ezdxf.readfile(str(path)).modelspace().query("SPLINE"))[0]
    zs = [p[2] for p in spline.control_points]
    assert len(zs) == len(r["control_points"]) and max(abs(z) for z in zs) > 1e-3
    with pytest.raises(ValueError, match="path"):
        lac.export_curve(space_curve, str(tmp_path / "space.svg"))
    with pytest.raises(ValueError, match="degree"):
        lac.to_bspline(space_curve, degree=4)
