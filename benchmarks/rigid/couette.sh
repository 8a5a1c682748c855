#!/bin/bash
# couette.sh DIR CELLS BODY VISCOUS_NUMBER [ENDTIME]: one neutrally buoyant
# disk (r 0.1) at the centre of plane Couette flow (walls at -1, +1 m/s,
# rho 1, the channel of scene A without body force); BODY is "rigid",
# "none" or a shear modulus G.  The viscous number Vn = mu dt/(rho dx^2)
# is set with a fixed step dt = min(dx/2, Vn dx^2) (Courant number 1/2 at
# most) and mu = Vn dx^2/dt (1 Pa s up to Vn = 1/(2 dx)).  The case is
# left in DIR for couette.py.  VHE_PIMPLE in the environment adds its
# entries to PIMPLE (e.g. VHE_PIMPLE="coupling { solve always; }").
. "$(dirname "$0")/../../tests/cases/lib.sh" 2>/dev/null
d=$1 n=$2 body=$3 vn=$4 tend=${5:-0.5}
dt=$(python3 -c "print(min(0.5/$n, $vn/$n**2))")
mu=$(python3 -c "print($vn/$n**2/$dt)")
nd=1; [ "$body" = none ] && nd=0
G=1000; [ "$body" = rigid ] || [ "$body" = none ] || G=$body
rig=no; [ "$body" = rigid ] && rig=yes
wi=$(python3 -c "print($tend/4)")
rm -rf "$d"
channelCase "$d" cells="$n" nDisks=$nd f=0 endTime="$tend" writeInterval="$wi" \
    G="$G" rigid="$rig" mu="$mu" || exit 1
if [ "$nd" = 1 ]; then
cat > "$d/system/setBodiesDict" <<DICT
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies { disk { material rubber; shape cylinder; centre (0.5 0.5 0.5); radius 0.1; axis (0 0 1); } }
DICT
fi
couetteWalls "$d" "$n" || exit 1
fixedStep "$d" "$dt" || exit 1
[ "$nd" = 1 ] && { (cd "$d" && setBodies > log.setBodies 2>&1) || exit 1; }
[ -n "${VHE_PIMPLE:-}" ] && sed -i "s/^    pRefValue .*/&\n    $VHE_PIMPLE/" "$d/system/fvSolution"
(cd "$d" && vheFoam > log.vheFoam 2>&1)
