"""Where the hollow square of paper 003 Sec. 4.2 breaks, snapshot by
snapshot: the points with damage of at least THRESHOLD near its four
interior corners and in the middles of its four inner faces (the boxes of
the corner_damage and face_damage probes of cases/blast_hollow_square.yaml,
on the points' reference positions), and in all.

usage: /usr/bin/python3 square_damage_regions.py RUN_DIR [THRESHOLD]
prints: time_us corner_points face_points all_points (one line a snapshot)"""
import os
import sys
import xml.etree.ElementTree as ET

import vtk
from vtk.util.numpy_support import vtk_to_numpy

CORNERS = [(0.14, 0.14, 0.16, 0.16), (0.24, 0.14, 0.26, 0.16),
           (0.14, 0.24, 0.16, 0.26), (0.24, 0.24, 0.26, 0.26)]
FACES = [(0.19, 0.14, 0.21, 0.16), (0.19, 0.24, 0.21, 0.26),
         (0.14, 0.19, 0.16, 0.21), (0.24, 0.19, 0.26, 0.21)]


def inside(x, y, boxes):
    hit = x < -1.0  # all false
    for x0, y0, x1, y1 in boxes:
        hit |= (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
    return hit


def main():
    run = sys.argv[1]
    threshold = float(sys.argv[2]) if len(sys.argv) > 2 else 0.5
    series = ET.parse(os.path.join(run, "solid.pvd")).getroot().find("Collection")
    for d in series.findall("DataSet"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(run, d.get("file")))
        reader.Update()
        out = reader.GetOutput()
        pts = vtk_to_numpy(out.GetPoints().GetData())
        data = out.GetPointData()
        u = vtk_to_numpy(data.GetArray("displacement"))
        damage = vtk_to_numpy(data.GetArray("damage"))
        x, y = pts[:, 0] - u[:, 0], pts[:, 1] - u[:, 1]
        hit = damage >= threshold
        print("%8.1f %6d %6d %6d" % (float(d.get("timestep")) * 1e6,
                                     (hit & inside(x, y, CORNERS)).sum(),
                                     (hit & inside(x, y, FACES)).sum(), hit.sum()))


main()
