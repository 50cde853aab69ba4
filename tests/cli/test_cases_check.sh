#!/bin/sh
# Every case file under cases/ is valid: `nspd check` accepts it.
#   usage: test_cases_check.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
passed=0
failed=0
for case in "$src"/cases/*.yaml; do
    if "$nspd" check "$case" >/dev/null; then
        passed=$((passed + 1))
    else
        echo "FAIL $case"
        failed=$((failed + 1))
    fi
done
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
