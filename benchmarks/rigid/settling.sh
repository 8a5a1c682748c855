#!/bin/bash
# settling.sh DIR CELLS_PER_DIAMETER [ENDTIME]: Glowinski et al. (2001)'s
# settling disk at the higher Reynolds number, in SI units: channel
# 0.02 x 0.06 m of liquid (rho 1000, nu 1e-6), disk d = 2.5e-3 m of
# rho 1500 released at rest at (0.01, 0.04), g 9.81.  The floatingBodies
# template with the tank full of water; run on 2 ranks (decomposed in y).
# The disk's track is DIR/postProcessing/bodies/0/bodies.dat (every
# 0.01 s); settling.py reads it.  GAMG for the pressure.
. "$(dirname "$0")/tank.sh"
d=$1 n=$2 tend=${3:-0.6}
nx=$(python3 -c "print(round(0.02/(0.0025/$n)))")
tankCase "$d" 0.02 0.06 "$nx" $((3*nx)) 1500 "$tend" 0.002 \
    "disk { material wood; shape disk; centre (0.01 0.04 0); radius 0.00125; }" \
    || exit 1
tankGAMG "$d" || exit 1
tankRun "$d"
