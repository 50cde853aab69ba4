#!/bin/sh
# make demo: the flagship coupled case - supersonic flow (Ma 1.7) cracking a
# cylinder, paper 000 Sec. 4.4 - at reduced resolution (solid spacing 0.01 D
# instead of 0.005 D, flow D/64 instead of D/128 near the body; about 20 s on
# 2 cores), into out/cylinder_crack_demo/ with Mach + damage pictures and
# ParaView files; then the pre-cracked steel plate of Sec. 4.2 at full
# resolution (about 25 s) into out/plate_crack/.
set -eu
nspd=${1:-build/nspd}

out=out/cylinder_crack_demo
h=0.015625 # D/64
"$nspd" run cases/cylinder_crack_ma17.yaml -o "$out" --force \
    --set solid.spacing=0.01 \
    --set flow.grid.x.segments.0.spacing_end=$h --set flow.grid.x.segments.1.spacing=$h \
    --set flow.grid.x.segments.2.spacing_start=$h \
    --set flow.grid.y.segments.0.spacing_end=$h --set flow.grid.y.segments.1.spacing=$h \
    --set flow.grid.y.segments.2.spacing_start=$h \
    --set output.field_interval=1e-3
"$nspd" movie "$out" --field mach_damage
report_cylinder=$("$nspd" report "$out")
echo
echo "results in $out/:"
echo "  mach_damage.mp4         the movie: the shock, the wake and the cracks, 1 ms a frame"
echo "  mach_damage_00020.png   Mach number with the cylinder's damage on top at t = 20 ms"
echo "                          (mach_damage_00000..20: every millisecond)"
echo "  damage_00020.png        the cracks alone; schlieren_*.png: density gradients"
echo "  flow.pvd, solid.pvd     open both in ParaView: flow fields per cell, damage per point"
echo "  case.yaml               the resolved case (the overrides above written in)"
echo "  summary.json            branch_angle_deg, broken_bond_fraction, cd, timings"
sed -n 's/.*"\(branch_angle_deg\|downstream_branch_time_s\|broken_bond_fraction\|wall_s\)": \(.*\),*/  \1 = \2/p' \
    "$out/summary.json"
echo

out=out/plate_crack
"$nspd" run cases/plate_crack.yaml -o "$out" --force
"$nspd" movie "$out" --field damage
report_plate=$("$nspd" report "$out")
echo
echo "results in $out/:"
echo "  damage.mp4              the movie of the crack running and branching"
echo "  damage_00010.png        the crack at t = 16.7 us (damage_00000..10: every 1.67 us)"
echo "  solid.pvd               open in ParaView: displacement, velocity, damage per point"
echo "  summary.json            crack_tip_x_m, crack_speed_m_per_s, timings"
sed -n 's/.*"\(crack_tip_x_m\|crack_speed_m_per_s\|wall_s\)": \(.*\),*/  \1 = \2/p' "$out/summary.json"
echo
echo "one page per run (open in a browser):"
echo "  $report_cylinder"
echo "  $report_plate"
