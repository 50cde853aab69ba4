#!/bin/sh
# The divided solid of a coupled case on several processes (issue 28;
# docs/PERFORMANCE.md "GKS on several processes"): the panel in a shock
# (3,224 points, 59,540 cells) to t = 1e-4 and the cracking cylinder
# (31,428 points, 66,750 cells) to t = 1e-3, each on 1 rank x 1 thread and
# 2 ranks x 1 thread, alternated, ROUNDS rounds. Prints per run and as
# medians the ms per step of the flow, the solid and the coupling: the
# flow and the bond solid are divided between the ranks (solid/bond/halo.h),
# the coupling's interface is not (every rank moves the whole immersed
# boundary and gathers the surface points' view of the solid).
#   usage: bench/mpi_coupled.sh [NSPD] [ROUNDS]
set -eu
nspd=${1:-build/nspd}
rounds=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1

key() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$2"; }

for r in $(seq "$rounds"); do
    for c in "panel_shock 1e-4" "cylinder_crack_ma17 1e-3"; do
        set -- $c
        for ranks in 1 2; do
            dir="$work/$1.$ranks"
            set -- "$1" "$2" cases/"$1".yaml -o "$dir" --quiet --force --set "time.end=$2" \
                --set output.field_interval=1 --set output.plots=false
            name=$1
            shift 2
            if [ "$ranks" -eq 1 ]; then
                "$nspd" run "$@"
            else
                mpiexec -n 2 --bind-to none "$nspd" run "$@" --processes 1x2 # slabs
            fi
            s="$dir/summary.json"
            echo "$name $ranks $(key steps "$s") $(key wall_s "$s") $(key flow_s "$s") $(key solid_s "$s") $(key coupling_s "$s")" |
                awk '{ printf "%s on %d ranks: %d steps, %.2f ms/step: flow %.2f, solid %.2f, coupling %.2f\n",
                    $1, $2, $3, 1e3 * $4 / $3, 1e3 * $5 / $3, 1e3 * $6 / $3, 1e3 * $7 / $3 }' |
                tee -a "$work/lines"
            set -- "$name" "$(echo "$c" | cut -d' ' -f2)"
        done
    done
done
echo "medians over $rounds rounds:"
for c in panel_shock cylinder_crack_ma17; do
    for ranks in 1 2; do
        grep "^$c on $ranks ranks" "$work/lines" | awk -v what="$c on $ranks ranks" '
            { gsub(",", ""); w[NR] = $7; f[NR] = $10; s[NR] = $12; k[NR] = $14 }
            function med(x, n,   i, j, t) { for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (x[j] < x[i]) { t = x[i]; x[i] = x[j]; x[j] = t }
                return n % 2 ? x[(n + 1) / 2] : (x[n / 2] + x[n / 2 + 1]) / 2 }
            END { printf "%s: %.2f ms/step (flow %.2f, solid %.2f, coupling %.2f)\n", what, med(w, NR), med(f, NR), med(s, NR), med(k, NR) }'
    done
done
