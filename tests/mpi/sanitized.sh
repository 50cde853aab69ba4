# The distributed paths under AddressSanitizer and UBSan (the build of
# `make test-asan`): a few cases on several processes against the run of
# one, every file the same, as tests/mpi/run.sh holds the release build:
# a stretched grid's pieces (.pvtr) and a run started from them, the
# immersed boundary's window and fresh cells with a divided solid on 2
# ranks and on 2 x 2 blocks, the penalty's gathered cells, a divided
# solid's pieces (.pvtu), the correspondence solid divided (its halo's
# exchanges, damage settling across the ranks; the classic force's
# reverse T and ghost states). Open MPI's own allocations that it never frees
# are not nspd's leaks: leak detection is off (ASan's other checks and
# UBSan's stay on; any report fails the run).
#   usage: sanitized.sh NSPD SOURCE_DIR MPIEXEC VTK_SAME
set -u
. "$2/tests/mpi/checks.sh"
export ASAN_OPTIONS=detect_leaks=0

check_case blasius 0.3 3
from=$(ls "$work/blasius.3"/flow_*.pvtr | tail -n 1)
"$nspd" run "$src/cases/blasius.yaml" -o "$work/from.1" --quiet --set time.end=0.05 \
    --set "flow.initial={from: $from}" && ok || fail "a run of one process from a .pvtr failed"
check_body cylinder_crack_ma17 crack "2 2x2"
check_body chamber_detonation chamber 2
check_body plate_crack plate 3
check_body hollow_cylinder_pulse hcy 3
check_body hollow_cylinder_pulse hcy_classic 3 --set solid.correspondence.force=classic
finish
