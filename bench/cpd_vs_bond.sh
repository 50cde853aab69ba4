#!/bin/sh
# Correspondence solid (issue 14) against the bond-based kernel, side by side.
#   bench/cpd_vs_bond.sh [NSPD] [REPEATS] [POINTS]
# For 1 and 2 threads, runs `nspd bench cpd` and `nspd bench pd` at the same
# point count (default 250,000) REPEATS times each (default 5), alternately,
# and prints the medians and the spread (min-max) of bond updates per second
# (each bond counted from both ends, as stored) and of seconds per step.
# The two bodies differ in families: the correspondence block has 24
# neighbours per point (square, delta 2.5 h), the PD plate 28 (disc,
# 3.015 dx). Raw JSON goes to bench/results/cpd_vs_bond.txt.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
nspd=${1:-$here/../build/nspd}
repeats=${2:-5}
points=${3:-250000}
cpd_steps=20
pd_steps=100
out=$here/results
mkdir -p "$out"
raw=$out/cpd_vs_bond.txt
: >"$raw"
field() { sed -n "s/.*\"$1\": \\([0-9.e+-]*\\).*/\\1/p" "$2"; }
stats() { sort -g | awk '{a[NR]=$1} END {printf "%.4g (%.4g-%.4g)", (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2), a[1], a[NR]}'; }
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

for p in 1 2; do
    for f in cpd_rate pd_rate cpd_step pd_step; do : >"$out/${f}_$p"; done
    for r in $(seq "$repeats"); do
        "$nspd" bench cpd --points "$points" --threads "$p" --steps "$cpd_steps" >"$out/cpd.json"
        cat "$out/cpd.json" >>"$raw"
        field bond_updates_per_s "$out/cpd.json" >>"$out/cpd_rate_$p"
        field seconds_per_step "$out/cpd.json" >>"$out/cpd_step_$p"
        "$nspd" bench pd --points "$points" --threads "$p" --steps "$pd_steps" >"$out/pd.json"
        cat "$out/pd.json" >>"$raw"
        field bond_updates_per_s "$out/pd.json" >>"$out/pd_rate_$p"
        field seconds "$out/pd.json" | awk -v s=$pd_steps '{print $1 / s}' >>"$out/pd_step_$p"
    done
done
echo "points $points; medians of $repeats alternated runs (min-max); cpd $cpd_steps steps, pd $pd_steps steps"
printf "%-14s %-8s %-34s %-32s\n" kernel threads "bond updates/s" "s per step"
for p in 1 2; do
    printf "%-14s %-8s %-34s %-32s\n" correspondence "$p" "$(stats <"$out/cpd_rate_$p")" "$(stats <"$out/cpd_step_$p")"
    printf "%-14s %-8s %-34s %-32s\n" bond-based "$p" "$(stats <"$out/pd_rate_$p")" "$(stats <"$out/pd_step_$p")"
    printf "ratio bond/cpd at %d threads: bond updates/s %.1f, time per step %.1f\n" "$p" \
        "$(echo "$(median <"$out/pd_rate_$p") $(median <"$out/cpd_rate_$p")" | awk '{print $1/$2}')" \
        "$(echo "$(median <"$out/cpd_step_$p") $(median <"$out/pd_step_$p")" | awk '{print $1/$2}')"
done
echo "(raw: $raw)"
