# Re 10 confined cylinder: wall pressure and wall shear against the angle
# (counterclockwise from the rear, theta = 0 on the +x side; the front
# stagnation point at 180 deg), nspd at three lattices and icoFoam's face
# pressures (scripts/pddo_wall_study.sh writes dir/*.txt: theta p tau).
set terminal pngcairo size 1000,820 font "DejaVu Sans,12"
set output out
set multiplot layout 2,1 title sprintf("Re 10 confined cylinder, the wall: nspd (inlet corners: %s) and icoFoam", corners)
set grid
set xrange [0:360]
set xtics 45
set key top left
set ylabel "wall pressure (Pa)"
plot dir.'/nspd_0.1.txt' using 1:2 with lines lw 1.5 lc rgb "#fde725" title "nspd dx 0.1 m", \
     dir.'/nspd_0.05.txt' using 1:2 with lines lw 1.5 lc rgb "#21918c" title "nspd dx 0.05 m", \
     dir.'/nspd_0.025.txt' using 1:2 with lines lw 1.5 lc rgb "#440154" title "nspd dx 0.025 m", \
     dir.'/foam_40.txt' using 1:2 with points pt 7 ps 0.5 lc rgb "#e66101" title "icoFoam H 0.05 m"
set xlabel "angle from the rear (deg); front stagnation point at 180"
set ylabel "wall shear (Pa)"
set key top right
plot dir.'/nspd_0.1.txt' using 1:3 with lines lw 1.5 lc rgb "#fde725" title "nspd dx 0.1 m", \
     dir.'/nspd_0.05.txt' using 1:3 with lines lw 1.5 lc rgb "#21918c" title "nspd dx 0.05 m", \
     dir.'/nspd_0.025.txt' using 1:3 with lines lw 1.5 lc rgb "#440154" title "nspd dx 0.025 m"
unset multiplot
