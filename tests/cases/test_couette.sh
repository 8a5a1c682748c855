#!/bin/bash
# Oscillating Couette flow, fluid (mu 1) over a purely elastic solid layer
# (mu 0, G 5) -- Sugiyama et al. 2011, REFERENCE.md verification 1 -- at 40
# cells with the interface on a cell face, semi-implicit elasticity,
# dt = 1e-3: RMS over the period 10 <= t <= 12 of the L2 errors of u and of
# the shear strain B_xy against the exact solution (C core); the
# fluid/solid/fluid variant (system/threeLayers, V = 0.4) at 30 cells,
# dt = 4e-3, over 18 <= t <= 20; the experimental elasticStabilisation 1
# on the two-layer case (40 cells, dt = 1e-3).  Bounds: 1.2 x the values
# measured when the checks were written (u, B_xy: 7.26e-3, 1.50e-2;
# 4.33e-3, 7.61e-2; 2.22e-3, 1.85e-3).  Measured since the stretch takes
# the deviatoric velocity gradient: 7.27e-3, 1.50e-2; 4.45e-3, 7.74e-2;
# 1.68e-3, 1.36e-3.
. "$(dirname "$0")/lib.sh"

# couette NAME KEY=VALUE... [include=FILE]: the study's Couette case with
# the given parameters (then system/FILE's), run in $WORK/NAME; prints the
# RMS over the error window of the L2 errors of u and B_xy
couette() {
    local d="$WORK/$1" kv include=""; shift
    cp -r "$VHE_ROOT/benchmarks/errorVsRuntime/couette" "$d"
    for kv in "$@"; do
        case $kv in
            include=*) include=${kv#include=} ;;
            *) foamDictionary -entry "${kv%%=*}" -set "${kv#*=}" "$d/system/parameters" > /dev/null ;;
        esac
    done
    [ -z "$include" ] || echo "#include \"$include\"" >> "$d/system/parameters"
    run "$d" blockMesh && run "$d" setBodies && run "$d" vheFoam || return 1
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

out=$(couette stabilised N=40 stabilisation=1) \
    || { fail stabilisedRun "$WORK/stabilised"; finish; }
read -r eu eb <<< "$out"
check stabilisedVelocity "$eu < 1.2*2.22e-3" "elasticStabilisation 1: RMS L2 error of u over a period: $eu"
check stabilisedStrain "$eb < 1.2*1.85e-3" "elasticStabilisation 1: RMS L2 error of B_xy: $eb"
finish
