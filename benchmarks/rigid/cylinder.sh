#!/bin/bash
# cylinder.sh DIR CELLS_PER_D [ENDTIME]: Schaefer & Turek (1996)'s 2D-2
# benchmark, the laminar flow past a fixed cylinder at Re = 100: channel
# 2.2 x 0.41 m, cylinder D = 0.1 m at (0.2, 0.2) (a rigid material with
# motion fixed), nu 1e-3, rho 1, parabolic inflow of peak 1.5 m/s (mean
# U = 1), outflow at p = 0, no-slip walls.  Square cells, CELLS_PER_D
# across the cylinder; maxCo 0.5; to t = ENDTIME (default 10).  The
# fluid's force on the cylinder is postProcessing/fixedBodies/0/
# forces.dat (every step); cylinder.py reads it.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 tend=${3:-10}
nx=$((22*n)) ny=$(python3 -c "print(round(4.1*$n))")
cylinderSetup "$d"
cylinderBox "$d" 2.2 0.41 "$nx" "$ny" "#eval{ 0.1/$n }" "    inlet  { type patch; faces ((0 4 7 3)); }
    outlet { type patch; faces ((1 2 6 5)); }
    walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }"
cylinderControl "$d" "$tend" 1e-4 1 yes
cylinderSolution "$d" 1e-8 1e-9
cylinderCase "$d" 0.2 0.2 1e-3 "motion fixed;"
inflow=$(python3 -c "
H = 0.41; n = $ny
print(' '.join('(%.12g 0 0)' % (6*(j + 0.5)*H/n*(H - (j + 0.5)*H/n)/H**2) for j in range(n)))")
cylinderChannelFields "$d" "(0 0 0)" "nonuniform List<vector> $ny ($inflow)" "type noSlip;"
cylinderRun "$d"
