# Cavity centreline profiles (PDDO, line tables) against Ghia et al. (1982).
set terminal pngcairo size 1000,440 font "DejaVu Sans,11"
set output outfile
set datafile separator ","
set multiplot layout 1,2 title "Lid-driven cavity, ".name." vs Ghia, Ghia and Shin (1982)"
set grid
set key bottom right
set xlabel "u / U at x = L/2"
set ylabel "y / L"
plot ufile every ::1 using ($3 / U):($2 / L) with lines lw 2 lc rgb "#21918c" title "nspd", \
     gu every ::1 using col:1 with points pt 6 ps 1.2 lc rgb "#440154" title "Ghia et al."
set key top right
set xlabel "x / L"
set ylabel "v / U at y = L/2"
plot vfile every ::1 using ($1 / L):($4 / U) with lines lw 2 lc rgb "#21918c" title "nspd", \
     gv every ::1 using 1:col with points pt 6 ps 1.2 lc rgb "#440154" title "Ghia et al."
unset multiplot
