#!/bin/sh
# The loops that must run in SIMD lanes stay vectorised (ctest
# unit.core.vectorised).
#
#   vectorised.sh CC SOURCE_DIR WORK_DIR [--from-build]
#
# With --from-build the reports are those the release build wrote into
# WORK_DIR as it compiled the files (CMakeLists.txt, NSPD_VEC_REPORTS);
# without, each file is compiled here as the release build compiles it
# (-O3 -march=native -fno-math-errno). GCC's -fopt-info-vec must report
# as vectorised:
# - each loop marked `NSPD_IVDEP /* vectorised: ... */` (the loop is on the
#   next line): the GKS step's face fluxes, slopes and stable-step rates;
# - for a mark `/* vectorised xN: ... */` on the line before a statement,
#   N loops reported there in 32- or 64-byte vectors (4 or 8 doubles: GCC
#   tuned for Intel's AVX-512 cores picks 32, for AMD's Zen, which it
#   takes for znver3, 64; 16 bytes, two lanes, would not count): GCC names an `omp simd`
#   loop over an inlined body by the body's first statement (the
#   correspondence solid's passes over bond pairs).
# A byte loaded beside the doubles once kept the GKS flux loop scalar
# without a word from the build, and a step took 4.3 times as long
# (docs/PERFORMANCE.md, "Rooflines"); an ordered comparison or an int flag
# can do the same to the pair passes (docs/STYLE.md). Another compiler
# than GCC: skipped (exit 77).
set -u
cc=$1
src=$2
work=$3
macros=$(echo | "$cc" -dM -E - 2>/dev/null)
if ! echo "$macros" | grep -q '__GNUC__' || echo "$macros" | grep -q '__clang__'; then
    echo "$cc is not GCC: the vectorisation report is GCC's; skipped"
    exit 77
fi
from_build=${4:-}
mkdir -p "$work" || exit 1
status=0
marked=0
for file in "$src"/src/flow/gks/*.c "$src"/src/solid/correspondence/*.c; do
    grep -q '/\* vectorised' "$file" || continue
    name=${file#"$src"/src/} # flow/gks/step.c: both folders have a step.c
    report="$work/$(echo "${name%.c}" | tr / _).txt"
    if [ "$from_build" = --from-build ]; then
        [ -f "$report" ] || { echo "FAIL: the build wrote no report $report (re-run cmake)"; exit 1; }
    else
        rm -f "$report"
        "$cc" -O3 -march=native -fno-math-errno -fopenmp -std=c17 -D_DEFAULT_SOURCE \
            -D_POSIX_C_SOURCE=200809L -I "$src/src" -fopt-info-vec-optimized="$report" \
            -c "$file" -o "${report%.txt}.o" || { echo "FAIL: $name does not compile"; exit 1; }
    fi
    for line in $(grep -n 'NSPD_IVDEP /\* vectorised' "$file" | cut -d: -f1); do
        marked=$((marked + 1))
        loop=$((line + 1))
        if ! grep -q "$name:$loop:[0-9]*: optimized: loop vectorized" "$report"; then
            echo "FAIL: $name:$loop: the loop is no longer vectorised (gcc -fopt-info-vec-all says why)"
            status=1
        fi
    done
    for mark in $(grep -n '/\* vectorised x[0-9]*:' "$file" | sed 's/^\([0-9]*\):.*vectorised x\([0-9]*\):.*/\1:\2/'); do
        line=${mark%:*}
        want=${mark#*:}
        marked=$((marked + want))
        at=$((line + 1))
        got=$(grep -c -E "$name:$at:[0-9]*: optimized: loop vectorized using (32|64) byte vectors" "$report")
        if [ "$got" -lt "$want" ]; then
            echo "FAIL: $name:$at: $got of the $want loops over this body vectorised (gcc -fopt-info-vec-all says why)"
            status=1
        fi
    done
done
[ "$marked" -gt 0 ] || { echo "FAIL: no marked loop found"; exit 1; }
[ "$status" -eq 0 ] && echo "$marked marked loops vectorised"
exit $status
