# ctest-labels: release
#!/bin/sh
# The refusal contract on every numeric key of every case under cases/: each
# set to 0, -1, 1e-300, 1e300, 1e11, a 20-digit integer, NaN and [] through
# `nspd check --set` (tests/cli/tools/mutate_cases.py says what each answer
# must be). About 4,500 calls, under a minute on two cores; the release
# build only (under the sanitizers each call costs ten times as much, and
# the fuzzers cover the same readers there).
#   usage: test_mutations.sh NSPD SOURCE_DIR
exec /usr/bin/python3 "$2/tests/cli/tools/mutate_cases.py" "$1" "$2" 2
