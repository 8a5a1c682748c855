#!/bin/bash
# Run-time refinement in parallel (dynamicRefineFvMesh after decomposePar,
# issue 26): the bubbleObstacle tutorial (base 20 x 10 x 40, one level at
# every interface, the obstacle cut out of the mesh, a soft ball) to
# t = 0.3 serial and on 2 ranks split at x = 0.5 (through the bubble and
# the free surface), with tight solver tolerances so that the
# two differ by the solvers' tolerance rather than their relTol:
#  - both refine and unrefine, with the same number of cells after every
#    mesh change;
#  - every phase volume of every step agrees to 1e-9 relative;
#  - the ball's centroid agrees to 1e-6 m at every row of solidDiagnostics.
. "$(dirname "$0")/lib.sh"

ser="$WORK/serial" par="$WORK/parallel"
sceneCase bubbleObstacle "$ser" endTime=0.3 writeInterval=0.3 \
    && run "$ser" topoSet && run "$ser" subsetMesh fluid -patch obstacle -overwrite \
    && run "$ser" setFields && run "$ser" setBodies || { fail setup "$ser"; finish; }
tightSolvers "$ser" 1e-12
cp -r "$ser" "$par"
# split across the bubble, the ball's path and the free surface (x = 0.5)
# rather than between them (the tutorial's z = 1)
foamDictionary -entry coeffs.n -set "(2 1 1)" "$par/system/decomposeParDict" > /dev/null
run "$ser" vheFoam || fail serialRun "$ser/log.vheFoam"
run "$par" decomposePar || fail decomposePar "$par/log.decomposePar"
(cd "$par" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1) || fail parallelRun "$par/log.vheFoam"

# the cell count after every refinement and unrefinement
changes() { grep -E "^(Refined|Unrefined) from" "$1/log.vheFoam" | awk '{print $1, $3, $5}'; }
nS=$(changes "$ser" | wc -l); nP=$(changes "$par" | wc -l)
nDiff=$(diff <(changes "$ser") <(changes "$par") | grep -c "^[<>]")
cells=$(changes "$ser" | awk '{if ($3 > m) m = $3} END {print m + 0}')
check sameRefinement "$nS > 2 and $nDiff == 0 and $(changes "$ser" | grep -c ^Unrefined) > 0" \
    "$nS mesh changes serial, $nP on 2 ranks, $nDiff differ (at most $cells cells)"

# phase volumes, step by step ("Phase <name> volume V" lines)
vols() { grep "^Phase .* volume" "$1/log.vheFoam" | awk '{print $2, $4}'; }
d=$(paste -d' ' <(vols "$ser") <(vols "$par") \
    | awk '$1 == $3 {r = ($2 - $4)/($2 + 1e-300); if (r < 0) r = -r; if (r > m) m = r; n++}
           END {if (n == 0) print 1; else printf "%.3g\n", m}')
check parallelVolumes "$d < 1e-9 and $(vols "$ser" | wc -l) == $(vols "$par" | wc -l)" \
    "largest relative difference of a phase volume $d over $(vols "$ser" | wc -l) values"

# the ball's centroid (columns 12-14 of solidDiagnostics)
path() { awk '!/^#/ {print $1, $12, $13, $14}' "$1/postProcessing/solidDiagnostics/0/solidDiagnostics.dat"; }
d=$(paste -d' ' <(path "$ser") <(path "$par") \
    | awk '{for (i = 2; i <= 4; i++) {e = $i - $(i + 4); if (e < 0) e = -e; if (e > m) m = e}; n++}
           END {if (n == 0) print 1; else printf "%.3g\n", m}')
z=$(path "$ser" | tail -1 | cut -d' ' -f4)
check parallelBallPath "$d < 1e-6" "largest difference of the ball's centroid $d m over $(path "$ser" | wc -l) rows (z at t = 0.3: $z m)"
finish
