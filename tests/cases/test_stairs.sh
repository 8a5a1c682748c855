#!/bin/bash
# The gmsh route (seed 003's stairs): tutorials/stairs meshed from its
# .geo by gmsh -3, gmshToFoam and changeDictionary, at its default size
# (dx = 0.025), run to t = 0.8:
#  - the mesh is the intended one: 2880 hexahedra, checkMesh OK, patches
#    walls, top (walls) and frontAndBack (empty);
#  - the water reaches the second and third steps (depth above 0.02 m;
#    measured 0.113 and 0.088 at t = 0.8), and
#  - both phase volumes are conserved to 1e-6 relative.
. "$(dirname "$0")/lib.sh"

d="$WORK/stairs"
sceneCase stairs "$d" endTime=0.8 writeInterval=0.8 && run "$d" setFields \
    || fail setup "$d"
run "$d" checkMesh || fail checkMesh "$d/log.checkMesh"
cells=$(awk '/^ *cells:/ {print $2}' "$d/log.checkMesh")
types=$(foamDictionary -entry boundaryField -keywords "$d/0/U" 2>/dev/null | tr '\n' ' ')
empty=$(grep -A3 "frontAndBack" "$d/constant/polyMesh/boundary" | grep -c "type *empty")
check gmshMesh "$cells == 2880 and $empty == 1 and $(grep -c 'Mesh OK' "$d/log.checkMesh") == 1" \
    "$cells cells, frontAndBack empty: $empty, U patches: $types"

run "$d" vheFoam || fail stairsRun "$d/log.vheFoam"
read -r step2 step3 <<< "$(awk '!/^#/ {a = $3; b = $4} END {print a, b}' \
    "$d/postProcessing/stepLevels/0/liquidLevel.dat")"
check waterDownStairs "$step2 > 0.02 and $step3 > 0.02" \
    "depth on step 2: $step2 m, step 3: $step3 m at t = 0.8"
drift=$(python3 "$TESTS_DIR/floating.py" volumes "$d")
check stairsVolumes "$drift < 1e-6" "largest relative phase volume drift $drift"
finish
