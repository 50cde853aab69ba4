#!/bin/sh
# Force coefficients need a reference speed (issue 61): against a gas at
# rest they are omitted - no cd, cl, cp_stagnation columns or summary keys,
# no cp, cf in the surface tables - with one warning on stderr at check and
# at run start, instead of being written as 0; a case with a free stream
# keeps them and says nothing.
#   usage: test_coefficients.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

panel="$src/cases/panel_shock.yaml"
"$nspd" check "$panel" >/dev/null 2>"$work/err" && ok || fail "check panel_shock: $(cat "$work/err")"
[ "$(grep -c "reference speed is 0" "$work/err")" -eq 1 ] && ok ||
    fail "check: expected one warning, got: $(cat "$work/err")"
"$nspd" check "$src/cases/cylinder_crack_ma17.yaml" >/dev/null 2>"$work/err" && [ ! -s "$work/err" ] &&
    ok || fail "a case with a free stream warns: $(cat "$work/err")"

# the golden run's coarse panel, two history rows
set -- run "$panel" -o "$work/panel" --quiet --set output.png=false --set output.plots=false
while IFS= read -r s; do set -- "$@" --set "$s"; done <<EOS
$(golden_overrides panel_shock)
EOS
set -- "$@" --set time.end=2e-5 --set output.history_interval=1e-5 --set output.field_interval=1e-5
"$nspd" "$@" >/dev/null 2>"$work/err" && ok || fail "run panel_shock: $(cat "$work/err")"
[ "$(grep -c "reference speed is 0" "$work/err")" -eq 1 ] && ok ||
    fail "run: expected one warning, got: $(cat "$work/err")"
head -n 1 "$work/panel/history.csv" | grep -q -E '(^|,)(cd|cl|cp_stagnation)(,|$)' &&
    fail "history.csv has coefficients: $(head -n 1 "$work/panel/history.csv")" || ok
head -n 1 "$work/panel/history.csv" | grep -q ',force_x_N_per_m,' && ok || fail "history.csv lost the force"
grep -q -E '"(cd|cl|cp_stagnation|coefficient_samples)"' "$work/panel/summary.json" &&
    fail "summary.json has coefficients" || ok
grep -v '^#' "$work/panel/surface_00000.csv" | head -n 1 | grep -qx 'body,arc_m,x_m,y_m,p_Pa,tau_Pa' && ok ||
    fail "surface table: $(grep -v "^#" "$work/panel/surface_00000.csv" | head -n 1)"
finish
