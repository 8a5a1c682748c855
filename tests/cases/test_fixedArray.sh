#!/bin/bash
# Held rigid bodies (solids { <name> { rigid yes; motion fixed; } }, or
# motion prescribed), their edge a wall (the cells whose centres are
# inside held, the fluid cells beside them given the wall's viscous stress
# at the surface).  Stokes flow through a square array of fixed cylinders,
# driven by a body force, against Sangani & Acrivos (1982): F/(mu U) =
# 51.53 at area fraction 0.2 (benchmarks/rigid/squareArray.sh, F = f rho
# L^2, U the mean velocity over the cell).  The convergence study
# (benchmarks/rigid: 16, 32, 64, 128 cells: -2.58, -0.03, +0.14, +0.10 %;
# at area fractions 0.05 to 0.3 within 0.87 % at 32 cells and 0.23 % at
# 64, second order from 16 to 64 at 0.05) sets the bounds: within 1.5 % at
# 32 cells and 0.5 % at 64.  (With the weight min(1, 4
# alpha) of a free body's edge: -7.09, -0.75, +1.08, +0.83 %, not
# monotone from 32 cells on.)  The cylinder's volume is its initial one
# to round-off, the liquid's too, and the fluid's force on it
# (postProcessing/fixedBodies) is the body force on the liquid, f rho
# V_liquid, within 1e-3 (measured 1e-10 at 64 cells).
. "$(dirname "$0")/lib.sh"

for n in 32 64; do
    bash "$VHE_ROOT/benchmarks/rigid/squareArray.sh" "$WORK/n$n" "$n" 0.2 1 \
        || fail "run$n" "squareArray.sh $n cells failed"
done
read -r e32 v32 < <(python3 "$VHE_ROOT/benchmarks/rigid/squareArray.py" "$WORK/n32" \
    | awk 'NR == 2 {print $6, $7}')
read -r k64 e64 v64 < <(python3 "$VHE_ROOT/benchmarks/rigid/squareArray.py" "$WORK/n64" \
    | awk 'NR == 2 {print $3, $6, $7}')
check sanganiAcrivos "abs($e64) < 0.005" "F/(mu U) = $k64 at 64 cells against 51.53 ($e64)"
check sanganiAcrivos32 "abs($e32) < 0.015" "error $e32 at 32 cells, $e64 at 64"
# The fluid's force on the cylinder (postProcessing/fixedBodies) balances
# the body force on the liquid at steady state: f rho (liquid volume)
fx=$(awk '!/^#/ {f = $3} END {print f}' "$WORK/n64/postProcessing/fixedBodies/0/forces.dat")
vl=$(grep "^Phase liquid volume" "$WORK/n64/log.vheFoam" | awk '{v = $4} END {print v}')
check fixedForce "abs($fx/(0.1*$vl) - 1) < 1e-3" "force $fx N against f rho V_liquid = $(python3 -c "print(0.1*$vl)") N"
lv=$(grep "^Phase liquid volume" "$WORK/n64/log.vheFoam" \
    | awk 'NR == 1 {a = $4} {d = $4 - a; if (d < 0) d = -d; if (d > m) m = d} END {print m + 0}')
check fixedVolumes "$v64 < 1e-12 and $lv < 1e-12" "cylinder volume change $v64, liquid $lv"

# A disk moved along the axis of a closed channel 8 diameters wide in
# Stokes flow (benchmarks/rigid/faxen.sh, Re 1e-3, to t = 1): F/(mu U)
# against Faxen's 10.558 for a cylinder midway between plane walls.
# Measured -0.47 % at 8 cells across, -0.03 % at 16 (with the weight min(1,
# 4 alpha) -1.43 % and -0.25 %; held rigid inside the prediction and
# projected after it, -8.4 %, -3.5 %); bounds: within 0.25 % at 16 cells,
# closer than at 8
for n in 8 16; do
    bash "$VHE_ROOT/benchmarks/rigid/faxen.sh" "$WORK/faxen$n" "$n" 1.0 \
        || fail "faxenRun$n" "$WORK/faxen$n/log.vheFoam"
done
read -r _ k8 e8 < <(python3 "$VHE_ROOT/benchmarks/rigid/faxen.py" "$WORK/faxen8")
read -r _ k16 e16 < <(python3 "$VHE_ROOT/benchmarks/rigid/faxen.py" "$WORK/faxen16")
check faxenDrag "abs($e16) < 0.0025 and abs($e16) < abs($e8)" \
    "F/(mu U) = $k16 at 16 cells ($e16), $k8 at 8 ($e8), Faxen 10.558"
finish
