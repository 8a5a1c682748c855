#!/bin/bash
# settling.sh DIR CELLS_PER_DIAMETER [ENDTIME]: Glowinski et al. (2001)'s
# settling disk at the higher Reynolds number, in SI units: channel
# 0.02 x 0.06 m of liquid (rho 1000, nu 1e-6), disk d = 2.5e-3 m of
# rho 1500 released at rest at (0.01, 0.04), g 9.81.  The floatingBodies
# template with the tank full of water; run on 2 ranks (decomposed in y).
# The disk's track is DIR/postProcessing/bodies/0/bodies.dat (every
# 0.01 s); settling.py reads it.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=$2 tend=${3:-0.6}
nx=$(python3 -c "print(round(0.02/(0.0025/$n)))")
ny=$((3*nx))
rm -rf "$d"
sceneCase floatingBodies "$d" W=0.02 H=0.06 nx="$nx" ny="$ny" \
    depthWater=0.07 rhoWater=1000 nuWater=1e-6 nuAir=1e-6 \
    rhoWood=1500 nuWood=1e-6 endTime="$tend" writeInterval=0.01 \
    maxDeltaT=0.002 || exit 1
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { disk { material wood; shape disk; centre (0.01 0.04 0); radius 0.00125; } }
DICT
sed -i 's/n (2 1 1)/n (1 2 1)/' "$d/system/decomposeParDict"
(cd "$d" && setFields > log.setFields 2>&1 && setBodies > log.setBodies 2>&1 \
    && decomposePar > log.decomposePar 2>&1) || exit 1
(cd "$d" && mpirun -np 2 vheFoam -parallel > log.vheFoam 2>&1)
