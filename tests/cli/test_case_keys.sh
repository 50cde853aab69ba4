#!/bin/sh
# docs/CASES.md has a table row (| `key` | ...) for every key of these
# maps, in the map's own section (from its heading to the next): the keys
# come from nspd itself, the "expected one of:" list an
# unknown key is refused with (every key the reader asks of the map), so a
# key added to a reader without its row fails here (issue 61: coupling and
# flow.initial.regions had none).
#   usage: test_case_keys.sh NSPD SOURCE_DIR
set -u
nspd=$1
src=$2
. "$src/tests/cli/common.sh"

while IFS='|' read -r case map heading; do
    keys=$("$nspd" check "$src/cases/$case" --set "$map.zz_not_a_key=1" 2>&1 |
        sed -n 's/.*unknown key; expected one of: //p' | tr -d ',')
    if [ -z "$keys" ]; then
        fail "$case: no key list for $map"
        continue
    fi
    awk -v h="$heading" '$0 == h { on = 1; next } on && /^#/ { exit } on' \
        "$src/docs/CASES.md" >"$work/section"
    [ -s "$work/section" ] || fail "docs/CASES.md has no section '$heading'"
    for k in $keys; do
        grep -q "^| \`$k\` |" "$work/section" && ok ||
            fail "docs/CASES.md's '$heading' has no row for $map.$k"
    done
done <<LIST
chamber_detonation.yaml|coupling|### coupling (kind: penalty)
blast_hollow_cylinder.yaml|coupling|### coupling (kind: penalty)
panel_shock.yaml|coupling|## coupling
chamber_detonation.yaml|flow.initial|### flow.initial
chamber_detonation.yaml|flow.initial.regions[0]|#### flow.initial.regions
sod.yaml|time|## time
sod.yaml|output|## output
sod.yaml|flow.gas|### flow.gas
sod.yaml|flow.numerics|### flow.numerics
plate_crack.yaml|solid|## solid
plate_crack.yaml|solid.material|### solid.material
blast_hollow_cylinder.yaml|solid.lattice|#### solid (correspondence) lattice
plate_hole_inp.yaml|solid.lattice|#### solid (correspondence) lattice
plate_hole_inp.yaml|solid.boundaries[0]|### solid.boundaries
LIST
finish
