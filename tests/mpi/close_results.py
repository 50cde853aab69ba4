"""Whether two runs' outputs agree to a relative tolerance, for a solver
whose rounding may depend on the rank count (the PDDO pressure on PETSc,
tests/mpi/pddo.sh); same_results (tests/cli/common.sh) asks for the same
bits instead.

Compared: every number of summary.json but the measurements of the
machine (times, rates, memory, counts of iterations and factor entries),
every column of every .csv, every point array of every .vtu. A value's
difference is taken relative to its column's (array's, key's) largest
magnitude in the reference run, but at least 1e-8 of the file's largest,
so that a column at round-off (a symmetric flow's y momentum, 4e-16 of
the x momentum) is held to the file's scale, not its own.

  python3 close_results.py REF RUN TOLERANCE
exit status 0 within TOLERANCE (the largest difference printed), 1 not
(where), 2 a file missing or unreadable."""
import csv
import json
import os
import sys

import vtk  # python3-vtk9 (scripts/deps.sh), under /usr/bin/python3

# summary keys that measure the run, not the flow
MACHINE = ("_s", "_per_s", "_mb", "threads", "processes", "iterations", "nonzeros")
KEEP = ("time_s", "dt_s", "dt_limit_s", "div_max_per_s", "average_from_s", "averaged_s",
        "period_s")


def machine_key(key):
    if key in KEEP or key.endswith("_m_per_s2"):
        return False
    return any(key.endswith(m) for m in MACHINE)


def worst(ref_cols, run_cols, where):
    """The largest scaled difference of columns (name -> list of floats)."""
    if set(ref_cols) != set(run_cols):
        raise ValueError(f"{where}: columns {sorted(ref_cols)} against {sorted(run_cols)}")
    top = max((max((abs(v) for v in c), default=0.0) for c in ref_cols.values()), default=0.0)
    out = (0.0, where)
    for name, a in ref_cols.items():
        b = run_cols[name]
        if len(a) != len(b):
            raise ValueError(f"{where}: {name} has {len(a)} and {len(b)} values")
        scale = max(max((abs(v) for v in a), default=0.0), 1e-8 * top, 1e-300)
        for x, y in zip(a, b):
            d = abs(x - y) / scale
            if d > out[0]:
                out = (d, f"{where}: {name}")
    return out


def read_csv(path):
    with open(path) as f:
        rows = [r for r in csv.reader(line for line in f if not line.startswith("#"))]
    head, body = rows[0], rows[1:]
    return {h: [float(r[k]) for r in body] for k, h in enumerate(head)}


def read_vtu(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    cols = {"points": values(grid.GetPoints().GetData())}
    data = grid.GetPointData()
    for k in range(data.GetNumberOfArrays()):
        cols[data.GetArrayName(k)] = values(data.GetArray(k))
    return cols


def values(array):
    """A VTK array's values, every component, as floats (without numpy,
    which Debian's python3-vtk9 does not pull in)."""
    n = array.GetNumberOfTuples() * array.GetNumberOfComponents()
    return [float(array.GetValue(k)) for k in range(n)]


def read_summary(path):
    with open(path) as f:
        d = json.load(f)
    return {k: [float(v)] for k, v in d.items()
            if isinstance(v, (int, float)) and not isinstance(v, bool) and not machine_key(k)}


def main(ref, run, tolerance):
    files = sorted(f for f in os.listdir(ref) if f.endswith((".csv", ".vtu")))
    files.append("summary.json")
    result = (0.0, "")
    for name in files:
        a, b = os.path.join(ref, name), os.path.join(run, name)
        if not os.path.exists(b):
            print(f"{run}: {name} missing")
            return 2
        read = read_summary if name == "summary.json" else read_vtu if name.endswith(".vtu") \
            else read_csv
        found = worst(read(a), read(b), name)
        result = max(result, found)
    print(f"largest difference {result[0]:.2e} of the scale ({result[1]})")
    return 0 if result[0] <= tolerance else 1


if __name__ == "__main__":
    if len(sys.argv) != 4:
        print(__doc__)
        sys.exit(2)
    try:
        sys.exit(main(sys.argv[1], sys.argv[2], float(sys.argv[3])))
    except (OSError, ValueError) as e:
        print(e)
        sys.exit(2)
