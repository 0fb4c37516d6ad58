#!/usr/bin/env python3
"""Reads the one SPLINE of a DXF file with ezdxf (an independent reader) and prints its degree and
number of control points, then `n` points "t x y" ("t x y z" with --dim 3) uniform in its parameter
range, as evaluated by ezdxf's B-spline.

Usage: read_dxf.py FILE N [--dim 2|3]"""
import argparse

import ezdxf

parser = argparse.ArgumentParser()
parser.add_argument("file")
parser.add_argument("n", type=int)
parser.add_argument("--dim", type=int, choices=(2, 3), default=2)
args = parser.parse_args()
doc = ezdxf.readfile(args.file)
splines = [e for e in doc.modelspace() if e.dxftype() == "SPLINE"]
assert len(splines) == 1, f"{len(splines)} SPLINE entities"
s = splines[0]
b = s.construction_tool()
knots = list(b.knots())
n = args.n
t0, t1 = knots[b.order - 1], knots[-b.order]
print(s.dxf.degree, len(s.control_points))
for i in range(n):
    t = t0 + (t1 - t0) * i / (n - 1)
    p = b.point(t)
    print(repr(t), *(repr(x) for x in (p.x, p.y, p.z)[: args.dim]))
