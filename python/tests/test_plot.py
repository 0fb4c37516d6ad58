"""lac.plot: the figure's panels, and its LCG: a straight line of slope alpha for one LA segment."""
import numpy as np
import pytest

import lac


def test_plot_curve_comb_kappa_lcg(tmp_path):
    import matplotlib

    matplotlib.use("Agg")
    r = lac.g1_hermite(p0=(0, 0), theta0=0.9, p1=(3, 0), theta1=-0.2, alpha=-0.7)
    assert r.usable
    fig = lac.plot(r.curve, comb=True, lcg=True)
    assert len(fig.axes) == 3
    lx, ly = fig.axes[2].lines[0].get_data()
    assert len(lx) > 100
    slope, _ = np.polyfit(lx, ly, 1)
    assert slope == pytest.approx(-0.7, abs=1e-6)
    path = tmp_path / "g1.png"
    fig.savefig(path, dpi=60)
    assert path.stat().st_size > 5000
    fig2 = lac.plot(lac.LaCurve(2.0, 0.5).eval(s=np.linspace(0, 1, 50)), comb=False, lcg=False)
    assert len(fig2.axes) == 2
