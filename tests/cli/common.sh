# What the end-to-end tests share (sourced by tests/cli/test_*.sh after they
# set $src): a scratch directory removed at exit (kept, and its path
# printed, when NSPD_KEEP_WORK is set), the check counters with ok / fail,
# the closing line and exit status (finish), the coarse golden runs'
# overrides (golden_overrides CASE: one per line, from tests/golden/runs.txt)
# and the comparison of two runs' files (same_results).
work=$(mktemp -d)
trap '[ -n "${NSPD_KEEP_WORK:-}" ] && echo "kept $work" || rm -rf "$work"' EXIT
failures=0
count=0
ok() { count=$((count + 1)); }
fail() { count=$((count + 1)); failures=$((failures + 1)); echo "FAIL $*"; }
finish() {
    echo "$((count - failures)) of $count checks passed"
    [ "$failures" -eq 0 ]
}
golden_overrides() {
    sed -n "s/^$1|//p" "$src/tests/golden/runs.txt" | tr ';' '\n'
}

# Every file of the run in $1 is in $2 with the same bytes (summary.json
# but for the keys that measure the machine and the process layout), and
# $2 has no other files than checkpoints and its log; $4 = paths: the two
# runs' cases name different files (case.yaml left out). A check named $3.
# Where $2 holds a grid or a point set in pieces (X.pvtr and its
# X_pNNNN.vtr, or X.pvtu and its .vtu, written by several processes) for
# $1's X.vtr or X.vtu, the two are held array by array by $vtk_same
# (tests/mpi/vtk_same.c; set by tests/mpi/run.sh), and the .pvd series
# must name the parallel file where $1's names the whole one.
same_results() {
    a=$1 b=$2 what=$3 skip=${4:-}
    bad=""
    for f in $(ls "$a"); do
        case "$f" in checkpoint_* | log.txt) continue ;; esac
        [ "$f" = case.yaml ] && [ "$skip" = paths ] && continue
        if [ "$f" = summary.json ]; then
            for d in "$a" "$b"; do
                grep -v -E '"(wall_s|flow_s|solid_s|coupling_s|setup_s|pressure_solve_s|threads|processes|process_grid|exchange_s|solid_exchange_s|agree_s|peak_rss_mb|[a-z_]+_per_s)":' \
                    "$d/summary.json" >"$d.summary"
            done
            cmp -s "$a.summary" "$b.summary" || bad="$bad $f"
        elif [ ! -e "$b/$f" ] && [ -e "$b/${f%.vt?}.pvt${f##*.vt}" ] && [ -n "${vtk_same:-}" ]; then
            "$vtk_same" "$a/$f" "$b/${f%.vt?}.pvt${f##*.vt}" >/dev/null || bad="$bad $f"
        elif [ "${f%.pvd}.pvd" = "$f" ] && grep -q '\.pvt[ru]"' "$b/$f" 2>/dev/null; then
            sed 's/\.pvt\([ru]\)"/.vt\1"/' "$b/$f" | cmp -s "$a/$f" - || bad="$bad $f"
        else
            cmp -s "$a/$f" "$b/$f" || bad="$bad $f"
        fi
    done
    extra=$(ls "$b" | grep -v -e '^checkpoint_' -e '^log.txt$' | while read -r f; do
        # a piece its .pvtr names; a .pvtr for a .vtr, alone
        case "$f" in
        *_p[0-9][0-9][0-9][0-9].vt[ru])
            grep -q "Source=\"$f\"" "$b/${f%_p*}.pvt${f##*.vt}" 2>/dev/null && continue ;;
        *.pvt[ru])
            whole=${f%.pvt?}.vt${f##*.pvt}
            [ -e "$a/$whole" ] && [ ! -e "$b/$whole" ] && continue ;;
        esac
        [ -e "$a/$f" ] || echo "$f"
    done)
    if [ -z "$bad$extra" ]; then
        ok
    else
        fail "$what: differs from $a in:$bad${extra:+; extra files: $extra}"
    fi
}
