# Mass loss (Eq. 24 of paper 003) against time for the couplings of one
# ring case on the GKS background, one panel per mesh (the runs of
# scripts/blast_study.sh with COUPLINGS="weak strong damaged sealed";
# a run that is missing is left out of its panel).
#   gnuplot -e "root='out/blast_study'; name='square'; outfile='docs/img/blast_square_couplings.png'" scripts/plots/blast_couplings.gp
set terminal pngcairo size 1800,520 font "DejaVu Sans,11"
set output outfile
set termoption noenhanced
set datafile separator ","
set grid
set key bottom right
set logscale y
set yrange [1e-4:1]
set xlabel "t (us)"
set ylabel "mass loss (mass fraction with damage >= 0.99)"
set multiplot layout 1,3 title sprintf("%s on the GKS background: mass loss by coupling and mesh", name)
colour(r) = r eq "weak" ? "#3b528b" : r eq "damaged" ? "#21918c" : r eq "strong" ? "#d1495b" : "#f4a261"
file(level, r) = sprintf("%s/%s/%s_gks_%s/history.csv", root, level, name, r)
do for [level in "coarse medium fine"] {
    set title level
    runs = system(sprintf("for r in weak damaged strong sealed; do [ -f %s/%s/%s_gks_$r/history.csv ] && printf '%%s ' $r; done", root, level, name))
    plot for [r in runs] file(level, r) \
        using ($2*1e6):(column("mass_loss") > 0 ? column("mass_loss") : NaN) with lines lw 2 \
        lc rgb colour(r) title r
}
unset multiplot
