#!/bin/sh
# The compiler launcher of the libraries whose vectorisation report the
# build keeps (CMakeLists.txt, NSPD_VEC_REPORTS): GCC appends to an
# -fopt-info file, so an incremental build's report would keep the lines of
# an earlier compile (a loop no longer vectorised would still pass
# unit.core.vectorised); each compile starts its report afresh.
#   usage: fresh_report.sh COMPILER ARGS...
for a in "$@"; do
    case "$a" in
    -fopt-info-vec-optimized=*) rm -f "${a#*=}" ;;
    esac
done
exec "$@"
