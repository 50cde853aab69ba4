#!/bin/sh
# The command's help (app/help.c, issue 61): `nspd CMD --help` and `-h`
# print CMD's usage on stdout and exit 0 for every command `nspd --help`
# lists, from the same strings (the synopsis of CMD --help is a line of
# nspd --help); every benchmark a model or cmd_bench.c has is listed and
# runs; a usage error still exits 2 with the synopsis on stderr.
#   usage: test_usage.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

"$nspd" --help >"$work/main" 2>"$work/main.err" && ok || fail "nspd --help exit $?"
[ -s "$work/main.err" ] && fail "nspd --help wrote to stderr" || ok
commands=$(sed -n 's/^  \([a-z]\{1,\}\)\( .*\)\{0,1\}$/\1/p' "$work/main" | sort -u)
[ "$(echo "$commands" | wc -l)" -ge 10 ] && ok || fail "nspd --help lists: $commands"
for c in $commands run check info bench movie plot report riemann radial version; do
    for h in --help -h; do
        "$nspd" "$c" "$h" >"$work/out" 2>"$work/err"
        status=$?
        if [ "$status" -ne 0 ] || [ -s "$work/err" ]; then
            fail "nspd $c $h: exit $status, stderr: $(cat "$work/err")"
        elif ! head -n 1 "$work/out" | grep -q "^usage: nspd $c\\b"; then
            fail "nspd $c $h: $(head -n 1 "$work/out")"
        else
            ok
        fi
    done
    # one text: the first synopsis line is the one the main help lists
    first=$(head -n 1 "$work/out" | sed 's/^usage: nspd //')
    awk -v f="  $first" '$0 == f || index($0, f "  ") == 1 { found = 1 } END { exit !found }' \
        "$work/main" && ok || fail "nspd $c --help's '$first' is not in nspd --help"
done
# --help after other arguments, not a --set value
"$nspd" run "$src/cases/sod.yaml" --set name=x --help >"$work/out" 2>&1 &&
    grep -q "^usage: nspd run" "$work/out" && ok || fail "nspd run CASE --help: $(head -n 2 "$work/out")"
"$nspd" check "$src/cases/sod.yaml" --set name=-h >"$work/out" 2>&1 &&
    grep -q ": ok" "$work/out" && ok || fail "a --set value -h taken for help: $(head -n 2 "$work/out")"
"$nspd" help info | head -n 1 | grep -q "^usage: nspd info" && ok || fail "nspd help info"

# every benchmark: the models' (bench_name in their ops tables) and the
# machine's (cmd_bench.c), listed in nspd --help and runnable
benches=$( (grep -rhoE '\.bench_name = "[a-z0-9_]+"' "$src/src" | sed 's/.*"\(.*\)"/\1/'
    grep -oE 'strcmp\(argv\[0\], "[a-z0-9_]+"\)' "$src/src/app/cmd_bench.c" |
        sed 's/.*"\(.*\)".*/\1/') | sort -u)
[ "$(echo "$benches" | wc -l)" -ge 5 ] && ok || fail "benchmarks found in the source: $benches"
for b in $benches; do
    grep -q "^  bench $b " "$work/main" && ok || fail "nspd --help does not list bench $b"
    "$nspd" bench "$b" --points 2000 --steps 1 --threads 1 >"$work/out" 2>"$work/err" &&
        grep -q '^{' "$work/out" && ok || fail "nspd bench $b: $(cat "$work/err")"
done

# usage errors: exit 2, the message and the synopsis on stderr, nothing on stdout
for args in "run" "run x.yaml --fast" "plot" "movie" "report" "bench" "riemann --wind 1" \
    "radial --wind 1"; do
    # shellcheck disable=SC2086 # args are words
    "$nspd" $args >"$work/out" 2>"$work/err"
    status=$?
    c=${args%% *}
    if [ "$status" -eq 2 ] && [ ! -s "$work/out" ] && grep -q "^usage: nspd $c" "$work/err"; then
        ok
    else
        fail "nspd $args: exit $status, stderr: $(cat "$work/err")"
    fi
done
finish
