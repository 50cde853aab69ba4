#!/bin/sh
# The IGA quadrature point's floating-point operations, counted
# (bench/iga/qp_flops.cpp: the kernel compiled as C++ over a counting
# number type). Needs g++.
# Usage: bench/iga_qp_flops.sh
set -eu
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
g++ -O1 -std=c++17 -Isrc -o "$dir/qp_flops" bench/iga/qp_flops.cpp
"$dir/qp_flops"
