#!/bin/sh
# make validate: the paper cases at full resolution, their numbers and plots
# for docs/VALIDATION.md (written to docs/img/ and printed), and the tests
# labelled slow.
#   scripts/validate.sh NSPD BUILD_DIR
set -eu
nspd=${1:-build/nspd}
build=${2:-build}
out=out/validate
mkdir -p "$out" docs/img

echo "== plate (paper 000 Sec. 4.2): without failure, Fig. 9"
"$nspd" run cases/plate_crack.yaml -o "$out/plate_elastic" --force --quiet \
    --set solid.failure.enabled=false
echo "== plate: with failure, Fig. 10"
"$nspd" run cases/plate_crack.yaml -o "$out/plate_crack" --force --quiet
cp "$out/plate_crack/damage_00010.png" docs/img/plate_damage_16.7us.png
cp "$out/plate_crack/damage_00007.png" docs/img/plate_damage_11.7us.png

# Fig. 9 reference: quasi-static opening of a centre crack 2a in a plate under
# remote stress sigma = E eps, eps = 2 v t / L (the edges move apart at 2v):
# u_y(x) = (2 sigma / E) sqrt(a^2 - x^2) (plane stress, Sneddon), with the
# finite-width factor sqrt(sec(pi a / W)) on the stress intensity.
t=$(sed -n '1s/# t = \([0-9.e+-]*\) s/\1/p' "$out/plate_elastic/line_upper_face_00010.csv")
gnuplot -e "datafile='$out/plate_elastic/line_upper_face_00010.csv'; t=$t; outfile='docs/img/plate_fig9_uy.png'" \
    scripts/plots/plate_fig9.gp
awk -F, -v t="$t" 'NR > 2 { if ($4 > m) { m = $4; x = $1 } }
    END { eps = 2 * 20 * t / 0.05; lefm = 2 * eps * 0.005; fw = lefm * sqrt(1 / cos(3.14159265 * 0.1));
          printf "Fig. 9: max u_y = %.4e m at x = %.2f mm; LEFM %.4e m (%+.1f %%), with finite width %.4e m (%+.1f %%)\n",
                 m, 1e3 * x, lefm, 100 * (m / lefm - 1), fw, 100 * (m / fw - 1) }' \
    "$out/plate_elastic/line_upper_face_00010.csv" | tee "$out/fig9.txt"

gnuplot -e "datafile='$out/plate_crack/history.csv'; outfile='docs/img/plate_fig10_tip.png'" \
    scripts/plots/plate_fig10.gp
sed -n 's/.*"\(crack_tip_x_m\|crack_speed_m_per_s\|wall_s\)": \(.*\),*/Fig. 10: \1 = \2/p' \
    "$out/plate_crack/summary.json" | tee "$out/fig10.txt"

echo "== slow tests"
ctest --test-dir "$build" --output-on-failure -L slow || true
echo "plots in docs/img/, runs in $out/"
