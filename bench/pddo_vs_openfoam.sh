#!/bin/sh
# Time to solution at matched accuracy: nspd's PDDO flow (paper 002)
# against OpenFOAM's icoFoam (finite volume, PISO, second-order central
# differences), both on one core, run alternately.
#   bench/pddo_vs_openfoam.sh [NSPD] [REPEATS]
#
# Cavity, Re 100, against Ghia, Ghia and Shin (1982): nspd runs
# cases/cavity_re200.yaml with the lid speed of Re 100, as
# scripts/validate.sh does for docs/VALIDATION.md, at several lattices,
# both wall treatments and two time steps; icoFoam runs the same flow in lid
# units (bench/openfoam/make_cavity.sh) on N x N cells. Both stop at the
# same steady criterion, max |du/dt| < 1e-6 U^2/L, and both are scored by
# scripts/ghia_compare.sh: the largest deviation from Ghia's 17 stations of
# u/U on x = L/2 and of v/U on y = L/2. For each code and setting, the
# coarsest resolution within 0.02 U (and 0.01 U) and its times.
#
# Confined cylinder, Re 10 (cases/cylinder_confined_re10.yaml): nspd at the
# coarse lattices of docs/VALIDATION.md, icoFoam on the O-grid of
# bench/openfoam/make_cylinder.sh at about the same cell size, both to the
# paper's t = 4 s: the paper's probes and the drag per unit span.
#
# Wall and CPU times are of the solver command alone (nspd run; icoFoam
# without blockMesh and sampling), medians of REPEATS runs (default 3).
# Errors and probes are deterministic and come from the last run. Needs
# scripts/deps.sh build bench (OpenFOAM, gnuplot, GNU time, VTK for
# Python). The lists below can be narrowed from the environment
# (PDDO_FOAM_CAVITY, PDDO_NSPD_CAVITY, PDDO_FOAM_CYLINDER,
# PDDO_NSPD_CYLINDER; empty skips), PDDO_CYLINDER_REPEATS runs the cylinders
# fewer times; PDDO_FOAM_RE100 adds icoFoam's Re 100 cylinder (a reference
# for docs/VALIDATION.md, not a timing).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/.." && pwd)
nspd=${1:-$root/build/nspd}
repeats=${2:-3}
# icoFoam cells per side (Courant 1)
foam_cavity=${PDDO_FOAM_CAVITY-16 20 24 32 48 64}
# nspd intervals per side:walls:dt (s; 4e-5 is docs/VALIDATION.md's, 1.6e-4
# is 0.8 of the convective limit 2 nu/U^2)
nspd_cavity=${PDDO_NSPD_CAVITY-80:paper:4e-5 90:paper:4e-5 100:paper:4e-5 \
30:antisymmetric:4e-5 40:antisymmetric:4e-5 50:antisymmetric:4e-5 \
30:antisymmetric:1.6e-4 35:antisymmetric:1.6e-4 40:antisymmetric:1.6e-4}
# icoFoam cells per quarter of the cylinder:dt (Courant 0.73 and 0.48;
# 40:1e-3, Courant 0.7, grows unstable from step 60), nspd spacing:dt
foam_cylinder=${PDDO_FOAM_CYLINDER-20:2e-3 30:1e-3}
nspd_cylinder=${PDDO_NSPD_CYLINDER-0.1:1e-3 0.05:1e-3}
# icoFoam only, once, if set (about 5 and 13 min): the Re 100 cylinder to
# t = 2 s, cells per quarter:dt (Courant 0.44), e.g. "20:1e-4 30:7e-5"
foam_re100=${PDDO_FOAM_RE100-}
# the cylinders take about 10 min of CPU a repeat: fewer repeats of them
cylinder_repeats=${PDDO_CYLINDER_REPEATS:-$repeats}

out=$here/results/pddo_vs_openfoam
mkdir -p "$out"
rm -f "$out"/*.time "$out"/*.info
raw=$here/results/pddo_vs_openfoam.txt
: >"$raw"
command -v icoFoam >/dev/null || { echo "OpenFOAM not found: scripts/deps.sh bench" >&2; exit 1; }
[ -x "$nspd" ] || { echo "no nspd at $nspd" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
# timed FILE COMMAND...: appends 'wall_s cpu_s' of COMMAND to FILE (on a
# loaded machine the CPU time, user + system, is the steadier of the two)
timed() {
    f=$1
    shift
    /usr/bin/time -f '%e %U %S' -o "$work/time" "$@"
    awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$work/time" >>"$f"
}
# foam DIR COMMAND: runs COMMAND in DIR in OpenFOAM's environment (bash)
foam() { bash -c ". /usr/share/openfoam/etc/bashrc >/dev/null 2>&1; cd '$1' && $2"; }
# foam_timed DIR SOLVER FILE: runs it there, appends its times to FILE
foam_timed() {
    foam "$1" "/usr/bin/time -f '%e %U %S' -o '$work/time' $2 >log.$2 2>&1" ||
        { echo "$2 failed in $1:" >&2; grep -E 'Time =|Courant|FOAM|Floating' "$1/log.$2" | tail -6 >&2; exit 1; }
    awk '{ printf "%.3f %.3f\n", $1, $2 + $3 }' "$work/time" >>"$3"
}
json() { sed -n "s/.*\"$2\": \([^,]*\),*/\1/p" "$1"; } # FILE KEY
# ghia RUN_DIR RE L U LABEL ID: scores the last line tables, writes ID.info
ghia() {
    line=$(sh "$root/scripts/ghia_compare.sh" "$1" "$2" "$3" "$4" "$out/$6.png" "$5")
    echo "$line" >>"$raw"
    echo "$line" | sed 's/.*u(y): max |dev| \([0-9.]*\).*v(x): max |dev| \([0-9.]*\).*/\1 \2/'
}

# ---- cavity -----------------------------------------------------------------
run_foam_cavity() { # N
    id=cavity_foam_$1
    d=$work/$id
    rm -rf "$d"
    sh "$here/openfoam/make_cavity.sh" "$d" "$1"
    foam "$d" "blockMesh >log.blockMesh 2>&1"
    foam_timed "$d" icoFoam "$out/$id.time"
    foam "$d" "postProcess -func sample -latestTime >log.sample 2>&1"
    t=$(ls "$d/postProcessing/sample")
    for s in vertical horizontal; do # nspd's line table layout, for ghia_compare.sh
        { echo "# t = $t s"; echo "x,y,u,v,p"
          awk -F, 'NR > 1 { print $1 "," $2 "," $4 "," $5 ",0" }' "$d/postProcessing/sample/$t/${s}_U.csv"; } \
            >"$d/line_${s}_00001.csv"
    done
    steps=$(grep -c '^Time = ' "$d/log.icoFoam")
    echo "icoFoam $1 x $1: t = $t s, $steps steps, $(tail -1 "$out/$id.time" | sed "s/ / s wall, /") s CPU" >>"$raw"
    echo "icoFoam - $1x$1 $(($1 * $1)) $steps $(ghia "$d" 100 1 1 "icoFoam $1 x $1" "$id")" >"$out/$id.info"
}
run_nspd_cavity() { # INTERVALS:WALLS:DT
    m=${1%%:*} rest=${1#*:}
    walls=${rest%%:*} dt=${rest#*:}
    id=cavity_nspd_${m}_${walls}_$dt
    d=$work/$id
    dx=$(awk -v m="$m" 'BEGIN { printf "%.10g", 0.001 / m }')
    timed "$out/$id.time" "$nspd" run "$root/cases/cavity_re200.yaml" -o "$d" --force --quiet --threads 1 \
        --set flow.spacing="$dx" --set flow.walls="$walls" --set flow.boundaries.y_max.velocity=0.1 \
        --set time.dt="$dt" --set time.end=1.0 --set flow.steady_tolerance=1e-5 \
        --set output.field_interval=1.0 --set output.history_interval=0.005 \
        --set output.png=false --set output.plots=false
    steps=$(json "$d/summary.json" steps)
    echo "nspd $m x $m $walls dt $dt: t = $(json "$d/summary.json" time_s) s, $steps steps, $(tail -1 "$out/$id.time" | sed "s/ / s wall, /") s CPU" >>"$raw"
    echo "nspd $walls,dt=$dt ${m}x$m $(json "$d/summary.json" physical_nodes) $steps $(ghia "$d" 100 0.001 0.1 "$walls ghosts, dt $dt s" "$id")" \
        >"$out/$id.info"
}

# ---- confined cylinder ------------------------------------------------------
run_foam_cylinder() { # NT:DT
    nt=${1%%:*} dt=${1#*:}
    id=cylinder_foam_$nt
    d=$work/$id
    rm -rf "$d"
    sh "$here/openfoam/make_cylinder.sh" "$d" "$nt" "$dt"
    foam "$d" "blockMesh >log.blockMesh 2>&1"
    foam_timed "$d" icoFoam "$out/$id.time"
    foam "$d" "postProcess -func sample -latestTime >log.sample 2>&1"
    s=$d/postProcessing/sample/4
    cells=$(sed -n 's/.*nCells: *\([0-9]*\).*/\1/p' "$d/log.blockMesh" | tail -1)
    steps=$(grep -c '^Time = ' "$d/log.icoFoam")
    # pressure in front, beside; |u| at (5, 4.2), (5, 1.8), the outlet
    probes=$(paste -d, "$s/probes_p.csv" "$s/probes_U.csv" | awk -F, 'NR > 1 { p[NR - 1] = $4; u[NR - 1] = sqrt($8 * $8 + $9 * $9) }
        END { printf "%.1f %.1f %.2f %.2f %.2f", p[1], p[2], u[3], u[4], u[5] }')
    # drag per unit span at t = 4 s: total, pressure, viscous; and at t = 3 s (steady?)
    drag=$(tr -d '()' <"$d/postProcessing/forces/0/force.dat" | awk '!/^#/ { if ($1 <= 3 + 1e-9) d3 = $2; t = $2; p = $5; v = $8 }
        END { printf "%.1f %.1f %.1f %.2g", t, p, v, (t - d3) / t }')
    echo "icoFoam cylinder $nt per quarter, dt $dt: $cells cells, $steps steps, $(tail -1 "$out/$id.time" | sed "s/ / s wall, /") s CPU; probes $probes; drag $drag" >>"$raw"
    echo "icoFoam H=$(awk -v n="$nt" 'BEGIN { print 2 / n }'),dt=$dt $cells $steps $probes $drag" >"$out/$id.info"
}
run_nspd_cylinder() { # SPACING:DT
    dx=${1%%:*} dt=${1#*:}
    id=cylinder_nspd_$dx
    d=$work/$id
    timed "$out/$id.time" "$nspd" run "$root/cases/cylinder_confined_re10.yaml" -o "$d" --force --quiet --threads 1 \
        --set flow.spacing="$dx" --set time.dt="$dt" --set output.field_interval=4.0 \
        --set output.png=false --set output.plots=false
    # the nearest output node to each probe (as docs/VALIDATION.md): p in
    # front (4.5, 3), beside (5, 3.5); |u| at (5, 4.2), (5, 1.8), (15, 3)
    probes=$(/usr/bin/python3 - "$(ls "$d"/flow_*.vtu | tail -1)" <<'EOF'
import math, sys, vtk
r = vtk.vtkXMLUnstructuredGridReader()
r.SetFileName(sys.argv[1])
r.Update()
g = r.GetOutput()
pts, u, p = g.GetPoints(), g.GetPointData().GetArray("velocity"), g.GetPointData().GetArray("pressure")
def near(x, y):
    return min(range(g.GetNumberOfPoints()), key=lambda k: (pts.GetPoint(k)[0] - x) ** 2 + (pts.GetPoint(k)[1] - y) ** 2)
def speed(k):
    return math.hypot(u.GetTuple(k)[0], u.GetTuple(k)[1])
print("%.1f %.1f %.2f %.2f %.2f" % (p.GetTuple1(near(4.5, 3)), p.GetTuple1(near(5, 3.5)),
      speed(near(5, 4.2)), speed(near(5, 1.8)), speed(near(15, 3))))
EOF
)
    s=$d/summary.json
    drag=$(printf "%.1f %.1f %.1f" "$(json "$s" drag_n)" "$(json "$s" drag_pressure_n)" "$(json "$s" drag_viscous_n)")
    steps=$(json "$s" steps)
    echo "nspd cylinder dx $dx, dt $dt: $(json "$s" nodes) nodes, $steps steps, $(tail -1 "$out/$id.time" | sed "s/ / s wall, /") s CPU; probes $probes; drag $drag (3-4 s mean)" >>"$raw"
    echo "nspd dx=$dx,dt=$dt $(json "$s" nodes) $steps $probes $drag -" >"$out/$id.info"
}

# ---- confined cylinder, Re 100: icoFoam only (a reference, not a timing) -----
# mean drag over 1-2 s, lift amplitude and period by nspd's rule (CASES.md,
# summary.json): upward zero crossings of the lift from 1 s, each re-armed
# once the lift was below -1e-3 q L; the period between the first and last
# crossing over their number less one; the amplitude half of max - min
# between them
run_foam_re100() { # NT:DT
    nt=${1%%:*} dt=${1#*:}
    id=re100_foam_$nt
    d=$work/$id
    rm -rf "$d"
    sh "$here/openfoam/make_cylinder.sh" "$d" "$nt" "$dt" 2 1 100 2
    foam "$d" "blockMesh >log.blockMesh 2>&1"
    foam_timed "$d" icoFoam "$out/$id.time"
    tr -d '()' <"$d/postProcessing/forces/0/force.dat" | awk -v t0=1 -v t1=2 -v nt="$nt" -v dt="$dt" '
        !/^#/ { t = $1; d = $2; l = $3
            if (t >= t0 && t <= t1 + 1e-9) { sd += d; n++
                if (nc >= 1) { if (l > mx) mx = l; if (l < mn) mn = l }
                if (pl < 0 && l >= 0 && armed) { c[++nc] = pt + (t - pt) * pl / (pl - l); armed = 0
                    if (nc == 1) { mx = l; mn = l } else { amx = mx; amn = mn } }
                if (l < -1e-3 * 0.5 * 100 * 100) armed = 1 }
            pt = t; pl = l }
        END { T = (c[nc] - c[1]) / (nc - 1)
            printf "icoFoam Re 100, H %.3g m, dt %s s: mean drag %.1f N/m, lift amplitude %.1f N/m, period %.5f s (St %.4f), %d periods\n",
                2 / nt, dt, sd / n, (amx - amn) / 2, T, 1 / (T * 100), nc - 1 }' |
        tee -a "$raw" >"$out/$id.info"
    echo "  $(tail -1 "$out/$id.time" | sed "s/ / s wall, /") s CPU (paper: 9501 N/m, 2153 N/m, 0.0447 s; Fluent 9448.4, 2224)" >>"$out/$id.info"
}

# ---- runs, the two codes alternately ------------------------------------------
alternate() { # RUN_A LIST_A RUN_B LIST_B: A1 B1 A2 B2 ... then the rest
    la=$2 lb=$4
    while [ -n "$la" ] || [ -n "$lb" ]; do
        if [ -n "$la" ]; then a=${la%% *}; "$1" "$a"; case "$la" in *" "*) la=${la#* } ;; *) la= ;; esac; fi
        if [ -n "$lb" ]; then b=${lb%% *}; "$3" "$b"; case "$lb" in *" "*) lb=${lb#* } ;; *) lb= ;; esac; fi
    done
}
squash() { echo "$*" | tr -s ' \n' '  ' | sed 's/^ //; s/ $//'; }
foam_cavity=$(squash "$foam_cavity")
nspd_cavity=$(squash "$nspd_cavity")
foam_cylinder=$(squash "$foam_cylinder")
nspd_cylinder=$(squash "$nspd_cylinder")
for r in $(seq "$repeats"); do
    echo "== repeat $r" >>"$raw"
    alternate run_foam_cavity "$foam_cavity" run_nspd_cavity "$nspd_cavity"
    [ "$r" -le "$cylinder_repeats" ] || continue
    alternate run_foam_cylinder "$foam_cylinder" run_nspd_cylinder "$nspd_cylinder"
done

for c in $(squash "$foam_re100"); do run_foam_re100 "$c"; done

# ---- tables ---------------------------------------------------------------------
wall() { cut -d' ' -f1 <"$out/$1.time" | median; }
cpu() { cut -d' ' -f2 <"$out/$1.time" | median; }
echo "Cavity, Re 100: max deviation from Ghia et al. (1982) in units of U; time to steady state"
printf "%-8s %-26s %-9s %-7s %-7s %-8s %-8s %-8s %s\n" code setting grid nodes steps "u(y)" "v(x)" "wall s" "CPU s"
for f in "$out"/cavity_*.info; do
    [ -e "$f" ] || continue
    id=$(basename "$f" .info)
    read -r code setting grid nodes steps eu ev <"$f"
    printf "%-8s %-26s %-9s %-7s %-7s %-8s %-8s %-8.2f %.2f\n" "$code" "$setting" "$grid" "$nodes" "$steps" "$eu" "$ev" \
        "$(wall "$id")" "$(cpu "$id")"
done | sort -k1,2 -k4n | tee "$out/cavity.txt"
echo
echo "Matched accuracy: the coarsest grid of each setting within the level (the larger of the u and v deviations)"
for level in 0.02 0.01; do
    awk -v lvl="$level" '{ e = $6 > $7 ? $6 : $7; key = $1 " " $2
        if (e <= lvl && !(key in best)) { best[key] = $0; order[++n] = key } }
        END { for (i = 1; i <= n; i++) { split(best[order[i]], f, " ")
            printf "  <= %s U: %-8s %-26s %-9s %.4f U, %s s wall, %s s CPU\n", lvl, f[1], f[2], f[3], (f[6] > f[7] ? f[6] : f[7]), f[8], f[9] } }' \
        "$out/cavity.txt"
done | tee "$out/matched.txt"
echo
echo "Confined cylinder, Re 10, t = 4 s (paper: 220 Pa, -37 Pa, 16.9 m/s, 13.81 m/s); drag in N/m"
printf "%-8s %-18s %-7s %-6s %-8s %-8s %-8s %-8s %-8s %-7s %-9s %-8s %-8s %-7s %s\n" code setting nodes steps \
    "p front" "p side" "|u| top" "|u| bot" "|u| out" drag pressure viscous "d(3-4s)" "wall s" "CPU s"
for f in "$out"/cylinder_*.info; do
    [ -e "$f" ] || continue
    id=$(basename "$f" .info)
    read -r code setting nodes steps pf ps ut ub uo d dp dv dd <"$f"
    printf "%-8s %-18s %-7s %-6s %-8s %-8s %-8s %-8s %-8s %-7s %-9s %-8s %-8s %-7.1f %.1f\n" "$code" "$setting" "$nodes" "$steps" \
        "$pf" "$ps" "$ut" "$ub" "$uo" "$d" "$dp" "$dv" "$dd" "$(wall "$id")" "$(cpu "$id")"
done | tee "$out/cylinder.txt"
for f in "$out"/re100_*.info; do [ -e "$f" ] || continue; cat "$f"; done
echo "(medians of $repeats runs, cylinders $cylinder_repeats, 1 core each; raw: $raw; plots: $out/*.png)"
