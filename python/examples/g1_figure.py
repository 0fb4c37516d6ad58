#!/usr/bin/env python3
"""Example: a G1 Hermite LA segment and a G2 triple, their points, the G2 curve exported for CAD
(a certified B-spline in a DXF file beside the figure) and a figure with the curvature comb,
kappa(s) and the logarithmic curvature graph.

    PYTHONPATH=build/python python3 python/examples/g1_figure.py [out.png]
"""
import sys

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402

import lac  # noqa: E402

r = lac.g1_hermite(p0=(0, 0), theta0=0.9, p1=(3, 0), theta1=-0.2, alpha=-0.7)
print(r.status, r.summary["length"], r.info["shape"])
c = r.curve
pts = c.eval(np.linspace(0, c.length, 5))
for s, x, y, k in zip(pts.s, pts.x, pts.y, pts.kappa):
    print(f"s={s:.4f}  x={x:+.6f}  y={y:+.6f}  kappa={k:+.6f}")

g = lac.g2_hermite(p0=(0, 0), theta0=0.6, kappa0=0.5, p1=(4, 0), theta1=-0.6, kappa1=-0.3, alpha=-0.5)
print(g.status, g.summary["length"], len(g.curve.segments), "segments")

out = sys.argv[1] if len(sys.argv) > 1 else "g1_figure.png"
dxf = out.rsplit(".", 1)[0] + "_g2.dxf"
e = lac.export_curve(g.curve, dxf, tolerance=1e-6)  # .step/.iges too when the module has OpenCASCADE
print(e["status"], "wrote", e["file"], e["control_points"].shape[0] if e["usable"] else 0, "control points,",
      f"max deviation {e['max_deviation']:.2e}")

fig = lac.plot(c, comb=True, lcg=True, title="G1 Hermite, alpha = -0.7")
fig.savefig(out, dpi=120)
print("wrote", out)
