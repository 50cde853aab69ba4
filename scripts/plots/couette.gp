# Couette flow with viscous heating: u and T across the channel vs exact.
set terminal pngcairo size 1000,420 font "DejaVu Sans,11"
set output outfile
set datafile separator ","
set multiplot layout 1,2 title "Couette flow with heating (Pr = 0.72, 32 cells)"
set grid
set key bottom right
set xlabel "y / H"
set ylabel "u / U"
plot x with lines lw 2 lc rgb "#440154" title "exact", \
     datafile every ::2 using 2:4 with points pt 7 ps 0.6 lc rgb "#21918c" title "nspd"
cp = 3.5
set ylabel "(T - T_w) / (Pr U^2 / 8 c_p)"
set key bottom center
plot 4 * x * (1 - x) with lines lw 2 lc rgb "#440154" title "exact", \
     (1/0.72) * 4 * x * (1 - x) with lines dt 2 lc rgb "#fde725" title "Pr = 1 (no Prandtl fix)", \
     datafile every ::2 using 2:(($7 - 1) / (0.72 / (8 * cp))) with points pt 7 ps 0.6 lc rgb "#21918c" title "nspd"
unset multiplot
