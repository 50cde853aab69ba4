# The checks of tests/mpi/run.sh and tests/mpi/sanitized.sh: a case run
# on several processes against the run of one without mpirun, every file
# the same (same_results, tests/cli/common.sh). Sourced by those scripts
# with their arguments: NSPD SOURCE_DIR MPIEXEC VTK_SAME.
nspd=$1
src=$2
mpiexec=$3
vtk_same=$4
. "$src/tests/cli/common.sh"
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# more ranks than cores: a rank that waits yields its core to one that
# works, instead of spinning (4 ranks on 2 cores: a run 7 times faster)
export OMPI_MCA_mpi_yield_when_idle=1
# the shared-memory transport's layer only: the network layers' probes cost
# 0.2 s a launch (a launch of 2 ranks 0.6 -> 0.4 s), over a hundred launches
export OMPI_MCA_pml=ob1
# a hung rank must fail the test, not the suite's time limit
on() { n=$1; shift; timeout -k 10 300 "$mpiexec" -n "$n" "$nspd" run "$@"; }

# $1: a layout, a number of processes ("3", slabs or the default grid) or
# a process grid ("2x2"), run under mpirun as `on` does; its name in
# messages is in $what afterwards
on_layout() {
    layout=$1
    shift
    case "$layout" in
    *x*)
        what="$layout blocks"
        on $((${layout%x*} * ${layout#*x})) "$@" --processes "$layout"
        ;;
    *)
        what="$layout ranks"
        on "$layout" "$@"
        ;;
    esac
}

# a case file's run of one process (directory $work/TAG.1), then on each
# layout (directories $work/TAG.LAYOUT), every file the same:
#   check TAG CASE "LAYOUT ..." [nspd run arguments]
check() {
    tag=$1 file=$2 layouts=$3
    shift 3
    [ -n "$layouts" ] || return 0 # none in this selection (run.sh's pick)
    "$nspd" run "$file" -o "$work/$tag.1" --quiet "$@" ||
        { fail "$tag: the run of one process failed"; return; }
    for l in $(echo "$layouts" | tr ' ' '\n'); do # split under any IFS
        if on_layout "$l" "$file" -o "$work/$tag.$l" --quiet "$@"; then
            same_results "$work/$tag.1" "$work/$tag.$l" "$tag on $what"
        else
            fail "$tag on $what: exit status $?"
        fi
    done
}

# a case of cases/ to an end time: check_case NAME END "LAYOUT ..."
check_case() {
    check "$1" "$src/cases/$1.yaml" "$3" --set "time.end=$2"
}

# a case at its golden resolution (tests/golden/runs.txt), then more
# --set arguments: check_body NAME TAG "LAYOUT ..." [ARGS]
check_body() {
    name=$1 tag=$2 layouts=$3
    shift 3
    set -f
    IFS='
'
    args=$(golden_overrides "$name" | while IFS= read -r o; do printf -- '--set\n%s\n' "$o"; done)
    check "$tag" "$src/cases/$name.yaml" "$layouts" $args "$@" # split at newlines only
    unset IFS
    set +f
}

# a run of n processes (1: without mpirun): runs N [nspd run arguments]
runs() {
    n=$1
    shift
    if [ "$n" -eq 1 ]; then "$nspd" run "$@"; else on "$n" "$@"; fi
}
# The run in $1 continued on $2 processes from its newest checkpoint, its
# outputs after it removed first (the last file of the series $3, and
# summary.json), ends as the run in $4 (a check named $5); the rest: the
# case and its arguments.
resume_check() {
    dir=$1 n=$2 series=$3 ref=$4 what=$5
    shift 5
    # the last output's file (.vtr or .pvtr; its pieces are left for the
    # resumed run to clear away, on another process count)
    # (no globs: some callers run under set -f)
    last=$(find "$dir" -maxdepth 1 -name "${series}_[0-9][0-9][0-9][0-9][0-9].*" | sort | tail -n 1)
    last=$(basename "${last%.*}")
    rm -f "$dir/summary.json"
    find "$dir" -maxdepth 1 -name "$last.*" -delete
    if runs "$n" "$@" -o "$dir" --quiet --resume; then
        [ -n "$(find "$dir" -maxdepth 1 -name "$last.*")" ] || fail "$what: $last not written again"
        same_results "$ref" "$dir" "$what"
    else
        fail "$what: exit status $?"
    fi
}

# A refusal: exit status 2, the message (an extended regex) once:
#   refused WHAT PATTERN N [nspd run arguments]
refused() {
    what=$1 pattern=$2 n=$3
    shift 3
    on "$n" "$@" >"$work/out" 2>&1
    status=$?
    lines=$(grep -c -E "$pattern" "$work/out")
    if [ "$status" -eq 2 ] && [ "$lines" -eq 1 ]; then
        ok
    else
        fail "$what: exit status $status, the message $lines times (expected 2, once):"
        cat "$work/out"
    fi
}
