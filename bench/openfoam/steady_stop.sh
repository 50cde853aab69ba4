#!/bin/sh
# Prints the function objects that stop an icoFoam run at steady state by
# nspd's criterion (flow.steady_tolerance): the largest |dU/dt| over the
# cells (ddt2, Euler as the solver; the magnitude, while nspd takes the
# larger component) below TOL m/s^2. For a controlDict's `functions`.
#   steady_stop.sh TOL
cat <<EOT
    dUdt { type ddt2; libs ("libfieldFunctionObjects.so"); fields (U); mag true; result dUdt; log false; writeControl writeTime; }
    dUdtMax { type fieldMinMax; libs ("libfieldFunctionObjects.so"); fields (dUdt); mode magnitude; log false; writeToFile false; }
    steady
    {
        type runTimeControl; libs ("libutilityFunctionObjects.so");
        conditions
        {
            dudt { type minMax; functionObject dUdtMax; fields (max(dUdt)); mode minimum; value $1; }
        }
    }
EOT
