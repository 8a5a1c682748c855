#!/bin/bash
# cubicArray.sh DIR CELLS C [ENDTIME]: Stokes flow through a simple cubic
# array of fixed spheres, the 3D form of squareArray.sh: one sphere of
# volume fraction C at the centre of a unit cube, periodic in x, y and z,
# a rigid material held in place (motion fixed), driven by a body force
# f = 0.1 m/s^2 per unit mass in x on everything; rho 1, mu 1; fixed step
# 0.01 to t = 3 (in 3D the fixed sphere is held and projected, and the
# projection takes of order the viscous number's steps to settle).
# cubicArray.py DIR gives K = F/(6 pi mu a U), U the mean velocity over the
# cell, against Hasimoto (1959)'s dilute series 1/(1 - 1.7601 C^(1/3) + C
# - 1.5593 C^2).  About 1 min at 32 cells.
. "$(dirname "$0")/arrayCase.sh"
d=$1 n=$2 c=$3 tend=${4:-3}
r=$(python3 -c "import math; print((3*$c/(4*math.pi))**(1/3))")
periodicCell "$d" "$n" "$tend" || exit 1
# z periodic too, on as many cells as x and y
sed -i 's/($cells $cells 1)/($cells $cells $cells)/; s/    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }/    back  { type cyclic; neighbourPatch front; faces ((0 3 2 1)); }\n    front { type cyclic; neighbourPatch back; faces ((4 5 6 7)); }/' "$d/system/blockMeshDict"
for f in "$d"/0/*; do
    sed -i 's/frontAndBack *{ *type empty; *}/back { type cyclic; }\n    front { type cyclic; }/' "$f"
done
! grep -q "frontAndBack" "$d"/0/* "$d/system/blockMeshDict" \
    || { echo "could not make $d 3D" >&2; exit 1; }
runCell "$d" 0.01 "s { material rubber; shape sphere; centre (0.5 0.5 0.5); radius $r; }"
