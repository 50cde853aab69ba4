#!/bin/sh
# Every kind of bad input is refused before anything runs: exit status 2, a
# "FILE:LINE:COL: what; expected" message on stderr (checked against the
# file's "# expect:" line), and no output directory. Files: tests/cli/bad/.
#   usage: test_bad_input.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
count=0

check() { # name, expected regex, command...
    name=$1
    expect=$2
    shift 2
    count=$((count + 1))
    "$@" >"$work/out" 2>"$work/err"
    status=$?
    if [ "$status" -ne 2 ]; then
        echo "FAIL $name: exit status $status, expected 2"
        cat "$work/err"
        failures=$((failures + 1))
    elif ! grep -Eq -- "$expect" "$work/err"; then
        echo "FAIL $name: message does not match /$expect/:"
        cat "$work/err"
        failures=$((failures + 1))
    elif [ "$placed" = yes ] && ! head -n 1 "$work/err" | grep -Eq '^([^ ]+:[0-9]+:[0-9]+|--set [^ ]+): '; then
        echo "FAIL $name: the message does not start with FILE:LINE:COL or the --set:"
        cat "$work/err"
        failures=$((failures + 1))
    elif [ -e "$work/result" ]; then
        echo "FAIL $name: created the output directory"
        failures=$((failures + 1))
    fi
    rm -rf "$work/result"
}

# every case file of bad/ is refused at a place in it (FILE:LINE:COL, or the
# --set of its "# args:"); the command-line checks below name their option
placed=yes
cd "$src/tests/cli/bad" || exit 1
for file in *.yaml; do
    expect=$(sed -n 's/^# expect: //p' "$file")
    args=$(sed -n 's/^# args: //p' "$file")
    # shellcheck disable=SC2086 # args are words
    check "run $file" "$expect" "$nspd" run "$file" -o "$work/result" $args
    check "check $file" "$expect" "$nspd" check "$file" $args
done
placed=no

check "missing file" "nonexistent.yaml: cannot open the case file" \
    "$nspd" run nonexistent.yaml -o "$work/result"
check "no case" "which case\\?" "$nspd" run
check "unknown option" "unknown option '--fast'" "$nspd" run x.yaml --fast
check "bad --set syntax" "--set solid: expected dotted.key=value" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set solid
check "unknown command" "unknown command 'walk'" "$nspd" walk
# the radial reference solver's options
check "radial geometry" "bad value 'conical' for --geometry" "$nspd" radial --geometry conical
check "radial charge" "bad value '1,0,-1' for --charge" "$nspd" radial --charge 1,0,-1
check "radial grid" "cells >= 2" "$nspd" radial --cells 1
check "radial probe" "probe r = 2 lies outside" "$nspd" radial --probes 0.5,2
# the flow's process grid: PXxPY, and as many blocks as processes
check "bad --processes" "--processes needs the flow's process grid as PXxPY" \
    "$nspd" run "$src/cases/sod.yaml" -o "$work/result" --processes 2
check "a process grid without mpirun" "--processes 2x2 makes 4 blocks for 1 process;" \
    "$nspd" run "$src/cases/sod.yaml" -o "$work/result" --processes 2x2
# the correspondence solid's own keys
hs="$src/cases/hollow_square_pressure.yaml"
check "correspondence: Poisson's ratio" "poisson_ratio: 0.5; expected a Poisson's ratio in \\(-1, 0.5\\)" \
    "$nspd" run "$hs" -o "$work/result" --set solid.material.poisson_ratio=0.5
check "correspondence: 3D" "solid.model: 3d: the correspondence solid is 2D" \
    "$nspd" run "$hs" -o "$work/result" --set solid.model=3d
check "correspondence: ductile without yield" "ductile failure needs plasticity" \
    "$nspd" run "$hs" -o "$work/result" --set solid.material.yield_stress=0
check "correspondence: stabilisation without classic" "stabilisation: the zero-energy stabilisation belongs to the classic" \
    "$nspd" run "$hs" -o "$work/result" --set solid.correspondence.stabilisation=0.5
check "correspondence: a bond-based key" "solid.critical_stretch: unknown key" \
    "$nspd" run "$hs" -o "$work/result" --set solid.critical_stretch=0.1
check "correspondence: brittle without sigma_cr" "solid.failure.critical_stress: missing required key" \
    "$nspd" run "$hs" -o "$work/result" --set solid.failure.law=brittle
check "correspondence: negative pressure time" "a negative time; expected rise_time, hold_time, fall_time >= 0" \
    "$nspd" run "$hs" -o "$work/result" --set solid.pressure_loads.0.rise_time=-1
cyl="$src/cases/cylinder_ma2_re300.yaml"
check "initial.from: no such file" "flow.initial.from: cannot open 'nothere.vtr' \\(No such file" \
    "$nspd" run "$cyl" -o "$work/result" --set "flow.initial={from: nothere.vtr}"
check "initial.from: not a .vtr" "flow.initial.from: .*expected a .vtr written by nspd" \
    "$nspd" run "$cyl" -o "$work/result" --set "flow.initial={from: $cyl}"
# files a case names must be regular files: a device or a FIFO would hang
# the reader (found while writing the fuzz harnesses); `timeout` turns a
# hang into a failure here
mkfifo "$work/fifo"
check "initial.from: a FIFO" "flow.initial.from: cannot open '.*fifo' \\(not a regular file" \
    timeout 10 "$nspd" check "$cyl" --set "flow.initial={from: $work/fifo}"
check "polygon body: /dev/zero" "file: cannot read '/dev/zero' \\(not a regular file" \
    timeout 10 "$nspd" check "$cyl" \
    --set "flow.bodies=[{shape: polygon, name: p, file: /dev/zero}]"
check "polygon body: a FIFO" "file: cannot read '.*fifo' \\(not a regular file" \
    timeout 10 "$nspd" check "$cyl" --set "flow.bodies=[{shape: polygon, name: p, file: $work/fifo}]"
check "horizon of 10^6 spacings" "solid.horizon_factor: 1e\\+06 spacings; expected m <= 50" \
    timeout 10 "$nspd" check "$src/cases/plate_crack.yaml" --set solid.horizon_factor=1e6
check "--set index past 2^31" "'4294967296' is not an item of a 1-item list" \
    "$nspd" check "$cyl" --set flow.bodies.4294967296.markers=40
check "initial.from with a state" "flow.initial.state: given together with 'from'" \
    "$nspd" check "$cyl" --set "flow.initial={from: nothere.vtr, state: free_stream}"
# hostile input (issue 12): a case nested 100,000 levels deep crashed the
# reader; a step or history count past 2^31 wrapped into an absurd allocation
python3 -c "print('a: ' + '[' * 100000 + ']' * 100000)" >"$work/deep.yaml" 2>/dev/null ||
    awk 'BEGIN { s = "a: "; for (i = 0; i < 100000; i++) s = s "["; for (i = 0; i < 100000; i++) s = s "]"; print s }' >"$work/deep.yaml"
check "nested 100,000 deep" "deep.yaml:1:67: maps and lists nested more than 64 deep" \
    "$nspd" check "$work/deep.yaml"
check "deep --set value" "nested more than 64 deep" \
    "$nspd" check "$src/cases/sod.yaml" --set "time.end=$(printf '%0.s[' $(seq 70))1$(printf '%0.s]' $(seq 70))"
awk 'BEGIN { print "name: big"; for (i = 0; i < 300000; i++) printf "# %060d\n", i }' >"$work/big.yaml"
check "a 19 MB case file" "big.yaml: larger than 16 MiB" "$nspd" check "$work/big.yaml"
awk 'BEGIN { s = "name: "; for (i = 0; i < 5000; i++) s = s "x"; print s }' >"$work/long.yaml"
check "a 5000-character value" "long.yaml:1:7: a value of 5000 characters; expected at most 4096" \
    "$nspd" check "$work/long.yaml"
awk 'BEGIN { s = "a: [0"; for (i = 0; i < 100000; i++) s = s ",0"; print s "]" }' >"$work/list.yaml"
check "a list of 100,001 entries" "list.yaml:1:4: more than 100000 entries in one list" \
    "$nspd" check "$work/list.yaml"
check "history rows past the limit" "plate_crack.yaml:[0-9]+:[0-9]+: output.history_interval: .* 1.5e\+10 history rows" \
    "$nspd" info "$src/cases/plate_crack.yaml" --set time.end=1e3
check "field outputs past the limit" "output.field_interval: .* field outputs" \
    "$nspd" check "$src/cases/sod.yaml" --set output.field_interval=1e-9
check "spacing far too small" "solid.spacing: 1e-08 m puts 2.53e\+13 lattice sites" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set solid.spacing=1e-8
# 9.9e8 points need about 400 GB, more than any machine this runs on
check "more memory than the machine" "the case needs about [0-9.]+ GB \\(9.[0-9]+e\\+08 points.* and this machine has" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set solid.spacing=1.6e-6
check "more memory than --max-memory" "and --max-memory allows 0.05 GB" \
    "$nspd" info "$src/cases/plate_crack.yaml" --max-memory 50
check "steps past the limit" "^--set time.end=1e3: time.end = 1000 s needs 7.48e\+10 steps" \
    "$nspd" run "$src/cases/plate_crack.yaml" -o "$work/result" --set time.end=1e3 \
    --set output.history_interval=1e-3 --set output.field_interval=1
# the PDDO flow (flow.method: pddo): a step above its stable limit, a
# lattice that does not divide the rectangle, a lone periodic side, line
# probes (they need a grid), point probes outside the fluid, bodies whose
# patches overlap and too many bodies
cav="$src/cases/cavity_re1.yaml"
check "PDDO step above the limit" "^--set time.dt=2e-4: time.dt: 0.0002 s exceeds the PDDO flow's stable limit 0.00016 s" \
    "$nspd" run "$cav" -o "$work/result" --set time.dt=2e-4
# the limit follows the horizon: 2 spacings cut it to (2/3)^2 of 3's
check "PDDO step above a shorter horizon's limit" "^--set time.dt=1e-4: time.dt: 0.0001 s exceeds the PDDO flow's stable limit 7.111e-05 s" \
    "$nspd" run "$cav" -o "$work/result" --set flow.horizon_factor=2 --set time.dt=1e-4
check "PDDO spacing" "flow.spacing: 3e-05 m gives 33.33333333 spacings along x" \
    "$nspd" check "$cav" --set flow.spacing=3e-5
check "PDDO lone periodic side" "flow.boundaries.x_max: the opposite side x_min is periodic; expected both" \
    "$nspd" check "$cav" --set flow.boundaries.x_min.type=periodic
check "PDDO flow line probe" "probe 'probe0': probes on the flow need a grid; the 'pddo' solver has none" \
    "$nspd" run "$cav" -o "$work/result" --set "output.probes=[{type: line, on: flow, at: [0.0005, 0.0005]}]"
check "PDDO probe outside" "probe 'far': at \\[0.0015, 0.0005\\] m is outside the flow's rectangle" \
    "$nspd" run "$cav" -o "$work/result" --set "output.probes=[{type: point, name: far, on: flow, at: [0.0015, 0.0005]}]"
cyl="$src/cases/cylinder_confined_re10.yaml"
check "PDDO body patch too large" "flow.bodies\[0\].patch_radius: 2.01 m: the patch and 2 x 3 fictitious layers reach 3.18 m" \
    "$nspd" check "$cyl" --set flow.spacing=0.2
check "PDDO overlapping patches" "flow.bodies\\[1\\].center: \\[7, 3\\]: its polar patch \\(reach 1.5086 m\\) overlaps that of body 0 at \\[5, 3\\]" \
    "$nspd" check "$cyl" --set "flow.bodies=[{shape: circle, center: [5, 3], radius: 0.5}, {shape: circle, center: [7, 3], radius: 0.5}]"
check "PDDO nine bodies" "flow.bodies: 9 bodies; expected at most 8" \
    "$nspd" check "$cyl" --set "flow.bodies=[$(for i in 1 2 3 4 5 6 7 8 9; do printf '{shape: circle, center: [%d, 3], radius: 0.1}, ' "$i"; done)]"
check "PDDO probe inside a body" "probe 'inside': at \\[5.1, 3\\] m is inside body 0" \
    "$nspd" run "$cyl" -o "$work/result" --set flow.spacing=0.2 --set flow.bodies.0.patch_radius=1.5 \
    --set "output.probes=[{type: point, name: inside, on: flow, at: [5.1, 3.0]}]"
check "PDDO body names" "flow.bodies\[1\].name: .body0. used twice" \
    "$nspd" check "$src/cases/cylinders_tandem_re10.yaml" --set flow.bodies.1.name=body0 --set flow.bodies.0.name=body0
check "PDDO body shape" "flow.bodies\[0\].shape" \
    "$nspd" check "$cyl" --set "flow.bodies=[{shape: naca, center: [5, 3], radius: 0.5}]"
check "PDDO seed without bodies" "flow.seed: a seed without bodies; expected flow.bodies to turn" \
    "$nspd" check "$cav" --set "flow.seed={spin: 1.0, until: 0.1}"
check "PDDO seed duration" "flow.seed.until: .*expected the time in s at which the walls stop" \
    "$nspd" check "$cyl" --set "flow.seed={spin: 1.0, until: 0.0}"
# the IGA flow (issue 25): what its reader refuses, at the key
iga=$src/cases/iga_cylindrical_blast.yaml
check "IGA degree" "flow.iga.degree: 4; expected 1, 2 \\(the paper's\\) or 3" \
    "$nspd" run "$iga" -o "$work/result" --set flow.iga.degree=4
check "IGA Courant number" "flow.iga.cfl: .*expected a Courant number of at most 0.5" \
    "$nspd" check "$iga" --set flow.iga.cfl=0.8
check "IGA stretched grid" "flow.grid.x: 1 segment\\(s\\), stretched; expected one uniform segment" \
    "$nspd" check "$iga" --set "flow.grid.x.segments=[{length: 0.3, spacing_start: 0.01, spacing_end: 0.005}]"
check "IGA two segments" "flow.grid.y: 2 segment\\(s\\); expected one uniform segment" \
    "$nspd" check "$iga" --set "flow.grid.y.segments=[{length: 0.1, spacing: 0.006}, {length: 0.2, spacing: 0.006}]"
check "IGA boundary kind" "flow.boundaries.x_max: subsonic_outflow; expected slip_wall or periodic" \
    "$nspd" check "$iga" --set "flow.boundaries.x_max={type: subsonic_outflow, pressure: 1e5}"
check "IGA gas constant" "flow.gas.gas_constant: .*expected" \
    "$nspd" check "$iga" --set flow.gas.gas_constant=-287
check "IGA free stream" "flow.free_stream: a free stream; expected an initial state, regions or a vortex for the IGA flow" \
    "$nspd" check "$iga" --set "flow.free_stream={density: 1.2, velocity: [10, 0], pressure: 1e5}"
check "IGA seal" "coupling: the penalty coupling's 'seal' needs a flow that can seal faces; the 'iga' flow solver cannot" \
    "$nspd" run "$src/cases/blast_hollow_square.yaml" -o "$work/result" --set flow.method=iga \
    --set coupling.seal=true
gcyl="$src/cases/cylinder_ma2_re300.yaml"
# did-you-mean from every key a map accepts, given or not (issue 61): an
# optional key the case leaves out, a key read only when present
# (flow.method, solid.lattice_origin), the IGA flow's keys on the GKS one
check "did you mean: an absent optional list" "output.probs: unknown key \\(did you mean 'probes'\\?\\)" \
    "$nspd" check "$src/cases/sod.yaml" --set "output.probs=[]"
check "did you mean: a key read when present" "flow.methd: unknown key \\(did you mean 'method'\\?\\)" \
    "$nspd" check "$gcyl" --set flow.methd=gks
check "did you mean: a solid key left out" "solid.latice_origin: unknown key \\(did you mean 'lattice_origin'\\?\\)" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set "solid.latice_origin=[0, 0]"
# the polar lattice (solid.lattice.kind: polar, correspondence only)
hcyl="$src/cases/blast_hollow_cylinder.yaml"
ring="kind: polar, center: [0.15, 0.15]"
check "polar lattice: negative radius" "solid.lattice.inner_radius: must be positive, got -0.07" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: -0.07, outer_radius: 0.1}"
check "polar lattice: inner >= outer" "solid.lattice.outer_radius: 0.07 m with inner_radius 0.1 m; expected r_o > r_i" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.1, outer_radius: 0.07}"
check "polar lattice: no ring" "solid.lattice.rings: 0; expected at least 1 ring" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.07, outer_radius: 0.1, rings: 0}"
check "polar lattice: rings against the spacing" "solid.lattice.rings: 10, but the spacing 0.002 m fits 15" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.07, outer_radius: 0.1, rings: 10}"
check "polar lattice: odd sectors" "solid.lattice.sectors: 267; expected an even number" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.07, outer_radius: 0.1, sectors: 267}"
check "polar lattice: did you mean" "solid.lattice.outer_radiuss: unknown key \\(did you mean 'outer_radius'\\?\\)" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.07, outer_radius: 0.1, outer_radiuss: 1}"
check "square lattice: a polar key" "solid.lattice.rings: a key of the polar lattice; expected kind: polar" \
    "$nspd" check "$hcyl" --set "solid.lattice={kind: square, rings: 3}"
check "polar lattice: off the geometry" "no element centroid of the polar lattice falls inside the solid geometry" \
    "$nspd" check "$hcyl" --set "solid.lattice={kind: polar, center: [0.5, 0.5], inner_radius: 0.07, outer_radius: 0.1}"
check "polar lattice: bond-based solid" "solid.lattice.kind: polar with the bond-based solid" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set solid.lattice.kind=polar
check "polar lattice: ghost-cell coupling" "coupling.kind: ghost_cell with solid.lattice.kind: polar" \
    "$nspd" check "$hcyl" --set "solid.lattice={$ring, inner_radius: 0.07, outer_radius: 0.1}" \
    --set coupling.kind=ghost_cell
check "did you mean: flow.iga on the GKS flow" "flow.iga.degre: unknown key \\(did you mean 'degree'\\?\\)" \
    "$nspd" check "$src/cases/blast_hollow_square.yaml" --set flow.iga.degre=2
check "flow.iga checked on the GKS flow" "flow.iga.degree: 4; expected 1, 2" \
    "$nspd" check "$src/cases/blast_hollow_square.yaml" --set flow.iga.degree=4
# a key the reader looks at but the map does not take is never offered
check "crack-tip probe: no 'at'" "output.probes\\[0\\].att: unknown key; expected one of: type, name, direction" \
    "$nspd" check "$src/cases/plate_crack.yaml" --set output.probes.0.att=1
# paths as messages print them are what --set takes: a[0].b
check "--set a[0].b" "^--set flow.bodies\\[0\\].markrs=40: flow.bodies\\[0\\].markrs: unknown key \\(did you mean 'markers'\\?\\)" \
    "$nspd" check "$gcyl" --set "flow.bodies[0].markrs=40"
check "--set a bracket without an index" "--set flow.bodies\\[x\\].markers=40: a '\\[' or '\\]' that is not a list index" \
    "$nspd" check "$gcyl" --set "flow.bodies[x].markers=40"
# the path of a refusal, pasted into --set, names the same key: another
# bad value is refused there, a good one accepted
path=$("$nspd" check "$gcyl" --set "flow.bodies[0].radius=-1" 2>&1 |
    sed -n 's/^--set [^ ]*: \([^ :]*\): .*/\1/p')
check "a refusal's path in --set" "^--set flow.bodies\\[0\\].radius=-2: flow.bodies\\[0\\].radius: must be positive, got -2" \
    "$nspd" check "$gcyl" --set "$path=-2"
count=$((count + 1))
if ! "$nspd" check "$gcyl" --set "$path=0.25" >"$work/out" 2>"$work/err"; then
    echo "FAIL the path '$path' of a refusal is not taken by --set:"
    cat "$work/err"
    failures=$((failures + 1))
fi
mkdir -p "$work/existing"
count=$((count + 1))
"$nspd" run "$src/cases/block_3d.yaml" -o "$work/existing" >"$work/out" 2>"$work/err"
if [ $? -ne 2 ] || ! grep -q "output directory '$work/existing' exists" "$work/err" ||
    [ -n "$(ls -A "$work/existing")" ]; then
    echo "FAIL existing directory without --force was not refused cleanly"
    cat "$work/err"
    failures=$((failures + 1))
fi

echo "$((count - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
