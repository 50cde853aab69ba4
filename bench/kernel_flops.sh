#!/bin/sh
# The floating-point operations of nspd's kernels, counted: each
# bench/flops/<kernel>.cpp compiles a kernel header as C++ over a number
# type that counts its arithmetic (bench/flops/counted.hpp). For the
# rooflines of docs/PERFORMANCE.md. Needs g++.
# Usage: bench/kernel_flops.sh [kernel ...]   (default: all of bench/flops/*.cpp)
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
kernels=${*:-$(basename -s .cpp bench/flops/*.cpp)}
for k in $kernels; do
    g++ -O1 -std=c++17 -Isrc -Ibench/flops -o "$dir/$k" "bench/flops/$k.cpp"
    "$dir/$k"
done
