# ctest-labels: release
# A run stopped by a signal (SIGTERM, SIGUSR1: checkpoint, outputs, exit
# 130) or killed outright (SIGKILL at a random step) and continued with
# `nspd run ... --resume` ends with every file bit for bit as the run that
# was never stopped: history.csv, every field file, picture, table and
# .pvd series, and summary.json but for the keys that measure the machine.
# The stopped runs use 2 threads and the resumed ones 1 (or the other way
# round): a checkpoint does not depend on the thread count. Seven kinds of
# run: solid only (plate), flow only (cylinder, a fixed body), coupled
# (panel), the correspondence solid while it breaks (hollow cylinder) and
# in the semi-Lagrangian frame (hollow square), the penalty coupling while a
# blast breaks a ring, the IGA flow's blast, and the PDDO flow to its
# steady state (cavity).
# Then the refusals: another case, another binary, no checkpoint, and a
# damaged newest checkpoint (the one before is used).
# Release build only: the runs are ~10 s in all here, minutes under ASan
# (tests/unit/core/test_checkpoint.c covers the file format there).
#   usage: test_resume.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"
random() { echo $(($(od -An -N2 -tu2 /dev/urandom) % $1)); }

# The coarse runs of the golden set (tests/golden/runs.txt), lengthened and
# checkpointed by the overrides after the case name, which come last and win.
case_args() {
    printf '%s\n' "$src/cases/$1.yaml" --quiet
    golden_overrides "$1" | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done
}

# nspd run with the case's arguments (one per line in $work/args.$1) and
# the options given, replacing the calling (sub)shell: `start` leaves the
# pid of nspd itself in $pid, for the signals.
exec_run() {
    name=$1
    shift
    IFS='
'
    set -f
    set -- "$@" $(cat "$work/args.$name")
    exec "$nspd" run "$@"
}
run() { (exec_run "$@"); }
start() {
    exec_run "$@" &
    pid=$!
}

# Waits until the run pid in dir has written n checkpoints (its log says
# so, a line each) or has ended.
wait_checkpoints() {
    dir=$1 n=$2 pid=$3
    while kill -0 "$pid" 2>/dev/null; do
        c=$(grep -c '^checkpoint at step' "$dir/log.txt" 2>/dev/null)
        [ "${c:-0}" -ge "$n" ] && return 0
        sleep 0.01
    done
    return 1
}

# One kind of run: uninterrupted (1 thread), stopped by $signal after the
# first checkpoint and resumed (2 threads, then 1), killed by SIGKILL at a
# random moment after a random checkpoint and resumed (1 thread, then 2).
check_kind() {
    name=$1 signal=$2
    shift 2
    { case_args "$name"; for s in "$@"; do printf -- '--set\n%s\n' "$s"; done; } >"$work/args.$name"
    run "$name" -o "$work/$name.ref" --threads 1 || { fail "$name: the uninterrupted run failed"; return; }

    start "$name" -o "$work/$name.sig" --threads 2
    if wait_checkpoints "$work/$name.sig" 1 "$pid"; then
        kill -s "$signal" "$pid"
        wait "$pid"
        st=$?
        [ "$st" -eq 130 ] && ok || fail "$name: stopped by $signal, exit status $st; expected 130"
        grep -q "stopped by SIG$signal" "$work/$name.sig/log.txt" && ok ||
            fail "$name: the log does not say it was stopped by $signal"
        run "$name" -o "$work/$name.sig" --threads 1 --resume &&
            same_results "$work/$name.ref" "$work/$name.sig" "$name ($signal, resumed)" ||
            fail "$name: the resumed run failed after $signal"
    else
        fail "$name: the run ended before its first checkpoint; lengthen it"
    fi

    k=$(($(random 3) + 1))
    delay=$(random 100) # ms
    start "$name" -o "$work/$name.kill" --threads 1
    if wait_checkpoints "$work/$name.kill" "$k" "$pid"; then
        sleep "0.$(printf %03d "$delay")"
        kill -KILL "$pid"
        wait "$pid"
        last=$(tail -1 "$work/$name.kill/history.csv" | cut -d, -f1)
        run "$name" -o "$work/$name.kill" --threads 2 --resume &&
            same_results "$work/$name.ref" "$work/$name.kill" \
                "$name (SIGKILL $delay ms after checkpoint $k, last row step $last, resumed)" ||
            fail "$name: the resumed run failed after SIGKILL"
    else
        fail "$name: the run ended before checkpoint $k; lengthen it"
    fi
}

check_kind plate_crack TERM time.end=3.34e-5 output.checkpoint_interval=2e-6
check_kind cylinder_ma2_re300 USR1 time.end=3.0 output.checkpoint_interval=0.2
check_kind panel_shock TERM time.end=3.0e-4 output.checkpoint_interval=2.0e-5
# the correspondence solid while it fractures (bond state, weights, the re-estimated step)
check_kind hollow_cylinder_pulse USR1 time.end=8e-5 output.checkpoint_interval=4e-6
# ... in the semi-Lagrangian frame, whose pairs' F_b is state (sl_force.h)
check_kind hollow_square_pressure USR1 time.end=3e-4 output.checkpoint_interval=1e-5 \
    solid.correspondence.frame=semi_lagrangian
# the penalty coupling (paper 003) on a ring the blast fragments (at the
# CFL step: the paper's are 50 times more steps of the same state)
check_kind blast_hollow_cylinder TERM time.end=1.2e-4 output.checkpoint_interval=1e-5 time.dt=stable
# ... with sealed faces, which the coupling rebuilds from the solid before every flow step
check_kind chamber_detonation USR1 time.end=3e-4 output.checkpoint_interval=3e-5 coupling.seal=true \
    time.dt=stable
# ... and the strong coupling at every step (the solid constrained: the drift-kick)
check_kind blast_hollow_square TERM time.end=4e-5 output.checkpoint_interval=5e-6 coupling.strong=true \
    time.dt=stable solid.spacing=4e-3 flow.grid.x.segments.0.spacing=0.016 \
    flow.grid.y.segments.0.spacing=0.016 coupling.h=0.016
# the IGA flow (control values, their rates, its clock)
check_kind iga_cylindrical_blast TERM time.end=6e-5 output.checkpoint_interval=1e-5 \
    flow.grid.x.segments.0.spacing=0.012 flow.grid.y.segments.0.spacing=0.012
# ... and its limited step, whose time-step bound is re-derived from the state read
check_kind sedov_quadrant USR1 time.end=0.3 output.checkpoint_interval=0.03
# the PDDO flow (u, v, p, its clock), ending at its steady state (max du/dt
# below 12 m/s^2 at step 636 of 1,000) after the checkpoints
check_kind cavity_re200 USR1 time.end=1e-2 output.checkpoint_interval=1e-3 \
    output.field_interval=2e-3 output.history_interval=1e-4 flow.steady_tolerance=12

# --- refusals, each with exit status 2 and nothing changed
name=plate_crack
dir=$work/$name.sig
before=$(cat "$dir/history.csv" | cksum)
run "$name" -o "$dir" --resume --set solid.material.density=8001 2>"$work/err"
st=$?
[ "$st" -eq 2 ] && grep -q "written for another case" "$work/err" && ok ||
    fail "another case: exit $st, $(cat "$work/err")"
mkdir -p "$work/bin"
cp "$nspd" "$work/bin/nspd" && printf 'x' >>"$work/bin/nspd" # another binary, still runnable
(nspd=$work/bin/nspd && exec_run "$name" -o "$dir" --resume) 2>"$work/err"
st=$?
[ "$st" -eq 2 ] && grep -q "another nspd binary" "$work/err" && ok ||
    fail "another binary: exit $st, $(cat "$work/err")"
[ "$(cat "$dir/history.csv" | cksum)" = "$before" ] && ok || fail "a refused resume changed history.csv"
mkdir -p "$work/empty"
run "$name" -o "$work/empty" --resume 2>"$work/err"
st=$?
[ "$st" -eq 2 ] && grep -q "holds no checkpoint" "$work/err" && ok ||
    fail "no checkpoint: exit $st, $(cat "$work/err")"
run "$name" -o "$work/missing" --resume 2>"$work/err"
st=$?
[ "$st" -eq 2 ] && grep -q "does not exist" "$work/err" && ok ||
    fail "no directory: exit $st, $(cat "$work/err")"
run "$name" -o "$work/x" --resume --force 2>"$work/err"
[ $? -eq 2 ] && ok || fail "--resume with --force accepted"

# A damaged newest checkpoint: the one before it continues the run.
start "$name" -o "$work/dmg" --threads 2
if wait_checkpoints "$work/dmg" 2 "$pid"; then
    kill -TERM "$pid"
    wait "$pid"
    newest=$(ls "$work/dmg" | grep '^checkpoint_' | sort | tail -1)
    size=$(wc -c <"$work/dmg/$newest")
    printf 'X' | dd of="$work/dmg/$newest" bs=1 seek=$((size / 2)) conv=notrunc 2>/dev/null
    run "$name" -o "$work/dmg" --threads 1 --resume 2>"$work/err" &&
        same_results "$work/$name.ref" "$work/dmg" "$name (damaged newest checkpoint)" ||
        fail "damaged newest checkpoint: the resumed run failed: $(cat "$work/err")"
    grep -q "passing over.*damaged" "$work/dmg/log.txt" && ok ||
        fail "damaged newest checkpoint: the log does not say it was passed over"
else
    fail "the run ended before its second checkpoint"
fi

finish
