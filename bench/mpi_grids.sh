#!/bin/sh
# 2D process grids against slabs (issue 28; docs/PERFORMANCE.md "GKS on
# several processes"): the isentropic vortex on N x N cells (a flow alone),
# to t = END (about 40 steps at N = 512), history every 0.1, no fields, 1 thread a rank; on 2 ranks
# as 1x2 (slabs of rows) and 2x1 (columns), on 4 ranks (oversubscribed on
# 2 cores) as 1x4 and 2x2; alternated, ROUNDS rounds. Prints per run and
# as medians the ms per step and the share in exchanges and reductions
# (summary.json's exchange_s, rank 0).
#   usage: bench/mpi_grids.sh [NSPD] [N] [END] [ROUNDS]
set -eu
nspd=${1:-build/nspd}
n=${2:-512}
end=${3:-0.2}
rounds=${4:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
key() { v=$(sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"); echo "${v:-0}"; }
for r in $(seq "$rounds"); do
    for layout in "2 1x2" "2 2x1" "4 1x4" "4 2x2"; do
        set -- $layout
        dir="$work/$2"
        mpiexec -n "$1" --oversubscribe --bind-to none "$nspd" run cases/vortex.yaml -o "$dir" \
            --quiet --force --processes "$2" --set "time.end=$end" \
            --set "flow.grid.x.segments=[{length: 10.0, cells: $n}]" \
            --set "flow.grid.y.segments=[{length: 10.0, cells: $n}]" \
            --set output.field_interval=1e9 --set output.plots=false
        s="$dir/summary.json"
        echo "$2 $(key steps "$s") $(key flow_s "$s") $(key exchange_s "$s")" |
            awk '{ printf "%s: %d steps, %.2f ms/step, exchange %.3f ms/step (%.1f %%)\n", $1, $2, 1e3 * $3 / $2, 1e3 * $4 / $2, 100 * $4 / $3 }' |
            tee -a "$work/lines"
    done
done
echo "medians over $rounds rounds:"
for layout in 1x2 2x1 1x4 2x2; do
    grep "^$layout:" "$work/lines" | awk -v what="$layout" '
        { t[NR] = $4; e[NR] = $7 }
        function med(x, n,   i, j, s) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { s = x[i]; x[i] = x[j]; x[j] = s }
            return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
        END { printf "%s: %.2f ms/step, exchange %.3f ms/step\n", what, med(t, NR), med(e, NR) }'
done
