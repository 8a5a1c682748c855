#!/bin/bash
# Surface tension (constant/vheProperties sigmas): the short forms of
# benchmarks/surfaceTension.
# - Static drop (Popinet 2009: R = 0.25, La 12000), 2D at 16 cells per
#   diameter, 200 steps, beside Debian's interFoam on the same case: the
#   pressure jump against sigma/R (the benchmark, 1000 steps: +0.63 % at 16
#   cells, +0.14 % at 32; interFoam -14 %, -9.6 %) within 2 %, and the
#   spurious velocity's capillary number at least 100 times below
#   interFoam's (the benchmark: 7000 times).  The same in 3D at 8 cells per
#   diameter (2 sigma/R) within 5 %.
# - The same 2D drop on 2 ranks (the height functions' stencils cross the
#   processor boundary) equals the serial run to the solvers' tolerance.
# - Hysing et al. (2009) test case 1 at h = 1/40 to t = 3: the bubble's
#   centroid and largest rise velocity within 2 % of the benchmark's.
# - The step never exceeds the capillary limit the log states.
. "$(dirname "$0")/lib.sh"
B="$VHE_ROOT/benchmarks/surfaceTension"

bash "$B/staticDrop.sh" "$WORK/drop" 16 200 || fail dropRun "$WORK/drop"
read -r dp edp ca < <(python3 "$B/staticDrop.py" "$WORK/drop/vheFoam" 2)
read -r dpi edpi cai < <(python3 "$B/staticDrop.py" "$WORK/drop/interFoam" 2)
check laplacePressure "abs($edp) < 0.02" \
    "pressure jump $dp against sigma/R = 4 ($edp; interFoam $dpi, $edpi)"
check spuriousCurrents "$ca*100 < $cai" \
    "capillary number of the spurious velocity $ca, interFoam $cai"
dtmax=$(awk '/^deltaT = / {if ($3 > m) m = $3} END {print m + 0}' "$WORK/drop/vheFoam/log.vheFoam")
dtcap=$(awk '/capillary step limit/ {print $4; exit}' "$WORK/drop/vheFoam/log.vheFoam")
check capillaryStepLimit "$dtcap > 0 and $(awk '/^deltaT/ {print $2; exit}' "$WORK/drop/vheFoam/system/controlDict" | tr -d ';') <= $dtcap*(1 + 1e-9)" \
    "the case's step against the capillary limit $dtcap s"

# 2 ranks: the same fields as the serial run
par="$WORK/dropParallel"
cp -r "$WORK/drop/vheFoam" "$par"; rm -rf "$par"/[1-9]* "$par"/0.* "$par"/log.*
cat > "$par/system/decomposeParDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2; method simple; coeffs { n (2 1 1); }
DICT
(cd "$par" && decomposePar > log.decomposePar 2>&1 && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1 \
    && reconstructPar -latestTime > log.reconstructPar 2>&1) || fail parallelRun "$par"
tl=$(ls -d "$par"/[0-9]* | xargs -n1 basename | sort -g | tail -1)
read -r du umax < <(maxFieldDiff "$WORK/drop/vheFoam" "$par" "$tl" U)
read -r dpp pmax < <(maxFieldDiff "$WORK/drop/vheFoam" "$par" "$tl" p)
check parallelEqualsSerial "$du < 1e-9 and $dpp < 1e-6*$pmax" \
    "2 ranks against serial: max |dU| $du (|U|max $umax), max |dp| $dpp"

bash "$B/staticDrop.sh" "$WORK/drop3D" 8 100 3 || fail drop3DRun "$WORK/drop3D"
read -r dp3 edp3 ca3 < <(python3 "$B/staticDrop.py" "$WORK/drop3D/vheFoam" 3)
read -r dp3i edp3i ca3i < <(python3 "$B/staticDrop.py" "$WORK/drop3D/interFoam" 3)
check laplacePressure3D "abs($edp3) < 0.05" \
    "pressure jump $dp3 against 2 sigma/R = 8 ($edp3; interFoam $dp3i, $edp3i); Ca $ca3, interFoam $ca3i"

bash "$B/risingBubble.sh" "$WORK/bubble" 40 || fail bubbleRun "$WORK/bubble"
read -r circ tc vel tv yc < <(python3 "$B/risingBubble.py" "$WORK/bubble/vheFoam" 2> /dev/null)
read -r circi tci veli tvi yci < <(python3 "$B/risingBubble.py" "$WORK/bubble/interFoam" 2> /dev/null)
check hysingRiseVelocity "abs($vel/0.2417 - 1) < 0.02" \
    "largest rise velocity $vel at t = $tv against 0.2417 (interFoam $veli)"
check hysingCentroid "abs($yc/1.0813 - 1) < 0.02" \
    "centroid at t = 3: $yc against 1.0813 (interFoam $yci)"
finish
