# nspd info's run-time estimate (docs/PERFORMANCE.md "nspd info's
# estimate"): the steps counted between the first step's size and the
# size five steps on, the solid by its sub-steps, and, for a solid whose
# cost grows once it breaks (a correspondence solid with a failure law),
# a second, larger figure; none for one that cannot break. No timing is
# compared here (the machine is shared): the measured table is in the doc.
#   usage: test_info_estimate.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

# nspd info on the golden run of case $1 (its overrides, one a line), with
# the arguments that follow, into $work/$1.info
info() {
    name=$1
    shift
    old_ifs=$IFS
    IFS='
'
    # shellcheck disable=SC2046 # one override a line: split on newlines only
    set -- $(golden_overrides "$name" | sed 's/^/--set\n/') "$@"
    IFS=$old_ifs
    "$nspd" info "$src/cases/$name.yaml" --threads 1 "$@" >"$work/$name.info" 2>&1 ||
        fail "info $name: $(tail -3 "$work/$name.info")"
}
seconds() { # progress_format_duration's "24.7s", "1m02s", "2h05m" -> seconds
    echo "$1" | awk '{t = 0; s = $0; while (match(s, /^[0-9.]+[hms]/)) {
        v = substr(s, 1, RLENGTH - 1) + 0; u = substr(s, RLENGTH, 1);
        t += v * (u == "h" ? 3600 : u == "m" ? 60 : 1); s = substr(s, RLENGTH + 1) } print t}'
}

# at the file's own (coarse) mesh: the golden run's 0.1 s rounds both
# figures alike
"$nspd" info "$src/cases/blast_hollow_square.yaml" --threads 1 >"$work/blast_hollow_square.info" \
    2>&1 || fail "info blast_hollow_square: $(tail -3 "$work/blast_hollow_square.info")"
line=$(grep '^estimated run time' "$work/blast_hollow_square.info")
echo "$line" | grep -q 'if the solid yields and breaks' && ok ||
    fail "a breaking correspondence solid got no second figure: '$line'"
first=$(seconds "$(echo "$line" | sed 's/^estimated run time *\([^,]*\),.*/\1/')")
broken=$(seconds "$(echo "$line" | sed 's/.*, or \(.*\) if the solid.*/\1/')")
awk -v a="$first" -v b="$broken" 'BEGIN { exit !(a > 0 && b > 1.5 * a) }' && ok ||
    fail "the broken figure $broken s is not well above $first s: '$line'"
echo "$line" | grep -q 'over about [0-9]* steps' && ok || fail "no step count: '$line'"

info chamber_detonation
line=$(grep '^estimated run time' "$work/chamber_detonation.info")
echo "$line" | grep -q 'yields and breaks' && fail "an unbreakable block got a broken figure" ||
    ok
echo "$line" | grep -q '^estimated run time *[0-9.]*[a-z]* (.* s per step over about [0-9]* steps' &&
    ok || fail "chamber_detonation: '$line'"

# a solid alone: its steps are fixed, the count is the planned one
info plate_crack
planned=$(sed -n 's/^steps *\([0-9]*\) .*/\1/p' "$work/plate_crack.info")
grep -q "over $planned steps" "$work/plate_crack.info" && ok ||
    fail "plate_crack: not over its $planned planned steps: $(grep estimated "$work/plate_crack.info")"
finish
