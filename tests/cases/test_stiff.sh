#!/bin/bash
# Stiff bodies at the flow time step (the point of the semi-implicit,
# C-ISMAC-style elasticity): six disks with G = 100 Pa in the channel
# (G/(rho U^2) ~ 7e5 for U ~ 0.012 m/s), 32 cells, t <= 2.
#  - semi-implicit: no more than 1.2 x the steps of the same case without
#    bodies (measured: 219 and 219),
#  - explicit (elastic Courant limited: measured 2566 steps), solved
#    coupled every step as the semi-implicit variant's iterated steps
#    are: the semi-implicit run converges to it at first order in dt.
#    Q 7.57938e-3 at 10 ms, 7.59237e-3 at 5 ms, explicit 7.60409e-3: the
#    difference falls to 0.47 of itself (bound 0.7), and the pair's
#    extrapolation 2 Q(5 ms) - Q(10 ms) is the explicit Q within 1.7e-4
#    (bound 5e-4).  At the flow step the two are 0.32 % apart: a KNOWN
#    line against the issue's 0.15 %,
#  - the stiff disks keep their shape: max |dev B| below 0.01 (measured
#    4.1e-3).
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
# the explicit variant's.  Since the disks' stress lives at the cell
# centres inside them (vhe_body_weight) their Q is 4.7 % higher (7.24e-3
# before; rigid disks 7.83e-3) and the semi-implicit step's first-order
# error in dt is 0.32 % (0.14 % before, converging faster than first
# order: the old edge cells' viscous skin moved with the step too)
n0=$(steps none); ns=$(steps semiImplicit); ne=$(steps explicit)
check stiffAtFlowStep "$ns <= 1.2*$n0" "semi-implicit $ns steps, no bodies $n0, explicit $ne"
qs=$(lastQ semiImplicit); qe=$(lastQ explicit)
qh=$(lastQ halfStep)
checkKnown stiffVariantsAgree "abs($qs/$qe - 1) < 1.5e-3" "abs($qs/$qe - 1) < 5e-3" \
    "Q semi-implicit $qs, explicit $qe" \
    "first order in dt: 0.15 % at half the step, docs/limitations.md"
check stiffVariantsConverge "abs($qh - $qe) < 0.7*abs($qs - $qe)" "Q semi-implicit at half the step $qh: difference $(python3 -c "print('%.2f' % (abs($qh - $qe)/abs($qs - $qe)))") of the full step's"
check stiffVariantsExtrapolate "abs((2*$qh - $qs)/$qe - 1) < 5e-4" \
    "Q extrapolated from the two steps $(python3 -c "print('%.6g' % (2*$qh - $qs))"), explicit $qe"
# The step's coupling (stepCoupling): a stiff disk (G/(rho U^2) = 1e5) in
# plane Couette flow at a viscous number of 10 turns with the flow (with
# one pass of the prediction and projection it turned at 0.089: the lagged
# transpose part of its stress increment resisted rotation as an inertia
# of dt Ghat/dx^2).  Its outline carried geometrically and its stress at
# the cell centres inside it (vhe_body_weight), it turns at 0.975 of half
# the vorticity at 32 cells and 0.978 at 64 (a rigid disk 0.984, 0.982;
# 0.964 and 0.974 when every cell of its edge carried G phi_s).  Its wall
# stress 1.088 at 32 cells, 1.073 at 64, approaches the rigid disk's
# (1.057, 1.065): 1.139 and 1.094 before; a KNOWN line at 32 cells
couette="$VHE_ROOT/benchmarks/rigid/couette.sh"
for b in 100000 rigid; do
    "$couette" "$WORK/couette_$b" 32 "$b" 10 0.5 || fail "couette_$b" "$WORK/couette_$b/log.vheFoam"
done
read -r _ tauS wS _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_100000" 32)"
read -r _ tauR wR _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_rigid" 32)"
passes=$(grep Coupling "$WORK/couette_100000/log.vheFoam" | awk '{s += $2} END {if (NR) printf "%.1f", s/NR; else print 1}')
checkKnown stiffDiskTurns "-($wS) > 0.97" "-($wS) > 0.9" \
    "stiff disk's rotation rate over half the vorticity $(python3 -c "print(-($wS))") (rigid $(python3 -c "print(-($wR))")), $passes passes a step" \
    "0.978 at 64 cells, docs/limitations.md"
checkKnown stiffRigidStress "abs($tauS/$tauR - 1) < 0.02" "abs($tauS/$tauR - 1) < 0.08" \
    "wall stress over the body-free flow's: stiff $tauS, rigid $tauR" \
    "the body's edge carries stress from a quarter cell outside its outline, and the rigid disk keeps the projection's leak: 1.073 against 1.065 at 64 cells, docs/limitations.md"
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
