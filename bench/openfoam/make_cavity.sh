#!/bin/sh
# Writes an OpenFOAM icoFoam case: the lid-driven cavity at Re 100 in units
# of the lid (L = 1 m, U = 1 m/s, nu = 0.01 m^2/s) on N x N uniform cells,
# one cell thick in z (empty front and back), started at rest. Time step
# Courant 1 (dt = 1/N s, as the icoFoam cavity tutorial). The run stops at
# steady state by nspd's criterion (flow.steady_tolerance): the largest
# |dU/dt| over the cells (the ddt2 function object, Euler as the solver;
# the magnitude, while nspd takes the larger component: up to sqrt 2
# stricter) below TOL U^2/L. A `sample` dictionary writes the two centrelines
# (x = L/2 and y = L/2, 201 points each, cellPoint interpolation) for
#   postProcess -func sample -latestTime
#   make_cavity.sh DIR N [TOL] [END]     (TOL 1e-6, END 100 s)
set -eu
dir=$1
n=$2
tol=${3:-1e-6}
end=${4:-100}
mkdir -p "$dir/system" "$dir/constant" "$dir/0"
header() { # class object
    printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n' "$1" "$2"
}
{
    header dictionary blockMeshDict
    cat <<EOT
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.1) (1 0 0.1) (1 1 0.1) (0 1 0.1) );
blocks ( hex (0 1 2 3 4 5 6 7) ($n $n 1) simpleGrading (1 1 1) );
boundary
(
    lid   { type wall; faces ((3 7 6 2)); }
    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOT
} >"$dir/system/blockMeshDict"
dt=$(awk -v n="$n" 'BEGIN { printf "%.8g", 1 / n }')
{
    header dictionary controlDict
    cat <<EOT
application icoFoam;
startFrom startTime; startTime 0; stopAt endTime; endTime $end;
deltaT $dt; adjustTimeStep no;
writeControl timeStep; writeInterval 1000000000; writeFormat binary; writePrecision 12;
runTimeModifiable false;
functions
{
EOT
    sh "$(dirname "$0")/steady_stop.sh" "$tol"
    echo "}"
} >"$dir/system/controlDict"
{
    header dictionary fvSchemes
    cat <<'EOT'
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; }
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes { default orthogonal; }
EOT
} >"$dir/system/fvSchemes"
# The cavity tutorial's tolerances: tighter ones (1e-10) give the same
# profiles to 4 digits and reach the steady criterion a little sooner, but
# cost more per step
{
    header dictionary fvSolution
    cat <<'EOT'
solvers
{
    p { solver PCG; preconditioner DIC; tolerance 1e-6; relTol 0.05; }
    pFinal { $p; relTol 0; }
    U { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-5; relTol 0; }
}
PISO { nCorrectors 2; nNonOrthogonalCorrectors 0; pRefCell 0; pRefValue 0; }
EOT
} >"$dir/system/fvSolution"
{
    header dictionary sample
    cat <<'EOT'
type sets; libs ("libsampling.so");
interpolationScheme cellPoint; setFormat csv; fields (U p);
sets
(
    vertical { type uniform; axis xyz; start (0.5 0 0.05); end (0.5 1 0.05); nPoints 201; }
    horizontal { type uniform; axis xyz; start (0 0.5 0.05); end (1 0.5 0.05); nPoints 201; }
);
EOT
} >"$dir/system/sample"
{
    header dictionary transportProperties
    echo "nu 0.01;"
} >"$dir/constant/transportProperties"
field() { # name class dimensions value lid
    {
        header "$2" "$1"
        printf 'dimensions %s;\ninternalField uniform %s;\nboundaryField\n{\n' "$3" "$4"
        printf '    lid { %s }\n    walls { %s }\n    frontAndBack { type empty; }\n}\n' "$5" "$6"
    } >"$dir/0/$1"
}
field U volVectorField "[0 1 -1 0 0 0 0]" "(0 0 0)" "type fixedValue; value uniform (1 0 0);" "type noSlip;"
field p volScalarField "[0 2 -2 0 0 0 0]" 0 "type zeroGradient;" "type zeroGradient;"
