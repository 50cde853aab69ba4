#!/bin/sh
# The status contract of core/status.h, as far as the source shows it: no
# failure code leaves a function without its message, so src/ may not
# return or assign a bare NSPD_ERR_* (only NSPD_FAIL makes a failure; TRY
# turns anything else into an internal error at run time, which
# unit.core.core tests).
#   usage: test_status_contract.sh NSPD SOURCE_DIR
set -u
src=$2
# core/status.c, which implements the contract, is the one exception
bad=$(grep -rnE '(return|=)[[:space:]]*NSPD_ERR_[A-Z]+[[:space:]]*;' "$src/src" --include='*.c' --include='*.h' |
    grep -vE '[<>=!]=[[:space:]]*NSPD_ERR_' | grep -v '/src/core/status\.c:')
if [ -n "$bad" ]; then
    echo "FAIL: a failure code without its message (use NSPD_FAIL(code, \"what; expected\")):"
    echo "$bad"
    exit 1
fi
echo "no bare NSPD_ERR_ return or assignment in src/"
