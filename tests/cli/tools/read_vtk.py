"""Opens every file of a .pvd series with VTK's own XML readers and checks
that each has the expected arrays, a consistent size and finite values.

usage: read_vtk.py SERIES.pvd EXPECTED_COUNT ARRAY[:COMPONENTS] ...
EXPECTED_COUNT is the number of points (.vtu) or cells (.vtr) per file.
The parallel files of a run on several processes (.pvtu, .pvtr) are read
whole through VTK's parallel readers, as ParaView reads them."""
import math
import os
import sys
import xml.etree.ElementTree as ET

import vtk


def main():
    pvd, expected = sys.argv[1], int(sys.argv[2])
    wanted = [a.split(":") for a in sys.argv[3:]]
    base = os.path.dirname(pvd)
    datasets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
    assert datasets, "empty series"
    times = [float(d.get("timestep")) for d in datasets]
    assert times == sorted(times), "time steps out of order"
    for d in datasets:
        path = os.path.join(base, d.get("file"))
        readers = {
            ".vtu": vtk.vtkXMLUnstructuredGridReader,
            ".vtr": vtk.vtkXMLRectilinearGridReader,
            ".pvtu": vtk.vtkXMLPUnstructuredGridReader,
            ".pvtr": vtk.vtkXMLPRectilinearGridReader,
        }
        kind = os.path.splitext(path)[1]
        if kind in readers:
            reader = readers[kind]()
        else:
            raise SystemExit("unknown file type " + path)
        reader.SetFileName(path)
        reader.Update()
        if reader.GetErrorCode() != 0:
            raise SystemExit("VTK could not read " + path)
        out = reader.GetOutput()
        if kind.endswith("vtu"):
            count, data = out.GetNumberOfPoints(), out.GetPointData()
            assert out.GetNumberOfCells() == count, "one vertex cell per point"
        else:
            count, data = out.GetNumberOfCells(), out.GetCellData()
        assert count == expected, "%s: %d items, expected %d" % (path, count, expected)
        for name, *comp in wanted:
            array = data.GetArray(name)
            assert array is not None, "%s: no array %s" % (path, name)
            ncomp = int(comp[0]) if comp else 1
            assert array.GetNumberOfComponents() == ncomp, "%s: %s has %d components" % (
                path, name, array.GetNumberOfComponents())
            assert array.GetNumberOfTuples() == count
            for c in range(ncomp):
                lo, hi = array.GetRange(c)
                assert math.isfinite(lo) and math.isfinite(hi), "%s: %s not finite" % (path, name)
    print("%d files read by VTK" % len(datasets))


main()
