"""lac: log-aesthetic curves in Python (bindings of the C++ library; docs/python.md).

Constructions with the names and options of the ``lac`` command line::

    import lac, numpy as np
    r = lac.g1_hermite(p0=(0, 0), theta0=0.3, p1=(1, 0), theta1=-0.4, alpha=-1.0)
    r.status, r.message, r.usable, r.summary
    c = r.curve
    pts = c.eval(np.linspace(0, c.length, 1001))      # pts.x, pts.y, pts.kappa, ...
    t = lac.solve_batch("g1", {"p0": (0, 0), "p1": (1, 0), "theta0": th0, "theta1": th1, "alpha": -1.0})
    lac.plot(c, comb=True, lcg=True)

Invalid input raises lac.InputError (a ValueError) whose message names the parameter and its range.
"""
from ._lac import (  # noqa: F401
    Curve,
    InputError,
    LaCurve,
    QuadraticCurve,
    Result,
    SpaceCurve,
    __version__,
    append,
    chain,
    closest_point,
    compound,
    dawson,
    erf,
    erf_inv,
    erfc,
    erfc_inv,
    erfcx,
    erfi,
    erfi_inv,
    export_curve,
    g1_hermite,
    g2_hermite,
    gamma_inc,
    gamma_inc_detailed,
    intersect_curves,
    intersect_line,
    intersect_plane,
    mirror,
    offset,
    offset_cusp,
    reverse,
    rotate,
    scale,
    scurve,
    space,
    split,
    to_bspline,
    translate,
    trim,
)
from ._columns import Columns  # noqa: F401


def solve_batch(kind, data, **options):
    """Solves one problem per row (numpy columns, scalars broadcast): see lac.batch.solve_batch.
    numpy is imported on the first call, so that ``import lac`` needs only the extension."""
    from .batch import solve_batch as _solve_batch

    return _solve_batch(kind, data, **options)


def eval(*, alpha, lambda_, theta=None, s=None, form="auto", integrator="gauss-kronrod"):  # noqa: A001
    """Points of the standard-form LA curve at theta or s (arrays), as ``lac eval``: columns s, x, y,
    theta, kappa, rho, dkappa, status, error_estimate."""
    return LaCurve(alpha, lambda_).eval(theta=theta, s=s, form=form, integrator=integrator)


def quadratic(*, alpha, gamma, lambda_, s=None, s_from=None, s_to=None, samples=100, integrator="gauss-kronrod",
              inverse="ours", through_inflection=False):
    """Points of the quadratic LA curve, as ``lac quadratic``: at the arc lengths s, or `samples` points
    from s_from to s_to (default: the curve's default_range, as ``lac quadratic``)."""
    import numpy as np

    c = QuadraticCurve(alpha, gamma, lambda_, inverse=inverse, through_inflection=through_inflection)
    if s is None:
        lo, hi = c.default_range
        s0 = s_from if s_from is not None else lo
        s1 = s_to if s_to is not None else hi
        s = np.linspace(s0, s1, samples)
    return c.eval(s, integrator=integrator)


def plot(curve, comb=True, lcg=True, **kwargs):
    """Figure of a curve: the curve with its curvature comb, kappa(s) and the logarithmic curvature
    graph (lac.plotting.plot_curve; matplotlib)."""
    from .plotting import plot_curve

    return plot_curve(curve, comb=comb, lcg=lcg, **kwargs)
