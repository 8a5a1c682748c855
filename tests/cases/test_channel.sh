#!/bin/bash
# Periodic channel (scene A) physics at small size:
#  - no disks: plane Poiseuille flow rate Q = f h^3/(12 nu).  Convergence
#    study (Q/Q_th - 1 at t = 1.5, steady): 16 cells 7.8e-3, 32 cells
#    1.95e-3, 64 cells 4.9e-4 (order 2).  Tolerance: 1.2 x the 32-cell error.
#  - with disks: the phase volumes are conserved, every alpha stays in
#    [0, 1], B* stays positive semi-definite, det(B) stays near 1, and
#    elastic disks lower the
#    flow rate, the stiffer ones more (seed 000: larger G, smaller Q).
. "$(dirname "$0")/lib.sh"

channelCase "$WORK/none" cells=32 nDisks=0 endTime=1.5 \
    && run "$WORK/none" vheFoam || fail poiseuille "vheFoam failed: $WORK/none"
qth=$(python3 -c "print(0.098/12)")
q=$(flowRate "$WORK/none" 1.4)
check poiseuille "abs($q/$qth - 1) < 1.2*1.95e-3" \
    "Q/Q_th = $(python3 -c "print('%.5f' % ($q/$qth))") at 32x32 cells"

# The same with the opt-in second-order wall stress (PIMPLE
# secondOrderWalls yes, wallShearCorrection.H): the wall's share of the
# error goes, the midpoint flux's 0.5/N^2 stays.  Below the 1e-3 that
# the verification asks at 32 cells, and 1.2 x the measured 4.87e-4
# (0.5/N^2: 1.95e-3, 4.87e-4, 1.20e-4 at 16, 32, 64 cells).
channelCase "$WORK/wall2" cells=32 nDisks=0 endTime=1.5 \
    && sed -i "s/^    pRefValue .*/&\n    secondOrderWalls yes;/" "$WORK/wall2/system/fvSolution" \
    && run "$WORK/wall2" vheFoam || fail poiseuilleWall2 "vheFoam failed: $WORK/wall2"
q2=$(flowRate "$WORK/wall2" 1.4)
check poiseuilleWall2 "abs($q2/$qth - 1) < min(1e-3, 1.2*4.87e-4)" \
    "secondOrderWalls: Q/Q_th = $(python3 -c "print('%.5f' % ($q2/$qth))") at 32x32 cells"

# The no-body case builds no phase fraction, B* or elastic term
n=$(find "$WORK/none" -name 'alpha.*' -o -name Bstar -o -name phis | wc -l)
check noSolidFields "$n == 0" "$n alpha.*, phis or Bstar files in a case without bodies"

for G in 0.1 0.5; do
    d="$WORK/G$G"
    channelCase "$d" cells=32 nDisks=6 G=$G endTime=4 \
        && run "$d" setBodies && run "$d" vheFoam \
        || fail "disks_G$G" "run failed: $d"
done

d="$WORK/G0.5"
vols=$(awk '!/^#/{print $2}' "$d"/postProcessing/solidDiagnostics/0/solidDiagnostics.dat)
v0=$(echo "$vols" | head -1); v1=$(echo "$vols" | tail -1)
check solidVolumeConserved "abs($v1/$v0 - 1) < 1e-6" "solid volume $v0 -> $v1"
read -r lo hi <<< "$(alphaRange "$d/log.vheFoam")"
check alphaBounded "$lo > -1e-6 and $hi < 1 + 1e-6" "alpha in [$lo, $hi]"
minEig=$(awk '!/^#/{print $4}' "$d"/postProcessing/solidDiagnostics/0/solidDiagnostics.dat | sort -g | head -1)
check BstarPSD "$minEig >= -1e-12" "min eigenvalue of B* over the run $minEig"

# det(B) = 1 exactly in the continuous model; B is carried with the solid's
# own flux and stretched with the deviatoric velocity gradient, so the drift
# stays small (measured max 5.04e-5 at 32 cells over this run; 3.25e-3 when
# the stretch took the full cell gradient, whose trace is not zero; 0.47
# with B* advected with the volume flux)
drift=$(awk '!/^#/{print $5}' "$d"/postProcessing/solidDiagnostics/0/solidDiagnostics.dat | sort -g | tail -1)
check detDrift "$drift < 1.5*5.04e-5" "max |det B - 1| over solid cells $drift"

q1=$(flowRate "$WORK/G0.1" 3.6)
q5=$(flowRate "$WORK/G0.5" 3.6)
q0=$(python3 -c "print($(flowRate "$WORK/none" 1.4))")
check disksSlowFlow "$q5 < 0.99*$q0" "Q(G=0.5)/Q(none) = $(python3 -c "print('%.4f' % ($q5/$q0))")"
check stifferSlower "$q5 < $q1" "Q(G=0.5) = $q5 < Q(G=0.1) = $q1"
finish
