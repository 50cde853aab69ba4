#!/usr/bin/env python3
"""The Sedov front of a quadrant run's last (or given) .vtr: the outer
half-rise of the cell density between the ambient (1) and each ray's peak,
along the x axis (the first row of cells) and the diagonal (cells i = i),
against the exact radius r_s = xi0 (E t^2 / rho0)^(1/4) (src/flow/sedov.h:
xi0 = 1.004022 for gamma 1.4). Usage: sedov_front.py OUTDIR [E] [T]
(defaults: cases/sedov_quadrant.yaml's E = 0.98396 and t from flow.pvd)."""
import math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from vtr import read_vtr, last_frame

def front(r, rho):
    half = 0.5 * (1.0 + max(rho))
    for s in range(len(rho) - 1, 0, -1):
        if rho[s - 1] >= half > rho[s]:
            return r[s - 1] + (r[s] - r[s - 1]) * (rho[s - 1] - half) / (rho[s - 1] - rho[s])
    return float('nan')

out = sys.argv[1]
E = float(sys.argv[2]) if len(sys.argv) > 2 else 0.98396
t, path = last_frame(out)
t = float(sys.argv[3]) if len(sys.argv) > 3 else t
xf, yf, rho = read_vtr(path)
nx, ny = len(xf) - 1, len(yf) - 1
h = xf[1] - xf[0]
axis = front([(i + 0.5) * h for i in range(nx)], [rho[i] for i in range(nx)])
diag = front([math.sqrt(2) * (i + 0.5) * h for i in range(nx)], [rho[i + nx * i] for i in range(nx)])
exact = 1.004022 * (E * t * t) ** 0.25
print('t %.4g  %d x %d  front axis %.4f (%+.2f %%)  diagonal %.4f (%+.2f %%)  exact %.4f  rays %.2f %% apart  peak rho %.3f'
      % (t, nx, ny, axis, 100 * (axis / exact - 1), diag, 100 * (diag / exact - 1), exact,
         100 * abs(axis - diag) / exact, max(rho)))
