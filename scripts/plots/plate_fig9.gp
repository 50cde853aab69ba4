# Paper 000 Fig. 9: vertical displacement of the points just above the crack
# line at t = 16.7 us without failure, against the quasi-static LEFM opening.
set terminal pngcairo size 900,560 font "DejaVu Sans,12"
set output outfile
set datafile separator ","
set xlabel "x (mm)"
set ylabel "u_y (mm)"
set title sprintf("Plate without failure: upper crack face at t = %.1f us", t * 1e6)
set key top right
set grid
a = 5.0                       # crack half-length, mm
eps = 2 * 20.0 * t / 0.05     # nominal strain of the 50 mm plate
fw = sqrt(1 / cos(pi * 0.1))  # finite-width factor, a/W = 0.1
lefm(x) = abs(x) < a ? 2 * eps * sqrt(a*a - x*x) : 1/0
plot datafile every ::2 using ($1*1e3):($4*1e3) with lines lw 2 lc rgb "#21918c" title "nspd (500 x 500 points)", \
     lefm(x) with lines dt 2 lw 2 lc rgb "#440154" title "LEFM, infinite plate", \
     fw * lefm(x) with lines dt 3 lw 2 lc rgb "#fde725" title "LEFM, finite width"
