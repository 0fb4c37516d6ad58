"""lac.InputError (a ValueError naming the parameter and its range), unknown options, special functions
against mpmath."""
import math

import mpmath
import numpy as np
import pytest

import lac


def test_input_error_names_parameter_and_range():
    with pytest.raises(ValueError) as e:
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=7.0)
    assert isinstance(e.value, lac.InputError) and e.value.parameter == "alpha"
    assert "alpha" in str(e.value) and "5" in str(e.value)
    with pytest.raises(lac.InputError, match="p1"):
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(0, 0), theta1=-0.4, alpha=-1.0)
    with pytest.raises(lac.InputError, match="theta1 is required"):
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), alpha=-1.0)
    with pytest.raises(lac.InputError, match="winding"):
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0, winding=1000)
    with pytest.raises(lac.InputError, match="integrator"):
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0, integrator="simpson")
    with pytest.raises(lac.InputError, match=r"alpha.*\[-5, 5\]|alpha.*-5"):
        lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, alpha=9.0)
    with pytest.raises(lac.InputError, match="solver"):
        lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, solver="gauss")
    with pytest.raises(lac.InputError, match="stagnation_window"):
        lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, stagnation_window=-1)
    with pytest.raises(lac.InputError, match="p0"):
        lac.g1_hermite(p0=(0, 0, 1), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0)
    with pytest.raises(lac.InputError, match="lambda"):
        lac.LaCurve(1.0, -1.0)
    with pytest.raises(lac.InputError, match="s"):
        r = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0)
        r.curve.eval([r.curve.length * 2])


def test_unknown_option_suggests_the_closest():
    with pytest.raises(TypeError, match="did you mean 'solver'"):
        lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0, solverr="auto")
    with pytest.raises(TypeError, match="did you mean 'fallback'"):
        lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, fallbak=False)


def test_special_functions_against_mpmath():
    mpmath.mp.dps = 30
    x = np.array([-3.0, -0.7, 0.0, 0.3, 1.5, 4.0])
    for f, ref in ((lac.erf, mpmath.erf), (lac.erfc, mpmath.erfc), (lac.erfi, mpmath.erfi),
                   (lac.dawson, lambda v: mpmath.sqrt(mpmath.pi) / 2 * mpmath.exp(-v * v) * mpmath.erfi(v)),
                   (lac.erfcx, lambda v: mpmath.exp(v * v) * mpmath.erfc(v))):
        got = f(x)
        assert got.shape == x.shape
        for g, v in zip(got, x):
            r = float(ref(mpmath.mpf(v)))
            assert g == pytest.approx(r, rel=1e-13, abs=1e-300), (f, v)
    y = np.array([-0.9, -0.1, 0.2, 0.99])
    assert lac.erf(lac.erf_inv(y)) == pytest.approx(y, rel=1e-14)
    assert lac.erf(lac.erf_inv(y, method="hybrid-003")) == pytest.approx(y, rel=1e-10)
    yi = np.array([-1e5, -2.0, 0.5, 30.0, 1e200])
    assert lac.erfi(lac.erfi_inv(yi)) == pytest.approx(yi, rel=1e-13)
    assert lac.erfc(lac.erfc_inv(np.array([0.1, 1.5]))) == pytest.approx([0.1, 1.5], rel=1e-14)
    for a, z in ((0.5, 2 + 1j), (-1.5, 0.3j), (2.0, 10.0), (0.0, 1 - 1j)):
        ref = complex(mpmath.gammainc(a, z))
        assert complex(lac.gamma_inc(a, z)) == pytest.approx(ref, rel=1e-13)
        d = lac.gamma_inc_detailed(a, z)
        assert d["status"] == "ok" and d["value"] == pytest.approx(ref, rel=1e-13) and d["region"]
    assert complex(lac.gamma_inc(1.0, 50.0, scaled=True)) == pytest.approx(
        complex(mpmath.exp(50) * mpmath.power(50, -1) * mpmath.gammainc(1, 50)), rel=1e-13)
    with pytest.raises(lac.InputError, match="y"):
        lac.erf_inv(1.5)
    with pytest.raises(lac.InputError, match="a"):
        lac.gamma_inc(20.0, 1.0)
    assert math.isinf(lac.erfi(30.0))
