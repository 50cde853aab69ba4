#!/bin/sh
# Flow throughput: nspd's viscous GKS step against OpenFOAM's rhoCentralFoam
# (viscous, Kurganov-Tadmor) on 2D grids of about 2e5 cells, side by side.
#   bench/gks_vs_openfoam.sh [NSPD] [REPEATS]
# For 1 and 2 cores (OpenMP threads for nspd, MPI ranks for OpenFOAM), runs
# each code REPEATS times (default 3) alternately and prints the medians of
# cell updates per second (one update = all faces of a cell, one time step).
# OpenFOAM's time excludes start-up: the difference of its ExecutionTime
# between step 5 and the last step.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
nspd=${1:-$here/../build/nspd}
repeats=${2:-3}
n=448 # 200,704 cells
steps=60
out=$here/results
mkdir -p "$out"
raw=$out/gks_vs_openfoam.txt
: >"$raw"
command -v rhoCentralFoam >/dev/null || { echo "OpenFOAM not found: scripts/deps.sh bench" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

# OpenFOAM's tools need its environment (a bash script)
foam() { bash -c ". /usr/share/openfoam/etc/bashrc >/dev/null 2>&1; cd '$work/case' && $*"; }
sh "$here/openfoam/make_case.sh" "$work/case" $n $steps
foam "blockMesh >log.blockMesh 2>&1 && setFields >log.setFields 2>&1 && decomposePar >log.decomposePar 2>&1"

foam_rate() { # log file -> cell updates per second
    awk -v cells=$((n * n)) '/^ExecutionTime/ { t[++k] = $3 }
        END { print cells * (k - 5) / (t[k] - t[5]) }' "$1"
}

for p in 1 2; do
    : >"$out/nspd_gks_$p" && : >"$out/foam_$p"
    for r in $(seq "$repeats"); do
        "$nspd" bench gks --cells $((n * n)) --threads "$p" --steps "$steps" >"$out/gks.json"
        cat "$out/gks.json" >>"$raw"
        sed -n 's/.*"cell_updates_per_s": \([0-9.e+]*\).*/\1/p' "$out/gks.json" >>"$out/nspd_gks_$p"
        if [ "$p" -eq 1 ]; then
            foam "rhoCentralFoam >log.foam 2>&1"
        else
            foam "mpirun --allow-run-as-root -np 2 rhoCentralFoam -parallel >log.foam 2>&1"
        fi
        rate=$(foam_rate "$work/case/log.foam")
        echo "rhoCentralFoam np=$p: $rate cell updates/s" >>"$raw"
        echo "$rate" >>"$out/foam_$p"
    done
done
printf "%-16s %-8s %-20s %-20s %s\n" code cores "cell updates/s" "per core" "ratio nspd/OpenFOAM"
for p in 1 2; do
    g=$(median <"$out/nspd_gks_$p")
    f=$(median <"$out/foam_$p")
    printf "%-16s %-8s %-20.4g %-20.4g %.1f\n" "nspd GKS" "$p" "$g" "$(echo "$g $p" | awk '{print $1/$2}')" "$(echo "$g $f" | awk '{print $1/$2}')"
    printf "%-16s %-8s %-20.4g %-20.4g\n" rhoCentralFoam "$p" "$f" "$(echo "$f $p" | awk '{print $1/$2}')"
done
echo "(medians of $repeats runs, $steps steps, $((n * n)) cells; raw: $raw)"
