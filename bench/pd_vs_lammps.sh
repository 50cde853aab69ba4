#!/bin/sh
# PD throughput: nspd against LAMMPS peri/pmb on the same plate, side by side.
#   bench/pd_vs_lammps.sh [NSPD] [REPEATS]
# For 1 and 2 threads/processes, runs each code REPEATS times (default 5)
# alternately, takes the median bond updates per second (a bond counted once
# from each end, as LAMMPS' PMB loop counts partners), and prints a table.
# Raw results go to bench/results/pd_vs_lammps.txt.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
nspd=${1:-$here/../build/nspd}
repeats=${2:-5}
steps=100
out=$here/results
mkdir -p "$out"
raw=$out/pd_vs_lammps.txt
: >"$raw"
command -v lmp >/dev/null || { echo "LAMMPS (lmp) not found: scripts/deps.sh bench" >&2; exit 1; }
bonds=6964036 # 250,000 points x ~28 partners, the same in both codes
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }

for p in 1 2; do
    : >"$out/nspd_$p" && : >"$out/lammps_$p"
    for r in $(seq "$repeats"); do
        "$nspd" bench pd --points 250000 --threads "$p" --steps "$steps" >"$out/nspd.json"
        sed -n 's/.*"bond_updates_per_s": \([0-9.e+]*\).*/\1/p' "$out/nspd.json" >>"$out/nspd_$p"
        cat "$out/nspd.json" >>"$raw"
        if [ "$p" -eq 1 ]; then
            OMP_NUM_THREADS=1 lmp -in "$here/lammps/plate_pmb.in" -var steps "$steps" -log none -screen "$out/lammps.log" >/dev/null
        else
            OMP_NUM_THREADS=1 mpirun --allow-run-as-root --oversubscribe -np 2 lmp -in "$here/lammps/plate_pmb.in" \
                -var steps "$steps" -log none -screen "$out/lammps.log" >/dev/null
        fi
        loop=$(grep "Loop time" "$out/lammps.log" | tail -1)
        echo "lammps np=$p: $loop" >>"$raw"
        echo "$loop" | awk -v b=$bonds -v s=$steps '{print b * s / $4}' >>"$out/lammps_$p"
    done
done
printf "%-10s %-8s %-22s %-22s %s\n" code workers "bond updates/s" "per core" "ratio nspd/LAMMPS"
for p in 1 2; do
    n=$(median <"$out/nspd_$p")
    l=$(median <"$out/lammps_$p")
    printf "%-10s %-8s %-22.4g %-22.4g %.1f\n" nspd "$p" "$n" "$(echo "$n $p" | awk '{print $1/$2}')" "$(echo "$n $l" | awk '{print $1/$2}')"
    printf "%-10s %-8s %-22.4g %-22.4g\n" LAMMPS "$p" "$l" "$(echo "$l $p" | awk '{print $1/$2}')"
done
echo "(medians of $repeats runs, $steps steps each; raw: $raw)"
