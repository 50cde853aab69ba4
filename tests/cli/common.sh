# What the end-to-end tests share (sourced by tests/cli/test_*.sh after they
# set $src): a scratch directory removed at exit (kept, and its path
# printed, when NSPD_KEEP_WORK is set), the check counters with ok / fail,
# the closing line and exit status (finish), and the coarse golden runs'
# overrides (golden_overrides CASE: one per line, from tests/golden/runs.txt).
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
