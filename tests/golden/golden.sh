#!/bin/sh
# Golden outputs: every case under cases/ run at a reduced resolution, its
# user-visible outputs kept under tests/golden/data/<case>/ so that a change
# meant to move no number (a refactor) is checked bit for bit.
#
#   golden.sh record  NSPD SOURCE_DIR            rewrite tests/golden/data (say why in the commit)
#   golden.sh check   NSPD SOURCE_DIR [THREADS]  run again and compare every file byte for byte
#   golden.sh confirm NSPD SOURCE_DIR [THREADS]  check on a machine the data was not recorded
#                                                for, with a binary known to be right; if every
#                                                file matches, add this machine to MACHINE
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
src=$(cd "$3" && pwd) # absolute, as ctest passes it, so "." records the same files
threads=${4:-2}
data="$src/tests/golden/data"

# The bits depend on the instructions the compiler chose (-march=native: the
# SIMD width sets the lane order of reductions in the flow and correspondence
# kernels, fused multiply-adds their last bits), so the golden set holds
# for machines whose native target is the one it was recorded on. Elsewhere
# the check is skipped (exit 77), saying so, rather than failing on a
# difference no code change made.
signature=$(gcc -march=native -E -v - </dev/null 2>&1 | sed -n 's/.*cc1 .* - \(-march=.*\)/\1/p' |
    tr ' ' '\n' | grep -v -E '^-(dumpbase|quiet)' | sort | cksum | cut -d' ' -f1)
# MACHINE lists the signatures (one a line) on which the data was recorded or
# confirmed: two targets may well give the same bits.
if [ "$mode" = check ] && ! grep -qx "$signature" "$data/MACHINE" 2>/dev/null; then
    echo "SKIP: tests/golden/data was recorded for other native targets (signatures" \
        "$(tr '\n' ' ' <"$data/MACHINE" 2>/dev/null)here $signature); confirm it on this machine" \
        "with a build of a commit known to be right: tests/golden/golden.sh confirm build/nspd ."
    exit 77
fi

# The runs: tests/golden/runs.txt, one line each, "case|override;override;...".
# The resolutions are the coarse ones the verify tests use, shortened so all
# of them take well under a minute on two cores (tests/cli/test_resume.sh
# runs some of them too).

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
    # no pictures: they are not compared (above), and drawing them took
    # 60 % of the runs' time (24 s against 9.4 s a pass)
    set -- "$@" --set output.png=false --set output.plots=false
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
    # the path as a literal (a '.' in it is not "any character")
    src_re=$(printf '%s\n' "$src" | sed 's/[][\.*^$|]/\\&/g')
    sed "s|$src_re|SRC|g" "$dir/case.yaml" >"$dir/case.tmp" && mv "$dir/case.tmp" "$dir/case.yaml"
    grep -v -E '"(wall_s|flow_s|solid_s|coupling_s|setup_s|pressure_solve_s|threads|peak_rss_mb|[a-z_]+_per_s)":' \
        "$dir/summary.json" >"$dir/summary.tmp" && mv "$dir/summary.tmp" "$dir/summary.json"
}

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
count=0
cp "$src/tests/golden/runs.txt" "$work/runs"
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
if [ "$mode" = confirm ] && [ "$failures" -eq 0 ] && ! grep -qx "$signature" "$data/MACHINE"; then
    echo "$signature" >>"$data/MACHINE"
    echo "confirmed: this machine's signature $signature added to tests/golden/data/MACHINE"
fi
echo "$((count - failures)) of $count cases as recorded ($mode, $threads threads)"
[ "$failures" -eq 0 ]
