#!/bin/sh
# The PDDO flow on several processes (issue 58): each rank computes its
# range of nodes and shares it, rank 0 solves the pressure (flow/pddo/
# share.h), so every file is the same as one process's: the cavity (a
# pinned, singular pressure matrix) on 2, 3 and 4 ranks, the Re 100
# cylinder (a polar patch, an outlet) on 3, the tandem cylinders (two
# patches) on 2; the cylinder's checkpoint of 3 ranks resumed on 2; the
# refusal of a process grid.
#   sh tests/mpi/pddo.sh NSPD SOURCE_DIR MPIEXEC VTK_SAME
set -u
. "$2/tests/mpi/checks.sh"

check_body cavity_re200 pddo_cavity "2 3 4"
check_body cylinder_confined_re100 pddo_cylinder "3"
check_body cylinders_tandem_re10 pddo_tandem "2"

# the cylinder's checkpoint of 3 processes resumed on 2
set -f
IFS='
'
args=$(golden_overrides cylinder_confined_re100 | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
args="$args
--set
output.checkpoint_interval=0.005"
cyl="$src/cases/cylinder_confined_re100.yaml"
"$nspd" run "$cyl" -o "$work/pck.ref" --quiet $args || fail "the checkpointed PDDO cylinder on one process failed"
if on 3 "$cyl" -o "$work/pck.3" --quiet $args; then
    resume_check "$work/pck.3" 2 flow "$work/pck.ref" \
        "the PDDO cylinder's checkpoint of 3 ranks resumed on 2" "$cyl" $args
else
    fail "the checkpointed PDDO cylinder on 3 ranks failed"
fi
unset IFS
set +f

refused "the PDDO flow on a 2x2 grid" "divides its node list into ranges" 4 \
    "$src/cases/cavity_re1.yaml" -o "$work/bad" --processes 2x2
[ -e "$work/bad" ] && fail "a refused run wrote $work/bad"
finish
