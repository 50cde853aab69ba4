# Shock on a panel: horizontal displacement of the panel's tip.
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "t (ms)"
set ylabel "tip displacement (mm)"
set grid
set key top left
set title "Panel (50 mm x 1 mm steel) hit by a Ma 1.21 shock"
# the shock reaches the panel's front face at 0.24 ms
set arrow from 0.24, graph 0 to 0.24, graph 1 nohead dt 3 lc rgb "#888888"
set label "shock arrives" at 0.26, graph 0.75 textcolor rgb "#555555"
plot datafile every ::1 using ($2*1e3):(column("tip_dx_m")*1e3) with lines lw 2 lc rgb "#21918c" title "nspd"
