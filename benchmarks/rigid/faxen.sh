#!/bin/bash
# faxen.sh DIR CELLS_PER_D [ENDTIME]: Stokes drag on a disk moved along the
# axis of a channel, against Faxen's (1946) result for a cylinder midway
# between two plane walls: F/(mu U) = 4 pi/(ln(l/a) - 0.9157 +
# 1.7244 (a/l)^2 - 1.7302 (a/l)^4 + ...), a the radius, l the distance to
# either wall; 10.558 at l/a = 8 (the settling channel's W/d).  A rigid
# cylinder (D = 0.1 m, motion prescribed) moved at U = 0.01 m/s along the
# axis of a closed box 0.8 m wide and 1.2 m long (walls 6 D above and
# below it) of liquid (rho 1, nu 1: Re 1e-3), fixed step 0.01 s (viscous
# number 0.64 CELLS_PER_D^2) to ENDTIME (0.3 s by default, twice the
# viscous time over the half width).  postProcessing/fixedBodies/0/
# forces.dat; faxen.py reads it.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 tend=${3:-0.3}
nx=$((8*n)) ny=$((12*n))
cylinderSetup "$d"
cylinderBox "$d" 0.8 1.2 "$nx" "$ny" "#eval{ 0.1/$n }" "    walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }"
cylinderControl "$d" "$tend" 0.01 0.1 no
cylinderSolution "$d" 1e-10 1e-12 "pRefCell 0; pRefValue 0;"
cylinderCase "$d" 0.4 0.6 1 "motion prescribed; velocity (0 -0.01 0);"
cylinderFields "$d" "(0 0 0)" "    walls { type noSlip; }" "    walls { type zeroGradient; }"
cylinderRun "$d"
