"""The export bindings for space curves (lac.to_bspline, lac.export_curve on a lac.SpaceCurve): the
B-spline evaluated by de Boor's algorithm here stays within max_deviation of the curve; DXF is read
back by ezdxf with its z coordinates; .svg is refused."""
import numpy as np
import pytest

import lac


@pytest.fixture(scope="module")
def curve():
    """A compound-rhythm segment with the endpoints of tests/cli/cli_space_test.cpp (000 Fig. 5a)."""
    r = lac.space(p0=(0, 0, 0), v0=(1, 0, 0), p1=(0.36235775447667362, 0.93203908596722629, 0),
                  v1=(-0.4838825660252134, 0.8293701183329452, 0.279289937364832), alpha=-1, beta=-1, omega=0.1,
                  type=1, alpha1=1, beta1=1, r_theta=0.5)
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
def test_space_bspline_within_its_bound(curve, degree):
    b = lac.to_bspline(curve, tolerance=1e-6, degree=degree)
    assert b["usable"] and b["status"] == "ok", b["message"]
    assert b["degree"] == degree and b["curvature_monotone"] is None
    assert b["continuity"] == ("G2" if degree == 5 else "G1")
    assert 0 < b["max_deviation"] <= 1e-6
    knots, cp = b["knots"], b["control_points"]
    assert cp.shape[1] == 3 and len(knots) == len(cp) + degree + 1
    s = np.linspace(0, curve.length, 1001)
    pts = curve.eval(s)
    got = np.array([de_boor(knots, cp, degree, t) for t in s])
    dist = np.sqrt((got[:, 0] - pts.x) ** 2 + (got[:, 1] - pts.y) ** 2 + (got[:, 2] - pts.z) ** 2)
    assert dist.max() <= b["max_deviation"]


def test_space_export_dxf_has_z_and_svg_is_refused(curve, tmp_path):
    ezdxf = pytest.importorskip("ezdxf")
    path = tmp_path / "space.dxf"
    r = lac.export_curve(curve, str(path))
    assert r["file"] == str(path) and r["format"] == "dxf" and r["degree"] == 5, r["message"]
    spline = list(ezdxf.readfile(str(path)).modelspace().query("SPLINE"))[0]
    zs = [p[2] for p in spline.control_points]
    assert len(zs) == len(r["control_points"]) and max(abs(z) for z in zs) > 1e-3
    with pytest.raises(ValueError, match="path"):
        lac.export_curve(curve, str(tmp_path / "space.svg"))
    with pytest.raises(ValueError, match="degree"):
        lac.to_bspline(curve, degree=4)
