#!/bin/sh
# The Re 10 confined cylinder's steady drag, time to solution: nspd's PDDO
# flow against OpenFOAM's icoFoam, both stopped by the same steady
# criterion (max |du/dt| over the nodes or cells below TOL m/s^2), run
# alternately, each on one core (nspd also on two threads).
#   bench/pddo_re10_steady.sh [NSPD] [REPEATS] [TOL] [DT] [DX]
# nspd: cases/cylinder_confined_re10.yaml at dx DX (default 0.0625 m) with
# the settings docs/VALIDATION.md found most accurate (antisymmetric walls,
# `updated`, `wall_pressure: momentum`, horizon_factor 2, the patch's local
# horizon with dr = dx, the inlet's corners holding the inflow so that the
# flow rate is the one posed), dt = tau = DT (default 2.2e-3 s, 0.79 of the
# stable limit 2.78e-3 s at dx 0.0625 m; dx 0.05 m takes 1.4e-3 s, 0.79 of
# 1.78e-3); icoFoam on bench/openfoam/make_cylinder.sh's O-grid, H = 0.1 m,
# dt 2e-3 s (Courant 0.73), the grid within 0.07 % of its own converged
# drag (288.8 N/m).
# Prints each run's drag (N/m), its deviation from 288.8, steps, wall and
# CPU seconds, then the medians. Needs scripts/deps.sh bench (OpenFOAM).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
nspd=${1:-$root/build/nspd}
repeats=${2:-5}
tol=${3:-1e-2}
dt=${4:-2.2e-3}
dx=${5:-0.0625}
command -v icoFoam >/dev/null || { echo "OpenFOAM not found: scripts/deps.sh bench" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export OMP_WAIT_POLICY=passive
mkdir -p "$here/results"
out=$here/results/pddo_re10_steady.txt
: >"$out"
foam() { bash -c ". /usr/share/openfoam/etc/bashrc >/dev/null 2>&1; cd '$1' && $2"; }
row() { # CODE DRAG STEPS TIMEFILE
    awk -v c="$1" -v d="$2" -v s="$3" '{ printf "%-16s drag %.3f N/m (%+.2f %%), %d steps, %.2f s wall, %.2f s CPU\n",
        c, d, 100 * (d / 288.8 - 1), s, $1, $2 + $3 }' "$4" | tee -a "$out"
}
run_foam() {
    d=$work/foam
    rm -rf "$d"
    sh "$here/openfoam/make_cylinder.sh" "$d" 20 2e-3 4 1 10 1 "$tol"
    foam "$d" "blockMesh >log.blockMesh 2>&1"
    foam "$d" "/usr/bin/time -f '%e %U %S' -o '$work/time' icoFoam >log.icoFoam 2>&1"
    drag=$(tr -d '()' <"$d/postProcessing/forces/0/force.dat" | awk '!/^#/ { d = $2 } END { print d }')
    row icoFoam "$drag" "$(grep -c '^Time = ' "$d/log.icoFoam")" "$work/time"
}
run_nspd() { # THREADS
    d=$work/nspd
    /usr/bin/time -f '%e %U %S' -o "$work/time" "$nspd" run "$root/cases/cylinder_confined_re10.yaml" \
        -o "$d" --force --quiet --threads "$1" --set flow.spacing="$dx" --set time.dt="$dt" \
        --set flow.walls=antisymmetric --set flow.divergence_term=updated \
        --set flow.wall_pressure=momentum --set flow.horizon_factor=2 \
        --set "flow.bodies=[{shape: circle, center: [5.0, 3.0], radius: 0.5, patch_radius: 2.01, horizon: local, dr_over_spacing: 1.0}]" \
        --set "flow.boundaries.x_min={type: inlet, velocity: 10.0, profile: uniform, corners: inlet}" \
        --set flow.steady_tolerance="$tol" --set output.field_interval=4.0 \
        --set output.png=false --set output.plots=false
    json() { sed -n "s/.*\"$1\": \([^,]*\),*/\1/p" "$d/summary.json"; }
    row "nspd $1 thread(s)" "$(json drag_n)" "$(json steps)" "$work/time"
}
for r in $(seq "$repeats"); do
    run_foam
    run_nspd 1
    run_nspd 2
done
echo "medians of $repeats (wall s, CPU s):"
for c in icoFoam "nspd 1" "nspd 2"; do
    grep "^$c" "$out" | sed 's/.* steps, \([0-9.]*\) s wall, \([0-9.]*\) s CPU/\1 \2/' | sort -g |
        awk -v c="$c" '{ w[NR] = $1; p[NR] = $2 } END { m = int((NR + 1) / 2); printf "%-8s %.2f %.2f\n", c, w[m], p[m] }'
done
