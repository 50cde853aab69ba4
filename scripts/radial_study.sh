#!/bin/sh
# Issue 57 item 2: the strong cylindrical and spherical shocks of pressure
# ratio 1e4 (charge rho 1, p 1 in r < 0.25; gas rho 1, p 1e-4; t = 0.5).
# 1. The 1D radial solver (nspd radial) on 250, 500, 1000, 2000 cells of
#    (0, 1.5) against its own 20,000-cell solution, cylinder and sphere.
# 2. cases/strong_shock_cylindrical.yaml on both backgrounds (quadrant
#    0.8 wide, 25 to 200 cells or elements a side, GKS also 400) against
#    the 20,000-cell cylinder, scripts/radial_l1.py (r < 0.75).
#   usage: scripts/radial_study.sh NSPD OUTDIR   (about 10 min on 2 cores)
set -eu
nspd=$1
out=$2
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
for g in cylindrical spherical; do
    nu=2; [ $g = spherical ] && nu=3
    [ -s "$out/ref_$g.csv" ] || "$nspd" radial --geometry $g --cells 20000 >"$out/ref_$g.csv"
    for n in 250 500 1000 2000; do
        "$nspd" radial --geometry $g --cells $n >"$out/${g}_$n.csv"
        printf '1D %s ' $g
        python3 "$src/scripts/radial_l1_1d.py" "$out/${g}_$n.csv" "$out/ref_$g.csv" $nu
    done
done
for m in gks iga; do
    for n in 25 50 100 200 400; do
        [ $m = iga ] && [ $n = 400 ] && continue
        h=$(python3 -c "print(0.8 / $n)")
        start=$(date +%s.%N)
        "$nspd" run "$src/cases/strong_shock_cylindrical.yaml" -o "$out/${m}_$n" --force --quiet \
            --set flow.method=$m --set flow.grid.x.segments.0.spacing=$h \
            --set flow.grid.y.segments.0.spacing=$h
        wall=$(python3 -c "import time; print('%.1f' % (time.time() - $start))")
        printf '%s %s s, %s steps: ' $m "$wall" "$(tail -1 "$out/${m}_$n/history.csv" | cut -d, -f1)"
        python3 "$src/scripts/radial_l1.py" "$out/${m}_$n" "$out/ref_cylindrical.csv"
    done
done
