#!/bin/sh
# Correspondence-solid throughput: nspd against LAMMPS peri/eps, side by side.
#   bench/cpd_vs_lammps.sh [NSPD] [REPEATS]
# LAMMPS has no correspondence model; peri/eps (Mitchell's elastic-plastic
# state-based PD) is its nearest plastic solid. For 1 and 2 threads/processes,
# runs `nspd bench cpd` (250,000 points, 24 neighbours each) and LAMMPS on
# bench/lammps/plate_eps.in (250,000 atoms in one layer, 28 partners each)
# REPEATS times each (default 5) alternately, and prints the medians and the
# spread (min-max) of bond updates per second (a bond counted once from each
# end in both codes: nspd's stored bonds, LAMMPS' partners). LAMMPS' time is
# its "Loop time" of the timed run (the family build is in an earlier run).
# Raw results go to bench/results/cpd_vs_lammps.txt.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
nspd=${1:-$here/../build/nspd}
repeats=${2:-5}
steps=20
out=$here/results
mkdir -p "$out"
raw=$out/cpd_vs_lammps.txt
: >"$raw"
command -v lmp >/dev/null || { echo "LAMMPS (lmp) not found: scripts/deps.sh bench" >&2; exit 1; }
bonds=6964036 # 250,000 atoms x ~28 partners (LAMMPS prints bonds/atom = 27.8561)
stats() { sort -g | awk '{a[NR]=$1} END {printf "%.4g (%.4g-%.4g)", (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2), a[1], a[NR]}'; }
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

for p in 1 2; do
    : >"$out/cpd_$p" && : >"$out/eps_$p"
    for r in $(seq "$repeats"); do
        "$nspd" bench cpd --points 250000 --threads "$p" --steps "$steps" >"$out/cpd.json"
        sed -n 's/.*"bond_updates_per_s": \([0-9.e+]*\).*/\1/p' "$out/cpd.json" >>"$out/cpd_$p"
        cat "$out/cpd.json" >>"$raw"
        if [ "$p" -eq 1 ]; then
            OMP_NUM_THREADS=1 lmp -in "$here/lammps/plate_eps.in" -var steps "$steps" -log none -screen "$out/lammps.log" >/dev/null
        else
            OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np 2 lmp -in "$here/lammps/plate_eps.in" \
                -var steps "$steps" -log none -screen "$out/lammps.log" >/dev/null
        fi
        loop=$(grep "Loop time" "$out/lammps.log" | tail -1)
        echo "lammps peri/eps np=$p: $loop" >>"$raw"
        echo "$loop" | awk -v b=$bonds -v s=$steps '{print b * s / $4}' >>"$out/eps_$p"
    done
done
printf "%-16s %-8s %-34s %-12s %s\n" code workers "bond updates/s" "per core" "ratio nspd/LAMMPS"
for p in 1 2; do
    n=$(median <"$out/cpd_$p")
    l=$(median <"$out/eps_$p")
    printf "%-16s %-8s %-34s %-12.4g %.2f\n" "nspd cpd" "$p" "$(stats <"$out/cpd_$p")" "$(echo "$n $p" | awk '{print $1/$2}')" "$(echo "$n $l" | awk '{print $1/$2}')"
    printf "%-16s %-8s %-34s %-12.4g\n" "LAMMPS peri/eps" "$p" "$(stats <"$out/eps_$p")" "$(echo "$l $p" | awk '{print $1/$2}')"
done
echo "(medians of $repeats alternated runs, $steps steps each, min-max in brackets; raw: $raw)"
