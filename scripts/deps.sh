#!/bin/sh
# Installs the Debian packages a make target needs, and nothing else.
#   scripts/deps.sh build      compiler, CMake, Ninja, libyaml, libpng, cairo and a font for the
#                              pictures' text, cmocka, VTK for Python (the tests open our
#                              .vtu/.vtr files with VTK's own readers), PyYAML (the mutation
#                              test walks the case files' keys), ffmpeg (movies),
#                              Chromium (tests/cli/test_report.sh opens report.html in it),
#                              SuiteSparse (UMFPACK: the PDDO flow's sparse LU of its
#                              pressure matrix, which is not symmetric), Open MPI (the
#                              distributed engine, core/comm.h; tests/mpi), PETSc with
#                              MUMPS and hypre (petsc-dev: the PDDO pressure solved on
#                              every process, flow/pddo/ppe_petsc.h; it leaves the BLAS
#                              alternative as it is, so UMFPACK's bits do not move)
#   scripts/deps.sh validate   + gnuplot (plots for docs/VALIDATION.md)
#   scripts/deps.sh bench      + LAMMPS (reference PD code), hyperfine, OpenFOAM (reference
#                              flow code), gnuplot and GNU time (bench/pddo_vs_openfoam.sh
#                              scores its cavities with scripts/ghia_compare.sh, which
#                              plots, and takes each solver's CPU time), g++
#                              (bench/kernel_flops.sh counts the kernels' flops in C++),
#                              SuperLU, sequential MUMPS and hypre (with Open MPI), which
#                              bench/ppe_solvers/ measures against UMFPACK
#   scripts/deps.sh fuzz       + clang, libFuzzer (libclang-rt-14-dev), OpenMP for clang (make fuzz)
# As root the missing packages are installed with apt-get; otherwise the exact
# command is printed and the script fails, so nothing runs half set up.
set -eu

want="gcc make cmake ninja-build pkg-config libyaml-dev libpng-dev libcairo2-dev fonts-dejavu-core libcmocka-dev python3-vtk9 python3-yaml ffmpeg chromium libsuitesparse-dev libopenmpi-dev openmpi-bin petsc-dev"
for group in "$@"; do
    case "$group" in
    build) ;;
    validate) want="$want gnuplot-nox" ;;
    bench) want="$want lammps hyperfine openfoam gnuplot-nox time g++ libsuperlu-dev libmumps-seq-dev libhypre-dev libopenmpi-dev" ;;
    fuzz) want="$want clang libclang-rt-14-dev libomp-14-dev" ;;
    *) echo "deps.sh: unknown group '$group' (expected build, validate, bench or fuzz)" >&2; exit 2 ;;
    esac
done

missing=""
for pkg in $want; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
        missing="$missing $pkg"
    fi
done
[ -z "$missing" ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
    echo "nspd needs these Debian packages:$missing" >&2
    echo "install them with:  sudo apt-get install -y --no-install-recommends$missing" >&2
    exit 1
fi
echo "installing:$missing" >&2
export DEBIAN_FRONTEND=noninteractive
# A fresh machine may have empty package lists; update only when needed.
if ! apt-get install -y --no-install-recommends $missing >/dev/null 2>&1; then
    apt-get update -qq
    apt-get install -y --no-install-recommends $missing >/dev/null
fi
