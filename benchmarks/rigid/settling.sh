#!/bin/bash
# settling.sh DIR CELLS_PER_DIAMETER [ENDTIME [RHO_S NU]]: Glowinski et
# al. (2001)'s settling disk, in SI units: channel 0.02 x 0.06 m of liquid
# (rho 1000, nu NU), disk d = 2.5e-3 m of rho RHO_S released at rest at
# (0.01, 0.04), g 9.81.  The higher Reynolds number's case by default
# (RHO_S 1500, NU 1e-6: largest Re 440 to 503 published); the lower's is
# RHO_S 1250, NU 1e-5 (largest Re about 17).  The floatingBodies
# template with the tank full of water; run on 2 ranks (decomposed in y).
# The disk's track is DIR/postProcessing/bodies/0/bodies.dat (every
# 0.01 s); settling.py reads it.  GAMG for the pressure.
. "$(dirname "$0")/tank.sh"
d=$1 n=$2 tend=${3:-0.6} rhoS=${4:-1500} nu=${5:-1e-6}
nx=$(python3 -c "print(round(0.02/(0.0025/$n)))")
tankCase "$d" 0.02 0.06 "$nx" $((3*nx)) "$rhoS" "$tend" 0.002 \
    "disk { material wood; shape disk; centre (0.01 0.04 0); radius 0.00125; }" \
    "$nu" || exit 1
tankGAMG "$d" || exit 1
tankRun "$d"
