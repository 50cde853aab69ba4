#!/bin/sh
# Strong scaling of the D/128 Mach 2 cylinder (issue 28; docs/PERFORMANCE.md
# "GKS on several processes"): the coupled flow (the immersed boundary with
# sealed ghost faces, its surface loads every history row) on 1 rank x 1
# thread, 1 rank x 2 threads and 2 ranks x 1 thread, alternated, ROUNDS
# rounds, to t = END from rest. Prints one line per run and the medians:
# ms per step of the whole run (outputs included) and of the flow steps,
# and the share of a step in exchanges (halo rows, reductions, the
# immersed boundary's cells) and in the driver's agreement.
#   usage: bench/mpi_cylinder.sh [NSPD] [END] [ROUNDS]
set -eu
nspd=${1:-build/nspd}
end=${2:-0.1}
rounds=${3:-5}
n=128
markers=808
h=$(awk -v n="$n" 'BEGIN { printf "%.10g", 1 / n }')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

run() { # ranks threads dir
    set -- "$@" cases/cylinder_ma2_re300.yaml --quiet --force \
        --set "flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: $h}, {length: 2.2, spacing: $h}, {length: 7.2, spacing_start: $h, spacing_end: 0.5}]" \
        --set "flow.grid.y.segments=[{length: 4.6, spacing_start: 0.5, spacing_end: $h}, {length: 2.8, spacing: $h}, {length: 4.6, spacing_start: $h, spacing_end: 0.5}]" \
        --set "flow.bodies.0.markers=$markers" --set "time.end=$end" --set output.average_from=0 \
        --set output.field_interval=1000 --set output.plots=false
    ranks=$1 threads=$2 dir=$3
    shift 3
    if [ "$ranks" -eq 1 ]; then
        OMP_NUM_THREADS=$threads "$nspd" run "$@" -o "$dir"
    else
        OMP_NUM_THREADS=$threads mpiexec -n "$ranks" --bind-to none "$nspd" run "$@" -o "$dir" \
            --processes "1x$ranks" # slabs of rows: the layout of the figures
    fi
}

key() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"; }

for r in $(seq "$rounds"); do
    for layout in "1 1" "1 2" "2 1"; do
        set -- $layout
        dir="$work/r$1t$2"
        run "$1" "$2" "$dir"
        s="$dir/summary.json"
        steps=$(key steps "$s")
        echo "$1 $2 $steps $(key wall_s "$s") $(key flow_s "$s") $(key exchange_s "$s") $(key agree_s "$s")" |
            awk -v round="$r" '{ printf "round %d: %d rank x %d thread: %d steps, %.2f ms/step, flow %.2f ms/step, exchange %.3f ms/step, agree %.3f ms/step\n",
                round, $1, $2, $3, 1e3 * $4 / $3, 1e3 * $5 / $3, 1e3 * ($6 == "" ? 0 : $6) / $3, 1e3 * ($7 == "" ? 0 : $7) / $3 }' |
            tee -a "$work/lines"
    done
done
echo "medians over $rounds rounds:"
for layout in "1 rank x 1 thread" "1 rank x 2 thread" "2 rank x 1 thread"; do
    grep "$layout" "$work/lines" | awk -v what="$layout" '
        { w[NR] = $(NF - 10); f[NR] = $(NF - 7); e[NR] = $(NF - 4); a[NR] = $(NF - 1) }
        function med(x, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
            return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
        END { printf "%s: %.2f ms/step (flow %.2f), exchange %.3f, agree %.3f ms/step\n", what, med(w, NR), med(f, NR), med(e, NR), med(a, NR) }'
done
