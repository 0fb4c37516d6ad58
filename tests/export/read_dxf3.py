#!/usr/bin/env python3
"""Reads the one SPLINE of a DXF file with ezdxf (an independent reader) and prints its degree and
number of control points, then `n` points "t x y z" uniform in its parameter range, as evaluated
by ezdxf's B-spline (the space counterpart of read_dxf.py)."""
import sys

import ezdxf

doc = ezdxf.readfile(sys.argv[1])
splines = [e for e in doc.modelspace() if e.dxftype() == "SPLINE"]
assert len(splines) == 1, f"{len(splines)} SPLINE entities"
s = splines[0]
b = s.construction_tool()
knots = list(b.knots())
n = int(sys.argv[2])
t0, t1 = knots[b.order - 1], knots[-b.order]
print(s.dxf.degree, len(s.control_points))
for i in range(n):
    t = t0 + (t1 - t0) * i / (n - 1)
    p = b.point(t)
    print(repr(t), repr(p.x), repr(p.y), repr(p.z))
