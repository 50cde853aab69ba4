#!/bin/sh
# Two studies of the Ma 2, Re 300 cylinder behind docs/VALIDATION.md (not
# part of make validate; each part can be run alone):
#   scripts/cylinder_studies.sh sensitivity   # about 10 min on 2 cores
#   scripts/cylinder_studies.sh sequence      # about 75 min on 2 cores
#
# sensitivity: what the choices the paper leaves open are worth, at D/32 to
#   t = 30 (drag averaged over 24-30, as the case file does): the domain's
#   size, the wall's thermal condition, the CFL number.
# sequence: grid sequencing to D/256: D/32 from rest to t = 30, then each
#   finer grid started from the coarser one's last field (flow.initial.from)
#   and run 4 time units (D/256: 3), the drag averaged over the second half.
set -eu
nspd=${NSPD:-build/nspd}
out=out/studies
mkdir -p "$out"
. scripts/lib/cylinder.sh
export OMP_WAIT_POLICY=passive

sensitivity() {
    h=0.03125 # D/32, for the grids written out in full below
    cylinder_at 32 202 base32
    cylinder_summary "as the case file" base32
    # boundaries further out: 10 D more downstream, 6 D more on each side
    cylinder_at 32 202 xlong32 --set "flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: $h}, {length: 2.2, spacing: $h}, {length: 7.2, spacing_start: $h, spacing_end: 0.5}, {length: 10.0, spacing: 0.5}]"
    cylinder_summary "x to 20 D" xlong32
    cylinder_at 32 202 ywide32 --set "flow.grid.y.segments=[{length: 6.0, spacing: 0.5}, {length: 4.6, spacing_start: 0.5, spacing_end: $h}, {length: 2.8, spacing: $h}, {length: 4.6, spacing_start: $h, spacing_end: 0.5}, {length: 6.0, spacing: 0.5}]" \
        --set "flow.bodies.0.center=[2.0, 12.0]" --set "output.probes.0.at=[1.0, 12.0]"
    cylinder_summary "y over 24 D" ywide32
    # the wall at the free-stream temperature (R = 1: T = p / rho = 1 / gamma)
    cylinder_at 32 202 iso32 --set flow.bodies.0.wall=isothermal \
        --set flow.bodies.0.wall_temperature=0.7142857142857143
    cylinder_summary "isothermal wall at T_inf" iso32
    cylinder_at 32 202 cfl04_32 --set flow.numerics.cfl=0.4
    cylinder_summary "CFL 0.4" cfl04_32
}

# sequence_step N MARKERS DIR FROM END: D/N started from FROM (a .vtr), run
# to END, averaged over the second half.
sequence_step() {
    cylinder_at "$1" "$2" "$3" --set "flow.initial={from: $PWD/$4}" --set flow.soft_start=0 \
        --set time.end="$5" --set output.average_from="$(awk -v e="$5" 'BEGIN { print e / 2 }')" \
        --set output.field_interval=1.0
    cylinder_summary "D/$1 from $4" "$3"
}

sequence() {
    cylinder_at 32 202 seq32
    cylinder_summary "D/32 from rest" seq32
    sequence_step 64 404 seq64 "$out/seq32/flow_00015.vtr" 4.0
    sequence_step 128 808 seq128 "$out/seq64/flow_00004.vtr" 4.0
    sequence_step 256 1616 seq256 "$out/seq128/flow_00004.vtr" 3.0
}

case "${1:-}" in
sensitivity | sequence) "$1" | tee "$out/$1.txt" ;;
*)
    echo "usage: scripts/cylinder_studies.sh sensitivity|sequence" >&2
    exit 2
    ;;
esac
