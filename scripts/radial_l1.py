#!/usr/bin/env python3
"""The L1 error of a quadrant run's last density field against a 1D radial
reference (nspd radial's CSV, r,rho,u,p): sum over the cells whose centre
lies within r < RMAX of area x |rho_cell - <rho_ref>_cell| over their area,
<rho_ref>_cell the reference sampled at 4 x 4 points of the cell (linear
between its cells) and averaged, so that a cell average (GKS) and an
element-centre value (IGA) are both compared with the reference's mean
over the cell. Usage: radial_l1.py OUTDIR REF.csv [RMAX] (default 0.75)."""
import bisect, math, os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from vtr import read_vtr, last_frame
from radial_csv import read_profile

out, ref_path = sys.argv[1], sys.argv[2]
rmax = float(sys.argv[3]) if len(sys.argv) > 3 else 0.75
r_ref, rho_ref = read_profile(ref_path)


def ref(r):
    k = bisect.bisect_left(r_ref, r)
    if k == 0:
        return rho_ref[0]
    if k == len(r_ref):
        return rho_ref[-1]
    w = (r - r_ref[k - 1]) / (r_ref[k] - r_ref[k - 1])
    return (1 - w) * rho_ref[k - 1] + w * rho_ref[k]


t, path = last_frame(out)
xf, yf, rho = read_vtr(path)
nx, ny = len(xf) - 1, len(yf) - 1
err = area = 0.0
S = 4
for j in range(ny):
    for i in range(nx):
        xc, yc = 0.5 * (xf[i] + xf[i + 1]), 0.5 * (yf[j] + yf[j + 1])
        if math.hypot(xc, yc) >= rmax:
            continue
        hx, hy = xf[i + 1] - xf[i], yf[j + 1] - yf[j]
        m = sum(ref(math.hypot(xf[i] + (a + 0.5) * hx / S, yf[j] + (b + 0.5) * hy / S))
                for a in range(S) for b in range(S)) / (S * S)
        err += hx * hy * abs(rho[i + nx * j] - m)
        area += hx * hy
print('t %.4g  %d x %d  L1(rho) %.4e  over r < %g' % (t, nx, ny, err / area, rmax))
