#!/bin/sh
# The isogeometric flow on several processes (issue 58): the flow alone,
# its limited step, and paper 003's system (the correspondence solid, the
# penalty coupling, weak and strong, on the isogeometric gas) on 1 to 4
# processes in slabs and blocks, every file the same as one process's;
# a coupled checkpoint of 3 processes resumed on 2 (within make test's
# budget: the coupled runs half the golden time, and 3 -> 1 and more
# layouts were run once, 2026-12-07); the refusal
# of what runs on one process only.
#   sh tests/mpi/iga.sh NSPD SOURCE_DIR MPIEXEC VTK_SAME
set -u
. "$2/tests/mpi/checks.sh"

check_body iga_cylindrical_blast iga "3 2x2 4x1"
check_body iga_cylindrical_blast iga_limited "3 2x2" --set flow.iga.limiter=convex \
    --set "flow.gas.viscosity={law: none}"
check_body chamber_detonation iga_chamber "2 4" --set flow.method=iga --set time.end=3e-5
check_body blast_hollow_cylinder iga_cylinder_strong "3" --set flow.method=iga \
    --set coupling.strong=true --set time.end=1.5e-5
check_body blast_hollow_square iga_square_damaged "2x2" --set flow.method=iga \
    --set coupling.damaged=true --set time.end=1.5e-5

# the chamber's checkpoint of 3 processes resumed on 2
set -f
IFS='
'
args=$(golden_overrides chamber_detonation | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
args="$args
--set
flow.method=iga
--set
output.checkpoint_interval=1.5e-5
--set
time.end=3e-5"
chamber="$src/cases/chamber_detonation.yaml"
"$nspd" run "$chamber" -o "$work/ick.ref" --quiet $args || fail "the checkpointed IGA chamber on one process failed"
if on 3 "$chamber" -o "$work/ick.3" --quiet $args; then
    for n in 2; do
        cp -r "$work/ick.3" "$work/ick.3to$n"
        resume_check "$work/ick.3to$n" "$n" flow "$work/ick.ref" \
            "the IGA chamber's checkpoint of 3 ranks resumed on $n" "$chamber" $args
    done
else
    fail "the checkpointed IGA chamber on 3 ranks failed"
fi
unset IFS
set +f

# refused on several processes (nothing written: the refused run's directory)
refused "the L2 projection start on 2 ranks" "runs on one process only" 2 \
    "$src/cases/iga_cylindrical_blast.yaml" -o "$work/bad" --set flow.iga.init=l2
[ -e "$work/bad" ] && fail "a refused run wrote $work/bad"
finish
