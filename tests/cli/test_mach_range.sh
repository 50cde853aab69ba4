# The Mach pictures' colour scale (docs/CASES.md "Pictures"): from the data
# by default, fixed for the series at the first output whose gas moves;
# output.mach_range fixes it instead. The renderer is deterministic, so a
# picture drawn on the scale the rule predicts is byte for byte the one
# drawn with that scale given as the key, and differs from one drawn on
# another scale. The speed pictures: coupled runs only, not moved by the
# key.
#   usage: test_mach_range.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

# Runs the coarse case $1 into $work/$2 with the overrides that follow.
run() {
    name=$1 dir=$2
    shift 2
    set -- run "$src/cases/$name.yaml" -o "$work/$dir" --quiet --threads 1 \
        --set output.plots=false --set output.vtk=false "$@"
    "$nspd" "$@" >"$work/$dir.log" 2>&1 || fail "$name $dir: $(tail -3 "$work/$dir.log")"
}
same() { cmp -s "$work/$1" "$work/$2"; }

# The golden run's overrides of case $1 (tests/golden/runs.txt), one
# argument each after --set, then the arguments that follow, run into $2.
coarse_run() {
    name=$1 dir=$2
    shift 2
    old_ifs=$IFS
    IFS='
'
    # shellcheck disable=SC2046 # one override a line: split on newlines only
    set -- $(golden_overrides "$name" | sed 's/^/--set\n/') "$@"
    IFS=$old_ifs
    run "$name" "$dir" "$@"
}

# Mach 2 at the first output (the free stream): 1.25 x 2 = 2.5
for k in auto:time.end=0.02 key25:output.mach_range=[0,2.5] key3:output.mach_range=[0,3]; do
    coarse_run cylinder_ma2_re300 "${k%%:*}" --set time.end=0.02 --set output.average_from=0 \
        --set output.field_interval=0.01 --set "${k#*:}"
done
same auto/mach_00000.png key25/mach_00000.png && ok ||
    fail "Mach 2's first picture is not drawn on 0 to 2.5"
same auto/mach_00001.png key25/mach_00001.png && ok ||
    fail "Mach 2's second picture is not on the first one's scale"
same auto/mach_00000.png key3/mach_00000.png &&
    fail "mach_range [0, 3] drew the 0 to 2.5 picture" || ok
grep -q mach_range "$work/auto/case.yaml" && fail "case.yaml got a mach_range it was not given" ||
    ok
grep -q 'mach_range: \[0, *3\]' "$work/key3/case.yaml" && ok || fail "case.yaml lost the mach_range"

# A charge at rest (the golden run's resolution): the first frame is drawn
# 0 to 1 and leaves the scale open, the second fixes it from its data, so
# it is not the 0-to-1 picture; the IGA flow alike. Coupled: mach_damage
# follows the key too. At the CFL step (time.dt=stable): the pictures, not
# the paper's steps, are what is tested here.
for method in gks iga; do
    coarse_run chamber_detonation rest_$method --set flow.method=$method --set time.dt=stable
    coarse_run chamber_detonation one_$method --set flow.method=$method --set time.dt=stable \
        --set "output.mach_range=[0, 1]"
    coarse_run chamber_detonation two_$method --set flow.method=$method --set time.dt=stable \
        --set "output.mach_range=[0.5, 2]"
    same rest_$method/mach_00000.png one_$method/mach_00000.png && ok ||
        fail "$method: the frame at rest is not drawn 0 to 1"
    same rest_$method/mach_00001.png one_$method/mach_00001.png &&
        fail "$method: the moving frame stayed on 0 to 1 (the frame at rest fixed the scale)" || ok
    same one_$method/mach_damage_00001.png two_$method/mach_damage_00001.png &&
        fail "$method: mach_damage ignores output.mach_range" || ok
    # the air speed (paper 003 Figs. 2, 7): drawn for coupled runs, with the
    # solid on top too; mach_range leaves it alone
    [ -f "$work/rest_$method/speed_00001.png" ] && [ -f "$work/rest_$method/speed_damage_00001.png" ] &&
        ok || fail "$method: the coupled chamber drew no speed or speed_damage picture"
    same rest_$method/speed_00001.png two_$method/speed_00001.png && ok ||
        fail "$method: output.mach_range moved the speed picture's scale"
done
# ... and not for a flow alone (the Mach picture shows it; pictures cost)
ls "$work/auto" | grep -q '^speed' && fail "the cylinder alone drew speed pictures" || ok

# refusals: exit 2, the key named
for bad in "[1, 1]" "[-1, 2]" "[0]" "2"; do
    "$nspd" check "$src/cases/cylinder_ma2_re300.yaml" --set "output.mach_range=$bad" \
        >/dev/null 2>"$work/err"
    rc=$?
    [ $rc -eq 2 ] && grep -q "output.mach_range" "$work/err" && ok ||
        fail "mach_range=$bad: exit $rc, '$(cat "$work/err")'"
done
"$nspd" check "$src/cases/plate_crack.yaml" --set "output.mach_range=[0, 2]" >/dev/null \
    2>"$work/err"
rc=$?
[ $rc -eq 2 ] && grep -q "draws no Mach picture" "$work/err" && ok ||
    fail "a solid alone took a mach_range: exit $rc, '$(cat "$work/err")'"
finish
