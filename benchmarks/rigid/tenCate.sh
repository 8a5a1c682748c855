#!/bin/bash
# tenCate.sh DIR CASE [CELLS_PER_D]: a rigid sphere settling in a closed
# box, ten Cate et al. (2002, Phys. Fluids 14, 4012): box 100 x 100 x 160
# mm (x, z across, y up), sphere d = 15 mm, rho_s 1120 kg/m^3, released
# from rest with its lowest point 120 mm above the floor (centre at 127.5
# mm), in silicone oil (CASE: rho_f kg/m^3, mu Pa s, u_inf m/s, Re):
#   E1  970 0.373 0.038  1.5      E3  962 0.113 0.091 11.6
#   E2  965 0.212 0.060  4.1      E4  960 0.058 0.128 31.9
# u_inf is the paper's table's terminal velocity in an unbounded liquid,
# not a velocity measured in the box: Abraham's drag correlation, Cd =
# 24/9.06^2 (1 + 9.06/Re^(1/2))^2, at u_inf balances the sphere's weight
# less its buoyancy within 0.8 % in all four cases.  In the box the walls
# slow the sphere (in Stokes flow a tube of the box's width would slow it
# by about 30 %); the paper's measured velocities are in its figures.
# CELLS_PER_D cells across the sphere (8 by default: 53 x 85 x 53 cells).
# No-slip walls all round (the top too), g 9.81, the user's defaults
# otherwise (the floatingBlock template: one outer iteration, maxCo 0.5,
# maxDeltaT 0.005 s).  Writes DIR/velocity.dat (t, settling velocity,
# centre height) from postProcessing/rigidBodies/0/poses.dat and prints
# the largest settling velocity against u_inf.  About
# 4 min for E4 at 6 cells, 10 at 8, 12 for E1 at 6 (serial, one core).
. "$(dirname "$0")/tank.sh"
d=$1 c=$2 n=${3:-8}
case $c in
    E1) rho=970 mu=0.373 uInf=0.038 tEnd=4.5 ;;
    E2) rho=965 mu=0.212 uInf=0.060 tEnd=3 ;;
    E3) rho=962 mu=0.113 uInf=0.091 tEnd=2 ;;
    E4) rho=960 mu=0.058 uInf=0.128 tEnd=1.5 ;;
    *) echo "Usage: $0 DIR E1|E2|E3|E4 [CELLS_PER_D]" >&2; exit 1 ;;
esac
tenCateSphere "$d" 0.1 0.16 "$n" "$rho" "$mu" 0.1275 "$tEnd" || exit 1
(run "$d" blockMesh && run "$d" setFields && run "$d" setBodies && run "$d" vheFoam) \
    || { echo "failed: $d" >&2; exit 1; }
awk '!/^#/ {print $1, -$7, $4}' "$d/postProcessing/rigidBodies/0/poses.dat" > "$d/velocity.dat"
awk -v c="$c" -v n="$n" -v u="$uInf" -v mu="$mu" -v rho="$rho" '
    $2 > m {m = $2; t = $1} END {
    printf "%s, %d cells per d: largest settling velocity %.4f m/s at t = %.3f s (Re %.2f), u_inf (unbounded) %.3f: %+.1f %%\n",
        c, n, m, t, rho*m*0.015/mu, u, 100*(m - u)/u}' "$d/velocity.dat"
