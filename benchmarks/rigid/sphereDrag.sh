#!/bin/bash
# sphereDrag.sh DIR MODE [CELLS_PER_D] [WIDTH] [VELOCITY]: ten Cate's E4
# sphere (d 15 mm, rho_s 1120, in oil of rho 960 and mu 0.058 Pa s,
# tenCate.sh) at u_inf, its terminal velocity in an unbounded liquid,
# 0.128 m/s (Re 31.8; VELOCITY to choose another), its drag taken apart.
# At u_inf an unbounded sphere's drag (Abraham's correlation, tenCate.sh)
# is its weight less its buoyancy, (rho_s - rho) V g = 2.774e-3 N: a ratio
# of 1 below is a sphere that would settle at VELOCITY.  MODE:
#   fixed   held fixed (motion fixed) in a 100 x 100 mm duct 240 mm long,
#           the oil coming in at the bottom at VELOCITY and the duct's
#           walls moving with it: the sphere's frame of a sphere settling
#           down a long duct of ten Cate's section (WIDTH m square, 0.1 by
#           default; 0.2 halves the walls' blockage).  No gravity.
#   moving  the same duct in the lab's frame: the oil at rest, the bottom
#           closed, the top open, the sphere moved down it at VELOCITY
#           (motion prescribed).  No gravity.  Against fixed: what moving
#           through the mesh adds.
#   box     ten Cate's closed box (tenCate.sh's case, gravity 9.81), the
#           sphere moved down at VELOCITY, reached over 0.1 s.
#   rest    the box, the sphere held at rest: the force less the oil's
#           buoyancy should be 0.
# To t = 0.6 s; prints the fluid's mean upward force on the sphere over
# t = 0.3 to 0.6 s (less rho V g in the box) and its ratio to 2.774e-3 N.
# DIR/force.dat: t and that force every step.  About 4 min each at 6
# cells across the sphere (8 by default, 10 to 15 min; the duct 0.2 wide at 6, 25 min), one
# core.
. "$(dirname "$0")/tank.sh"
d=$1 mode=$2 n=${3:-8} W=${4:-0.1} u=${5:-0.128}
rho=960 mu=0.058 tEnd=0.6
case $mode in
    fixed|moving) H=0.24; y=0.08 ;;
    box|rest) H=0.16; y=0.1275 ;;
    *) echo "Usage: $0 DIR fixed|moving|box|rest [CELLS_PER_D] [WIDTH] [VELOCITY]" >&2; exit 1 ;;
esac
[ "$mode" = moving ] && y=$(python3 -c "print(0.08 + $u*$tEnd)")
[ "$W" = 0.1 ] || [ "$mode" = fixed ] || [ "$mode" = moving ] || { echo "WIDTH is for the duct only" >&2; exit 1; }
tenCateSphere "$d" "$W" "$H" "$n" "$rho" "$mu" "$y" "$tEnd" || exit 1
props=$d/constant/vheProperties
case $mode in
    fixed) motion="motion fixed;" ;;
    moving) motion="motion prescribed; velocity (0 -$u 0);" ;;
    box) motion="motion prescribed; velocity table ((0 (0 0 0)) (0.1 (0 -$u 0)) (10 (0 -$u 0)));" ;;
    rest) motion="motion fixed;" ;;
esac
sed -i "s|rigid yes;|rigid yes; $motion|" "$props"
grep -q "rigid yes; motion" "$props" || { echo "could not set $props's motion" >&2; exit 1; }
if [ "$mode" = fixed ] || [ "$mode" = moving ]; then
    # The duct: the bottom an inlet, the top an outlet, no gravity (and no
    # water level to find)
    [ "$mode" = fixed ] && s=$u || s=0
    sed -i "s|walls { type wall; faces ((0 4 7 3) (1 2 6 5) (0 1 5 4)); }|walls { type wall; faces ((0 4 7 3) (1 2 6 5)); } inlet { type patch; faces ((0 1 5 4)); }|; s|top   { type wall;|top { type patch;|" \
        "$d/system/blockMeshDict"
    sed -i 's/^value .*/value (0 0 0);/' "$d/constant/g"
    sed -i "/Water and water+oil levels/,/^    }/d" "$d/system/controlDict"
    python3 - "$d" "$s" <<'PY' || exit 1
import sys
d, s = sys.argv[1], sys.argv[2]
U = f"uniform (0 {s} 0)"
def patches(f, entries):
    p = f"{d}/0/{f}"
    t = open(p).read()
    t = t[:t.index('boundaryField')] + "boundaryField\n{\n" \
        + "".join(f"    {k} {{ {e} }}\n" for k, e in entries) + "}\n"
    open(p, "w").write(t)
moving = f"type fixedValue; value {U};"
patches("U", [("walls", moving), ("frontAndBack", moving), ("inlet", moving),
              ("top", f"type inletOutlet; inletValue uniform (0 0 0); value {U};")])
flux = "type fixedFluxPressure; value uniform 0;"
patches("p_rgh", [("walls", flux), ("frontAndBack", flux), ("inlet", flux),
                  ("top", "type fixedValue; value uniform 0;")])
for f, a in (("alpha.water", 1), ("alpha.air", 0), ("alpha.oil", 0)):
    patches(f, [(k, "type zeroGradient;") for k in ("walls", "frontAndBack", "top")]
               + [("inlet", f"type fixedValue; value uniform {a};")])
PY
    sed -i "s/^internalField .*/internalField uniform (0 $s 0);/" "$d/0/U"
    grep -q "inlet { type patch" "$d/system/blockMeshDict" || { echo "could not make $d a duct" >&2; exit 1; }
    buoyancy=0
else
    buoyancy=$(python3 -c "import math; print($rho*math.pi/6*0.015**3*9.81)")
fi
(run "$d" blockMesh && run "$d" setFields && run "$d" setBodies && run "$d" vheFoam) \
    || { echo "failed: $d" >&2; exit 1; }
awk -v b="$buoyancy" '!/^#/ {print $1, $4 - b}' "$d/postProcessing/fixedBodies/0/forces.dat" > "$d/force.dat"
awk -v m="$mode" -v n="$n" '$1 >= 0.3 {s += $2; k++} END {
    printf "%s, %d cells per d: mean force %.4e N over t = 0.3 to 0.6 s, %.3f times (rho_s - rho) V g\n",
        m, n, s/k, s/k/2.7737e-3}' "$d/force.dat"
