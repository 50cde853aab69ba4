#!/bin/sh
# The PDDO pressure solve on PETSc against the serial direct solve (issue
# 58): the paper's Re 100 cylinder (cases/cylinder_confined_re100.yaml,
# 122,833 nodes at dx 0.03 m) and the lattices of 4 and 16 times its nodes
# (dx 0.015 and 0.0075 m, the time step scaled with dx^2 to stay inside
# the stable limit), a few steps each, on 1 and 2 processes, one thread a
# process. A table row per run: the solve, the processes, the nodes, the
# setup (cloud, operators and the factorisation or hierarchy), the
# pressure solve per step, the whole step, the Krylov iterations per step
# and the peak resident memory of rank 0.
#   bench/pddo_pressure_scaling.sh NSPD [WORK] [STEPS] [SPACINGS] [SOLVES] [RANKS]
# SPACINGS defaults to "0.03 0.015 0.0075", SOLVES to "runs mumps
# boomeramg", RANKS to "1 2" (the direct solve always on one: its solve
# is rank 0's alone at any count, docs/PERFORMANCE.md).
set -eu
nspd=$1
work=${2:-out/pddo_pressure_scaling}
steps=${3:-10}
spacings=${4:-0.03 0.015 0.0075}
solves=${5:-runs mumps boomeramg}
ranks=${6:-1 2}
root=$(cd "$(dirname "$0")/.." && pwd)
case_file=$root/cases/cylinder_confined_re100.yaml
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_pml=ob1
mkdir -p "$work"
key() { sed -n "s/.*\"$2\": \([^,}]*\).*/\1/p" "$1/summary.json"; }
printf '| solve | processes | nodes | setup | solve per step | step | iterations per step | peak memory (rank 0) |\n'
printf '|---|---|---|---|---|---|---|---|\n'
for dx in $spacings; do
    dt=$(awk -v dx="$dx" 'BEGIN { printf "%.6g", 5e-5 * (dx / 0.03) ^ 2 }')
    for solve in $solves; do
        for n in $ranks; do
            [ "$solve" = runs ] && [ "$n" -gt 1 ] && continue
            out=$work/$solve.$dx.$n
            set -- "$nspd" run "$case_file" -o "$out" --force --quiet --set "flow.spacing=$dx" \
                --set "time.dt=$dt" --set "time.end=$(awk -v dt="$dt" -v s="$steps" 'BEGIN { print (s + 0.5) * dt }')" \
                --set output.field_interval=100 --set output.history_interval=100 \
                --set output.average_from=0 --set "flow.pressure_solve=$solve"
            if [ "$n" -gt 1 ]; then
                mpiexec -n "$n" "$@" || { echo "| $solve | $n | dx $dx failed |"; continue; }
            else
                "$@" || { echo "| $solve | $n | dx $dx failed |"; continue; }
            fi
            s=$(key "$out" steps)
            awk -v solve="$solve" -v n="$n" -v nodes="$(key "$out" nodes)" \
                -v setup="$(key "$out" setup_s)" -v ps="$(key "$out" pressure_solve_s)" \
                -v flow="$(key "$out" flow_s)" -v it="$(key "$out" pressure_iterations)" \
                -v rss="$(key "$out" peak_rss_mb)" -v s="$s" 'BEGIN {
                    printf "| %s | %d | %d | %.1f s | %.1f ms | %.1f ms | %s | %.0f MB |\n",
                        solve, n, nodes, setup, 1e3 * ps / s, 1e3 * flow / s,
                        it == "" ? "-" : sprintf("%.1f", it / s), rss }'
        done
    done
done
