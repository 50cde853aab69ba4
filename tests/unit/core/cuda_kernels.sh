#!/bin/sh
# Compile-only CUDA check of the kernels (ctest unit.core.cuda_kernels).
#
#   cuda_kernels.sh NVCC SOURCE_DIR WORK_DIR
#
# Every src/**/*_kernel.h is compiled on its own as CUDA (a generated .cu
# that includes it: the header is valid C++ for nvcc), then
# tests/unit/core/cuda_kernels.cu, which calls each kernel from a __global__
# function (nvcc refuses a call to a host-only function from device code; an
# include alone would not show it). Nothing runs, so no GPU is needed.
# Warnings are errors, nvcc's and the host compiler's; the host side is
# compiled with OpenMP as the C build is (the kernels' `omp simd` pragmas).
# Without nvcc the test is skipped (exit 77).
set -u
nvcc=$1
src=$2
work=$3
if [ -z "$nvcc" ] || ! [ -x "$nvcc" ]; then
    echo "nvcc not found: CUDA compile check skipped"
    exit 77
fi
mkdir -p "$work" || exit 1
flags="-x cu -arch=sm_90 -std=c++17 -Werror all-warnings -Xcompiler -fopenmp,-Wall,-Wextra,-Werror -I $src/src"
# The compiles run side by side: each spends most of its time starting
# nvcc's passes, not computing (about 3 s each, under 1 s of CPU).
compile() { # TU OBJECT MESSAGE
    # shellcheck disable=SC2086 # flags is a word list
    "$nvcc" $flags -c "$1" -o "$2" || { echo "FAIL: $3" && return 1; }
}
pids=""
count=0
for header in $(cd "$src/src" && find . -name '*_kernel.h' | sed 's|^\./||' | sort); do
    tu="$work/$(echo "$header" | tr '/.' '__').cu"
    printf '#include "%s"\n' "$header" >"$tu"
    compile "$tu" "$tu.o" "$header does not compile as CUDA" &
    pids="$pids $!"
    count=$((count + 1))
done
if [ "$count" -eq 0 ]; then
    echo "FAIL: no *_kernel.h under $src/src"
    exit 1
fi
compile "$src/tests/unit/core/cuda_kernels.cu" "$work/cuda_kernels.o" \
    "a kernel cannot be called from device code (tests/unit/core/cuda_kernels.cu)" &
pids="$pids $!"
status=0
for pid in $pids; do wait "$pid" || status=1; done
[ "$status" -eq 0 ] && echo "$count kernel headers and their device calls compile as CUDA"
exit "$status"
