#!/bin/sh
# Golden outputs: every case under cases/ run at a reduced resolution, its
# user-visible outputs kept under tests/golden/data/<case>/ so that a change
# meant to move no number (a refactor) is checked bit for bit.
#
#   golden.sh record NSPD SOURCE_DIR            rewrite tests/golden/data (say why in the commit)
#   golden.sh check  NSPD SOURCE_DIR [THREADS]  run again and compare every file byte for byte
#
# Compared: case.yaml (with the source path written as SRC), history.csv, every
# CSV (probes, surfaces), the .pvd series, the last .vtu/.vtr of each series
# (the data arrays are raw binary in the appended block, so equal files are
# equal bits; kept gzipped, as the earlier ones feed the last), and
# summary.json without the keys that measure the machine (wall and part
# times, rates, threads, peak memory). PNGs are left out: they are pictures
# of the same arrays and would tie the golden set to the renderer.
set -u
mode=$1
nspd=$2
src=$3
threads=${4:-2}
data="$src/tests/golden/data"

# The bits depend on the instructions the compiler chose (-march=native: the
# SIMD width sets the lane order of the force sums), so the golden set holds
# for machines whose native target is the one it was recorded on. Elsewhere
# the check is skipped (exit 77), saying so, rather than failing on a
# difference no code change made.
signature=$(gcc -march=native -E -v - </dev/null 2>&1 | sed -n 's/.*cc1 .* - \(-march=.*\)/\1/p' |
    tr ' ' '\n' | grep -v -E '^-(dumpbase|quiet)' | sort | cksum | cut -d' ' -f1)
if [ "$mode" = check ] && [ "$(cat "$data/MACHINE" 2>/dev/null)" != "$signature" ]; then
    echo "SKIP: tests/golden/data was recorded for another native target (signature" \
        "$(cat "$data/MACHINE" 2>/dev/null) here $signature); re-record on this machine from a" \
        "commit known to be right: tests/golden/golden.sh record build/nspd ."
    exit 77
fi

# The runs: one line each, "case|override;override;...". The resolutions are
# the coarse ones the verify tests use, shortened so all of them take well
# under a minute on two cores.
runs() {
    cat <<'RUNS'
plate_crack|solid.spacing=5e-4;solid.thickness=5e-4;time.dt=6.6835e-8;solid.material.critical_stretch=0.02;solid.geometry=[{shape: rectangle, min: [-0.025, -0.0265], max: [0.025, 0.0265]}];output.probes.1.region=[{shape: rectangle, min: [-0.025, 0.0], max: [0.025, 5.0e-4]}];time.end=8.35e-6;output.field_interval=4.175e-6;output.history_interval=3.3417e-7
block_3d|solid.spacing=1e-3;time.end=2e-6;output.field_interval=1e-6;output.history_interval=2e-7
sod|flow.grid.x.segments=[{length: 1.0, cells: 100}];output.field_interval=0.1
lax|flow.grid.x.segments=[{length: 1.0, cells: 100}];output.field_interval=0.07
vortex|flow.grid.x.segments=[{length: 10.0, cells: 24}];flow.grid.y.segments=[{length: 10.0, cells: 24}];time.end=1.0;output.field_interval=0.5
couette|flow.grid.y.segments=[{length: 1.0, cells: 16}];time.end=2.0;output.field_interval=1.0
blasius|flow.grid.x.segments=[{length: 1.0, spacing_start: 0.2, spacing_end: 0.05}, {length: 1.0, spacing_start: 0.05, spacing_end: 0.1}];flow.grid.y.segments=[{length: 1.2, spacing_start: 0.01, spacing_end: 0.2}];time.end=0.5;output.field_interval=0.25
cylinder_ma2_re300|flow.grid.x.segments=[{length: 0.6, spacing_start: 0.08, spacing_end: 0.0625}, {length: 2.2, spacing: 0.0625}, {length: 7.2, spacing_start: 0.0625, spacing_end: 0.5}];flow.grid.y.segments=[{length: 4.6, spacing_start: 0.5, spacing_end: 0.0625}, {length: 2.8, spacing: 0.0625}, {length: 4.6, spacing_start: 0.0625, spacing_end: 0.5}];flow.bodies.0.markers=104;time.end=1.0;output.average_from=0.5;output.field_interval=0.5
naca0012_ma05_re5000|flow.grid.x.segments=[{length: 9.97, spacing_start: 0.5, spacing_end: 0.0625}, {length: 1.33, spacing: 0.0625}, {length: 18.7, spacing_start: 0.0625, spacing_end: 0.5}];flow.grid.y.segments=[{length: 9.7, spacing_start: 0.5, spacing_end: 0.0625}, {length: 0.6, spacing: 0.0625}, {length: 9.7, spacing_start: 0.0625, spacing_end: 0.5}];flow.bodies.0.markers=100;time.end=0.5;output.average_from=0.25;output.field_interval=0.25
panel_shock|solid.spacing=2.5e-4;solid.thickness=2.5e-4;solid.geometry=[{shape: rectangle, min: [0.1, -7.5e-4], max: [0.101, 0.05]}];flow.grid.x.segments=[{length: 0.095, spacing_start: 2.0e-3, spacing_end: 5.0e-4}, {length: 0.02, spacing: 5.0e-4}, {length: 0.185, spacing_start: 5.0e-4, spacing_end: 2.0e-3}];flow.grid.y.segments=[{length: 0.065, spacing: 2.0e-3}];time.end=2.0e-4;output.history_interval=2.0e-5;output.field_interval=1.0e-4
cylinder_crack_ma17|solid.spacing=0.025;flow.grid.x.segments=[{length: 1.3, spacing_start: 0.5, spacing_end: 0.0625}, {length: 1.4, spacing: 0.0625}, {length: 7.3, spacing_start: 0.0625, spacing_end: 0.5}];flow.grid.y.segments=[{length: 5.3, spacing_start: 0.5, spacing_end: 0.0625}, {length: 1.4, spacing: 0.0625}, {length: 5.3, spacing_start: 0.0625, spacing_end: 0.5}];time.end=2e-3;output.field_interval=1e-3;output.history_interval=2e-4
RUNS
}

# Runs one case into $2 with the overrides of its line ($1).
run_case() {
    line=$1
    out=$2
    name=${line%%|*}
    sets=${line#*|}
    set -- run "$src/cases/$name.yaml" -o "$out" --force --quiet --threads "$threads"
    old_ifs=$IFS
    IFS=';'
    for s in $sets; do set -- "$@" --set "$s"; done
    IFS=$old_ifs
    "$nspd" "$@" >/dev/null 2>"$out.err" || { cat "$out.err" >&2; return 1; }
}

# Keeps the files compared (see the header) and strips summary.json of the
# machine's measurements.
keep_comparable() {
    dir=$1
    find "$dir" -type f ! \( -name '*.csv' -o -name '*.vtu' -o -name '*.vtr' -o -name '*.pvd' \
        -o -name case.yaml -o -name summary.json \) -delete
    for series in solid flow; do
        last=$(ls "$dir" | grep "^${series}_[0-9]*\.vt[ru]$" | sort | tail -1)
        [ -n "$last" ] || continue
        for f in "$dir/${series}"_[0-9]*.vt[ru]; do [ "$(basename "$f")" = "$last" ] || rm "$f"; done
        gzip -n -9 "$dir/$last"
    done
    sed "s|$src|SRC|g" "$dir/case.yaml" >"$dir/case.tmp" && mv "$dir/case.tmp" "$dir/case.yaml"
    grep -v -E '"(wall_s|flow_s|solid_s|coupling_s|threads|peak_rss_mb|[a-z_]+_per_s)":' \
        "$dir/summary.json" >"$dir/summary.tmp" && mv "$dir/summary.tmp" "$dir/summary.json"
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
count=0
runs >"$work/runs"
while IFS= read -r line; do
    name=${line%%|*}
    count=$((count + 1))
    if ! run_case "$line" "$work/$name"; then
        echo "FAIL $name: the run failed"
        failures=$((failures + 1))
        continue
    fi
    keep_comparable "$work/$name"
    if [ "$mode" = record ]; then
        rm -rf "${data:?}/$name"
        mkdir -p "$data"
        cp -r "$work/$name" "$data/$name"
        echo "recorded $name: $(ls "$data/$name" | wc -l) files"
        continue
    fi
    bad=""
    for f in "$data/$name"/* "$work/$name"/*; do
        b=$(basename "$f")
        case "$b" in
        *.gz) # compare the data, not one gzip's encoding of it
            gzip -dc "$data/$name/$b" >"$work/want" 2>/dev/null &&
                gzip -dc "$work/$name/$b" >"$work/got" 2>/dev/null &&
                cmp -s "$work/want" "$work/got" || bad="$bad $b" ;;
        *) cmp -s "$data/$name/$b" "$work/$name/$b" || bad="$bad $b" ;;
        esac
    done
    if [ -n "$bad" ]; then
        echo "FAIL $name ($threads threads): differs from tests/golden/data/$name in$(echo "$bad" | tr ' ' '\n' | sort -u | tr '\n' ' ')"
        failures=$((failures + 1))
    fi
done <"$work/runs"
[ "$mode" = record ] && echo "$signature" >"$data/MACHINE"
echo "$((count - failures)) of $count cases as recorded ($mode, $threads threads)"
[ "$failures" -eq 0 ]
