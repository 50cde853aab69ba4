#!/bin/sh
# Strong scaling of a solid (issue 28; docs/PERFORMANCE.md "GKS on
# several processes"): by default the pre-cracked plate of paper 000 at
# its own resolution (253,000 points, 3.5 million bonds) divided by points
# (solid/bond/halo.h), or CASE with its --set arguments (a correspondence
# solid: solid/correspondence/halo.h), on 1 rank x 1 thread, 1 rank x 2
# threads and 2 ranks x 1 thread, alternated, ROUNDS rounds, to t = END
# (the case's history; no field files). Prints one line per run and the
# medians: ms per step of the whole run and of the solid's steps, the
# share in the solid's ghosts' exchange and reductions, and the peak
# memory of rank 0.
#   usage: bench/mpi_plate.sh [NSPD] [END] [ROUNDS] [CASE [ARGS...]]
set -eu
nspd=${1:-build/nspd}
end=${2:-2.67e-6}
rounds=${3:-5}
case_file=${4:-cases/plate_crack.yaml}
[ $# -ge 4 ] && shift 4 || shift $#
extra=$*
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

run() { # ranks threads dir
    ranks=$1 threads=$2 dir=$3
    set -- "$case_file" --quiet --force --set "time.end=$end" \
        --set output.field_interval=1 --set output.plots=false -o "$dir" $extra
    if [ "$ranks" -eq 1 ]; then
        OMP_NUM_THREADS=$threads "$nspd" run "$@"
    else
        OMP_NUM_THREADS=$threads mpiexec -n "$ranks" --bind-to none "$nspd" run "$@"
    fi
}

# a summary key's value, 0 where the run has none (one process: no exchanges)
key() { v=$(sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"); echo "${v:-0}"; }

for r in $(seq "$rounds"); do
    for layout in "1 1" "1 2" "2 1"; do
        set -- $layout
        dir="$work/r$1t$2"
        run "$1" "$2" "$dir"
        s="$dir/summary.json"
        echo "$1 $2 $(key steps "$s") $(key wall_s "$s") $(key solid_s "$s") $(key solid_exchange_s "$s") $(key peak_rss_mb "$s")" |
            awk -v round="$r" '{ printf "round %d: %d rank x %d thread: %d steps, %.2f ms/step, solid %.2f ms/step, exchange %.3f ms/step, rss %.0f MB\n",
                round, $1, $2, $3, 1e3 * $4 / $3, 1e3 * $5 / $3, 1e3 * $6 / $3, $7 }' |
            tee -a "$work/lines"
    done
done
echo "medians over $rounds rounds:"
for layout in "1 rank x 1 thread" "1 rank x 2 thread" "2 rank x 1 thread"; do
    grep "$layout" "$work/lines" | awk -v what="$layout" '
        { w[NR] = $(NF - 10); f[NR] = $(NF - 7); e[NR] = $(NF - 4); m[NR] = $(NF - 1) }
        function med(x, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
            return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
        END { printf "%s: %.2f ms/step (solid %.2f), exchange %.3f ms/step, rss %.0f MB\n", what, med(w, NR), med(f, NR), med(e, NR), med(m, NR) }'
done
