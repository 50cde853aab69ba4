# Cylinder Ma 2 Re 300: pressure coefficient along the surface against the
# angle from the front stagnation point (paper 000 Fig. 7 plots it against
# (y - 6D)/D; the angle separates the two sides).
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "angle from the front stagnation point (deg)"
set ylabel "C_p"
set grid
set key top right
set title sprintf("Cylinder, Ma 2, Re 300, %s", label)
plot surffile every ::2 using (atan2(-($4 - 6.0), -($3 - 2.0)) * 180 / pi):5 with points pt 7 ps 0.4 lc rgb "#21918c" title "nspd", \
     pitot with lines dt 2 lc rgb "#440154" title "Rayleigh pitot C_p"
