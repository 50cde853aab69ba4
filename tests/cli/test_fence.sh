#!/bin/sh
# The include fence (CMakeLists.txt nspd_module, docs/STYLE.md): every
# library is compiled against build/layers/<library>/, which holds only the
# headers of the folders it may use. For each rule, a one-line translation
# unit that includes a forbidden header is compiled against the library's
# layer and must fail with "No such file or directory"; the same header is
# checked to exist in src/ (so a rename cannot make a rule vacuous), and an
# allowed header of the library is checked to be found (so a missing layer
# cannot either).
#   usage: test_fence.sh NSPD SOURCE_DIR   (run in the build directory)
set -u
src=$2
layers=$(pwd)/layers
cc=${CC:-cc}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
count=0

# preprocess only: which headers are found is all the fence decides
found() { # layer header
    printf '#include "%s"\n' "$2" >"$work/tu.c"
    "$cc" -E -I "$layers/$1" "$work/tu.c" -o /dev/null 2>"$work/err"
}

# layer, an allowed header, then the forbidden ones
rule() {
    layer=$1
    allowed=$2
    shift 2
    if [ ! -d "$layers/$layer" ]; then
        echo "FAIL $layer: no layer $layers/$layer"
        failures=$((failures + 1))
        return
    fi
    if ! found "$layer" "$allowed"; then
        echo "FAIL $layer: its allowed header $allowed is not found:"
        cat "$work/err"
        failures=$((failures + 1))
    fi
    for header in "$@"; do
        count=$((count + 1))
        if [ ! -f "$src/src/$header" ]; then
            echo "FAIL $layer: the rule names $header, which is not in src/"
            failures=$((failures + 1))
        elif found "$layer" "$header"; then
            echo "FAIL $layer may include $header"
            failures=$((failures + 1))
        elif ! grep -q "No such file or directory" "$work/err"; then
            echo "FAIL $layer: including $header fails otherwise:"
            cat "$work/err"
            failures=$((failures + 1))
        fi
    done
}

# the layers between modules
rule nspd_core core/status.h flow/flow.h solid/solid.h io/json.h sim/sim.h
rule nspd_io io/json.h flow/flow.h solid/solid.h couple/coupling.h sim/sim.h
rule nspd_flow flow/flow.h solid/solid.h couple/coupling.h io/json.h sim/sim.h
rule nspd_solid solid/solid.h flow/flow.h couple/coupling.h io/json.h
rule nspd_couple couple/coupling.h sim/sim.h io/json.h
rule nspd_sim sim/sim.h case/case_read.h
# an interface sees none of its models
rule nspd_flow flow/riemann_exact.h flow/gks/solver.h flow/gks/model.h flow/pddo/model.h \
    flow/iga/model.h
rule nspd_solid solid/solid.h solid/pd/config.h solid/bond/model.h solid/correspondence/model.h
rule nspd_couple flow/flow.h couple/ghost/model.h couple/penalty/model.h flow/gks/model.h \
    solid/pd/surface.h
# the models see their interface and shared part, not each other
rule nspd_flow_gks flow/gks/solver.h flow/pddo/cloud.h flow/pddo/model.h solid/solid.h \
    flow/iga/model.h
rule nspd_flow_pddo flow/pddo/model.h flow/gks/grid.h flow/gks/model.h solid/solid.h \
    flow/iga/space.h
rule nspd_flow_iga flow/iga/model.h flow/gks/grid.h flow/gks/model.h flow/pddo/model.h \
    solid/solid.h couple/coupling.h
rule nspd_solid_pd solid/pd/lattice.h solid/bond/body.h solid/correspondence/body.h flow/flow.h
rule nspd_solid_bond solid/pd/regions.h solid/correspondence/body.h solid/correspondence/j2_kernel.h
rule nspd_solid_correspondence solid/pd/regions.h solid/bond/body.h solid/bond/force_kernel.h
rule nspd_couple_ghost flow/gks/model.h flow/pddo/model.h solid/bond/model.h \
    solid/correspondence/model.h sim/sim.h couple/penalty/model.h
# the penalty coupling works through the interfaces only: no flow's or
# solid's own header, not even the PD lattice's
rule nspd_couple_penalty couple/penalty/relax.h flow/gks/model.h flow/gks/grid.h \
    flow/pddo/model.h flow/iga/model.h solid/pd/config.h solid/bond/model.h solid/correspondence/model.h \
    couple/ghost/model.h sim/sim.h
# the driver, its output and the command name no model
rule nspd_sim solid/solid.h flow/gks/model.h flow/gks/grid.h flow/pddo/model.h flow/iga/model.h \
    solid/pd/config.h \
    solid/bond/model.h solid/correspondence/model.h couple/ghost/model.h couple/penalty/model.h
rule nspd app/commands.h flow/gks/solver.h flow/pddo/model.h solid/pd/config.h \
    solid/bond/body.h solid/correspondence/body.h couple/ghost/model.h couple/penalty/relax.h

echo "$count forbidden includes refused"
[ "$failures" -eq 0 ]
