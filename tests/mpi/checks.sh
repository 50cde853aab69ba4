# The checks of tests/mpi/run.sh and tests/mpi/sanitized.sh: a case run
# on several processes against the run of one without mpirun, every file
# the same (same_results, tests/cli/common.sh). Sourced after common.sh,
# with nspd, src and mpiexec set.
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# a hung rank must fail the test, not the suite's time limit
on() { n=$1; shift; timeout -k 10 300 "$mpiexec" -n "$n" "$nspd" run "$@"; }

# name, end time, the process counts; one process without mpirun first
check_case() {
    name=$1 end=$2
    shift 2
    ref="$work/$name.1"
    "$nspd" run "$src/cases/$name.yaml" -o "$ref" --quiet --set "time.end=$end" ||
        { fail "$name: the run of one process failed"; return; }
    for n in "$@"; do
        if on "$n" "$src/cases/$name.yaml" -o "$work/$name.$n" --quiet --set "time.end=$end"; then
            same_results "$ref" "$work/$name.$n" "$name on $n ranks"
        else
            fail "$name on $n ranks: exit status $?"
        fi
    done
}

# name, end time, process grids (PXxPY), against the run of check_case
check_grid() {
    name=$1 end=$2
    shift 2
    for g in "$@"; do
        n=$((${g%x*} * ${g#*x}))
        if on "$n" "$src/cases/$name.yaml" -o "$work/$name.$g" --quiet --set "time.end=$end" \
            --processes "$g"; then
            same_results "$work/$name.1" "$work/$name.$g" "$name on $g blocks"
        else
            fail "$name on $g blocks: exit status $?"
        fi
    done
}

# a case at its golden resolution (tests/golden/runs.txt), tag, the
# process counts ("2 3"), more --set arguments
check_body() {
    name=$1 tag=$2 ranks=$3
    shift 3
    set -f
    IFS='
'
    args=$(golden_overrides "$name" | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
    ref="$work/$tag.1"
    "$nspd" run "$src/cases/$name.yaml" -o "$ref" --quiet $args "$@" ||
        { fail "$tag: the run of one process failed"; unset IFS; set +f; return; }
    for n in $(echo "$ranks" | tr " " "\n"); do
        if on "$n" "$src/cases/$name.yaml" -o "$work/$tag.$n" --quiet $args "$@"; then
            same_results "$ref" "$work/$tag.$n" "$tag on $n ranks"
        else
            fail "$tag on $n ranks: exit status $?"
        fi
    done
    unset IFS
    set +f
}

# the same on one process grid, against check_body's run of one process
check_body_grid() {
    name=$1 tag=$2 grid=$3
    shift 3
    set -f
    IFS='
'
    args=$(golden_overrides "$name" | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
    n=$((${grid%x*} * ${grid#*x}))
    if on "$n" "$src/cases/$name.yaml" -o "$work/$tag.$grid" --quiet $args "$@" --processes "$grid"; then
        same_results "$work/$tag.1" "$work/$tag.$grid" "$tag on $grid blocks"
    else
        fail "$tag on $grid blocks: exit status $?"
    fi
    unset IFS
    set +f
}
