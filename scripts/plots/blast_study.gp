# A blast experiment of paper 003 on both gas backgrounds, weak and strong
# coupling (scripts/blast_study.sh): the probe's pressure and, for the
# chamber, the block's centre-of-mass displacement and the penalty force on
# it, for the rings their mass loss and broken bonds, against time.
#   gnuplot -e "dir='...'; name='chamber'; probe='right_wall'; level='coarse'; outfile='...'"
set terminal pngcairo size 1800,520 font "DejaVu Sans,11"
set output outfile
set termoption noenhanced
set datafile separator ","
set grid
set key top left
set multiplot layout 1,3 title sprintf("%s, %s mesh: GKS and IGA backgrounds, weak and strong coupling", name, level)
runs = "gks_weak gks_strong iga_weak iga_strong"
colour(k) = word("#3b528b #5ec962 #d1495b #f4a261", k)
dash(k) = (k % 2 == 1) ? 1 : 2
file(k) = sprintf("%s/%s_%s/history.csv", dir, name, word(runs, k))
set xlabel "t (us)"
set ylabel sprintf("p at %s (MPa)", probe)
pcol = probe."_p_Pa"
plot for [k=1:4] file(k) using ($2*1e6):(column(pcol)*1e-6) with lines lw 2 \
    dt dash(k) lc rgb colour(k) title word(runs, k)
if (name eq "chamber") {
    set ylabel "block centre-of-mass displacement (mm)"
    plot for [k=1:4] file(k) using ($2*1e6):(column("com_dx_m")*1e3) with lines lw 2 \
        dt dash(k) lc rgb colour(k) title word(runs, k)
    set ylabel "penalty force on the block, x (kN per m of depth)"
    plot for [k=1:4] file(k) using ($2*1e6):(column("penalty_force_x_N_per_m")*1e-3) with lines \
        lw 2 dt dash(k) lc rgb colour(k) title word(runs, k)
} else {
    set ylabel "mass loss"
    plot for [k=1:4] file(k) using ($2*1e6):(column("mass_loss")) with lines lw 2 \
        dt dash(k) lc rgb colour(k) title word(runs, k)
    set ylabel "broken bonds"
    plot for [k=1:4] file(k) using ($2*1e6):(column("broken_bonds")) with lines lw 2 \
        dt dash(k) lc rgb colour(k) title word(runs, k)
}
unset multiplot
