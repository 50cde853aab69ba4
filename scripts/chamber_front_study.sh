#!/bin/sh
# Issue 57 item 3: the blast front of paper 003's chamber charge in free
# field (cases/iga_cylindrical_blast.yaml, inviscid as the reference) on
# the limited isogeometric step (lumped-L2 and nodal starts) and on GKS,
# 6, 3 and 1.5 mm, against the project's converged 1D radial solution
# (nspd radial, 25 um cells; 50 um beside it shows it converged): the
# half-rise arrival and the peak at r = 5, 7 and 10 cm
# (scripts/lib/blast_arrival.awk, scripts/lib/probe_arrival.awk).
#   usage: scripts/chamber_front_study.sh NSPD OUTDIR   (about 12 min on 2 cores)
set -eu
nspd=$1
out=$2
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
for n in 6000 12000; do
    "$nspd" radial --charge 16.053811,0,6.75e6 --ambient 1.2014708,0,1e5 --radius 0.035 \
        --length 0.3 --outer open --cells $n --time 1.3e-4 --probes 0.05,0.07,0.1 \
        >"$out/reference_$n.csv" 2>/dev/null
    echo "reference, $n cells of 0.3 m:"
    awk -f "$src/scripts/lib/probe_arrival.awk" "$out/reference_$n.csv"
done
for h in 6e-3 3e-3 1.5e-3; do
    for run in "iga lumped_l2" "iga nodal" "gks -"; do
        set -- $run
        name=$1_$2_$h
        extra=""
        [ "$1" = iga ] && extra="--set flow.iga.limiter=convex --set flow.iga.init=$2"
        start=$(date +%s)
        # shellcheck disable=SC2086 # extra holds words
        "$nspd" run "$src/cases/iga_cylindrical_blast.yaml" -o "$out/$name" --force --quiet \
            --set flow.method=$1 --set "flow.gas.viscosity={law: none}" \
            --set flow.grid.x.segments.0.spacing=$h --set flow.grid.y.segments.0.spacing=$h $extra
        echo "$name: $(($(date +%s) - start)) s"
        awk -f "$src/scripts/lib/blast_arrival.awk" "$out/$name/history.csv"
    done
done
