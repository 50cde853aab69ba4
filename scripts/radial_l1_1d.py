#!/usr/bin/env python3
"""The L1 error of a 1D radial profile against a finer one (both nspd
radial CSVs, r,rho,u,p, the fine grid an integer refinement of the coarse):
sum_i V_i |rho_i - <rho_fine>_i| / sum_i V_i, V = r^nu / nu differences,
<rho_fine>_i the fine cells' volume-weighted mean over coarse cell i.
Usage: radial_l1_1d.py COARSE.csv FINE.csv NU (2 cylindrical, 3 spherical)."""
import sys


def read(path):
    r, rho = [], []
    for line in open(path):
        if line[0].isdigit():
            v = line.split(',')
            r.append(float(v[0]))
            rho.append(float(v[1]))
    return r, rho


(rc, qc), (rf, qf), nu = read(sys.argv[1]), read(sys.argv[2]), int(sys.argv[3])
ratio = len(rf) // len(rc)
hf = 2 * rf[0]
vol = lambda r0, r1: (r1 ** nu - r0 ** nu) / nu
vf = [vol(i * hf, (i + 1) * hf) for i in range(len(rf))]
hc = 2 * rc[0]
err = total = 0.0
for i in range(len(rc)):
    v = vol(i * hc, (i + 1) * hc)
    m = sum(vf[k] * qf[k] for k in range(i * ratio, (i + 1) * ratio)) / sum(vf[i * ratio:(i + 1) * ratio])
    err += v * abs(qc[i] - m)
    total += v
print('%d cells  L1(rho) %.4e' % (len(rc), err / total))
