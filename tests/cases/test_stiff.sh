#!/bin/bash
# Stiff bodies at the flow time step (the point of the semi-implicit,
# C-ISMAC-style elasticity): six disks with G = 100 Pa in the channel
# (G/(rho U^2) ~ 7e5 for U ~ 0.012 m/s), 32 cells, t <= 2.
#  - semi-implicit: no more than 1.2 x the steps of the same case without
#    bodies (measured: 219 and 219),
#  - explicit (elastic Courant limited: measured 2566 steps) gives the same
#    flow rate within 1.5e-3 relative (measured 1.2e-3), and the
#    semi-implicit one converges to it in dt: with the step capped at
#    5 ms instead of 10 ms the difference falls by 0.59 (Q 7.16415e-3,
#    7.16777e-3, 7.17027e-3 at 10, 5, 2.5 ms; explicit 7.17284e-3),
#  - the stiff disks keep their shape: max |dev B| below 0.01 (measured
#    2.5e-3; 3.4e-3 before the stretch took the flux as its face-normal
#    velocity).
. "$(dirname "$0")/lib.sh"

for v in none semiImplicit explicit halfStep; do
    d="$WORK/$v"
    if [ $v = none ]; then
        channelCase "$d" cells=32 nDisks=0 endTime=2 || fail setup "$d"
    else
        channelCase "$d" cells=32 nDisks=6 G=100 endTime=2 && run "$d" setBodies \
            || fail setup "$d"
        if [ $v = halfStep ]; then
            sed -i "s/^maxDeltaT .*/maxDeltaT 0.005;/" "$d/system/controlDict"
        else
            sed -i "s/^    pRefValue .*/&\n    elasticity $v;/" "$d/system/fvSolution"
        fi
    fi
    run "$d" vheFoam || fail "${v}Run" "$d/log.vheFoam"
done
steps() { grep -c "^Time = " "$WORK/$1/log.vheFoam"; }
lastQ() { awk '!/^#/{q = -$2} END {print q}' "$WORK/$1/postProcessing/flowRate/0/surfaceFieldValue.dat"; }

# The projection (pEqn.H) corrects U* by dt/rho grad(p increment), which
# a stiff body does not resist: the disks take a spurious strain of the
# splitting each step (measured: Q 1.7 % above the explicit variant's;
# PISO, whose 1/A holds the elastic viscosity, had 0.12 % but diverges at
# large viscous numbers).  A documented limitation of the coupling.
splitting="projection splitting error in stiff bodies, docs/limitations.md"
n0=$(steps none); ns=$(steps semiImplicit); ne=$(steps explicit)
check stiffAtFlowStep "$ns <= 1.2*$n0" "semi-implicit $ns steps, no bodies $n0, explicit $ne"
qs=$(lastQ semiImplicit); qe=$(lastQ explicit)
qh=$(lastQ halfStep)
checkKnown stiffVariantsAgree "abs($qs/$qe - 1) < 1.5e-3" "abs($qs/$qe - 1) < 2.5e-2" \
    "Q semi-implicit $qs, explicit $qe" "$splitting"
checkKnown stiffVariantsConverge "abs($qh - $qe) < 0.7*abs($qs - $qe)" "abs($qh - $qe) < abs($qs - $qe)" "Q semi-implicit at half the step $qh: difference $(python3 -c "print('%.2f' % (abs($qh - $qe)/abs($qs - $qe)))") of the full step's" "$splitting"
devB=$(awk '!/^#/{m = $3} END {print m}' "$WORK/semiImplicit/postProcessing/solidDiagnostics/0/solidDiagnostics.dat")
check stiffKeepShape "$devB < 0.01" "max |dev B| at t = 2: $devB"
finish
