#!/usr/bin/env python3
"""The Sedov front of a quadrant run's last (or given) .vtr: the outer
half-rise of the cell density between the ambient (1) and each ray's peak,
along the x axis (the first row of cells) and the diagonal (cells i = i),
against the exact radius r_s = xi0 (E t^2 / rho0)^(1/4) (src/flow/sedov.h:
xi0 = 1.004022 for gamma 1.4). Usage: sedov_front.py OUTDIR [E] [T]
(defaults: cases/sedov_quadrant.yaml's E = 0.98396 and t from flow.pvd)."""
import re, struct, sys, glob, math

def read_vtr(path):
    data = open(path, 'rb').read()
    head = data[:data.index(b'<AppendedData')].decode()
    ext = [int(v) for v in re.search(r'WholeExtent="([^"]+)"', head).group(1).split()]
    nx, ny = ext[1] - ext[0], ext[3] - ext[2]
    cell = head[head.index('<CellData'):]
    off = int(re.search(r'Name="density"[^>]*offset="(\d+)"', cell).group(1))
    base = data.index(b'_', data.index(b'<AppendedData')) + 1
    n = struct.unpack_from('<Q', data, base + off)[0] // 8
    rho = struct.unpack_from('<%dd' % n, data, base + off + 8)
    return nx, ny, rho

def front(r, rho):
    half = 0.5 * (1.0 + max(rho))
    for s in range(len(rho) - 1, 0, -1):
        if rho[s - 1] >= half > rho[s]:
            return r[s - 1] + (r[s] - r[s - 1]) * (rho[s - 1] - half) / (rho[s - 1] - rho[s])
    return float('nan')

out = sys.argv[1]
E = float(sys.argv[2]) if len(sys.argv) > 2 else 0.98396
pvd = open(out + '/flow.pvd').read()
t, f = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', pvd)[-1]
t = float(sys.argv[3]) if len(sys.argv) > 3 else float(t)
nx, ny, rho = read_vtr(out + '/' + f)
L = 1.2 if len(sys.argv) <= 4 else float(sys.argv[4])
h = L / nx
axis = front([(i + 0.5) * h for i in range(nx)], [rho[i] for i in range(nx)])
diag = front([math.sqrt(2) * (i + 0.5) * h for i in range(nx)], [rho[i + nx * i] for i in range(nx)])
exact = 1.004022 * (E * t * t) ** 0.25
print('t %.4g  %d x %d  front axis %.4f (%+.2f %%)  diagonal %.4f (%+.2f %%)  exact %.4f  rays %.2f %% apart  peak rho %.3f'
      % (t, nx, ny, axis, 100 * (axis / exact - 1), diag, 100 * (diag / exact - 1), exact,
         100 * abs(axis - diag) / exact, max(rho)))
