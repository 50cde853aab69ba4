# The cylinder case file (cases/cylinder_ma2_re300.yaml) at fine spacing D/N
# with M markers (about two per cell); sourced by scripts/validate.sh and
# scripts/cylinder_studies.sh, which set $nspd and $out.
#   cylinder_at N M DIR [--set key=value ...]
cylinder_at() {
    h=$(awk -v n="$1" 'BEGIN { printf "%.10g", 1 / n }')
    markers=$2
    dir=$3
    shift 3
    "$nspd" run cases/cylinder_ma2_re300.yaml -o "$out/$dir" --force --quiet \
        --set "flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: $h}, {length: 2.2, spacing: $h}, {length: 7.2, spacing_start: $h, spacing_end: 0.5}]" \
        --set "flow.grid.y.segments=[{length: 4.6, spacing_start: 0.5, spacing_end: $h}, {length: 2.8, spacing: $h}, {length: 4.6, spacing_start: $h, spacing_end: 0.5}]" \
        --set flow.bodies.0.markers="$markers" "$@"
}

# The drag and its parts from DIR's summary.json, one line: LABEL cd ... .
cylinder_summary() {
    printf '%s:' "$1"
    sed -n 's/.*"\(cd\|cd_pressure\|cd_viscous\|cp_stagnation\|steps\|wall_s\)": \([^,]*\),*/ \1 \2/p' \
        "$out/$2/summary.json" | tr -d '\n'
    echo
}
