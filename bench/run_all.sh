#!/bin/sh
# make bench: every benchmark of docs/PERFORMANCE.md, medians of repeated runs.
#   bench/run_all.sh [NSPD]
set -eu
here=$(cd "$(dirname "$0")" && pwd)
nspd=${1:-$here/../build/nspd}
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
field() { sed -n "s/.*\"$1\": \\([0-9.e+-]*\\).*/\\1/p"; }

echo "== memory bandwidth (STREAM triad, best of 10)"
for t in 1 2; do
    printf "threads %d: %.3g GB/s\n" "$t" "$("$nspd" bench memory --threads "$t" | field triad_bytes_per_s | awk '{print $1/1e9}')"
done

echo "== FP64 peak (fused multiply-adds, vector and scalar, best of 10)"
for t in 1 2; do
    "$nspd" bench flops --threads "$t" | tr -d ' \n' | sed 's/.*"fp64_simd/threads '"$t"': "fp64_simd/; s/,"check.*//'
    echo
done
echo "== the kernels' flops, counted (bench/flops/*.cpp)"
(cd "$here/.." && bench/kernel_flops.sh)

echo "== GKS, viscous 2D, 1000 x 1000 cells (median of 5 runs of 20 steps)"
for t in 1 2; do
    rates=""
    for r in 1 2 3 4 5; do
        rates="$rates $("$nspd" bench gks --cells 1000000 --threads "$t" --steps 20 | field cell_updates_per_s)"
    done
    printf "threads %d: %.4g cell updates/s\n" "$t" "$(echo $rates | tr ' ' '\n' | median)"
done

echo "== PD against LAMMPS peri/pmb"
"$here/pd_vs_lammps.sh" "$nspd" 5
echo "== correspondence solid (issue 14, nspd bench cpd) against the bond-based kernel"
"$here/cpd_vs_bond.sh" "$nspd" 5
echo "== correspondence against LAMMPS peri/eps"
"$here/cpd_vs_lammps.sh" "$nspd" 5
echo "== GKS against OpenFOAM rhoCentralFoam"
"$here/gks_vs_openfoam.sh" "$nspd" 3
echo "== PDDO flow against OpenFOAM icoFoam at matched accuracy (about 30 min)"
"$here/pddo_vs_openfoam.sh" "$nspd" 3
echo "== the IGA flow against the GKS flow on the free-field blast"
(cd "$here/.." && bench/iga_vs_gks.sh "$nspd" 5)
