#!/bin/sh
# Runs the libFuzzer harnesses one after the other (make fuzz; docs/RELIABILITY.md).
#   usage: tests/fuzz/fuzz.sh BUILD_FUZZ SECONDS [HARNESS...]   (harnesses: case vtk sim expr stl inp)
# Each harness runs for SECONDS in fork mode with one worker (-fork=1: one
# core, and a crash, leak, timeout or out-of-memory is saved and the run goes
# on, so a long run finds everything it can instead of stopping at the
# first). It starts from the seed corpus (tests/fuzz/corpus/HARNESS) and the
# regression inputs (tests/fuzz/regressions/HARNESS), and keeps what it
# learns in BUILD_FUZZ/corpus/HARNESS (not committed). Every input that
# crashed, leaked, hung or ran out of memory is copied into
# tests/fuzz/regressions/HARNESS/, where `make test` replays it
# (unit.fuzz.HARNESS) once the bug is fixed. Exit status 1 if anything was
# found.
set -u
build=$1
seconds=$2
shift 2
[ $# -gt 0 ] || set -- case vtk sim expr stl inp
src=$(cd "$(dirname "$0")/../.." && pwd)
fuzz=$src/tests/fuzz
found=0
summary=""

for h in "$@"; do
    exe=$build/tests/fuzz/fuzz_$h
    [ -x "$exe" ] || { echo "fuzz.sh: no $exe; build it first (make fuzz)" >&2; exit 2; }
    case $h in
    case | sim) max_len=16384 ;;
    expr) max_len=1100 ;;
    *) max_len=65536 ;;
    esac
    seeds=$h # fuzz_sim reads case files: the case seeds and dictionary
    [ "$h" = sim ] && seeds=case
    work=$build/corpus/$h
    artifacts=$build/artifacts/$h
    log=$build/fuzz_$h.log
    # the harnesses' scratch directories (and libFuzzer's fork-mode files)
    # go here, so a crashed worker leaves nothing in /tmp; one per harness,
    # so that two harnesses can run side by side (one core each)
    tmp=$build/tmp/$h
    rm -rf "$artifacts" "$tmp"
    mkdir -p "$work" "$artifacts" "$tmp" "$fuzz/regressions/$h"
    echo "fuzz_$h: $seconds s, log $log"
    TMPDIR=$tmp "$exe" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
        -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=$max_len \
        -dict="$fuzz/$seeds.dict" -artifact_prefix="$artifacts/" -print_final_stats=1 \
        "$work" "$fuzz/corpus/$seeds" "$fuzz/regressions/$h" >"$log" 2>&1
    status=$?
    rm -rf "$tmp"
    new=0
    for f in "$artifacts"/crash-* "$artifacts"/leak-* "$artifacts"/timeout-* "$artifacts"/oom-*; do
        [ -f "$f" ] || continue
        cp "$f" "$fuzz/regressions/$h/"
        echo "  found: $(basename "$f") -> tests/fuzz/regressions/$h/"
        new=$((new + 1))
    done
    # the parent's last status line: "#RUNS: cov: C ft: F corp: N exec/s E
    # oom/timeout/crash: a/b/c time: Ts ..."
    last=$(grep -E '^#[0-9]+: cov: ' "$log" | tail -n 1)
    files=$(find "$work" -type f | wc -l)
    bytes=$(du -sk "$work" | cut -f1)
    line="fuzz_$h: ${last:-no status line (see $log)}; working corpus $files files, ${bytes} kB; $new new artifacts (libFuzzer exit $status)"
    echo "$line"
    summary="$summary$line
"
    [ "$new" -eq 0 ] || found=1
done

echo
echo "summary ($seconds s per harness):"
printf '%s' "$summary"
[ "$found" -eq 0 ] || echo "inputs that failed are in tests/fuzz/regressions/: fix the reader, keep the input"
exit $found
