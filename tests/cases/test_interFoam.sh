#!/bin/bash
# No solids: vheFoam against Debian's interFoam (v1912) on the same case,
# the scene B dam break without spheres at 21 x 10 x 10 cells to t = 0.5
# (liquid/gas, density ratio 1000, nu 1e-2, no surface tension; interFoam
# as its damBreak tutorial runs: PISO, 3 correctors, no momentum predictor).
# vheFoam's projection (pEqn.H) is a different discretisation of the same
# equations, so the two differ by a discretisation error, which the check
# bounds by interFoam's own: its change from this mesh to the mesh twice
# as fine (restricted to this one).  Measured (mean over cells):
#   |alpha vheFoam - interFoam| 0.0077 against interFoam's mesh change
#   0.0097; |U| difference 0.096 m/s against 0.183 m/s; liquid centroid
#   x/L 0.4964 and 0.4969 against 0.4947 on the fine mesh.
# Bounds: 1.5 x interFoam's mesh change for alpha and U; the centroids
# closer than interFoam's coarse and fine meshes are to each other.
# vheFoam's step count stays within 10 % of interFoam's.
. "$(dirname "$0")/lib.sh"

setupPair() {
    local vhe=$1 inter=$2; shift 2
    sceneCase damBreakSpheres "$vhe" "$@" endTime=0.5 writeInterval=0.5 \
        nSpheres=0 || return 1
    tightSolvers "$vhe" 1e-10
    run "$vhe" setFields || return 1
    # The same case for interFoam (bin/vheToInterFoam)
    "$VHE_ROOT/bin/vheToInterFoam" "$vhe" "$inter" > /dev/null
}
vhe="$WORK/vheFoam" inter="$WORK/interFoam" fine="$WORK/interFoamFine"
setupPair "$vhe" "$inter" n1=21 n2=10 n3=10 || { fail setup "$vhe"; finish; }
setupPair "$WORK/vheFoamFine" "$fine" n1=42 n2=20 n3=20 || { fail setup "$fine"; finish; }

run "$vhe" vheFoam || fail vheFoamRun "$vhe/log.vheFoam"
run "$inter" interFoam || fail interFoamRun "$inter/log.interFoam"
run "$fine" interFoam || fail interFoamRun "$fine/log.interFoam"

sv=$(grep -c "^Time = " "$vhe/log.vheFoam"); si=$(grep -c "^Time = " "$inter/log.interFoam")
check similarSteps "abs($sv - $si) <= 0.1*$si" "vheFoam $sv steps, interFoam $si steps"
read -r da du daf duf xv xi xf <<< \
    "$(cd "$TESTS_DIR" && python3 coarseDiff.py 0.5 21 10 10 "$vhe" "$inter" "$fine")"
check alphaWithinMeshError "$da < 1.5*$daf" \
    "mean |alpha vheFoam - interFoam| $da, interFoam coarse - fine $daf"
check velocityWithinMeshError "$du < 1.5*$duf" \
    "mean |U vheFoam - interFoam| $du, interFoam coarse - fine $duf"
check centroidWithinMeshError "abs($xv - $xi) < abs($xi - $xf)" \
    "liquid centroid x/L: vheFoam $xv, interFoam $xi, interFoam fine $xf"
finish
