#!/bin/sh
# Writes an OpenFOAM rhoCentralFoam case: a viscous 2D periodic square of
# N x N cells (one cell thick in z, empty front and back), air-like gas with
# mu > 0 and Pr = 0.72, at rest with a hot high-pressure square in the middle
# so that every solver does real work; fixed time step, `steps` steps.
#   make_case.sh DIR N STEPS
set -eu
dir=$1
n=$2
steps=$3
mkdir -p "$dir/system" "$dir/constant" "$dir/0"
header() { # class object
    printf 'FoamFile\n{\n    version 2.0;\n    format ascii;\n    class %s;\n    object %s;\n}\n' "$1" "$2"
}
{
    header dictionary blockMeshDict
    cat <<EOT
convertToMeters 1;
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 0.01) (1 0 0.01) (1 1 0.01) (0 1 0.01) );
blocks ( hex (0 1 2 3 4 5 6 7) ($n $n 1) simpleGrading (1 1 1) );
boundary
(
    left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }
    bottom { type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }
    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }
);
EOT
} >"$dir/system/blockMeshDict"
# dt: about CFL 0.3 for the sound speed of T = 300 K air on a 1/N grid
dt=$(awk -v n="$n" 'BEGIN { printf "%.6g", 0.3 / n / 450 }')
{
    header dictionary controlDict
    cat <<EOT
application rhoCentralFoam;
startFrom startTime; startTime 0; stopAt endTime;
endTime $(awk -v d="$dt" -v s="$steps" 'BEGIN { printf "%.6g", d * s }');
deltaT $dt; adjustTimeStep no;
writeControl timeStep; writeInterval 100000; writeFormat binary;
runTimeModifiable false;
EOT
} >"$dir/system/controlDict"
{
    header dictionary fvSchemes
    cat <<'EOT'
fluxScheme Kurganov;
ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes { default none; div(tauMC) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; reconstruct(rho) vanLeer; reconstruct(U) vanLeerV; reconstruct(T) vanLeer; }
snGradSchemes { default corrected; }
EOT
} >"$dir/system/fvSchemes"
{
    header dictionary fvSolution
    cat <<'EOT'
solvers
{
    "(rho|rhoU|rhoE)" { solver diagonal; }
    U { solver smoothSolver; smoother GaussSeidel; nSweeps 2; tolerance 1e-9; relTol 0.01; }
    e { $U; tolerance 1e-10; relTol 0; }
}
EOT
} >"$dir/system/fvSolution"
{
    header dictionary setFieldsDict
    cat <<'EOT'
defaultFieldValues ( volScalarFieldValue T 300 volScalarFieldValue p 1e5 );
regions ( boxToCell { box (0.4 0.4 -1) (0.6 0.6 1); fieldValues ( volScalarFieldValue T 400 volScalarFieldValue p 2e5 ); } );
EOT
} >"$dir/system/setFieldsDict"
{
    header dictionary decomposeParDict
    printf 'numberOfSubdomains 2;\nmethod simple;\nsimpleCoeffs { n (2 1 1); delta 0.001; }\n'
} >"$dir/system/decomposeParDict"
{
    header dictionary thermophysicalProperties
    cat <<'EOT'
thermoType { type hePsiThermo; mixture pureMixture; transport const; thermo hConst; equationOfState perfectGas; specie specie; energy sensibleInternalEnergy; }
mixture
{
    specie { molWeight 28.96; }
    thermodynamics { Cp 1004.5; Hf 0; }
    transport { mu 1.8e-5; Pr 0.72; }
}
EOT
} >"$dir/constant/thermophysicalProperties"
{
    header dictionary turbulenceProperties
    echo "simulationType laminar;"
} >"$dir/constant/turbulenceProperties"
field() { # name class dimensions value
    {
        header "$2" "$1"
        printf 'dimensions %s;\ninternalField uniform %s;\n' "$3" "$4"
        printf 'boundaryField\n{\n    "(left|right|bottom|top)" { type cyclic; }\n    frontAndBack { type empty; }\n}\n'
    } >"$dir/0/$1"
}
field T volScalarField "[0 0 0 1 0 0 0]" 300
field p volScalarField "[1 -1 -2 0 0 0 0]" 1e5
field U volVectorField "[0 1 -1 0 0 0 0]" "(0 0 0)"
