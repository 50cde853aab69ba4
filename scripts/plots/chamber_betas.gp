# The chamber of paper 003 (its Figs. 4-5): the block's centre-of-mass
# displacement and the integrated penalty force on it against time, for
# beta = 1/3, 1, 3, 9 and the strong coupling, one column per background,
# at the paper's steps (the runs of scripts/blast_study.sh with COUPLINGS
# "weak strong beta0.333333 beta3 beta9"; a missing run is left out).
#   gnuplot -e "root='out/blast_study'; level='coarse'; outfile='docs/img/chamber_betas_coarse.png'" scripts/plots/chamber_betas.gp
set terminal pngcairo size 1400,900 font "DejaVu Sans,11"
set output outfile
set termoption noenhanced
set datafile separator ","
set grid
set key top left
set xlabel "t (ms)"
label(r) = r eq "weak" ? "beta 1" : r eq "beta0.333333" ? "beta 1/3" : r eq "strong" ? "strong" : "beta ".substr(r, 5, 9)
colour(r) = r eq "beta0.333333" ? "#9ecae1" : r eq "weak" ? "#3b528b" : r eq "beta3" ? "#21918c" : r eq "beta9" ? "#5ec962" : "#d1495b"
file(bg, r) = sprintf("%s/%s/chamber_%s_%s/history.csv", root, level, bg, r)
runs(bg) = system(sprintf("for r in beta0.333333 weak beta3 beta9 strong; do [ -f %s/%s/chamber_%s_$r/history.csv ] && printf '%%s ' $r; done", root, level, bg))
set multiplot layout 2,2 title sprintf("chamber detonation, %s mesh, the paper's time steps", level)
do for [bg in "gks iga"] {
    set title sprintf("%s: centre-of-mass displacement", bg)
    set ylabel "com dx (mm)"
    rs = runs(bg)
    plot for [r in rs] file(bg, r) using ($2*1e3):(column("com_dx_m")*1e3) with lines lw 2 lc rgb colour(r) title label(r)
}
do for [bg in "gks iga"] {
    set title sprintf("%s: integrated penalty force", bg)
    set ylabel "impulse x (N s/m)"
    rs = runs(bg)
    plot for [r in rs] file(bg, r) using ($2*1e3):(column("penalty_impulse_x_N_s_per_m")) with lines lw 2 lc rgb colour(r) title label(r)
}
unset multiplot
