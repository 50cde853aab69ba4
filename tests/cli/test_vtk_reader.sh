#!/bin/sh
# The VTK files nspd writes open in VTK's own XML readers (what ParaView
# uses): a small 3D solid run (.vtu) and a shock tube (.vtr), every file of
# each .pvd series.
#   usage: test_vtk_reader.sh NSPD SOURCE_DIR
set -eu
nspd=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$nspd" run "$src/cases/block_3d.yaml" -o "$work/block" --quiet --set time.end=1e-6 \
    --set output.field_interval=5e-7
points=$(sed -n 's/.*"points": \([0-9]*\).*/\1/p' "$work/block/summary.json")
/usr/bin/python3 "$src/tests/cli/tools/read_vtk.py" "$work/block/solid.pvd" "$points" \
    displacement:3 velocity:3 damage volume
"$nspd" run "$src/cases/sod.yaml" -o "$work/sod" --quiet --set time.end=0.05 \
    --set output.field_interval=0.025
cells=$(sed -n 's/.*"cells": \([0-9]*\).*/\1/p' "$work/sod/summary.json")
/usr/bin/python3 "$src/tests/cli/tools/read_vtk.py" "$work/sod/flow.pvd" "$cells" \
    density velocity:3 pressure temperature mach cell_kind
echo "2 passed, 0 failed"
