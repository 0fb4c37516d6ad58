"""Figures of lac curves with matplotlib: the curve with its curvature comb, kappa(s) and the
logarithmic curvature graph (LCG), in which an LA segment of slope alpha is a straight line
log(rho ds/drho) = alpha log(rho) - log(Lambda) (docs/math.md §1)."""
import numpy as np


def _columns(curve, n):
    """Columns s, x, y, theta, kappa, dkappa of a lac.Curve (n points), or the columns themselves."""
    if hasattr(curve, "eval") and hasattr(curve, "length"):
        if hasattr(curve, "segments"):
            return curve.sample(n), [seg["length"] for seg in curve.segments]
        raise TypeError("lac.plot: a SpaceCurve has no planar figure; plot its eval() columns x, y, z yourself")
    if isinstance(curve, dict) and all(k in curve for k in ("x", "y", "kappa")):
        return curve, None
    raise TypeError("lac.plot: expected a lac.Curve or columns with x, y, kappa (e.g. LaCurve.eval)")


def lcg_points(kappa, dkappa):
    """(log rho, log(rho ds/drho)) where both are finite: rho ds/drho = -kappa / (dkappa/ds)."""
    kappa = np.asarray(kappa, float)
    dkappa = np.asarray(dkappa, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        x = -np.log(np.abs(kappa))
        y = np.log(np.abs(kappa / dkappa))
    ok = np.isfinite(x) & np.isfinite(y)
    return x[ok], y[ok]


def plot_curve(curve, comb=True, lcg=True, kappa_plot=True, n=400, comb_teeth=80, comb_scale=None, fig=None,
               title=None):
    """Figure (matplotlib) of `curve` (a lac.Curve, or columns with s, x, y, theta, kappa, dkappa):

    - the curve, with its curvature comb (teeth -kappa N, scaled to 20 % of the curve's size unless
      comb_scale is given) when comb is true;
    - kappa(s) when kappa_plot is true;
    - the LCG, log(rho ds/drho) against log rho, when lcg is true (needs dkappa).

    Returns the Figure; save it with fig.savefig(path)."""
    import matplotlib.pyplot as plt

    pts, seg_lengths = _columns(curve, n)
    x, y = np.asarray(pts["x"]), np.asarray(pts["y"])
    kappa = np.asarray(pts["kappa"])
    panels = 1 + bool(kappa_plot) + bool(lcg and "dkappa" in pts)
    if fig is None:
        fig = plt.figure(figsize=(4.5 * panels, 4.2), layout="constrained")
    axes = fig.subplots(1, panels, squeeze=False)[0]
    ax = axes[0]
    ax.plot(x, y, color="C0", lw=1.6, label="curve")
    if comb and "theta" in pts:
        theta = np.asarray(pts["theta"])
        idx = np.unique(np.linspace(0, len(x) - 1, min(comb_teeth, len(x))).astype(int))
        size = max(np.ptp(x[np.isfinite(x)]), np.ptp(y[np.isfinite(y)]), 1e-300)
        kmax = np.nanmax(np.abs(kappa[idx])) if np.any(np.isfinite(kappa[idx])) else 0
        scale = comb_scale if comb_scale is not None else (0.2 * size / kmax if kmax > 0 else 0)
        nx, ny = -np.sin(theta[idx]), np.cos(theta[idx])
        tx, ty = x[idx] - scale * kappa[idx] * nx, y[idx] - scale * kappa[idx] * ny
        for i in range(len(idx)):
            ax.plot([x[idx[i]], tx[i]], [y[idx[i]], ty[i]], color="0.6", lw=0.6)
        ax.plot(tx, ty, color="C3", lw=0.9, label="curvature comb")
        ax.legend(loc="best", fontsize="small")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_title(title or "curve")
    k = 1
    if kappa_plot:
        axk = axes[k]
        k += 1
        axk.plot(pts["s"], kappa, color="C1")
        if seg_lengths and len(seg_lengths) > 1:
            for sj in np.cumsum(seg_lengths)[:-1]:
                axk.axvline(sj, color="0.8", lw=0.8, ls="--")
        axk.set_xlabel("s")
        axk.set_ylabel("κ(s)")
        axk.set_title("curvature")
    if lcg and "dkappa" in pts:
        axl = axes[k]
        lx, ly = lcg_points(kappa, pts["dkappa"])
        axl.plot(lx, ly, ".", ms=2.5, color="C2")
        axl.set_xlabel("log ρ")
        axl.set_ylabel("log(ρ ds/dρ)")
        axl.set_title("logarithmic curvature graph")
    return fig
