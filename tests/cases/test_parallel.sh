#!/bin/bash
# decomposePar + mpirun: setBodies on a decomposed case places the same
# bodies as in serial, and vheFoam on 2 ranks agrees with the serial run
# with tight solver tolerances (bounds: 1e-12 for the bodies; 1e-6 of the
# field scale for U and B*).
. "$(dirname "$0")/lib.sh"

ser="$WORK/serial" par="$WORK/parallel"
channelCase "$ser" cells=32 nDisks=6 G=0.5 endTime=0.5 writeInterval=0.5 || { fail setup blockMesh; finish; }
# tight pressure solves, so that serial and parallel differ by round-off
# rather than by relTol
sed -i 's/relTol          0.01;/relTol 0;/' "$ser/system/fvSolution"
cp -r "$ser" "$par"
run "$ser" setBodies && run "$ser" vheFoam || fail serialRun "$ser"

run "$par" decomposePar || fail decomposePar "$par/log.decomposePar"
run "$par" mpirun -np 2 setBodies -parallel || fail parallelSetBodies "$par/log.mpirun"
mv "$par/log.mpirun" "$par/log.setBodies"
run "$par" mpirun -np 2 vheFoam -parallel || fail parallelRun "$par/log.mpirun"
run "$par" reconstructPar -withZero || fail reconstructPar "$par/log.reconstructPar"

read -r d m <<< "$(maxFieldDiff "$ser" "$par" 0 alpha.rubber)"
check setBodiesParallel "$d < 1e-12" "max |alpha serial - parallel| = $d at t = 0"
read -r d m <<< "$(maxFieldDiff "$ser" "$par" 0.5 U)"
check solverParallel "$d < 1e-6*$m" "max |U serial - parallel| = $d (max |U| $m) at t = 0.5"
read -r d m <<< "$(maxFieldDiff "$ser" "$par" 0.5 Bstar)"
check BstarParallel "$d < 1e-6*$m" "max |B* serial - parallel| = $d at t = 0.5"
finish
