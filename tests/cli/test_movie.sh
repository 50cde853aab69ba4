# nspd movie: a run's picture series become H.264 MP4 movies (yuv420p, even
# sizes) with one frame per picture; --field picks one series; a missing
# directory, an unknown series or a single frame are refused with exit 2
# and nothing written.
#   usage: test_movie.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
if ! command -v ffmpeg >/dev/null || ! command -v ffprobe >/dev/null; then
    echo "SKIP: ffmpeg is not installed (scripts/deps.sh build installs it)"
    exit 77
fi
. "$src/tests/cli/common.sh"

# a coarse vortex: 6 outputs of two picture series
"$nspd" run "$src/cases/vortex.yaml" -o "$work/run" --quiet \
    --set "flow.grid.x.segments=[{length: 10.0, cells: 32}]" \
    --set "flow.grid.y.segments=[{length: 10.0, cells: 32}]" \
    --set time.end=1.0 --set output.field_interval=0.2 || fail "the run failed"
series=$(ls "$work/run" | sed -n 's/^\(.*\)_00000\.png$/\1/p')
[ -n "$series" ] && ok || fail "the run wrote no pictures"

"$nspd" movie "$work/run" >"$work/out" 2>&1 && ok || fail "movie: $(cat "$work/out")"
for s in $series; do
    frames=$(ls "$work/run" | grep -c "^${s}_[0-9]*\.png$")
    info=$(ffprobe -v error -select_streams v:0 -count_frames \
        -show_entries stream=codec_name,pix_fmt,nb_read_frames -of csv=p=0 "$work/run/$s.mp4" 2>&1)
    [ "$info" = "h264,yuv420p,$frames" ] && ok || fail "$s.mp4: '$info', expected h264,yuv420p,$frames"
done
ls "$work/run" | grep -q '\.part$' && fail "a .part file was left" || ok

# one series only, at another rate
first=$(echo "$series" | head -1)
rm -f "$work/run"/*.mp4
"$nspd" movie "$work/run" --field "$first" --fps 25 >/dev/null && ok || fail "--field $first"
[ "$(ls "$work/run" | grep -c '\.mp4$')" -eq 1 ] && [ -s "$work/run/$first.mp4" ] && ok ||
    fail "--field made $(ls "$work/run" | grep '\.mp4$')"

# refusals
"$nspd" movie "$work/none" 2>"$work/err"
[ $? -eq 2 ] && grep -q "cannot read" "$work/err" && ok || fail "missing directory: $(cat "$work/err")"
"$nspd" movie "$work/run" --field nothing 2>"$work/err"
[ $? -eq 2 ] && grep -q "no picture series nothing" "$work/err" && ok || fail "unknown series: $(cat "$work/err")"
mkdir "$work/one" && cp "$work/run/${first}_00000.png" "$work/one/"
"$nspd" movie "$work/one" --field "$first" 2>"$work/err"
[ $? -eq 2 ] && grep -q "expected at least 2" "$work/err" && ok || fail "one frame: $(cat "$work/err")"
[ -z "$(ls "$work/one" | grep -v png)" ] && ok || fail "a refused movie left $(ls "$work/one")"
"$nspd" movie "$work/run" --fps 0 2>/dev/null
[ $? -eq 2 ] && ok || fail "--fps 0 accepted"

finish
