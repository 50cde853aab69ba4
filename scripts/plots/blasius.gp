# Flat plate: skin friction against Blasius. cffile: x, Re_x, Cf (from validate.sh).
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "Re_x"
set ylabel "C_f"
set logscale xy
set grid
set title "Laminar flat plate, Ma 0.3: skin friction"
plot [5e3:1e5] 0.664 / sqrt(x) with lines lw 2 lc rgb "#440154" title "Blasius 0.664/sqrt(Re_x)", \
     cffile using 2:3 with points pt 7 ps 0.6 lc rgb "#21918c" title "nspd"
