#!/bin/bash
# stirrer.sh DIR CELLS [ENDTIME]: a prescribed motion (motion prescribed):
# a rigid disk of radius R = 0.1 at the centre of a closed unit box of
# liquid (rho 1, mu 1: Reynolds number Omega R^2/nu = 0.01, Stokes flow),
# turned at Omega = 1 rad/s about its axis.  The torque that turns it,
# per unit depth, lies between those of the Taylor-Couette flows in the
# box's inscribed and circumscribed circles (the Stokes flow dissipates
# least in the larger domain: the box's admissible flows include the
# inscribed circle's, and are included in the circumscribed one's):
#     4 pi mu Omega R^2 R2^2/(R2^2 - R^2),  R2 = 1/sqrt(2) and 1/2,
# 1.0204 to 1.0417 times 4 pi mu Omega R^2.  Fixed step 0.01 (a viscous
# number of 0.01 CELLS^2), to t = 1 (20 e-folds of the slowest viscous
# mode).  stirrer.py reads DIR/postProcessing/fixedBodies and
# DIR/postProcessing/rigidBodies.
. "$(dirname "$0")/arrayCase.sh"
d=$1 n=$2 tend=${3:-1}
unitCell "$d" "$n" "$tend" 0 || exit 1
caseEdits "$d" <<'PY' || exit 1
# the cyclic pair -> walls: a closed box
sub(d + '/system/blockMeshDict',
    'left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n'
    '    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }\n'
    '    walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }',
    'walls  { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }')
for f in ('U', 'p_rgh'):
    sub(d + '/0/' + f, '    left  { type cyclic; }\n    right { type cyclic; }\n', '')
sub(d + '/constant/vheProperties', 'rigid yes;',
    'rigid yes; motion prescribed; angularVelocity (0 0 1);')
PY
(cd "$d" && foamDictionary -entry functions/flowRate -remove system/controlDict) > /dev/null
runBody "$d" 0.01 \
    "stirrer { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius 0.1; axis (0 0 1); }"
