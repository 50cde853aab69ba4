# nspd report: OUTDIR/report.html, one self-contained page (no network, no
# other file): the case name and description, the summary numbers, the last
# picture of every series and a chosen one, the movie, the timing and the
# resolved case. Every embedded picture and movie decodes to the bytes of
# its file. Then headless Chromium loads the page with no console error and
# no failed resource, its DOM holds every image and the movie, and it draws
# a screenshot (skipped, saying so, without Chromium; scripts/deps.sh build
# installs it). A directory that is not a run's is refused (exit 2) and no
# report is left.
#   usage: test_report.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

# the coupled panel, coarse (tests/golden/runs.txt): flow and solid pictures
golden_overrides panel_shock >"$work/overrides"
set -- run "$src/cases/panel_shock.yaml" -o "$work/run" --quiet
while IFS= read -r o; do set -- "$@" --set "$o"; done <"$work/overrides"
"$nspd" "$@" || fail "the run failed"
if command -v ffmpeg >/dev/null; then
    "$nspd" movie "$work/run" --field mach_damage >/dev/null || fail "movie"
fi
"$nspd" report "$work/run" --frame 1 >"$work/out" || fail "report: $(cat "$work/out")"
page=$work/run/report.html
[ -s "$page" ] && ok || fail "no report.html"
grep -q "<h1>panel_shock</h1>" "$page" && ok || fail "no case name"
grep -q "Shock on an elastic panel" "$page" && ok || fail "no description"
broken=$(sed -n 's/.*"broken_bonds": \([0-9]*\).*/\1/p' "$work/run/summary.json")
grep -q "<td>broken_bonds</td><td class=\"num\">$broken</td>" "$page" && ok ||
    fail "summary number broken_bonds = $broken not on the page"
grep -q "<td>time_s</td><td class=\"num\">[^<]*</td><td>s</td>" "$page" && ok || fail "no units"
grep -q "<details><summary>the resolved case" "$page" && ok || fail "no resolved case"
if grep -q -E '(src|href)="(https?:|//)' "$page"; then fail "the page reaches the network"; else ok; fi

# every history plot, and of every picture series output 1 and the last;
# each embedded image is its file
series=$(ls "$work/run" | sed -n 's/^\(.*\)_00000\.png$/\1/p')
plots=$(ls "$work/run" | grep -c '^history_.*\.png$')
[ "$plots" -gt 10 ] && ok || fail "the run drew $plots history plots"
want=$(($(echo "$series" | wc -l) * 2 + plots))
imgs=$(grep -o '<img alt="[^"]*" src="data:image/png;base64,[^"]*"' "$page")
[ "$(echo "$imgs" | grep -c .)" -eq "$want" ] && ok ||
    fail "$(echo "$imgs" | grep -c .) images, expected $want ($series)"
echo "$imgs" | while IFS= read -r img; do
    file=$(echo "$img" | sed 's/<img alt="\([^"]*\)".*/\1/')
    echo "$img" | sed 's/.*base64,//; s/"$//' | base64 -d >"$work/decoded" 2>/dev/null
    cmp -s "$work/decoded" "$work/run/$file" || echo "$file"
done >"$work/bad"
[ ! -s "$work/bad" ] && ok || fail "embedded images differ from their files: $(cat "$work/bad")"
if [ -f "$work/run/mach_damage.mp4" ]; then
    grep -o '<video[^>]*src="data:video/mp4;base64,[^"]*"' "$page" | sed 's/.*base64,//; s/"$//' |
        base64 -d >"$work/movie" 2>/dev/null
    cmp -s "$work/movie" "$work/run/mach_damage.mp4" && ok || fail "the embedded movie differs"
fi

# refusals
"$nspd" report "$work/none" 2>/dev/null
[ $? -eq 2 ] && ok || fail "missing directory accepted"
mkdir "$work/empty"
"$nspd" report "$work/empty" 2>"$work/err"
[ $? -eq 2 ] && grep -q "summary.json" "$work/err" && ok || fail "no summary.json: $(cat "$work/err")"
[ -z "$(ls "$work/empty")" ] && ok || fail "a refused report left $(ls "$work/empty")"

# a real browser
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "SKIP (browser part): Chromium is not installed (scripts/deps.sh build installs it)"
else
    flags="--headless --no-sandbox --disable-gpu --user-data-dir=$work/profile"
    timeout 120 "$browser" $flags --enable-logging=stderr --v=0 --virtual-time-budget=5000 \
        --dump-dom "file://$page" >"$work/dom" 2>"$work/console"
    grep -q "<h1>panel_shock</h1>" "$work/dom" && ok || fail "Chromium's DOM lacks the case name"
    [ "$(grep -o '<img ' "$work/dom" | wc -l)" -eq "$want" ] && ok || fail "Chromium's DOM: images"
    if [ -f "$work/run/mach_damage.mp4" ]; then
        grep -q "<video" "$work/dom" && ok || fail "Chromium's DOM has no video"
    fi
    if grep -E "CONSOLE|Failed to load resource|Uncaught|net::ERR" "$work/console"; then
        fail "Chromium reported the lines above"
    else ok; fi
    timeout 120 "$browser" $flags --hide-scrollbars --window-size=1280,2400 \
        --screenshot="$work/shot.png" "file://$page" 2>/dev/null
    [ "$(wc -c <"$work/shot.png" 2>/dev/null || echo 0)" -gt 20000 ] && ok ||
        fail "no screenshot (or a blank one)"
    [ -n "${NSPD_REPORT_SHOT:-}" ] && cp "$work/shot.png" "$NSPD_REPORT_SHOT"
fi

finish
