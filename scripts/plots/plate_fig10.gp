# Paper 000 Fig. 10: position of the right crack tip against time.
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "t (us)"
set ylabel "right crack tip x (mm)"
set title "Plate with failure: right crack tip"
set key top left
set grid
cR = 2758.2e-3 # Rayleigh speed, mm/us (plane stress, nu = 1/3)
plot datafile using ($2*1e6):($7*1e3) with steps lw 2 lc rgb "#21918c" title "nspd", \
     [6:16.7] 5.0 + cR * (x - 6.0) with lines dt 2 lc rgb "#440154" title "slope of the Rayleigh speed"
