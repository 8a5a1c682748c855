#!/bin/bash
# squareArray.sh DIR CELLS C [ENDTIME]: Stokes flow through a square array
# of fixed cylinders (Sangani & Acrivos 1982): one cylinder of area
# fraction C (radius sqrt(C/pi)) at the centre of a unit cell, periodic in
# x and y, a rigid material held in place (motion fixed), driven by a body
# force f = 0.1 m/s^2 per unit mass in x on everything (fluid and
# cylinder, as a mean pressure gradient acts).  rho 1, mu 1: Reynolds
# number U L/nu below 0.01.  Fixed step dt = 0.01 (a viscous number of
# 0.01 CELLS^2: 41 at 64 cells), to t = 1 (40 times the slowest viscous
# time L^2/(4 pi^2 nu)).  The case is left in DIR for squareArray.py.
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=$2 c=$3 tend=${4:-1}
r=$(python3 -c "import math; print(math.sqrt($c/math.pi))")
rm -rf "$d"
channelCase "$d" cells="$n" nDisks=1 rigid=yes f=0.1 mu=1 endTime="$tend" \
    writeInterval="$tend" || exit 1
python3 - "$d" <<'PY'
import sys, re
d = sys.argv[1]
def sub(path, old, new):
    s = open(path).read()
    if old not in s:
        sys.exit(path + ': no ' + old)
    open(path, 'w').write(s.replace(old, new))
# walls -> a cyclic pair
sub(d + '/system/blockMeshDict',
    'walls  { type wall; faces ((0 1 5 4) (3 7 6 2)); }',
    'bottom { type cyclic; neighbourPatch top; faces ((0 1 5 4)); }\n'
    '    top    { type cyclic; neighbourPatch bottom; faces ((3 7 6 2)); }')
sub(d + '/0/U', 'walls { type noSlip; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
sub(d + '/0/p_rgh', 'walls { type fixedFluxPressure; value uniform 0; }',
    'bottom { type cyclic; }\n    top { type cyclic; }')
sub(d + '/constant/vheProperties', 'rigid yes;', 'rigid yes; motion fixed;')
PY
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { cylinder { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius $r; axis (0 0 1); } }
DICT
(cd "$d" && foamDictionary -entry functions/flowRate/writeInterval -set 1 system/controlDict) > /dev/null
fixedStep "$d" "${DT:-0.01}" || exit 1
(cd "$d" && blockMesh > log.blockMesh 2>&1 && setBodies > log.setBodies 2>&1) || exit 1
(cd "$d" && vheFoam > log.vheFoam 2>&1)
