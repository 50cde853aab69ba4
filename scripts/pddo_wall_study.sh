#!/bin/sh
# The Re 10 confined cylinder's wall pressure and wall shear, node by node,
# at three lattices, against icoFoam's face pressures at three grids (issue
# 26: "a grid study of drag and of the wall pressure ... at three
# spacings"). nspd: cases/cylinder_confined_re10.yaml with the settings of
# docs/VALIDATION.md's "A horizon of two spacings" (antisymmetric walls,
# `updated`, `wall_pressure: momentum`, horizon_factor 2, the patch's local
# horizon with dr = dx, the inlet's corners CORNERS, default `inlet`; tau =
# dt = 3e-4 s, steady to 1e-4 m/s^2) at dx 0.1, 0.05 and 0.025 m; its last
# wall table (wall_NNNNN.csv). icoFoam:
# bench/openfoam/make_cylinder.sh at H = 0.1, 0.067 and 0.05 m (NT 20, 30,
# 40; dt 2e-3, 1e-3, 5e-4 s) to t = 3 s, the cylinder's face pressures
# (the `wallSample` function). Every distribution is resampled at 144
# angles (every 2.5 degrees, linear between its own stations, periodic);
# prints each nspd lattice's largest and rms difference from the next finer
# one (and their observed orders), and from icoFoam's finest grid, for the
# pressure and (nspd only) the wall shear; plots both.
#   scripts/pddo_wall_study.sh NSPD [WORK] [PNG] [CORNERS]
# WORK keeps the runs (default: a temporary directory, removed); PNG the
# plot (default docs/img/cylinder_wall_re10.png). About 6 min on 2 cores.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
nspd=$1
work=${2:-}
png=${3:-$root/docs/img/cylinder_wall_re10.png}
corners=${4:-inlet}
if [ -z "$work" ]; then
    work=$(mktemp -d)
    trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"
command -v icoFoam >/dev/null || [ -f /usr/share/openfoam/etc/bashrc ] ||
    { echo "OpenFOAM not found: scripts/deps.sh bench" >&2; exit 1; }
foam() { bash -c ". /usr/share/openfoam/etc/bashrc >/dev/null 2>&1; cd '$1' && $2"; }

run_nspd() { # DX THREADS
    d=$work/nspd_$1
    "$nspd" run "$root/cases/cylinder_confined_re10.yaml" -o "$d" --force --quiet --threads "$2" \
        --set flow.spacing="$1" --set time.dt=3e-4 --set flow.walls=antisymmetric \
        --set flow.divergence_term=updated --set flow.wall_pressure=momentum \
        --set flow.horizon_factor=2 \
        --set "flow.bodies=[{shape: circle, center: [5.0, 3.0], radius: 0.5, patch_radius: 2.01, horizon: local, dr_over_spacing: 1.0}]" \
        --set "flow.boundaries.x_min={type: inlet, velocity: 10.0, profile: uniform, corners: $corners}" \
        --set flow.steady_tolerance=1e-4 --set output.field_interval=10 \
        --set output.png=false --set output.plots=false
    # theta (deg), p, wall shear
    tail -n +3 "$(ls "$d"/wall_*.csv | tail -1)" | awk -F, '{ print $1, $4, $5 }' >"$work/nspd_$1.txt"
}
run_foam() { # NT DT
    d=$work/foam_$1
    rm -rf "$d"
    sh "$root/bench/openfoam/make_cylinder.sh" "$d" "$1" "$2" 3 1 10 500
    foam "$d" "blockMesh >log.blockMesh 2>&1 && icoFoam >log.icoFoam 2>&1 &&
        postProcess -func wallSample -latestTime >log.wall 2>&1"
    awk '!/^#/ { t = atan2($2 - 3, $1 - 5) * 45 / atan2(1, 1); if (t < 0) t += 360; print t, $4, 0 }' \
        "$(ls -d "$d"/postProcessing/wallSample/* | sort -g | tail -1)/p_cylinder.raw" |
        sort -g >"$work/foam_$1.txt"
}

# icoFoam on one core beside nspd on the other
(run_foam 20 2e-3 && run_foam 30 1e-3 && run_foam 40 5e-4) &
foam_job=$!
run_nspd 0.1 1
run_nspd 0.05 1
run_nspd 0.025 1
wait "$foam_job"

# resample FILE COLUMN: 144 lines "theta value", periodic linear interpolation
resample() {
    awk -v c="$2" '{ n++; t[n] = $1; v[n] = $c }
        END { t[0] = t[n] - 360; v[0] = v[n]; t[n + 1] = t[1] + 360; v[n + 1] = v[1]
              for (q = 0; q < 144; q++) { a = 2.5 * q
                  for (k = 0; k <= n && t[k + 1] < a; k++) ;
                  w = (a - t[k]) / (t[k + 1] - t[k]); print a, (1 - w) * v[k] + w * v[k + 1] } }' "$1"
}
for f in nspd_0.1 nspd_0.05 nspd_0.025 foam_20 foam_30 foam_40; do
    resample "$work/$f.txt" 2 >"$work/$f.p"
    resample "$work/$f.txt" 3 >"$work/$f.tau"
done
# diff A B: "max rms" of A - B over the 144 angles
diff_ab() {
    paste "$1" "$2" | awk '{ d = $2 - $4; a = d < 0 ? -d : d; if (a > m) m = a; s += d * d; n++ }
        END { printf "%.4g %.4g", m, sqrt(s / n) }'
}
order() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", log(a / b) / log(2) }'; }
for q in p tau; do
    name=$([ "$q" = p ] && echo "wall pressure (Pa)" || echo "wall shear (Pa)")
    set -- $(diff_ab "$work/nspd_0.1.$q" "$work/nspd_0.05.$q") $(diff_ab "$work/nspd_0.05.$q" "$work/nspd_0.025.$q")
    echo "$name, nspd: dx 0.1 - 0.05 max $1 rms $2; 0.05 - 0.025 max $3 rms $4; orders $(order "$1" "$3") (max), $(order "$2" "$4") (rms)"
done
for h in 20 30; do
    echo "wall pressure, icoFoam NT $h - NT 40: max rms $(diff_ab "$work/foam_$h.p" "$work/foam_40.p")"
done
for dx in 0.1 0.05 0.025; do
    echo "wall pressure, nspd dx $dx - icoFoam NT 40: max rms $(diff_ab "$work/nspd_$dx.p" "$work/foam_40.p")"
done
for f in nspd_0.1 nspd_0.05 nspd_0.025 foam_20 foam_30 foam_40; do
    awk -v f="$f" 'NR == 1 { r = $2 } $1 == 180 { s = $2 } NR == 1 || $2 < m { m = $2; at = $1 }
        END { printf "%-11s p rear %.3f, front %.3f, min %.3f at %.1f deg\n", f, r, s, m, at }' "$work/$f.p"
done
mkdir -p "$(dirname "$png")"
gnuplot -e "dir='$work'; out='$png'; corners='$corners'" "$here/plots/cylinder_wall.gp"
echo "plot: $png"
