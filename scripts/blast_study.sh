#!/bin/sh
# The three blast experiments of paper 003 (chamber, hollow square, hollow
# cylinder) on both gas backgrounds (gks, iga) with weak and strong
# coupling, at one of the paper's meshes; one table row per run and the
# chamber's and the rings' pressure histories plotted side by side.
#   scripts/blast_study.sh NSPD LEVEL [CASES] [THREADS]
# LEVEL: coarse, medium or fine (the meshes of the case files' headers);
# CASES: a space-separated subset of "chamber square cylinder" (default all).
# Results under out/blast_study/LEVEL/, the table in
# out/blast_study/LEVEL/table_CASES.txt (one per invocation, so that the
# cases of a level can run side by side), plots in
# docs/img/blast_*_LEVEL.png.
# REUSE=1 in the environment keeps the runs that completed (their
# summary.json says so) and only tabulates and plots them.
# BACKGROUNDS (default "gks iga") and COUPLINGS (default "weak strong";
# "damaged" is the weak coupling with the damaged penalty, Eq. 23;
# "sealed" the weak coupling with sealed faces, coupling.seal, GKS only;
# "betaB" the weak coupling with beta = B, e.g. beta0.333333 beta3 beta9) in
# the environment choose the runs. The background "igal" is the isogeometric
# flow's limited step (flow.iga.limiter: convex, inviscid: issue 57).
# STEPS (default "paper"): the paper's time steps (issue 60: the weak
# couplings at C_pen's step, the strong one at 8 (chamber) or 4 times it,
# constrained at every step); "cfl": the flow's CFL step, the strong
# coupling slaved once per flow step (strong_constraint: flow_step), the
# runs of before issue 60.
set -eu
nspd=${1:-build/nspd}
level=${2:-coarse}
cases=${3:-chamber square cylinder}
threads=${4:-1}
out=out/blast_study/$level
[ "${STEPS:-paper}" = paper ] || out=out/blast_study/${level}_$STEPS
mkdir -p "$out" docs/img

# mesh CASE: the --set overrides of LEVEL (solid spacing, gas spacing,
# C_pen's h and dt), from the case files' headers
mesh() {
    case "$1:$level" in
    *:coarse) echo "" ;;
    chamber:medium) echo "3.3333333e-3 0.01 6.25e-8" ;;
    chamber:fine) echo "1.6666667e-3 0.005 3.125e-8" ;;
    square:medium) echo "1.5e-3 6.0e-3 7.5e-8" ;;
    square:fine) echo "1.0e-3 4.0e-3 5.0e-8" ;;
    cylinder:medium) echo "1.5e-3 4.5e-3 7.5e-8" ;;
    cylinder:fine) echo "1.0e-3 3.0e-3 5.0e-8" ;;
    *) echo "blast_study.sh: unknown case or level '$1:$level'" >&2; exit 2 ;;
    esac
}

# weak_dt CASE: the paper's weak-coupling step at LEVEL (C_pen's dt), s
weak_dt() {
    case "$1:$level" in
    chamber:coarse) echo 1.25e-7 ;;
    chamber:medium) echo 6.25e-8 ;;
    chamber:fine) echo 3.125e-8 ;;
    *:coarse) echo 1.0e-7 ;;
    *:medium) echo 7.5e-8 ;;
    *:fine) echo 5.0e-8 ;;
    esac
}

file_of() {
    case "$1" in
    chamber) echo cases/chamber_detonation.yaml ;;
    square) echo cases/blast_hollow_square.yaml ;;
    cylinder) echo cases/blast_hollow_cylinder.yaml ;;
    esac
}

# key FILE NAME: a number from summary.json
key() { sed -n "s/.*\"$2\": \([^,]*\),*/\1/p" "$1" | head -1; }
# fmt FORMAT VALUE [SCALE]: the value scaled and formatted, "-" if absent
fmt() { echo "$2" | awk -v f="$1" -v m="${3:-1}" '{ if ($0 == "" || $0 == "null") print "-"; else printf f "\n", m * $1 }'; }

table=$out/table_$(echo $cases | tr ' ' _).txt
[ -n "${BACKGROUNDS:-}${COUPLINGS:-}" ] &&
    table=$out/table_$(echo $cases ${BACKGROUNDS:-} ${COUPLINGS:-} | tr ' ' _).txt
printf '%-8s %-4s %-7s %6s %8s %7s %10s %8s %7s %9s %11s %8s %9s %7s %5s %8s %11s\n' case bg coupl steps \
    wall_s flow_s mean_p_Pa F_max_N impulse com_dx_mm corners_um broken mass_loss partly frag eps_p \
    onset_c/f_us >"$table"
for c in $cases; do
    set -- $(mesh "$c")
    over=""
    if [ $# -eq 3 ]; then
        over="--set solid.spacing=$1 --set flow.grid.x.segments.0.spacing=$2 \
--set flow.grid.y.segments.0.spacing=$2 --set coupling.h=$2 --set coupling.dt=$3"
    fi
    for bg in ${BACKGROUNDS:-gks iga}; do
        for coupling in ${COUPLINGS:-weak strong}; do
            dir=$out/${c}_${bg}_$coupling
            strong=false damaged=false seal=false beta=1
            case "$coupling" in beta*) beta=${coupling#beta} ;; esac
            [ "$coupling" = strong ] && strong=true
            [ "$coupling" = damaged ] && damaged=true
            [ "$coupling" = sealed ] && seal=true
            # the limited step's settings as words that keep their spaces
            method=$bg
            set --
            if [ "$bg" = igal ]; then
                method=iga
                set -- --set flow.iga.limiter=convex --set "flow.gas.viscosity={law: none}"
            fi
            # the step: the paper's (the strong one 8 or 4 times the weak)
            # or the CFL step with the slaving of before issue 60
            step="--set time.dt=stable --set coupling.strong_constraint=flow_step"
            if [ "${STEPS:-paper}" = paper ]; then
                factor=1
                [ "$coupling" = strong ] && factor=4
                [ "$coupling:$c" = strong:chamber ] && factor=8
                step="--set time.dt=$(awk -v a="$(weak_dt "$c")" -v f=$factor 'BEGIN { printf "%.6g", a * f }')"
            fi
            echo "== $c, $level, $bg, $coupling, ${STEPS:-paper} steps"
            [ "${REUSE:-0}" = 1 ] && grep -q '"completed": true' "$dir/summary.json" 2>/dev/null ||
            # shellcheck disable=SC2086
            "$nspd" run "$(file_of "$c")" -o "$dir" --force --quiet --threads "$threads" \
                --set flow.method=$method --set coupling.strong=$strong \
                --set coupling.damaged=$damaged --set coupling.seal=$seal --set coupling.beta=$beta \
                $over $step "$@"
            s=$dir/summary.json
            impulse=- corners=- onset=-
            if [ "$c" = chamber ]; then
                impulse=$(awk -f scripts/lib/first_pulse.awk "$dir/history.csv")
                corners=$(awk -f scripts/lib/corner_distortion.awk "$dir/history.csv" | tr ' ' /)
            fi
            # the square's first damage at its interior corners and mid-faces
            [ "$c" = square ] && onset="$(fmt %.1f "$(key "$s" corner_damage_onset_s)" 1e6)/$(fmt %.1f \
                "$(key "$s" face_damage_onset_s)" 1e6)"
            printf '%-8s %-4s %-7s %6s %8s %7s %10s %8s %7s %9s %11s %8s %9s %7s %5s %8s %11s\n' \
                "$c" "$bg" "$coupling" \
                "$(key "$s" steps)" "$(fmt %.1f "$(key "$s" wall_s)")" "$(fmt %.2f "$(key "$s" flow_s)")" \
                "$(fmt %.1f "$(key "$s" mean_pressure_pa)")" "$(fmt %.0f "$(key "$s" penalty_force_x_max_n)")" \
                "$impulse" "$(fmt %.3f "$(key "$s" com_dx_m)" 1e3)" "$corners" \
                "$(fmt %.4f "$(key "$s" broken_bond_fraction)")" \
                "$(fmt %.4f "$(key "$s" mass_loss)")" "$(fmt %.4f "$(key "$s" partly_damaged_fraction)")" \
                "$(key "$s" fragment_count)" "$(fmt %.4f "$(key "$s" max_plastic_strain)")" "$onset" >>"$table"
        done
    done
    # the probe's pressure on both backgrounds, weak and strong
    probe=centre
    [ "$c" = chamber ] && probe=right_wall
    # (the plot is of the gks and iga runs: not drawn for another choice)
    if [ -z "${BACKGROUNDS:-}" ]; then
        gnuplot -e "dir='$out'; name='$c'; probe='$probe'; level='$level'; \
outfile='docs/img/blast_${c}_$level.png'" scripts/plots/blast_study.gp
    fi
done
cat "$table"
