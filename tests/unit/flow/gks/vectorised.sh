#!/bin/sh
# The GKS step's row loops stay vectorised (ctest unit.flow.gks.vectorised).
#
#   vectorised.sh CC SOURCE_DIR WORK_DIR
#
# Each loop marked `NSPD_IVDEP /* vectorised: ... */` in src/flow/gks/*.c
# (the face fluxes, the slopes, the stable step's rates) must be reported
# by GCC's -fopt-info-vec as vectorised, compiled as the release build
# compiles it (-O3 -march=native -fno-math-errno). A byte loaded beside
# the doubles once kept the flux loop scalar without a word from the
# build, and a step took 4.3 times as long (docs/PERFORMANCE.md,
# "Rooflines"). Another compiler than GCC: skipped (exit 77).
set -u
cc=$1
src=$2
work=$3
macros=$(echo | "$cc" -dM -E - 2>/dev/null)
if ! echo "$macros" | grep -q '__GNUC__' || echo "$macros" | grep -q '__clang__'; then
    echo "$cc is not GCC: the vectorisation report is GCC's; skipped"
    exit 77
fi
mkdir -p "$work" || exit 1
status=0
marked=0
for file in "$src"/src/flow/gks/*.c; do
    lines=$(grep -n 'NSPD_IVDEP /\* vectorised' "$file" | cut -d: -f1)
    [ -n "$lines" ] || continue
    name=$(basename "$file")
    report="$work/${name%.c}.txt"
    rm -f "$report"
    "$cc" -O3 -march=native -fno-math-errno -fopenmp -std=c17 -D_DEFAULT_SOURCE \
        -D_POSIX_C_SOURCE=200809L -I "$src/src" -fopt-info-vec-optimized="$report" \
        -c "$file" -o "$work/${name%.c}.o" || { echo "FAIL: $name does not compile"; exit 1; }
    for line in $lines; do
        marked=$((marked + 1))
        loop=$((line + 1))
        if ! grep -q "$name:$loop:[0-9]*: optimized: loop vectorized" "$report"; then
            echo "FAIL: $name:$loop: the row loop is no longer vectorised (gcc -fopt-info-vec-all says why)"
            status=1
        fi
    done
done
[ "$marked" -gt 0 ] || { echo "FAIL: no marked loop found"; exit 1; }
[ "$status" -eq 0 ] && echo "$marked marked row loops vectorised"
exit $status
