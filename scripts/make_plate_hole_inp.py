#!/usr/bin/env python3
"""Writes cases/geometry/plate_hole.inp: a plate with a central hole meshed
with CPS4 quadrilaterals, an Abaqus input file in mm (cases/plate_hole_inp.yaml
reads it with solid.lattice kind abaqus, scale 1e-3).

The plate is W x H = 40 x 80 mm about the origin with a hole of radius 6 mm.
The square [-20, 20]^2 around the hole is an O-grid: each side of the square
cut into NS equal segments, each square node joined to the hole node at its
angle (its radial projection onto the circle) by NR cells graded
geometrically (ratio Q) from the hole out; the rest of the plate, above and
below the square, are NS x NB blocks of equal rows. So the mesh's outer
boundary is the rectangle exactly and its inner one the polygon of the 4 NS
hole nodes: the elements' areas sum to W H minus that polygon's area
(unit.io.inp_read checks it to round-off). Sets: ELSET PLATE (every element,
by ELSET= on *ELEMENT), TOP and BOTTOM (the first and last LOAD_ROWS rows of
the blocks, as GENERATE ranges), NSET HOLE (the hole's nodes counter-clockwise
from angle -45 degrees). Rerun to regenerate (the file is committed).
Usage: scripts/make_plate_hole_inp.py [OUT [NS NR NB]] (a coarser mesh: the
fuzzer's seed tests/fuzz/corpus/inp/plate_hole_coarse.inp is OUT 8 4 4)"""
import math, sys

W, H, R = 40.0, 80.0, 6.0
A = W / 2          # half the square's side
NS, NR, NB = 24, 14, 12
if len(sys.argv) > 4:
    NS, NR, NB = (int(a) for a in sys.argv[2:5])
Q = 1.1
LOAD_ROWS = 2

nodes = {}         # exact key -> id
coords = []


def node(x, y):
    key = (round(x, 12), round(y, 12))
    if key not in nodes:
        coords.append((x, y))
        nodes[key] = len(coords)
    return nodes[key]


def square_point(j):
    """Node j (0 .. 4 NS - 1) of the square's boundary, counter-clockwise
    from the corner (A, -A)."""
    side, i = divmod(j % (4 * NS), NS)
    s = -A + 2 * A * i / NS
    return [(A, s), (-s, A), (-A, -s), (s, -A)][side]


t = [(Q ** k - 1) / (Q ** NR - 1) for k in range(NR + 1)]
ogrid = {}
hole = []
for j in range(4 * NS):
    px, py = square_point(j)
    r = math.hypot(px, py)
    hx, hy = R * px / r, R * py / r
    for k in range(NR + 1):
        if k == NR:
            x, y = px, py  # exactly on the square
        else:
            x, y = hx + t[k] * (px - hx), hy + t[k] * (py - hy)
        ogrid[j, k] = node(x, y)
    hole.append(ogrid[j, 0])

elements = []      # node lists, counter-clockwise


def quad(a, b, c, d):
    p = [coords[n - 1] for n in (a, b, c, d)]
    area = sum(p[i - 1][0] * p[i][1] - p[i][0] * p[i - 1][1] for i in range(4))
    elements.append([a, b, c, d] if area > 0 else [a, d, c, b])


for j in range(4 * NS):
    for k in range(NR):
        j1 = (j + 1) % (4 * NS)
        quad(ogrid[j, k], ogrid[j, k + 1], ogrid[j1, k + 1], ogrid[j1, k])

rows = {}
for block, (y0, y1) in enumerate([(A, H / 2), (-A, -H / 2)]):
    first = len(elements) + 1
    for r in range(NB):
        ya, yb = y0 + (y1 - y0) * r / NB, y0 + (y1 - y0) * (r + 1) / NB
        if r + 1 == NB:
            yb = y1
        for i in range(NS):
            xa, xb = -A + W * i / NS, -A + W * (i + 1) / NS
            if i + 1 == NS:
                xb = A
            quad(node(xa, ya), node(xb, ya), node(xb, yb), node(xa, yb))
    # the outermost LOAD_ROWS rows: the block's last elements
    last = len(elements)
    rows['TOP' if block == 0 else 'BOTTOM'] = (last - LOAD_ROWS * NS + 1, last)

out = open(sys.argv[1] if len(sys.argv) > 1 else 'cases/geometry/plate_hole.inp', 'w')
out.write('*Heading\n plate %g x %g mm with a hole of radius %g mm, CPS4 '
          '(scripts/make_plate_hole_inp.py)\n' % (W, H, R))
out.write('** %d nodes, %d elements\n' % (len(coords), len(elements)))
out.write('*Part, name=plate\n*Node\n')
for n, (x, y) in enumerate(coords, 1):
    out.write('%d, %.17g, %.17g\n' % (n, x, y))
out.write('*Element, type=CPS4, elset=PLATE\n')
for e, ns in enumerate(elements, 1):
    out.write('%d, %d, %d, %d, %d\n' % (e, *ns))
for name, (a, b) in rows.items():
    out.write('*Elset, elset=%s, generate\n%d, %d, 1\n' % (name, a, b))
out.write('*Nset, nset=HOLE\n')
for i in range(0, len(hole), 16):
    out.write(', '.join(str(n) for n in hole[i:i + 16]) + '\n')
out.write('*Solid Section, elset=PLATE, material=PMMA\n1.,\n*End Part\n')
