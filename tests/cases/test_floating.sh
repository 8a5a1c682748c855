#!/bin/bash
# Floating and sinking bodies and three fluids (seed 003), from the
# floatingBlock tutorial's template on a 40 x 40 tank (dx = 0.025):
#  - Archimedes: a stiff box (G/rho_s = 10 m^2/s^2, rigid-like: G/(rho U^2)
#    ~ 1e3), rho_s = 500 in water (nu 1e-2) under air, 0.3 wide and 0.1
#    tall (wide enough to float upright: a square of this density floats
#    corner down), released at half its draft.  Its mean draft over
#    2 <= t <= 3 must be the Archimedes one, (rho_s - rho_air)/(rho_water -
#    rho_air) x height = 0.04995 m, within 0.5 % of its height (KNOWN:
#    measured 0.04922, 0.73 % of the height high; 0.54 % once settled, t = 6
#    to 8, and 0.46 % on 80 x 80 cells; ten times stiffer, 3 %:
#    docs/limitations.md, benchmarks/rigid/floating.sh).
#  - a box of rho_s = 2000 sinks: its lowest point falls from 0.3 m to
#    within 0.075 m of the floor by t = 2 (measured 0.031: the last film of
#    water drains slowly, as it should), never moving up.
#  - the Archimedes box ten times stiffer (G/rho_s = 100, elastic Courant about
#    2 at the flow step): no spurious air currents, the largest air speed
#    at t = 3 below 0.1 m/s (measured 0.009, 0.018 before the coupled
#    step interpolated rho/A a_c as one; 4.9 before the semi-implicit
#    increment's explicit part was weighted down at body/gas faces).
#  - three fluids and a body: the tutorial's soft disk sinking through oil
#    onto water; alphas in [0, 1] within 1e-6 (measured -1e-9); every
#    phase volume conserved to 1e-6 relative (measured 6e-8), and in the
#    Archimedes and sinking cases.
. "$(dirname "$0")/lib.sh"

box=(nx=40 ny=40 depthOil=0 depthWater=0.5 shape=box blockWidth=0.3
     blockHeight=0.1 nuWater=1e-2 writeInterval=0.5)
setup() {
    local d="$WORK/$1"; shift
    sceneCase floatingBlock "$d" "$@" && run "$d" setFields && run "$d" setBodies \
        || fail setup "$d"
    run "$d" vheFoam || fail "$(basename "$d")Run" "$d/log.vheFoam"
}
setup archimedes "${box[@]}" blockBottom=0.475 rhoSolid=500 endTime=3 GperRho=10
setup stiff "${box[@]}" blockBottom=0.475 rhoSolid=500 endTime=3 GperRho=100
setup sinking "${box[@]}" blockBottom=0.3 rhoSolid=2000 endTime=2 GperRho=10
setup threeFluids nx=40 ny=40 endTime=1.5 writeInterval=0.5

figure() { python3 "$TESTS_DIR/floating.py" "$@"; }

exact=$(python3 -c "print((500 - 1)/(1000 - 1)*0.1)")
draft=$(figure draft "$WORK/archimedes" 0.1 2)
# A stiff elastic box floats high (G/rho_s 10: 0.73 % of its height over
# 2 <= t <= 3, 0.54 % settled, 0.46 % at 80 cells; 2.1 % with MULES's
# diffuse edge, 0.94 % and 2.3 % while its edge cells were stressed in
# proportion to phi_s).  Its side columns keep the water's slide past them
# as a shear strain, and their face stress hangs the box on the water
# beside it: the error grows with G (3 % at G/rho_s 100).  A rigid box
# floats at the Archimedes draft within 0.5 % of its height (test_rigid).
# Target 0.5 % (issue 24)
checkKnown archimedesDraft "abs($draft - $exact) < 0.005*0.1" "abs($draft - $exact) < 0.03*0.1" \
    "draft $draft m, Archimedes $exact m (height 0.1 m)" \
    "its edge cells keep the water's slide past them as a strain that holds it up, docs/limitations.md"

air=$(figure airSpeed "$WORK/stiff" 3)
check stiffBodyQuietAir "$air < 0.1" "largest air speed $air m/s around a box of G/rho_s = 100"

read -r bottom0 bottom1 maxUp <<< "$(figure sink "$WORK/sinking" 0.1)"
check heavyBodySinks "$bottom0 > 0.29 and $bottom1 < 0.075 and $maxUp <= 0" \
    "lowest point $bottom0 -> $bottom1 m, largest upward velocity $maxUp m/s"

for c in archimedes sinking threeFluids; do
    drift=$(figure volumes "$WORK/$c")
    check "${c}Volumes" "$drift < 1e-12" "largest relative phase volume drift $drift"
done
read -r lo hi <<< "$(alphaRange "$WORK/threeFluids/log.vheFoam")"
check threeFluidsBounded "$lo > -1e-6 and $hi < 1 + 1e-6" "alpha in [$lo, $hi]"
finish
