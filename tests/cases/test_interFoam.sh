#!/bin/bash
# No solids: vheFoam reproduces Debian's interFoam (v1912) on the same
# case, the scene B dam break without spheres at 21 x 10 x 10 cells to
# t = 0.5 (liquid/gas, density ratio 1000, nu 1e-2, no surface tension,
# interFoam with MULESCorr off and one alpha corrector, tight solver
# tolerances).  Measured: the same 69 steps, max |alpha difference| 1e-8
# and max |U difference| 6e-7 of 2.9 m/s, i.e. the 8-digit write
# precision.  Bounds: 1e-7 and 1e-6 relative.
. "$(dirname "$0")/lib.sh"

vhe="$WORK/vheFoam" inter="$WORK/interFoam"
sceneCase damBreakSpheres "$vhe" n1=21 n2=10 n3=10 endTime=0.5 writeInterval=0.5 \
    nSpheres=0 || { fail setup "$vhe"; finish; }
sed -i 's/relTol          0.05;/relTol 0;/; s/tolerance       1e-7;/tolerance 1e-10;/' \
    "$vhe/system/fvSolution"
run "$vhe" setFields || { fail setup "$vhe"; finish; }

# The same case for interFoam (bin/vheToInterFoam)
"$VHE_ROOT/bin/vheToInterFoam" "$vhe" "$inter" > /dev/null || { fail setup "$inter"; finish; }

run "$vhe" vheFoam || fail vheFoamRun "$vhe/log.vheFoam"
run "$inter" interFoam || fail interFoamRun "$inter/log.interFoam"

sv=$(grep -c "^Time = " "$vhe/log.vheFoam"); si=$(grep -c "^Time = " "$inter/log.interFoam")
check sameSteps "$sv == $si" "vheFoam $sv steps, interFoam $si steps"
read -r d m <<< "$(maxFieldDiff "$vhe" "$inter" 0.5 alpha.liquid)"
check sameAlpha "$d < 1e-7" "max |alpha vheFoam - interFoam| = $d at t = 0.5"
read -r d m <<< "$(maxFieldDiff "$vhe" "$inter" 0.5 U)"
check sameVelocity "$d < 1e-6*$m" "max |U vheFoam - interFoam| = $d (max |U| $m) at t = 0.5"
finish
