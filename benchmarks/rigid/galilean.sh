#!/bin/bash
# galilean.sh DIR CELLS_PER_D MODE [ENDTIME [RE]]: is a moving rigid body's drag
# Galilean invariant?  A cylinder D = 0.1 m in a doubly periodic 1 x 1 m
# box of liquid (rho 1, nu 0.1/RE: RE = 100 by default at 1 m/s), no
# gravity:
#   MODE fixed    the cylinder held at (0.5, 0.5), the liquid started at
#                 1 m/s in x around it (an impulsively started stream);
#   MODE moving   the liquid at rest, the cylinder moved at -1 m/s in x
#                 (motion prescribed) from (0.6, 0.5).
# The two are the same flow seen from frames 1 m/s apart (no walls, the
# box periodic): the fluid's force on the cylinder must agree at every
# time.  postProcessing/fixedBodies/0/forces.dat (every step);
# galilean.py compares two runs.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
. "$(dirname "$0")/cylinderCase.sh"
d=$1 n=$2 mode=$3 tend=${4:-0.4} Re=${5:-100}
nu=$(python3 -c "print(0.1/$Re)")
N=$((10*n))
case $mode in
    fixed)  U0="(1 0 0)" x0=0.5 motion="motion fixed;" ;;
    moving) U0="(0 0 0)" x0=0.6 motion="motion prescribed; velocity (-1 0 0);" ;;
    *) echo "MODE: fixed or moving" >&2; exit 1 ;;
esac
cylinderSetup "$d"
cylinderBox "$d" 1 1 "$N" "$N" "#eval{ 1.0/$N }" "    left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }
    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }
    bottom { type cyclic; neighbourPatch top;   faces ((0 1 5 4)); }
    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }
    frontAndBack { type empty; faces ((0 3 2 1) (4 5 6 7)); }"
cylinderControl "$d" "$tend" 0.0025 0.1 no
cylinderSolution "$d" 1e-9 1e-10 "pRefCell 0; pRefValue 0;"
cylinderCase "$d" "$x0" 0.5 "$nu" "$motion"
cylinderFields "$d" "$U0" \
    '    "(left|right|bottom|top)" { type cyclic; }' \
    '    "(left|right|bottom|top)" { type cyclic; }'
cylinderRun "$d"
