# A shock tube: density, velocity and pressure against the exact solution.
# Variables: datafile (line probe CSV), exactfile (nspd riemann CSV), outfile, name
set terminal pngcairo size 1200,420 font "DejaVu Sans,11"
set output outfile
set datafile separator ","
set multiplot layout 1,3 title name
set key top right
set grid
set xlabel "x"
set ylabel "density"
plot exactfile every ::1 using 1:2 with lines lw 2 lc rgb "#440154" title "exact", \
     datafile every ::2 using 1:3 with points pt 7 ps 0.35 lc rgb "#21918c" title "nspd"
set ylabel "velocity"
plot exactfile every ::1 using 1:3 with lines lw 2 lc rgb "#440154" notitle, \
     datafile every ::2 using 1:4 with points pt 7 ps 0.35 lc rgb "#21918c" notitle
set ylabel "pressure"
plot exactfile every ::1 using 1:4 with lines lw 2 lc rgb "#440154" notitle, \
     datafile every ::2 using 1:6 with points pt 7 ps 0.35 lc rgb "#21918c" notitle
unset multiplot
