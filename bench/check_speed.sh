#!/bin/sh
# `nspd check` on the largest case each model accepts on this machine (the
# memory estimate just under its memory), and on each shipped case: wall
# time, median of 5 (issue 23: under one second however large the case).
# Usage: bench/check_speed.sh [build/nspd]
set -eu
NSPD=${1:-build/nspd}
median5() { # command...: the median wall time of 5 runs, in s
    for k in 1 2 3 4 5; do
        /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1
    done | sort -n | sed -n 3p
}
row() { # label case.yaml --set...: the check's time and its one line
    label=$1; shift
    printf '%-34s %6s s  ' "$label" "$(median5 "$NSPD" check "$@")"
    "$NSPD" check "$@" 2>&1 | sed 's/.*(case [^:]*: //; s/;.*//; s/)$//' | cut -c1-100
}
echo "machine memory: $(awk '/MemTotal/ {printf "%.1f GB", $2 / 1e6}' /proc/meminfo)"
row "bond PD, plate 7.5 um (20 GB)" cases/plate_crack.yaml --set solid.spacing=7.5e-6
row "correspondence, square 50 um" cases/hollow_square_pressure.yaml --set solid.spacing=5e-5
row "GKS, Sod 12000 x 12000" cases/sod.yaml --set flow.grid.x.segments.0.cells=12000 \
    --set flow.grid.y.segments.0.cells=12000
# 8 mm, the next spacing that divides the sides, needs 26.8 GB
row "PDDO, confined cylinder 10 mm" cases/cylinder_confined_re100.yaml --set flow.spacing=0.01
row "penalty, cylinder 50 um, 0.1 mm" cases/blast_hollow_cylinder.yaml --set solid.spacing=5e-5 \
    --set flow.grid.x.segments.0.spacing=1e-4 --set flow.grid.y.segments.0.spacing=1e-4
row "ghost, panel 3 um" cases/panel_shock.yaml --set solid.spacing=3e-6
row "IGA, blast 0.1 mm" cases/iga_cylindrical_blast.yaml --set flow.grid.x.segments.0.spacing=1e-4 \
    --set flow.grid.y.segments.0.spacing=1e-4
for f in cases/*.yaml; do row "$(basename "$f")" "$f"; done
