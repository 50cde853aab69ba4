#!/bin/sh
# Issue 60: the time-step study of paper 003's three blast cases on their
# coarse meshes (GKS background): the weak coupling (beta = 1) at the
# paper's step, half and twice it, with the implicit relaxation and the
# paper's explicit update, and at the flow's CFL step; the strong coupling
# at every step (the paper's) at its step, half and twice it, and slaved
# once per CFL step (strong_constraint: flow_step). C_pen keeps the paper's
# step (coupling.dt) throughout, so only the integration's step moves.
# Per run: the impulse on the solid (the history's penalty force along x,
# trapezoids), the centre of mass's x displacement, the mass loss, the
# fragments, the broken bonds and the wall time (one thread each, two
# runs at a time): the table in OUTDIR/table.md (docs/COUPLING_STRONG.md).
#   usage: scripts/timestep_study.sh NSPD OUTDIR   (about 20 min on 2 cores)
set -eu
nspd=$1
out=$2
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
# case | the paper's weak step | its strong step
cases="chamber_detonation 1.25e-7 1.0e-6
blast_hollow_square 1.0e-7 4.0e-7
blast_hollow_cylinder 1.0e-7 4.0e-7"
jobs="$out/jobs.txt"
: >"$jobs"
echo "$cases" | while read -r name weak strong; do
    for f in 2 1 0.5; do
        dt=$(awk -v a="$weak" -v f="$f" 'BEGIN { printf "%.6g", a * f }')
        sdt=$(awk -v a="$strong" -v f="$f" 'BEGIN { printf "%.6g", a * f }')
        for integration in implicit explicit; do
            echo "$name weak_${integration}_$dt --set time.dt=$dt --set coupling.integration=$integration" >>"$jobs"
        done
        echo "$name strong_every_$sdt --set time.dt=$sdt --set coupling.strong=true" >>"$jobs"
    done
    echo "$name weak_implicit_cfl --set time.dt=stable" >>"$jobs"
    echo "$name strong_flowstep_cfl --set time.dt=stable --set coupling.strong=true --set coupling.strong_constraint=flow_step" >>"$jobs"
done
# shellcheck disable=SC2016 # expanded by the inner shell
xargs -P 2 -L 1 sh -c 'name=$1 run=$2; shift 2
    "$0" run "'"$src"'/cases/$name.yaml" -o "'"$out"'/$name/$run" --force --quiet --threads 1 "$@" \
        >"'"$out"'/$name.$run.log" 2>&1 || echo "$name $run: exit $?"' "$nspd" <"$jobs"
python3 "$src/scripts/lib/timestep_table.py" "$out" >"$out/table.md"
cat "$out/table.md"
