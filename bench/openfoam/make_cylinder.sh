#!/bin/sh
# Writes an OpenFOAM icoFoam case: the confined cylinder of
# cases/cylinder_confined_re10.yaml (paper 002 Sec. 5.3). A 15 m x 6 m
# channel, nu = mu/rho = 1 m^2/s (rho = 1: OpenFOAM's kinematic pressure is
# the pressure in Pa), uniform inflow 10 m/s at x = 0, no-slip walls y = 0
# and y = 6, p = 0 at the outlet x = 15, a cylinder of D = 1 m at (5, 3).
# One cell 1 m thick in z (empty front and back), so the forces function
# object gives N per metre of span.
#
# Mesh (blockMesh, 12 blocks): the channel cut at x = 4, 6 and y = 2, 4 into
# 3 x 3 blocks of square cells of side H = 2/NT; the middle one, the 2 m box
# round the cylinder, is an O-grid of four blocks, each a quarter of the
# cylinder (NT cells along it) and NR = NT/2 cells from the box to the
# wall, shrinking 4-fold towards the wall (the first cell about H/4 thick).
#
#   make_cylinder.sh DIR NT DT [END] [NU] [U0] [EVERY] [TOL]
# (END 4 s, the paper's; NU 1, U0 10: Re 10; U0 100 is Re 100). With TOL
# the run stops before END at steady state by nspd's criterion
# (flow.steady_tolerance), as make_cavity.sh does: the largest |dU/dt| over
# the cells below TOL m/s^2.
# Sampled after the run (postProcess -func sample -latestTime), cellPoint:
# p in front (4.5, 3), beside (5, 3.5), |u| at (5, 4.2), (5, 1.8) and at the
# outlet (15, 3) (just inside each boundary); the cylinder's face pressures
# by `postProcess -func wallSample -latestTime` (postProcessing/wallSample/
# TIME/p_cylinder.raw: x y z p a face); the forces function object
# writes drag and lift on the cylinder every EVERY steps (default 50).
set -eu
dir=$1
nt=$2
dt=$3
end=${4:-4}
nu=${5:-1}
u0=${6:-10}
every=${7:-50}
tol=${8:-}
nr=$((nt / 2))
mkdir -p "$dir/system" "$dir/constant" "$dir/0"
header() { # class object
    printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n' "$1" "$2"
}
# cells per block edge at the cell side H = 2/NT of the box edge
cells() { awk -v len="$1" -v nt="$nt" 'BEGIN { n = len * nt / 2; printf "%d", n < 1 ? 1 : n + 0.5 }'; }
nx0=$(cells 4)
nx2=$(cells 9)
ny=$(cells 2)
{
    header dictionary blockMeshDict
    # vertices 0-15: the 4 x 4 corners of the channel blocks, i + 4 j at
    # x = (0, 4, 6, 15)[i], y = (0, 2, 4, 6)[j]; 16-19: the cylinder at 225,
    # 315, 45 and 135 degrees; 20-39 the same at z = 1
    awk 'BEGIN {
        split("0 4 6 15", x, " "); split("0 2 4 6", y, " "); a = 0.5 / sqrt(2)
        cx[1] = 5 - a; cy[1] = 3 - a; cx[2] = 5 + a; cy[2] = 3 - a
        cx[3] = 5 + a; cy[3] = 3 + a; cx[4] = 5 - a; cy[4] = 3 + a
        print "convertToMeters 1;"; print "vertices"; print "("
        for (z = 0; z <= 1; z++) {
            for (j = 1; j <= 4; j++) for (i = 1; i <= 4; i++) printf "    (%s %s %d)\n", x[i], y[j], z
            for (k = 1; k <= 4; k++) printf "    (%.12g %.12g %d)\n", cx[k], cy[k], z
        }
        print ");" }'
    # hex (a b c d) at z = 0, counter-clockwise, and the same + 20 at z = 1
    hex() { # a b c d nx ny grading
        echo "    hex ($1 $2 $3 $4 $(($1 + 20)) $(($2 + 20)) $(($3 + 20)) $(($4 + 20))) ($5 $6 1) simpleGrading ($7 1)"
    }
    echo "blocks"
    echo "("
    hex 0 1 5 4 "$nx0" "$ny" "1 1"
    hex 1 2 6 5 "$nt" "$ny" "1 1"
    hex 2 3 7 6 "$nx2" "$ny" "1 1"
    hex 4 5 9 8 "$nx0" "$nt" "1 1"
    hex 6 7 11 10 "$nx2" "$nt" "1 1"
    hex 8 9 13 12 "$nx0" "$ny" "1 1"
    hex 9 10 14 13 "$nt" "$ny" "1 1"
    hex 10 11 15 14 "$nx2" "$ny" "1 1"
    # the O-grid: first direction along the box edge, second inwards
    hex 5 6 17 16 "$nt" "$nr" "1 0.25"
    hex 6 10 18 17 "$nt" "$nr" "1 0.25"
    hex 10 9 19 18 "$nt" "$nr" "1 0.25"
    hex 9 5 16 19 "$nt" "$nr" "1 0.25"
    echo ");"
    cat <<'EOT'
edges
(
    arc 16 17 (5 2.5 0)  arc 36 37 (5 2.5 1)
    arc 17 18 (5.5 3 0)  arc 37 38 (5.5 3 1)
    arc 18 19 (5 3.5 0)  arc 38 39 (5 3.5 1)
    arc 19 16 (4.5 3 0)  arc 39 36 (4.5 3 1)
);
boundary
(
    inlet { type patch; faces ((0 20 24 4) (4 24 28 8) (8 28 32 12)); }
    outlet { type patch; faces ((3 7 27 23) (7 11 31 27) (11 15 35 31)); }
    walls { type wall; faces ((0 1 21 20) (1 2 22 21) (2 3 23 22) (12 32 33 13) (13 33 34 14) (14 34 35 15)); }
    cylinder { type wall; faces ((16 36 37 17) (17 37 38 18) (18 38 39 19) (19 39 36 16)); }
    frontAndBack
    {
        type empty;
        faces
        (
            (0 4 5 1) (1 5 6 2) (2 6 7 3) (4 8 9 5) (6 10 11 7) (8 12 13 9) (9 13 14 10) (10 14 15 11)
            (5 16 17 6) (6 17 18 10) (10 18 19 9) (9 19 16 5)
            (20 21 25 24) (21 22 26 25) (22 23 27 26) (24 25 29 28) (26 27 31 30) (28 29 33 32) (29 30 34 33) (30 31 35 34)
            (25 26 37 36) (26 30 38 37) (30 29 39 38) (29 25 36 39)
        );
    }
);
EOT
} >"$dir/system/blockMeshDict"
{
    header dictionary controlDict
    cat <<EOT
application icoFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime $end;
deltaT $dt; adjustTimeStep no;
writeControl runTime; writeInterval $end; writeFormat binary; writePrecision 12;
runTimeModifiable false;
functions
{
    forces
    {
        type forces; libs ("libforces.so"); patches (cylinder);
        rho rhoInf; rhoInf 1; CofR (5 3 0.5); log false;
        executeControl timeStep; executeInterval $every; writeControl timeStep; writeInterval $every;
    }
EOT
    [ -z "$tol" ] || sh "$(dirname "$0")/steady_stop.sh" "$tol"
    echo "}"
} >"$dir/system/controlDict"
{
    header dictionary fvSchemes
    cat <<'EOT'
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
EOT
} >"$dir/system/fvSchemes"
{
    header dictionary fvSolution
    cat <<'EOT'
solvers
{
    p { solver GAMG; smoother GaussSeidel; tolerance 1e-6; relTol 0.05; }
    pFinal { $p; relTol 0; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-5; relTol 0; }
}
PISO { nCorrectors 2; nNonOrthogonalCorrectors 1; }
EOT
} >"$dir/system/fvSolution"
{
    header dictionary sample
    cat <<'EOT'
type sets; libs ("libsampling.so");
interpolationScheme cellPoint; setFormat csv; fields (U p);
sets
(
    probes
    {
        type cloud; axis xyz;
        points ((4.4999 3 0.5) (5 3.5001 0.5) (5 4.2 0.5) (5 1.8 0.5) (14.9999 3 0.5));
    }
);
EOT
} >"$dir/system/sample"
{
    header dictionary wallSample
    cat <<'EOT'
type surfaces; libs ("libsampling.so");
interpolationScheme cell; surfaceFormat raw; fields (p);
surfaces ( cylinder { type patch; patches (cylinder); interpolate false; } );
EOT
} >"$dir/system/wallSample"
{
    header dictionary transportProperties
    echo "nu $nu;"
} >"$dir/constant/transportProperties"
field() { # name class dimensions value inlet outlet
    {
        header "$2" "$1"
        printf 'dimensions %s;\ninternalField uniform %s;\nboundaryField\n{\n' "$3" "$4"
        printf '    inlet { %s }\n    outlet { %s }\n    "(walls|cylinder)" { %s }\n    frontAndBack { type empty; }\n}\n' "$5" "$6" "$7"
    } >"$dir/0/$1"
}
field U volVectorField "[0 1 -1 0 0 0 0]" "(0 0 0)" "type fixedValue; value uniform ($u0 0 0);" "type zeroGradient;" "type noSlip;"
field p volScalarField "[0 2 -2 0 0 0 0]" 0 "type zeroGradient;" "type fixedValue; value uniform 0;" "type zeroGradient;"
