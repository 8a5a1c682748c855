#!/bin/bash
# setBodies: a body across the periodic boundary is wrapped and keeps its
# whole volume; a packing is reproducible from its seed; running setBodies
# twice gives the same fields (fluid fractions are rebuilt, not reduced
# twice); paraFoam -touch only creates the .foam file.
. "$(dirname "$0")/lib.sh"

d="$WORK/wrap"
channelCase "$d" cells=32 || { fail setup blockMesh; finish; }
cat > "$d/system/setBodiesDict" <<'DICT'
FoamFile { version 2.0; format ascii; class dictionary; object setBodiesDict; }
bodies
{
    edge { material rubber; shape cylinder; centre (0.01 0.5 0.5); radius 0.2; }
    slab { material rubber; shape box; min (0.5 0.1 0); max (0.7 0.25 1); }
}
DICT
run "$d" setBodies || fail periodicWrap "setBodies failed: $d/log.setBodies"
read -r exact placed across <<< "$(grep "^Body edge" "$d/log.setBodies" | sed 's/.*volume \([^,]*\), on the mesh \([^,]*\), half-width \([^ ]*\) cells/\1 \2 \3/')"
check periodicWrap "abs($placed/$exact - 1) < 1e-3" \
    "disk across x = 0: volume on the mesh $placed, exact $exact"
read -r exact placed <<< "$(grep "^Body slab" "$d/log.setBodies" | sed 's/.*volume \([^,]*\), on the mesh \([^,]*\),.*/\1 \2/')"
check boxVolume "abs($placed/$exact - 1) < 1e-6" \
    "a 2D box: volume $exact (its area times the depth), on the mesh $placed"
check halfWidth "abs($across - 6.4) < 1e-9 and $(grep -c 'cells from centre to surface' "$d/log.setBodies") == 0" \
    "radius 0.2 on cells of 1/32: half-width $across cells, no warning"

d="$WORK/seed"
channelCase "$d" cells=32 || { fail setup blockMesh; finish; }
run "$d" setBodies && cp "$d/0/alpha.rubber" "$WORK/alpha.first" \
    && cp "$d/0/alpha.liquid" "$WORK/liquid.first" && run "$d" setBodies \
    || fail reproducible "setBodies failed: $d/log.setBodies"
warned=$(grep -o "[0-9]* of [0-9]* bodies are less than 2 cells[^)]*)" "$d/log.setBodies")
check coarseWarning "'$warned'.startswith('16 of 16 bodies') and '$warned'.endswith(': 1.6)')" \
    "the channel's disks of radius 0.05 on cells of 1/32: '$warned'"
if cmp -s "$d/0/alpha.rubber" "$WORK/alpha.first" && cmp -s "$d/0/alpha.liquid" "$WORK/liquid.first"; then
    pass reproducible "same seed, same alpha.rubber; a second run leaves alpha.liquid unchanged"
else
    fail reproducible "fields differ between two setBodies runs"
fi
foamDictionary -entry seed -set 2 "$d/system/parameters" > /dev/null
run "$d" setBodies
if cmp -s "$d/0/alpha.rubber" "$WORK/alpha.first"; then
    fail seedMatters "seed 2 gave the same bodies as seed 1"
else
    pass seedMatters "seed 2 places other bodies"
fi

rm -f "$d"/*.foam
out=$(paraFoam -case "$d" -touch)
check paraFoamTouch "$(ls "$d"/*.foam 2>/dev/null | wc -l) == 1" "$out"
finish
