# ctest-labels: release
# Every case under cases/ at a reduced resolution gives bit for bit the
# outputs recorded in tests/golden/data, on 1 and on 2 threads (see
# tests/golden/golden.sh; re-record only for a change meant to move numbers,
# and say which moved and by how much in the commit).
#   usage: test_golden.sh NSPD SOURCE_DIR
set -u
status=0
for threads in 1 2; do
    sh "$2/tests/golden/golden.sh" check "$1" "$2" "$threads"
    result=$?
    [ "$result" -eq 77 ] && exit 77 # recorded for another native target: skipped, not failed
    [ "$result" -ne 0 ] && status=1
done
exit $status
