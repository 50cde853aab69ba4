#!/bin/sh
# The Re 10 confined cylinder's steady drag against the lattice and the
# PPE's divergence time tau (flow.divergence_time), behind the tau table of
# docs/VALIDATION.md (not part of make validate):
#   scripts/pddo_tau_study.sh          # about 14 min on 2 cores
#   scripts/pddo_tau_study.sh momentum # flow.wall_pressure: momentum, about 10 min
#   scripts/pddo_tau_study.sh local    # momentum and the patch's local horizon, about 7 min
# Prints one line a run: dx, tau, dt, the drag and its parts (N/m), the
# largest |div u| over the fluid nodes (1/s) and the wall time.
# tau ~ dx^2 is the paper's scheme at dt = tau (0.4 of each lattice's
# diffusive limit); tau held at 1.6e-3 s runs dx 0.025 m at the stable
# dt 4e-4 s (the steady state does not depend on dt once tau is given).
set -eu
nspd=${NSPD:-build/nspd}
out=out/pddo_tau
mkdir -p "$out"
export OMP_WAIT_POLICY=passive

run() { # dx tau dt [wall_pressure [horizon]]
    wp=${4:-zero_gradient}
    horizon=${5:-lattice}
    dir="$out/dx$1_tau$2_$wp"
    [ "$horizon" = lattice ] || dir="${dir}_$horizon"
    "$nspd" run cases/cylinder_confined_re10.yaml --threads 2 --quiet --force -o "$dir" \
        --set flow.spacing="$1" --set flow.divergence_time="$2" --set time.dt="$3" \
        --set flow.wall_pressure="$wp" \
        --set "flow.bodies=[{shape: circle, center: [5.0, 3.0], radius: 0.5, patch_radius: 2.01, horizon: $horizon}]" \
        --set flow.walls=antisymmetric --set flow.divergence_term=updated \
        --set flow.steady_tolerance=1e-4 --set output.png=false --set output.plots=false
    printf 'dx %s tau %s dt %s %s %s:' "$1" "$2" "$3" "$wp" "$horizon"
    sed -n 's/.*"\(drag_n\|drag_pressure_n\|drag_viscous_n\|div_max_per_s\|wall_s\)": \([^,]*\),*/ \1 \2/p' \
        "$dir/summary.json" | tr -d '\n'
    echo
}

if [ "${1:-}" = local ]; then
    # the patch's local horizon (bodies[].horizon), tau = dt = 4e-4 s
    for dx in 0.1 0.05 0.025; do run $dx 4e-4 4e-4 momentum local; done
    exit 0
fi

if [ "${1:-}" = momentum ]; then
    # the momentum equation's wall pressure: tau = dt = 4e-4 s on every
    # lattice, and tau 1.6e-3 s on the two coarser ones
    for dx in 0.1 0.05 0.025; do run $dx 4e-4 4e-4 momentum; done
    run 0.1 1.6e-3 4e-4 momentum
    run 0.05 1.6e-3 4e-4 momentum
    exit 0
fi

# tau ~ dx^2 (0.64 dx^2 s/m^2)
run 0.1 6.4e-3 6.4e-3
run 0.05 1.6e-3 1.6e-3
run 0.025 4e-4 4e-4
# tau held
run 0.1 1.6e-3 1.6e-3
run 0.025 1.6e-3 4e-4
run 0.1 4e-4 4e-4
# the same tau at a quarter of the step: the same steady state
run 0.1 4e-4 1e-4
