#!/bin/bash
# vortex.sh DIR CELLS MAXCO [ENDTIME [KEY=VALUE...]]: a free rigid disk
# (r 0.05) in a rotating flow: Taylor-Green vortices, u = sin(kx) cos(ky),
# v = -cos(kx) sin(ky), k = 2 pi, in a periodic unit square (rho 1, mu
# 1e-3: Reynolds number 1000 on the vortex cell, the vortices decaying as
# exp(-2 nu k^2 t), by 8 % a second).  The disk starts 0.1 from the centre
# of the vortex at (0.25, 0.25), on the streamline psi = sin(kx) sin(ky) =
# 0.809, and turns about it in about a second.  Time step by the Courant
# number MAXCO, to t = ENDTIME (default 3).  KEY=VALUE: the channel's
# parameters changed (rhoDisk=0.1: a light disk, which the vortex draws
# in; rigid=no G=1e5: a stiff elastic disk).  vortex.py reads the orbit
# (postProcessing/rigidBodies, or bodies for an elastic disk).
. "$(dirname "$0")/arrayCase.sh"
d=$1 n=$2 co=$3 tend=${4:-3}; shift $(($# < 4 ? $# : 4))
rm -rf "$d"
channelCase "$d" cells="$n" nDisks=1 rigid=yes f=0 mu=1e-3 endTime="$tend" \
    writeInterval="$tend" "$@" && cyclicWalls "$d" || exit 1
caseEdits "$d" <<'PY'
# the vortices, cell by cell (blockMesh numbers x fastest)
import math
n = int(open(d + '/system/parameters').read().split('cells')[1].split(';')[0])
k = 2*math.pi
u = ['(%.15g %.15g 0)' % (math.sin(k*(i + 0.5)/n)*math.cos(k*(j + 0.5)/n),
                          -math.cos(k*(i + 0.5)/n)*math.sin(k*(j + 0.5)/n))
     for j in range(n) for i in range(n)]
sub(d + '/0/U', 'internalField uniform (0 0 0);',
    'internalField nonuniform List<vector> %d\n(\n%s\n);' % (n*n, '\n'.join(u)))
PY
[ $? = 0 ] || exit 1
(cd "$d" && foamDictionary -entry maxCo -set "$co" system/controlDict > /dev/null) || exit 1
runBody "$d" "" "disk { material rubber; shape cylinder; centre (0.35 0.25 0.5); radius 0.05; axis (0 0 1); }"
