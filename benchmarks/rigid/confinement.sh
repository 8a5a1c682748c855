#!/bin/bash
# confinement.sh DIR L CELLS: a free rigid disk (r 0.1) at the centre of
# plane Couette flow between walls L apart moving at -1 and +1 m/s (the
# channel of scene A without body force, rho 1, mu 1, dt 0.0098, t = 1),
# to tell the walls' share of its rotation shortfall.  Prints its last two
# (t, omega_z); half the vorticity is -2/L.  Measured: L 1 at 32 cells
# -0.981 of -1, L 2 at 64 cells (the same 3.2 cells per radius) -0.4975 of
# -0.5: 0.995 (solved coupled; projected 0.978, 0.993).
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 L=$2 n=$3
dt=0.0098
rm -rf "$d"
channelCase "$d" L=$L cells="$n" nDisks=1 f=0 endTime=1 writeInterval=0.25 rigid=yes mu=1 > /dev/null || exit 1
c=$(python3 -c "print($L/2)")
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { disk { material rubber; shape cylinder; centre ($c $c 0.5); radius 0.1; axis (0 0 1); } }
DICT
couetteWalls "$d" "$n" || exit 1
fixedStep "$d" "$dt" || exit 1
(cd "$d" && setBodies > log.setBodies 2>&1 && vheFoam > log.vheFoam 2>&1)
awk '!/^#/ {print $1, $14}' $d/postProcessing/bodies/0/bodies.dat | tail -2
