#!/bin/bash
# Stiff bodies at the flow time step (the point of the semi-implicit,
# C-ISMAC-style elasticity): six disks with G = 100 Pa in the channel
# (G/(rho U^2) ~ 7e5 for U ~ 0.012 m/s), 32 cells, t <= 2.
#  - semi-implicit: no more than 1.2 x the steps of the same case without
#    bodies (measured: 219 and 219),
#  - explicit (elastic Courant limited: measured 2566 steps), solved
#    coupled every step as the semi-implicit variant's iterated steps
#    are, gives the same flow rate within 1.5e-3 relative (measured
#    1.4e-3), and the semi-implicit one converges to it in dt: with the
#    step capped at 5 ms instead of 10 ms the difference falls to 0.25
#    of itself (Q 7.24005e-3, 7.24768e-3 at 10, 5 ms; explicit
#    7.25020e-3; bound 0.7),
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
            # The explicit reference solved coupled every step, as the
            # semi-implicit variant's iterated steps are: the same
            # Rhie-Chow damping rho/A, at a twelfth of the step
            [ $v = explicit ] && sed -i "s/^    elasticity explicit;/&\n    coupling { solve always; }/" \
                "$d/system/fvSolution"
        fi
    fi
    run "$d" vheFoam || fail "${v}Run" "$d/log.vheFoam"
done
steps() { grep -c "^Time = " "$WORK/$1/log.vheFoam"; }
lastQ() { awk '!/^#/{q = -$2} END {print q}' "$WORK/$1/postProcessing/flowRate/0/surfaceFieldValue.dat"; }

# The semi-implicit run's iterated steps solve momentum and continuity
# together (coupledStep) with the momentum equation's Rhie-Chow damping
# rho/A.  With the projection's damping, of coefficient dt, liquid leaked
# past the stiff disks' edges in proportion to the step: Q was 1.7 % above
# the explicit variant's (7.43129e-3 at 10 ms, 7.40008e-3 at 5 ms,
# explicit 7.31076e-3, itself leaking at its twelfth of the step).
n0=$(steps none); ns=$(steps semiImplicit); ne=$(steps explicit)
check stiffAtFlowStep "$ns <= 1.2*$n0" "semi-implicit $ns steps, no bodies $n0, explicit $ne"
qs=$(lastQ semiImplicit); qe=$(lastQ explicit)
qh=$(lastQ halfStep)
check stiffVariantsAgree "abs($qs/$qe - 1) < 1.5e-3" \
    "Q semi-implicit $qs, explicit $qe"
check stiffVariantsConverge "abs($qh - $qe) < 0.7*abs($qs - $qe)" "Q semi-implicit at half the step $qh: difference $(python3 -c "print('%.2f' % (abs($qh - $qe)/abs($qs - $qe)))") of the full step's"
# The step's coupling (stepCoupling): a stiff disk (G/(rho U^2) = 1e5) in
# plane Couette flow at a viscous number of 10 turns with the flow (with
# one pass of the prediction and projection it turned at 0.089: the lagged
# transpose part of its stress increment resisted rotation as an inertia
# of dt Ghat/dx^2).  With its outline carried geometrically it turns at
# 0.946 of half the vorticity at 32 cells and 0.965 at 64 (a rigid disk
# 0.984, 0.982; with MULES's diffuse edge 0.992 and 0.951): a KNOWN line,
# the resisting torque's cause open.  Its wall stress 1.121 at 32 cells,
# 1.091 at 64, approaches the rigid disk's (1.057, 1.065): the stiff edge
# sharpens with the mesh (MULES: 1.123, 1.107); a KNOWN line at 32 cells
couette="$VHE_ROOT/benchmarks/rigid/couette.sh"
for b in 100000 rigid; do
    "$couette" "$WORK/couette_$b" 32 "$b" 10 0.5 || fail "couette_$b" "$WORK/couette_$b/log.vheFoam"
done
read -r _ tauS wS _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_100000" 32)"
read -r _ tauR wR _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_rigid" 32)"
passes=$(grep Coupling "$WORK/couette_100000/log.vheFoam" | awk '{s += $2} END {if (NR) printf "%.1f", s/NR; else print 1}')
checkKnown stiffDiskTurns "-($wS) > 0.97" "-($wS) > 0.9" \
    "stiff disk's rotation rate over half the vorticity $(python3 -c "print(-($wS))") (rigid $(python3 -c "print(-($wR))")), $passes passes a step" \
    "0.974 at 64 cells; the torque that slows it is not found, docs/limitations.md"
checkKnown stiffRigidStress "abs($tauS/$tauR - 1) < 0.02" "abs($tauS/$tauR - 1) < 0.08" \
    "wall stress over the body-free flow's: stiff $tauS, rigid $tauR" \
    "its edge cells are stiff in proportion to phi_s, and the rigid disk keeps the projection's leak: 1.094 against 1.065 at 64 cells, docs/limitations.md"
# A rigid disk solved coupled every step (coupling { solve always; }: each
# iterate of the bodies' fixed point solves momentum and continuity
# together): its wall stress the same at viscous numbers 10 and 1000
# (measured 1.0681 and 1.0680; with the projection 1.057 and 1.039, its
# damping leaking in proportion to the step)
for vn in 10 1000; do
    VHE_PIMPLE="coupling { solve always; }" "$couette" "$WORK/coupledRigid_$vn" 32 rigid $vn 0.5 \
        || fail "coupledRigid_$vn" "$WORK/coupledRigid_$vn/log.vheFoam"
done
read -r _ tau10 _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/coupledRigid_10" 32)"
read -r _ tau1000 _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/coupledRigid_1000" 32)"
check coupledRigidStepFree "abs($tau1000/$tau10 - 1) < 1e-3" \
    "rigid disk's wall stress at viscous numbers 10 and 1000, solved coupled: $tau10, $tau1000"
devB=$(awk '!/^#/{m = $3} END {print m}' "$WORK/semiImplicit/postProcessing/solidDiagnostics/0/solidDiagnostics.dat")
check stiffKeepShape "$devB < 0.01" "max |dev B| at t = 2: $devB"
finish
