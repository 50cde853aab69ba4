# `mpirun -n N nspd run` (issue 28): the flow cases that run on several
# processes end with every file bit for bit as the run of one process
# without mpirun (history.csv, every .vtr (in pieces), .pvd, picture and line table,
# and summary.json but for the keys that measure the machine), on 2, 3
# and 4 ranks for the cases issue 28 names (the shock tube, the coarse
# cylinder with sealed and with reflected faces, the coarse panel, the
# coarse penalty blast in its chamber, the plate), on some of them for
# the others (the suite's time): a shock tube (extrapolated ends, periodic y), the isentropic
# vortex (periodic box), Couette flow (moving isothermal walls), the
# Blasius plate (stretched rows, inflow, outflow, a no-slip plate, point
# probes), fixed bodies in a stream (the Mach 2 cylinder with sealed and
# with reflected ghost faces, the NACA 0012: ghost cells, surface loads and
# forces), and solids coupled to the flow: by the ghost-cell boundary
# (the bond solid divided between the ranks) (the panel in a shock, the cracking cylinder:
# moving walls) and by the volumetric penalty (the detonation chamber, the
# hollow square in a blast with sealed faces), and solids alone divided
# between the ranks (the pre-cracked plate; the correspondence solid's
# hollow square and hollow cylinder, damage and fragments across the
# ranks). Then the state moves between process counts: a checkpoint
# written on 3 ranks resumes on 2 and on 1 (the flow, the coupled
# cylinder, the plate, the hollow cylinder), and a field written on 3
# ranks starts a run on 1 (and one written by 1 a run on 3), all with the
# same bits. Then the refusals: a bad case, more
# ranks than rows, each exit status 2 with its message
# printed once; and runs that blow up (the flow, the solid), stopped on
# every rank with the message of one process.
# A grid that several processes write in pieces (.pvtr) is held against
# the one process's .vtr array by array (VTK_SAME, tests/mpi/vtk_same.c).
# Each case runs on the layouts of the first list of its `pick` in make
# test (mpi.run, MODE suite), and on those of the second in `make
# validate` (mpi.run_more, MODE more, labelled slow; those layouts only,
# nothing after them): together the 2, 3 and 4 ranks and the process grids
# each case had in one test of 56 launches, 2 minutes of make test's 12
# on 2 cores (docs/PERFORMANCE.md, "make test on 2 cores").
#   usage: run.sh NSPD SOURCE_DIR MPIEXEC VTK_SAME [suite|more]
set -u
. "$2/tests/mpi/checks.sh"
mode=${5:-suite}
pick() { if [ "$mode" = more ]; then echo "$2"; else echo "$1"; fi; }

# Each case on numbers of processes (slabs of rows, or the default grid)
# and on 2D process grids (PXxPY: --processes): the x halo, the corners,
# the blocks' edge columns, the totals passed along x.
check_case sod 0.2 "$(pick "3 2x1" "2 4 3x1")"
check_case vortex 1.0 "$(pick "3 2x2" "2 4 4x1")"
check_case couette 2.0 "$(pick "3 2x1" "")"
check_case blasius 0.3 "$(pick "3 2x2" "2 3x1")"

# Fixed bodies (the ghost-cell immersed boundary, couple/ghost/share.c):
# the coarse golden runs of the Mach 2 cylinder (sealed ghost faces, soft
# start, forces) and of it with reflected faces, and of the NACA 0012
# (reflected), on some of 2, 3 and 4 ranks each (the suite's time): the
# walls cross the slabs' edges; and on a 2D process grid each, as the
# coupled cases below (ghost cells, fetched stencils, sealed faces, probes,
# moving walls and the penalty's cells across blocks).
check_body cylinder_ma2_re300 cylinder_sealed "$(pick "3 2x2" "2 4")"
check_body cylinder_ma2_re300 cylinder_reflected "$(pick "3 2x1" "2 4")" --set flow.ghost_faces=reflected
check_body naca0012_ma05_re5000 naca "$(pick "3x1" "2 4")"
# A solid coupled to the flow (ghost-cell FSI, moving walls): divided
# between the ranks as a solid alone; the coarse panel in a shock and the coarse cracking
# cylinder.
check_body panel_shock panel "$(pick "3" "2 4")"
check_body cylinder_crack_ma17 crack "$(pick "2x2" "2 4")"
# The volumetric penalty coupling (the solid divided, its whole view
# gathered for the relaxation; cells gathered and scattered by the
# flow's ops): the coarse detonation chamber, and the
# hollow square in a blast with sealed faces, shortened.
check_body chamber_detonation chamber "$(pick "3 2x2" "2 4")"
check_body blast_hollow_square blast_sealed "$(pick "3 2x1" "")" --set time.end=2e-5 --set coupling.seal=true \
    --set output.field_interval=1e-5
# A solid alone, divided between the ranks (solid/bond/halo.h): the coarse
# pre-cracked plate (bonds break across the ranks' runs; energies, the
# crack-tip and line probes, damage pictures).
check_body plate_crack plate "$(pick "3" "2 4")"
# ... and a 3D block under velocity Verlet (the ghosts' displacements
# exchanged between the drift and the second force), bonds breaking.
check_body block_3d block3d "$(pick "3" "2")"
# The correspondence solid alone, divided (solid/correspondence/halo.h):
# the coarse hollow square (pressure loads, ductile damage; in plane
# strain and in plane stress) and the coarse hollow cylinder (brittle
# damage, debris and 8 fragments: the weights settle across the ranks).
check_body hollow_square_pressure hsq "$(pick "2" "3 4")"
check_body hollow_square_pressure hsq_stress "$(pick "3" "")" --set solid.model=plane_stress
check_body hollow_cylinder_pulse hcy "$(pick "4" "2 3")"
# The classic force (per-point state; the crossing bonds' T_ji from their
# owners, the damage law's ghost states exchanged)
check_body hollow_square_pressure hsq_classic "$(pick "3" "2")" --set solid.correspondence.force=classic
check_body hollow_square_pressure hsq_classic_stress "$(pick "3" "")" --set solid.correspondence.force=classic \
    --set solid.model=plane_stress
check_body hollow_cylinder_pulse hcy_classic "$(pick "2" "4")" --set solid.correspondence.force=classic

# the rest in make test only
if [ "$mode" = more ]; then
    finish
    exit
fi

# Checkpoints: written on 3 ranks (every 0.2 of 1.0), the newest resumed
# on 2 and on 1 with the outputs after it removed; both end as the run of
# one process.
vortex="$src/cases/vortex.yaml"
ck="--set time.end=1.0 --set output.checkpoint_interval=0.2"
# n processes: by mpiexec, or one without it
"$nspd" run "$vortex" -o "$work/ck.ref" --quiet $ck || fail "the checkpointed run of one process failed"
if on 3 "$vortex" -o "$work/ck.3" --quiet $ck; then
    for n in 2 1; do
        cp -r "$work/ck.3" "$work/ck.3to$n"
        # the last field output (t = 1.0) and the summary come after the newest checkpoint
        resume_check "$work/ck.3to$n" "$n" flow "$work/ck.ref" \
            "checkpoint of 3 ranks resumed on $n" "$vortex" $ck
    done
else
    fail "the checkpointed run on 3 ranks failed"
fi

# A checkpoint of a 2 x 2 process grid resumes on 3 slabs and on one
# process with the same bits.
if on 4 "$vortex" -o "$work/ck.2x2" --quiet $ck --processes 2x2; then
    for n in 3 1; do
        cp -r "$work/ck.2x2" "$work/ck.2x2to$n"
        resume_check "$work/ck.2x2to$n" "$n" flow "$work/ck.ref" \
            "checkpoint of 2 x 2 blocks resumed on $n" "$vortex" $ck
    done
else
    fail "the checkpointed run on 2 x 2 blocks failed"
fi

# A signal to mpirun (SIGUSR1, which it forwards): the ranks agree to stop
# at the same step with a checkpoint and the outputs (exit status 130);
# resumed on 2 ranks, the run ends as the one of one process that never
# stopped.
set -f
IFS='
'
sig=$(printf '%s\n' --set "flow.grid.x.segments=[{length: 10.0, cells: 24}]" --set "flow.grid.y.segments=[{length: 10.0, cells: 24}]" --set time.end=60)
"$nspd" run "$vortex" -o "$work/sig.ref" --quiet $sig || fail "the run to be signalled, on one process, failed"
"$mpiexec" -n 3 "$nspd" run "$vortex" -o "$work/sig.3" --quiet $sig >/dev/null 2>&1 &
pid=$!
# once the run is stepping (its log says so), the signal
while kill -0 "$pid" 2>/dev/null && ! grep -q processes "$work/sig.3/log.txt" 2>/dev/null; do sleep 0.05; done
sleep 0.2
kill -s USR1 "$pid"
wait "$pid"
status=$?
if [ "$status" -eq 130 ] && ls "$work/sig.3" | grep -q "^checkpoint_"; then
    if on 2 "$vortex" -o "$work/sig.3" --quiet --resume $sig; then
        same_results "$work/sig.ref" "$work/sig.3" "stopped by a signal on 3 ranks, resumed on 2"
    else
        fail "the signalled run resumed on 2 ranks: exit status $?"
    fi
else
    fail "SIGUSR1 to mpirun on 3 ranks: exit status $status (expected 130 and a checkpoint)"
fi
unset IFS
set +f

# The coupled cylinder's checkpoint (the solid, the moving interface, the
# flow) written on 2 x 2 blocks resumes on 2 slabs with the same bits.
set -f
IFS='
'
crack_args=$(golden_overrides cylinder_crack_ma17 | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
crack="$src/cases/cylinder_crack_ma17.yaml"
"$nspd" run "$crack" -o "$work/cck.ref" --quiet $crack_args --set output.checkpoint_interval=1e-3 ||
    fail "the checkpointed coupled run of one process failed"
if on 4 "$crack" -o "$work/cck.2x2" --quiet $crack_args --set output.checkpoint_interval=1e-3 \
    --processes 2x2; then
    resume_check "$work/cck.2x2" 2 flow "$work/cck.ref" \
        "the coupled checkpoint of 2 x 2 blocks resumed on 2" "$crack" $crack_args \
        --set output.checkpoint_interval=1e-3
else
    fail "the checkpointed coupled run on 2 x 2 blocks failed"
fi
unset IFS
set +f

# The divided solid's checkpoint (displacements, velocities, forces and
# the broken bonds, in the whole body's order) written on 3 ranks resumes
# on 2 with the same bits.
set -f
IFS='
'
plate_args=$(golden_overrides plate_crack | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
plate="$src/cases/plate_crack.yaml"
"$nspd" run "$plate" -o "$work/pck.ref" --quiet $plate_args --set output.checkpoint_interval=2e-6 ||
    fail "the checkpointed solid of one process failed"
if on 3 "$plate" -o "$work/pck.3" --quiet $plate_args --set output.checkpoint_interval=2e-6; then
    resume_check "$work/pck.3" 2 solid "$work/pck.ref" \
        "the solid's checkpoint of 3 ranks resumed on 2" "$plate" $plate_args \
        --set output.checkpoint_interval=2e-6
else
    fail "the checkpointed solid on 3 ranks failed"
fi
# The correspondence solid's checkpoint (the pairs' material state in the
# whole body's pair order, the bonds' damage and RK weights, the points'
# flags) written on 3 ranks resumes on 2 and on 1 with the same bits.
hcy_args=$(golden_overrides hollow_cylinder_pulse | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
hcy="$src/cases/hollow_cylinder_pulse.yaml"
"$nspd" run "$hcy" -o "$work/hck.ref" --quiet $hcy_args --set output.checkpoint_interval=1.5e-5 ||
    fail "the checkpointed correspondence solid of one process failed"
if on 3 "$hcy" -o "$work/hck.3" --quiet $hcy_args --set output.checkpoint_interval=1.5e-5; then
    for n in 2 1; do
        cp -r "$work/hck.3" "$work/hck.3to$n"
        resume_check "$work/hck.3to$n" "$n" solid "$work/hck.ref" \
            "the correspondence solid's checkpoint of 3 ranks resumed on $n" "$hcy" $hcy_args \
            --set output.checkpoint_interval=1.5e-5
    done
else
    fail "the checkpointed correspondence solid on 3 ranks failed"
fi
# The classic force's checkpoint (the material state per point, ghosts
# read back too) of 3 ranks resumed on 2.
"$nspd" run "$hcy" -o "$work/hckc.ref" --quiet $hcy_args --set output.checkpoint_interval=1.5e-5 \
    --set solid.correspondence.force=classic ||
    fail "the checkpointed classic correspondence solid of one process failed"
if on 3 "$hcy" -o "$work/hckc.3" --quiet $hcy_args --set output.checkpoint_interval=1.5e-5 \
    --set solid.correspondence.force=classic; then
    resume_check "$work/hckc.3" 2 solid "$work/hckc.ref" \
        "the classic correspondence solid's checkpoint of 3 ranks resumed on 2" "$hcy" $hcy_args \
        --set output.checkpoint_interval=1.5e-5 --set solid.correspondence.force=classic
else
    fail "the checkpointed classic correspondence solid on 3 ranks failed"
fi
# A solid that blows up (a given step 4 times the stable one) stops all
# ranks with the message of one process.
"$nspd" run "$plate" -o "$work/pblow.1" --quiet $plate_args --set time.dt=4e-7 2>/dev/null
on 3 "$plate" -o "$work/pblow.3" --quiet $plate_args --set time.dt=4e-7 >"$work/out" 2>&1
status=$?
if [ "$status" -eq 1 ] && [ "$(grep -c "nspd: error: the solid blew up" "$work/out")" -eq 1 ] &&
    [ "$(grep stopped_by "$work/pblow.3/summary.json")" = "$(grep stopped_by "$work/pblow.1/summary.json")" ]; then
    ok
else
    fail "a solid blowing up on 3 ranks: exit status $status (expected 1, the message of one process, once):"
    cat "$work/out"
fi
unset IFS
set +f

# Fields: the last field of the Blasius plate on 3 ranks starts a run of
# one process, and the one process's a run on 3; each ends as the other.
blasius="$src/cases/blasius.yaml"
from3=$(ls "$work/blasius.3"/flow_*.pvtr | tail -n 1)
from1=$(ls "$work/blasius.1"/flow_*.vtr | tail -n 1)
"$nspd" run "$blasius" -o "$work/from3.1" --quiet --set time.end=0.1 --set "flow.initial={from: $from3}" ||
    fail "a run of one process from the field of 3 ranks failed"
if on 3 "$blasius" -o "$work/from1.3" --quiet --set time.end=0.1 --set "flow.initial={from: $from1}"; then
    same_results "$work/from3.1" "$work/from1.3" "a field of 3 ranks on 1 against one of 1 on 3" paths
else
    fail "a run on 3 ranks from the field of one process: exit status $?"
fi

# The pieces open in VTK's own parallel readers (ParaView's): the shock
# tube's .pvtr series of 3 ranks, the plate's .pvtu series of 3, every
# file whole (python3-vtk9, installed by scripts/deps.sh).
if /usr/bin/python3 -c "import vtk" 2>/dev/null; then
    cells=$(sed -n 's/.*"cells": \([0-9]*\).*/\1/p' "$work/sod.3/summary.json")
    points=$(sed -n 's/.*"points": \([0-9]*\).*/\1/p' "$work/plate.3/summary.json")
    if /usr/bin/python3 "$src/tests/cli/tools/read_vtk.py" "$work/sod.3/flow.pvd" "$cells" \
        density velocity:3 pressure temperature mach cell_kind >"$work/out" 2>&1 &&
        grep -q pvtr "$work/sod.3/flow.pvd" &&
        /usr/bin/python3 "$src/tests/cli/tools/read_vtk.py" "$work/plate.3/solid.pvd" "$points" \
            displacement:3 velocity:3 damage volume >>"$work/out" 2>&1 &&
        grep -q pvtu "$work/plate.3/solid.pvd"; then
        ok
    else
        fail "VTK's parallel readers on the pieces:"
        cat "$work/out"
    fi
fi

# Refusals (checks.sh: refused)
sod="$src/cases/sod.yaml"
refused "a bad key on 2 ranks" "flow.nonsense: unknown key" 2 "$sod" -o "$work/bad" --set flow.nonsense=1
refused "a correspondence body thinner than its family on 3 ranks" \
    "3900 points, the first at \\(-0.079, -0.079\\) m, have too few neighbours" 3 \
    "$src/cases/hollow_square_pressure.yaml" -o "$work/bad" --set solid.horizon_factor=1.0
refused "4 rows on 3 slabs" "4 rows over 3 processes" 3 "$sod" -o "$work/bad" --processes 1x3
refused "a grid of 3 blocks on 2 ranks" "processes 3x1 makes 3 blocks for 2 processes" 2 "$sod" \
    -o "$work/bad" --processes 3x1
refused "a grid of 3 blocks for a solid alone on 2 ranks" "processes 3x1 makes 3 blocks for 2 processes" 2 \
    "$src/cases/plate_crack.yaml" -o "$work/bad" --processes 3x1
[ -e "$work/bad" ] && fail "a refused run wrote $work/bad"

# A run that fails (the gas leaves the physical range: a given time step
# 34 times the stable one) stops all ranks at the same step: exit status
# 1, the message once and the serial run's (the first bad cell of the
# whole grid), summary.json written by rank 0 saying why.
"$nspd" run "$src/cases/vortex.yaml" -o "$work/blowup.1" --quiet --set time.dt=0.5 2>/dev/null
# on 4 ranks the first bad cell, (25, 20), is on rank 1, which words it
on 4 "$src/cases/vortex.yaml" -o "$work/blowup" --quiet --set time.dt=0.5 --processes 1x4 >"$work/out" 2>&1
status=$?
lines=$(grep -c "nspd: error: .*in step" "$work/out")
if [ "$status" -eq 1 ] && [ "$lines" -eq 1 ] && grep -q '"completed": false' "$work/blowup/summary.json" &&
    [ "$(grep stopped_by "$work/blowup/summary.json")" = "$(grep stopped_by "$work/blowup.1/summary.json")" ]; then
    ok
else
    fail "a blow-up on 4 ranks: exit status $status, the message $lines times (expected 1, once, as one process's):"
    cat "$work/out"
fi

finish
