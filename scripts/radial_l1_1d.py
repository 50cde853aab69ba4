#!/usr/bin/env python3
"""The L1 error of a 1D radial profile against a finer one (both nspd
radial CSVs, r,rho,u,p, the fine grid an integer refinement of the coarse):
sum_i V_i |rho_i - <rho_fine>_i| / sum_i V_i, V = r^nu / nu differences,
<rho_fine>_i the fine cells' volume-weighted mean over coarse cell i.
Usage: radial_l1_1d.py COARSE.csv FINE.csv NU (2 cylindrical, 3 spherical)."""
import os, sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), 'lib'))
from radial_csv import read_profile

(rc, qc), (rf, qf), nu = read_profile(sys.argv[1]), read_profile(sys.argv[2]), int(sys.argv[3])
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
