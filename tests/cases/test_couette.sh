#!/bin/bash
# Oscillating Couette flow, fluid (mu 1) over a purely elastic solid layer
# (mu 0, G 5) -- Sugiyama et al. 2011, REFERENCE.md verification 1 -- at 40
# cells with the interface on a cell face, semi-implicit elasticity,
# dt = 1e-3: RMS over the period 10 <= t <= 12 of the L2 errors of u and of
# the shear strain B_xy against the exact solution (C core); the
# fluid/solid/fluid variant (system/threeLayers, V = 0.4) at 30 cells,
# dt = 4e-3, over 18 <= t <= 20 (bounds 1.2 x the values measured when
# the checks were written: u, B_xy 7.26e-3, 1.50e-2; 4.33e-3, 7.61e-2;
# now 7.35e-3, 1.50e-2; 4.70e-3, 8.04e-2).  The experimental
# elasticStabilisation 0.1 with Euler and with backward, and its
# order with the interface on a face: bounds 1.2 x the values measured
# since the stretch takes the flux as the face-normal velocity
# (vheElasticity::velocityGradient).
. "$(dirname "$0")/lib.sh"

# couette NAME KEY=VALUE... [include=FILE]: the study's Couette case with
# the given parameters (then system/FILE's), run in $WORK/NAME; prints the
# RMS over the error window of the L2 errors of u and B_xy
couette() {
    local d="$WORK/$1" kv include="" np=1; shift
    cp -r "$VHE_ROOT/benchmarks/errorVsRuntime/couette" "$d"
    for kv in "$@"; do
        case $kv in
            include=*) include=${kv#include=} ;;
            np=*) np=${kv#np=} ;;
            *) foamDictionary -entry "${kv%%=*}" -set "${kv#*=}" "$d/system/parameters" > /dev/null ;;
        esac
    done
    [ -z "$include" ] || echo "#include \"$include\"" >> "$d/system/parameters"
    run "$d" blockMesh && run "$d" setBodies || return 1
    if [ "$np" = 1 ]; then
        run "$d" vheFoam || return 1
    else
        run "$d" decomposePar && (cd "$d" && mpirun -np "$np" vheFoam -parallel > log.vheFoam 2>&1) || return 1
    fi
    tail -1 "$d/postProcessing/couetteError/0/couetteError.dat" | awk '{print $6, $8}'
}

out=$(couette couette N=40) || { fail couetteRun "$WORK/couette"; finish; }
read -r eu eb <<< "$out"
check couetteVelocity "$eu < 1.2*7.26e-3" "RMS L2 error of u over a period: $eu (amplitude 1)"
check couetteStrain "$eb < 1.2*1.50e-2" "RMS L2 error of B_xy in the solid: $eb"

out=$(couette threeLayers N=30 deltaT=4e-3 include=threeLayers) \
    || { fail threeLayersRun "$WORK/threeLayers"; finish; }
read -r eu eb <<< "$out"
check threeLayersVelocity "$eu < 1.2*4.33e-3" "fluid/solid/fluid: RMS L2 error of u over a period: $eu (amplitude 0.4)"
check threeLayersStrain "$eb < 1.2*7.61e-2" "fluid/solid/fluid: RMS L2 error of B_xy in the solid: $eb"

# The experimental stabilisation at 0.1, the coefficient that keeps the
# interface second order (1 leaves an O(dx) error in the last two solid
# cells: README, Verification)
S=0.1
out=$(couette stabilised N=40 stabilisation=$S) \
    || { fail stabilisedRun "$WORK/stabilised"; finish; }
read -r eu eb <<< "$out"
check stabilisedVelocity "$eu < 1.2*7.93e-4" "elasticStabilisation $S: RMS L2 error of u over a period: $eu"
check stabilisedStrain "$eb < 1.2*5.72e-4" "elasticStabilisation $S: RMS L2 error of B_xy: $eb"

# The backward scheme (ddtSchemes backward, BDF2) at 20 and 40 cells with
# dt = 0.08/N: second order in space and time with the interface on a face
out=$(couette bdf2_20 N=20 deltaT=4e-3 stabilisation=$S ddtScheme=backward) \
    || { fail bdf2Run "$WORK/bdf2_20"; finish; }
read -r e20 eb <<< "$out"
out=$(couette bdf2 N=40 deltaT=2e-3 stabilisation=$S ddtScheme=backward) \
    || { fail bdf2Run "$WORK/bdf2"; finish; }
read -r eu eb <<< "$out"
check bdf2Velocity "$eu < 1.2*1.62e-4" "backward (BDF2), dt 2e-3: RMS L2 error of u over a period: $eu"
check bdf2Strain "$eb < 1.2*9.05e-5" "backward (BDF2), dt 2e-3: RMS L2 error of B_xy: $eb"
eb2=$eb eu2=$eu
check bdf2Order "math.log($e20/$eu, 2) > 1.8" "interface on a face, backward: order of u from 20 to 40 cells (dt halved too) $(python3 -c "import math; print(round(math.log($e20/$eu, 2), 2))")"

# The same on 2 ranks split across y (system/decomposeParDict): the
# processor boundary is the interface, where the stabilisation's face
# stress and face velocity need the other side's stress gradient
# (measured: the errors agree with the serial ones to 6e-6)
out=$(couette bdf2_np2 N=40 deltaT=2e-3 stabilisation=$S ddtScheme=backward np=2) \
    || { fail bdf2ParallelRun "$WORK/bdf2_np2"; finish; }
read -r eu eb <<< "$out"
check bdf2Parallel "abs($eu/$eu2 - 1) < 1e-4 and abs($eb/$eb2 - 1) < 1e-4" \
    "2 ranks, the interface on the processor boundary: u $eu, B_xy $eb (serial $eu2, $eb2)"

# A viscoelastic solid filling the gap (no interface), backward scheme
# with dt = 0.08/N: second order in space and time together (measured
# 6.9e-4 at 20 cells, 1.72e-4 at 40: order 2.0)
out=$(couette gap20 N=20 deltaT=4e-3 stabilisation=$S ddtScheme=backward include=viscoelasticGap) \
    || { fail solidGapRun "$WORK/gap20"; finish; }
read -r e20 eb <<< "$out"
out=$(couette gap40 N=40 deltaT=2e-3 stabilisation=$S ddtScheme=backward include=viscoelasticGap) \
    || { fail solidGapRun "$WORK/gap40"; finish; }
read -r e40 eb <<< "$out"
check solidGapVelocity "$e40 < 1.2*1.72e-4" "viscoelastic gap, 40 cells: RMS L2 error of u over a period: $e40"
check solidGapOrder "math.log($e20/$e40, 2) > 1.8" "viscoelastic gap: order of u from 20 to 40 cells (dt halved too) $(python3 -c "import math; print(round(math.log($e20/$e40, 2), 2))")"

# Time error alone: the final u with dt = 4 and 2 ms differ (the spatial
# error cancels).  At 20 cells backward's difference over Euler's was
# measured 0.039 (0.179 before the stretch took the flux as its
# face-normal velocity).  Backward's difference halves, not quarters, per
# halving of dt at a fixed mesh, but it also halves with dx at a fixed dt
# (measured 0.48 from 20 to 40 cells): an O(dt dx) term (the interface
# and stabilisation weights take the stress viscosity tau Ghat phi_s),
# second order when dt falls with dx.
for run in Euler_20 backward_20 backward_40; do
    for dt in 4e-3 2e-3; do
        couette "time_${run}_$dt" N=${run#*_} deltaT=$dt stabilisation=$S ddtScheme=${run%_*} endTime=6 > /dev/null \
            || { fail timeRun "$WORK/time_${run}_$dt"; finish; }
    done
done
read -r ratio meshRatio <<< "$(python3 - "$WORK" <<'PY'
import math, sys
def u(d):
    body = open(f"{sys.argv[1]}/{d}/6/U").read().split("internalField", 1)[1].split("boundaryField")[0]
    return [float(l.split()[0][1:]) for l in body.split("\n") if l.startswith("(") and len(l) > 1]
def diff(run):
    a, b = u(f"time_{run}_4e-3"), u(f"time_{run}_2e-3")
    return math.sqrt(sum((p - q) ** 2 for p, q in zip(a, b)) / len(a))
print(diff("backward_20") / diff("Euler_20"), diff("backward_40") / diff("backward_20"))
PY
)"
check bdf2TimeError "$ratio < 1.2*0.039" "time error (final u, dt 4 vs 2 ms, 20 cells) of backward over Euler: $ratio"
check bdf2TimeErrorMesh "$meshRatio < 0.6" "backward's time error (dt 4 vs 2 ms) at 40 cells over 20 cells: $meshRatio"
finish
