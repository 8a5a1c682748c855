#!/bin/bash
# jeffery.sh DIR CELLS [ENDTIME]: a free, neutrally buoyant rigid ellipse
# (semi-axes 0.15 and 0.075, aspect ratio 2) at the centre of plane
# Couette flow (walls at -1, +1 m/s over a height of 1: shear rate 2/s;
# rho 1, mu 1: Reynolds number 0.05 on the ellipse), its major axis along
# the flow at the start.  In unbounded Stokes shear it tumbles on Jeffery's
# orbit (Jeffery 1922): dtheta/dt = -G (a^2 sin^2 theta + b^2 cos^2
# theta)/(a^2 + b^2), period T = 2 pi (a/b + b/a)/G = 7.854 s here; the
# walls, 0.5 from its centre (3.3 semi-axes), slow it a little.  Fixed
# step 0.5/CELLS (Courant number 1/2 at the walls).  jeffery.py reads
# DIR/postProcessing/rigidBodies.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=$2 tend=${3:-8}
dt=$(python3 -c "print(0.5/$n)")
rm -rf "$d"
channelCase "$d" cells="$n" nDisks=1 f=0 endTime="$tend" writeInterval="$tend" \
    rigid=yes mu=1 || exit 1
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { ellipse { material rubber; shape ellipsoid; centre (0.5 0.5 0.5); semiAxes (0.15 0.075 1); } }
DICT
couetteWalls "$d" "$n" || exit 1
(cd "$d" && foamDictionary -entry functions/flowRate -remove system/controlDict) > /dev/null
fixedStep "$d" "$dt" || exit 1
(cd "$d" && setBodies > log.setBodies 2>&1) || exit 1
(cd "$d" && vheFoam > log.vheFoam 2>&1)
