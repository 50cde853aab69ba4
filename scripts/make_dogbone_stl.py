#!/usr/bin/env python3
"""Writes cases/geometry/dogbone.stl: a flat tensile specimen (the outline
below, in mm, extruded 4 mm along z from z = -2), an ASCII STL: each face
cut into the vertical trapezoids between consecutive vertices of the top
edge and their mirror images (the outline is symmetric about y = 0 and
single-valued in x), two triangles each, and two triangles per side quad. The specimen of
cases/dogbone_stl.yaml; rerun to regenerate (the file is committed).
Usage: scripts/make_dogbone_stl.py [OUT]"""
import math, sys

# the right half of the outline, counter-clockwise from the axis: the
# gauge (half-width 5, to x = 20), a circular shoulder of radius 8 to the
# grip (half-width 10), the grip to x = 50
half = [(0.0, 5.0), (20.0, 5.0)]
for k in range(1, 9):  # the shoulder: a quarter-ish arc from (20, 5) to (28, 10)
    a = math.pi / 2 * k / 8
    half.append((20.0 + 8.0 * math.sin(a), 5.0 + 5.0 * (1 - math.cos(a))))
half += [(50.0, 10.0)]
# full outline, counter-clockwise: right half top, mirrored
top = [(x, y) for x, y in half]                      # x from 0 to 50, y > 0
right = [(x, y) for x, y in reversed(top)]           # 50 -> 0 along the top
left = [(-x, y) for x, y in top[1:]]                 # 0 -> -50 along the top
outline_top = right + left                           # (50,10) ... (-50, 10)
outline = outline_top + [(x, -y) for x, y in reversed(outline_top)]
# counter-clockwise order: reverse if the signed area is negative
area = sum(outline[i - 1][0] * outline[i][1] - outline[i][0] * outline[i - 1][1]
           for i in range(len(outline)))
if area < 0:
    outline.reverse()
z0, z1 = -2.0, 2.0
out = open(sys.argv[1] if len(sys.argv) > 1 else 'cases/geometry/dogbone.stl', 'w')
out.write('solid dogbone (mm), scripts/make_dogbone_stl.py\n')


def facet(a, b, c):
    out.write('  facet normal 0 0 0\n    outer loop\n')
    for v in (a, b, c):
        out.write('      vertex %.6f %.6f %.6f\n' % v)
    out.write('    endloop\n  endfacet\n')


chain = sorted(set([(-x, y) for x, y in top] + top))  # the top edge, x increasing
for (xa, ya), (xb, yb) in zip(chain, chain[1:]):
    quad = [(xa, -ya), (xb, -yb), (xb, yb), (xa, ya)]  # counter-clockwise seen from +z
    for z, up in ((z1, True), (z0, False)):
        a, b, c, d = [(x, y, z) for x, y in quad]
        if up:
            facet(a, b, c), facet(a, c, d)
        else:
            facet(a, c, b), facet(a, d, c)
n = len(outline)
for i in range(n):
    (xa, ya), (xb, yb) = outline[i], outline[(i + 1) % n]
    facet((xa, ya, z0), (xb, yb, z0), (xb, yb, z1))  # side, outward
    facet((xa, ya, z0), (xb, yb, z1), (xa, ya, z1))
out.write('endsolid dogbone\n')
