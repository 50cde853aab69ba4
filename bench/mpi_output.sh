#!/bin/sh
# The cost of the field outputs on several processes (issue 28;
# docs/PERFORMANCE.md "Field outputs in pieces"): the D/128 Mach 2
# cylinder (156,674 cells) on RANKS ranks x 1 thread, 20 steps with a field
# output after every few of them (OUTPUTS in all, VTK only: output.png =
# false), beside the same run with no field output but the first and last,
# for each binary given (NSPD_A, NSPD_B: before and after a change),
# alternated, ROUNDS rounds. Prints per run the wall time and rank 0's peak
# resident set, and the medians: ms per field output (the difference of the
# two runs over the outputs between them) and rank 0's peak.
#   usage: bench/mpi_output.sh NSPD_A NSPD_B [RANKS] [ROUNDS]
set -eu
a=$1
b=$2
ranks=${3:-2}
rounds=${4:-5}
h=$(awk 'BEGIN { printf "%.10g", 1 / 128 }')
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
export OMPI_MCA_rmaps_base_oversubscribe=1

run() { # nspd field_interval dir
    mpiexec -n "$ranks" --bind-to none "$1" run cases/cylinder_ma2_re300.yaml --quiet --force \
        --set "flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: $h}, {length: 2.2, spacing: $h}, {length: 7.2, spacing_start: $h, spacing_end: 0.5}]" \
        --set "flow.grid.y.segments=[{length: 4.6, spacing_start: 0.5, spacing_end: $h}, {length: 2.8, spacing: $h}, {length: 4.6, spacing_start: $h, spacing_end: 0.5}]" \
        --set flow.bodies.0.markers=808 --set time.end=1e-2 --set "output.field_interval=$2" \
        --set output.png=false --set output.plots=false --set output.average_from=0 -o "$3"
}

key() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"; }

for r in $(seq "$rounds"); do
    for which in a b; do
        eval nspd=\$$which
        run "$nspd" 5e-4 "$work/many"
        run "$nspd" 1 "$work/few"
        outputs=$(($(ls "$work/many" | grep -c -E '^flow_[0-9]{5}\.p?vtr$') - 2))
        echo "$which $(key wall_s "$work/many/summary.json") $(key wall_s "$work/few/summary.json") $outputs $(key peak_rss_mb "$work/many/summary.json")" |
            awk -v round="$r" '{ printf "round %d: %s: %.3f s with %d outputs more than %.3f s: %.1f ms an output; rank 0 peak %.1f MB\n",
                round, $1, $2, $4, $3, 1e3 * ($2 - $3) / $4, $5 }' | tee -a "$work/lines"
    done
done
echo "medians over $rounds rounds ($ranks ranks):"
for which in a b; do
    grep ": $which: " "$work/lines" | awk -v what="$which" '
        { o[NR] = $(NF - 8); m[NR] = $(NF - 1) }
        function med(x, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
            return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
        END { printf "%s: %.1f ms an output, rank 0 peak %.1f MB\n", what, med(o, NR), med(m, NR) }'
done
