#!/bin/sh
# Two nspd binaries side by side, alternating run by run so that both see
# the same machine: bench pd, bench gks (one thread) and one coupled case
# (the cylinder crack at the demo's resolution, 4 ms, no field output).
# Prints the median of N runs of each and the ratio new/old.
#   bench/old_vs_new.sh OLD_NSPD NEW_NSPD [N=5]
set -eu
old=$1
new=$2
runs=${3:-5}
here=$(cd "$(dirname "$0")" && pwd)
src=$here/..
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR%2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2)}'; }
field() { sed -n "s/.*\"$1\": \\([0-9.e+-]*\\).*/\\1/p"; }

h=0.015625
coupled() {
    "$1" run "$src/cases/cylinder_crack_ma17.yaml" -o "$work/run" --force --quiet --threads 1 \
        --set solid.spacing=0.01 --set time.end=4e-3 --set output.field_interval=1 \
        --set output.vtk=false --set output.png=false \
        --set flow.grid.x.segments.0.spacing_end=$h --set flow.grid.x.segments.1.spacing=$h \
        --set flow.grid.x.segments.2.spacing_start=$h \
        --set flow.grid.y.segments.0.spacing_end=$h --set flow.grid.y.segments.1.spacing=$h \
        --set flow.grid.y.segments.2.spacing_start=$h
    field wall_s <"$work/run/summary.json"
}

for r in $(seq "$runs"); do
    for which in old new; do
        eval bin=\$$which
        "$bin" bench pd --threads 1 | field bond_updates_per_s >>"$work/pd_$which"
        "$bin" bench gks --threads 1 | field cell_updates_per_s >>"$work/gks_$which"
        coupled "$bin" >>"$work/coupled_$which"
    done
done
printf "%-34s %14s %14s %8s\n" "median of $runs" old new new/old
for b in pd gks coupled; do
    o=$(median <"$work/${b}_old")
    n=$(median <"$work/${b}_new")
    case $b in
    pd) what="bench pd: bond updates/s" ;;
    gks) what="bench gks: cell updates/s" ;;
    coupled) what="cylinder crack 4 ms: wall s" ;;
    esac
    printf "%-34s %14.5g %14.5g %8.4f\n" "$what" "$o" "$n" "$(echo "$n $o" | awk '{print $1/$2}')"
done
