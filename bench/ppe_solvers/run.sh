#!/bin/sh
# The PDDO pressure solvers side by side on the matrix of a case (issue 26;
# README.md). Builds a copy of nspd with dump.patch, runs the case's first
# 153 steps with NSPD_PPE_DUMP, then the direct solvers (direct.c) and
# hypre's BoomerAMG (amg.c) on the dumped matrix and right-hand sides.
#   bench/ppe_solvers/run.sh [CASE] [WORK_DIR]
# CASE defaults to the paper's Re 100 cylinder (cases/cylinder_confined_re100.yaml).
set -eu
root=$(cd "$(dirname "$0")/../.." && pwd)
case_file=${1:-$root/cases/cylinder_confined_re100.yaml}
work=${2:-$root/out/ppe_solvers}
"$root/scripts/deps.sh" build bench
mkdir -p "$work/dump"
rm -rf "$work/src"
git -C "$root" worktree add -f --detach "$work/src" HEAD >/dev/null
trap 'git -C "$root" worktree remove --force "$work/src"' EXIT
git -C "$work/src" apply "$root/bench/ppe_solvers/dump.patch"
cmake -S "$work/src" -B "$work/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$work/build" -j "$(nproc)" --target nspd >/dev/null
dt=$(sed -n 's/^ *dt: *//p' "$case_file" | head -1)
NSPD_PPE_DUMP="$work/dump" OMP_NUM_THREADS=1 "$work/build/nspd" run "$case_file" \
    --set time.end="$(awk -v dt="$dt" 'BEGIN { print 153.5 * dt }')" \
    --set output.average_from=0 -o "$work/run" --force --quiet
here="$root/bench/ppe_solvers"
cc -O3 -march=native -o "$work/direct" "$here/direct.c" -I/usr/include/suitesparse \
    -I/usr/include/superlu -I/usr/include/mumps_seq -lumfpack -lsuperlu -ldmumps_seq -lblas -lm
mpicc -O3 -march=native -o "$work/amg" "$here/amg.c" -I/usr/include/hypre -lHYPRE -lm
"$work/direct" "$work/dump" 152 5
for settings in "0.25 10 6 6" "0.25 10 6 18" "0.5 6 0 6"; do
    echo "BoomerAMG + BiCGStab to 1e-8, threshold coarsening interpolation relaxation = $settings"
    # shellcheck disable=SC2086
    "$work/amg" "$work/dump" 1e-8 $settings
done
