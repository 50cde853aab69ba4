#!/bin/sh
# A PDDO cavity run's centreline profiles against Ghia, Ghia and Shin (1982)
# (tests/verify/pddo_cavity/ghia1982_{u,v}.csv): u/U along x = L/2 and v/U
# along y = L/2, linearly interpolated between the nodes to Ghia's 17
# stations each. Prints the largest deviations (all stations, the next
# largest, which shows a lone outlier, and the largest of the 15 off the
# walls and lid, where both sides are exact) and plots both profiles.
#   usage: ghia_compare.sh RUN_DIR RE L U OUT_PNG [LABEL]
set -eu
run=$1 re=$2 len=$3 speed=$4 png=$5 label=${6:-PDDO}
here=$(dirname "$0")
data="$here/../tests/verify/pddo_cavity"
col=$(case "$re" in 100) echo 2 ;; 400) echo 3 ;; 1000) echo 4 ;; *) echo "no Ghia table at Re $re" >&2; exit 2 ;; esac)
vert=$(ls "$run"/line_vertical_*.csv | tail -1)
horiz=$(ls "$run"/line_horizontal_*.csv | tail -1)
# compare TABLE POSITION_COLUMN VALUE_COLUMN GHIA_FILE NAME: "NAME max_all at max_inner at"
compare() {
    awk -F, -v pc="$2" -v vc="$3" -v gc="$col" -v L="$len" -v U="$speed" -v name="$5" '
        FNR == NR { if (FNR > 2) { n++; s[n] = $pc / L; f[n] = $vc / U }; next }
        /^[#a-z]/ { next }
        { t = $1; g = $gc
          for (k = 1; k < n && s[k + 1] < t; k++) ;
          w = s[k + 1] > s[k] ? (t - s[k]) / (s[k + 1] - s[k]) : 0
          v = (1 - w) * f[k] + w * f[k + 1]; d = v - g; a = d < 0 ? -d : d
          if (a > all) { next_all = all; at_next = at_all; all = a; at_all = t }
          else if (a > next_all) { next_all = a; at_next = t }
          if (t > 0 && t < 1 && a > inner) { inner = a; at_inner = t }
          printf "%s,%.6g,%.6g,%.6g\n", name, t, g, v > "/dev/stderr" }
        END { printf "%s: max |dev| %.4f (at %.4f; next %.4f at %.4f), off the sides %.4f (at %.4f)\n", name, all, at_all, next_all, at_next, inner, at_inner }' \
        "$1" "$4"
}
u=$(compare "$vert" 2 3 "$data/ghia1982_u.csv" "u(y)" 2>"$run/ghia_u.csv")
v=$(compare "$horiz" 1 4 "$data/ghia1982_v.csv" "v(x)" 2>"$run/ghia_v.csv")
echo "Re $re, $label: $u; $v"
gnuplot -e "ufile='$vert'; vfile='$horiz'; gu='$data/ghia1982_u.csv'; gv='$data/ghia1982_v.csv'; col=$col; L=$len; U=$speed; outfile='$png'; name='Re $re, $label'" \
    "$here/plots/cavity_ghia.gp"
