# History plots: a run writes history_<column>.png for every column of
# history.csv but step and time_s (output.plots, on by default; off writes
# none); nspd plot OUTDIR [COLUMN ...] [--svg] redraws chosen columns, also
# as SVG; an unknown column or a directory without history.csv is refused
# with exit 2, naming the columns there.
#   usage: test_plot.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

coarse="--set solid.spacing=5e-4 --set solid.thickness=5e-4 --set time.end=4e-6"
"$nspd" run "$src/cases/plate_crack.yaml" -o "$work/on" --quiet $coarse || fail "run"
columns=$(head -1 "$work/on/history.csv" | tr ',' '\n' | grep -v -x -e step -e time_s)
for c in $columns; do
    f="$work/on/history_$c.png"
    if [ -s "$f" ] && file "$f" | grep -q "PNG image data, 1000 x 560"; then ok; else
        fail "history_$c.png: $(file "$f" 2>&1)"
    fi
done
[ "$(ls "$work/on" | grep -c '^history_.*\.png$')" -eq "$(echo "$columns" | wc -l)" ] && ok ||
    fail "plots: $(ls "$work/on" | grep '^history_')"

# (a tenth of the steps: what is tested here is the switch and the replot)
"$nspd" run "$src/cases/plate_crack.yaml" -o "$work/off" --quiet $coarse --set output.plots=false \
    --set time.end=4e-7 --set output.history_interval=6.6835e-8 ||
    fail "run with plots off"
[ -z "$(ls "$work/off" | grep '^history_.*\.png$')" ] && ok || fail "output.plots=false wrote plots"

"$nspd" plot "$work/off" kinetic_energy_J broken_bonds --svg >"$work/out" || fail "nspd plot: $(cat "$work/out")"
for c in kinetic_energy_J broken_bonds; do
    [ -s "$work/off/history_$c.png" ] && grep -q "<svg" "$work/off/history_$c.svg" && ok ||
        fail "nspd plot $c: $(ls "$work/off")"
done
[ "$(ls "$work/off" | grep -c '^history_')" -eq 4 ] && ok || fail "nspd plot drew others: $(ls "$work/off")"
python3 -c "import sys, xml.dom.minidom as m; d = m.parse(sys.argv[1]); \
assert d.documentElement.tagName == 'svg' and d.documentElement.getAttribute('width').startswith('1000')" \
    "$work/off/history_kinetic_energy_J.svg" && ok || fail "the SVG is not a 1000-wide SVG document"

"$nspd" plot "$work/off" no_such_column 2>"$work/err"
[ $? -eq 2 ] && grep -q "has no column 'no_such_column'; expected one of: step, time_s, kinetic" \
    "$work/err" && ok || fail "unknown column: $(cat "$work/err")"
mkdir "$work/empty"
"$nspd" plot "$work/empty" 2>"$work/err"
[ $? -eq 2 ] && grep -q "history.csv" "$work/err" && ok || fail "no history: $(cat "$work/err")"
ls "$work/off" "$work/empty" | grep -q '\.part$' && fail "a .part file was left" || ok

finish
