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
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=$2 tend=${3:-1}
rm -rf "$d"
channelCase "$d" cells="$n" nDisks=1 rigid=yes f=0 mu=1 endTime="$tend" \
    writeInterval="$tend" || exit 1
python3 - "$d" <<'PY'
import sys
d = sys.argv[1]
def sub(path, old, new):
    s = open(path).read()
    if old not in s:
        sys.exit(path + ': no ' + old)
    open(path, 'w').write(s.replace(old, new))
# the cyclic pair -> walls: a closed box
sub(d + '/system/blockMeshDict',
    'left   { type cyclic; neighbourPatch right; faces ((0 4 7 3)); }\n'
    '    right  { type cyclic; neighbourPatch left;  faces ((1 2 6 5)); }\n'
    '    walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }',
    'walls  { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4) (3 7 6 2)); }')
for f, bc in (('U', 'noSlip'), ('p_rgh', 'fixedFluxPressure; value uniform 0')):
    sub(d + '/0/' + f, '    left  { type cyclic; }\n    right { type cyclic; }\n', '')
sub(d + '/constant/vheProperties', 'rigid yes;',
    'rigid yes; motion prescribed; angularVelocity (0 0 1);')
PY
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { stirrer { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius 0.1; axis (0 0 1); } }
DICT
(cd "$d" && foamDictionary -entry functions/flowRate -remove system/controlDict) > /dev/null
fixedStep "$d" 0.01 || exit 1
(cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || exit 1
(cd "$d" && vheFoam > log.vheFoam 2>&1)
