#!/bin/sh
# The isogeometric flow against the GKS flow on the same mesh (issue 25):
# the machine's ceilings (nspd bench flops, memory), then the free-field
# blast (cases/iga_cylindrical_blast.yaml, 50 x 50 elements or cells, to
# 130 us) on both backgrounds at 1 and 2 threads, alternating, medians of
# 5: wall time, stepping time (flow_s), steps, and the IGA flow's cost
# per quadrature point and corrector pass.
# Usage: bench/iga_vs_gks.sh [build/nspd] [REPEATS]
set -eu
NSPD=${1:-build/nspd}
reps=${2:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
key() { sed -n "s/.*\"$2\": \([^,]*\),*/\1/p" "$1" | head -1; }
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

for t in 1 2; do
    echo "threads $t: $("$NSPD" bench flops --threads "$t" | tr -d ' \n' | sed 's/.*"fp64_simd/"fp64_simd/; s/,"check.*//')"
    echo "threads $t: $("$NSPD" bench memory --threads "$t" | tr -d ' \n' | sed 's/.*"triad/"triad/; s/,"check.*//')"
done
for t in 1 2; do
    : >"$out/iga_$t" && : >"$out/gks_$t"
    for r in $(seq "$reps"); do
        for bg in iga gks; do
            "$NSPD" run cases/iga_cylindrical_blast.yaml -o "$out/run" --force --quiet --threads "$t" \
                --set flow.method=$bg --set output.field_interval=1
            s=$out/run/summary.json
            echo "$(key "$s" wall_s) $(key "$s" steps) $(key "$s" flow_s)" >>"$out/${bg}_$t"
        done
    done
    for bg in iga gks; do
        w=$(cut -d' ' -f1 "$out/${bg}_$t" | median)
        f=$(cut -d' ' -f3 "$out/${bg}_$t" | median)
        steps=$(head -1 "$out/${bg}_$t" | cut -d' ' -f2)
        printf 'blast 50 x 50, %s, %d thread(s): wall %s s, stepping %s s (medians of %d), %s steps' \
            "$bg" "$t" "$w" "$f" "$reps" "$steps"
        # the stepping time (flow_s) over 2500 elements x 9 points x 3 passes a step
        [ "$bg" = iga ] && awk -v f="$f" -v s="$steps" -v t="$t" \
            'BEGIN { printf ", %.2f us per quadrature point and pass (%.2f core-us)", 1e6 * f / (2500 * 9 * 3 * s), 1e6 * t * f / (2500 * 9 * 3 * s) }'
        echo
    done
done
