#!/bin/bash
# dkt.sh DIR CELLS_PER_DIAMETER [ENDTIME]: Glowinski et al. (2001)'s
# drafting, kissing and tumbling of two disks, in SI units: channel
# 0.02 x 0.08 m of liquid (rho 1000, nu 1e-6), two rigid disks of d = 2e-3
# m and rho 1010 released at rest at (0.01, 0.072) and (0.0103, 0.068)
# (the lower one offset by 0.03 cm), g 9.81.  The floatingBodies template
# with the tank full of water and its contact { strength 0.5; }; run on 2
# ranks (decomposed in y).  dkt.py reads DIR/postProcessing/bodies/0/
# bodies.dat (every 0.01 s).
. "$(dirname "$0")/tank.sh"
d=$1 n=$2 tend=${3:-5}
tankCase "$d" 0.02 0.08 $((10*n)) $((40*n)) 1010 "$tend" 0.005 \
    "upper { material wood; shape disk; centre (0.01 0.072 0); radius 0.001; }
       lower { material wood; shape disk; centre (0.0103 0.068 0); radius 0.001; }" \
    || exit 1
tankGAMG "$d" || exit 1
tankRun "$d"
