#!/bin/bash
# sliding.sh DIR CELLS_PER_D [ENDTIME [RE]]: the settling disk's steady
# flow seen from the disk: a fixed cylinder (D = 0.1 m, rigid, motion
# fixed) on the axis of a channel 8 D wide (the settling channel's
# W/d), the liquid entering at U = 1 m/s and both walls sliding at U
# (fluid at rest far from the disk in the walls' frame), nu = 0.1/RE
# (RE 17.3 by default: the lower-Reynolds settling case's published
# largest Re).  The channel runs from 10 D upstream to 25 D downstream
# of the disk; outflow at p = 0.  Square cells, maxCo 0.5, to ENDTIME
# (3 s by default, 30 D/U).  postProcessing/fixedBodies/0/forces.dat;
# the steady drag coefficient Cd = 2 Fx/(rho U^2 D dz) is the one a
# disk settling at that Reynolds number meets (compare with a
# body-fitted solution: benchmarks/rigid/README.md).
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 tend=${3:-3} Re=${4:-17.3}
nu=$(python3 -c "print(0.1/$Re)")
nx=$((35*n)) ny=$((8*n))
cylinderSetup "$d"
cylinderBox "$d" 3.5 0.8 "$nx" "$ny" "#eval{ 0.1/$n }" "    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }"
cylinderControl "$d" "$tend" 1e-4 1 yes
cylinderSolution "$d" 1e-8 1e-9
cylinderCase "$d" 1.0 0.4 "$nu" "motion fixed;"
cylinderChannelFields "$d" "(1 0 0)" "uniform (1 0 0)" "type fixedValue; value uniform (1 0 0);"
cylinderRun "$d"
