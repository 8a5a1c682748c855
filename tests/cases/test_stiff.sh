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
#    step capped at 5 ms instead of 10 ms the difference falls to 0.26
#    of itself (Q 7.49102e-3, 7.49877e-3 at 10, 5 ms; explicit
#    7.50145e-3; bound 0.7; 7.24e-3 when the disks' edge cells were
#    stiff in proportion to phi_s and the disks acted larger),
#  - the stiff disks keep their shape: max |dev B| below 0.01 (measured
#    4.6e-3).
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
# the explicit variant's.
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
# of dt Ghat/dx^2; its coupled steps now take that part in their matrix,
# 2.3 passes a step).  Its stress lives at the cell centres inside it
# (vhe_body_weight): stressed in proportion to phi_s its edge cells were
# rigid down to small fractions and it acted half a cell larger, turning
# at 0.964 of half the vorticity with a wall stress of 1.139 at 32 cells;
# now 0.975 and 1.089, the rigid disk 1.0623 (below).
couette="$VHE_ROOT/benchmarks/rigid/couette.sh"
for b in 100000 rigid; do
    "$couette" "$WORK/couette_$b" 32 "$b" 10 0.5 || fail "couette_$b" "$WORK/couette_$b/log.vheFoam"
done
# Rigid bodies are held in the coupled step's matrix, their velocities
# unknowns of it (coupledRigidRows): the disk's wall stress is the same at
# viscous numbers 10 and 1000 (measured 1.0623 and 1.0623; held rigid
# inside the prediction and projected after it, coupling { solve stiff; },
# 1.057 and 1.039: the projection's damping leaked in proportion to the
# step)
"$couette" "$WORK/rigid_1000" 32 rigid 1000 0.5 || fail rigid_1000 "$WORK/rigid_1000/log.vheFoam"
read -r _ tauS wS _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_100000" 32)"
read -r _ tauR wR _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/couette_rigid" 32)"
read -r _ tau1000 _ <<< "$(python3 "$VHE_ROOT/benchmarks/rigid/couette.py" "$WORK/rigid_1000" 32)"
passes=$(grep Coupling "$WORK/couette_100000/log.vheFoam" | awk '{s += $2} END {if (NR) printf "%.1f", s/NR; else print 1}')
check stiffDiskTurns "-($wS) > 0.97" \
    "stiff disk's rotation rate over half the vorticity $(python3 -c "print(-($wS))") (rigid $(python3 -c "print(-($wR))")), $passes passes a step"
# The rigid disk's edge is a wall (rigidBodies::edge): its wall stress
# converges with the mesh, 1.0623, 1.0650, 1.0654 at 32, 64, 128 cells
# (benchmarks/rigid/couette.sh, viscous number 10).  The stiff disk's
# edge cells, stressed down to a quarter of a cell outside its outline,
# make it act larger by a first-order skin: 1.0885, 1.0871, 1.0750, so
# +2.5, +2.1, +0.9 % over the rigid disk (target 2 %, issue 24; while the
# rigid disk had a diffuse edge of its own, 1.0681 at 32 cells, the two
# agreed within 1.9 %)
checkKnown stiffRigidStress "abs($tauS/$tauR - 1) < 0.02" "abs($tauS/$tauR - 1) < 0.03" \
    "wall stress over the body-free flow's: stiff $tauS, rigid $tauR" \
    "the stiff disk's edge skin, first order in the cell: +0.9 % at 128 cells, docs/limitations.md"
check rigidStepFree "abs($tau1000/$tauR - 1) < 1e-3" \
    "rigid disk's wall stress at viscous numbers 10 and 1000: $tauR, $tau1000"
devB=$(awk '!/^#/{m = $3} END {print m}' "$WORK/semiImplicit/postProcessing/solidDiagnostics/0/solidDiagnostics.dat")
check stiffKeepShape "$devB < 0.01" "max |dev B| at t = 2: $devB"
finish
