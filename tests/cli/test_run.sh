#!/bin/sh
# nspd run end to end on a small case: every output file is there and well
# formed, the resolved case.yaml repeats the run bit for bit, an existing
# directory needs --force, and Ctrl-C stops cleanly (exit 130, outputs
# complete, summary marked interrupted).
#   usage: test_run.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

# a coarse plate: 10,600 points, 250 steps, crack grows (see tests/verify/pd_plate)
out="$work/plate"
if "$nspd" run "$src/cases/plate_crack.yaml" -o "$out" --quiet --set solid.spacing=5e-4 \
    --set solid.thickness=5e-4 --set time.dt=6.6835e-8 --set solid.material.critical_stretch=0.02 \
    --set "solid.geometry=[{shape: rectangle, min: [-0.025, -0.0265], max: [0.025, 0.0265]}]" \
    --set "output.probes.1.region=[{shape: rectangle, min: [-0.025, 0.0], max: [0.025, 5.0e-4]}]"
then ok; else fail "run exit $?"; fi
for f in case.yaml log.txt history.csv summary.json solid.pvd solid_00000.vtu solid_00010.vtu \
    damage_00000.png damage_00010.png line_upper_face_00010.csv; do
    if [ -s "$out/$f" ]; then ok; else fail "missing $f"; fi
done
head -1 "$out/history.csv" | grep -q "^step,time_s,kinetic_energy_J,elastic_energy_J,total_energy_J,broken_bonds,crack_tip_x_m,crack_tip_y_m$" && ok || fail "history header: $(head -1 "$out/history.csv")"
[ "$(wc -l <"$out/history.csv")" -ge 250 ] && ok || fail "history rows"
for key in time_s steps wall_s threads crack_tip_x_m crack_speed_m_per_s; do
    grep -q "\"$key\": [0-9.e+-]*" "$out/summary.json" && ok || fail "summary lacks $key"
done
grep -q '"completed": true' "$out/summary.json" && ok || fail "not completed"
grep -q "spacing: 5e-4" "$out/case.yaml" && grep -q "safety_factor: 0.8" "$out/case.yaml" && ok ||
    fail "case.yaml lacks an override or a default"

# the resolved case repeats the run exactly
if "$nspd" run "$out/case.yaml" -o "$work/again" --quiet; then ok; else fail "rerun of case.yaml"; fi
cmp -s "$out/history.csv" "$work/again/history.csv" && ok || fail "resolved case gave another history"
cmp -s "$out/solid_00010.vtu" "$work/again/solid_00010.vtu" && ok || fail "resolved case gave other fields"

# an existing directory needs --force, which replaces the results
"$nspd" run "$out/case.yaml" -o "$out" --quiet 2>/dev/null
[ $? -eq 2 ] && ok || fail "existing directory not refused"
touch "$out/my_notes.txt"
if "$nspd" run "$out/case.yaml" -o "$out" --quiet --force --set time.end=2e-7 \
    --set output.average_from=0; then ok; else fail "--force"; fi
[ -e "$out/my_notes.txt" ] && ok || fail "--force removed a file that nspd did not write"

# Ctrl-C: finish the step, write outputs, exit 130 (the coarse plate: the
# full one takes most of a minute to build under the sanitizers)
"$nspd" run "$src/cases/plate_crack.yaml" -o "$work/stopped" --quiet --set solid.spacing=5e-4 \
    --set solid.thickness=5e-4 --set time.end=1.0 --set output.history_interval=1e-3 \
    --set output.field_interval=1.0 &
pid=$!
i=0
while [ ! -s "$work/stopped/history.csv" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
sleep 1
kill -INT $pid
wait $pid
status=$?
[ $status -eq 130 ] && ok || fail "interrupted run exit $status, expected 130"
grep -q '"interrupted": true' "$work/stopped/summary.json" 2>/dev/null && ok || fail "summary not marked interrupted"
[ -s "$work/stopped/solid_00001.vtu" ] && ok || fail "no final field output after Ctrl-C"

# A solid that blows up (a time step 10x the stable one) stops the run where
# it happens: status 1, the point, its coordinates and the step named, the
# outputs before kept, summary.json incomplete and why.
"$nspd" run "$src/cases/plate_crack.yaml" -o "$work/blowup" --quiet --set solid.spacing=5e-4 \
    --set solid.thickness=5e-4 --set time.dt=1e-6 --set time.end=1e-4 2>"$work/err"
status=$?
[ $status -eq 1 ] && ok || fail "blown-up solid: exit $status, expected 1"
grep -q "the solid blew up by t = .*: point [0-9]* at (.*) m has displacement .* (in step [0-9]*, from t" \
    "$work/err" && ok || fail "blown-up solid: message '$(cat "$work/err")'"
grep -q '"completed": false' "$work/blowup/summary.json" && grep -q '"stopped_by": "the solid blew up' \
    "$work/blowup/summary.json" && ok || fail "blown-up solid: summary.json does not say why it stopped"
[ -s "$work/blowup/solid_00000.vtu" ] && ok || fail "blown-up solid: the outputs before were not kept"

finish
