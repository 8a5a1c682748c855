#!/bin/bash
# Three-phase path (gas 1, liquid 1000, solid 1000 kg/m^3) on a small dam
# break with the four spheres (scene B at 21 x 10 x 10 cells, t <= 0.3):
#  - liquid and solid volumes conserved to 1e-6 relative over the run,
#  - every alpha in [0, 1] within 1e-6 at every step, also with two alpha
#    sub-cycles per step,
#  - the liquid level starts at the dam depth (0.8) on the left wall,
#  - 2 ranks (decomposePar, mpirun) agree with serial with tight solver
#    tolerances: alpha to 1.5e-8 (one unit of the 8th written digit: a
#    value that rounds the other way; measured 1e-8), U to 1e-6 relative
#    (measured 2e-8, the write precision), liquid level to 1e-5 relative.
. "$(dirname "$0")/lib.sh"

ser="$WORK/serial" par="$WORK/parallel"
sceneCase damBreakSpheres "$ser" n1=21 n2=10 n3=10 endTime=0.3 writeInterval=0.3 \
    GperRho=10 || { fail setup "$ser"; finish; }
# tight pressure and velocity solves, so that serial and parallel differ by
# round-off rather than by the solvers' relTol
tightSolvers "$ser" 1e-11
run "$ser" setFields && run "$ser" setBodies \
    || { fail setup "$ser"; finish; }
cp -r "$ser" "$par"
cp -r "$ser" "$WORK/subCycled"
run "$ser" vheFoam || fail serialRun "$ser/log.vheFoam"

# volumes: first and last "Phase <name> volume V" lines
for phase in liquid gel; do
    read -r v0 v1 <<< "$(grep "^Phase $phase volume" "$ser/log.vheFoam" \
        | awk 'NR==1{a=$4} {b=$4} END{print a, b}')"
    check "${phase}VolumeConserved" "abs($v1/$v0 - 1) < 1e-6" \
        "$phase volume $v0 -> $v1 over $(grep -c '^Time =' "$ser/log.vheFoam") steps"
done
read -r lo hi <<< "$(alphaRange "$ser/log.vheFoam")"
check alphaBounded "$lo > -1e-6 and $hi < 1 + 1e-6" "every alpha within [$lo, $hi]"

# the same with two alpha sub-cycles per step
sub="$WORK/subCycled"
sed -i 's/nAlphaSubCycles 1;/nAlphaSubCycles 2;/' "$sub/system/fvSolution"
run "$sub" vheFoam || fail subCycledRun "$sub/log.vheFoam"
read -r v0 v1 <<< "$(grep "^Phase liquid volume" "$sub/log.vheFoam" | awk 'NR==1{a=$4} {b=$4} END{print a, b}')"
read -r lo hi <<< "$(alphaRange "$sub/log.vheFoam")"
check subCycles "abs($v1/$v0 - 1) < 1e-6 and $lo > -1e-6 and $hi < 1 + 1e-6" \
    "nAlphaSubCycles 2: liquid volume $v0 -> $v1, alpha in [$lo, $hi]"

hl="$ser/postProcessing/liquidLevel/0/liquidLevel.dat"
h0=$(awk '!/^#/{print $2; exit}' "$hl")
check liquidLevelStart "abs($h0 - 0.8) < 2e-3" "h_L(x1 = 0) after the first step: $h0 (dam depth 0.8)"

run "$par" decomposePar || fail decomposePar "$par/log.decomposePar"
run "$par" mpirun -np 2 vheFoam -parallel || fail parallelRun "$par/log.mpirun"
run "$par" reconstructPar -latestTime || fail reconstructPar "$par/log.reconstructPar"

read -r d m <<< "$(maxFieldDiff "$ser" "$par" 0.3 alpha.liquid)"
check parallelAlpha "$d < 1.5e-8" "max |alpha.liquid serial - parallel| = $d at t = 0.3"
read -r d m <<< "$(maxFieldDiff "$ser" "$par" 0.3 U)"
check parallelU "$d < 1e-6*$m" "max |U serial - parallel| = $d (max |U| $m) at t = 0.3"
d=$(paste <(awk '!/^#/{print $2}' "$hl") <(awk '!/^#/{print $2}' "$par/postProcessing/liquidLevel/0/liquidLevel.dat") \
    | awk '{d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d} END {print m + 0}')
check parallelLiquidLevel "$d < 1e-5*0.8" "max |h_L serial - parallel| = $d"
finish
