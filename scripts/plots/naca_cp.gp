# NACA 0012 Ma 0.5 Re 5000: -Cp along the chord (both sides).
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "x / c"
set ylabel "C_p"
set yrange [*:*] reverse
set grid
set key bottom right
set title "NACA 0012, Ma 0.5, Re 5000, alpha 0 (c/512)"
plot surffile every ::2 using 3:5 with points pt 7 ps 0.3 lc rgb "#21918c" title "nspd (both sides)", \
     isen with lines dt 2 lc rgb "#440154" title "isentropic stagnation C_p"
